"""What a consumer of URDF is to urdfcli, and what it builds from a model: its bodies
(links fused or lumped into one), the links it drops, a fixed or floating base, its
degrees of freedom, and the masses and tensors it will use.

Each consumer is a package of :mod:`urdfcli.targets` whose ``build`` module declares
its :class:`Consumer` and builds the model as the consumer's source does; this
module holds what they share. The target rules, ``tree --target`` and ``inertia
--target`` all read the same :class:`Build`. Nothing here imports a consumer: these
are predictions, checked against the real programs by the test suite.

A profile is a consumer and the options it is run with (``pybullet:inertia-from-file``,
``pinocchio:mimic``); where the model itself sets a consumer's options (MuJoCo's
``<mujoco><compiler>``, Gazebo's ``<preserveFixedJoint>``), they are read from it.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

from ..diagnostics import Diagnostic
from ..read.memo import once
from . import massprops
from .kinematics import children_by_joint_name, walks
from .load import Loaded
from .massprops import Matrix, Vector
from .poses import body_poses
from .robot import Geometry, Joint, Link

DOF = {"fixed": 0, "revolute": 1, "continuous": 1, "prismatic": 1, "planar": 3, "floating": 6}
WATER = 1000.0  # kg/m³: MuJoCo's default geom density, and Drake's replacement sphere


class Variant(NamedTuple):
    """An option a consumer is run with: ``mimic`` for ``pinocchio:mimic``."""

    name: str
    means: str  # how the consumer is called with it, for the help and the docs


class Consumer(NamedTuple):
    """One consumer of URDF: its name on the command line, its title in messages, the
    prefix of its rules' codes, the version its profile follows, its variants, how it
    builds a model (``build(loaded, profile)``), and the plain errors (a rule's error
    no tool reads as meant, such as J003) it loads the model with all the same."""

    name: str
    title: str
    prefix: str
    follows: str
    variants: tuple[Variant, ...]
    build: Callable[[Loaded, "Profile"], "Build"]
    loads_anyway: frozenset[str] = frozenset()  # the plain error rules (codes) whose models it loads all the same

    def variant_names(self) -> tuple[str, ...]:
        return tuple(variant.name for variant in self.variants)


class Profile(NamedTuple):
    """A consumer and the variants it runs with."""

    consumer: Consumer
    variants: frozenset[str] = frozenset()

    @property
    def target(self) -> str:
        return self.consumer.name

    @property
    def name(self) -> str:
        return self.consumer.title

    def text(self) -> str:
        return ":".join((self.target, *sorted(self.variants)))


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
    broken: dict[str, str] = {}  # a body's top link -> why the consumer refuses the body as it builds it



# -- shared pieces ----------------------------------------------------------------------


def declared_mass(link: Link) -> float | None:
    inertial = link.inertial
    return inertial.mass if inertial is not None else None


def declared_matrix(link: Link) -> Matrix | None:
    inertial = link.inertial
    if inertial is None or inertial.inertia is None:
        return None
    return _turned(massprops.matrix(inertial.inertia), inertial.origin.rpy)


def _turned(tensor: Matrix, rpy) -> Matrix:
    if not any(rpy):  # most inertials are not turned: no rotation to apply
        return tensor
    return massprops.rotate(tensor, massprops.rotation(rpy))


class DeclaredTensor(NamedTuple):
    """A link's declared ``<inertia>``, as every consumer judges it: as written (in the
    inertial frame's axes), in the link's axes, the principal moments of each (the same
    object where the inertial is not turned), and whether it is all zero."""

    written: Matrix
    tensor: Matrix
    moments: Vector  # of ``tensor``
    written_moments: Vector  # of ``written``
    zero: bool


def declared_tensors(loaded: Loaded) -> dict[str, DeclaredTensor]:
    """Each link's declared tensor and its principal moments, worked out once per model: the
    consumers' rules and builds all judge them (valid, positive, triangle inequality)."""
    return once(loaded, _declared_tensors)


