"""A session's source files: each read once, and what is worked out from it once.

A :class:`SourceFile` is one file as read from disk (or as an editor holds it,
unsaved): its bytes, and, each computed the first time it is asked for and then
kept, its text with the positions of its lines and elements (it is a
:class:`~urdfcli.read.positions.Text`), its XML tree with where each element
starts, and its xacro scan (what it defines and uses, macro signatures split
with xacro's grammar). The expansion, the rules, the editor's outline, the
fixes and the diagnostics' excerpts all read the one object.

:class:`SourceFiles` are a session's: a file is read again only when it changes
on disk (or an editor gives a new text for it); ``reads`` and ``parses`` count
what was read and parsed, so that a test can hold the promise.
"""

from __future__ import annotations

import contextlib
import os
import weakref
from collections import Counter
from collections.abc import Callable
from functools import cached_property
from pathlib import Path
from typing import Any, TypeVar

from .positions import Text, decode
from .xacro_scan import XacroFile, scan
from .xml import WHOLE_UP_TO, Element, XmlError, parse

T = TypeVar("T")

STDIN_NAME = "<stdin>"


def file_key(name: str | os.PathLike) -> str:
    """A file's name as a session keeps it: its absolute path ("<stdin>" as it is)."""
    name = os.fspath(name)
    return name if name.startswith("<") else os.path.abspath(name)


class SourceFile(Text):
    """One source file's bytes and what is worked out from them (see the module).

    ``name`` is the file as diagnostics name it; ``data`` its bytes. ``text`` (the
    decoded text, line ends normalised) and the positions of :class:`Text`, ``tree``,
    ``error``, ``elements``, ``starts`` and ``scan`` are computed when first asked for."""

    def __init__(self, name: str, data: bytes, files: SourceFiles | None = None) -> None:
        self.name = name
        self.data = data
        self._asked = 0
        self._files = files  # whose ``parses`` count this file's

    @cached_property
    def text(self) -> str:
        text = decode(self.data)
        return text.replace("\r\n", "\n").replace("\r", "\n") if "\r" in text else text

    @cached_property
    def _parsed(self) -> tuple[Element | None, XmlError | None]:
        if self._files is not None:
            self._files.parses[file_key(self.name)] += 1
        try:
            return parse(self.data), None
        except XmlError as error:
            return None, error

    @property
    def tree(self) -> Element | None:
        """The root of the document, elements only (see :func:`urdfcli.read.xml.parse`);
        None when it is not well-formed XML (``error`` says why)."""
        return self._parsed[0]

    @property
    def error(self) -> XmlError | None:
        """Why the document is not well-formed XML (None when it is)."""
        return self._parsed[1]

    def take_tree(self) -> Element | None:
        """The tree, for a reader that takes its elements out as it goes (the model
        reader of a plain URDF, which keeps no tree): the file lets go of it, and parses
        the document again should anything ask for its tree later."""
        tree = self.tree
        for worked_out in ("_parsed", "elements", "_element_starts"):
            self.__dict__.pop(worked_out, None)
        return tree

    @cached_property
    def elements(self) -> list[Element]:
        """Every element of the tree, in document order (none when not well-formed)."""
        root = self.tree
        return list(root.iter()) if root is not None else []

    @cached_property
    def _element_starts(self) -> dict[Element, int] | None:
        elements = self.elements
        starts = self.element_starts(len(elements))
        return dict(zip(elements, starts)) if starts is not None else None

    def start_of(self, element: Element) -> int | None:
        """The offset of an element's ``<`` in the text (None when the text cannot tell)."""
        starts = self._element_starts
        return starts.get(element) if starts is not None else None

    def place_of(self, element: Element) -> tuple[int, int | None]:
        """The line and column of an element's ``<``; libxml2's line (where its start tag
        ends) and no column when the text cannot tell."""
        start = self.start_of(element)
        if start is None:
            return element.sourceline or 1, None
        return self.position(start)

    @cached_property
    def scan(self) -> XacroFile | None:
        """What the file defines, uses and makes as xacro (None when it is not XML)."""
        return scan(self.tree, self.name, self) if self.tree is not None else None


