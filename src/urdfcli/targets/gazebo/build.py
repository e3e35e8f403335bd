"""Gazebo's URDF conversion, sdformat 12 (``sdf::Root::Load``, ``ign sdf -p``): the links it keeps,
from src/parser_urdf.cc (CreateSDF, CreateLink, ReduceFixedJoints)."""

from __future__ import annotations

from typing import NamedTuple

from ...model.kinematics import children_by_joint_name, walks
from ...model.load import Loaded
from ...model.robot import Joint
from ...model.massprops import number
from ...model.targets import Body, Build, Consumer, Profile, declared_body, declared_mass, fused, joint_dof, tree_joints


def preserved_joints(loaded: Loaded) -> set[str]:
    """Fixed joints a ``<gazebo reference>`` keeps from lumping (preserveFixedJoint,
    disableFixedJointLumping)."""
    kept = set()
    for block in loaded.robot.blocks("gazebo"):
        reference = block.get("reference")
        if not reference:
            continue
        seen = set()  # the first element of each tag decides, as find() gives it
        for element in block:
            if element.tag in KEEPS and element.tag not in seen:
                seen.add(element.tag)
                if (element.text or "").strip() == "true":
                    kept.add(reference)
    return kept


KEEPS = ("preserveFixedJoint", "disableFixedJointLumping")


NO_MASS = 1e-6  # sdformat 12 compares a mass with 0 by ignition::math::equal, whose tolerance is 1e-6


class Lumped(NamedTuple):
    """A link's inertial once sdformat has lumped its fixed children into it (ReduceInertialToParent):
    whether it has one, its mass, and whether its centre of mass became NaN (a mass added to a
    total of 0: dMassAdd divides by the sum)."""

    inertial: bool
    mass: float
    nan: bool


def build(loaded: Loaded, chosen: Profile) -> Build:
    """What sdformat 12 makes of the model. ReduceFixedJoints first lumps each link on a fixed
    joint (not one from ``world``, nor kept by ``preserveFixedJoint``) into its parent, children
    first, in the order of their joints' names. CreateSDF then walks the tree from the root: a
    link (not ``world``) without an inertial or whose mass is within 1e-6 of 0 is "not modeled",
    and nothing below it is visited: its joint and every link below go (a massless link on a
    fixed joint takes only the moving joints below it). A link on a moving joint becomes an SDF
    link; one whose centre of mass is NaN is refused ("Pose values must be finite")."""
    robot = loaded.robot
    kept = preserved_joints(loaded)
    children = children_by_joint_name(robot)

    def lumped(joint: Joint | None) -> bool:
        return joint is not None and joint.type == "fixed" and joint.name not in kept and joint.parent != "world"

    inertials: dict[str, Lumped] = {}

    def lump(link: str) -> Lumped:
        if link in inertials:
            return inertials[link]
        own = robot.links[link]
        found = inertials[link] = Lumped(own.inertial is not None, declared_mass(own) or 0.0, False)  # a loop comes back to this
        for joint in children.get(link, ()):
            if lumped(joint) and joint.child in robot.links and joint.child != link:
                child = lump(joint.child)
                if child.inertial:
                    total = found.mass + child.mass
                    found = Lumped(True, total, found.nan or child.nan or total == 0)
        inertials[link] = found
        return found

    members = fused(loaded, lambda joint: not lumped(joint))
    dropped: dict[str, str] = {}
    broken: dict[str, str] = {}
    bodies = []

    visited: set[str] = set()

    def visit(link: str, joint: Joint | None) -> None:
        if link in visited:  # a second parent, or a loop: sdformat refuses such a model (urdfdom's T003, T004)
            return
        visited.add(link)
        found = lump(link)
        if link != "world" and (not found.inertial or abs(found.mass) <= NO_MASS):
            massless = "has no <inertial>" if not found.inertial else "has a mass of 0" if found.mass == 0 else f"has a mass of {number(found.mass)} kg, within 1e-6 of 0"
            if lumped(joint):  # lumped, nothing of it lost: the moving joints below it go
                because = f"below {link}, which {massless}"
                for below in children.get(link, ()):
                    if not lumped(below) and below.child != link:
                        dropped[below.child] = because
                        for further in subtree(loaded, below.child)[1:]:
                            dropped.setdefault(further, because)
                    elif below.child != link:
                        skip_lumped(below.child, because)
                return
            dropped[link] = f"it {massless}"
            for below in subtree(loaded, link)[1:]:
                dropped.setdefault(below, f"below {link}, which is dropped")
            return
        if link != "world" and not lumped(joint):
            links = members[link]
            mass, moments = declared_body(loaded, tuple(links))
            moving = joint if joint is not None and joint.type != "fixed" else None
            bodies.append(Body(tuple(links), moving, mass, moments, "declared (lumped)" if len(links) > 1 else "declared"))
            if found.nan:
                massless = ", ".join(f"'{n}'" for n in links[1:] if robot.links[n].inertial is not None and not declared_mass(robot.links[n]))
                broken[link] = f"lumping the massless {massless} into it through fixed joints makes its centre of mass NaN"
        for below in children.get(link, ()):
            if below.child != link and below.child not in dropped:
                visit(below.child, below)

    def skip_lumped(link: str, because: str) -> None:
        """A lumped link below a massless one is not visited: its moving joints go too, for the same reason."""
        for below in children.get(link, ()):
            if below.child == link:
                continue
            if lumped(below):
                skip_lumped(below.child, because)
            else:
                for further in subtree(loaded, below.child):
                    dropped.setdefault(further, because)

    for root in walks(robot):
        visit(root, None)
    changed, dof = {}, 0
    for joint in tree_joints(loaded):
        if joint.child in dropped:
            continue
        limit = joint.limit
        if joint.type == "continuous":
            changed[joint.name] = "revolute with limits of ±1e16"
        elif joint.type in ("revolute", "prismatic") and limit is not None and limit.lower > limit.upper:
            changed[joint.name] = "its limits swapped"
        if joint.mimic is not None:
            changed[joint.name] = "a free joint (<mimic> dropped by sdformat 12)"
        dof += joint_dof(joint)
    base = "fixed" if "world" in robot.links else "floating"
    return Build(chosen, tuple(bodies), dropped, base, dof, changed, broken=broken)


def subtree(loaded: Loaded, top: str) -> list[str]:
    """``top`` and every link below it, parents first."""
    children = children_by_joint_name(loaded.robot)
    order, stack, seen = [], [top], {top}
    while stack:
        link = stack.pop()
        order.append(link)
        for joint in reversed(children.get(link, ())):
            if joint.child not in seen:
                seen.add(joint.child)
                stack.append(joint.child)
    return order


# The plain errors whose models it loads all the same (tests/target_cases.py: PLAIN_ERRORS, one case each)
LOADS_ANYWAY = frozenset({
    "D004", "D013", "F001", "J008", "J009", "V006", "V010",
})

CONSUMER = Consumer("gazebo", "Gazebo", "C5", "sdformat 12.3 (Debian 12), ign sdf", (), build, LOADS_ANYWAY)
