"""Suppression comments in the sources of a description.

``<!-- urdfcli: noqa: CODE1, CODE2 -->`` silences those rules for one element
and everything inside it, whatever line of it a diagnostic points at: the
element whose start tag shares a line with the comment (any line of a tag
written over several), or else the element just below the comment. A bare
``<!-- urdfcli: noqa -->`` silences every rule there. ``<!-- urdfcli:
noqa-file: CODE1 -->`` anywhere in a file silences them for every diagnostic
in that file. Codes, code prefixes (``I``) and rule names
(``visual-without-collision``) are accepted, as in the configuration. A
diagnostic on an element a xacro macro made is silenced too by a comment on
the macro call (any call in its trace). A suppression that silences nothing is
reported (U001), and so is a word that names no rule (U002).

Two calls: :func:`parse` reads the comments of one source text, :func:`apply`
filters diagnostics with them.
"""

from __future__ import annotations

import bisect
import os
import re
from typing import NamedTuple

from ..diagnostics import Diagnostic, Location
from ..read.document import SUPPRESSION_MARK
from ..read.positions import Text
from ..rules import REGISTRY
from ..rules.structure import X001, X002, X003, X004
from ..rules.suppression import U001, U002
from .config import matches, selector

COMMENT = re.compile(r"<!--\s*urdfcli\s*:\s*(noqa-file|noqa)(?![\w-])\s*(?::\s*(.*?))?\s*-->", re.DOTALL)

Position = tuple[int, int]  # line, column (1-based)


class Suppression(NamedTuple):
    file: str  # as diagnostics name it
    line: int  # where the comment is
    column: int
    selectors: tuple[str, ...]  # codes or prefixes
    regions: tuple[tuple[Position, Position], ...] | None  # the elements it covers, [start, end); None: the whole file
    target: int | None  # the line of the (first) element it silences
    unknown: tuple[str, ...]  # words that name no rule
    bare: bool  # no codes: every rule
    used: set[str]  # the selectors that silenced something ("" for a bare noqa), filled in by apply

    @property
    def kind(self) -> str:
        return "noqa-file" if self.regions is None else "noqa"

    def selecting(self, code: str) -> str | None:
        """The selector of this suppression that names ``code``, if any."""
        if self.bare:
            return ""
        return next((s for s in self.selectors if matches(s, code)), None)

    def covers(self, diagnostic: Diagnostic) -> bool:
        places = (diagnostic.location, *diagnostic.location.trace)
        return any(same_file(place.file, self.file) and self._inside(place.line, place.column) for place in places)

    def took_part(self, written: dict[str, list[Position]] | None) -> bool:
        """Whether an element it covers was made (or a macro call it covers made one)
        in this expansion: a noqa in a macro this model never calls, or in a xacro:if
        branch it never takes, silenced nothing here but may elsewhere."""
        if written is None or self.regions is None:
            return True
        places = (place for file, found in written.items() if same_file(file, self.file) for place in found)
        return any(self._inside(line, column or None) for line, column in places)

    def _inside(self, line: int | None, column: int | None) -> bool:
        if self.regions is None:
            return True
        if not line:
            return False
        if column is None:  # only the line is known: any line of the element
            return any(start[0] <= line <= end[0] for start, end in self.regions)
        return any(start <= (line, column) < end for start, end in self.regions)


def file_key(file: str) -> str:
    """A file as one name, however it is written: an included file is named relative to
    the working folder by its locations and absolutely by the expansion's includes."""
    return file if file.startswith("<") else os.path.abspath(file)


def same_file(a: str, b: str) -> bool:
    return a == b or file_key(a) == file_key(b)


