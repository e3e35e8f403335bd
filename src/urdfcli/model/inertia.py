"""Mass properties as declared and as the geometry implies them: each link's declared
body, the uniform body its shapes make, the most its mass can reach inside them,
and the whole robot's total.

The closed-form maths is :mod:`.massprops`, meshes are read by :mod:`.meshes`, the
links' poses come from :mod:`.poses`. What the geometry proves wrong is the rules'
(:mod:`urdfcli.rules.inertia`).

Frames: a declared tensor is given in the frame of its ``<inertial><origin>``;
the *expected* tensor is expressed in that same frame, so the two compare one to one.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..diagnostics import Applicability, Fix, InsertChild, SetAttribute
from ..read.memo import once
from . import massprops
from .load import Loaded
from .massprops import Matrix, Vector
from .mesh_summaries import GeometryUnknown
from .meshes import mesh_properties
from .poses import link_poses
from .robot import Link, Shape
from .units import mis_scaled

TOLERANCE = massprops.TOLERANCE
TIMES = 2.0  # a declared tensor this many times the expected one's size, or a this-many-th of it, is said so
UNSAFE = Applicability.UNSAFE


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

    def times(self) -> str | None:
        """``60 times larger`` (or ``smaller``): the declared tensor's size against the expected
        one's, when one is :data:`TIMES` or more times the other. The difference, a fraction
        of the larger tensor, nears 100 % however far apart they are: it cannot tell 3 from 60
        times. None when they are closer in size, or when there is no expected tensor."""
        if self.expected is None:
            return None
        declared, expected = massprops.scale_of(self.declared), massprops.scale_of(self.expected)
        if declared == 0 or expected == 0 or max(declared, expected) < TIMES * min(declared, expected):
            return None
        ratio = max(declared, expected) / min(declared, expected)
        size = f"{ratio:.1f}" if ratio < 10 else f"{ratio:.0f}"  # as the rules' messages give times: 2.5, 60
        return f"{size} times {'larger' if declared > expected else 'smaller'}"


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
    if inertial.mass != 0:
        return False
    tensor = declared_tensor(link)
    return tensor is None or massprops.is_zero(tensor)


# -- implied by geometry ---------------------------------------------------------------
def implied(loaded: Loaded, link: Link, density: float | None = None) -> Implied:
    """The body the link's collision shapes (else its visual shapes, see :func:`filled_shapes`) make, with the
    declared mass spread by volume, or ``density`` times the volume when given;
    worked out once per link (several rules and the audit ask)."""
    return once(loaded, _implied_named, link.name, density)


def _implied_named(loaded: Loaded, name: str, density: float | None) -> Implied:
    return _implied(loaded, loaded.robot.links[name], density)


STAND_IN = 0.1
"""Collision shapes whose bounding box's longest side is under this fraction of the visual
shapes' are a stand-in, not the body: Baxter's head, a 2 mm sphere on a 15 cm part, and
Go1's cameras (1 mm on 5 cm) are 1 to 2 %; the smallest real collision of example-robot-data's
models is TIAGo Pro's laser, 15 % of its visual."""


def filled_shapes(loaded: Loaded, link: Link) -> tuple[str, tuple[Shape, ...], str]:
    """(kind, shapes, note): the shapes a uniform body fills: the collision shapes, else the
    visual shapes; the visual shapes too when the collision shapes are a :data:`STAND_IN`,
    which ``note`` then says (else it is empty)."""
    collisions = tuple([s for s in link.collisions if s.geometry is not None])
    visuals = tuple([s for s in link.visuals if s.geometry is not None])
    if not collisions or not visuals:
        return ("collision", collisions, "") if collisions else ("visual", visuals, "")
    if {_measure(s.geometry) for s in collisions} & {_measure(s.geometry) for s in visuals}:
        return "collision", collisions, ""  # a collision the size of a visual (most links): not a stand-in
    collision_box, visual_box = extent(loaded, link, collisions), extent(loaded, link, visuals)
    if collision_box is None or visual_box is None:
        return "collision", collisions, ""  # not measured: nothing shows they are a stand-in
    collision_size, visual_size = _longest(collision_box), _longest(visual_box)
    if collision_size >= STAND_IN * visual_size:
        return "collision", collisions, ""
    smaller = f"{visual_size / collision_size:.0f} times smaller" if collision_size > 0 else "sizeless"
    return "visual", visuals, f", not its {smaller} collision geometry"


def _measure(geometry) -> tuple:
    """A shape's geometry but for its place in the document: equal for one box, cylinder or mesh written twice."""
    return geometry._replace(at=0)


