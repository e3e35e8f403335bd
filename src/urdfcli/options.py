"""What a run is asked to do: one frozen value, built once by the command line,
the library or the editor, and read by everything below.

Nothing below this value asks which command it is in: the rule set, the xacro
arguments, the targets, the selections over the configuration, the package
paths, the output format and the number of processes are all here.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from .model.massprops import TOLERANCE
from .rules import RuleSet

if TYPE_CHECKING:
    from .model.targets import Profile
    from .project.config import Config


class UsageError(Exception):
    """urdfcli cannot run as asked: an unreadable input, a bad package path or configuration."""


def xacro_arguments(arguments: Iterable[str]) -> dict[str, str]:
    """``NAME:=VALUE`` texts as a mapping; raises UsageError for anything else."""
    mappings = {}
    for argument in arguments:
        name, separator, value = argument.partition(":=")
        if not separator or not name:
            raise UsageError(f"bad xacro argument {argument!r}: expected NAME:=VALUE")
        mappings[name] = value
    return mappings


class AuditOptions(NamedTuple):
    """The mass-property audit of ``urdfcli inertia``: how far a tensor may be from its
    geometry's (a fraction), the density that weighs the geometry instead of the declared
    masses, and whether to suggest an <inertial> for each flagged link (``xacro``: and
    the call of the macro that wrote it)."""

    tolerance: float = TOLERANCE
    density: float | None = None
    suggest: bool = False
    xacro: bool = False


@dataclass(frozen=True)
class Options:
    """One run's options. Lists given for the tuples are kept as tuples, and target
    texts (``"mujoco"``, ``"pinocchio:mimic"``, ``"drake,kdl"``, ``"all"``) as profiles: a
    target that names no consumer raises ValueError.

    ``select`` and ``targets`` replace the configuration's, ``ignore`` and
    ``extend_select`` add to it; ``config`` is a configuration file to use instead
    of the nearest one above each input (or a :class:`Config` itself), and
    ``isolated`` reads none. With ``libraries``, a xacro library is checked through
    the models that include it; with ``srdfs``, the MoveIt SRDFs that describe the robot
    of a model given (or of one including a library given) are checked too. ``deleted`` are files a change
    deletes (or renames away): the models that include one are checked too, as for a library
    given (their include now fails). ``jobs`` other than 1 checks models in that many
    processes (0: one per CPU). ``audit`` asks for the mass-property audit, ``load``
    for a load of each model into its targets' own packages (``check --load``).
    ``format`` names the reporter of the command line. ``fix`` and ``unsafe_fixes``
    say which fixes :func:`urdfcli.api.fix` applies. ``urdf`` is the URDF an SRDF is
    checked against; ``show_info`` False has the text formats show only warnings and
    errors (the configuration's ``show-info``)."""

    rule_set: RuleSet = RuleSet.LINT
    arguments: tuple[tuple[str, str], ...] = ()  # xacro arguments NAME:=VALUE, over the configuration's
    package_paths: tuple[str, ...] = ()  # -P: NAME=DIR, or a folder to scan for package.xml
    config: Path | Config | None = None
    isolated: bool = False
    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    targets: tuple[Profile, ...] = ()
    libraries: bool = True
    srdfs: bool = False  # and the SRDFs of the models' robots (see :func:`urdfcli.project.semantic.describing`)
    deleted: tuple[str, ...] = ()  # files a change deletes: the models including one are checked too
    jobs: int = 1
    audit: AuditOptions | None = None
    load: bool = False
    format: str = "text"
    urdf: str | None = None  # --urdf: the URDF an SRDF is checked against (else the one of its robot, found nearby)
    show_info: bool | None = None  # --no-info (False), --info (True): over the configuration's show-info
    fix: bool | None = None  # apply the safe fixes (None: the configuration's ``fix``)
    unsafe_fixes: bool | None = None  # and the unsafe ones (None: the configuration's ``unsafe-fixes``)

    def __post_init__(self) -> None:
        if isinstance(self.arguments, dict):
            object.__setattr__(self, "arguments", tuple(self.arguments.items()))
        for name in ("arguments", "package_paths", "select", "ignore", "extend_select", "deleted"):
            object.__setattr__(self, name, tuple(getattr(self, name) or ()))
        if isinstance(self.config, str):
            object.__setattr__(self, "config", Path(self.config))
        chosen: list[Profile] = []
        for target in self.targets or ():
            if isinstance(target, str):
                from .targets import profiles  # (the consumers' registry: only where one is named)

                chosen += [p for text in target.split(",") if text.strip() for p in profiles(text)]
            else:
                chosen.append(target)
        object.__setattr__(self, "targets", tuple(dict.fromkeys(chosen)))

    @property
    def mappings(self) -> dict[str, str]:
        """The xacro arguments as a mapping."""
        return dict(self.arguments)

    @property
    def overrides(self) -> dict:
        """What the command line changes in each configuration (see :meth:`Config.overridden`)."""
        return {"select": self.select, "ignore": self.ignore, "extend_select": self.extend_select, "targets": self.targets, "show_info": self.show_info}

    def but(self, **changes) -> Options:
        """These options with some changed."""
        return replace(self, **changes)


__all__ = ["AuditOptions", "Options", "RuleSet", "UsageError", "xacro_arguments"]
