"""Where each element of a source text starts: the line and column of its ``<``.

libxml2 (lxml's ``sourceline``) gives the line where a start tag *ends*, which
for a tag written over several lines is not where anyone looks. In well-formed
XML a ``<`` outside comments, CDATA sections, processing instructions and the
document type declaration always opens markup, so the element starts are the
``<`` not followed by ``!``, ``?`` or ``/``, in document order: the order in
which lxml's ``iter(etree.Element)`` visits the same document's elements.

A session's files (:class:`urdfcli.read.files.SourceFiles`) are texts with their
positions too.
"""

from __future__ import annotations

import bisect
import codecs
import itertools
import re
from collections.abc import Iterator
from functools import cached_property

_AFTER_NAME = frozenset(" \t\n/>")
_ELEMENT = re.compile(r"<(?![!?/])")
_START = re.Match.start
_MARKUP = re.compile(r"<[!?]")  # where a comment, CDATA section, processing instruction or DOCTYPE may begin
_DOCTYPE = re.compile(r"<!DOCTYPE(?:[^\[>]|\[.*?\])*>", re.DOTALL)  # its internal subset in brackets
# A start tag (name, attributes with quoted values that may hold '>', then '/>' or '>') or an end tag.
_TAG = re.compile(r"""<(?:/[^>]*>|[^\s/>!?](?:[^>"'/]|/(?!>)|"[^"]*"|'[^']*')*(/?)>)""")
_NAME = re.compile(r"<[^\s/>]+")
_ENTITY = re.compile(r"&(#x[0-9a-fA-F]+|#[0-9]+|lt|gt|amp|quot|apos);")
_ENTITIES = {"lt": "<", "gt": ">", "amp": "&", "quot": '"', "apos": "'"}
_ATTRIBUTE = re.compile(r"""\s+([^\s=/>]+)\s*=\s*(?:"[^"]*"|'[^']*')""")
_DECLARED = re.compile(rb"""\A(?:\xef\xbb\xbf)?\s*<\?xml[^>]*?\sencoding\s*=\s*["']([A-Za-z0-9._:-]{1,64})["']""")
_ASCII_COMPATIBLE = ("utf8", "ascii", "usascii", "iso88591", "latin1")
_BOMS = ((codecs.BOM_UTF32_LE, "utf-32"), (codecs.BOM_UTF32_BE, "utf-32"), (codecs.BOM_UTF8, "utf-8-sig"),
         (codecs.BOM_UTF16_LE, "utf-16"), (codecs.BOM_UTF16_BE, "utf-16"))


def _entity(match: re.Match) -> str:
    name = match.group(1)
    if name.startswith("#"):
        return chr(int(name[2:], 16) if name[1] == "x" else int(name[1:]))
    return _ENTITIES[name]


def bom_encoding(data: bytes) -> str | None:
    """The encoding a document's byte-order mark names, if it starts with one."""
    return next((name for bom, name in _BOMS if data.startswith(bom)), None)


def declared_encoding(data: bytes) -> str | None:
    """The encoding the XML declaration names, if it names one."""
    found = _DECLARED.match(data)
    return found.group(1).decode("ascii") if found else None


def ascii_compatible(data: bytes) -> bool:
    """Whether the bytes of markup are ASCII, so that they can be searched as bytes."""
    if bom_encoding(data) not in (None, "utf-8-sig"):
        return False  # UTF-16 or UTF-32
    declared = declared_encoding(data)
    return declared is None or declared.lower().replace("-", "").replace("_", "") in _ASCII_COMPATIBLE


def decode(data: bytes) -> str:
    """The text of an XML document: its byte-order mark, else its declared encoding, else UTF-8."""
    encoding = bom_encoding(data) or declared_encoding(data) or "utf-8"
    try:
        return data.decode(encoding, errors="replace")
    except LookupError:
        return data.decode("utf-8", errors="replace")


