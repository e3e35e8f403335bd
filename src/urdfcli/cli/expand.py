"""`urdfcli expand`: the xacro tool, in-process and without ROS."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ..diagnostics import Severity
from ..report.console import Output, write
from ..report.escape import escape
from ..report.output import OutputError, write_atomic
from ..options import Options
from .common import ColorOption, ConfigOption, Exit, FileArgument, IsolatedOption, PackagePathOption, fail, session_for, split_inputs


def expand(
    inputs: FileArgument,
    output: Annotated[Path | None, typer.Option("--output", "-o", metavar="PATH", help="Write to this file (atomically) instead of standard output.")] = None,
    deps: Annotated[bool, typer.Option("--deps", help="List the files the input includes, one per line, instead of expanding.")] = False,
    package_path: PackagePathOption = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
    color: ColorOption = "auto",
    in_order: Annotated[bool, typer.Option("--inorder", "-i", hidden=True, help="Accepted for old scripts; does nothing.")] = False,
) -> None:
    """Expand a xacro file to URDF, exactly as the xacro tool does.

    $(find pkg) and package:// resolve without ROS (see --package-path).
    Arguments not given as NAME:=VALUE are those the configuration gives the
    file (its xacro-args table, or the first argument set of models), else their
    defaults.
    A xacro error is one line with file:line, exit 1, and no output file.
    """
    from .. import api
    from ..report.lines import diagnostics_lines

    paths, mappings = split_inputs(inputs)
    if len(paths) != 1:
        raise fail(f"expand takes one input file, got {len(paths)}")
    path = paths[0]
    console = Output.standard(color)
    if in_order:  # what xacro says of it, with the fix (xacro's --inorder became its only mode in ROS Melodic)
        console.err.file.write("urdfcli: warning: --inorder does nothing: in-order processing is xacro's only mode since ROS Melodic; drop the option\n")
    with session_for(Options(arguments=tuple(mappings.items()), package_paths=tuple(package_path or ()), config=config, isolated=isolated)) as session:
        text, includes, diagnostics = api.expand(path, session)
    write(console.err, diagnostics_lines(diagnostics, None))
    if text is None or any(d.severity is Severity.ERROR for d in diagnostics):
        raise SystemExit(Exit.PROBLEMS)
    text = "".join(f"{escape(name)}\n" for name in includes) if deps else text
    if output is None:
        console.out.file.write(text)
        return
    try:
        write_atomic(output, text, [path, *includes])
    except OutputError as error:
        raise fail(str(error)) from None
