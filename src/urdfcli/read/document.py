"""A read description: the bytes of its model, and where each element was written.

:func:`read_document` reads an input (a file, or standard input) and expands
it with xacro where it uses xacro. Elements are named by their index in
document order (the root is 0); their places are found from the source text
when a diagnostic needs one, so reading keeps nothing per element.
"""

from __future__ import annotations

import bisect
import re
import sys
from array import array
from functools import cached_property
from pathlib import Path
from typing import NamedTuple

from ..diagnostics import Diagnostic, Location
from . import positions
from .expanded import ExpansionError, Origins
from .packages import PackageIndex, PackageResolver
from .files import STDIN_NAME, SourceFile, SourceFiles
from .positions import Text
from .xacro import Expander
from .xacro_scan import XACRO_NAMESPACES
from .xml import WHOLE_UP_TO, Element

NAMED = {"link", "joint", "material", "transmission", "gazebo"}
SUPPRESSION_MARK = "urdfcli"  # every suppression comment (``<!-- urdfcli: noqa -->``) names it


def tag_name(element: Element) -> str:
    """The tag as tinyxml2 (urdfdom) sees it: the prefix kept, a default namespace ignored."""
    tag = element.tag
    if "{" not in tag:
        return tag  # no namespace: the common case, and faster
    local = local_name(tag)
    return f"{element.prefix}:{local}" if element.prefix else local


def local_name(tag: str) -> str:
    """The name of a tag (or attribute) in lxml's ``{namespace}name`` notation, without its namespace."""
    return tag.rpartition("}")[2]


def namespace_of(tag: str) -> str | None:
    """The namespace of a tag in lxml's ``{namespace}name`` notation (None when it has none)."""
    return tag[1:].partition("}")[0] if tag.startswith("{") else None


