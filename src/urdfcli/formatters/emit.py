"""Writing results in the format asked for: one entry point for check and lint."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from ..escape import escape
from . import check_urdf, concise_line, github, summary_line
from .text import print_diagnostic, print_tree

if TYPE_CHECKING:
    from rich.console import Console


def emit(results, output_format: str, stdout: Console, stderr: Console, tree: bool = True) -> None:
    """Write the results in one format; ``tree`` adds check's kinematic tree to the text format.

    Machine formats go to the standard streams as plain text; the text format
    goes through the given rich consoles (results on stdout, diagnostics on stderr)."""
    if output_format == "json":
        from . import json as json_format  # (json: only for this format)

        sys.stdout.write(json_format.render(results) + "\n")
    elif output_format == "sarif":
        from ..formatters import sarif

        sys.stdout.write(sarif.render(results) + "\n")
    elif output_format == "github":
        for loaded in results:
            for diagnostic in loaded.diagnostics:
                sys.stdout.write(github.line(diagnostic) + "\n")
    elif output_format == "concise":
        for loaded in results:
            for diagnostic in loaded.diagnostics:
                sys.stdout.write(concise_line(diagnostic) + "\n")
            sys.stderr.writelines(line + "\n" for line in library_lines(loaded))
        if results:  # nothing was read: the one-line reasons already said why
            sys.stderr.write(summary_line(results) + "\n")
    elif output_format == "check_urdf":
        for loaded in results:
            errors = check_urdf.error_lines(loaded)
            if errors:
                sys.stderr.write("\n".join(errors) + "\n")
            else:
                sys.stdout.write("".join(line + "\n" for line in check_urdf.tree_lines(loaded)))
    else:
        for loaded in results:
            library = getattr(loaded, "checked_through", None) is not None
            if tree and not library:
                if len(results) > 1:
                    stdout.print(f"==> {escape(getattr(loaded, 'label', None) or loaded.document.shown)} <==", style="bold", markup=False)
                print_tree(stdout, loaded)
            for diagnostic in loaded.diagnostics:
                print_diagnostic(stderr, diagnostic, excerpt=True)
            for line in library_lines(loaded):
                stderr.print(line, markup=False, style="dim")
        if results:
            stderr.print(summary_line(results), markup=False, style="bold")


def library_lines(result) -> list[str]:
    """For a xacro library: which models it was checked through, and why one could not be."""
    through = getattr(result, "checked_through", None)
    if through is None:
        return []
    lines = [f"{result.path}: xacro library, checked through {', '.join(through)}"] if through else []
    return lines + [f"{result.path}: {note}" for note in result.notes]
