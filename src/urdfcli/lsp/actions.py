"""Quick fixes as text edits: a ``noqa`` comment that silences one rule on one
element, a new ``<inertial>`` (or macro call) in place of the one written, and the
fixes the diagnostics carry (one at a time, or every safe one of a file).

An edit is (start offset, end offset, new text) in a source's text; the caller
turns offsets into places.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from typing import NamedTuple

from ..diagnostics import Diagnostic, Fix
from ..project.fixing import select
from ..project.suppressions import noqa_edit
from ..read.files import SourceFiles
from ..read.positions import Text
from .places import Place, offset_place


class Edit(NamedTuple):
    start: int
    end: int
    text: str


def noqa(source: Text, line: int, code: str) -> Edit | None:
    """The edit that silences ``code`` on the element whose ``<`` is on ``line``
    (1-based): the code added to a ``noqa`` comment already on that line or alone
    on the line above, else a comment of its own on a new line above, indented
    as the element is."""
    found = noqa_edit(source, line, [code])
    return Edit(*found) if found is not None else None


def replace_element(source: Text, line: int, column: int | None, replacement: str) -> Edit | None:
    """The edit that replaces the element whose ``<`` is at ``line``:``column`` (the
    first on the line when no column is known) by ``replacement``, indented as the
    element is. None when the text is not well-formed, or holds no element there."""
    line_start = source.offset(line)
    text = source.line(line)
    if line_start is None or text is None:
        return None
    start = line_start + (column - 1 if column else len(text) - len(text.lstrip()))
    span = next((s for s in source.spans if s[0] == start), None)
    if span is None:
        return None
    indentation = text[: len(text) - len(text.lstrip())]
    lines = replacement.split("\n")
    return Edit(span[0], span[2], "\n".join([lines[0], *(indentation + rest for rest in lines[1:])]))


# -- the fixes diagnostics carry ------------------------------------------------------------
def fix_edits(fix: Fix, files: SourceFiles) -> tuple[tuple[Place, str], ...] | None:
    """A diagnostic's fix as the editor's edits (each file's text as the session has it,
    the editor's unsaved buffers included); None when it has none or a file cannot be read."""
    if not fix.available:
        return None
    found = []
    for edit in fix.edits:
        source = files.get(edit.file)
        if source is None:
            return None
        found.append((offset_place(os.path.abspath(edit.file), source, edit.start, edit.end), edit.text))
    return tuple(found)


def fix_title(fix: Fix) -> str:
    return fix.title[:1].upper() + fix.title[1:] + ("" if fix.safe else " (unsafe)")


def own_fixes(diagnostics: Iterable[Diagnostic], path: str, code: str, line: int) -> list[Fix]:
    """The fixes of the diagnostics of ``code`` at ``line`` (0-based) of ``path``, each once:
    written there, or made by a macro called there (the editor shows those at the call too)."""
    found = []
    for diagnostic in diagnostics:
        location = diagnostic.location
        if diagnostic.code != code or diagnostic.fix is None or not diagnostic.fix.available or location.expanded or diagnostic.fix in found:
            continue
        places = [(location.file, location.line), *((call.file, call.line) for call in location.trace)]
        if any(at == line + 1 and os.path.abspath(file) == path for file, at in places):
            found.append(diagnostic.fix)
    return found


def fix_all(diagnostics: Iterable[Diagnostic], path: str) -> list[Fix]:
    """The safe fixes of the diagnostics in ``path`` that `urdfcli lint --fix` would apply
    in one round: each once, none overlapping another."""
    chosen = [(d, False) for d in diagnostics if not d.location.expanded and os.path.abspath(d.location.file) == path]
    return select(chosen).fixes