class Document:
    """A description as read. ``data`` is the model's XML (xacro's output for xacro
    inputs), let go of once the model is read: a large model's text is not kept
    beside it (diagnostics read their lines from the file, or from ``expanded_text``).
    None when unreadable; ``readable`` stays true once the data is let go of."""

    def __init__(
        self,
        path: str,  # as the user gave it ("-" for stdin)
        data: bytes | None,
        file: Path | None = None,  # the file on disk, None for stdin
        is_xacro: bool = False,
        expanded_text: str | None = None,  # xacro output, for xacro inputs
        includes: list[str] | None = None,
        origins: Origins | None = None,  # xacro inputs: one per element
        files: SourceFiles | None = None,  # the session's files, where diagnostics are located
    ) -> None:
        self.path = path
        self.files = files if files is not None else SourceFiles()
        self.data = data
        self.file = file
        self.is_xacro = is_xacro
        self.expanded_text = expanded_text
        self.includes = includes if includes is not None else []
        self.origins = origins
        self.tops = array("l")  # the index of each top-level element, as read
        # Whether the file's own text may hold a suppression comment (SUPPRESSION_MARK),
        # told from its bytes while they are at hand (None: not told; look in the file).
        self.may_suppress: bool | None = None
        self.readable = data is not None  # whether a model could be read
        self.missing_argument: str | None = None  # a xacro argument the expansion needed and had no value for
        self.tree: Element | None = None  # the file's tree (elements only), when it was parsed whole to tell whether it uses xacro
        self.places: dict[tuple[int | None, str | None], tuple[Location, str | None]] = {}  # (element, attribute) -> where, its path

    @property
    def shown(self) -> str:
        return "<stdin>" if self.path == "-" else self.path

    def diagnostic(
        self, code: str, message: str, at: int | None, hint: str | None = None, attribute: str | None = None, subjects: tuple[str, ...] = ()
    ) -> Diagnostic:
        """A diagnostic about the element ``at`` (or one of its attributes), located where it
        was written: each place worked out once (rules, the consumers' above all, say several
        things of one link or joint)."""
        place = self.places.get((at, attribute))
        if place is None:
            place = self.places[at, attribute] = (self.locate(at, attribute), self.element_path(at))
        return Diagnostic(code, message, place[0], place[1], hint, subjects=subjects)

    def locate(self, at: int | None, attribute: str | None = None) -> Location:
        """Where the ``<`` of element ``at`` was written; with ``attribute``, where that
        attribute's name was, when it is written there (else the element's place)."""
        location = self._locate(at)
        if attribute is None or not location.line or not location.column:
            return location
        text = self.files.get(location.file)
        start = text.offset(location.line, location.column) if text is not None else None
        found = text.attribute(start, attribute) if start is not None else None
        if found is None:
            return location
        line, column = text.position(found)
        return Location(location.file, line, column, location.expanded, location.trace)

    def _locate(self, at: int | None) -> Location:
        if at is None:
            return Location(self.shown)
        if self.origins is not None:
            origin = self.origins[at] if at < len(self.origins) else None
            if origin is not None:
                return origin.location()
        text = self.model_source
        start = text.start(at) if text is not None else None
        if start is None:
            return Location(self.shown, expanded=self.is_xacro)
        line, column = text.position(start)
        return Location(self.shown, line, None, expanded=True) if self.is_xacro else Location(self.shown, line, column)

    def element_on_line(self, line: int) -> int | None:
        """The element a message about ``line`` of the model's text (the file, or xacro's
        output) is about: the last one starting on or before that line."""
        text = self.model_source
        end = text.offset(line + 1) if text is not None else None
        if text is None or line < 1:
            return None
        starts = text.starts
        index = bisect.bisect_left(starts, end if end is not None else len(text.text)) - 1
        return index if index >= 0 else None

    @cached_property
    def model_source(self) -> Text | None:
        """The text the model was read from: the file, or xacro's output."""
        return Text(self.expanded_text) if self.expanded_text is not None else self.files.get(self.shown)

    def element_path(self, at: int | None) -> str | None:
        """An XPath-like name such as ``link[@name='arm']/visual[2]/geometry``, worked
        out from the text of the top-level element that holds ``at``."""
        text = self.model_source
        if at is None or text is None or text.start(at) is None:
            return None
        if at == 0 or not self.tops or at < self.tops[0]:
            name = text.value(at, "name")
            return f"robot[@name='{name}']" if name is not None else text.tag(at)
        which = bisect.bisect_right(self.tops, at) - 1
        top = self.tops[which]
        parents = text.parents_within(top, self.tops[which + 1] if which + 1 < len(self.tops) else None)
        parts = []
        node = at
        while node != top:
            parent = parents[node - top] + top
            tag = text.tag(node)
            same = [i for i in range(parent + 1, top + len(parents)) if parents[i - top] + top == parent and text.tag(i) == tag]
            parts.append(f"{tag}[{same.index(node) + 1}]" if len(same) > 1 else tag)
            node = parent
        tag, name = text.tag(top), text.value(top, "name")
        if tag in NAMED and name is not None:
            parts.append(f"{tag}[@name='{name}']")
        elif tag == "gazebo" and (reference := text.value(top, "reference")) is not None:
            parts.append(f"gazebo[@reference='{reference}']")
        else:
            same = [i for i in self.tops if text.tag(i) == tag]
            parts.append(f"{tag}[{same.index(top) + 1}]" if len(same) > 1 else tag)
        return "/".join(reversed(parts))


# -- reading an input ---------------------------------------------------------------
STDIN = "-"


class InputError(Exception):
    """The input cannot be read at all (exit 2)."""


class Inputs(NamedTuple):
    """What reading shares across a session: the source files, the package
    look-ups and the xacro worker."""

    files: SourceFiles
    packages: PackageIndex
    expander: Expander


def read_input(path: str, files: SourceFiles) -> SourceFile:
    """An input: a file (or the text an editor gave for it), or standard input."""
    if path == STDIN:
        if STDIN_NAME not in files.given():  # read once a run: checked again (after a fix), it is the text given
            files.give(STDIN_NAME, sys.stdin.buffer.read())  # excerpts and columns, as for a file
        return files.read(STDIN_NAME)
    try:
        if Path(path).is_dir():
            raise InputError(f"{path}: is a directory, not a file")
        return files.read(path)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except PermissionError:
        raise InputError(f"{path}: permission denied") from None
    except IsADirectoryError:
        raise InputError(f"{path}: is a directory, not a file") from None
    except OSError as error:
        raise InputError(f"{path}: cannot read: {error.strerror}") from None


