"""Reports: the formats by name, the tree, the graph, the inertia audit.

Every format is a :class:`~urdfcli.report.base.Reporter` registered here by name;
each writes the one :class:`~urdfcli.model.result.Result` type, and computes
nothing of its own. Machine formats are written plain, never through rich.
"""

from __future__ import annotations

import os

from .base import Reporter
from .check_urdf import CheckUrdfReporter
from .concise import ConciseReporter
from .github import GithubReporter
from .json import JsonReporter
from .sarif import SarifReporter
from .text import TextReporter

REPORTERS: dict[str, type[Reporter]] = {
    reporter.name: reporter for reporter in (TextReporter, ConciseReporter, JsonReporter, SarifReporter, GithubReporter, CheckUrdfReporter)
}


def resolve(name: str) -> str:
    """A format's name; ``auto`` is github under GitHub Actions, else text."""
    name = name.lower()
    if name == "auto":
        return "github" if os.environ.get("GITHUB_ACTIONS") == "true" else "text"
    return name


def reporter(name: str) -> type[Reporter]:
    """The reporter of a format (``auto`` resolved)."""
    return REPORTERS[resolve(name)]


__all__ = ["REPORTERS", "Reporter", "reporter", "resolve"]
