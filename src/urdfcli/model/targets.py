"""What each consumer builds from a model: its bodies (links fused or lumped into
one), the links it drops, a fixed or floating base, its degrees of freedom, and
the masses and tensors it will use.

One function per consumer, each from what the consumer's source does (cited in
docs/targets.md and in the rules of :mod:`urdfcli.rules.targets`); the target
rules, ``tree --target`` and ``inertia --target`` all read the same
:class:`Build`. Nothing here imports a consumer: these are predictions,
checked against the real programs by the test suite.

A profile is a consumer and the options it is run with (``pybullet:inertia-from-file``,
``pinocchio:mimic``); where the model itself sets a consumer's options (MuJoCo's
``<mujoco><compiler>``, Gazebo's ``<preserveFixedJoint>``), they are read from it.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..read.memo import once
from . import massprops
from .kinematics import children_by_joint_name, roots, walks
from .load import Loaded
from .massprops import Matrix, Vector
from .poses import body_poses
from .robot import Geometry, Joint, Link

NAMES = {
    "mujoco": "MuJoCo",
    "drake": "Drake",
    "pinocchio": "Pinocchio",
    "pybullet": "PyBullet",
    "gazebo": "Gazebo",
    "kdl": "KDL",
    "isaac": "Isaac Sim",
}
VARIANTS = {
    "mujoco": (),
    "drake": (),
    "pinocchio": ("mimic", "free-flyer"),
    "pybullet": ("inertia-from-file", "fixed-base"),
    "gazebo": (),
    "kdl": (),
    "isaac": (),
}
CODES = {"mujoco": "C1", "drake": "C2", "pinocchio": "C3", "pybullet": "C4", "gazebo": "C5", "kdl": "C6", "isaac": "C7"}  # the rules' prefixes
DOF = {"fixed": 0, "revolute": 1, "continuous": 1, "prismatic": 1, "planar": 3, "floating": 6}
MJMINVAL = 1e-15  # MuJoCo's mjMINVAL: a moving body's mass and moments must exceed it
WATER = 1000.0  # kg/m³: MuJoCo's default geom density, and Drake's replacement sphere


class Profile(NamedTuple):
    """A consumer and the options it runs with."""

    target: str
    variants: frozenset[str] = frozenset()

    @property
    def name(self) -> str:
        return NAMES[self.target]

    def text(self) -> str:
        return ":".join((self.target, *sorted(self.variants)))


def profile(text: str) -> Profile:
    """``NAME`` or ``NAME:VARIANT[:VARIANT]``; raises ValueError saying what is known."""
    target, *variants = (part.strip().lower() for part in text.split(":"))
    if target not in NAMES:
        raise ValueError(f"unknown target '{text}'; the targets are {', '.join(NAMES)}")
    for variant in variants:
        if variant not in VARIANTS[target]:
            known = ", ".join(f"{target}:{v}" for v in VARIANTS[target]) or "none"
            raise ValueError(f"unknown variant '{variant}' of target {target}; its variants are {known}")
    return Profile(target, frozenset(variants))


class Body(NamedTuple):
    """A body as the consumer builds it: the links it holds (the top one first),
    the joint that carries it (None: welded to the world or the root), and the mass
    properties the consumer will use (None: it cannot be told without the mesh files)."""

    links: tuple[str, ...]
    joint: Joint | None
    mass: float | None
    moments: Vector | None  # principal moments about the centre of mass
    source: str  # where the consumer takes them from

    @property
    def top(self) -> str:
        return self.links[0]


class Build(NamedTuple):
    profile: Profile
    bodies: tuple[Body, ...]
    dropped: dict[str, str]  # link -> why the consumer leaves it out
    base: str  # "fixed" or "floating"
    dof: int  # velocities (nv): each mimic joint counted when the consumer keeps it free
    changed: dict[str, str]  # joint -> what the consumer makes of it, where that is not what URDF says
    notes: tuple[str, ...] = ()


# -- shared pieces ----------------------------------------------------------------------


def declared_mass(link: Link) -> float | None:
    inertial = link.inertial
    return inertial.mass if inertial is not None else None


def declared_matrix(link: Link) -> Matrix | None:
    inertial = link.inertial
    if inertial is None or inertial.inertia is None:
        return None
    tensor = massprops.matrix(inertial.inertia)
    if not any(inertial.origin.rpy):  # most inertials are not turned: no rotation to apply
        return tensor
    return massprops.rotate(tensor, massprops.rotation(inertial.origin.rpy))


def primitive_volume(geometry: Geometry | None) -> float | None:
    """The volume of a box, cylinder or sphere (None for a mesh or a shape without size)."""
    if geometry is None:
        return None
    if geometry.kind == "box" and geometry.size is not None:
        return massprops.box_volume(geometry.size)
    if geometry.kind == "cylinder" and geometry.radius is not None and geometry.length is not None:
        return massprops.cylinder_volume(geometry.radius, geometry.length)
    if geometry.kind == "sphere" and geometry.radius is not None:
        return massprops.sphere_volume(geometry.radius)
    return None


def mesh_extension(uri: str) -> str:
    """The file extension of a mesh URI, lower-case, with its dot ('' when none)."""
    name = uri.rsplit("/", 1)[-1]
    return "." + name.rsplit(".", 1)[-1].lower() if "." in name else ""


def moving(joint: Joint | None) -> bool:
    return joint is not None and joint.type not in (None, "fixed")


def tree_joints(loaded: Loaded) -> list[Joint]:
    """The joints of the tree below each root, parents before children."""
    children = children_by_joint_name(loaded.robot)
    found = []
    for order in walks(loaded.robot).values():
        for link in order:
            found.extend(joint for joint in children.get(link, ()) if joint.child != link)
    return found


def fused(loaded: Loaded, keeps_joint) -> dict[str, list[str]]:
    """Each body's top link -> the links fused into it: a link whose parent joint the
    consumer does not keep (``keeps_joint(joint)`` false) joins its parent's body."""
    robot = loaded.robot
    top: dict[str, str] = {}
    members: dict[str, list[str]] = {}
    for order in walks(robot).values():
        for link in order:
            joint = loaded.parent_joint(link)
            if joint is not None and not keeps_joint(joint) and joint.parent in top:
                top[link] = top[joint.parent]
            else:
                top[link] = link
                members[link] = []
            members[top[link]].append(link)
    return members


