"""What every subcommand shares: input arguments, consoles and exit codes."""

from __future__ import annotations

import os
from enum import IntEnum
from typing import Annotated

import typer
from rich.console import Console

from ..load import InputError, LoadOptions, load
from ..loaded import Loaded
from ..packages import PackageError


class Exit(IntEnum):
    OK = 0
    PROBLEMS = 1
    CANNOT_RUN = 2


COLOR_MODES = ("auto", "always", "never")


def console_options(mode: str, to_stderr: bool) -> dict:
    """Colour and styles on a terminal (``auto``), always, or never. NO_COLOR, when
    set, means never for ``auto``: no bold or dim either, not only no colours."""
    never = mode == "never" or (mode == "auto" and os.environ.get("NO_COLOR"))
    return dict(stderr=to_stderr, highlight=False, soft_wrap=True, color_system=None if never else "auto", force_terminal=True if mode == "always" else None)


stdout = Console(**console_options("auto", False))
stderr = Console(**console_options("auto", True))


def set_color(mode: str) -> str:
    """The --color option: set the two consoles up again for this mode."""
    if mode not in COLOR_MODES:
        raise typer.BadParameter(f"{mode!r} is not one of {', '.join(COLOR_MODES)}")
    for console, to_stderr in ((stdout, False), (stderr, True)):
        console.__init__(**console_options(mode, to_stderr))
    return mode


ColorOption = Annotated[
    str,
    typer.Option("--color", metavar="WHEN", callback=set_color, is_eager=True,
                 help="Colour and bold text: auto (on a terminal, unless NO_COLOR is set), always, or never."),
]

InputsArgument = Annotated[
    list[str],
    typer.Argument(
        metavar="FILE... [NAME:=VALUE]...",
        help="URDF or xacro files ('-' reads standard input); NAME:=VALUE sets a xacro argument.",
        show_default=False,
    ),
]
FileArgument = Annotated[
    list[str],
    typer.Argument(
        metavar="FILE [NAME:=VALUE]...",
        help="URDF or xacro file ('-' reads standard input); NAME:=VALUE sets a xacro argument.",
        show_default=False,
    ),
]
PackagePathOption = Annotated[
    list[str] | None,
    typer.Option(
        "--package-path",
        "-P",
        metavar="NAME=DIR|DIR",
        help="Where to find ROS packages for $(find) and package://: NAME=DIR, or a folder to scan for package.xml. Repeatable.",
    ),
]


def fail(message: str) -> typer.Exit:
    """Print one line and give the exit code for 'could not run'."""
    stderr.print(f"urdfcli: {message}", markup=False)
    return typer.Exit(Exit.CANNOT_RUN)


def split_inputs(arguments: list[str]) -> tuple[list[str], dict[str, str]]:
    paths, mappings = [], {}
    for argument in arguments:
        if ":=" in argument:
            name, _, value = argument.partition(":=")
            if not name:
                raise fail(f"bad xacro argument {argument!r}: expected NAME:=VALUE")
            mappings[name] = value
        else:
            paths.append(argument)
    if not paths:
        raise fail("no input file given")
    return paths, mappings


def load_all(arguments: list[str], package_paths: list[str] | None, checks: str = "check") -> tuple[list[Loaded], bool]:
    """Load every input; an unreadable one is reported in one line and skipped.

    Returns the loaded files and whether any input could not be read.
    """
    paths, mappings = split_inputs(arguments)
    options = LoadOptions(tuple(package_paths or ()), mappings, checks)
    results, unreadable = [], False
    for path in paths:
        try:
            results.append(load(path, options))
        except InputError as error:
            stderr.print(f"urdfcli: {error}", markup=False)
            unreadable = True
        except PackageError as error:
            raise fail(str(error)) from None
    return results, unreadable
