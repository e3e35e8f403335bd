"""Load one input with its configuration applied: the path every command shares.

``load`` gives the diagnostics of the rules a command runs; this module
re-runs the rules whose options the configuration changes, keeps the rules
the configuration selects for the file, applies severity overrides, and drops
what suppression comments silence. ``check``, ``lint``, ``inertia``, ``tree``
and ``graph`` all load through :func:`load_configured`, so configuration and
``noqa`` comments mean the same everywhere. Nothing here exits the process;
:class:`Linted` results are plain, picklable data so that files can be
linted in other processes.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import NamedTuple

from .config import Config
from .diagnostics import Diagnostic, Location, Severity
from .document import SUPPRESSION_MARK
from .load import STDIN, InputError, LoadOptions, load, load_document, read_input
from .loaded import Loaded
from .packages import PackageError, PackageResolver
from .rules import rule
from . import positions, suppressions

# xacro's words for $(arg NAME) when NAME has no value, and what urdfcli says instead
_UNDEFINED_ARGUMENT = re.compile(r"\bUndefined substitution argument (\w+)")
NEEDS_ARGUMENT = re.compile(r"^needs xacro argument '([^']+)'")


class RobotName(NamedTuple):
    name: str | None


class Linted:
    """What the formatters need of a linted file (the shape of a Loaded)."""

    def __init__(self, path: str, robot: RobotName | None, diagnostics: list[Diagnostic], includes: tuple[str, ...]) -> None:
        self.path = path
        self.robot = robot
        self.diagnostics = diagnostics
        self.includes = includes  # every file the xacro expansion read

    @property
    def ok(self) -> bool:
        return not any(d.severity is Severity.ERROR for d in self.diagnostics)


def load_configured(
    path: str,
    config: Config,
    package_paths: tuple[str, ...] = (),
    mappings: dict[str, str] | None = None,
    data: bytes | None = None,
    checks: str = "all",
    alone: bool = False,
    unchecked: str = "",
) -> Loaded:
    """Load one input and keep the diagnostics its configuration and suppressions leave.

    ``checks`` names the rules that run ("check", "all" or "none"); ``alone``
    expands a xacro library on its own and keeps only what reading and
    expanding it reports (its macros are not called, so there is no robot to
    judge); ``unchecked`` says why the models that include it could not check it
    (X006). Raises InputError (unreadable) or PackageError (bad -P).
    """
    if data is None and path == STDIN:
        data = read_input(path)
    # A rule the configuration turns off everywhere does not run (per-file ignores are applied to what runs).
    options = LoadOptions(config.package_paths + tuple(package_paths), {**config.mappings_for(path), **(mappings or {})}, checks, config.enabled)
    if alone:
        resolver = PackageResolver(options.package_paths, None if path == STDIN else Path(path))
        document, found = load_document(path, options, data, resolver=resolver)
        loaded = Loaded(document, diagnostics=found, resolver=resolver)
        if unchecked:
            loaded.diagnostics.append(Diagnostic.of(
                "X006",
                f"xacro library checked on its own only: no model that includes it could check it ({unchecked})",
                Location(document.shown),
                hint='list their argument sets in [tool.urdfcli] models, e.g. models = { "urdf/robot.urdf.xacro" = [["name:=robot"]] }',
            ))
    else:
        loaded = load(path, options, data)
    loaded.diagnostics = configured(loaded, path, config, checks)
    return loaded


def configured(
    loaded: Loaded, path: str, config: Config, checks: str = "all", diagnostics: list[Diagnostic] | None = None
) -> list[Diagnostic]:
    """A loaded file's diagnostics (or the ``diagnostics`` given, found on it)
    after configuration and suppression comments. A suppression naming a rule
    that did not run under ``checks`` is not reported as unused."""
    def ran(code: str) -> bool:
        spec = rule(code)  # loads every rule module only for a code not met yet
        return checks == "all" or spec.function is None or (checks == "check" and spec.in_check)

    rerun = diagnostics is None
    diagnostics = [_explained(d, path) for d in (loaded.diagnostics if diagnostics is None else diagnostics)]
    configured_options = {code: values for code, values in config.rule_options().items() if ran(code)}
    if rerun and configured_options and loaded.robot is not None and loaded.robot.at is not None:
        diagnostics = [d for d in diagnostics if d.code not in configured_options]
        for code, values in configured_options.items():
            diagnostics.extend(rule(code).run(loaded, values))

    def enabled(code: str, file: str) -> bool:
        return config.enabled(rule(code), path, file)

    unreadable = not loaded.document.readable  # why nothing was checked is never selected away
    selected = [d for d in diagnostics if unreadable or enabled(d.code, d.file)]
    files = {loaded.document.shown, *loaded.document.includes}
    files |= {place.file for d in selected for place in (d.location, *d.location.trace)}
    if loaded.document.may_suppress is False:  # told while its bytes were read
        files.discard(loaded.document.shown)
    sources = [] if unreadable else sorted(files)  # nor silenced by a comment
    found = [s for file in sources if (text := positions.text_of(file, containing=SUPPRESSION_MARK)) is not None for s in suppressions.parse(file, text)]
    kept = suppressions.apply(selected, found, lambda code: ran(code) and enabled(code, path))
    kept = [d for d in kept if d.code not in ("U001", "U002") or enabled(d.code, d.file)]
    kept = [_with_severity(d, config) for d in kept]
    kept.sort(key=Diagnostic.sort_key)
    return kept


def _explained(diagnostic: Diagnostic, path: str) -> Diagnostic:
    """xacro's 'Undefined substitution argument X', said so that it names the fix for the input ``path``."""
    match = _UNDEFINED_ARGUMENT.search(diagnostic.message) if diagnostic.code == "X003" else None
    if match is None:
        return diagnostic
    name = match.group(1)
    message = (f"needs xacro argument '{name}': it has no value where it is used (no default, or used before its "
               f"<xacro:arg>); pass {name}:=VALUE, or list the model's argument sets in [tool.urdfcli] models")
    file = Path(path).name if path != STDIN else "FILE"
    hint = f'give {name}:=VALUE after the file on the command line, or in pyproject.toml: [tool.urdfcli.xacro-args] "{file}" = {{ {name} = "VALUE" }}'
    return Diagnostic(diagnostic.code, diagnostic.severity, message, diagnostic.location, diagnostic.element, diagnostic.hint or hint)


