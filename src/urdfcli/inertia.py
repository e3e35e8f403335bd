"""Mass properties of each link and of the whole robot: declared, and implied by geometry.

The closed-form maths is :mod:`urdfcli.massprops`. Meshes are loaded by yourdfpy and
trimesh, with urdfcli's package resolver as the filename handler (never from a network);
the robot's pose at zero joint positions comes from yourdfpy's scene graph. Both are
imported only when this work needs them.

Frames: a declared tensor is given in the frame of its ``<inertial><origin>``;
the *expected* tensor is expressed in that same frame, so the two compare one to one.
"""

from __future__ import annotations

import contextlib
import functools
import logging
import math
import warnings
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from . import massprops
from .kinematics import walk
from .loaded import Loaded
from .massprops import Matrix, Transform, Vector
from .model import Joint, Link, Shape
from .packages import PackageResolver

TOLERANCE = massprops.TOLERANCE


class GeometryUnknown(Exception):
    """The geometry cannot give mass properties (unreadable mesh, bad size...)."""


@dataclass(frozen=True)
class Body:
    mass: float
    com: Vector  # centre of mass
    tensor: Matrix  # about the centre of mass


@dataclass(frozen=True)
class Implied:
    """What a link's geometry implies; ``body`` is None when it cannot tell, and ``source`` says why."""

    body: Body | None
    source: str
    volume: float | None = None
    shapes: tuple[Shape, ...] = ()


@dataclass(frozen=True)
class Assessment:
    """A link's declared tensor next to the one its geometry implies, both in the inertial frame."""

    link: Link
    declared: Matrix
    implied: Implied
    expected: Matrix | None
    difference: float | None

    def off(self, tolerance: float) -> bool:
        return self.difference is not None and self.difference > tolerance


# -- declared --------------------------------------------------------------------------
def inertial_rotation(link: Link) -> Matrix:
    return massprops.rotation(link.inertial.origin.rpy) if link.inertial is not None else massprops.IDENTITY


def declared_tensor(link: Link) -> Matrix | None:
    """The tensor as written, in the inertial frame."""
    inertial = link.inertial
    if inertial is None or inertial.inertia is None:
        return None
    return massprops.matrix(inertial.inertia)


def declared_body(link: Link) -> Body | None:
    """Mass, centre and tensor as declared, in the link frame."""
    tensor = declared_tensor(link)
    if tensor is None or link.inertial.mass is None:
        return None
    return Body(link.inertial.mass, link.inertial.origin.xyz, massprops.rotate(tensor, inertial_rotation(link)))


def is_frame(link: Link) -> bool:
    """A massless frame link: no inertial, or mass 0 with a zero (or no) tensor."""
    inertial = link.inertial
    if inertial is None:
        return True
    tensor = declared_tensor(link)
    return inertial.mass == 0 and (tensor is None or massprops.is_zero(tensor))


# -- implied by geometry ---------------------------------------------------------------
def resolver_of(loaded: Loaded) -> PackageResolver:
    return loaded.resolver or PackageResolver((), loaded.document.file)


def implied(loaded: Loaded, link: Link, density: float | None = None) -> Implied:
    """The body the link's collision shapes (else its visual shapes) make, with the
    declared mass spread by volume, or ``density`` times the volume when given."""
    collisions = tuple(s for s in link.collisions if s.geometry is not None)
    kind, shapes = ("collision", collisions) if collisions else ("visual", tuple(s for s in link.visuals if s.geometry is not None))
    if not shapes:
        return Implied(None, "no collision or visual geometry")
    names = ", ".join(s.geometry.kind for s in shapes)
    source = f"{kind} {names}" if len(shapes) == 1 else f"{kind} shapes ({names})"
    try:
        parts = [shape_part(loaded, shape) for shape in shapes]
    except GeometryUnknown as error:
        return Implied(None, str(error), shapes=shapes)
    volume = sum(v for v, _, _ in parts)
    if volume <= 0:
        return Implied(None, f"{source} has no volume", shapes=shapes)
    mass = density * volume if density is not None else (link.inertial.mass if link.inertial else None)
    if mass is None or mass <= 0:
        return Implied(None, "no mass to spread over the geometry", volume, shapes)
    total, com, tensor = massprops.combine(
        (mass * v / volume, centre, massprops.scaled(unit, mass * v / volume)) for v, centre, unit in parts
    )
    return Implied(Body(total, com, tensor), source, volume, shapes)


