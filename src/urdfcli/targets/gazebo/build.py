"""Gazebo's URDF conversion, sdformat 12 (``sdf::Root::Load``, ``ign sdf -p``): the links it keeps,
from src/parser_urdf.cc (CreateSDF, CreateLink, ReduceFixedJoints)."""

from __future__ import annotations

from ...model.kinematics import children_by_joint_name, walks
from ...model.load import Loaded
from ...model.robot import Joint
from ...model.targets import Body, Build, Consumer, Profile, combined, declared_mass, declared_part, fused, joint_dof, tree_joints


def preserved_joints(loaded: Loaded) -> set[str]:
    """Fixed joints a ``<gazebo reference>`` keeps from lumping (preserveFixedJoint,
    disableFixedJointLumping)."""
    kept = set()
    for block in loaded.robot.blocks("gazebo"):
        reference = block.get("reference")
        for tag in ("preserveFixedJoint", "disableFixedJointLumping"):
            element = block.find(tag)
            if reference and element is not None and (element.text or "").strip() == "true":
                kept.add(reference)
    return kept


def build(loaded: Loaded, chosen: Profile) -> Build:
    robot = loaded.robot
    kept = preserved_joints(loaded)

    def lumped(joint: Joint) -> bool:
        return joint.type == "fixed" and joint.name not in kept

    members = fused(loaded, lambda joint: not lumped(joint))
    dropped: dict[str, str] = {}
    bodies = []
    for order in walks(robot).values():
        for link in order:
            if link not in members or link in dropped:
                continue
            links = members[link]
            joint = loaded.parent_joint(link)
            if link == "world" and joint is None:
                continue
            if sum(declared_mass(robot.links[n]) or 0.0 for n in links) == 0:  # sdformat: no inertial, or a mass equal to 0
                why = "it has no <inertial>" if robot.links[link].inertial is None else "its mass is 0"
                dropped[link] = why
                for below in subtree(loaded, link)[1:]:
                    dropped.setdefault(below, f"below {link}, which is dropped")
                continue
            mass, moments = combined(loaded, links, declared_part)
            bodies.append(Body(tuple(links), joint if joint is not None and not lumped(joint) else None, mass, moments, "declared (lumped)" if len(links) > 1 else "declared"))
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
    return Build(chosen, tuple(bodies), dropped, base, dof, changed)


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