def parse(file: str, text: str) -> list[Suppression]:
    """Every urdfcli suppression comment in one source text."""
    if SUPPRESSION_MARK not in text:
        return []
    source = Text(text)
    text = source.text
    found = []
    for match in COMMENT.finditer(text):
        line, column = source.position(match.start())
        words = [w for w in re.split(r"[,\s]+", match.group(2) or "") if w]
        resolved = [(w, selector(w)) for w in words]
        selectors = tuple(dict.fromkeys(s for _, s in resolved if s is not None))
        unknown = tuple(w for w, s in resolved if s is None)
        bare = not words
        if match.group(1) == "noqa-file":
            found.append(Suppression(file, line, column, selectors, None, None, unknown, bare, set()))
            continue
        regions = _targets(source, match.start(), match.end())
        target = regions[0][0][0] if regions else line + 1
        if not regions:  # not well-formed here: the line below, as a fallback
            regions = [((line + 1, 1), (line + 2, 1))]
        found.append(Suppression(file, line, column, selectors, tuple(regions), target, unknown, bare, set()))
    return found


def _targets(source: Text, start: int, end: int) -> list[tuple[Position, Position]]:
    """The elements a comment at [start, end) silences: those whose start tag shares
    a line with it, else the first element after it. Empty when unknown."""
    spans = source.spans
    if not spans:
        return []
    text = source.text
    line_start = text.rfind("\n", 0, start) + 1
    line_end = text.find("\n", end)
    line_end = len(text) if line_end < 0 else line_end
    starts = [s for s, _, _ in spans]
    tag_ends = [t for _, t, _ in spans]
    first = bisect.bisect_right(tag_ends, line_start)  # start tags are in order and never overlap
    last = bisect.bisect_left(starts, line_end)
    chosen = spans[first:last]
    if not chosen:
        after = bisect.bisect_left(starts, end)
        chosen = spans[after : after + 1]
    return [(source.position(s), source.position(e)) for s, _, e in chosen]


def apply(diagnostics: list[Diagnostic], suppressions: list[Suppression], enabled=lambda code: True, written=None) -> list[Diagnostic]:
    """The diagnostics no suppression covers, plus U001/U002 for the suppressions themselves.

    ``enabled(code)`` tells whether a rule is on here: a suppression of a rule
    that is off is not reported as unused. ``written`` (see
    :meth:`~urdfcli.read.expanded.Origins.written`; None for a plain URDF) tells
    which elements an expansion made: a suppression of an element it did not
    make is not reported as unused either.
    """
    kept = []
    by_file: dict[str, list[Suppression]] = {}
    for suppression in suppressions:
        by_file.setdefault(file_key(suppression.file), []).append(suppression)
    for diagnostic in diagnostics:
        files = {file_key(diagnostic.file), *(file_key(call.file) for call in diagnostic.location.trace)}
        silenced = False
        for suppression in (s for f in files for s in by_file.get(f, ())):
            chosen = suppression.selecting(diagnostic.code)
            if chosen is not None and suppression.covers(diagnostic):
                suppression.used.add(chosen)
                silenced = True
        if not silenced:
            kept.append(diagnostic)
    known = REGISTRY
    for suppression in suppressions:
        where = Location(suppression.file, suppression.line, suppression.column)
        kind = suppression.kind
        for word in suppression.unknown:
            kept.append(Diagnostic(U002.code, f"'{kind}: {word}' names no rule", where, hint="`urdfcli rules` lists the codes and names"))
        if not suppression.took_part(written):
            continue
        scope = "in this file" if suppression.target is None else f"on the element at line {suppression.target}"
        if suppression.bare:
            if "" not in suppression.used:
                kept.append(Diagnostic(U001.code, f"'{kind}' silences nothing: no diagnostic {scope}", where, hint="remove it"))
            continue
        for chosen in suppression.selectors:
            if chosen not in suppression.used and any(enabled(code) for code in known if matches(chosen, code)):
                kept.append(Diagnostic(U001.code, f"'{kind}: {chosen}' silences nothing: no {chosen} {scope}", where, hint="remove it"))
    return kept