def shape_part(loaded: Loaded, shape: Shape) -> tuple[float, Vector, Matrix]:
    """Volume, centre (link frame) and tensor per unit mass (link axes) of one shape."""
    geometry = shape.geometry
    if geometry.kind == "mesh":
        volume, centre, unit, _ = mesh_properties(geometry.filename, tuple(geometry.scale), MeshFiles.of(loaded))
    else:
        volume, unit = primitive(geometry)
        centre = (0.0, 0.0, 0.0)
    pose = massprops.transform(shape.origin.xyz, shape.origin.rpy)
    return volume, massprops.place(pose, centre), massprops.rotate(unit, pose[0])


def primitive(geometry) -> tuple[float, Matrix]:
    """Volume and tensor per unit mass of a box, cylinder or sphere (SPEC section 6)."""
    if geometry.kind == "box":
        dims = geometry.size
        if min(dims) <= 0:
            raise GeometryUnknown("box size is not positive")
        return massprops.box_volume(dims), massprops.box(1.0, dims)
    if geometry.kind == "cylinder":
        if geometry.radius <= 0 or geometry.length <= 0:
            raise GeometryUnknown("cylinder radius or length is not positive")
        return massprops.cylinder_volume(geometry.radius, geometry.length), massprops.cylinder(1.0, geometry.radius, geometry.length)
    if geometry.radius <= 0:
        raise GeometryUnknown("sphere radius is not positive")
    return massprops.sphere_volume(geometry.radius), massprops.sphere(1.0, geometry.radius)


def shape_bounds(loaded: Loaded, shape: Shape) -> tuple[Vector, Vector]:
    """Lowest and highest corner, in the link frame, of a box holding the shape
    (its own bounding box, turned as the shape is)."""
    geometry = shape.geometry
    if geometry.kind == "mesh":
        low, high = mesh_properties(geometry.filename, tuple(geometry.scale), MeshFiles.of(loaded))[3]
    else:
        primitive(geometry)  # raises on a shape without size
        if geometry.kind == "box":
            half = tuple(d / 2.0 for d in geometry.size)
        elif geometry.kind == "cylinder":
            half = (geometry.radius, geometry.radius, geometry.length / 2.0)
        else:
            half = (geometry.radius,) * 3
        low, high = tuple(-h for h in half), half
    pose = massprops.transform(shape.origin.xyz, shape.origin.rpy)
    corners = [massprops.place(pose, (x, y, z)) for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])]
    return tuple(min(c[i] for c in corners) for i in range(3)), tuple(max(c[i] for c in corners) for i in range(3))  # type: ignore[return-value]


def extent(loaded: Loaded, link: Link, shapes=None) -> tuple[Vector, Vector] | None:
    """The box (lowest and highest corner, link frame) that holds the shapes, by default every
    visual and collision shape of the link; None when there are none, or one cannot be measured."""
    if shapes is None:
        shapes = (*link.visuals, *link.collisions)
    shapes = [s for s in shapes if s.geometry is not None]
    if not shapes:
        return None
    try:
        boxes = [shape_bounds(loaded, shape) for shape in shapes]
    except GeometryUnknown:
        return None
    return (
        tuple(min(b[0][i] for b in boxes) for i in range(3)),  # type: ignore[return-value]
        tuple(max(b[1][i] for b in boxes) for i in range(3)),
    )


@dataclass(frozen=True)
class MeshFiles:
    """yourdfpy's filename handler: a mesh's URI to a file, through urdfcli's package resolver.

    Raises GeometryUnknown, which passes through yourdfpy, when there is no such file.
    Equal for one input's shapes, so each of its meshes is read once."""

    resolver: PackageResolver
    base: Path | None

    @classmethod
    def of(cls, loaded: Loaded) -> MeshFiles:
        return loaded.remembered(
            "mesh files", lambda: cls(resolver_of(loaded), loaded.document.file.resolve().parent if loaded.document.file else None)
        )

    def __call__(self, fname: str) -> str:
        path = self.resolver.resolve_uri(fname, self.base)
        if path is None:
            raise GeometryUnknown(f"mesh {fname} cannot be resolved")
        if not path.is_file():
            raise GeometryUnknown(f"mesh {fname} not found ({path})")
        return str(path)


def mesh_properties(filename: str, scale: Vector, files: MeshFiles) -> tuple[float, Vector, Matrix, tuple[Vector, Vector]]:
    """Volume, centre, tensor per unit mass and bounds (lowest and highest corner) of a mesh, ``scale`` applied.

    yourdfpy loads it (through ``files``, with trimesh) as the collision geometry of a
    one-link robot. A mesh that is not closed has no inside: its convex hull stands in."""
    files(filename)  # a mesh that does not resolve is told before numpy, trimesh and yourdfpy load (1-2 s)
    return _mesh_properties(filename, scale, files)


