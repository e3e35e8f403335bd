"""The link tree as a Graphviz DOT graph, and its rendering with ``dot``.

Two styles. ``compat_dot`` writes exactly the statements urdf_to_graphviz
writes (same order, labels and C++ number formatting), for scripts that parse
them. ``styled_dot`` is for people: joints labelled with name and type and
coloured by type, a legend, origins on the edges, and optional limits, masses
and merged chains of fixed joints. Every user-supplied text is escaped.

The graphviz package is imported only when rendering.
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Iterable
from typing import NamedTuple

from ..model.kinematics import children_by_joint_name, walk
from ..model.robot import MOVING_AXIS_TYPES, Joint, Robot, Vec3
from .escape import escape
from .tree import axis_text, limit_text, mimic_text, readable

# Colour per joint type (the palette of matplotlib's tab10, easy to tell apart).
JOINT_COLOURS = {
    "fixed": "#7f7f7f",
    "revolute": "#1f77b4",
    "continuous": "#2ca02c",
    "prismatic": "#ff7f0e",
    "floating": "#d62728",
    "planar": "#9467bd",
}
UNKNOWN_COLOUR = "#000000"
DOT_PACKAGE_HINT = "install Graphviz (Debian/Ubuntu: sudo apt-get install graphviz)"


# -- urdf_to_graphviz, statement for statement ------------------------------------


def cpp_number(value: float) -> str:
    """A double as a default C++ ``ostream`` prints it: ``%g`` with 6
    significant digits (``1e-07``, ``1.23457e+08``, ``0.3``), ``-0`` kept."""
    if math.isnan(value):
        return "-nan" if math.copysign(1.0, value) < 0 else "nan"
    return "%g" % value


def urdfdom_rpy(rpy: Vec3) -> Vec3:
    """Roll, pitch, yaw as urdfdom gives them back: it stores an origin's
    ``rpy`` as a normalised quaternion and converts it back with getRPY, so
    ``0 0 0`` comes out as ``0 -0 0``. Same operations in the same order."""
    phi, the, psi = rpy[0] / 2.0, rpy[1] / 2.0, rpy[2] / 2.0
    sin, cos = math.sin, math.cos
    x = sin(phi) * cos(the) * cos(psi) - cos(phi) * sin(the) * sin(psi)
    y = cos(phi) * sin(the) * cos(psi) + sin(phi) * cos(the) * sin(psi)
    z = cos(phi) * cos(the) * sin(psi) - sin(phi) * sin(the) * cos(psi)
    w = cos(phi) * cos(the) * cos(psi) + sin(phi) * sin(the) * sin(psi)
    squared_norm = x * x + y * y + z * z + w * w
    if squared_norm <= 0.0:
        x, y, z, w = 0.0, 0.0, 0.0, 1.0
    else:
        s = math.sqrt(squared_norm)
        x, y, z, w = x / s, y / s, z / s, w / s
    sqx, sqy, sqz, sqw = x * x, y * y, z * z, w * w
    sarg = -2 * (x * z - w * y)
    pi_2 = 1.57079632679489661923
    if sarg <= -0.99999:
        return 0.0, -pi_2, 2 * math.atan2(x, -y)
    if sarg >= 0.99999:
        return 0.0, pi_2, 2 * math.atan2(-x, y)
    roll = math.atan2(2 * (y * z + w * x), sqw - sqx - sqy + sqz)
    yaw = math.atan2(2 * (x * y + w * z), sqw + sqx - sqy - sqz)
    return roll, math.asin(sarg), yaw


def compat_dot(robot: Robot, root: str) -> str:
    """urdf_to_graphviz's .gv file: links depth-first, then two edges per joint.

    Names are written as urdf_to_graphviz writes them, except that control
    and direction-changing characters are shown as escapes.
    """
    children = children_by_joint_name(robot)
    order = list(walk(robot, root, children))
    lines = ["digraph G {", "node [shape=box];"]
    lines += [f'"{escape(link)}" [label="{escape(link)}"];' for _, _, link in order]
    lines.append("node [shape=ellipse, color=blue, fontcolor=blue];")
    for _, joint, link in order:
        if joint is None:
            continue
        xyz = " ".join(cpp_number(v) for v in joint.origin.xyz)
        rpy = " ".join(cpp_number(v) for v in urdfdom_rpy(joint.origin.rpy))
        parent, name = escape(joint.parent), escape(joint.name)
        lines.append(f'"{parent}" -> "{name}" [label="xyz: {xyz} \\nrpy: {rpy}"]')
        lines.append(f'"{name}" -> "{escape(link)}"')
    lines.append("}")
    return "".join(line + "\n" for line in lines)


# -- the styled graph -------------------------------------------------------------


class Style(NamedTuple):
    """What the styled graph shows."""

    limits: bool = False
    inertial: bool = False
    rankdir: str = "TB"
    collapse_fixed: bool = False


def dot_text(text: str) -> str:
    """``text`` inside a DOT quoted string, shown literally: control characters
    escaped (a line break in a name too), then backslashes and quotes."""
    return escape(text).replace("\\", "\\\\").replace('"', '\\"')


def quote(text: str) -> str:
    """``text`` as a DOT quoted string whose label shows it literally."""
    return f'"{dot_text(text)}"'


def label(*lines: str) -> str:
    """A quoted, escaped DOT label of several centred lines."""
    return '"' + "\\n".join(dot_text(line) for line in lines if line) + '"'


def origin_lines(joint: Joint) -> list[str]:
    """``xyz: ...`` and ``rpy: ...``, each left out when zero."""
    parts = []
    if any(joint.origin.xyz):
        parts.append("xyz: " + " ".join(readable(v) for v in joint.origin.xyz))
    if any(joint.origin.rpy):
        parts.append("rpy: " + " ".join(readable(v) for v in joint.origin.rpy))
    return parts


def joint_lines(joint: Joint, style: Style) -> list[str]:
    lines = [joint.name, joint.type or "unknown type"]
    if joint.type in MOVING_AXIS_TYPES:
        lines.append("axis " + axis_text(joint.axis, readable))
    if style.limits:
        lines += limit_text(joint, readable, full=True).split(", ")
    if joint.mimic is not None:  # it moves with another joint: not a joint of its own to command
        lines.append(mimic_text(joint))
    return lines


def link_lines(robot: Robot, names: list[str], style: Style) -> list[str]:
    """A link's label; a merged group lists its links under the first."""
    lines = [names[0]]
    if style.inertial:
        inertial = robot.links[names[0]].inertial
        lines.append("no inertial" if inertial is None or inertial.mass is None else f"mass {readable(inertial.mass)} kg")
    shown = names[1:9]
    lines += [f"+ {name}" for name in shown]
    if len(names) > 1 + len(shown):
        lines.append(f"+ {len(names) - 1 - len(shown)} more")
    if style.inertial and len(names) > 1:
        masses = [robot.links[n].inertial.mass for n in names if robot.links[n].inertial and robot.links[n].inertial.mass]
        lines.append(f"total mass {readable(sum(masses))} kg")
    return lines


