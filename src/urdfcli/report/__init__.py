"""Reports: the formats by name, the tree, the graph, the inertia audit.

Every format is a :class:`~urdfcli.report.base.Reporter` registered here by name
(its module is imported when the format is asked for); each writes the one
:class:`~urdfcli.model.result.Result` type, and computes nothing of its own.
Machine formats are written plain, never through rich.
"""

from __future__ import annotations

import os
from importlib import import_module
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .base import Reporter

REPORTERS = {
    "text": ("text", "TextReporter"),
    "concise": ("concise", "ConciseReporter"),
    "json": ("json", "JsonReporter"),
    "sarif": ("sarif", "SarifReporter"),
    "github": ("github", "GithubReporter"),
    "check_urdf": ("check_urdf", "CheckUrdfReporter"),
}
"""Each format's name -> its module and reporter class."""

DIFF_FORMATS = ("text", "json", "markdown", "github")
"""The formats of ``urdfcli diff`` (:mod:`.diff`)."""


def resolve(name: str) -> str:
    """A format's name; ``auto`` is github under GitHub Actions, else text."""
    name = name.lower()
    if name == "auto":
        return "github" if os.environ.get("GITHUB_ACTIONS") == "true" else "text"
    return name


def reporter(name: str) -> type[Reporter]:
    """The reporter of a format (``auto`` resolved)."""
    module, cls = REPORTERS[resolve(name)]
    return getattr(import_module(f".{module}", __name__), cls)


def statistics(results, output, view: str = "lint", output_format: str = "text") -> None:
    """``--statistics``: the count of each rule's diagnostics, as a table, or JSON with ``--format json``."""
    from .statistics import report

    report(results, output, view, output_format="json" if resolve(output_format) == "json" else "text")


__all__ = ["DIFF_FORMATS", "REPORTERS", "reporter", "resolve", "statistics"]