class SourceFiles:
    """The files of a session (see the module). Names are paths as diagnostics give them
    (relative to the working folder, or absolute); "<stdin>" is standard input. A file
    larger than WHOLE_UP_TO is kept only while something uses it: a large model's
    text is not held beside the model."""

    def __init__(self) -> None:
        self._kept: dict[str, tuple[tuple[int, int], SourceFile]] = {}  # key -> (file stamp, file)
        self._large: weakref.WeakValueDictionary[str, SourceFile] = weakref.WeakValueDictionary()
        self._stamps: dict[str, tuple[int, int]] = {}  # of the large files
        self._given: dict[str, bytes] = {}
        self._given_files: dict[str, SourceFile] = {}  # made when first read, named as first asked for
        self._derived: dict[tuple[str, Callable], tuple[tuple[int, int], Any]] = {}  # (key, what) -> (file stamp, value)
        self.reads: Counter[str] = Counter()  # file key -> times read from disk
        self.parses: Counter[str] = Counter()  # file key -> XML trees made of it

    def give(self, name: str, data: bytes) -> None:
        """Let ``data`` stand for the file ``name`` (or standard input) from now on (the
        same text given again keeps what was worked out from it)."""
        key = file_key(name)
        if self._given.get(key) == data:
            return
        self._given[key] = data
        self._given_files.pop(key, None)

    def take_back(self, name: str) -> None:
        """Read ``name`` from its file again."""
        key = file_key(name)
        self._given.pop(key, None)
        self._given_files.pop(key, None)

    def given(self) -> dict[str, bytes]:
        """The texts given (absolute path -> bytes), for a xacro expansion to read."""
        return dict(self._given)

    def read(self, name: str | os.PathLike) -> SourceFile:
        """The file ``name``: as given, or as on disk (read again only when it changed).
        Raises OSError."""
        key = file_key(name)
        if key in self._given:
            given = self._given_files.get(key)
            if given is None:
                given = self._given_files[key] = SourceFile(_shown(os.fspath(name)), self._given[key], self)
            return given
        status = os.stat(key)
        stamp = (status.st_mtime_ns, status.st_size)
        kept = self._kept.get(key)
        if kept is not None and kept[0] == stamp:
            return kept[1]
        large = self._large.get(key)
        if large is not None and self._stamps.get(key) == stamp:
            return large
        data = Path(key).read_bytes()
        self.reads[key] += 1
        found = SourceFile(_shown(os.fspath(name)), data, self)
        if len(data) > WHOLE_UP_TO:
            self._large[key] = found
            self._stamps[key] = stamp
            self._kept.pop(key, None)
        else:
            self._kept[key] = (stamp, found)
        return found

    def derived(self, name: str | os.PathLike, compute: Callable[[Path, SourceFile | None], T]) -> T:
        """``compute(path, file)`` (file None: unreadable), kept until the file changes on
        disk: a large file is not kept in memory, and what a look across the workspace
        asks of every file would read it again each time. Worked out anew for a given text."""
        key = file_key(name)
        stamp = None
        if key not in self._given:
            with contextlib.suppress(OSError):
                status = os.stat(key)
                stamp = status.st_mtime_ns, status.st_size
        known = self._derived.get((key, compute))
        if stamp is not None and known is not None and known[0] == stamp:
            return known[1]
        value = compute(Path(key), self.get(name))
        if stamp is not None:
            self._derived[key, compute] = (stamp, value)
        return value

    def get(self, name: str | os.PathLike) -> SourceFile | None:
        """The file ``name``, or None when it cannot be read."""
        try:
            return self.read(name)
        except OSError:
            return None

    def line(self, name: str, number: int) -> str | None:
        """One line of a file (1-based), or None when there is no such line."""
        found = self.get(name)
        return found.line(number) if found is not None else None


def _shown(name: str) -> str:
    """A file's name as diagnostics give it: as given, "<stdin>" for standard input."""
    return STDIN_NAME if name in ("-", STDIN_NAME) else name


__all__ = ["STDIN_NAME", "SourceFile", "SourceFiles", "file_key"]
