"""A parsed description: its XML tree and where each element was written."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING

from lxml import etree

from .diagnostics import Diagnostic, Location
from .positions import Source, source

if TYPE_CHECKING:
    from .expansion import Origin

NAMED = {"link", "joint", "material", "transmission", "gazebo"}


def tag_name(element: etree._Element) -> str:
    """The tag as tinyxml2 (urdfdom) sees it: the prefix kept, a default namespace ignored."""
    tag = element.tag
    if isinstance(tag, str) and "{" not in tag and ":" not in tag:
        return tag  # no namespace and no prefix: the common case, and much faster
    qname = etree.QName(element)
    return f"{element.prefix}:{qname.localname}" if element.prefix else qname.localname


@dataclass
class Document:
    path: str  # as the user gave it ("-" for stdin)
    root: etree._Element | None
    file: Path | None = None  # the file on disk, None for stdin
    is_xacro: bool = False
    expanded_text: str | None = None  # xacro output, for xacro inputs
    includes: list[str] = field(default_factory=list)
    origins: list[Origin | None] | None = None  # xacro inputs: one per element

    @property
    def shown(self) -> str:
        return "<stdin>" if self.path == "-" else self.path

    @cached_property
    def _index(self) -> dict[etree._Element, int]:
        return {element: i for i, element in enumerate(self.root.iter(etree.Element))} if self.root is not None else {}

    def diagnostic(
        self, code: str, message: str, element: etree._Element | None, hint: str | None = None, attribute: str | None = None
    ) -> Diagnostic:
        """A diagnostic about ``element`` (or one of its attributes), located where it was written."""
        return Diagnostic.of(code, message, self.locate(element, attribute), self.element_path(element), hint)

    def locate(self, element: etree._Element | None, attribute: str | None = None) -> Location:
        """Where the ``<`` of ``element`` was written; with ``attribute``, where that
        attribute's name was, when it is written there (else the element's place)."""
        location = self._locate(element)
        if attribute is None or not location.line or not location.column:
            return location
        text = source(location.file)
        start = text.offset(location.line, location.column) if text is not None else None
        found = text.attribute(start, attribute) if start is not None else None
        if found is None:
            return location
        line, column = text.position(found)
        return Location(location.file, line, column, location.expanded, location.trace)

    def _locate(self, element: etree._Element | None) -> Location:
        if element is None:
            return Location(self.shown)
        if self.origins is not None:
            index = self._index.get(element)
            origin = self.origins[index] if index is not None and index < len(self.origins) else None
            if origin is not None:
                return Location(origin.file, origin.line or None, origin.column, trace=origin.trace)
            return Location(self.shown, element.sourceline, None, expanded=True)
        text, index = self._source, self._index.get(element)
        start = text.start(index, tag_name(element)) if text is not None and index is not None else None
        if start is None:
            return Location(self.shown, element.sourceline)
        line, column = text.position(start)
        return Location(self.shown, line, column)

    @cached_property
    def _source(self) -> Source | None:
        return source(self.shown)

    @staticmethod
    def element_path(element: etree._Element | None) -> str | None:
        """An XPath-like name such as ``link[@name='arm']/visual[2]/geometry``."""
        if element is None:
            return None
        parts = []
        node = element
        while node is not None and node.getparent() is not None:
            tag = tag_name(node)
            name = node.get("name")
            if tag in NAMED and name is not None and node.getparent().getparent() is None:
                parts.append(f"{tag}[@name='{name}']")
            elif tag == "gazebo" and node.get("reference") is not None:
                parts.append(f"gazebo[@reference='{node.get('reference')}']")
            else:
                same = [s for s in node.getparent() if s.tag == node.tag]
                parts.append(f"{tag}[{same.index(node) + 1}]" if len(same) > 1 else tag)
            node = node.getparent()
        if not parts:
            name = element.get("name")
            return f"robot[@name='{name}']" if name is not None else tag_name(element)
        return "/".join(reversed(parts))


def source_line(file: str, line: int) -> str | None:
    """One line of a source file (1-based), or None when there is no such line."""
    text = source(file)
    return text.line(line) if text is not None else None
