"""Exactly what check_urdf prints: the tree of a file it accepts on standard output,
its errors on standard error."""

from __future__ import annotations

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


def rejected(result: Result) -> list:
    """The errors check_urdf itself reports: those of what urdfdom rejects."""
    return [d for d in result.diagnostics if d.severity is Severity.ERROR and REGISTRY[d.code].urdfdom]


def error_lines(result: Result) -> list[str]:
    lines = [f"Error:   {escape(d.message)}" for d in rejected(result)]
    return lines + ["ERROR: Model Parsing the xml failed"] if lines else []


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
        if errors:
            write(output.err, ([(line, "")] for line in errors))
        else:
            write(output.out, ([(line, "")] for line in tree_lines(result.loaded)))
        beyond = [d for d in result.errors if not REGISTRY[d.code].urdfdom]
        write(output.err, ([(concise_line(d), "")] for d in beyond))
