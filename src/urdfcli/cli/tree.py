"""`urdfcli tree`: the kinematic tree in the terminal, or as nested JSON."""

from __future__ import annotations

from typing import Annotated

import typer

from ..options import Options, RuleSet
from ..report.console import Output, write
from ..report.escape import escape
from .common import (
    ColorOption,
    ConfigOption,
    Exit,
    FileArgument,
    IsolatedOption,
    PackagePathOption,
    TargetOption,
    choose,
    fail,
    format_option,
    session_for,
    split_inputs,
)


def tree(
    inputs: FileArgument,
    max_depth: Annotated[int | None, typer.Option("--max-depth", min=0, metavar="N", help="Show links down to depth N (the start link is depth 0).")] = None,
    from_link: Annotated[str | None, typer.Option("--from", metavar="LINK", help="Show the subtree below LINK instead of the whole tree.")] = None,
    no_joints: Annotated[bool, typer.Option("--no-joints", help="Show link names only.")] = False,
    ascii_only: Annotated[bool, typer.Option("--ascii", help="Plain ASCII characters (for logs).")] = False,
    output_format: format_option("text, or json (nested: each link with its children as {joint, link}).") = "text",
    target: TargetOption = None,
    package_path: PackagePathOption = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
    color: ColorOption = "auto",
) -> None:
    """Print the kinematic tree, each joint's type, axis and limits, and a summary.

    Each link is shown with the joint leading to it (name, type, axis, limits;
    revolute limits in radians with degrees alongside); the summary counts links,
    joints by type, degrees of freedom, depth and leaf links.

    Children are listed in the order of the names of the joints that lead to
    them, the order check_urdf uses. A link reached by a second joint (two
    parents, or a loop) is shown again, marked, and not followed. The summary
    covers the whole tree below the start link, also what --max-depth hides.

    Exit 0; 1 when the model has errors, the ones `check` reports apart from a
    missing or unreadable mesh (printed on stderr; the tree is still shown when
    there is one); 2 when the input cannot be read.
    """
    from ..targets import build, profiles
    from ..report.targets import build_dict
    from ..report.targets import summary as target_summary
    from ..report.tree import cut, summarise, text_lines, tree_json, tree_rows
    from .drawn import load_model, report_errors, start_link, target_notes

    output_format = choose(output_format, ("text", "json"))
    paths, mappings = split_inputs(inputs)
    if len(paths) != 1:
        raise fail(f"tree takes one input file, got {len(paths)}")
    output = Output.standard(color)
    options = Options(RuleSet.CHECK, tuple(mappings.items()), tuple(package_path or ()), config, isolated, format=output_format)
    with session_for(options) as session:
        result = load_model(paths[0], session)
        has_errors = report_errors(result, output, session)
        start = start_link(result, from_link, output)
        if start is None:
            raise SystemExit(Exit.PROBLEMS)
        robot = result.robot
        rows = tree_rows(robot, start)
        summary = summarise(robot, rows)
        shown = cut(rows, max_depth)
        builds = [build(result.loaded, chosen) for value in target or () for text in value.split(",") for chosen in profiles(text)]
        notes = target_notes(builds)
        if options.format == "json":
            output.out.file.write(tree_json(robot, shown, summary, [build_dict(b) for b in builds]) + "\n")
        else:
            write(output.out, text_lines(robot, shown, joints=not no_joints, ascii_only=ascii_only, notes=notes))
            write(output.out, [[(summary.text(), "bold")]])
            write(output.out, [[(escape(target_summary(b)), "bold")] for b in builds])
    if has_errors:
        raise SystemExit(Exit.PROBLEMS)
