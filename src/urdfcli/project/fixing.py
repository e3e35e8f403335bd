"""Which fixes a run applies, and the edits they make, file by file.

The rules give each diagnostic its fix (:class:`urdfcli.diagnostics.Fix`); here a
run chooses among them: the safe ones, or the unsafe ones too. A fix is applied
whole or not at all. The same fix found twice (a library checked through two
models, a model checked with two argument sets) is applied once; of two fixes
that change the same text differently, the first is applied and the other waits
for the next round, when the rules have seen the first one's result.

``--add-noqa`` writes one ``noqa`` comment per element for what remains.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable
from pathlib import Path
from typing import NamedTuple

from ..diagnostics import Diagnostic, Edit, Fix, Severity
from ..read.files import SourceFiles
from ..read.xacro_scan import shown
from .suppressions import noqa_edit
from .workspace import Index, search_roots

MAX_ROUNDS = 10  # a fix may let another be found; this many rounds at most, as ruff does


class Selection(NamedTuple):
    """The edits of each file (in no particular order), and the fixes they make."""

    edits: dict[str, list[Edit]]
    fixes: list[Fix]


def applies(fix: Fix | None, unsafe: bool) -> bool:
    """Whether a run applies ``fix`` (with ``unsafe``: the unsafe fixes too)."""
    return fix is not None and fix.available and (fix.safe or unsafe)


def select(chosen: Iterable[tuple[Diagnostic, bool]]) -> Selection:
    """The fixes to apply now, each once, none overlapping another, of the diagnostics
    given each with whether its unsafe fix may be applied."""
    taken: dict[str, list[Edit]] = defaultdict(list)
    fixes: list[Fix] = []
    seen: set[tuple[Edit, ...]] = set()
    for diagnostic, unsafe in chosen:
        fix = diagnostic.fix
        if not applies(fix, unsafe):
            continue
        edits = tuple(sorted(set(fix.edits)))
        if edits in seen:
            continue
        seen.add(edits)
        new = [e for e in edits if e not in taken[e.file]]
        if any(_overlap(edit, other) for edit in new for other in taken[edit.file]) or _overlapping(new):
            continue
        for edit in new:
            taken[edit.file].append(edit)
        fixes.append(fix)
    return Selection({file: edits for file, edits in taken.items() if edits}, fixes)


def called_elsewhere(diagnostic: Diagnostic, own: set[Path], index: Index) -> str | None:
    """Why an unsafe fix is not applied, when it edits a macro's body (not a model's own
    call or property) and a file of the repository or workspace outside ``own`` (the
    files the models being fixed read) expands that macro: the edit would change the
    other model too, where the value was right (a tensor fitting its box). None when
    it may be applied. A safe fix keeps every model's meaning: never asked here."""
    for edit in diagnostic.fix.edits:
        file = index.packages.real_path(Path(edit.file))
        scan = index.xacro_file(file)
        macros = [scan.macros[m].name.removeprefix("xacro:") for m in scan.macros_at(edit.start)] if scan is not None else []
        if not macros:
            continue
        others = sorted(index.calling(index.scan(*search_roots(file, index.packages)), set(macros)) - own)
        if others:
            more = f" (and {len(others) - 1} more)" if len(others) > 1 else ""
            return (
                f"{edit.file}:{scan.source.position(edit.start)[0]}: {diagnostic.code} not fixed: macro '{macros[0]}', whose body it edits, "
                f"is also expanded by {shown(others[0])}{more}, which is not among the models fixed"
            )
    return None


def _overlap(one: Edit, other: Edit) -> bool:
    """Whether two edits of one file change the same text (insertions at one place do not)."""
    if one.start == one.end or other.start == other.end:
        return other.start < one.start < other.end or one.start < other.start < one.end
    return one.start < other.end and other.start < one.end


def _overlapping(edits: list[Edit]) -> bool:
    return any(_overlap(a, b) for i, a in enumerate(edits) for b in edits[i + 1:] if a.file == b.file)


def counts(diagnostics: Iterable[Diagnostic], unsafe: bool) -> tuple[int, int]:
    """How many of the diagnostics a run would fix, and how many more ``--unsafe-fixes`` would."""
    fixable = hidden = 0
    for diagnostic in diagnostics:
        if applies(diagnostic.fix, unsafe):
            fixable += 1
        elif applies(diagnostic.fix, True):
            hidden += 1
    return fixable, hidden


class Comments(NamedTuple):
    """The ``noqa`` comments to write: each file's edits, the diagnostics each file's
    comments silence, and the warnings and errors no comment can silence (a file that
    is not XML, a line of the xacro expansion)."""

    edits: dict[str, list[Edit]]
    silenced: dict[str, list[Diagnostic]]
    left: list[Diagnostic]


def noqa_edits(diagnostics: Iterable[Diagnostic], files: SourceFiles) -> Comments:
    """For every warning and error, the ``noqa`` comment that silences it: one per
    element, naming every code found there; one ``noqa-file`` comment per file for the
    diagnostics on a whole file. What a macro call made is silenced at the outermost
    call (in the model's own file), not in the macro's body, where the comment would
    silence every call of every model, those to come too. A diagnostic with no place
    in a source (a line of the xacro expansion) gets none, nor one of the codes no
    comment silences (:data:`~.suppressions.UNSILENCEABLE`)."""
    groups: dict[tuple[str, int, int, bool], tuple[int | None, int | None, list[str]]] = {}
    silenced: dict[str, list[Diagnostic]] = defaultdict(list)
    left: list[Diagnostic] = []
    for diagnostic in diagnostics:
        location = diagnostic.location
        if (diagnostic.severity or Severity.INFO) is Severity.INFO:
            continue
        place = location.trace[-1] if location.trace else location
        source = files.get(place.file) if not location.expanded else None
        found = noqa_edit(source, place.line or None, [diagnostic.code], place.column) if source is not None else None
        if found is None:
            left.append(diagnostic)
            continue
        silenced[place.file].append(diagnostic)
        key = (place.file, found[0], found[1], "noqa-file" in found[2])  # (the file's comment and its first element's may both go at its start)
        line, column, codes = groups.setdefault(key, (place.line or None, place.column, []))
        if diagnostic.code not in codes:
            codes.append(diagnostic.code)
    edits: dict[str, list[Edit]] = defaultdict(list)
    for (file, *_), (line, column, codes) in groups.items():
        found = noqa_edit(files.get(file), line, codes, column)
        if found is not None:
            edits[file].append(Edit(file, *found))
    return Comments(dict(edits), dict(silenced), left)
