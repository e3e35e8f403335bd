"""`urdfcli check`: a drop-in check_urdf that reports every problem at once."""

from __future__ import annotations

from typing import Annotated

import typer

from .. import report
from ..diagnostics import Severity
from ..options import Options, RuleSet
from ..report.console import Output
from . import fixes
from .common import (
    LIBRARIES_HELP,
    ColorOption,
    ConfigOption,
    Exit,
    InputsArgument,
    IsolatedOption,
    QuietOption,
    SrdfsOption,
    GitDeletionsOption,
    PackagePathOption,
    NoInfoOption,
    StatisticsOption,
    TargetOption,
    UrdfOption,
    changed_inputs,
    nothing_to_check,
    choose,
    format_option,
    session_for,
)
from .interrupt import CtrlC
from .fixes import DiffOption, FixOption, UnsafeFixesOption

FORMATS = ("auto", "text", "concise", "json", "sarif", "github", "check_urdf")
FormatOption = format_option(
    "Output format: auto (text, or github under GitHub Actions), text, concise, json, sarif, github, "
    "or check_urdf (exactly check_urdf's standard output)."
)


def check(
    ctx: typer.Context,
    inputs: InputsArgument = None,
    output_format: FormatOption = "auto",
    strict: Annotated[bool, typer.Option("--strict", help="Fail (exit 1) on warnings too.")] = False,
    target: TargetOption = None,
    load: Annotated[bool, typer.Option("--load", help="Also load each model into the --target consumers' own Python packages (mujoco, pydrake, pinocchio, pybullet) and report what they say.")] = False,
    package_path: PackagePathOption = None,
    urdf: UrdfOption = None,
    srdfs: SrdfsOption = False,
    git_deletions: GitDeletionsOption = False,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
    fix: FixOption = None,
    unsafe_fixes: UnsafeFixesOption = None,
    diff: DiffOption = False,
    quiet: QuietOption = False,
    no_info: NoInfoOption = None,
    statistics: StatisticsOption = False,
    color: ColorOption = "auto",
) -> None:
    """Check URDF/xacro files the way check_urdf does, and find what it misses.

    Prints the kinematic tree (as check_urdf does) and every problem as
    PATH:LINE:COL: CODE severity: message. Exit 0 when no file has errors,
    1 when one has (or warnings, with --strict), 2 when a file cannot be read.

    Configuration (the tool.urdfcli table of the nearest pyproject.toml, or urdfcli.toml)
    and noqa comments apply as they do for lint; --fix, --unsafe-fixes and --diff fix what
    check finds as they do for lint.
    """
    paths, mappings, deleted = changed_inputs(ctx, inputs, git_deletions)
    output_format = choose(output_format, FORMATS)
    if nothing_to_check(paths, deleted, output_format):
        return
    from .. import api  # (the library: imported when the command runs, not for --help)

    asked = fixes.Fixing(fix, unsafe_fixes, diff, False)
    options = Options(
        RuleSet.CHECK, tuple(mappings.items()), tuple(package_path or ()), config, isolated, targets=tuple(target or ()),
        load=load, format=output_format, fix=asked.applies, unsafe_fixes=unsafe_fixes, urdf=urdf, srdfs=srdfs, deleted=deleted,
        show_info=None if no_info is None else not no_info,
    )
    output = Output.standard(color, quiet)
    with session_for(options) as session:
        outcome = fixes.run(api.find_models(paths, session), session, asked, progress=CtrlC.stop_if_pressed)
        found = outcome.fixed.run
        fixes.report(outcome, session, output, asked, statistics)
        if diff:
            raise SystemExit(Exit.CANNOT_RUN if found.unreadable else Exit.PROBLEMS if outcome.changed else Exit.OK)
    failing = Severity.WARNING.rank if strict else Severity.ERROR.rank
    if found.unreadable:
        raise SystemExit(Exit.CANNOT_RUN)
    # check_urdf's format fails as check_urdf does: not on an error urdfdom only logs and goes on past
    from ..report.check_urdf import logged_by_urdfdom

    counted = (lambda d: not logged_by_urdfdom(d)) if report.resolve(options.format) == "check_urdf" and not strict else (lambda d: True)
    if any(d.severity.rank >= failing and counted(d) for result in found.results for d in result.diagnostics):
        raise SystemExit(Exit.PROBLEMS)


check.__doc__ += "\n\n    " + LIBRARIES_HELP
