"""The mass-property audit: each link's declared mass properties against those its geometry
implies, what the geometry proves wrong, and the whole robot's total.

The closed-form maths is :mod:`urdfcli.massprops`, meshes are read by :mod:`urdfcli.meshes`,
the links' poses come from :mod:`urdfcli.poses`, and :mod:`urdfcli.fixes` suggests the fixes.

Frames: a declared tensor is given in the frame of its ``<inertial><origin>``;
the *expected* tensor is expressed in that same frame, so the two compare one to one.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from . import massprops
from .loaded import Loaded
from .massprops import Matrix, Vector
from .meshes import GeometryUnknown, MeshFiles, mesh_properties
from .model import Link, Shape
from .poses import link_poses

TOLERANCE = massprops.TOLERANCE


class Body(NamedTuple):
    mass: float
    com: Vector  # centre of mass
    tensor: Matrix  # about the centre of mass


class Implied(NamedTuple):
    """What a link's geometry implies; ``body`` is None when it cannot tell, and ``source`` says why."""

    body: Body | None
    source: str
    volume: float | None = None
    shapes: tuple[Shape, ...] = ()


class Assessment(NamedTuple):
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
def implied(loaded: Loaded, link: Link, density: float | None = None) -> Implied:
    """The body the link's collision shapes (else its visual shapes) make, with the
    declared mass spread by volume, or ``density`` times the volume when given;
    worked out once per link (several rules and the audit ask)."""
    return loaded.remembered(("implied", link.name, density), lambda: _implied(loaded, link, density))


def _implied(loaded: Loaded, link: Link, density: float | None) -> Implied:
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
    worst = 0.0
    moments_a, moments_b = massprops.principal_moments(a), massprops.principal_moments(b)
    for i in range(3):
        if _distinct(moments_a, i) and _distinct(moments_b, i):
            axis_a, axis_b = massprops.principal_axis(a, moments_a[i]), massprops.principal_axis(b, moments_b[i])
            if axis_a is not None and axis_b is not None:
                cosine = abs(sum(x * y for x, y in zip(axis_a, axis_b)))
                worst = max(worst, math.degrees(math.acos(min(1.0, cosine))))
    return worst


def _distinct(moments, i: int) -> bool:
    largest = max(abs(m) for m in moments)
    return largest > 0 and all(abs(moments[i] - moments[j]) >= DISTINCT * largest for j in range(3) if j != i)


class Reach(NamedTuple):
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


class Verdict(NamedTuple):
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
class LinkReport(NamedTuple):
    link: Link
    frame: bool  # a massless frame link: listed quietly
    assessment: Assessment | None
    problems: tuple  # Diagnostics located in this link
    mass: float | None = None  # the mass the total counts: from --density, or as declared
    from_density: bool = False


class Report(NamedTuple):
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
