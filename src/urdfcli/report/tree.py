"""The kinematic tree for people (rich text, or plain ASCII) and for programs (JSON).

Rows come from ``kinematics.walk_all``: depth first from the start link,
children in the order of the names of the joints leading to them (the order
check_urdf prints). A joint that reaches a link already shown (a second
parent, or a loop closing) is shown once more, marked, and not followed.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Callable, Iterator
from typing import NamedTuple

from ..model.kinematics import depth_and_leaves, walk_all
from ..model.numbers import format_number
from ..model.robot import JOINT_TYPES, MOVING_AXIS_TYPES, Joint, Link, Robot, Vec3
from .escape import escape

# Degrees of freedom per joint type, as MoveIt and Pinocchio count them (planar: x, y and yaw).
DOF = {"fixed": 0, "revolute": 1, "continuous": 1, "prismatic": 1, "planar": 3, "floating": 6}
TYPE_STYLES = {
    "fixed": "bright_black",
    "revolute": "blue",
    "continuous": "green",
    "prismatic": "yellow",
    "floating": "red",
    "planar": "magenta",
}
UNICODE_GUIDES = ("├── ", "└── ", "│   ", "    ", "←", "…", "°", "↺ already shown above")
ASCII_GUIDES = ("|-- ", "`-- ", "|   ", "    ", "<-", "..", " deg", "(already shown above)")


class Row:
    __slots__ = ("depth", "joint", "link", "repeat", "hidden", "last")

    def __init__(self, depth: int, joint: Joint | None, link: str, repeat: bool = False) -> None:
        self.depth = depth
        self.joint = joint
        self.link = link
        self.repeat = repeat
        self.hidden = 0  # links below this one that --max-depth leaves out
        self.last = True  # the last child of its parent


class Summary(NamedTuple):
    links: int
    joints: Counter
    dof: int  # without the mimic joints: they follow others
    depth: int
    leaves: int
    mimics: int = 0  # moving joints that mimic another

    def text(self) -> str:
        by_type = ", ".join(f"{self.joints[t]} {t}" for t in JOINT_TYPES if self.joints[t])
        unknown = sum(n for t, n in self.joints.items() if t not in JOINT_TYPES)
        by_type += f"{', ' if by_type else ''}{unknown} of unknown type" if unknown else ""
        joints = sum(self.joints.values())
        return (
            f"{plural(self.links, 'link')}, {plural(joints, 'joint')}{f' ({by_type})' if by_type else ''}, "
            f"{self.dof} DOF{self.mimic_text()}, depth {self.depth}, {plural(self.leaves, 'leaf link')}"
        )

    def mimic_text(self) -> str:
        if not self.mimics:
            return ""
        return f" ({plural(self.mimics, 'mimic joint')} {'follows' if self.mimics == 1 else 'follow'} others, not counted)"

    def as_dict(self) -> dict:
        return {
            "links": self.links,
            "joints": {t: self.joints[t] for t in JOINT_TYPES if self.joints[t]},
            "dof": self.dof,
            "mimic_joints": self.mimics,
            "depth": self.depth,
            "leaf_links": self.leaves,
        }


def plural(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"


# -- joint details, shared with the graph ----------------------------------------


def short(value: float, digits: int = 4) -> str:
    """A number for people: 4 significant digits (or ``digits``), no ``-0``."""
    text = f"{value:.{digits}g}"
    return "0" if text == "-0" else text


def significant_digits(text: str) -> int:
    """The significant digits a number's text has: 3 in ``-0.00123e5``, 1 in ``100``."""
    return len(text.lower().lstrip("+-").partition("e")[0].replace(".", "").strip("0"))


def readable(value: float, digits: int = 6, written: int = 7) -> str:
    """A value as written when it is short (at most ``written`` significant digits: ``1.57``),
    else to ``digits`` significant digits: what xacro computed (``2.9670597283903604`` for
    ``${radians(170)}``, ``3.3333333333333335e-05`` for ``${1/30000}``) reads ``2.96706``.
    A zero reads ``0`` however it is signed (a CAD exporter's ``rpy="0 -0.000000 1.570796"``)."""
    text = format_number(value + 0.0)
    return text if significant_digits(text) <= written else short(value, digits)


