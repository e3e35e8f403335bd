"""A xacro expansion as the rest of urdfcli sees it: the expanded text, where each
of its elements was written, and the errors.

xacro itself runs in :mod:`.expansion`, inside the bounded worker of
:mod:`.sandbox`: this module asks for it by name, so that only the worker imports
xacro (a sixth of the start-up of a run on a small xacro file). See :func:`start`.
"""

from __future__ import annotations

import os
from array import array
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from . import sandbox
from .diagnostics import Call, Location

_EXPANSION = "urdfcli.expansion"  # where xacro runs; imported by the worker only

if TYPE_CHECKING:
    from lxml import etree

    from .packages import PackageResolver


@dataclass(frozen=True, slots=True)
class Origin:
    """Where an element was written (line and column of its ``<``), and the macro
    calls that made it, innermost first."""

    file: str
    line: int
    column: int | None = None
    trace: tuple[Call, ...] = ()


class ExpansionError(Exception):
    """A xacro error, with where it happened as far as it can be told."""

    def __init__(self, message: str, origin: Origin | None, file: str | None, code: str = "X003", includes: tuple[str, ...] = ()):
        super().__init__(message)
        self.message = message
        self.origin = origin
        self.file = file
        self.code = code
        self.includes = includes  # the files read before it stopped: a library it reached is affected

    def __reduce__(self):
        return (ExpansionError, (self.message, self.origin, self.file, self.code, self.includes))


class PackageNotFound(LookupError):
    pass


class Origins(Sequence):
    """Where each element of an expansion was written, one per element in document
    order, kept as a few lists and one array of integers: the expansion's process
    sends them whole, and as one object per element they took about a tenth of
    `check` on a model of 1,500 macro calls to pickle and unpickle. An element's
    Origin is made when it is asked for."""

    __slots__ = ("files", "calls", "traces", "places")

    def __init__(self, files: list[str], calls: list[tuple], traces: list[tuple[int, ...]], places: array):
        self.files = files
        self.calls = calls  # each macro call site as Call's fields
        self.traces = traces  # the calls around an element (indices in `calls`), innermost first
        self.places = places  # per element: file index (-1: unknown), line, column (0: none), trace index

    def __len__(self) -> int:
        return len(self.places) // 4

    def __getitem__(self, index: int) -> Origin | None:
        at = range(len(self))[index] * 4  # (raises IndexError as a list does)
        file, line, column, trace = self.places[at : at + 4]
        if file < 0:
            return None
        return Origin(self.files[file], line, column or None, tuple(Call(*self.calls[i]) for i in self.traces[trace]))


@dataclass
class Expansion:
    text: str  # the expanded document, as `xacro` prints it
    origins: Origins  # one per element of `text`, in document order
    includes: list[str]
    warnings: list[tuple[str, Origin | None]] = field(default_factory=list)


def located(origin: Origin | None, file: str) -> Location:
    """The location of an origin; just ``file`` when there is none."""
    if origin is None:
        return Location(file)
    return Location(origin.file, origin.line or None, origin.column, trace=origin.trace)


def display_path(path: str) -> str:
    try:
        relative = os.path.relpath(path)
    except ValueError:
        return path
    return path if relative.startswith("..") else relative


def start() -> None:
    """Start the xacro worker now, importing xacro, when a second CPU can do that
    while this process goes on importing the model and its rules (on one CPU the
    worker starts at the first expansion, as it would)."""
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    if cpus > 1:
        sandbox.start(_EXPANSION)


def expand(
    root: etree._Element,
    file: str | None,
    mappings: dict[str, str],
    resolver: "PackageResolver",
    data: bytes | None = None,
) -> Expansion:
    """Expand the parsed xacro document ``root`` read from ``file`` (None: stdin) as ``data``.

    The expansion runs under sandbox.bounded: limited in time and memory.
    """
    try:
        return sandbox.bounded(sandbox.call, _EXPANSION, "expand_here", root, file, mappings, resolver, data)
    except sandbox.LimitExceeded as error:
        shown = display_path(file) if file else "<stdin>"
        raise ExpansionError(f"xacro expansion stopped: {error} (the limit for one file)", None, shown) from None