@functools.lru_cache(maxsize=256)
def _mesh_properties(filename: str, scale: Vector, files: MeshFiles) -> tuple[float, Vector, Matrix, tuple[Vector, Vector]]:
    import numpy
    import trimesh
    import yourdfpy

    name = Path(filename).name
    geometry = yourdfpy.Geometry(mesh=yourdfpy.Mesh(filename=filename, scale=numpy.array(scale)))
    robot = yourdfpy.Robot(name="mesh", links=[yourdfpy.Link(name="mesh", collisions=[yourdfpy.Collision(name="mesh", geometry=geometry)])])
    try:
        with quiet_libraries():
            scene = yourdfpy.URDF(
                robot, build_scene_graph=False, build_collision_scene_graph=True, load_collision_meshes=True, filename_handler=files
            ).collision_scene
    except GeometryUnknown:
        raise
    except Exception as error:  # noqa: BLE001  (trimesh raises many kinds)
        raise GeometryUnknown(f"mesh {name} cannot be read: {error}") from None
    meshes = [m for m in scene.geometry.values() if isinstance(m, trimesh.Trimesh) and not m.is_empty]
    if not meshes:
        raise GeometryUnknown(f"mesh {name} has no triangles")
    mesh = meshes[0]
    if not mesh.is_watertight:
        mesh = mesh.convex_hull
    if mesh.volume < 0:
        mesh.invert()
    properties = mesh.mass_properties  # density 1: mass equals volume
    volume = float(properties["volume"])
    if volume <= 0:
        raise GeometryUnknown(f"mesh {name} has no volume")
    unit = tuple(tuple(float(v) / volume for v in row) for row in properties["inertia"])
    bounds = tuple(tuple(float(v) for v in corner) for corner in mesh.bounds)
    return volume, tuple(float(c) for c in properties["center_mass"]), unit, bounds  # type: ignore[return-value]


@contextlib.contextmanager
def quiet_libraries():
    """yourdfpy and trimesh log warnings to stderr (and yourdfpy calls a deprecated trimesh
    function); urdfcli reports the problems itself."""
    loggers = [logging.getLogger(name) for name in ("yourdfpy", "trimesh")]
    levels = [logger.level for logger in loggers]
    for logger in loggers:
        logger.setLevel(logging.CRITICAL)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            yield
    finally:
        for logger, level in zip(loggers, levels):
            logger.setLevel(level)


# -- comparison ------------------------------------------------------------------------
def assess(loaded: Loaded, link: Link, density: float | None = None) -> Assessment | None:
    """Declared against implied, for a link that declares a tensor (None otherwise).

    Worked out once per link and density: three rules and the audit ask for it."""
    return loaded.remembered(("assess", link.name, density), lambda: _assess(loaded, link, density))


def _assess(loaded: Loaded, link: Link, density: float | None) -> Assessment | None:
    declared = declared_tensor(link)
    if declared is None or is_frame(link):
        return None
    found = implied(loaded, link, density)
    if found.body is None:
        return Assessment(link, declared, found, None, None)
    back = massprops.transpose(inertial_rotation(link))
    expected = massprops.tidy(massprops.rotate(found.body.tensor, back))
    return Assessment(link, declared, found, expected, massprops.relative_difference(declared, expected))


def shapes_rotation(shapes: tuple[Shape, ...]) -> Matrix | None:
    """The rotation every shape shares, or None when they differ."""
    rotations = [massprops.rotation(s.origin.rpy) for s in shapes]
    first = rotations[0] if rotations else None
    if first is None or any(massprops.relative_difference(r, first) > 1e-9 for r in rotations[1:]):
        return None
    return first


def rotated_fit(assessment: Assessment) -> tuple[Vector, float] | None:
    """When the geometry is rotated and the inertial frame is not rotated with it:
    the shapes' rpy, and the difference left if the tensor were read in their frame."""
    shapes = assessment.implied.shapes
    shared = shapes_rotation(shapes)
    inertial = inertial_rotation(assessment.link)
    if shared is None or massprops.relative_difference(shared, inertial) < 1e-6:
        return None
    # the declared tensor read in the shapes' frame, then expressed in the inertial frame
    in_link = massprops.rotate(assessment.declared, shared)
    moved = massprops.rotate(in_link, massprops.transpose(inertial))
    return shapes[0].origin.rpy, massprops.relative_difference(moved, assessment.expected)


# -- what the geometry proves ---------------------------------------------------------
OVERREACH = 1.1
"""A moment is impossible when it exceeds the most its mass can reach by this factor
(the margin absorbs meshes a little smaller than the part they draw)."""