def axis_text(axis: Vec3, number: Callable[[float], str] = format_number) -> str:
    """An axis as people read it: a CAD exporter's ``-0.000000 1.000000 -0.000000`` reads ``0 1 0``
    (adding 0.0 drops the sign of a zero, the one difference between -0 and 0)."""
    return " ".join(number(v + 0.0) for v in axis)


def limit_text(joint: Joint, number: Callable[[float], str] = format_number, ascii_only: bool = False, full: bool = False) -> str:
    """The range of a revolute joint (radians, and degrees to 4 digits) or a
    prismatic one (metres); ``full`` adds effort and velocity. Empty when none."""
    limit = joint.limit
    if limit is None or joint.type not in ("revolute", "prismatic", "continuous"):
        return ""
    dots = ".." if ascii_only else "…"
    parts = []
    if joint.type == "revolute":
        degree = " deg" if ascii_only else "°"
        degrees = f"{short(math.degrees(limit.lower))}{dots}{short(math.degrees(limit.upper))}{degree}"
        parts.append(f"{number(limit.lower)}{dots}{number(limit.upper)} rad ({degrees})")
    elif joint.type == "prismatic":
        parts.append(f"{number(limit.lower)}{dots}{number(limit.upper)} m")
    if full:
        effort = "N" if joint.type == "prismatic" else "Nm" if ascii_only else "N·m"
        speed = "m/s" if joint.type == "prismatic" else "rad/s"
        if limit.effort is not None:
            parts.append(f"effort {number(limit.effort)} {effort}")
        if limit.velocity is not None:
            parts.append(f"velocity {number(limit.velocity)} {speed}")
    return ", ".join(parts)


def joint_details(joint: Joint, ascii_only: bool = False) -> list[str]:
    """What the tree shows after a joint's type: axis, range, what it mimics."""
    parts = []
    if joint.type in MOVING_AXIS_TYPES:
        parts.append("axis " + axis_text(joint.axis))
    limits = limit_text(joint, readable, ascii_only=ascii_only)
    if limits:
        parts.append(limits)
    if joint.mimic is not None:
        parts.append(mimic_text(joint, ascii_only))
    return parts


def mimic_text(joint: Joint, ascii_only: bool = False) -> str:
    """What a mimic joint follows: ``mimics joint_2 × -0.25 + 0.1``."""
    mimic = joint.mimic
    factor = f" {'*' if ascii_only else '×'} {readable(mimic.multiplier)}" if mimic.multiplier != 1 else ""
    offset = f" {'-' if mimic.offset < 0 else '+'} {readable(abs(mimic.offset))}" if mimic.offset else ""
    return f"mimics {mimic.joint}{factor}{offset}"


# -- rows and summary -------------------------------------------------------------


def tree_rows(robot: Robot, start: str) -> list[Row]:
    """Every row of the tree from ``start``, with each row's ``last`` flag."""
    rows = [Row(depth, joint, link, repeat) for depth, joint, link, repeat in walk_all(robot, start)]
    sibling_after: list[bool] = []
    for row in reversed(rows):
        del sibling_after[row.depth + 1 :]
        while len(sibling_after) <= row.depth:
            sibling_after.append(False)
        row.last = not sibling_after[row.depth]
        sibling_after[row.depth] = True
    return rows


def summarise(robot: Robot, rows: list[Row]) -> Summary:
    """Counts over all ``rows`` (the whole tree below their first link)."""
    depth, leaves = depth_and_leaves(robot, rows[0].link)
    moving = [row for row in rows if row.joint is not None and DOF.get(row.joint.type or "", 0)]
    return Summary(
        links=sum(1 for row in rows if not row.repeat),
        joints=Counter(row.joint.type or "unknown" for row in rows if row.joint is not None),
        dof=sum(DOF.get(row.joint.type or "", 0) for row in moving if row.joint.mimic is None),
        depth=depth,
        leaves=len(leaves),
        mimics=sum(1 for row in moving if row.joint.mimic is not None),
    )


def cut(rows: list[Row], max_depth: int | None) -> list[Row]:
    """The rows down to ``max_depth``; each row at that depth counts the links it hides."""
    if max_depth is None:
        return rows
    kept: list[Row] = []
    for row in rows:
        if row.depth <= max_depth:
            kept.append(row)
        elif not row.repeat:
            kept[-1].hidden += 1  # depth first: the last row kept is its ancestor at max_depth
    return kept


# -- text -------------------------------------------------------------------------


