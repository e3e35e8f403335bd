"""The human format: each diagnostic as ``PATH:LINE:COL: CODE severity: message``,
its macro calls, hint and source line, and a summary; ``check`` also prints each
model's tree as check_urdf does.

``check`` keeps check_urdf's layout (the tree on standard output, diagnostics on
standard error); ``lint`` writes everything on standard output, so that
``> report.txt`` holds it. Styles only where the console shows them.
"""

from __future__ import annotations

import io
from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..read.files import SourceFiles
from .base import Reporter
from .check_urdf import tree_lines
from .console import Line, Output, Stream, write
from .escape import escape
from .lines import diagnostic_lines, fixable_line, library_lines, summary_line

if TYPE_CHECKING:
    from rich.console import Console

    from ..model.result import Result

def tree_text(result: Result) -> list[Line]:
    """check_urdf's tree of a model, styled."""
    lines: list[Line] = []
    root = result.loaded.root if result.loaded is not None else None
    for line in tree_lines(result.loaded):
        if line.startswith("robot name is: "):
            lines.append([(line[:15], ""), (line[15:], "bold")])
        elif line.startswith("root Link: "):
            name = escape(root or "")
            lines.append([(line[:11], ""), (name, "bold green"), (line[11 + len(name):], "")])
        elif "child(" in line:
            cut = line.index("):  ") + 4
            lines.append([(line[:cut], ""), (line[cut:], "green")])
        else:
            lines.append([(line, "")])
    return lines


class TextReporter(Reporter):
    """``check``: each model's tree on standard output (as check_urdf prints it), the
    diagnostics on standard error; ``lint``: everything on standard output, so that
    ``> report.txt`` holds it; both then say what ``--fix`` would fix. ``drift``: as
    lint, without the fixes (it takes no ``--fix``); ``audit``: the mass-property table."""

    name = "text"

    def check(self, results: list[Result]) -> None:
        output = self.output
        for result in results:
            if result.library is None and result.loaded is not None and not output.quiet:
                if len(results) > 1:
                    write(output.out, [[(f"==> {escape(result.label if result.arguments else result.shown)} <==", "bold")]])
                write(output.out, tree_text(result))
            write(output.err, self._diagnostics(result))
        self._summary(results, output.err, fixes=True)

    def lint(self, results: list[Result]) -> None:
        self._all(results, fixes=True)

    def drift(self, results: list[Result]) -> None:
        self._all(results, fixes=False)

    def audit(self, results: list[Result]) -> None:
        from .inertia import write_audit

        write_audit(results, self.output)

    def _all(self, results: list[Result], fixes: bool) -> None:
        for result in results:
            write(self.output.out, self._diagnostics(result))
        self._summary(results, self.output.out, fixes)

    def _diagnostics(self, result: Result) -> Iterator[Line]:
        return (line for diagnostic in result.diagnostics for line in diagnostic_lines(diagnostic, self.files))

    def _summary(self, results: list[Result], target: Console, fixes: bool) -> None:
        if not self.output.quiet:
            write(target, ([(line, "dim")] for line in library_lines(results)))
        if results:
            write(target, [[(summary_line(results), "bold")]])
            fixable = fixable_line(results) if fixes else None
            if fixable is not None:
                write(target, [[(fixable, "")]])


def plain_text(results: list[Result], files: SourceFiles | None = None) -> str:
    """What ``lint`` writes of the results, as plain text."""
    if files is None:
        files = next((r.loaded.document.files for r in results if r.loaded is not None), None) or SourceFiles()
    buffer = io.StringIO()
    target = Stream("never", buffer)
    TextReporter(Output(target, target), files).lint(results)
    return buffer.getvalue()