PLACEHOLDER_FACTOR = 100.0
"""A tensor this many times below a uniform body of the same mass and geometry is a placeholder."""

DENSEST = 22600.0
"""kg/m³ (osmium): a mass denser than this in its geometry's bounding box is not drawn by that
geometry (a millimetre sphere standing in for a finger), which then proves nothing."""

AXES = ("ixx", "iyy", "izz")
TURNED = 30.0  # degrees between principal axes that say the axes are swapped or rotated
DISTINCT = 0.15  # a principal moment this far (relative to the largest) from the others has a well-defined axis


def axes_apart(a: Matrix, b: Matrix) -> float:
    """The largest angle (degrees) between matching principal axes of two tensors, over the
    axes whose moment stands apart from the other two in both (others are not defined)."""
    import numpy

    worst = 0.0
    eig_a, eig_b = numpy.linalg.eigh(numpy.array(a)), numpy.linalg.eigh(numpy.array(b))
    for i in range(3):
        if all(_distinct(moments, i) for moments in (eig_a[0], eig_b[0])):
            cosine = abs(float(numpy.dot(eig_a[1][:, i], eig_b[1][:, i])))
            worst = max(worst, math.degrees(math.acos(min(1.0, cosine))))
    return worst


def _distinct(moments, i: int) -> bool:
    largest = max(abs(m) for m in moments)
    return largest > 0 and all(abs(moments[i] - moments[j]) >= DISTINCT * largest for j in range(3) if j != i)


@dataclass(frozen=True)
class Reach:
    """The most each moment (link-frame axes, about the declared centre of mass) can be
    for the declared mass held inside the geometry's bounding box."""

    bounds: Vector
    sides: Vector


def reach(loaded: Loaded, link: Link) -> Reach | None:
    """None when the link has no measurable geometry, or geometry too small to hold its mass.

    Along each axis, a mass held in [lo, hi] with its mean at c has a variance of at most
    (hi - c)(c - lo) (the Bhatia-Davis inequality); a moment is the mass times the sum of
    two such variances. A centre outside the box gives (farthest extent)² instead."""
    inertial = link.inertial
    if inertial is None or not (inertial.mass or 0) > 0:
        return None
    declared = declared_body(link)
    # the shapes already measured first: a box that holds the tensor proves nothing, and a
    # larger one around the same centre would not either, so the other meshes are read only
    # when it does not (or when the centre lies outside it, where the bound is not monotone)
    box = extent(loaded, link, implied(loaded, link).shapes)
    first = _reach(inertial, box)
    inside = box is not None and all(lo <= c <= h for lo, h, c in zip(*box, inertial.origin.xyz))
    if first is not None and inside and declared is not None and all(declared.tensor[i][i] <= OVERREACH * first.bounds[i] for i in range(3)):
        return first
    return _reach(inertial, extent(loaded, link))


def _reach(inertial, box) -> Reach | None:
    if box is None:
        return None
    low, high = box
    sides = tuple(h - lo for lo, h in zip(low, high))
    volume = sides[0] * sides[1] * sides[2]
    if volume <= 0 or inertial.mass / volume > DENSEST:
        return None
    spread = []
    for lo, h, c in zip(low, high, inertial.origin.xyz):
        spread.append((h - c) * (c - lo) if lo <= c <= h else max(h - c, c - lo) ** 2)
    x, y, z = spread
    m = inertial.mass
    return Reach((m * (y + z), m * (x + z), m * (x + y)), sides)  # type: ignore[arg-type]


@dataclass(frozen=True)
class Verdict:
    """What the geometry proves wrong about a declared tensor: ``kind`` is ``impossible``,
    ``rotated`` or ``placeholder``; ``factor`` says by how much."""

    kind: str
    factor: float
    message: str
    hint: str


