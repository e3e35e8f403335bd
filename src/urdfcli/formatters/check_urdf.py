"""Exactly what check_urdf prints on standard output for a file it accepts."""

from __future__ import annotations

from ..escape import escape
from ..loaded import Loaded


def tree_lines(loaded: Loaded) -> list[str]:
    """check_urdf's tree. A link with two parents is listed under both, as
    urdfdom does; a loop is cut where it closes (urdfdom would print forever).
    Names are shown escaped where check_urdf would print control characters."""
    robot = loaded.robot
    root = loaded.root
    if robot is None or root is None:
        return []
    from ..kinematics import children_by_joint_name  # (a model was read: its modules are loaded)

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


def error_lines(loaded: Loaded) -> list[str]:
    lines = [f"Error:   {escape(d.message)}" for d in loaded.diagnostics if d.severity.value == "error"]
    return lines + ["ERROR: Model Parsing the xml failed"] if lines else []
