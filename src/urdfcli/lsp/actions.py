"""Quick fixes as text edits: a ``noqa`` comment that silences one rule on one
element, and a new ``<inertial>`` (or macro call) in place of the one written.

An edit is (start offset, end offset, new text) in a source's text; the caller
turns offsets into places.
"""

from __future__ import annotations

import re
from typing import NamedTuple

from ..project.suppressions import COMMENT
from ..read.positions import Source

# codes a comment is not the fix for: a file that cannot be read is reported whatever the
# comments say, and a comment about the comments (U001 unused, U002 unknown code) wants editing
UNSILENCEABLE = ("X001", "X002", "U001", "U002")


class Edit(NamedTuple):
    start: int
    end: int
    text: str


def noqa(source: Source, line: int, code: str) -> Edit | None:
    """The edit that silences ``code`` on the element whose ``<`` is on ``line``
    (1-based): the code added to a ``noqa`` comment already on that line or alone
    on the line above, else a comment of its own on a new line above, indented
    as the element is."""
    text = source.line(line)
    if text is None or code in UNSILENCEABLE:
        return None
    line_start = source.offset(line)
    for number, start in ((line, line_start), (line - 1, source.offset(line - 1) if line > 1 else None)):
        written = source.line(number) if start is not None else None
        found = COMMENT.search(written) if written is not None else None
        if found is None or found.group(1) != "noqa" or (number != line and written.strip() != found.group()):
            continue
        codes = [c for c in re.split(r"[,\s]+", found.group(2) or "") if c]
        if not codes:
            return None  # a bare noqa silences every rule already
        return Edit(start + found.start(), start + found.end(), f"<!-- urdfcli: noqa: {', '.join([*codes, code])} -->")
    indentation = text[: len(text) - len(text.lstrip())]
    return Edit(line_start, line_start, f"{indentation}<!-- urdfcli: noqa: {code} -->\n")


def replace_element(source: Source, line: int, column: int | None, replacement: str) -> Edit | None:
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
