"""Positions as an editor counts them: 0-based lines, and characters with the text
of their line, so that the protocol layer can count them in the client's units."""

from __future__ import annotations

import re
from typing import NamedTuple

from ..read.positions import Text

_TOKEN = re.compile(r"<?[^\s=/>\"']+")


class Point(NamedTuple):
    line: int  # 0-based
    character: int  # 0-based, in characters (code points)
    text: str  # the whole line, for counting in UTF-16 or UTF-8 units


class Place(NamedTuple):
    file: str  # absolute path
    start: Point
    end: Point


def token_place(file: str, source: Text | None, line: int | None, column: int | None) -> Place:
    """The place of a 1-based line and column: the tag name or attribute name that
    starts there, the written part of the line when no column is known, and the
    start of the file when not even a line is (or the file cannot be read)."""
    text = source.line(line) if source is not None and line else None
    if text is None:
        first = source.line(1) if source is not None else None
        return Place(file, Point(0, 0, first or ""), Point(0, 0, first or ""))
    if column is None:
        start = len(text) - len(text.lstrip())
        end = len(text.rstrip())
    else:
        start = min(column - 1, len(text))
        token = _TOKEN.match(text, start)
        end = token.end() if token is not None else start
    return Place(file, Point(line - 1, start, text), Point(line - 1, max(end, start), text))


def offset_place(file: str, source: Text, start: int, end: int) -> Place:
    """The place between two offsets of a source's text."""
    return Place(file, _point(source, start), _point(source, end))


def _point(source: Text, offset: int) -> Point:
    line, column = source.position(offset)
    return Point(line - 1, column - 1, source.line(line) or "")


def offset(source: Text, line: int, character: int) -> int:
    """The offset of a 0-based line and character (clamped to the line, and to the text)."""
    text = source.line(line + 1)
    if text is None:
        return len(source.text)
    return source.offset(line + 1, min(character, len(text)) + 1)