def _longest(box: tuple[Vector, Vector]) -> float:
    low, high = box
    return max(h - lo for lo, h in zip(low, high))


def _implied(loaded: Loaded, link: Link, density: float | None) -> Implied:
    kind, shapes, note = filled_shapes(loaded, link)
    if not shapes:
        return Implied(None, "no collision or visual geometry")
    if len(shapes) == 1:  # (most links)
        source = f"{kind} {shapes[0].geometry.kind}{note}"
    else:
        source = f"{kind} shapes ({', '.join([s.geometry.kind for s in shapes])}){note}"
    if _mis_scaled(loaded, shapes):
        return Implied(None, f"a {kind} mesh is in a wrong unit (F003)", shapes=shapes)
    try:
        parts = [shape_part(loaded, shape) for shape in shapes]
    except GeometryUnknown as error:
        return Implied(None, str(error), shapes=shapes)
    volume = sum([v for v, _, _ in parts])
    if volume <= 0:
        return Implied(None, f"{source} has no volume", shapes=shapes)
    mass = density * volume if density is not None else (link.inertial.mass if link.inertial else None)
    if mass is None or mass <= 0:
        return Implied(None, "no mass to spread over the geometry", volume, shapes)
    bodies = []
    for v, centre, unit in parts:
        share = mass * v / volume  # spread by volume
        bodies.append((share, centre, massprops.scaled(unit, share)))
    total, com, tensor = massprops.combine(bodies)
    return Implied(Body(total, com, tensor), source, volume, shapes)


def shape_part(loaded: Loaded, shape: Shape) -> tuple[float, Vector, Matrix]:
    """Volume, centre (link frame) and tensor per unit mass (link axes) of one shape."""
    geometry = shape.geometry
    if geometry.kind == "mesh":
        volume, centre, unit, _ = mesh_properties(loaded, geometry.filename, tuple(geometry.scale))
    else:
        volume, unit = primitive(geometry)
        centre = (0.0, 0.0, 0.0)
    pose = massprops.transform(shape.origin.xyz, shape.origin.rpy)
    return volume, massprops.place(pose, centre), massprops.rotate(unit, pose[0])


def primitive(geometry) -> tuple[float, Matrix]:
    """Volume and tensor per unit mass of a box, cylinder or sphere."""
    _measurable(geometry)
    if geometry.kind == "box":
        return massprops.box_volume(geometry.size), massprops.box(1.0, geometry.size)
    if geometry.kind == "cylinder":
        return massprops.cylinder_volume(geometry.radius, geometry.length), massprops.cylinder(1.0, geometry.radius, geometry.length)
    return massprops.sphere_volume(geometry.radius), massprops.sphere(1.0, geometry.radius)


def _measurable(geometry) -> None:
    """Raises GeometryUnknown for a box, cylinder or sphere without size."""
    if geometry.kind == "box":
        if min(geometry.size) <= 0:
            raise GeometryUnknown("box size is not positive")
    elif geometry.kind == "cylinder":
        if geometry.radius <= 0 or geometry.length <= 0:
            raise GeometryUnknown("cylinder radius or length is not positive")
    elif geometry.radius <= 0:
        raise GeometryUnknown("sphere radius is not positive")


def shape_bounds(loaded: Loaded, shape: Shape) -> tuple[Vector, Vector]:
    """Lowest and highest corner, in the link frame, of a box holding the shape
    (its own bounding box, turned as the shape is)."""
    geometry = shape.geometry
    if geometry.kind == "mesh":
        low, high = mesh_properties(loaded, geometry.filename, tuple(geometry.scale))[3]
    else:
        _measurable(geometry)
        if geometry.kind == "box":
            x, y, z = geometry.size
            high = (x / 2.0, y / 2.0, z / 2.0)
        elif geometry.kind == "cylinder":
            high = (geometry.radius, geometry.radius, geometry.length / 2.0)
        else:
            high = (geometry.radius,) * 3
        low = (-high[0], -high[1], -high[2])
    origin = shape.origin
    if not any(origin.rpy):  # not turned: moved only (most shapes; a tenth of the time)
        x, y, z = origin.xyz
        return (low[0] + x, low[1] + y, low[2] + z), (high[0] + x, high[1] + y, high[2] + z)
    pose = massprops.transform(shape.origin.xyz, shape.origin.rpy)
    corners = [massprops.place(pose, (x, y, z)) for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])]
    return tuple(min(c[i] for c in corners) for i in range(3)), tuple(max(c[i] for c in corners) for i in range(3))  # type: ignore[return-value]


