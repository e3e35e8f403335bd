"""Isaac Sim 6's URDF importer, stage 1: urdf-usd-converter 0.3.4 (_impl/link.py,
_impl/link_hierarchy.py). Isaac Sim's Kit post-processing is not modelled."""

from __future__ import annotations

from ...model.load import Loaded
from ...read.memo import once
from ...model.robot import Link
from ...model.targets import Body, Build, Consumer, Profile, declared_body, declared_mass, joint_dof, moving, tree_joints


def zero_equivalent(link: Link) -> bool:
    """urdf-usd-converter's "no inertial data": no <inertial> or mass, or a mass <= 0 with
    no tensor or a zero diagonal (``_is_zero_equivalent_inertial``)."""
    inertial = link.inertial
    if inertial is None or inertial.mass is None:
        return True
    if inertial.mass > 0:
        return False
    tensor = inertial.inertia
    return tensor is None or all(tensor[key] == 0 for key in ("ixx", "iyy", "izz"))


def merged_child(loaded: Loaded, link: Link) -> str | None:
    """The inertial-only child whose inertia the converter writes onto ``link`` (a link with
    shapes but no inertial data): the first one on a fixed joint (``_fixed_dummy_inertia_children``)."""
    return merged_children(loaded).get(link.name)


def merged_children(loaded: Loaded) -> dict[str, str]:
    """Each link -> its merged child (see :func:`merged_child`), found in one pass over the
    joints per model."""
    return once(loaded, _merged_children)


def _merged_children(loaded: Loaded) -> dict[str, str]:
    links = loaded.robot.links
    found: dict[str, str] = {}
    for joint in loaded.robot.joints.values():
        parent, child = links.get(joint.parent), links.get(joint.child)
        if joint.type != "fixed" or parent is None or child is None or joint.parent in found:
            continue
        if zero_equivalent(parent) and (parent.visuals or parent.collisions) and not zero_equivalent(child) and not (child.visuals or child.collisions):
            found[joint.parent] = child.name
    return found


def build(loaded: Loaded, chosen: Profile) -> Build:
    bodies, changed, dof = [], {}, 0
    merged = merged_children(loaded)
    absorbed = set(merged.values())
    for name, link in loaded.robot.links.items():
        if name in absorbed:
            continue
        joint = loaded.parent_joint(name)
        written = loaded.robot.links[merged[name]] if name in merged else link
        mass = declared_mass(written)
        if mass:
            source = f"declared by {written.name} (written unchecked)" if name in merged else "declared (written unchecked)"
            moments = declared_body(loaded, (written.name,))[1]
        else:
            source, mass, moments = "derived by the physics engine from the collision shapes (mass 0 is unset in USD)", None, None
        bodies.append(Body((name, merged[name]) if name in merged else (name,), joint if moving(joint) else None, mass, moments, source))
    for joint in tree_joints(loaded):
        if joint.type in ("revolute", "prismatic") and joint.limit is None:
            changed[joint.name] = "locked (no <limit>: lower = upper = 0)"
            continue
        if joint.type == "floating":
            changed[joint.name] = "no joint: the child is a free body"
        dof += joint_dof(joint)
    return Build(chosen, tuple(bodies), {}, "fixed", dof, changed)


# The plain errors whose models it loads all the same (tests/target_cases.py: PLAIN_ERRORS, one case each)
LOADS_ANYWAY = frozenset({
    "D004", "D013", "F001", "G001", "G002", "I001", "I005", "J003", "J006", "J009", "M001", "R003", "T001",
    "T003", "V002", "V005", "V006", "V010", "X002",
})

CONSUMER = Consumer("isaac", "Isaac Sim", "C7", "urdf-usd-converter 0.3.4 (PyPI), stage 1 of Isaac Sim 6's URDF importer", (), build, LOADS_ANYWAY)