def verdict(loaded: Loaded, link: Link, tolerance: float = TOLERANCE, density: float | None = None) -> Verdict | None:
    """The one thing the geometry proves wrong about the link's tensor, if any.

    In order: a moment larger than any distribution of the mass in the geometry's bounding
    box allows; principal moments that match the geometry's on axes that do not; with a
    density, any difference beyond the tolerance from that uniform body; a tensor orders of
    magnitude below a uniform body's. Anything else (a CAD tensor within a few times of the
    uniform body's) is left alone."""
    declared = declared_body(link)
    if declared is None or massprops.is_negligible(declared.tensor):
        return None
    light = declared.mass < massprops.LIGHT  # only a rotation, which a formula got wrong, is worth saying
    limits = reach(loaded, link) if not light else None
    if limits is not None:
        worst = max(range(3), key=lambda i: declared.tensor[i][i] / limits.bounds[i] if limits.bounds[i] > 0 else math.inf)
        moment, most = declared.tensor[worst][worst], limits.bounds[worst]
        if moment > OVERREACH * most:
            factor = moment / most if most > 0 else math.inf
            sides = " x ".join(f"{side:.3g}" for side in limits.sides)
            times = f"{factor:.1f} times" if factor < math.inf else "infinitely more than"
            return Verdict(
                "impossible", factor,
                f"{AXES[worst]}={moment:.3g} (link axes) is {times} the most {number(declared.mass)} kg can reach "
                f"about the declared centre of mass inside the {sides} m box its shapes fill: {most:.3g}",
                "the tensor, the centre of mass or the mass is wrong (units?); "
                "`urdfcli inertia --suggest` prints a uniform body's values as a start",
            )
    found = assess(loaded, link, density)
    if found is None or found.expected is None or massprops.is_zero(found.expected):
        return None
    source = found.implied.source
    turned = axes_apart(found.declared, found.expected) if massprops.moments_difference(found.declared, found.expected) <= tolerance else 0.0
    if found.difference > 2 * tolerance and turned > TURNED:
        return Verdict(
            "rotated", turned,
            f"its principal moments match its {source}, but on axes {turned:.0f}° away: declared {tensor_text(found.declared, found.expected)}, "
            f"the {source} gives {tensor_text(found.expected, found.declared)}",
            "the axes are swapped or rotated: `urdfcli inertia --suggest` prints the tensor on the geometry's axes",
        )
    if density is not None and found.off(tolerance):  # the link is said to be that uniform material
        return Verdict(
            "density", found.difference,
            f"it is {found.difference:.0%} off what its {source} implies at density {number(density)}: "
            f"declared {tensor_text(found.declared, found.expected)}, expected {tensor_text(found.expected, found.declared)}",
            "`urdfcli inertia --suggest --density ...` prints the uniform body's <inertial>",
        )
    largest, expected_largest = massprops.principal_moments(found.declared)[2], massprops.principal_moments(found.expected)[2]
    if not light and largest * PLACEHOLDER_FACTOR < expected_largest:
        factor = expected_largest / largest
        return Verdict(
            "placeholder", factor,
            f"its largest moment {largest:.3g} is {factor:.0f} times below the {expected_largest:.3g} of a uniform body of "
            f"{number(declared.mass)} kg filling its {source}: a placeholder",
            "`urdfcli inertia --suggest` prints the uniform body's tensor, a better start than the placeholder",
        )
    return None


# -- the whole robot -------------------------------------------------------------------
def link_poses(loaded: Loaded) -> dict[str, Transform]:
    """Each link's pose in the root frame at zero joint positions (a mimic joint at its offset).

    yourdfpy's scene graph gives each joint's transform; urdfcli chains them down the tree,
    because a root-to-link query multiplies the whole path each time (trimesh orders that
    product at a cost that grows with the path's length cubed: 20 s on a 200-link chain).
    Only the tree's joints are given to yourdfpy; the structure rules report the others."""
    root = loaded.root
    if root is None:
        return {}
    joints = [joint for _, joint, _ in walk(loaded.robot, root) if joint is not None]
    poses = {root: massprops.ORIGIN}
    if not joints:
        return poses
    scene = kinematic_scene(loaded.robot.name or "robot", root, joints)
    for joint in joints:
        matrix = scene.get_transform(joint.child, joint.parent)
        step = (tuple(tuple(float(v) for v in row[:3]) for row in matrix[:3]), tuple(float(v) for v in matrix[:3, 3]))
        poses[joint.child] = massprops.compose(poses[joint.parent], step)
    return poses


def kinematic_scene(name: str, root: str, joints: list[Joint]):
    """A yourdfpy model of the kinematic tree alone (no geometry), at zero joint positions.

    At zero positions only a mimic joint's offset moves a joint, so the others are given
    as fixed: yourdfpy looks each moving joint up in a list, which would make setting up
    a large robot quadratic in its joints."""
    import numpy
    import trimesh.transformations as tra
    import yourdfpy

    def joint_of(joint: Joint) -> yourdfpy.Joint:
        matrix = tra.euler_matrix(*joint.origin.rpy, axes="sxyz")
        matrix[:3, 3] = joint.origin.xyz
        # a zero axis (reported by J007) gives no direction to move along
        moves = joint.mimic is not None and joint.type in ("revolute", "continuous", "prismatic") and any(joint.axis)
        return yourdfpy.Joint(
            name=joint.name, type=joint.type if moves else "fixed", parent=joint.parent, child=joint.child, origin=matrix,
            axis=numpy.array(joint.axis) if moves else None,
            mimic=yourdfpy.Mimic(joint.mimic.joint, joint.mimic.multiplier, joint.mimic.offset) if moves else None,
        )

    links = [yourdfpy.Link(name=root)] + [yourdfpy.Link(name=joint.child) for joint in joints]
    with quiet_libraries():
        return yourdfpy.URDF(yourdfpy.Robot(name=name, links=links, joints=[joint_of(j) for j in joints]), load_meshes=False)


