"""`urdfcli tree`: the kinematic tree in the terminal, or as nested JSON."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated

from ..diagnostics import Severity
from ..formatters.text import plain, print_diagnostic
from ..formatters.tree import cut, summarise, text_lines, tree_json, tree_rows
from ..kinematics import roots
from ..loaded import Loaded
from ..suggestions import close_matches
from .common import ConfigOption, Exit, FileArgument, IsolatedOption, PackagePathOption, configurations, fail, load_one, split_inputs, stderr, stdout
from .options import BadValue, Option


def tree(
    inputs: FileArgument,
    max_depth: Annotated[int | None, Option("--max-depth", min=0, metavar="N", help="Show links down to depth N (the start link is depth 0).")] = None,
    from_link: Annotated[str | None, Option("--from", metavar="LINK", help="Show the subtree below LINK instead of the whole tree.")] = None,
    no_joints: Annotated[bool, Option("--no-joints", help="Show link names only.")] = False,
    ascii_only: Annotated[bool, Option("--ascii", help="Plain ASCII characters (for logs).")] = False,
    output_format: Annotated[str, Option("--format", "-f", metavar="FORMAT", help="text, or json (nested: each link with its children as {joint, link}).", case_sensitive=False)] = "text",
    package_path: PackagePathOption = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
) -> None:
    """Print the kinematic tree, each joint's type, axis and limits, and a summary.

    Each link is shown with the joint leading to it (name, type, axis, limits;
    revolute limits in radians with degrees alongside); the summary counts links,
    joints by type, degrees of freedom, depth and leaf links.

    Children are listed in the order of the names of the joints that lead to
    them, the order check_urdf uses. A link reached by a second joint (two
    parents, or a loop) is shown again, marked, and not followed. The summary
    covers the whole tree below the start link, also what --max-depth hides.

    Exit 0; 1 when the model has errors, the ones `check` reports (printed on
    stderr; the tree is still shown when there is one); 2 when the input
    cannot be read.
    """
    if output_format.lower() not in ("text", "json"):
        raise BadValue(f"unknown format {output_format!r}; choose text or json", "--format")
    paths, mappings = split_inputs(inputs)
    if len(paths) != 1:
        raise fail(f"tree takes one input file, got {len(paths)}")
    loaded = load_model(paths[0], mappings, package_path, config, isolated)
    has_errors = report_errors(loaded)
    start = start_link(loaded, from_link)
    if start is None:
        raise SystemExit(Exit.PROBLEMS)
    robot = loaded.robot
    rows = tree_rows(robot, start)
    summary = summarise(robot, rows)
    shown = cut(rows, max_depth)
    if output_format.lower() == "json":
        sys.stdout.write(tree_json(robot, shown, summary) + "\n")
    else:
        lines = text_lines(robot, shown, joints=not no_joints, ascii_only=ascii_only)
        if plain(stdout):
            stdout.file.writelines("".join(text for text, _ in line) + "\n" for line in lines)
        else:
            from rich.text import Text  # only to style: plain output never imports rich

            for line in lines:
                stdout.print(Text.assemble(*line), soft_wrap=True, highlight=False)
        stdout.print(summary.text(), style="bold", markup=False, highlight=False)
    if has_errors:
        raise SystemExit(Exit.PROBLEMS)


def load_model(path: str, mappings: dict[str, str], package_path: list[str] | None, config: Path | None = None, isolated: bool = False) -> Loaded:
    """Load one input for drawing, with its configuration and the rules `check` runs:
    its errors are the model's errors, the same as `check` reports."""
    return load_one(path, mappings, package_path, "check", configurations(config, isolated))


def report_errors(loaded: Loaded) -> bool:
    """Print the model's errors on stderr as `check` prints them; whether there were any."""
    errors = [d for d in loaded.diagnostics if d.severity is Severity.ERROR]
    for diagnostic in errors:
        print_diagnostic(stderr, diagnostic, excerpt=True)
    return bool(errors) or loaded.robot is None or loaded.robot.at is None


def start_link(loaded: Loaded, from_link: str | None) -> str | None:
    """The link to draw from: ``--from``, else the root. None (after saying
    why) when the model has no single root; an unknown ``--from`` exits 2."""
    robot = loaded.robot
    if robot is None or robot.at is None or not robot.links:
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
            stderr.print(f"urdfcli: {len(found)} links have no parent; choose one with --from LINK", markup=False)
        else:
            stderr.print("urdfcli: every link has a parent (a loop), so there is no root; choose one with --from LINK", markup=False)
        return None
    return loaded.root
