"""`urdfcli check`: a drop-in check_urdf that reports every problem at once."""

from __future__ import annotations

from typing import Annotated

from ..diagnostics import Severity
from ..formatters import FORMATS, resolve
from ..formatters.emit import emit
from .common import LIBRARIES_HELP, ConfigOption, Exit, InputsArgument, IsolatedOption, PackagePathOption, configurations, load_all, stderr, stdout
from .options import BadValue, Option

FormatOption = Annotated[
    str,
    Option(
        "--format",
        "-f",
        metavar="FORMAT",
        help="Output format: auto (text, or github under GitHub Actions), text, concise, json, sarif, github, "
        "or check_urdf (exactly check_urdf's standard output).",
        case_sensitive=False,
    ),
]


def check(
    inputs: InputsArgument,
    output_format: FormatOption = "auto",
    strict: Annotated[bool, Option("--strict", help="Fail (exit 1) on warnings too.")] = False,
    package_path: PackagePathOption = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
) -> None:
    """Check URDF/xacro files the way check_urdf does, and find what it misses.

    Prints the kinematic tree (as check_urdf does) and every problem as
    PATH:LINE:COL: CODE severity: message. Exit 0 when no file has errors,
    1 when one has (or warnings, with --strict), 2 when a file cannot be read.

    Configuration (the tool.urdfcli table of the nearest pyproject.toml, or urdfcli.toml)
    and noqa comments apply as they do for lint.
    """
    if output_format not in FORMATS:
        raise BadValue(f"unknown format {output_format!r}; choose from {', '.join(FORMATS)}", "--format")
    results, unreadable = load_all(inputs, package_path, "check", configurations(config, isolated), libraries=True)
    emit(results, resolve(output_format), stdout, stderr)
    failing = Severity.WARNING.rank if strict else Severity.ERROR.rank
    if unreadable:
        raise SystemExit(Exit.CANNOT_RUN)
    if any(d.severity.rank >= failing for loaded in results for d in loaded.diagnostics):
        raise SystemExit(Exit.PROBLEMS)


check.__doc__ += "\n\n    " + LIBRARIES_HELP
