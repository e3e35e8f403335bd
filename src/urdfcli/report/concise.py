"""One plain line per diagnostic (with the macro call that made its element) on
standard output, for logs and editors' problem matchers; the libraries' notes
and the summary on standard error, so that standard output holds nothing else.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .base import Reporter
from .console import Output
from .lines import concise_line, fixable_line, library_lines, summary_line

if TYPE_CHECKING:
    from ..model.result import Result


class ConciseReporter(Reporter):
    """One line per diagnostic on standard output; notes and the summary on standard error."""

    name = "concise"

    def lint(self, results: list[Result]) -> None:
        write_concise(results, self.output, fixes=True)

    def drift(self, results: list[Result]) -> None:
        write_concise(results, self.output, fixes=False)


def write_concise(results: list[Result], output: Output, fixes: bool) -> None:
    """Each diagnostic on a line; with ``fixes``, what ``--fix`` would fix after the summary."""
    out, notes = output.out.file, output.err.file
    for result in results:
        out.writelines(concise_line(d) + "\n" for d in result.displayed)
    if not output.quiet:
        notes.writelines(line + "\n" for line in library_lines(results))
    if results:  # nothing was read: the one-line reasons already said why
        notes.write(summary_line(results) + "\n")
        fixable = fixable_line(results) if fixes else None
        if fixable is not None:
            notes.write(fixable + "\n")