_XACRO_TAGS = tuple(f"{{{namespace}}}*" for namespace in sorted(XACRO_NAMESPACES))  # any element in xacro's namespace
_PREFIXED = "boolean(//*[namespace-uri() != '' and starts-with(name(), 'xacro:')])"
# ${...} and $(...) where xacro evaluates them: attribute values and text (comments are not text here).
_SUBSTITUTION = "boolean(//@*[contains(., '${') or contains(., '$(')] | //text()[contains(., '${') or contains(., '$(')])"


def is_xacro(file: SourceFile) -> bool:
    """Whether a document not named .xacro uses xacro: a xacro element (in xacro's
    namespace, or any element prefixed ``xacro:``), or ``${`` / ``$(`` in an attribute
    or in text outside comments. A namespace declaration alone is not use: xacro's
    output would read the same, at many times the cost. A document that is not
    well-formed is not xacro: reading it says what is wrong; nor is one whose root is
    not ``<robot>`` (a launch file). Where the bytes (in
    ASCII), comments left out, cannot hold a mark, the tree is not searched for it:
    a generated URDF often keeps the ``$(find ...)`` of its source in a comment."""
    data = file.data
    ascii = positions.ascii_compatible(data)
    if ascii:
        if b"$" not in data and b"xacro" not in data:
            return False  # neither mark anywhere: no comment to take out
        data = _without_comments(data)
        if b"$" not in data and b"xacro" not in data:
            return False  # neither mark in markup written in ASCII: nothing to parse
    root = file.tree
    if root is None or tag_name(root) != "robot":
        return False  # not a robot (a launch file's $(find xacro)): reading it says so (R001)
    if next(root.iter(*_XACRO_TAGS), None) is not None:
        return True
    if (not ascii or b"<xacro:" in data) and root.xpath(_PREFIXED):
        return True
    return (not ascii or b"${" in data or b"$(" in data) and bool(root.xpath(_SUBSTITUTION))


_COMMENT = re.compile(rb"<!--.*?-->", re.DOTALL)
_DECLARATION = re.compile(rb"(?:\xef\xbb\xbf)?<\?xml\s")


def _without_comments(data: bytes) -> bytes:
    """The bytes of a document (ASCII-compatible) without its comments, where only a
    comment can hold ``<!--``: with a CDATA section, or a processing instruction after
    the XML declaration, the bytes as they are."""
    declaration = _DECLARATION.match(data) is not None
    if b"<!--" not in data or b"<![CDATA[" in data or data.count(b"<?") > declaration:
        return data
    return _COMMENT.sub(b"", data)


def read_document(
    path: str,
    inputs: Inputs,
    resolver: PackageResolver,
    mappings: dict[str, str] | None = None,
    force_xacro: bool = False,
) -> tuple[Document, list[Diagnostic]]:
    """Read one input and, where it uses xacro, expand it. Raises InputError."""
    files = inputs.files
    source = read_input(path, files)
    data = source.data
    file = None if path == STDIN else Path(path)
    shown = STDIN_NAME if file is None else path
    if not (force_xacro or path.endswith(".xacro")) and not is_xacro(source):
        document = Document(path, data, file, files=files)
        if len(data) <= WHOLE_UP_TO:  # (a larger one is streamed)
            document.tree = source.take_tree()  # the file's tree (parsed once), which the model reads and takes apart
        return document, []
    try:
        result = inputs.expander.expand(data, str(file) if file else None, mappings or {}, resolver, files.given())
    except ExpansionError as error:
        location = error.origin.location() if error.origin is not None else Location(error.file or shown)
        document = Document(path, None, file, is_xacro=True, includes=list(error.includes), files=files)
        document.missing_argument = error.missing_argument
        from . import xacro_warnings

        said = [xacro_warnings.warning(text, origin.location() if origin is not None else Location(shown), files, True) for text, origin in error.reported]
        return document, [*said, Diagnostic(error.code, error.message, location, hint=error.hint)]
    document = Document(path, result.text.encode("utf-8"), file, True, result.text, result.includes, result.origins, files)
    if not result.warnings:
        return document, []
    from . import xacro_warnings  # (only for an expansion xacro warned about: its words, fifteen patterns)

    return document, [
        xacro_warnings.warning(text, origin.location() if origin is not None else Location(shown), files, error)
        for text, origin, error in result.warnings
    ]

