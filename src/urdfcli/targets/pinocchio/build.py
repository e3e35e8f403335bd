"""Pinocchio 4.1.0 (``pinocchio.buildModelFromUrdf``): the model it builds, from
src/parsers/urdf/model.cpp and model.hxx (the tree walk)."""

from __future__ import annotations

from ...model.load import Loaded
from ...model.targets import Body, Build, Consumer, Profile, Variant, declared_body, fused, joint_dof, moving, tree_joints


def build(loaded: Loaded, chosen: Profile) -> Build:
    members = fused(loaded, moving)
    bodies = []
    for top, links in members.items():
        joint = loaded.parent_joint(top)
        mass, moments = declared_body(loaded, tuple(links))
        bodies.append(Body(tuple(links), joint if moving(joint) else None, mass, moments, "declared"))
    mimic = "mimic" in chosen.variants
    changed, dof = {}, 0
    for joint in tree_joints(loaded):
        if joint.mimic is not None and joint.type in ("revolute", "continuous", "prismatic"):
            if mimic:
                changed[joint.name] = f"a mimic of {joint.mimic.joint} (no degree of freedom)"
                continue
            changed[joint.name] = "a free degree of freedom (<mimic> ignored)"
        if joint.type == "continuous":
            changed.setdefault(joint.name, "unbounded revolute (nq 2: cos, sin), its limits ignored")
        dof += joint_dof(joint)
    free = "free-flyer" in chosen.variants
    return Build(chosen, tuple(bodies), {}, "floating" if free else "fixed", dof + (6 if free else 0), changed)


# The plain errors whose models it loads all the same (tests/target_cases.py: PLAIN_ERRORS, one case each)
LOADS_ANYWAY = frozenset({
    "D004", "D013", "F001", "G001", "G002", "I001", "I005", "J007", "J008", "J009", "M001", "N003", "T003",
    "V001", "V002", "V003", "V004", "V005", "V006", "V007", "V010", "X002",
})

CONSUMER = Consumer("pinocchio", "Pinocchio", "C3", "pin 4.1.0 (PyPI), pinocchio.buildModelFromUrdf", (Variant("mimic", "buildModelFromUrdf(path, mimic=True)"), Variant("free-flyer", "buildModelFromUrdf(path, JointModelFreeFlyer())")), build, LOADS_ANYWAY)
