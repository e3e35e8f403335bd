"""What a URDF or xacro source says by itself, read without expanding it, and what
the text at a cursor is.

:func:`outline` lists the macros, properties and arguments a source defines, the
links and joints it writes with literal names, and the files it includes, each
where its ``<`` was written. :func:`cursor` tells which tag and attribute value a
position is in, from the text alone, so that it also works on a half-typed tag.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import NamedTuple

from ..project.workspace import WorkspaceFile, workspace_file
from ..read.document import XACRO_NAMESPACES, local_name, namespace_of
from ..read.files import SourceFile
from ..read.positions import declared_encoding

XACRO_KEYWORDS = ("arg", "attribute", "call", "element", "if", "include", "insert_block", "macro", "property", "unless")
_TAG_NAME = re.compile(r"<([A-Za-z_][\w.:-]*)")
_SPACE = re.compile(r"\s*")
# name="value" or name='value'; a value stops at '<' (which XML never allows in one), so
# that a quote not yet closed takes in no more than the rest of its tag
_ATTRIBUTE = re.compile(r"""([^\s=/>"'<]+)\s*=\s*(?:"([^"<]*)("?)|'([^'<]*)('?))""")
_LONGEST_TAG = 65_536  # a start tag longer than this is not one being typed in
_EXPRESSION = re.compile(r"\$\{([^}]*)\}?")
_IDENTIFIER = re.compile(r"[A-Za-z_]\w*")
_SUBSTITUTION = re.compile(r"\$\(\s*(\w+)\s+([^()\s]*)\s*\)?")


class Definition(NamedTuple):
    """A name a source defines, where its element's ``<`` was written."""

    kind: str  # "macro", "property", "arg", "link" or "joint"
    name: str
    file: str
    line: int  # 1-based
    column: int  # 1-based
    detail: str = ""  # a macro's parameters, a property's value, an argument's default
    macro: str | None = None  # the macro it is written in (a property local to it)


class Written(NamedTuple):
    """An attribute value as written, and where its element starts (an include's filename)."""

    value: str
    line: int
    column: int


class Outline(NamedTuple):
    file: str
    definitions: tuple[Definition, ...]
    includes: tuple[Written, ...]
    declared: WorkspaceFile  # what resolving its includes needs: its arguments' defaults, its properties' values

    def named(self, kind: str, name: str) -> list[Definition]:
        return [d for d in self.definitions if d.kind == kind and d.name == name]


def encoded(text: str) -> bytes:
    """An editor's text as the bytes of a file: in the encoding its XML declaration
    names (UTF-8 when it names none, or one that cannot hold the text)."""
    encoding = declared_encoding(text[:256].encode("utf-8", "replace")) or "utf-8"
    try:
        return text.encode(encoding)
    except (LookupError, UnicodeError):
        return text.encode("utf-8")


def is_xacro_element(element) -> bool:
    return element.prefix == "xacro" or namespace_of(element.tag) in XACRO_NAMESPACES


def outline(file: str, source: SourceFile) -> Outline | None:
    """What the source of ``file`` defines; None when it is not well-formed XML."""
    if source.tree is None:
        return None
    definitions: list[Definition] = []
    includes: list[Written] = []
    for element in source.elements:
        line, column = source.place_of(element)
        column = column or 1
        found = _definition(element, file, line, column)
        if found is not None:
            definitions.append(found)
        elif is_xacro_element(element) and local_name(element.tag) == "include" and element.get("filename"):
            includes.append(Written(element.get("filename"), line, column))
    return Outline(file, tuple(definitions), tuple(includes), workspace_file(Path(file), source))


def _definition(element, file: str, line: int, column: int) -> Definition | None:
    name = element.get("name")
    if not name:
        return None
    local = local_name(element.tag)
    macro = _enclosing_macro(element)
    if is_xacro_element(element):
        if local == "macro":
            return Definition("macro", name, file, line, column, element.get("params", ""), macro)
        if local == "property":
            value = element.get("value")
            detail = value if value is not None else "a block of XML"
            return Definition("property", name, file, line, column, detail, macro)
        if local == "arg":
            return Definition("arg", name, file, line, column, element.get("default", ""), macro)
        return None
    if element.getparent() is None or ("$" in name and macro is None):
        return None  # a link named by an expression is named in a macro's body: '${prefix}base_link'
    written_in = element.getparent()
    in_robot = is_xacro_element(written_in) or local_name(written_in.tag) == "robot"
    if local == "link" and in_robot:
        return Definition("link", name, file, line, column, "", macro)
    if local == "joint" and in_robot and element.get("type") is not None:
        return Definition("joint", name, file, line, column, element.get("type", ""), macro)
    return None


def _enclosing_macro(element) -> str | None:
    for ancestor in element.iterancestors():
        if is_xacro_element(ancestor) and local_name(ancestor.tag) == "macro":
            return ancestor.get("name")
    return None


# -- the text at a cursor ---------------------------------------------------------
class Cursor(NamedTuple):
    """Where an offset is in a start tag: on its name, or in one attribute's value."""

    tag: str  # as written, e.g. "xacro:wheel" or "parent"
    tag_start: int  # the offset of its '<'
    on_name: bool  # on the tag's name (or just after it)
    attribute: str | None = None  # the attribute whose value holds the offset
    value: str = ""  # that value as written so far
    value_start: int = 0  # the offset of the value's first character
    value_end: int = 0  # the offset after its last one (before the closing quote)


def cursor(text: str, offset: int) -> Cursor | None:
    """The start tag that ``offset`` is in, from the text alone (a tag being typed
    included); None in text, comments, end tags and between tags."""
    start = text.rfind("<", 0, offset + 1)
    if start < 0:
        return None
    name = _TAG_NAME.match(text, start)
    if name is None:
        return None
    tag = name.group(1)
    if offset <= name.end():
        return Cursor(tag, start, True)
    at = name.end()
    limit = min(len(text), start + _LONGEST_TAG)
    while at < limit:
        at = _SPACE.match(text, at).end()
        if at >= offset:
            return Cursor(tag, start, False)
        if text.startswith((">", "/>", "<"), at):
            return None  # the tag ended before the offset
        attribute = _ATTRIBUTE.match(text, at)
        if attribute is None:
            return Cursor(tag, start, False)  # an attribute being typed
        group = 2 if attribute.group(2) is not None else 4
        value, begin = attribute.group(group), attribute.start(group)
        if not attribute.group(group + 1):  # not closed yet: the value being typed ends with its line
            value = value.split("\n", 1)[0]
        if begin <= offset <= begin + len(value):
            return Cursor(tag, start, False, attribute.group(1), value, begin, begin + len(value))
        at = attribute.end()
    return None


def expression_name(value: str, at: int) -> str | None:
    """The name at position ``at`` of ``value`` when it is inside a ``${...}``."""
    for expression in _EXPRESSION.finditer(value):
        if expression.start(1) <= at <= expression.end(1):
            for word in _IDENTIFIER.finditer(value, expression.start(1), expression.end(1)):
                if word.start() <= at <= word.end() and (word.start() == 0 or value[word.start() - 1] != "."):
                    return word.group()
    return None


def expression_names(text: str) -> set[str]:
    """The names the ``${...}`` expressions of ``text`` use."""
    return {word for expression in _EXPRESSION.finditer(text) for word in _IDENTIFIER.findall(expression.group(1))}


def substitution(value: str, at: int) -> tuple[str, str] | None:
    """The ``$(function argument)`` at position ``at`` of ``value``: (function, argument)."""
    for found in _SUBSTITUTION.finditer(value):
        if found.start() <= at <= found.end():
            return found.group(1), found.group(2)
    return None