def _markup_end(text: str, at: int) -> int | None:
    """The end of the comment, CDATA section, processing instruction or DOCTYPE at ``at``."""
    for opening, closing in (("<!--", "-->"), ("<![CDATA[", "]]>"), ("<?", "?>")):
        if text.startswith(opening, at):
            close = text.find(closing, at + len(opening))
            return close + len(closing) if close >= 0 else None
    doctype = _DOCTYPE.match(text, at)
    return doctype.end() if doctype else None


class Text:
    """One source text, its line ends normalised as XML does (CR LF and CR read as LF)."""

    def __init__(self, text: str):
        self.text = text.replace("\r\n", "\n").replace("\r", "\n") if "\r" in text else text
        self._asked = 0

    @cached_property
    def lines(self) -> list[str]:
        return self.text.split("\n")

    @cached_property
    def _line_starts(self) -> list[int]:
        starts = [0]
        starts.extend(itertools.accumulate(len(line) + 1 for line in self.lines))
        return starts

    @cached_property
    def _holes(self) -> list[tuple[int, int]]:
        """Comments, CDATA, processing instructions and DOCTYPE that hold a '<' of their own."""
        text = self.text
        holes = []
        at = 0
        while (found := _MARKUP.search(text, at)) is not None:  # the next '<!' or '<?'
            at = found.start()
            end = _markup_end(text, at)
            if end is None:  # not closed: no markup to step over
                at += 2
                continue
            if text.find("<", at + 1, end) >= 0:
                holes.append((at, end))
            at = end
        return holes

    def _between_holes(self, pattern: re.Pattern, begin: int = 0, end: int | None = None) -> Iterator[re.Match]:
        """The matches of ``pattern`` between ``begin`` and ``end``, outside the holes
        (chained in C: a model's element starts are many)."""
        return itertools.chain.from_iterable(pattern.finditer(self.text, a, b) for a, b in self._outside_holes(begin, end))

    def _outside_holes(self, begin: int, end: int | None) -> Iterator[tuple[int, int]]:
        """The stretches of text between ``begin`` and ``end`` that no hole covers."""
        end = len(self.text) if end is None else end
        for hole_start, hole_end in self._holes:
            if hole_start >= end:
                break
            if hole_end > begin:
                yield begin, hole_start
                begin = hole_end
        yield begin, end

    @cached_property
    def starts(self) -> list[int]:
        """The offset of every element's ``<``, in document order."""
        return list(map(_START, self._between_holes(_ELEMENT)))

    def start(self, index: int, tag: str | None = None) -> int | None:
        """The offset of the ``<`` of the element ``index`` (in document order), checked
        against its tag when one is given. Found by scanning no further than needed:
        a diagnostic near the top of a large model costs nearly nothing."""
        found = self._found
        while len(found) <= index:
            known = len(found)
            found.extend(map(_START, itertools.islice(self._scan, max(1024, index + 1 - known))))
            if len(found) == known:
                return None
        start = found[index]
        if tag is None:
            return start
        if not self.text.startswith(tag, start + 1):
            return None  # not the text of this tree
        end = start + 1 + len(tag)
        return start if end == len(self.text) or self.text[end] in _AFTER_NAME else None

    def parents_within(self, first: int, end: int | None) -> list[int]:
        """For the elements ``first`` to ``end`` (excluded; None: to the end of the text),
        which must hold no element of the text before ``first``, the index of each
        one's parent counted from ``first`` (-1 for ``first`` itself)."""
        stop = self.start(end) if end is not None else None
        found: list[int] = []
        open_: list[int] = []
        for match in self._tags(self.start(first), len(self.text) if stop is None else stop):
            if self.text[match.start() + 1] == "/":
                if open_:
                    open_.pop()
                continue
            found.append(open_[-1] if open_ else -1)
            if not match.group(1):
                open_.append(len(found) - 1)
        return found

    def _tags(self, begin: int = 0, end: int | None = None) -> Iterator[re.Match]:
        """The start and end tags between two offsets, outside comments and the like."""
        return self._between_holes(_TAG, begin, end)

    def tag(self, index: int) -> str | None:
        """The name written in the start tag of element ``index``."""
        start = self.start(index)
        name = _NAME.match(self.text, start) if start is not None else None
        return name.group()[1:] if name else None

    def value(self, index: int, attribute: str) -> str | None:
        """The value of ``attribute`` on element ``index``, entities replaced."""
        start = self.start(index)
        at = self.attribute(start, attribute) if start is not None else None
        found = _ATTRIBUTE.match(self.text, at - 1) if at is not None else None
        if found is None:
            return None
        written = found.group(0).split("=", 1)[1].strip()[1:-1]
        return _ENTITY.sub(_entity, written) if "&" in written else written

    @cached_property
    def _found(self) -> list[int]:
        return []

    @cached_property
    def _scan(self) -> Iterator[re.Match]:
        return self._between_holes(_ELEMENT)

    @cached_property
    def spans(self) -> list[tuple[int, int, int]]:
        """Per element in document order: offsets of its ``<``, of the end of its start
        tag, and of the end of the element (after its end tag). Empty when the text is
        not the well-formed document it should be."""
        found: list[list[int]] = []
        open_: list[int] = []
        for match in self._tags():
            start = match.start()
            if self.text[start + 1] == "/":
                if not open_:
                    return []
                found[open_.pop()][2] = match.end()
            else:
                found.append([start, match.end(), match.end()])
                if not match.group(1):
                    open_.append(len(found) - 1)
        if open_:
            return []
        return [(a, b, c) for a, b, c in found]

    def span(self, index: int) -> tuple[int, int, int] | None:
        """``spans[index]`` alone, found by scanning the text from the element's ``<``
        to its end tag only (a fix inserted into one element of a large model need not
        work out every element's); None when the text there is not well-formed."""
        start = self.start(index)
        if start is None:
            return None
        tags = self._tags(start)
        first = next(tags, None)
        if first is None or first.start() != start or self.text[start + 1] == "/":
            return None
        if first.group(1):  # <tag/>
            return start, first.end(), first.end()
        depth = 1
        for match in tags:
            if self.text[match.start() + 1] != "/":
                depth += not match.group(1)
                continue
            depth -= 1
            if depth == 0:
                return start, first.end(), match.end()
        return None

    def position(self, offset: int) -> tuple[int, int]:
        """1-based line and column (in characters) of an offset."""
        self._asked += 1
        if self._asked < 32 and "_line_starts" not in self.__dict__:  # a few: counting is faster than a table
            line_start = self.text.rfind("\n", 0, offset) + 1
            return self.text.count("\n", 0, line_start) + 1, offset - line_start + 1
        line = bisect.bisect_right(self._line_starts, offset)
        return line, offset - self._line_starts[line - 1] + 1

    def offset(self, line: int, column: int | None = None) -> int | None:
        if not 0 < line <= len(self._line_starts):
            return None
        return self._line_starts[line - 1] + (column or 1) - 1

    def attribute(self, start: int, name: str) -> int | None:
        """The offset of attribute ``name`` in the start tag whose ``<`` is at ``start``."""
        tag = _NAME.match(self.text, start)
        if tag is None:
            return None
        at = tag.end()
        while (found := _ATTRIBUTE.match(self.text, at)) is not None:
            if found.group(1) == name:
                return found.start(1)
            at = found.end()
        return None

    def line(self, number: int) -> str | None:
        lines = self.lines
        return lines[number - 1] if 0 < number <= len(lines) else None

    def element_starts(self, count: int) -> list[int] | None:
        """The element starts, if there are exactly ``count`` of them (the parsed tree's
        element count): anything else means the text is not that tree's source."""
        starts = self.starts
        return starts if len(starts) == count else None


def may_contain(data: bytes, text: str) -> bool:
    """Whether the document ``data`` may contain ``text`` (ASCII): told from the bytes
    when they can tell, true otherwise."""
    return text.encode() in data or not ascii_compatible(data)
