"""Lint one file: every rule's diagnostics, then configuration and suppressions.

``load(..., checks="all")`` gives the diagnostics of every rule; the linter
re-runs the rules whose options the configuration changes, keeps the rules
the configuration selects for the file, applies severity overrides, and drops
what suppression comments silence. Nothing here exits the process; results
are plain, picklable data so that files can be linted in other processes.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .config import Config
from .diagnostics import Diagnostic, Severity
from .load import STDIN, InputError, LoadOptions, load, read_input
from .packages import PackageError
from .rules import load_all
from . import suppressions


@dataclass(frozen=True)
class RobotName:
    name: str | None


@dataclass
class Linted:
    """What the formatters need of a linted file (the shape of a Loaded)."""

    path: str
    robot: RobotName | None
    diagnostics: list[Diagnostic] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not any(d.severity is Severity.ERROR for d in self.diagnostics)


def lint_file(path: str, config: Config, package_paths: tuple[str, ...] = (), mappings: dict[str, str] | None = None, data: bytes | None = None) -> Linted:
    """Lint one input. Raises InputError (unreadable) or PackageError (bad -P)."""
    if data is None and path == STDIN:
        data = read_input(path)
    options = LoadOptions(config.package_paths + tuple(package_paths), {**config.mappings_for(path), **(mappings or {})}, checks="all")
    loaded = load(path, options, data)
    diagnostics = loaded.diagnostics
    registry = load_all()
    configured = config.rule_options()
    if configured and loaded.robot is not None and loaded.robot.element is not None:
        diagnostics = [d for d in diagnostics if d.code not in configured]
        for code, values in configured.items():
            diagnostics.extend(registry[code].run(loaded, values))

    def enabled(code: str, file: str) -> bool:
        return config.enabled(registry[code], path, file)

    selected = [d for d in diagnostics if enabled(d.code, d.file)]
    sources = _sources(loaded.document.shown, path, data, {d.file for d in selected} | set(loaded.document.includes))
    found = [s for file, text in sources.items() for s in suppressions.parse(file, text)]
    kept = suppressions.apply(selected, found, lambda code: enabled(code, path))
    kept = [d for d in kept if d.code not in ("U001", "U002") or enabled(d.code, d.file)]
    kept = [_with_severity(d, config) for d in kept]
    kept.sort(key=Diagnostic.sort_key)
    robot = RobotName(loaded.robot.name) if loaded.robot is not None else None
    return Linted(loaded.path, robot, kept)


def _with_severity(diagnostic: Diagnostic, config: Config) -> Diagnostic:
    severity = config.severity_of(diagnostic.code, diagnostic.severity)
    return diagnostic if severity is diagnostic.severity else diagnostic.with_severity(severity)


def _sources(shown: str, path: str, data: bytes | None, files: set[str]) -> dict[str, str]:
    """The text of every source file a suppression may sit in, by the name diagnostics use."""
    texts = {}
    if data is not None:
        texts[shown] = data.decode("utf-8", errors="replace")
    for file in {shown, *files} - set(texts):
        source = Path(path if file == shown else file)
        try:
            texts[file] = source.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
    return texts


@dataclass(frozen=True)
class Job:
    path: str
    config: Config
    package_paths: tuple[str, ...] = ()
    mappings: tuple[tuple[str, str], ...] = ()


def run_job(job: Job) -> Linted | str:
    """Lint in a worker: the result, or the one-line reason the file could not be read."""
    try:
        return lint_file(job.path, job.config, job.package_paths, dict(job.mappings))
    except (InputError, PackageError) as error:
        return str(error)


__all__ = ["Job", "Linted", "lint_file", "run_job"]