def extent(loaded: Loaded, link: Link, shapes=None) -> tuple[Vector, Vector] | None:
    """The box (lowest and highest corner, link frame) that holds the shapes, by default every
    visual and collision shape of the link; None when there are none, or one cannot be measured."""
    if shapes is None:
        shapes = (*link.visuals, *link.collisions)
    shapes = [s for s in shapes if s.geometry is not None]
    if not shapes or _mis_scaled(loaded, shapes):
        return None
    try:
        if len(shapes) == 1:  # (most links: its own box)
            return shape_bounds(loaded, shapes[0])
        lows, highs = zip(*(shape_bounds(loaded, shape) for shape in shapes))
    except GeometryUnknown:
        return None
    return tuple(map(min, zip(*lows))), tuple(map(max, zip(*highs)))  # type: ignore[return-value]


def _mis_scaled(loaded: Loaded, shapes) -> bool:
    """Whether a shape is a mesh in a wrong unit (F003 reports it; its volume and size prove nothing)."""
    return any(s.geometry.kind == "mesh" for s in shapes) and any(s.at in mis_scaled(loaded) for s in shapes)


# -- comparison ------------------------------------------------------------------------
def assess(loaded: Loaded, link: Link, density: float | None = None) -> Assessment | None:
    """Declared against implied, for a link that declares a tensor (None otherwise).

    Worked out once per link and density: three rules and the audit ask for it."""
    return once(loaded, _assess_named, link.name, density)


def _assess_named(loaded: Loaded, name: str, density: float | None) -> Assessment | None:
    return _assess(loaded, loaded.robot.links[name], density)


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


def rotated_fit(loaded: Loaded, assessment: Assessment) -> tuple[Vector, float] | None:
    """When the geometry is rotated and the inertial frame is not rotated with it:
    the shapes' rpy, and the difference left if the tensor were read in their frame.
    None when the declared centre of mass lies outside the shapes: a tensor computed
    for them would have its centre inside, so it was measured on the part (CAD)."""
    shapes = assessment.implied.shapes
    shared = shapes_rotation(shapes)
    inertial = inertial_rotation(assessment.link)
    if shared is None or massprops.relative_difference(shared, inertial) < 1e-6:
        return None
    box = extent(loaded, assessment.link, shapes)
    if box is None or outside(assessment.link.inertial.origin.xyz, box) > 0:
        return None
    # the declared tensor read in the shapes' frame, then expressed in the inertial frame
    in_link = massprops.rotate(assessment.declared, shared)
    moved = massprops.rotate(in_link, massprops.transpose(inertial))
    return shapes[0].origin.rpy, massprops.relative_difference(moved, assessment.expected)


# -- what the geometry proves ---------------------------------------------------------
OVERREACH = 1.3
"""A moment is impossible when it exceeds the most its mass can reach by this factor.
The margin absorbs meshes a little smaller than the part they draw and CAD rounding:
published arms are 1.1 to 1.2 times over (FR3's link2, UR3e's wrist_2)."""

DENSEST = 22600.0
"""kg/m³ (osmium): a mass denser than this in its geometry's bounding box is not drawn by that
geometry (a millimetre sphere standing in for a finger), which then proves nothing."""

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


def reach(loaded: Loaded, link: Link, declared: Body | None) -> Reach | None:
    """None when the link has no measurable geometry, or geometry too small to hold its mass;
    ``declared`` is the link's :func:`declared_body`.

    Along each axis, a mass held in [lo, hi] with its mean at c has a variance of at most
    (hi - c)(c - lo) (the Bhatia-Davis inequality); a moment is the mass times the sum of
    two such variances. A centre outside the box gives (farthest extent)² instead."""
    inertial = link.inertial
    if inertial is None or not (inertial.mass or 0) > 0:
        return None
    # the shapes already measured first: a box that holds the tensor proves nothing, and a
    # larger one around the same centre would not either, so the other meshes are read only
    # when it does not (or when the centre lies outside it, where the bound is not monotone)
    box = extent(loaded, link, implied(loaded, link).shapes)
    first = _reach(inertial, box)
    if first is not None and declared is not None and outside(inertial.origin.xyz, box) == 0 and _within(declared.tensor, first.bounds):
        return first
    return _reach(inertial, extent(loaded, link))


def outside(point: Vector, box: tuple[Vector, Vector]) -> float:
    """How far (m) a point lies outside a box (lowest and highest corner): 0 inside it."""
    low, high = box
    return math.sqrt(sum(max(lo - p, 0.0, p - h) ** 2 for p, lo, h in zip(point, low, high)))


def _within(tensor: Matrix, bounds: Vector) -> bool:
    """Whether each moment is within OVERREACH of its bound."""
    return tensor[0][0] <= OVERREACH * bounds[0] and tensor[1][1] <= OVERREACH * bounds[1] and tensor[2][2] <= OVERREACH * bounds[2]


