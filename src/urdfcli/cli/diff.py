"""`urdfcli diff`: what changed in the robot between two versions of its description."""

from __future__ import annotations

from typing import Annotated

import typer

from ..report import DIFF_FORMATS, resolve
from ..report.console import Output
from ..options import Options, RuleSet
from .common import ColorOption, ConfigOption, Exit, IsolatedOption, PackagePathOption, choose, fail, format_option, session_for, split_inputs

FORMATS = ("auto", *DIFF_FORMATS)


def _tolerance(value: float) -> float:
    if not 0 <= value < 1:
        raise typer.BadParameter(f"{value:g} is not a relative tolerance: give a number from 0 to below 1, such as 1e-6")
    return value


def diff(
    inputs: Annotated[
        list[str],
        typer.Argument(
            metavar="OLD NEW [NAME:=VALUE]...",
            help="Two URDF or xacro files: a path, '-' for standard input, or REV:PATH for a file at a git revision "
            "(as git show names it: HEAD~1:urdf/robot.urdf.xacro), read with its includes as they were then "
            "(a package of another repository of the workspace as it is now, noted). "
            "NAME:=VALUE sets a xacro argument of both, over those the configuration's xacro-args table gives each.",
            show_default=False,
        ),
    ],
    output_format: format_option("auto (text, or github under GitHub Actions), text, json, markdown (a pull-request comment) or github.") = "auto",
    tolerance: Annotated[
        float,
        typer.Option("--tolerance", metavar="FRACTION", callback=_tolerance, help="Relative tolerance: numbers closer than this fraction of the larger are the same."),
    ] = 1e-6,
    package_path: PackagePathOption = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
    color: ColorOption = "auto",
) -> None:
    """Compare two versions of a robot by meaning, not text.

    Reports links and joints added, removed and renamed; each changed joint
    field, mass, centre of mass, inertia (with the percentage), geometry,
    material, transmission, ros2_control and gazebo block; the total mass and
    degrees of freedom; and each link whose pose at zero joint positions moved,
    in millimetres and degrees. Each change names the line of NEW's sources
    (OLD's for a removal) where it was written, through includes and macro
    calls. Number formatting, attribute order, comments and whitespace are
    never changes. Exit 0 when the robots are the same, 1 when they differ,
    2 when one cannot be read.
    """
    from .. import api
    from ..report import diff as formats

    output_format = choose(output_format, FORMATS)
    paths, mappings = split_inputs(inputs)
    if len(paths) != 2:
        raise fail(f"diff compares two files, OLD and NEW; got {len(paths)}")
    options = Options(RuleSet.TREE, tuple(mappings.items()), tuple(package_path or ()), config, isolated, format=output_format)
    with session_for(options) as session:
        difference, revisions = api.diff_with_revisions(paths[0], paths[1], {}, session, tolerance, {})
    formats.report(difference, Output.standard(color), resolve(output_format), revisions)
    if not difference.same:
        raise SystemExit(Exit.PROBLEMS)