def used_body(loaded: Loaded, link: Link, density: float | None = None) -> Body | None:
    """The body the total counts for a link: with ``density`` the one its geometry fills
    (a link without geometry keeps its declared one), else the declared one."""
    return (density is not None and implied(loaded, link, density).body) or declared_body(link)


def total(loaded: Loaded, density: float | None = None) -> Body | None:
    """Mass, centre of mass (root frame) and tensor about it of the whole robot: the declared
    links, or with ``density`` each link its geometry fills (links without any keep theirs)."""
    poses = link_poses(loaded)
    if not poses:
        return None
    parts = []
    for name, pose in poses.items():
        body = used_body(loaded, loaded.robot.links[name], density)
        if body is not None and body.mass > 0:
            parts.append((body.mass, massprops.place(pose, body.com), massprops.rotate(body.tensor, pose[0])))
    mass, com, tensor = massprops.combine(parts)
    return Body(mass, com, massprops.tidy(tensor))


# -- the audit -------------------------------------------------------------------------
@dataclass(frozen=True)
class LinkReport:
    link: Link
    frame: bool  # a massless frame link: listed quietly
    assessment: Assessment | None
    problems: tuple  # Diagnostics located in this link
    mass: float | None = None  # the mass the total counts: from --density, or as declared
    from_density: bool = False


@dataclass(frozen=True)
class Report:
    loaded: Loaded
    links: tuple[LinkReport, ...]
    total: Body | None
    problems: tuple  # every mass-property Diagnostic, in file order
    tolerance: float = TOLERANCE


def problems(loaded: Loaded, tolerance: float = TOLERANCE, density: float | None = None) -> list:
    """Every mass-property rule (codes I...), with this run's options where a rule takes them."""
    from .rules import load_all

    given = {"tolerance": tolerance, "density": density or 0.0}
    found = []
    for code, spec in sorted(load_all().items()):
        if code.startswith("I") and spec.function is not None:
            found.extend(spec.run(loaded, {k: v for k, v in given.items() if k in spec.defaults}))
    return sorted(found, key=lambda d: d.sort_key())


def audit(loaded: Loaded, tolerance: float = TOLERANCE, density: float | None = None) -> Report:
    """The per-link table, the problems and the whole-robot total of one loaded model."""
    found = problems(loaded, tolerance, density)
    paths = {link.name: loaded.document.element_path(link.at) for link in loaded.robot.links.values()}
    by_link: dict[str, list] = {path: [] for path in paths.values()}
    for diagnostic in found:
        path = diagnostic.element or ""
        cuts = [i for i, c in enumerate(path) if c == "/"] + [len(path)]
        prefix = next((path[:cut] for cut in cuts if path[:cut] in by_link), None)
        if prefix is not None:
            by_link[prefix].append(diagnostic)
    for diagnostic in found:
        if diagnostic.code in GROUPED:  # a group's diagnostic points at its first link and names every one
            for link in loaded.robot.links.values():
                mine = by_link[paths[link.name]]
                if f"'{link.name}'" in diagnostic.message and diagnostic not in mine:
                    mine.append(diagnostic)
    links = []
    for link in loaded.robot.links.values():
        mine = tuple(by_link[paths[link.name]])
        used = used_body(loaded, link, density)
        from_density = density is not None and implied(loaded, link, density).body is not None
        links.append(LinkReport(link, is_frame(link), assess(loaded, link, density), mine, used.mass if used else None, from_density))
    return Report(loaded, tuple(links), total(loaded, density), tuple(found), tolerance)


# -- presenting ------------------------------------------------------------------------
def number(value: float) -> str:
    """Six significant digits, never '-0'."""
    text = f"{value:.6g}"
    return "0" if text in ("-0", "0") else text


def tensor_text(tensor: Matrix, other: Matrix | None = None) -> str:
    """``ixx=.. iyy=.. izz=..``, with the products of inertia where either tensor has one."""
    values = massprops.as_dict(tensor)
    extra = massprops.as_dict(other) if other is not None else values
    shown = [k for k in massprops.KEYS if k in ("ixx", "iyy", "izz") or values[k] or extra[k]]
    return " ".join(f"{k}={values[k]:.3g}" for k in shown)