# -- writing them -------------------------------------------------------------------------
# codes a comment is not the fix for: a file that cannot be read or expanded (no model is
# checked then) is reported whatever the comments say, and a comment about the comments
# (U001 unused, U002 unknown code) wants editing
UNSILENCEABLE = (X001.code, X002.code, X003.code, X004.code, U001.code, U002.code)


def noqa_edit(source: Text, line: int | None, codes: list[str], column: int | None = None) -> tuple[int, int, str] | None:
    """The edit (start, end, text) of ``source``'s text that silences ``codes`` on the
    element at ``line`` (and ``column``; the element whose start tag holds that place):
    the codes added to a ``noqa`` comment already on the element's line or alone on
    the line above, else a comment of its own on a new line above the element,
    indented as it is. A diagnostic on the whole file (no line, or the XML declaration,
    as a generated URDF's drift is) gets a ``noqa-file`` comment instead. None when
    nothing needs writing (a bare ``noqa`` is there already) or no comment can be
    written there."""
    codes = [c for c in dict.fromkeys(codes) if c not in UNSILENCEABLE]
    if not codes:
        return None
    if line is None:
        return _noqa_file_edit(source, codes)
    text = source.line(line)
    if text is None:
        return None
    line = _element_line(source, line, column)
    text = source.line(line)
    if "<?xml" in text:
        return _noqa_file_edit(source, codes)  # nothing may come before the XML declaration
    line_start = source.offset(line)
    for number, start in ((line, line_start), (line - 1, source.offset(line - 1) if line > 1 else None)):
        written = source.line(number) if start is not None else None
        found = COMMENT.search(written) if written is not None else None
        if found is None or found.group(1) != "noqa" or (number != line and written.strip() != found.group()):
            continue
        present = [c for c in re.split(r"[,\s]+", found.group(2) or "") if c]
        if not present:
            return None  # a bare noqa silences every rule already
        added = [c for c in codes if c not in present]
        if not added:
            return None
        return start + found.start(), start + found.end(), f"<!-- urdfcli: noqa: {', '.join([*present, *added])} -->"
    indentation = text[: len(text) - len(text.lstrip())]
    return line_start, line_start, f"{indentation}<!-- urdfcli: noqa: {', '.join(codes)} -->\n"


_DECLARATION = re.compile(r"\s*<\?xml\b.*?\?>", re.DOTALL)


def _noqa_file_edit(source: Text, codes: list[str]) -> tuple[int, int, str] | None:
    """The codes added to the file's ``noqa-file`` comment, else a comment of its own
    after the XML declaration (at the start of a file without one)."""
    text = source.text
    for found in COMMENT.finditer(text):
        if found.group(1) != "noqa-file":
            continue
        present = [c for c in re.split(r"[,\s]+", found.group(2) or "") if c]
        added = [c for c in codes if c not in present]
        if not present or not added:
            return None  # silenced already
        return found.start(), found.end(), f"<!-- urdfcli: noqa-file: {', '.join([*present, *added])} -->"
    comment = f"<!-- urdfcli: noqa-file: {', '.join(codes)} -->"
    declaration = _DECLARATION.match(text)
    if declaration is None:
        return 0, 0, comment + "\n"
    return declaration.end(), declaration.end(), "\n" + comment


def _element_line(source: Text, line: int, column: int | None) -> int:
    """The line of the ``<`` of the element whose start tag holds ``line``:``column`` (the
    first non-blank character of the line without a column): a comment may not be
    written inside a tag written over several lines."""
    written = source.line(line) or ""
    offset = source.offset(line, column or (len(written) - len(written.lstrip()) + 1))
    spans = source.spans
    if offset is None or not spans:
        return line
    starts = [span[0] for span in spans]
    at = bisect.bisect_right(starts, offset) - 1
    if at >= 0 and spans[at][0] <= offset < spans[at][1]:
        return source.position(spans[at][0])[0]
    return line