def combined(loaded: Loaded, links: list[str], part) -> tuple[float | None, Vector | None]:
    """Total mass and principal moments of links joined rigidly, each link's
    (mass, com, tensor in link axes) from ``part(link)`` (None: unknown)."""
    parts = []
    poses = body_poses(loaded, links)
    for name in links:
        found = part(loaded.robot.links[name])
        if found is None:
            return None, None
        mass, com, tensor = found
        if mass == 0 and massprops.is_zero(tensor):
            continue
        pose = poses[name]
        parts.append((mass, massprops.place(pose, com), massprops.rotate(tensor, pose[0])))
    if not parts:
        return 0.0, (0.0, 0.0, 0.0)
    if len(parts) == 1:
        return parts[0][0], massprops.principal_moments(parts[0][2])
    mass = sum(p[0] for p in parts)
    if mass <= 0:
        return mass, None
    mass, _, tensor = massprops.combine(parts)
    return mass, massprops.principal_moments(tensor)


def declared_part(link: Link):
    """A link's declared (mass, com, tensor in link axes); a link without ``<inertial>`` has none."""
    mass, tensor = declared_mass(link), declared_matrix(link)
    if link.inertial is None:
        return 0.0, (0.0, 0.0, 0.0), massprops.ZERO
    if mass is None or tensor is None:
        return None
    return mass, link.inertial.origin.xyz, tensor


def valid_tensor(mass: float, tensor: Matrix, rel_tol: float = 1e-9) -> bool:
    """Positive semi-definite with principal moments meeting the triangle inequality."""
    return massprops.is_positive_semidefinite(tensor, rel_tol) and massprops.triangle_violation(tensor) is None


def joint_dof(joint: Joint) -> int:
    return DOF.get(joint.type or "", 0)


def build(loaded: Loaded, chosen: Profile) -> Build:
    """What ``chosen`` builds from the model, worked out once per model."""
    return once(loaded, _build, chosen)