def text_lines(
    robot: Robot, rows: list[Row], joints: bool = True, ascii_only: bool = False, notes: dict[str, str] | None = None
) -> Iterator[list[tuple[str, str]]]:
    """One line per row, with tree guides and joint details, as (text, rich style) pieces;
    ``notes`` adds a remark after a link or joint, by name (what a consumer makes of it)."""
    notes = notes or {}
    branch, corner, through, blank, arrow, more, _, again = ASCII_GUIDES if ascii_only else UNICODE_GUIDES
    open_levels: list[bool] = []  # per depth: does the ancestor there have siblings after it?
    for row in rows:
        del open_levels[row.depth :]
        line = []
        if row.depth:
            line.append(("".join(through if is_open else blank for is_open in open_levels[1:]), "bright_black"))
            line.append((corner if row.last else branch, "bright_black"))
        open_levels.append(not row.last)
        line.append((escape(row.link), "bold green" if row.depth == 0 else "bold"))
        if joints and row.joint is not None:
            line.append((f"  {arrow} ", "bright_black"))
            line.append((escape(row.joint.name), "cyan"))
            line.append((" (", "bright_black"))
            line.append((escape(row.joint.type or "unknown type"), TYPE_STYLES.get(row.joint.type or "", "red")))
            line.append((escape("".join(", " + part for part in joint_details(row.joint, ascii_only))), "bright_black"))
            line.append((")", "bright_black"))
        for name in (row.link, row.joint.name if row.joint is not None else None):
            if name in notes:
                line.append((f"  [{escape(notes[name])}]", "yellow"))
        if row.repeat:
            line.append((f"  {again}", "red"))
        if row.hidden:
            line.append((f"  {more} {plural(row.hidden, 'link')} below", "bright_black"))
        yield line


# -- JSON -------------------------------------------------------------------------


def joint_dict(joint: Joint) -> dict:
    limit = joint.limit
    return {
        "name": joint.name,
        "type": joint.type,
        "parent": joint.parent,
        "child": joint.child,
        "origin": {"xyz": list(joint.origin.xyz), "rpy": list(joint.origin.rpy)},
        "axis": list(joint.axis) if joint.type in MOVING_AXIS_TYPES else None,
        "limit": None
        if limit is None
        else {"lower": limit.lower, "upper": limit.upper, "effort": limit.effort, "velocity": limit.velocity},
        "mimic": None
        if joint.mimic is None
        else {"joint": joint.mimic.joint, "multiplier": joint.mimic.multiplier, "offset": joint.mimic.offset},
        "dof": DOF.get(joint.type or "", 0),
    }


def link_dict(link: Link, row: Row) -> dict:
    inertial = link.inertial
    data: dict = {"name": link.name, "mass": inertial.mass if inertial is not None else None}
    if row.repeat:
        data["repeat"] = True
    if row.hidden:
        data["hidden_links"] = row.hidden
    return data


def tree_json(robot: Robot, rows: list[Row], summary: Summary, targets: list[dict] | None = None) -> str:
    """``{"version", "robot", "root": LINK, "summary"}`` where a LINK is
    ``{"name", "mass", "children": [{"joint": {...}, "link": LINK}, ...]}``; and
    ``"targets"`` (what each consumer builds) when given.

    Written without recursion, so a chain of any depth serialises.
    """
    import json  # only for this format

    dump = json.dumps
    out = [f'{{"version": 1, "robot": {dump(robot.name)}, "root": ']
    open_depths: list[int] = []  # depths of the links whose children list is open
    counts: list[int] = []
    for row in rows:
        while open_depths and open_depths[-1] >= row.depth:
            out.append("]}}" if open_depths.pop() > 0 else "]}")
            counts.pop()
        if row.depth > 0:
            if counts[-1]:
                out.append(", ")
            counts[-1] += 1
            out.append(f'{{"joint": {dump(joint_dict(row.joint))}, "link": ')
        out.append(dump(link_dict(robot.links[row.link], row))[:-1] + ', "children": [')
        open_depths.append(row.depth)
        counts.append(0)
    while open_depths:
        out.append("]}}" if open_depths.pop() > 0 else "]}")
    out.append(f', "summary": {dump(summary.as_dict())}')
    out.append(f', "targets": {dump(targets)}}}' if targets else "}")
    return "".join(out)
