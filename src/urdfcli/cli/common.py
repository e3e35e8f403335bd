"""What every subcommand shares: its options, its session and consoles, its exit codes."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from enum import IntEnum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from ..options import Options, UsageError, xacro_arguments
from . import click_exceptions
from ..report.console import COLOR_MODES, Output
from ..report.escape import escape

if TYPE_CHECKING:
    from ..model.result import Unreadable
    from ..session import Session


class Exit(IntEnum):
    OK = 0
    PROBLEMS = 1
    CANNOT_RUN = 2


def _color(mode: str) -> str:
    if mode not in COLOR_MODES:
        raise typer.BadParameter(f"{mode!r} is not one of {', '.join(COLOR_MODES)}")
    return mode


ColorOption = Annotated[
    str,
    typer.Option("--color", metavar="WHEN", callback=_color, help="Colour and bold text: auto (on a terminal, unless NO_COLOR is set), always, or never."),
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
ConfigOption = Annotated[
    Path | None,
    typer.Option("--config", metavar="FILE", help="Use this urdfcli.toml or pyproject.toml instead of the nearest one above each input.", show_default=False),
]
IsolatedOption = Annotated[
    bool,
    typer.Option("--isolated", help="Read no configuration file (neither the tool.urdfcli table of pyproject.toml nor urdfcli.toml)."),
]
UrdfOption = Annotated[
    str | None,
    typer.Option(
        "--urdf", metavar="FILE",
        help="Check SRDF files (MoveIt's .srdf, .srdf.xacro) against this URDF or xacro file, instead of the one of their robot's name found in their package or workspace.",
        show_default=False,
    ),
]
SrdfsOption = Annotated[
    bool,
    typer.Option(
        "--srdfs",
        help="Also check the MoveIt SRDFs (.srdf, .srdf.xacro) of the repository or workspace that describe the robot of a model given, "
        "or of a model including a library given: a link or joint renamed in the model is caught where a planning group or collision pair "
        "still names it (the pre-commit hooks pass it).",
    ),
]
GitDeletionsOption = Annotated[
    bool,
    typer.Option(
        "--git-deletions",
        help="Also check the models that include a file deleted or renamed in git's staged changes (between PRE_COMMIT_FROM_REF and "
        "PRE_COMMIT_TO_REF when pre-commit sets them), which pre-commit never passes, or name a mesh or YAML file so deleted: their "
        "include or mesh fails now. No input file is needed "
        "then (the check and lint pre-commit hooks pass it, and run on every commit).",
    ),
]
NoInfoOption = Annotated[
    bool | None,
    typer.Option(
        "--no-info/--info", show_default=False,
        help="Show only warnings and errors (info is still counted in the summary); --info shows it whatever the configuration's show-info says.",
    ),
]
StatisticsOption = Annotated[
    bool,
    typer.Option("--statistics", help="Print how many diagnostics each rule gave, most first, instead of the diagnostics."),
]
QuietOption = Annotated[
    bool,
    typer.Option("--quiet", "-q", help="Print only the diagnostics and the summary: no tree, no notes on libraries, no progress bar."),
]


def _targets(values: list[str] | None) -> list[str] | None:
    if not values:
        return []  # (no consumer imported when none is asked for)
    from ..targets import profiles

    for value in values:
        for text in value.split(","):
            try:
                profiles(text)
            except ValueError as error:
                raise typer.BadParameter(str(error)) from None
    return values


TargetOption = Annotated[
    list[str] | None,
    typer.Option(
        "--target",
        "-t",
        metavar="NAME",
        callback=_targets,
        # the registry's help_text(), written out so that --help imports no consumer (tests/test_targets.py compares them)
        help="Also say what this consumer rejects, changes or warns about: mujoco, drake, pinocchio, pybullet, gazebo, kdl, isaac, or all; "
        "variants pinocchio:mimic, pinocchio:free-flyer, pybullet:inertia-from-file, pybullet:fixed-base. Repeatable; replaces `targets` of the configuration.",
        show_default=False,
    ),
]
LIBRARIES_HELP = (
    "A xacro file (*.xacro) that only defines macros and properties (no link, joint or macro call outside its macros) "
    "is a library: it is checked through the models of its repository or workspace that include it, "
    "with the diagnostics located in it, or, when no model includes it, expanded on its own for its own xacro errors."
)


def format_option(help: str, metavar: str = "FORMAT"):
    return Annotated[str, typer.Option("--format", "-f", metavar=metavar, help=help, case_sensitive=False)]


def fail(message: str) -> SystemExit:
    """Say in one line why the command cannot run, and give exit code 2."""
    Output.standard("never").err.file.write(f"urdfcli: {escape(message)}\n")
    return SystemExit(Exit.CANNOT_RUN)


def choose(value: str, choices, option: str = "--format") -> str:
    """``value`` (any case) when it is one of ``choices``, else a usage error."""
    if value.lower() not in choices:
        raise typer.BadParameter(f"unknown format {value!r}; choose from {', '.join(choices)}", param_hint=option)
    return value.lower()


def split_inputs(arguments: list[str], none_needed: bool = False) -> tuple[list[str], dict[str, str]]:
    """The files of a command line and its NAME:=VALUE xacro arguments (``none_needed``:
    no file is fine)."""
    try:
        mappings = xacro_arguments(a for a in arguments if ":=" in a)
    except UsageError as error:
        raise fail(str(error)) from None
    paths = [a for a in arguments if ":=" not in a]
    if not paths and not none_needed:
        raise fail("no input file given")
    return paths, mappings


def changed_inputs(ctx: typer.Context, arguments: list[str] | None, git_deletions: bool) -> tuple[list[str], dict[str, str], tuple[str, ...]]:
    """The files and xacro arguments of a command line whose files may be none with
    ``--git-deletions``, and the files git says are deleted (see :func:`deleted_by_change`).
    Without ``--git-deletions`` the files are required, as typer says."""
    if not arguments and not git_deletions:
        raise click_exceptions().MissingParameter(ctx=ctx, param=next(p for p in ctx.command.params if p.name == "inputs"))
    paths, mappings = split_inputs(arguments or [], none_needed=git_deletions)
    return paths, mappings, deleted_by_change() if git_deletions else ()


def nothing_to_check(paths: list[str], deleted: tuple[str, ...], output_format: str) -> bool:
    """Whether a run has no file and nothing deleted (``--git-deletions`` on a commit that changes
    no description: the hooks run on every commit) and would print nothing: the command returns
    at once, without importing the library. JSON and SARIF still print a report of no file."""
    return not paths and not deleted and output_format not in ("json", "sarif")


def deleted_by_change() -> tuple[str, ...]:
    """The files git's staged changes delete, or those deleted between the revisions pre-commit
    gives a hook it runs on a range (``pre-commit run --from-ref A --to-ref B``, a pre-push hook)."""
    from ..read.revision import deleted_files

    between = (os.environ.get("PRE_COMMIT_FROM_REF", ""), os.environ.get("PRE_COMMIT_TO_REF", ""))
    # only what a model reads: a commit deleting scripts or launch files asks nothing more
    return tuple(str(file) for file in deleted_files(Path.cwd(), between if all(between) else None) if file.suffix.lower() in DESCRIPTION_SUFFIXES)


DESCRIPTION_SUFFIXES = (".urdf", ".xacro", ".stl", ".dae", ".obj", ".ply", ".glb", ".gltf", ".yaml", ".yml")
"""The files a model reads: descriptions, meshes and the YAML of ``xacro.load_yaml``."""


@contextlib.contextmanager
def session_for(options: Options) -> Iterator[Session]:
    """The command's session, closed when it ends; a bad -P or configuration, or an
    input that cannot be read, ends the command with exit code 2."""
    from ..read.packages import PackageError
    from ..session import Session

    try:
        opened = Session(options)
    except PackageError as error:
        raise fail(str(error)) from None
    try:
        yield opened
    except UsageError as error:
        raise fail(str(error)) from None
    finally:
        opened.close()


def report_unreadable(output: Output, unreadable: list[Unreadable]) -> None:
    for found in unreadable:
        output.err.file.write(f"urdfcli: {escape(found.reason)}\n")


def refuse_library(path: str, session) -> None:
    """Exit 2 for a xacro library given to draw or audit: it makes no robot by itself;
    the message names a model that includes it, to give instead."""
    from .. import api  # (the library: imported when the command runs)

    models = api.library_models(path, session)
    if models is None:
        return
    if not models:
        raise fail(f"{path}: a xacro library (macros and properties only), which makes no robot by itself, and no model of its repository or workspace includes it")
    more = f" (one of {len(models)} that do)" if len(models) > 1 else ""
    raise fail(f"{path}: a xacro library (macros and properties only), which makes no robot by itself; give a model that includes it: {models[0]}{more}")


def not_a_robot(path: str) -> str:
    """Why an SRDF is not drawn or audited, and what to do with it instead."""
    return f"{path}: an SRDF (MoveIt's semantic description), which has no links of its own; `urdfcli check {path}` checks it against its URDF"