def _build(loaded: Loaded, chosen: Profile) -> Build:
    return BUILDERS[chosen.target](loaded, chosen)


# -- MuJoCo 4.0 (src/xml/xml_urdf.cc; URDF defaults in src/xml/xml.cc) --------------------


class MujocoOptions(NamedTuple):
    fusestatic: bool = True
    discardvisual: bool = True
    balanceinertia: bool = False
    inertiafromgeom: str = "auto"


def mujoco_options(loaded: Loaded) -> MujocoOptions:
    """The ``<mujoco><compiler .../></mujoco>`` options the model sets over the URDF defaults."""
    found = MujocoOptions()
    for block in loaded.robot.blocks("mujoco"):
        for compiler in block.iter("compiler"):
            for name in ("fusestatic", "discardvisual", "balanceinertia"):
                value = compiler.get(name)
                if value in ("true", "false"):
                    found = found._replace(**{name: value == "true"})
            if compiler.get("inertiafromgeom") in ("true", "false", "auto"):
                found = found._replace(inertiafromgeom=compiler.get("inertiafromgeom"))
    return found


def mujoco_part(link: Link, options: MujocoOptions, fusing: bool = False):
    """A link's mass properties in MuJoCo: declared, or with no ``<inertial>`` (inertiafromgeom
    auto) those of its collision shapes at 1000 kg/m³ (unknown for a mesh). Fusing static
    bodies (``fusestatic``), MuJoCo counts a negative mass as none, its tensor kept (measured)."""
    if weighed_by_geometry(link, options):
        return geometry_body(link)
    found = declared_part(link)
    if fusing and found is not None and found[0] < 0:
        return 0.0, found[1], found[2]
    return found


def weighed_by_geometry(link: Link, options: MujocoOptions) -> bool:
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


def mujoco_build(loaded: Loaded, chosen: Profile) -> Build:
    options = mujoco_options(loaded)
    bodies, dropped = [], {}
    members = fused(loaded, lambda joint: moving(joint) or not options.fusestatic)
    root_fused = options.fusestatic
    for top, links in members.items():
        joint = loaded.parent_joint(top)
        if joint is None and root_fused:
            for link in links:
                dropped[link] = "fused into the world body"
            continue
        mass, moments = combined(loaded, links, lambda link: mujoco_part(link, options, fusing=len(links) > 1))
        weighed = [n for n in links if weighed_by_geometry(loaded.robot.links[n], options)]
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


# -- Drake 1.51 (multibody/parsing/detail_urdf_parser.cc, detail_common.cc) ---------------


def drake_part(link: Link):
    """Drake's mass properties: declared, or for an invalid inertia a solid sphere of
    water of the declared mass (1 kg when the mass is not positive)."""
    found = declared_part(link)
    if found is None or link.inertial is None:
        return found
    mass, com, tensor = found
    if drake_replaces(link):
        mass = mass if mass > 0 else 1.0
        radius = (3.0 * mass / (4.0 * math.pi * WATER)) ** (1.0 / 3.0)
        return mass, com, massprops.sphere(mass, radius)
    return found


def drake_replaces(link: Link) -> bool:
    """Whether Drake replaces a link's inertia (ParseSpatialInertia: the checks of
    SpatialInertia::IsPhysicallyValid fail)."""
    found = declared_part(link)
    if found is None or link.inertial is None:
        return False
    mass, _, tensor = found
    if mass < 0:
        return True
    if mass == 0:
        return not massprops.is_zero(tensor)
    return not valid_tensor(mass, tensor, 1e-14)


def drake_build(loaded: Loaded, chosen: Profile) -> Build:
    robot = loaded.robot
    bodies = []
    for name, link in robot.links.items():
        mass, moments = combined(loaded, [name], drake_part)
        joint = loaded.parent_joint(name)
        source = "a solid water sphere (its inertia is not physical)" if drake_replaces(link) else "declared"
        bodies.append(Body((name,), joint if moving(joint) else None, mass, moments, source))
    changed = {}
    dof = 0
    for joint in tree_joints(loaded):
        dof += joint_dof(joint)
        if joint.type == "continuous" and joint.limit is not None and joint.limit.has_lower and joint.limit.has_upper:
            changed[joint.name] = "revolute with limits (its <limit> lower and upper are kept)"
        elif joint.type == "floating":
            changed[joint.name] = "no joint: the child is a free body"
    floating_roots = [r for r in roots(robot) if r != "world"]  # a link named world is Drake's world body
    dof += 6 * len(floating_roots)
    return Build(chosen, tuple(bodies), {}, "floating" if floating_roots else "fixed", dof, changed)


