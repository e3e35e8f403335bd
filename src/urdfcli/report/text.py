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
from .console import Line, Output, Stream, rich_console, write
from .escape import escape
from .lines import SourcesOnce, diagnostics_lines, fixable_line, library_lines, plural, summary_line, wrap_line
from .targets import compatibility_lines

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


def semantic_text(loaded) -> list[Line]:
    """What ``check`` prints of an SRDF in place of a tree: its robot, what it holds, its URDF."""
    semantic = loaded.semantic
    parts = [plural(len(semantic.groups), "group"), plural(len(semantic.states), "group state"), plural(len(semantic.end_effectors), "end effector")]
    described = loaded.described
    against = f"checked against {escape(described.path)}" if described is not None and described.modelled else "no URDF to check it against"
    return [[("SRDF of robot: ", ""), (escape(semantic.name or ""), "bold")], [(f"{', '.join(parts)}; {against}", "")]]


class TextReporter(Reporter):
    """``check``: each model's tree on standard output (as check_urdf prints it), the
    diagnostics on standard error; ``lint``: everything on standard output, so that
    ``> report.txt`` holds it; both then say what ``--fix`` would fix. ``drift``: as
    lint, without the fixes (it takes no ``--fix``); ``audit``: the mass-property table.
    On a terminal, a line longer than it goes on below; in a file, one line each."""

    name = "text"

    def check(self, results: list[Result]) -> None:
        output = self.output
        for result in results:
            if result.library is None and result.loaded is not None and not output.quiet:
                if len(results) > 1:
                    write(output.out, [[(f"==> {escape(result.label if result.arguments else result.shown)} <==", "bold")]])
                write(output.out, semantic_text(result.loaded) if result.loaded.semantic is not None else tree_text(result))
            write(output.err, self._diagnostics(result, output.err))
            write(output.err, compatibility_lines(result))
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
            write(self.output.out, self._diagnostics(result, self.output.out))
            write(self.output.out, compatibility_lines(result))
        self._summary(results, self.output.out, fixes)

    def _diagnostics(self, result: Result, target: Stream | Console) -> Iterator[Line]:
        width = _width(target)
        files = SourcesOnce(self.files)
        return diagnostics_lines(result.displayed, files, width)

    def _summary(self, results: list[Result], target: Stream | Console, fixes: bool) -> None:
        if not self.output.quiet:
            width = _width(target)
            write(target, ([(piece, "dim")] for line in library_lines(results) for piece in (wrap_line(line, width) if width else [line])))
        if results:
            write(target, [[(summary_line(results), "bold")]])
            fixable = fixable_line(results) if fixes else None
            if fixable is not None:
                write(target, [[(fixable, "")]])


def _width(target: Stream | Console) -> int | None:
    """The terminal's width, when the stream is one (else None: a line is never broken)."""
    return rich_console(target).width if target.is_terminal else None


def plain_text(results: list[Result], files: SourceFiles | None = None) -> str:
    """What ``lint`` writes of the results, as plain text."""
    if files is None:
        files = next((r.loaded.document.files for r in results if r.loaded is not None), None) or SourceFiles()
    buffer = io.StringIO()
    target = Stream("never", buffer)
    TextReporter(Output(target, target), files).lint(results)
    return buffer.getvalue()
