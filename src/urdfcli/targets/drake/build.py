"""Drake 1.51.1 (``Parser(plant).AddModels``): the bodies it builds, from
multibody/parsing/detail_urdf_parser.cc and detail_common.cc (``ParseSpatialInertia``)."""

from __future__ import annotations

import math

from ...model import massprops
from ...model.kinematics import roots
from ...model.load import Loaded
from ...model.robot import Link
from ...model.targets import WATER, Body, Build, Consumer, Profile, combined, declared_mass, declared_part, declared_tensors, joint_dof, moving, tree_joints, valid_tensor


def part(loaded: Loaded, link: Link):
    """Drake's mass properties: declared, or for an invalid inertia a solid sphere of
    water of the declared mass (1 kg when the mass is not positive)."""
    found = declared_part(link)
    if found is None or link.inertial is None:
        return found
    mass, com, tensor = found
    if replaces(loaded, link):
        mass = mass if mass > 0 else 1.0
        radius = (3.0 * mass / (4.0 * math.pi * WATER)) ** (1.0 / 3.0)
        return mass, com, massprops.sphere(mass, radius)
    return found


def replaces(loaded: Loaded, link: Link) -> bool:
    """Whether Drake replaces a link's inertia (ParseSpatialInertia: the checks of
    SpatialInertia::IsPhysicallyValid fail), judged on the principal moments every
    consumer reads (worked out once per model)."""
    declared = declared_tensors(loaded).get(link.name)
    mass = declared_mass(link)
    if declared is None or mass is None:  # no <inertial>, or one without a mass or a tensor: nothing to judge
        return False
    if mass < 0:
        return True
    if mass == 0:
        return not massprops.is_zero(declared.tensor)
    return not valid_tensor(mass, declared.tensor, 1e-14, declared.moments)


def build(loaded: Loaded, chosen: Profile) -> Build:
    robot = loaded.robot
    bodies = []
    for name, link in robot.links.items():
        mass, moments = combined(loaded, [name], lambda link: part(loaded, link))
        joint = loaded.parent_joint(name)
        source = "a solid water sphere (its inertia is not physical)" if replaces(loaded, link) else "declared"
        bodies.append(Body((name,), joint if moving(joint) else None, mass, moments, source))
    changed = {}
    dof = 0
    for joint in tree_joints(loaded):
        dof += joint_dof(joint)
        if joint.type == "continuous" and joint.limit is not None and joint.limit.has_lower and joint.limit.has_upper:
            changed[joint.name] = "revolute with limits (its <limit> lower and upper are kept)"
        elif joint.type == "floating":
            changed[joint.name] = "no joint: the child is a free body"
        elif joint.type in ("revolute", "prismatic") and joint.limit is not None and not joint.limit.has_lower and not joint.limit.has_upper:
            changed[joint.name] = "unlimited (its <limit> has no lower and upper)"
    floating_roots = [r for r in roots(robot) if r != "world"]  # a link named world is Drake's world body
    dof += 6 * len(floating_roots)
    return Build(chosen, tuple(bodies), {}, "floating" if floating_roots else "fixed", dof, changed)


# The plain errors whose models it loads all the same (tests/target_cases.py: PLAIN_ERRORS, one case each)
LOADS_ANYWAY = frozenset({
    "D013", "F001", "I001", "I005", "J003", "J006", "M001", "R003", "R004", "T001", "V001", "V007", "X002",
})

CONSUMER = Consumer("drake", "Drake", "C2", "drake 1.51.1 (PyPI), Parser(plant).AddModels on AddMultibodyPlantSceneGraph", (), build, LOADS_ANYWAY)
