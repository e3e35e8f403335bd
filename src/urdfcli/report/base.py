"""What a format is: a reporter, made with a command's output and the session's files,
that writes results. Each format is one class, registered by name (:data:`urdfcli.report.REPORTERS`);
it only writes what the results hold, computing nothing.

``check`` writes what ``urdfcli check`` prints (a format keeps the layout of the tool it
stands in for), ``lint`` what ``urdfcli lint`` prints, ``audit`` the mass-property audit of
``urdfcli inertia``. A format that has nothing of its own to say for ``check`` writes what it
writes for ``lint``; the command line offers a format only for the commands it writes.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .console import Output

if TYPE_CHECKING:
    from ..model.result import Result
    from ..read.files import SourceFiles


class Reporter:
    """A format (see the module). ``files`` are where source lines are read for excerpts."""

    name = ""

    def __init__(self, output: Output, files: SourceFiles | None = None) -> None:
        self.output = output
        self.files = files

    def check(self, results: list[Result]) -> None:
        self.lint(results)

    def lint(self, results: list[Result]) -> None:
        raise NotImplementedError(f"the {self.name} format writes no lint results")

    def drift(self, results: list[Result]) -> None:
        """``urdfcli drift``'s results: as lint's, where a format says nothing of its own."""
        self.lint(results)

    def audit(self, results: list[Result]) -> None:
        raise NotImplementedError(f"the {self.name} format writes no mass-property audit")


__all__ = ["Reporter"]