def _declared_tensors(loaded: Loaded) -> dict[str, DeclaredTensor]:
    found = {}
    for name, link in loaded.robot.links.items():
        inertial = link.inertial
        if inertial is None or inertial.inertia is None:
            continue
        written = massprops.matrix(inertial.inertia)
        tensor = _turned(written, inertial.origin.rpy)
        moments = massprops.principal_moments(tensor)
        found[name] = DeclaredTensor(written, tensor, moments, moments if tensor is written else massprops.principal_moments(written), massprops.is_zero(written))
    return found


def declared_moments(loaded: Loaded, link: Link) -> Vector | None:
    """The principal moments of a link's declared tensor (see :func:`declared_tensors`)."""
    found = declared_tensors(loaded).get(link.name)
    return found.moments if found is not None else None


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


def tree_joints(loaded: Loaded) -> tuple[Joint, ...]:
    """The joints of the tree below each root, parents before children (once per model)."""
    return once(loaded, _tree_joints)


def _tree_joints(loaded: Loaded) -> tuple[Joint, ...]:
    children = children_by_joint_name(loaded.robot)
    found = []
    for order in walks(loaded.robot).values():
        for link in order:
            found.extend(joint for joint in children.get(link, ()) if joint.child != link)
    return tuple(found)


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
    if len(links) == 1:  # most bodies: one link, in its own axes (no pose to compose)
        found = part(loaded.robot.links[links[0]])
        if found is None:
            return None, None
        mass, _, tensor = found
        if mass == 0 and massprops.is_zero(tensor):
            return 0.0, (0.0, 0.0, 0.0)
        return mass, declared_moments(loaded, loaded.robot.links[links[0]]) if part is declared_part else massprops.principal_moments(tensor)
    found = {}
    for name in links:
        own = part(loaded.robot.links[name])
        if own is None:
            return None, None
        if not (own[0] == 0 and massprops.is_zero(own[2])):  # a massless frame adds nothing: not placed
            found[name] = own
    poses = body_poses(loaded, [links[0], *found]) if found else {}
    parts = []
    for name, (mass, com, tensor) in found.items():
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


def declared_body(loaded: Loaded, links: tuple[str, ...]) -> tuple[float | None, Vector | None]:
    """Total mass and principal moments of links joined rigidly, as each declares them: the
    body Gazebo lumps, Pinocchio and MuJoCo fuse, worked out once per model for every
    consumer that builds it (see :func:`combined`)."""
    if len(links) == 1:  # most bodies: the link's own mass and moments
        return combined(loaded, list(links), declared_part)
    return once(loaded, _declared_body, links)


def _declared_body(loaded: Loaded, links: tuple[str, ...]) -> tuple[float | None, Vector | None]:
    return combined(loaded, list(links), declared_part)


def declared_part(link: Link):
    """A link's declared (mass, com, tensor in link axes); a link without ``<inertial>`` has none."""
    mass, tensor = declared_mass(link), declared_matrix(link)
    if link.inertial is None:
        return 0.0, (0.0, 0.0, 0.0), massprops.ZERO
    if mass is None or tensor is None:
        return None
    return mass, link.inertial.origin.xyz, tensor


def valid_tensor(mass: float, tensor: Matrix, rel_tol: float = 1e-9, moments: Vector | None = None) -> bool:
    """Positive semi-definite with principal moments meeting the triangle inequality
    (``moments``: the tensor's, where they were worked out already)."""
    if moments is None:
        moments = massprops.principal_moments(tensor)
    return massprops.is_positive_semidefinite(tensor, rel_tol, moments) and massprops.triangle_violation(tensor, moments=moments) is None


def joint_dof(joint: Joint) -> int:
    return DOF.get(joint.type or "", 0)


class Verdict(NamedTuple):
    """What one consumer does with a model, as urdfcli predicts it: ``refuses`` it, or loads
    it with ``changes`` elements changed (warnings of its rules); ``reason`` is the first
    refusal, else the first change (None: it loads the model as written)."""

    profile: str  # "pinocchio:mimic"
    title: str
    refuses: bool
    changes: int
    reason: Diagnostic | None = None

    @property
    def outcome(self) -> str:
        if self.refuses:
            return "refuses"
        if self.changes:
            return f"loads with {self.changes} change{'s' if self.changes > 1 else ''}"
        return "loads"
