"""`urdfcli tree`: the kinematic tree in the terminal, or as nested JSON."""

from __future__ import annotations

from typing import Annotated

import typer

from .. import api
from ..model.kinematics import roots
from ..model.result import Result, Unreadable
from ..model.targets import build, profile
from ..options import Options, RuleSet
from ..report.escape import escape
from ..report.console import Output, write
from ..report.lines import diagnostic_lines
from ..report.targets import build_dict, joint_notes, link_notes
from ..report.targets import summary as target_summary
from ..report.tree import cut, summarise, text_lines, tree_json, tree_rows
from ..rules import REGISTRY, Kind
from ..rules.suggestions import close_matches
from ..session import Session
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
        builds = [build(result.loaded, profile(text)) for value in target or () for text in value.split(",")]
        notes = target_notes(builds)
        if options.format == "json":
            output.out.file.write(tree_json(robot, shown, summary, [build_dict(b) for b in builds]) + "\n")
        else:
            write(output.out, text_lines(robot, shown, joints=not no_joints, ascii_only=ascii_only, notes=notes))
            write(output.out, [[(summary.text(), "bold")]])
            write(output.out, [[(escape(target_summary(b)), "bold")] for b in builds])
    if has_errors:
        raise SystemExit(Exit.PROBLEMS)


def target_notes(builds) -> dict[str, str]:
    """What the targets make of each link and joint, each said by its target when there are several."""
    notes: dict[str, list[str]] = {}
    for built in builds:
        prefix = f"{built.profile.name}: " if len(builds) > 1 else ""
        for name, note in (link_notes(built) | joint_notes(built)).items():
            notes.setdefault(name, []).append(prefix + note)
    return {name: "; ".join(found) for name, found in notes.items()}


def load_model(path: str, session: Session) -> Result:
    """One input to draw, with its configuration and the rules `check` runs (its
    errors are the model's errors, as `check` reports them): the first argument
    set ``[tool.urdfcli] models`` lists for it, under the command line's."""
    config = api.configured(session)(path)
    first_set = (config.argument_sets(path) or [{}])[0]
    found = api.check_target(api.Target(path), session.using(session.options.but(arguments=tuple({**first_set, **session.options.mappings}.items()))))
    if isinstance(found, Unreadable):
        raise fail(found.reason)
    return found


def report_errors(result: Result, output: Output, session: Session) -> bool:
    """Print the model's errors on stderr as `check` prints them; whether there were any.
    A missing or unreadable mesh is no error of the tree: it is left to `check`."""
    errors = [d for d in result.errors if REGISTRY[d.code].kind is not Kind.FILES]
    write(output.err, (line for d in errors for line in diagnostic_lines(d, session.files)))
    loaded = result.loaded
    return bool(errors) or loaded is None or not loaded.modelled


def start_link(result: Result, from_link: str | None, output: Output) -> str | None:
    """The link to draw from: ``--from``, else the root. None (after saying
    why) when the model has no single root; an unknown ``--from`` exits 2."""
    loaded = result.loaded
    robot = result.robot
    if loaded is None or not loaded.modelled or not robot.links:
        return None
    if from_link is not None:
        if from_link not in robot.links:
            close = close_matches(from_link, robot.links, n=3)
            suggestion = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
            raise fail(f"no link named {from_link!r} in robot {robot.name!r}{suggestion}")
        return from_link
    if loaded.root is None:
        found = roots(robot)
        if found:
            output.err.file.write(f"urdfcli: {len(found)} links have no parent; choose one with --from LINK\n")
        else:
            output.err.file.write("urdfcli: every link has a parent (a loop), so there is no root; choose one with --from LINK\n")
        return None
    return loaded.root
