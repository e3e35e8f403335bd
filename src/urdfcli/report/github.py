"""GitHub Actions workflow annotations, each file named from the top of its repository
(:mod:`.repository`), where GitHub looks for it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic
from .base import Reporter
from .escape import escape
from .lines import severity_name
from .repository import RepositoryPaths

if TYPE_CHECKING:
    from ..model.result import Result

LEVELS = {"error": "error", "warning": "warning", "info": "notice"}


def escape_data(text: str) -> str:
    """Workflow-command escaping, after the control characters are made visible (the log is a terminal)."""
    return escape(text).replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def escape_property(text: str) -> str:
    return escape_data(text).replace(":", "%3A").replace(",", "%2C")


def line(diagnostic: Diagnostic, paths: RepositoryPaths) -> str:
    location = diagnostic.location
    props = [f"file={escape_property(paths.path(location.file))}"]
    if location.line:
        props.append(f"line={location.line}")
        if location.column:
            props.append(f"col={location.column}")
    props.append(f"title={escape_property(diagnostic.code)}")
    calls = [call.phrase for call in location.trace] + ([diagnostic.through] if diagnostic.through else [])
    calls += [f"hint: {diagnostic.hint}"] if diagnostic.hint else []
    return f"::{LEVELS[severity_name(diagnostic)]} {','.join(props)}::" + "%0A".join(map(escape_data, [diagnostic.message, *calls]))


class GithubReporter(Reporter):
    """One workflow command per diagnostic, on standard output."""

    name = "github"

    def lint(self, results: list[Result]) -> None:
        paths = RepositoryPaths.from_environment()
        self.output.out.file.writelines(line(d, paths) + "\n" for result in results for d in result.displayed)
