"""KDL as robot_state_publisher builds it: kdl_parser 1.14 ``treeFromUrdfModel``
(kdl_parser/src/kdl_parser.cpp) over urdfdom."""

from __future__ import annotations

from ...model.load import Loaded
from ...model.targets import Body, Build, Consumer, Profile, declared_body, declared_mass, joint_dof, moving, tree_joints


def build(loaded: Loaded, chosen: Profile) -> Build:
    root = loaded.root
    bodies, changed, dof = [], {}, 0
    for name, link in loaded.robot.links.items():
        joint = loaded.parent_joint(name)
        if name == root:
            continue  # the root is the tree's base, not a segment
        mass, moments = declared_body(loaded, (name,))
        bodies.append(Body((name,), joint if moving(joint) else None, mass, moments, "declared"))
    for joint in tree_joints(loaded):
        if joint.type in ("floating", "planar"):
            changed[joint.name] = "fixed (KDL has no floating or planar joint)"
            continue
        dof += joint_dof(joint)
    dropped = {root: "the root's inertia is dropped (it is the tree's base)"} if root is not None and (declared_mass(loaded.robot.links[root]) or 0.0) > 0 else {}
    return Build(chosen, tuple(bodies), dropped, "fixed", dof, changed)


# The plain errors whose models it loads all the same (tests/target_cases.py: PLAIN_ERRORS, one case each)
LOADS_ANYWAY = frozenset({
    "D004", "D013", "F001", "G001", "G002", "I001", "I005", "J007", "J008", "J009", "M001", "N003", "T003",
    "V001", "V002", "V003", "V004", "V005", "V006", "V007", "V010",
})

CONSUMER = Consumer("kdl", "KDL", "C6", "kdl_parser 1.14.2 with urdfdom 3.0.1 (Debian 12), treeFromUrdfModel", (), build, LOADS_ANYWAY)
