"""Exactly what check_urdf prints: the tree of a file it accepts on standard output,
its errors on standard error.

urdfdom rejects some mistakes (check_urdf exits 255, and prints no tree) and only
logs others and goes on: a link's visual, collision or inertial it cannot read is
dropped, and a top-level material without a name or colour is kept as it is. For
those it prints its error lines and then the tree, and exits 0.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from ..diagnostics import Severity
from ..model.kinematics import children_by_joint_name
from ..model.load import Loaded
from ..rules import REGISTRY
from .base import Reporter
from .console import Output, write
from .escape import escape
from .lines import concise_line

if TYPE_CHECKING:
    from ..model.result import Result


def tree_lines(loaded: Loaded) -> list[str]:
    """check_urdf's tree. A link with two parents is listed under both, as
    urdfdom does; a loop is cut where it closes (urdfdom would print forever).
    Names are shown escaped where check_urdf would print control characters."""
    robot = loaded.robot if loaded is not None else None
    root = loaded.root if loaded is not None else None
    if robot is None or root is None:
        return []
    children = children_by_joint_name(robot)
    lines = [
        f"robot name is: {escape(robot.name or '')}",
        "---------- Successfully Parsed XML ---------------",
        f"root Link: {escape(root)} has {len(children.get(root, []))} child(ren)",
    ]
    stack = [(root, 0, iter(children.get(root, [])), 0)]
    on_path = {root}
    while stack:
        link, level, pending, count = stack[-1]
        joint = next(pending, None)
        if joint is None:
            stack.pop()
            on_path.discard(link)
            continue
        count += 1
        stack[-1] = (link, level, pending, count)
        lines.append("    " * (level + 1) + f"child({count}):  {escape(joint.child)}")
        if joint.child not in on_path:
            on_path.add(joint.child)
            stack.append((joint.child, level + 1, iter(children.get(joint.child, [])), 0))
    return lines


_IN_A_LINK_PART = re.compile(r"^link\[@name='(?:[^']|'')*'\]/(?:visual|collision|inertial)(?:\[\d+\])?(?:/|$)")
LOGGED_ON_MATERIALS = frozenset(("N003", "M001", "V007"))  # a top-level material urdfdom keeps as it is


def rejected(result: Result) -> list:
    """The errors check_urdf itself reports: those of what urdfdom rejects or logs."""
    return [d for d in result.diagnostics if d.severity is Severity.ERROR and REGISTRY[d.code].urdfdom]


def logged(diagnostic) -> bool:
    """Whether urdfdom only logs this error and goes on (check_urdf still exits 0): it is
    in a link's visual, collision or inertial, which urdfdom drops, or on a top-level
    material, which it keeps."""
    element = diagnostic.element or ""
    return bool(_IN_A_LINK_PART.match(element)) or (element.startswith("material") and diagnostic.code in LOGGED_ON_MATERIALS)


def logged_by_urdfdom(diagnostic) -> bool:
    """Whether the diagnostic is an error of urdfdom's that it only logs (check_urdf exits 0)."""
    return REGISTRY[diagnostic.code].urdfdom and logged(diagnostic)


def fails(result: Result) -> bool:
    """Whether check_urdf fails on the file (exit 255): an error it does not only log."""
    return any(not logged(d) for d in rejected(result))


def error_lines(result: Result) -> list[str]:
    lines = [f"Error:   {escape(d.message)}" for d in rejected(result)]
    return lines + ["ERROR: Model Parsing the xml failed"] if fails(result) else lines


class CheckUrdfReporter(Reporter):
    """check_urdf's output for each file: what urdfdom rejects on standard error, else
    the tree on standard output, as check_urdf prints them; the errors urdfdom does not
    check (a negative mass, a loop) follow on standard error, one line each."""

    name = "check_urdf"

    def check(self, results: list[Result]) -> None:
        write_check_urdf(results, self.output)


def write_check_urdf(results: list[Result], output: Output) -> None:
    for result in results:
        errors = error_lines(result)
        write(output.err, ([(line, "")] for line in errors))
        if not fails(result):
            write(output.out, ([(line, "")] for line in tree_lines(result.loaded)))
        beyond = [d for d in result.errors if not REGISTRY[d.code].urdfdom]
        write(output.err, ([(concise_line(d), "")] for d in beyond))
