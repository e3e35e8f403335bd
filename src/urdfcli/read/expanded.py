"""What a xacro expansion gives: the expanded text, where each of its elements was
written in the sources (its origin), the files it read, and the errors."""

from __future__ import annotations

import os
from array import array
from collections import namedtuple
from collections.abc import Sequence

from ..diagnostics import Call, Location


class Origin(namedtuple("Origin", "file line column trace", defaults=(None, ()))):
    """Where an element was written (line and column of its ``<``; ``column`` may
    be None), and the macro calls that made it (``trace``, :class:`Call`\\ s),
    innermost first. (A standard named tuple: xacro's worker sends these back.)"""

    __slots__ = ()

    def location(self) -> Location:
        return Location(self.file, self.line or None, self.column, trace=self.trace)


class ExpansionError(Exception):
    """A xacro error, with where it happened as far as it can be told."""

    def __init__(
        self, message: str, origin: Origin | None, file: str | None, code: str = "X003", includes: tuple[str, ...] = (),
        missing_argument: str | None = None, hint: str | None = None, reported: tuple = (),
    ):
        super().__init__(message)
        self.message = message
        self.origin = origin
        self.file = file
        self.code = code
        self.includes = includes  # the files read before it stopped: a library it reached is affected
        self.missing_argument = missing_argument  # a $(arg NAME) that had no value
        self.hint = hint  # what to write instead, where it can be told
        self.reported = reported  # (words, origin) of what the model said with xacro.error() before: often the cause

    def __reduce__(self):
        return (ExpansionError, (self.message, self.origin, self.file, self.code, self.includes, self.missing_argument, self.hint, self.reported))


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

    def written(self) -> dict[str, list[tuple[int, int]]]:
        """Each file's places (line, column; 0: unknown) where the expansion made an
        element or called a macro: what of the sources took part in it."""
        found: dict[str, list[tuple[int, int]]] = {}
        places = self.places
        for at in range(0, len(places), 4):
            if places[at] >= 0:
                found.setdefault(self.files[places[at]], []).append((places[at + 1], places[at + 2]))
        for file, line, column, _ in self.calls:
            if line:
                found.setdefault(file, []).append((line, column or 0))
        return found


class Expansion:
    """A xacro document expanded: its text as the ``xacro`` tool prints it, where each
    of its elements was written (one origin per element, in document order), the
    files it read, and xacro's warnings (with the errors the model printed by
    ``xacro.error()``, marked)."""

    __slots__ = ("text", "origins", "includes", "warnings")

    def __init__(self, text: str, origins: Origins, includes: list[str], warnings: list[tuple[str, Origin | None, bool]]):
        self.text = text
        self.origins = origins
        self.includes = includes
        self.warnings = warnings


def display_path(path: str) -> str:
    try:
        relative = os.path.relpath(path)
    except ValueError:
        return path
    return path if relative.startswith("..") else relative
