"""MuJoCo 4.0.0 (``mujoco.MjModel.from_xml_path``): the bodies it builds, from src/xml/xml_urdf.cc
and its URDF defaults in src/xml/xml.cc (``fusestatic``, ``discardvisual``)."""

from __future__ import annotations

from typing import NamedTuple

from ...model import massprops
from ...model.load import Loaded
from ...read.memo import once
from ...model.robot import Link
from ...model.targets import WATER, Body, Build, Consumer, Profile, combined, declared_body, declared_mass, declared_part, fused, joint_dof, moving, primitive_volume, tree_joints

MJMINVAL = 1e-15  # MuJoCo's mjMINVAL: a moving body's mass and moments must exceed it
MJEPS = 1e-14  # MuJoCo's mjEPS: a declared tensor's smallest eigenvalue must reach it (mjuu_fullInertia)


class Options(NamedTuple):
    fusestatic: bool = True
    discardvisual: bool = True
    balanceinertia: bool = False
    inertiafromgeom: str = "auto"


def compiler_options(loaded: Loaded) -> Options:
    """The ``<mujoco><compiler .../></mujoco>`` options the model sets over the URDF defaults
    (read once per model: the build and most rules ask)."""
    return once(loaded, _compiler_options)


def _compiler_options(loaded: Loaded) -> Options:
    found = Options()
    for block in loaded.robot.blocks("mujoco"):
        for compiler in block.iter("compiler"):
            for name in ("fusestatic", "discardvisual", "balanceinertia"):
                value = compiler.get(name)
                if value in ("true", "false"):
                    found = found._replace(**{name: value == "true"})
            if compiler.get("inertiafromgeom") in ("true", "false", "auto"):
                found = found._replace(inertiafromgeom=compiler.get("inertiafromgeom"))
    return found


def part(link: Link, options: Options, fusing: bool = False):
    """A link's mass properties in MuJoCo: declared, or with no ``<inertial>`` (inertiafromgeom
    auto) those of its collision shapes at 1000 kg/m³ (unknown for a mesh). Fusing static
    bodies (``fusestatic``), MuJoCo counts a negative mass as none, its tensor kept (measured).
    With ``balanceinertia``, a tensor breaking A + B >= C has its principal moments replaced by
    their mean, link by link before fusing (src/user/user_objects.cc)."""
    if weighed_by_geometry(link, options):
        return geometry_body(link)
    found = declared_part(link)
    if found is not None and options.balanceinertia and massprops.triangle_violation(found[2], rel_tol=1e-9) is not None:
        mean = sum(massprops.principal_moments(found[2])) / 3.0
        found = (found[0], found[1], massprops.diagonal(mean, mean, mean))
    if fusing and found is not None and found[0] < 0:
        return 0.0, found[1], found[2]
    return found


def as_declared(loaded: Loaded, links: list[str], options: Options) -> bool:
    """Whether :func:`part` takes the mass properties of links none of which is weighed by
    its geometry as they are declared: no ``balanceinertia``, no negative mass to fuse."""
    fusing = len(links) > 1
    return not options.balanceinertia and not (fusing and any((declared_mass(loaded.robot.links[n]) or 0.0) < 0 for n in links))


def weighed_by_geometry(link: Link, options: Options) -> bool:
    """Whether MuJoCo takes a link's mass from its collision shapes (no ``<inertial>``)."""
    return link.inertial is None and options.inertiafromgeom != "false" and bool(link.collisions)


def geometry_body(link: Link, density: float = WATER):
    """(mass, com, tensor) of a link's collision primitives filled at ``density``; None with a mesh."""
    parts = []
    for shape in link.collisions:
        volume = primitive_volume(shape.geometry)
        if volume is None:
            return None
        mass = density * volume
        geometry = shape.geometry
        if geometry.kind == "box":
            tensor = massprops.box(mass, geometry.size)
        elif geometry.kind == "cylinder":
            tensor = massprops.cylinder(mass, geometry.radius, geometry.length)
        else:
            tensor = massprops.sphere(mass, geometry.radius)
        parts.append((mass, shape.origin.xyz, massprops.rotate(tensor, massprops.rotation(shape.origin.rpy))))
    return massprops.combine(parts)


def build(loaded: Loaded, chosen: Profile) -> Build:
    options = compiler_options(loaded)
    bodies, dropped = [], {}
    members = fused(loaded, lambda joint: moving(joint) or not options.fusestatic)
    root_fused = options.fusestatic
    for top, links in members.items():
        joint = loaded.parent_joint(top)
        if joint is None and root_fused:
            for link in links:
                dropped[link] = "fused into the world body"
            continue
        weighed = [n for n in links if weighed_by_geometry(loaded.robot.links[n], options)]
        if weighed or not as_declared(loaded, links, options):
            mass, moments = combined(loaded, links, lambda link: part(link, options, fusing=len(links) > 1))
        else:  # the body every consumer fusing these links builds
            mass, moments = declared_body(loaded, tuple(links))
        source = f"{', '.join(weighed)}: collision geometry at 1000 kg/m³" if weighed else "declared"
        bodies.append(Body(tuple(links), joint if moving(joint) else None, mass, moments, source))
    changed = {}
    joints = tree_joints(loaded)
    for joint in joints:
        limit = joint.limit
        if joint.type == "revolute" and limit is not None and limit.lower >= limit.upper:
            changed[joint.name] = "unlimited"
        elif joint.type == "planar":
            changed[joint.name] = "three joints (_TX, _TY, _RZ)"
        elif joint.mimic is not None:
            changed[joint.name] = f"an equality constraint on {joint.mimic.joint}"
    return Build(chosen, tuple(bodies), dropped, "fixed", sum(joint_dof(j) for j in joints), changed)


# The plain errors whose models it loads all the same (tests/target_cases.py: PLAIN_ERRORS, one case each)
LOADS_ANYWAY = frozenset({
    "D004", "D013", "F001", "G001", "G002", "I001", "I005", "J003", "J006", "J008", "M001", "N003", "N005",
    "N006", "R002", "R003", "R004", "T001", "V004", "V005", "V006", "V007", "V010", "X002",
})

CONSUMER = Consumer("mujoco", "MuJoCo", "C1", "mujoco 4.0.0 (PyPI), mujoco.MjModel.from_xml_path", (), build, LOADS_ANYWAY)
