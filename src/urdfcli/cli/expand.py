"""`urdfcli expand`: the xacro tool, in-process and without ROS."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated

from ..escape import escape
from ..formatters.text import print_diagnostic
from ..load import InputError, LoadOptions, load_document
from ..output import OutputError, write_atomic
from ..packages import PackageError
from .common import Exit, FileArgument, PackagePathOption, fail, split_inputs, stderr
from .options import Option


def expand(
    inputs: FileArgument,
    output: Annotated[Path | None, Option("--output", "-o", metavar="PATH", help="Write to this file (atomically) instead of standard output.")] = None,
    deps: Annotated[bool, Option("--deps", help="List the files the input includes, one per line, instead of expanding.")] = False,
    package_path: PackagePathOption = None,
) -> None:
    """Expand a xacro file to URDF, exactly as the xacro tool does.

    $(find pkg) and package:// resolve without ROS (see --package-path).
    A xacro error is one line with file:line, exit 1, and no output file.
    """
    paths, mappings = split_inputs(inputs)
    if len(paths) != 1:
        raise fail(f"expand takes one input file, got {len(paths)}")
    path = paths[0]
    try:
        document, diagnostics = load_document(path, LoadOptions(tuple(package_path or ()), mappings), force_xacro=True)
    except InputError as error:
        raise fail(str(error)) from None
    except PackageError as error:
        raise fail(str(error)) from None
    errors = [d for d in diagnostics if d.severity.value == "error"]
    for diagnostic in diagnostics:
        print_diagnostic(stderr, diagnostic)
    if errors:
        raise SystemExit(Exit.PROBLEMS)
    text = "".join(f"{escape(name)}\n" for name in document.includes) if deps else document.expanded_text
    if output is None:
        sys.stdout.write(text)
        return
    try:
        write_atomic(output, text, [path, *document.includes])
    except OutputError as error:
        raise fail(str(error)) from None
