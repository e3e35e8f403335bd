"""A xacro expansion as the rest of urdfcli sees it: the expanded text, where each
of its elements was written, and the errors.

xacro itself runs in :mod:`.expansion`, inside the bounded worker of
:mod:`.sandbox`: this module asks for it by name, so that only the worker imports
xacro (a sixth of the start-up of a run on a small xacro file). See :func:`started`.
"""

from __future__ import annotations

import contextlib
import os
from array import array
from collections.abc import Iterator, Sequence

from . import sandbox
from .places import Call, Origin

_EXPANSION = "urdfcli.expansion"  # where xacro runs; imported by the worker only

TYPE_CHECKING = False  # typing's flag, without typing: the worker imports this module
if TYPE_CHECKING:
    from .diagnostics import Location
    from .packages import PackageResolver


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


class Expansion:
    """A xacro document expanded: its text as the ``xacro`` tool prints it, where each
    of its elements was written (one origin per element, in document order), the
    files it read, and xacro's warnings."""

    __slots__ = ("text", "origins", "includes", "warnings")

    def __init__(self, text: str, origins: Origins, includes: list[str], warnings: list[tuple[str, Origin | None]]):
        self.text = text
        self.origins = origins
        self.includes = includes
        self.warnings = warnings


def located(origin: Origin | None, file: str) -> Location:
    """The location of an origin; just ``file`` when there is none."""
    from .diagnostics import Location

    if origin is None:
        return Location(file)
    return Location(origin.file, origin.line or None, origin.column, trace=origin.trace)


def display_path(path: str) -> str:
    try:
        relative = os.path.relpath(path)
    except ValueError:
        return path
    return path if relative.startswith("..") else relative


@contextlib.contextmanager
def started(path: str | None = None, mappings: dict[str, str] | None = None) -> Iterator[None]:
    """Start the xacro worker now, importing xacro, for the run in the block, when a
    second CPU can do that while this process goes on importing the model and its
    rules (on one CPU the worker starts at the first expansion, as it would).

    Given the run's first xacro input (``path``) and the xacro arguments of its
    command line, the worker expands it with them right away: when the run asks
    for that very expansion (the same text, arguments, package paths,
    environment and folder), the answer is there or on its way. Any other first
    expansion (a library checked through the models that include it, arguments
    from a configuration file) drops it: read and left when done, else stopped
    with the worker. So is one not asked for by the end of the block.
    """
    global _ahead
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    if cpus > 1:
        sandbox.start(_EXPANSION)
        if path is not None:
            _ahead = _sent_ahead(path, mappings or {})
    try:
        yield
    finally:
        ahead, _ahead = _ahead, None
        if ahead is not None:
            ahead[1].drop()


def answered_ahead() -> bool:
    """Whether the expansion :func:`started` sent is done, its answer waiting."""
    return _ahead is not None and _ahead[1].answered()


def _sent_ahead(path: str, mappings: dict[str, str]) -> tuple[tuple, sandbox.Sent] | None:
    from pathlib import Path

    from .packages import PackageResolver

    try:
        file = Path(path)
        job = (file.read_bytes(), str(file), dict(mappings), PackageResolver((), file))
        return _same_job(*job), sandbox.Sent(sandbox.call, _EXPANSION, "expand_here", *job)
    except Exception:  # noqa: BLE001 - not readable, or no process to spare: the run says what is wrong when it gets there
        return None


_ahead: tuple[tuple, sandbox.Sent] | None = None  # the expansion :func:`started` sent, until the first one asked for


def _same_job(data: bytes | None, file: str | None, mappings: dict[str, str], resolver: "PackageResolver") -> tuple:
    """What an expansion depends on: equal for two jobs, the same answer."""
    try:
        folder = os.getcwd()
    except OSError:  # a working folder removed: no job sent ahead was sent from it
        folder = None
    return (data, file, sorted(mappings.items()), resolver.settings(), sorted(os.environ.items()), folder)


def expand(data: bytes, file: str | None, mappings: dict[str, str], resolver: "PackageResolver") -> Expansion:
    """Expand the xacro document ``data`` read from ``file`` (None: stdin).

    The expansion runs under sandbox.bounded: limited in time and memory. The first
    one takes the answer to the same job sent ahead by :func:`started`, if any.
    """
    global _ahead
    ahead, _ahead = _ahead, None
    try:
        if ahead is not None and ahead[0] == _same_job(data, file, mappings, resolver):
            return ahead[1].result()
        if ahead is not None:
            ahead[1].drop()
        return sandbox.bounded(sandbox.call, _EXPANSION, "expand_here", data, file, mappings, resolver)
    except sandbox.LimitExceeded as error:
        shown = display_path(file) if file else "<stdin>"
        raise ExpansionError(f"xacro expansion stopped: {error} (the limit for one file)", None, shown) from None
