"""The human format: each diagnostic as ``PATH:LINE:COL: CODE severity: message``,
its macro calls, hint and source line, and a summary; ``check`` also prints each
model's tree as check_urdf does.

``check`` keeps check_urdf's layout (the tree on standard output, diagnostics on
standard error); ``lint`` writes everything on standard output, so that
``> report.txt`` holds it. Styles only where the console shows them.
"""

from __future__ import annotations

import io
from typing import TYPE_CHECKING

from ..read.files import SourceFiles
from .check_urdf import tree_lines
from .console import Line, Output, console, write
from .escape import escape
from .lines import diagnostic_lines, fixable_line, library_lines, summary_line

if TYPE_CHECKING:
    from .result import Result

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


def report(results: list[Result], output: Output, view: str = "lint", files: SourceFiles | None = None) -> None:
    """``check``: each model's tree on standard output, diagnostics on standard error;
    ``lint`` (and ``drift``): everything on standard output, and for check and lint what
    ``--fix`` would fix; ``inertia``: the audit."""
    if view == "inertia":
        from .inertia import report as audit_report

        audit_report(results, output, view, files)
        return
    out = output.out
    err = output.err if view == "check" else output.out
    for result in results:
        if view == "check" and result.library is None and result.loaded is not None and not output.quiet:
            if len(results) > 1:
                write(out, [[(f"==> {escape(result.label if result.arguments else result.shown)} <==", "bold")]])
            write(out, tree_text(result))
        write(err, (line for diagnostic in result.diagnostics for line in diagnostic_lines(diagnostic, files)))
    if not output.quiet:
        write(err, ([(line, "dim")] for line in library_lines(results)))
    if results:
        write(err, [[(summary_line(results), "bold")]])
        fixable = fixable_line(results) if view in ("check", "lint") else None
        if fixable is not None:
            write(err, [[(fixable, "")]])


def plain_report(results: list[Result], files: SourceFiles | None = None) -> str:
    """:func:`report` of ``lint`` as plain text."""
    if files is None:
        files = next((r.loaded.document.files for r in results if r.loaded is not None), None) or SourceFiles()
    buffer = io.StringIO()
    target = console("never", buffer)
    report(results, Output(target, target), "lint", files)
    return buffer.getvalue()