def _vector(values) -> list[float]:
    return [float(v) for v in values]


def _tensor(tensor: Matrix | None) -> dict[str, float] | None:
    return None if tensor is None else {k: float(v) for k, v in massprops.as_dict(tensor).items()}


def link_json(entry: LinkReport) -> dict:
    link, found = entry.link, entry.assessment
    inertial = link.inertial
    declared = declared_tensor(link)
    return {
        "name": link.name,
        "mass": inertial.mass if inertial is not None else None,
        "mass_used": entry.mass,
        "com": _vector(inertial.origin.xyz) if inertial is not None else None,
        "inertia": _tensor(declared),
        "principal": _vector(massprops.principal_moments(declared)) if declared is not None else None,
        "expected": _tensor(found.expected) if found is not None else None,
        "expected_from": expected_from(entry),
        "problems": [{"code": d.code, "severity": d.severity.value, "message": d.message} for d in entry.problems],
    }


def expected_from(entry: LinkReport) -> str:
    if entry.frame:
        return "massless frame link"
    if entry.assessment is None:
        return "no inertia tensor declared"
    return entry.assessment.implied.source


def report_json(report: Report) -> dict:
    body = report.total
    return {
        "robot": report.loaded.robot.name if report.loaded.robot is not None else None,
        "links": [link_json(entry) for entry in report.links],
        "total": None if body is None else {"mass": body.mass, "com": _vector(body.com), "inertia": _tensor(body.tensor)},
    }


GROUPED = {"I008"}  # one diagnostic for the links sharing one tensor
FIXABLE = {"I001", "I002", "I003", "I004", "I005", "I006", "I007", "I008", "I009", "I010"}


def flagged(report: Report) -> list[LinkReport]:
    """Links with a mass-property problem, for which a uniform body's <inertial> is suggested."""
    return [entry for entry in report.links if any(d.code in FIXABLE for d in entry.problems)]


def suggestion(loaded: Loaded, entry: LinkReport, density: float | None = None) -> str:
    """A ready-to-paste ``<inertial>`` for a link, in the frame of its current one: the
    uniform body its geometry makes, said to be an estimate, never a correction; an XML
    comment saying why when the geometry cannot tell."""
    link = entry.link
    found = implied(loaded, link, density)
    if found.body is None:
        why = found.source if link.inertial is not None or density else "it declares no mass (give --density)"
        return f"<!-- link '{link.name}': no suggestion: {why} -->"
    rpy = link.inertial.origin.rpy if link.inertial is not None else (0.0, 0.0, 0.0)
    tensor = massprops.tidy(massprops.rotate(found.body.tensor, massprops.transpose(massprops.rotation(rpy))))
    values = massprops.as_dict(tensor)
    return "\n".join(
        [
            f"<!-- link '{link.name}': a uniform body filling its {found.source} (an estimate: the part's CAD values are better) -->",
            "<inertial>",
            f'  <origin xyz="{" ".join(map(number, found.body.com))}" rpy="{" ".join(map(number, rpy))}"/>',
            f'  <mass value="{number(found.body.mass)}"/>',
            "  <inertia " + " ".join(f'{k}="{number(values[k])}"' for k in massprops.KEYS) + "/>",
            "</inertial>",
        ]
    )


# -- xacro macros ----------------------------------------------------------------------
@dataclass(frozen=True)
class MacroUse:
    """The xacro macro whose body wrote a link's <inertial>, and the call that used it."""

    name: str
    params: str
    defined_at: str  # FILE:LINE
    call: str | None  # the call as written, e.g. <xacro:box_inertia m="${mass}" .../>
    called_at: str | None


@functools.lru_cache(maxsize=64)
def _source_tree(file: str):
    from .xmlsafe import XmlError, parse_bytes

    try:
        return parse_bytes(Path(file).read_bytes())
    except (OSError, XmlError):
        return None


@functools.lru_cache(maxsize=64)
def _start_lines(file: str) -> dict:
    """The line of each source element's ``<`` (where diagnostics point)."""
    from .positions import source

    root, text = _source_tree(file), source(file)
    if root is None:
        return {}
    elements = list(root.iter(etree.Element))
    starts = text.element_starts(len(elements)) if text is not None else None
    if starts is None:
        return {e: e.sourceline for e in elements}
    return {e: text.position(start)[0] for e, start in zip(elements, starts)}


def _written(file: str, line: int, tag: str):
    """The element of that tag written at file:line, in the xacro source."""
    return next((e for e, at in _start_lines(file).items() if at == line and etree.QName(e).localname == tag), None)