def fixed_groups(robot: Robot, root: str) -> dict[str, str]:
    """Each link's group head: the top of its chain of fixed joints."""
    head: dict[str, str] = {}
    for _, joint, link in walk(robot, root):
        head[link] = head[joint.parent] if joint is not None and joint.type == "fixed" else link
    return head


def styled_dot(robot: Robot, root: str, style: Style = Style()) -> str:
    """The design-review graph: links as boxes, joints as coloured ellipses."""
    order = list(walk(robot, root))
    head = fixed_groups(robot, root) if style.collapse_fixed else {link: link for _, _, link in order}
    members: dict[str, list[str]] = defaultdict(list)
    for _, _, link in order:
        members[head[link]].append(link)
    lines = [
        f"digraph {quote(robot.name or 'robot')} {{",
        f"graph [rankdir={style.rankdir}, fontname=\"Helvetica\", labelloc=t, fontsize=16, label={quote(robot.name or '')}];",
        'node [fontname="Helvetica", fontsize=11];',
        'edge [fontname="Helvetica", fontsize=9, arrowsize=0.7];',
        'node [shape=box, style="rounded,filled", fillcolor="#f5f5f5", color="#404040"];',
    ]
    for group, names in members.items():
        lines.append(f"{link_id(group)} [label={label(*link_lines(robot, names, style))}];")
    lines.append('node [shape=ellipse, style="filled", fillcolor="white"];')
    used_types = []
    for _, joint, link in order:
        if joint is None or (style.collapse_fixed and joint.type == "fixed"):
            continue
        colour = JOINT_COLOURS.get(joint.type or "", UNKNOWN_COLOUR)
        if joint.type not in used_types:
            used_types.append(joint.type)
        node = joint_id(joint.name)
        lines.append(f"{node} [label={label(*joint_lines(joint, style))}, color={quote(colour)}, fontcolor={quote(colour)}];")
        origin = origin_lines(joint)
        edge_label = f", label={label(*origin)}" if origin else ""
        lines.append(f"{link_id(head[joint.parent])} -> {node} [color={quote(colour)}{edge_label}];")
        lines.append(f"{node} -> {link_id(head[link])} [color={quote(colour)}];")
    if used_types:
        lines.append(legend([t for t in JOINT_COLOURS if t in used_types]))
    lines.append("}")
    return "".join(line + "\n" for line in lines)


def identity(name: str) -> str:
    """A name for a node ID: its backslashes doubled, so that no two names
    give one ID once control characters are escaped."""
    return name.replace("\\", "\\\\")


def link_id(name: str) -> str:
    return quote(f"link:{identity(name)}")


def joint_id(name: str) -> str:
    return quote(f"joint:{identity(name)}")


def legend(types: Iterable[str]) -> str:
    """A node whose HTML table shows each joint type drawn, in its colour."""
    rows = "".join(
        f'<tr><td bgcolor="{JOINT_COLOURS[t]}" width="14"> </td><td align="left"><font color="{JOINT_COLOURS[t]}">{t}</font></td></tr>'
        for t in types
    )
    table = f'<table border="0" cellborder="0" cellspacing="2"><tr><td colspan="2"><b>joint types</b></td></tr>{rows}</table>'
    return f'"legend" [shape=box, style="rounded", color="#bbbbbb", label=<{table}>];'


# -- rendering --------------------------------------------------------------------


class RenderError(Exception):
    """``dot`` could not make the picture (missing, failed or too slow)."""


def render(dot: str, output_format: str, timeout: float) -> bytes:
    """Run Graphviz ``dot`` through the graphviz package, within ``timeout`` seconds."""
    import subprocess

    from graphviz.backend import ExecutableNotFound, dot_command, execute

    command = dot_command.command("dot", output_format)
    try:
        process = execute.run_check(command, input=dot.encode("utf-8"), capture_output=True, timeout=timeout)
    except ExecutableNotFound:
        raise RenderError(f"the Graphviz program 'dot' was not found; {DOT_PACKAGE_HINT}") from None
    except subprocess.TimeoutExpired:
        raise RenderError(f"dot took longer than {timeout:g} s; try --collapse-fixed or a longer --timeout") from None
    except subprocess.CalledProcessError as error:
        message = (error.stderr or b"").decode("utf-8", "replace").strip().splitlines()
        raise RenderError(f"dot failed: {message[0] if message else f'exit status {error.returncode}'}") from None
    return process.stdout
