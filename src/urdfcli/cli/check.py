"""`urdfcli check`: a drop-in check_urdf that reports every problem at once."""

from __future__ import annotations

import sys
from typing import Annotated

import typer

from ..diagnostics import Severity
from ..formatters import FORMATS, check_urdf, github, plain_line, resolve, summary_line
from ..formatters import json as json_format
from ..formatters.text import print_diagnostic, print_tree
from .common import Exit, InputsArgument, PackagePathOption, load_all, stderr, stdout

FormatOption = Annotated[
    str,
    typer.Option(
        "--format",
        "-f",
        help="Output format: auto (text, or github under GitHub Actions), text, concise, json, sarif, github, "
        "or check_urdf (exactly check_urdf's standard output).",
        case_sensitive=False,
    ),
]


def check(
    inputs: InputsArgument,
    output_format: FormatOption = "auto",
    strict: Annotated[bool, typer.Option("--strict", help="Fail (exit 1) on warnings too.")] = False,
    package_path: PackagePathOption = None,
) -> None:
    """Check URDF/xacro files the way check_urdf does, and find what it misses.

    Prints the kinematic tree (as check_urdf does) and every problem as
    PATH:LINE:COL: CODE severity: message. Exit 0 when no file has errors,
    1 when one has (or warnings, with --strict), 2 when a file cannot be read.
    """
    if output_format not in FORMATS:
        raise typer.BadParameter(f"unknown format {output_format!r}; choose from {', '.join(FORMATS)}", param_hint="--format")
    results, unreadable = load_all(inputs, package_path)
    emit(results, resolve(output_format))
    failing = Severity.WARNING.rank if strict else Severity.ERROR.rank
    if unreadable:
        raise typer.Exit(Exit.CANNOT_RUN)
    if any(d.severity.rank >= failing for loaded in results for d in loaded.diagnostics):
        raise typer.Exit(Exit.PROBLEMS)


def emit(results, output_format: str, tree: bool = True) -> None:
    """Write the results in one format; ``tree`` adds check's kinematic tree to the text format."""
    if output_format == "json":
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
                sys.stdout.write(plain_line(diagnostic) + "\n")
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
            if tree:
                if len(results) > 1:
                    stdout.print(f"==> {loaded.document.shown} <==", style="bold", markup=False)
                print_tree(stdout, loaded)
            for diagnostic in loaded.diagnostics:
                print_diagnostic(stderr, diagnostic, excerpt=True)
        stderr.print(summary_line(results), markup=False, style="bold")