def _is_xacro(element, name: str) -> bool:
    from .load import XACRO_NAMESPACES

    qname = etree.QName(element)
    return qname.namespace in XACRO_NAMESPACES and qname.localname == name


def macro_use(loaded: Loaded, link: Link) -> MacroUse | None:
    """Which xacro macro produced the link's <inertial> (None when it was written in place)."""
    if link.inertial is None or loaded.document.origins is None:
        return None
    where = loaded.document.locate(link.inertial.at)
    written = _written(where.file, where.line, "inertial") if where.line and not where.expanded else None
    macro = next((a for a in written.iterancestors() if _is_xacro(a, "macro")), None) if written is not None else None
    if macro is None:
        return None
    name = macro.get("name", "")
    call, called_at = None, None
    link_where = loaded.document.locate(link.at)
    source_link = _written(link_where.file, link_where.line, "link") if link_where.line and not link_where.expanded else None
    if source_link is not None:
        found = next((e for e in source_link.iter(etree.Element) if _is_xacro(e, name)), None)
        if found is not None:
            attributes = " ".join(f'{k}="{v}"' for k, v in found.attrib.items())
            call, called_at = f"<xacro:{name} {attributes}/>", f"{link_where.file}:{_start_lines(link_where.file)[found]}"
    return MacroUse(name, macro.get("params", ""), f"{where.file}:{_start_lines(where.file)[macro]}", call, called_at)


def _macro_element(use: MacroUse):
    file, _, line = use.defined_at.rpartition(":")
    return _written(file, int(line), "macro")


def _dimensions(geometry) -> tuple[float, ...]:
    if geometry.kind == "box":
        return tuple(geometry.size)
    if geometry.kind == "cylinder":
        return geometry.radius, geometry.length
    return (geometry.radius,)


def matching_call(loaded: Loaded, link: Link, use: MacroUse) -> str | None:
    """A call of the macro that writes the tensor the link's geometry implies, found by
    expanding the macro with the mass and each ordering of the shape's dimensions;
    None when no call does (e.g. the macro cannot rotate its tensor with the shape)."""
    import itertools

    from . import expansion
    from .xmlsafe import parse_bytes

    found = implied(loaded, link)
    macro = _macro_element(use)
    if found.body is None or len(found.shapes) != 1 or found.shapes[0].geometry.kind == "mesh" or macro is None:
        return None
    required = [p.lstrip("^") for p in use.params.split() if not p.startswith("*") and ":=" not in p and "=" not in p]
    masses = [p for p in required if p.lower() in ("m", "mass") or "mass" in p.lower()]
    others = [p for p in required if p not in masses]
    dimensions = _dimensions(found.shapes[0].geometry)
    if len(masses) != 1 or len(others) != len(dimensions):
        return None
    calls = []
    for order in dict.fromkeys(itertools.permutations(dimensions)):
        values = {masses[0]: found.body.mass, **dict(zip(others, order))}
        calls.append(f"<xacro:{use.name} " + " ".join(f'{k}="{number(v)}"' for k, v in values.items()) + "/>")
    namespace = etree.QName(macro).namespace
    probe = f'<robot name="probe" xmlns:xacro="{namespace}">{etree.tostring(macro, encoding="unicode", with_tail=False)}'
    probe += "".join(f'<link name="c{i}">{call}</link>' for i, call in enumerate(calls)) + "</robot>"
    try:
        text = expansion.expand(parse_bytes(probe.encode()), None, {}, resolver_of(loaded)).text
        links = parse_bytes(text.encode()).findall("link")
    except Exception:  # noqa: BLE001  (a macro that needs more than its parameters)
        return None
    for call, probe_link in zip(calls, links):
        tensor = _probe_tensor(probe_link)
        if tensor is not None and massprops.relative_difference(tensor, found.body.tensor) <= 1e-3:
            return call
    return None


def _probe_tensor(link) -> Matrix | None:
    """The link-frame tensor of an expanded probe link's <inertial>."""
    from .model import INERTIA_KEYS
    from .numbers import NumberError, parse_double, parse_vector

    try:
        inertia = link.find("inertial/inertia")
        values = {k: parse_double(inertia.get(k)) for k in INERTIA_KEYS}
        origin = link.find("inertial/origin")
        rpy = parse_vector(origin.get("rpy", "0 0 0")) if origin is not None else (0.0, 0.0, 0.0)
    except (AttributeError, TypeError, NumberError, ValueError):
        return None
    return massprops.rotate(massprops.matrix(values), massprops.rotation(rpy))