# -- Pinocchio 4.1 (src/parsers/urdf/model.cpp, model.hxx) --------------------------------


def pinocchio_build(loaded: Loaded, chosen: Profile) -> Build:
    members = fused(loaded, moving)
    bodies = []
    for top, links in members.items():
        joint = loaded.parent_joint(top)
        mass, moments = combined(loaded, links, declared_part)
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


# -- PyBullet 3.2.7 (examples/Importers/ImportURDFDemo: UrdfParser.cpp, BulletUrdfImporter.cpp, URDF2Bullet.cpp)


def pybullet_box_moments(loaded: Loaded, link: Link, mass: float) -> Vector | None:
    """The tensor PyBullet computes without URDF_USE_INERTIA_FROM_FILE: a box filling the
    axis-aligned bounding box of the collision shapes in the inertial frame (exact for
    boxes; cylinders and spheres are hulls with a margin, so approximately; None for meshes)."""
    if not link.collisions:  # an empty compound shape: PyBullet's bounding box is a 2 mm cube (measured)
        side = massprops.box(mass, (0.002, 0.002, 0.002))[0][0]
        return (side, side, side)
    inertial = link.inertial
    frame = massprops.transform(inertial.origin.xyz, inertial.origin.rpy) if inertial is not None else massprops.ORIGIN
    back = (massprops.transpose(frame[0]), tuple(-v for v in massprops.apply(massprops.transpose(frame[0]), frame[1])))
    low, high = [math.inf] * 3, [-math.inf] * 3
    for shape in link.collisions:
        half = primitive_half_extents(shape.geometry)
        if half is None:
            return None
        pose = massprops.compose(back, massprops.transform(shape.origin.xyz, shape.origin.rpy))
        for corner in ((x, y, z) for x in (-half[0], half[0]) for y in (-half[1], half[1]) for z in (-half[2], half[2])):
            point = massprops.place(pose, corner)
            for i in range(3):
                low[i], high[i] = min(low[i], point[i]), max(high[i], point[i])
    size = tuple(h - lo for lo, h in zip(low, high))
    box = massprops.box(mass, size)
    return (box[0][0], box[1][1], box[2][2])


def primitive_half_extents(geometry: Geometry | None) -> Vector | None:
    if geometry is None or primitive_volume(geometry) is None:
        return None
    if geometry.kind == "box":
        return tuple(d / 2.0 for d in geometry.size)  # type: ignore[return-value]
    if geometry.kind == "cylinder":
        return (geometry.radius, geometry.radius, geometry.length / 2.0)
    return (geometry.radius,) * 3


def pybullet_link(loaded: Loaded, link: Link, from_file: bool) -> tuple[float | None, Vector | None, str]:
    """Mass, principal moments and their source, as PyBullet sets them for one link."""
    inertial = link.inertial
    if inertial is None:
        if link.name == "world":
            return 0.0, (0.0, 0.0, 0.0), "none (a link named world is the fixed base)"
        if from_file:
            return 1.0, (1.0, 1.0, 1.0), "the default 1 kg and unit tensor (no <inertial>)"
        return 1.0, pybullet_box_moments(loaded, link, 1.0), "the default 1 kg (no <inertial>), tensor from the collision shapes' bounding box"
    mass = inertial.mass
    if from_file:
        tensor = declared_matrix(link)
        if tensor is None or mass is None:
            return mass, None, "declared"
        if not valid_tensor(mass, tensor):
            return mass, (0.0, 0.0, 0.0), "zero (the declared tensor is not physical)"
        return mass, massprops.principal_moments(tensor), "declared"
    if mass is None:
        return None, None, "declared mass"
    return mass, pybullet_box_moments(loaded, link, mass), "declared mass, tensor from the collision shapes' bounding box"


