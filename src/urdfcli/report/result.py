"""What urdfcli found in one input: the one result type every command produces."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

from ..diagnostics import Diagnostic, Severity

if TYPE_CHECKING:
    from ..model.load import Loaded
    from ..model.robot import Robot


class Library(NamedTuple):
    """For a xacro library (macros only): the models it was checked through, and
    why others could not check it."""

    checked_through: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()


class Result:
    """One input checked: its diagnostics (configuration and suppressions applied,
    each with its severity), the model it read, and for a xacro library the models
    it was checked through.

    ``path`` is the input as given; ``label`` adds the xacro arguments of a run
    listed in ``[tool.urdfcli] models``. ``loaded`` (the document and robot read)
    is None for a library, an unreadable input, and a result sent back from
    another process (``robot_name`` is kept). ``audit`` is the mass-property
    audit of ``urdfcli inertia``; ``meshes`` what ``lint`` read of each mesh file.
    """

    def __init__(
        self,
        path: str,
        diagnostics: list[Diagnostic],
        loaded: Loaded | None = None,
        arguments: dict[str, str] | None = None,
        library: Library | None = None,
        includes: tuple[str, ...] = (),
        needs_argument: str | None = None,
        meshes: tuple[dict, ...] = (),
    ) -> None:
        self.path = path
        self.diagnostics = diagnostics
        self.loaded = loaded
        self.arguments = dict(arguments or {})
        self.library = library
        self.includes = includes  # every file the xacro expansion read
        self.needs_argument = needs_argument  # a xacro argument the model needs and was not given
        self.meshes = meshes  # what lint read of each mesh file (model.meshes.mesh_facts), for JSON
        robot = loaded.robot if loaded is not None else None
        self.robot_name: str | None = robot.name if robot is not None else None
        self.audit: Any = None

    @property
    def robot(self) -> Robot | None:
        """The model read: ``robot.links`` and ``robot.joints`` by name."""
        return self.loaded.robot if self.loaded is not None else None

    @property
    def label(self) -> str:
        if not self.arguments:
            return self.path
        return f"{self.path} [{' '.join(f'{k}:={v}' for k, v in self.arguments.items())}]"

    @property
    def shown(self) -> str:
        """The input as diagnostics name it ("<stdin>" for standard input)."""
        return "<stdin>" if self.path == "-" else self.path

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
        """No error (warnings allowed)."""
        return not self.errors

    def report(self) -> str:
        """The diagnostics as the text format writes them, with a summary line."""
        from .text import plain_report

        return plain_report([self])

    def detached(self) -> Result:
        """The same result without the model read (to send to another process)."""
        result = Result(self.path, self.diagnostics, None, self.arguments, self.library, self.includes, self.needs_argument, self.meshes)
        result.robot_name = self.robot_name
        return result

    def __repr__(self) -> str:
        counts = f"{len(self.errors)} errors, {len(self.warnings)} warnings"
        return f"<Result {self.label!r}: {counts}>"
