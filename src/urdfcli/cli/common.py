"""What every subcommand shares: input arguments, configuration, loading, consoles and exit codes."""

from __future__ import annotations

import os
from collections.abc import Callable
from enum import IntEnum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

from ..escape import escape
from ..load import InputError
from ..packages import PackageError
from .options import Argument, BadValue, Option
from .streams import Stream

if TYPE_CHECKING:
    from ..config import Config
    from ..loaded import Loaded


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


stdout = Stream(**console_options("auto", False))
stderr = Stream(**console_options("auto", True))


def set_color(mode: str) -> str:
    """The --color option: set the two consoles up again for this mode."""
    if mode not in COLOR_MODES:
        raise BadValue(f"{mode!r} is not one of {', '.join(COLOR_MODES)}", "--color")
    for console, to_stderr in ((stdout, False), (stderr, True)):
        console.configure(**console_options(mode, to_stderr))
    return mode


ColorOption = Annotated[
    str,
    Option("--color", metavar="WHEN", callback=set_color, is_eager=True,
           help="Colour and bold text: auto (on a terminal, unless NO_COLOR is set), always, or never."),
]

InputsArgument = Annotated[
    list[str],
    Argument(
        metavar="FILE... [NAME:=VALUE]...",
        help="URDF or xacro files ('-' reads standard input); NAME:=VALUE sets a xacro argument.",
        show_default=False,
    ),
]
FileArgument = Annotated[
    list[str],
    Argument(
        metavar="FILE [NAME:=VALUE]...",
        help="URDF or xacro file ('-' reads standard input); NAME:=VALUE sets a xacro argument.",
        show_default=False,
    ),
]
PackagePathOption = Annotated[
    list[str] | None,
    Option(
        "--package-path",
        "-P",
        metavar="NAME=DIR|DIR",
        help="Where to find ROS packages for $(find) and package://: NAME=DIR, or a folder to scan for package.xml. Repeatable.",
    ),
]
ConfigOption = Annotated[
    Path | None,
    Option("--config", metavar="FILE", help="Use this urdfcli.toml or pyproject.toml instead of the nearest one above each input.", show_default=False),
]
IsolatedOption = Annotated[
    bool,
    Option("--isolated", help="Read no configuration file (neither the tool.urdfcli table of pyproject.toml nor urdfcli.toml)."),
]
LIBRARIES_HELP = (
    "A xacro file (*.xacro) that only defines macros and properties (no link, joint or macro call outside its macros) "
    "is a library: it is checked through the models of its repository or workspace that include it, "
    "with the diagnostics located in it, or, when no model includes it, expanded on its own for its own xacro errors."
)


def fail(message: str) -> SystemExit:
    """Print one line and give the exit code for 'could not run'."""
    stderr.print(f"urdfcli: {escape(message)}", markup=False)
    return SystemExit(Exit.CANNOT_RUN)


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


def configurations(explicit: Path | None = None, isolated: bool = False, overrides: dict | None = None) -> Callable[[str], Config]:
    """The configuration of each input (found once per folder: the files of a folder
    share it); a mistake in one exits 2."""
    from ..config import ConfigError, for_input  # `expand` reads no configuration

    cache: dict[str, Config] = {}

    def config_for(path: str) -> Config:
        folder = path if path == "-" else os.path.dirname(os.path.abspath(path))
        if folder not in cache:
            try:
                cache[folder] = for_input(path, explicit, isolated).overridden(**(overrides or {}))
            except ConfigError as error:
                raise fail(str(error)) from None
        return cache[folder]

    return config_for


def load_one(path: str, mappings: dict[str, str], package_paths: list[str] | None, checks: str = "none", config_for: Callable[[str], Config] | None = None, data: bytes | None = None) -> Loaded:
    """Load one input with its configuration; an unreadable one exits 2."""
    from ..linter import load_configured

    config_for = config_for or configurations()
    config = config_for(path)
    first_set = (config.argument_sets(path) or [{}])[0]  # one model to draw: the first listed argument set
    try:
        return load_configured(path, config, tuple(package_paths or ()), {**first_set, **mappings}, data, checks)
    except (InputError, PackageError) as error:
        raise fail(str(error)) from None


def load_all(
    arguments: list[str],
    package_paths: list[str] | None,
    checks: str = "check",
    config_for: Callable[[str], Config] | None = None,
    libraries: bool = False,
) -> tuple[list, bool]:
    """Load every input with its configuration; an unreadable one is reported in one line and skipped.

    With ``libraries``, a xacro library is checked through the models that
    include it (see urdfcli.workspace), and a model listed in ``[tool.urdfcli]
    models`` once per argument set. Returns the results and whether any input
    could not be read.
    """
    from ..linter import Job
    from ..workspace import Entry, assemble, model_targets, plan

    paths, mappings = split_inputs(arguments)
    config_for = config_for or configurations()
    extra = tuple(package_paths or ())
    try:
        if libraries:
            entries = plan(paths, config_for, extra)
        else:
            entries = [Entry(path, model_targets(path, config_for(path).argument_sets(path))) for path in paths]
    except PackageError as error:
        raise fail(str(error)) from None
    done: dict = {}

    def outcome(target):
        if target not in done:
            try:
                done[target] = Job.of(target, config_for(target.path), extra, mappings).load(checks)
            except InputError as error:
                done[target] = str(error)
            except PackageError as error:
                raise fail(str(error)) from None
        return done[target]

    results, unreadable = assemble(entries, outcome, lambda loaded: loaded.document.includes)
    for reason in unreadable:
        stderr.print(f"urdfcli: {reason}", markup=False)
    return results, bool(unreadable)