def lint_file(
    path: str,
    config: Config,
    package_paths: tuple[str, ...] = (),
    mappings: dict[str, str] | None = None,
    data: bytes | None = None,
    alone: bool = False,
    unchecked: str = "",
) -> Linted:
    """Lint one input. Raises InputError (unreadable) or PackageError (bad -P)."""
    return _linted(load_configured(path, config, package_paths, mappings, data, "all", alone, unchecked))


def _linted(loaded: Loaded) -> Linted:
    robot = RobotName(loaded.robot.name) if loaded.robot is not None else None
    return Linted(loaded.path, robot, loaded.diagnostics, tuple(loaded.document.includes))


def _with_severity(diagnostic: Diagnostic, config: Config) -> Diagnostic:
    severity = config.severity_of(diagnostic.code, diagnostic.severity)
    return diagnostic if severity is diagnostic.severity else diagnostic.with_severity(severity)


class Job(NamedTuple):
    path: str
    config: Config
    package_paths: tuple[str, ...] = ()
    mappings: tuple[tuple[str, str], ...] = ()
    alone: bool = False
    unchecked: str = ""

    @classmethod
    def of(cls, target, config: Config, package_paths: tuple[str, ...], mappings: dict[str, str]) -> "Job":
        """The load of a urdfcli.workspace.Target: its argument set over the command line's."""
        arguments = tuple({**mappings, **dict(target.arguments)}.items())
        return cls(target.path, config, package_paths, arguments, target.alone, target.unchecked)

    def load(self, checks: str) -> Loaded:
        """The configured load; raises InputError or PackageError as load_configured does."""
        return load_configured(self.path, self.config, self.package_paths, dict(self.mappings), None, checks, self.alone, self.unchecked)


def run_job(job: Job) -> Linted | str:
    """Lint in a worker: the result, or the one-line reason the file could not be read."""
    try:
        return _linted(job.load("all"))
    except (InputError, PackageError) as error:
        return str(error)


__all__ = ["Job", "Linted", "configured", "lint_file", "load_configured", "run_job"]
