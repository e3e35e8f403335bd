"""The one problem type every part of urdfcli reports, and where it points.

A diagnostic is a plain value: what was found (``code``, ``message``, ``hint``),
where (``location``, with the xacro macro calls that made the element), and
what it is about (``subjects``: the names of the links or joints). Readers and
rules make them without a severity; the linter gives each one its rule's
severity, or the one the configuration sets (see :mod:`urdfcli.project.linter`).
A rule that knows better than its default (a finding on a 5 g link) gives one.

A diagnostic may carry its ``fix``: what to change in the robot (``changes``,
about elements of the model as read) or in a file (``edits``, spans of a source's
text), how safe that is, and, where no edit can be made, why.
"""

from __future__ import annotations

from collections import namedtuple
from enum import Enum
from typing import NamedTuple


class Severity(str, Enum):
    ERROR = "error"
    WARNING = "warning"
    INFO = "info"

    @property
    def rank(self) -> int:
        return _RANKS[self.value]


_RANKS = {"error": 2, "warning": 1, "info": 0}


class Call(namedtuple("Call", "file line column macro")):
    """A xacro macro call: where it was written (``line`` and ``column`` may be
    None), and the name of the macro it called. (A standard named tuple: xacro's
    worker makes these and sends them back.)"""

    __slots__ = ()

    @property
    def phrase(self) -> str:
        """Where it was written: ``in macro 'wheel' called at FILE:LINE:COL``."""
        where = ":".join([self.file] + ([str(self.line), str(self.column or 1)] if self.line else []))
        return f"in macro '{self.macro}' called at {where}"


class Location(NamedTuple):
    """Where an element was written.

    ``expanded`` is true when the line is in the xacro-expanded document
    because the element's origin in the sources could not be determined.
    ``trace`` lists the macro calls that made the element, innermost first.
    """

    file: str
    line: int | None = None
    column: int | None = None
    expanded: bool = False
    trace: tuple[Call, ...] = ()


class Applicability(str, Enum):
    """How safe a fix is, as ruff means it: ``safe`` keeps the robot's meaning (a
    declaration, a file name, a path, a deprecated form xacro still reads);
    ``unsafe`` changes a mass, a pose, a limit, a scale, a shape or the expansion."""

    SAFE = "safe"
    UNSAFE = "unsafe"


class Edit(NamedTuple):
    """Replace ``start:end`` of a source's text (``file`` as diagnostics name it;
    offsets in characters of the text with its line ends read as ``\\n``, as
    :class:`urdfcli.read.positions.Source` keeps it) by ``text``."""

    file: str
    start: int
    end: int
    text: str


class SetAttribute(NamedTuple):
    """Give attribute ``attribute`` of the model's element ``at`` (its index in the
    document read, the xacro expansion for a xacro input) the value ``value``."""

    at: int
    attribute: str
    value: str


class InsertChild(NamedTuple):
    """Write ``markup`` as the first child of the model's element ``at``."""

    at: int
    markup: str


Change = SetAttribute | InsertChild


class Fix(NamedTuple):
    """What fixes a diagnostic. A rule gives ``changes`` to the model, or ``edits``
    of a file directly (what it found in a file as written); the changes are then
    placed where their values were written (:mod:`urdfcli.model.written`), which
    turns them into edits, or into the ``reason`` no edit can be made."""

    title: str  # what it does: ``swap lower and upper of joint 'elbow'``
    applicability: Applicability
    edits: tuple[Edit, ...] = ()
    changes: tuple[Change, ...] = ()
    reason: str | None = None  # why there is no edit (the value is computed by an expression...)
    inputs: tuple[tuple[int, str], ...] = ()  # (element, attribute): values the changes were worked out from, which must be the same for every call

    @property
    def available(self) -> bool:
        """Whether the fix can be applied: it has edits, and nothing keeps it from being placed."""
        return bool(self.edits) and not self.changes and self.reason is None

    @property
    def safe(self) -> bool:
        return self.applicability is Applicability.SAFE


class Diagnostic(NamedTuple):
    code: str
    message: str
    location: Location
    element: str | None = None  # an element path such as joint[@name='elbow']
    hint: str | None = None
    severity: Severity | None = None  # None until the linter gives the rule's or the configured one
    subjects: tuple[str, ...] = ()  # the links or joints it is about
    model: str | None = None  # located in a xacro library: the model (and arguments) whose expansion found it
    fix: Fix | None = None  # what fixes it, or why nothing can

    @property
    def through(self) -> str | None:
        """``found through model robot.urdf.xacro``, for a diagnostic a model found in a library."""
        return f"found through model {self.model}" if self.model else None

    @property
    def path(self) -> str:
        return self.location.file

    file = path

    @property
    def line(self) -> int | None:
        return self.location.line

    @property
    def column(self) -> int | None:
        return self.location.column

    @property
    def trace(self) -> tuple[Call, ...]:
        return self.location.trace

    def with_severity(self, severity: Severity) -> Diagnostic:
        return self._replace(severity=severity)

    def with_fix(self, fix: Fix | None) -> Diagnostic:
        return self._replace(fix=fix)

    def sort_key(self) -> tuple:
        trace = tuple((c.file, c.line or 0, c.column or 0) for c in self.location.trace)
        return (self.path, self.line or 0, self.column or 0, self.code, trace)


def joined(parts) -> str:
    """``a, b and c``: how a message lists what it names."""
    parts = list(parts)
    return ", ".join(parts[:-1]) + " and " + parts[-1] if len(parts) > 1 else "".join(parts)