def pybullet_build(loaded: Loaded, chosen: Profile) -> Build:
    from_file = "inertia-from-file" in chosen.variants
    bodies = []
    for name, link in loaded.robot.links.items():
        mass, moments, source = pybullet_link(loaded, link, from_file)
        joint = loaded.parent_joint(name)
        bodies.append(Body((name,), joint if moving(joint) else None, mass, moments, source))
    changed, dof = {}, 0
    for joint in tree_joints(loaded):
        limit = joint.limit
        if joint.type == "floating":
            changed[joint.name] = "fixed (PyBullet does not support floating joints)"
            continue
        if joint.type in ("revolute", "prismatic") and limit is not None and limit.lower > limit.upper:
            changed[joint.name] = "unlimited (lower > upper)"
        if joint.mimic is not None:
            changed[joint.name] = "a free degree of freedom (<mimic> ignored)"
        dof += joint_dof(joint)
    root = loaded.root
    base_mass = declared_mass(loaded.robot.links[root]) if root is not None and loaded.robot.links[root].inertial is not None else None
    fixed = "fixed-base" in chosen.variants or root == "world" or base_mass == 0
    return Build(chosen, tuple(bodies), {}, "fixed" if fixed else "floating", dof + (0 if fixed else 6), changed)


# -- Gazebo: sdformat 12 (src/parser_urdf.cc: CreateSDF, ReduceFixedJoints) ----------------


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


def has_mass(link: Link) -> bool:
    mass = declared_mass(link)
    return mass is not None and mass > 0


def gazebo_build(loaded: Loaded, chosen: Profile) -> Build:
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


# -- KDL / robot_state_publisher (kdl_parser/src/kdl_parser.cpp) ----------------------------


def kdl_build(loaded: Loaded, chosen: Profile) -> Build:
    root = loaded.root
    bodies, changed, dof = [], {}, 0
    for name, link in loaded.robot.links.items():
        joint = loaded.parent_joint(name)
        if name == root:
            continue  # the root is the tree's base, not a segment
        mass, moments = combined(loaded, [name], declared_part)
        bodies.append(Body((name,), joint if moving(joint) else None, mass, moments, "declared"))
    for joint in tree_joints(loaded):
        if joint.type in ("floating", "planar"):
            changed[joint.name] = "fixed (KDL has no floating or planar joint)"
            continue
        dof += joint_dof(joint)
    dropped = {root: "the root's inertia is dropped (it is the tree's base)"} if root is not None and has_mass(loaded.robot.links[root]) else {}
    return Build(chosen, tuple(bodies), dropped, "fixed", dof, changed)


# -- Isaac Sim 6 importer, stage 1: urdf-usd-converter 0.3.4 (_impl/link.py, _impl/link_hierarchy.py) --


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


def isaac_merged_child(loaded: Loaded, link: Link) -> str | None:
    """The inertial-only child whose inertia the converter writes onto ``link`` (a link with
    shapes but no inertial data): the first one on a fixed joint (``_fixed_dummy_inertia_children``)."""
    if not zero_equivalent(link) or not (link.visuals or link.collisions):
        return None
    for joint in loaded.robot.joints.values():
        child = loaded.robot.links.get(joint.child)
        if joint.parent == link.name and joint.type == "fixed" and child is not None:
            if not zero_equivalent(child) and not (child.visuals or child.collisions):
                return child.name
    return None


def isaac_build(loaded: Loaded, chosen: Profile) -> Build:
    bodies, changed, dof = [], {}, 0
    merged = {name: child for name, link in loaded.robot.links.items() if (child := isaac_merged_child(loaded, link))}
    for name, link in loaded.robot.links.items():
        if name in merged.values():
            continue
        joint = loaded.parent_joint(name)
        written = loaded.robot.links[merged[name]] if name in merged else link
        mass = declared_mass(written)
        if mass:
            source = f"declared by {written.name} (written unchecked)" if name in merged else "declared (written unchecked)"
            moments = combined(loaded, [written.name], declared_part)[1]
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


BUILDERS = {
    "mujoco": mujoco_build,
    "drake": drake_build,
    "pinocchio": pinocchio_build,
    "pybullet": pybullet_build,
    "gazebo": gazebo_build,
    "kdl": kdl_build,
    "isaac": isaac_build,
}
