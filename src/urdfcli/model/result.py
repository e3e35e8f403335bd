"""What urdfcli found in one input: the one result type every command produces, a
value made whole by the pipeline and then only read; and why an input could not be
read at all."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, NamedTuple

from ..diagnostics import Diagnostic, Severity

if TYPE_CHECKING:
    from .audit import Audit
    from .load import Loaded
    from .meshes import MeshFile
    from .robot import Robot
    from .targets import Verdict


class Library(NamedTuple):
    """For a xacro library (macros only): the models it was checked through, and
    why others could not check it."""

    checked_through: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    unchecked: bool = False  # a file of a folder that no model read: named in a note, not counted as checked
    fragment: bool = False  # a model's part in a file of its own, not a library of macros
    read: tuple[str, ...] = ()  # the models it was checked through and the files their expansions read


class Unreadable(NamedTuple):
    """An input that could not be read at all, and the one-line reason (exit code 2)."""

    path: str
    reason: str

    def __str__(self) -> str:
        return self.reason


@dataclass(frozen=True)
class Result:
    """One input checked: its diagnostics (configuration and suppressions applied,
    each with its severity), the model it read, and for a xacro library the models
    it was checked through.

    ``path`` is the input as given; ``arguments`` the xacro arguments of a run listed
    in ``[tool.urdfcli] models``. ``loaded`` (the document and robot read) is None
    for a library, an unreadable input, and a result sent back from another process
    (``robot_name`` is kept). ``includes`` are the files the xacro expansion read;
    ``needs_argument`` a xacro argument the model needs and was not given; ``called``
    the names of the macros the expansion called (as written after ``xacro:``; None when
    not known: no expansion, or one that failed); ``meshes``
    what ``lint`` read of each mesh file; ``audit`` the mass-property audit of
    ``urdfcli inertia``; ``compatibility`` what each consumer of ``--target`` does
    with the model, as urdfcli predicts it."""

    path: str
    diagnostics: tuple[Diagnostic, ...] = ()
    loaded: Loaded | None = None
    arguments: tuple[tuple[str, str], ...] = ()
    library: Library | None = None
    includes: tuple[str, ...] = ()
    needs_argument: str | None = None
    called: tuple[str, ...] | None = None
    meshes: tuple[MeshFile, ...] = ()
    audit: Audit | None = None
    compatibility: tuple[Verdict, ...] = ()
    robot_name: str | None = None  # the robot's name: told by ``loaded`` when it is there
    show_info: bool = True  # whether its info diagnostics are shown, in every format (its configuration's show-info)
    failed: bool | None = None  # set when a batch shows some of its findings under another model: whether they held an error

    def __post_init__(self) -> None:
        robot = self.loaded.robot if self.loaded is not None else None
        semantic = self.loaded.semantic if self.loaded is not None else None
        if robot is not None or semantic is not None:  # (an SRDF names its robot too)
            object.__setattr__(self, "robot_name", robot.name if robot is not None else semantic.name)

    @property
    def robot(self) -> Robot | None:
        """The model read: ``robot.links`` and ``robot.joints`` by name; None when no robot
        could be read (not well-formed, a root that is not ``<robot>``, an SRDF)."""
        return self.loaded.robot if self.loaded is not None and self.loaded.modelled else None

    @property
    def label(self) -> str:
        if not self.arguments:
            return self.path
        return f"{self.path} [{' '.join(f'{k}:={v}' for k, v in self.arguments)}]"

    @property
    def shown(self) -> str:
        """The input as diagnostics name it ("<stdin>" for standard input)."""
        return "<stdin>" if self.path == "-" else self.path

    @property
    def displayed(self) -> list[Diagnostic]:
        """The diagnostics the formats show (the summaries count all): info too unless its configuration hides it."""
        if self.show_info:
            return self.diagnostics
        return [d for d in self.diagnostics if d.severity is not Severity.INFO]

    def of_severity(self, severity: Severity) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity is severity]

    @property
    def errors(self) -> list[Diagnostic]:
        return self.of_severity(Severity.ERROR)

    @property
    def warnings(self) -> list[Diagnostic]:
        return self.of_severity(Severity.WARNING)

    @property
    def infos(self) -> list[Diagnostic]:
        return self.of_severity(Severity.INFO)

    @property
    def ok(self) -> bool:
        """No error (warnings allowed), among all the model's findings: a library's mistake
        that a batch shows once, under another model, breaks this one too."""
        return not self.errors if self.failed is None else not self.failed

    def but(self, **changes) -> Result:
        """This result with some fields changed (a new value)."""
        return replace(self, **changes)

    def detached(self) -> Result:
        """The same result without the model read (to send to another process)."""
        return replace(self, loaded=None, audit=None)

    def __repr__(self) -> str:
        counts = f"{len(self.errors)} errors, {len(self.warnings)} warnings"
        return f"<Result {self.label!r}: {counts}>"


__all__ = ["Library", "Result", "Unreadable"]