def _reach(inertial, box) -> Reach | None:
    if box is None:
        return None
    low, high = box
    sides = (high[0] - low[0], high[1] - low[1], high[2] - low[2])
    volume = sides[0] * sides[1] * sides[2]
    if volume <= 0 or inertial.mass / volume > DENSEST:
        return None
    cx, cy, cz = inertial.origin.xyz
    x, y, z = _spread(low[0], high[0], cx), _spread(low[1], high[1], cy), _spread(low[2], high[2], cz)
    m = inertial.mass
    return Reach((m * (y + z), m * (x + z), m * (x + y)), sides)


def _spread(lo: float, h: float, c: float) -> float:
    """The most variance along one axis of a mass held in [lo, h] with its mean at c."""
    return (h - c) * (c - lo) if lo <= c <= h else max(h - c, c - lo) ** 2


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




# -- a suggested inertial ----------------------------------------------------------------
class Suggested(NamedTuple):
    """The ``<inertial>`` a uniform body filling a link's geometry gives: in the frame
    of the link's current ``<inertial><origin>`` rotation (``rpy``), so that only the
    centre and the tensor change; ``source`` names the shapes it fills."""

    mass: float
    xyz: Vector
    rpy: Vector
    tensor: dict[str, float]
    source: str


def suggested(loaded: Loaded, link: Link, density: float | None = None) -> Suggested | str:
    """The inertial a uniform body filling the link's geometry gives (an estimate: a
    part's CAD values are better), or why the geometry cannot tell."""
    found = implied(loaded, link, density)
    if found.body is None:
        return found.source if link.inertial is not None or density else "it declares no mass (give --density)"
    rpy = link.inertial.origin.rpy if link.inertial is not None else (0.0, 0.0, 0.0)
    tensor = massprops.tidy(massprops.rotate(found.body.tensor, massprops.transpose(massprops.rotation(rpy))))
    return Suggested(found.body.mass, found.body.com, rpy, massprops.as_dict(tensor), found.source)


def inertial_fix(loaded: Loaded, link: Link) -> Fix:
    """The fix that writes :func:`suggested`'s tensor and centre of mass into the link's
    ``<inertial>`` (its mass and the rotation of its frame kept); unsafe: the robot's
    dynamics change."""
    found = suggested(loaded, link)
    title = f"write the tensor and centre of mass of a uniform body filling the geometry of link '{link.name}'"
    inertial = link.inertial
    if isinstance(found, str):
        return Fix(title, UNSAFE, reason=f"the geometry cannot tell: {found}")
    if inertial is None or inertial.inertia_at is None:
        return Fix(title, UNSAFE, reason=f"link '{link.name}' has no <inertia> to write it in")
    declared = inertial.inertia or {}
    changes: list = [
        SetAttribute(inertial.inertia_at, key, massprops.number(found.tensor[key]))
        for key in massprops.KEYS if not _same(declared.get(key), found.tensor[key])
    ]
    xyz = " ".join(map(massprops.number, found.xyz))
    if not all(_same(a, b) for a, b in zip(inertial.origin.xyz, found.xyz)):
        if inertial.origin_at is not None:
            changes.append(SetAttribute(inertial.origin_at, "xyz", xyz))
        else:
            changes.append(InsertChild(inertial.at, f'<origin xyz="{xyz}" rpy="0 0 0"/>'))
    if not changes:
        return Fix(title, UNSAFE, reason="the declared values are those already")
    return Fix(f"{title}: {found.source}", UNSAFE, changes=tuple(changes), inputs=_inputs(loaded, link))


def _inputs(loaded: Loaded, link: Link) -> tuple[tuple[int, str], ...]:
    """The values a suggested inertial is worked out from: the mass, and the size and
    place of the shapes the body fills."""
    found = [(link.inertial.mass_at, "value")] if link.inertial.mass_at is not None else []
    for shape in filled_shapes(loaded, link)[1]:
        geometry = shape.geometry
        found += [(geometry.at, attribute) for attribute in _SIZED_BY[geometry.kind]]
        if shape.origin_at is not None:
            found += [(shape.origin_at, "xyz"), (shape.origin_at, "rpy")]
    return tuple(found)


_SIZED_BY = {"box": ("size",), "cylinder": ("radius", "length"), "sphere": ("radius",), "mesh": ("filename", "scale")}


def _same(declared: float | None, value: float) -> bool:
    """Whether a declared number is the value as a fix would write it (six digits)."""
    return declared is not None and math.isclose(declared, float(massprops.number(value)), rel_tol=1e-6, abs_tol=1e-15)
