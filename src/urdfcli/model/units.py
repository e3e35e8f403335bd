"""A mesh in the wrong unit, found from evidence: what the rest of its link says its size is.

CAD tools export millimetres by default; a mesh written in millimetres and used
without ``scale="0.001 0.001 0.001"`` is a thousand times too large in rviz,
Gazebo and every simulator. The mesh's size alone proves nothing (a crane boom is
20 m long); the rest of its link does. Each piece of evidence gives a band of
plausible sizes for the mesh's largest side (after ``scale`` and COLLADA's
``<unit meter>``); the bands are wide, set from the 2,141 mesh uses of the 69
published example-robot-data models (all in metres) with a margin of three to
ten on both sides:

- the link's mass (20 g or more) held in the mesh's bounding box: a density from
  1 to 1,000,000 kg/m³ (the corpus spans 10 to 50,000);
- its child joints: the farthest child joint origin ``d``, the mesh from 0.05 d to 50 d
  (corpus: 0.16 d to 17 d);
- its parent joint's offset ``p``, from 0.02 p to 100 p (corpus: 0.13 p to 35 p);
- its boxes, cylinders and spheres (not placeholders of 2 cm or less), from 1/20 to
  20 times the largest.

Other meshes are no evidence: exported together, they share their unit. The mesh
is in a wrong unit when every piece of evidence finds it too large (or too small),
the mass alone being decisive when the density is below 0.001 kg/m³ (a thousand
times lighter than air; mm meshes give 1e-5 and less) and two pieces otherwise,
and when the mesh divided by 1000, 100 or 25.4 fits every band; the unit whose
size sits closest to the middle of the bands is named. The declared tensor is no
evidence: many are wrong (I009 finds 101 in the corpus), and used as a bound (a
mesh may not be too small to hold it) it made the corpus's meshes, each read as
if exported in millimetres, found less often (91 % instead of 95 %) and named
centimetres more often (43 times instead of 12). Each read in metres, none is
reported. Too small is said
only when a ``scale`` or ``<unit>`` shrank the mesh by that factor (a scale of
0.001 on a mesh already in metres). A mesh that fits any band is never reported.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..read.memo import once
from . import massprops
from .kinematics import children_by_joint_name
from .load import Loaded
from .mesh_summaries import MeshSummary, scaled_bounds
from .meshes import MeshUse, mesh_uses, summary_of
from .robot import Link

UNITS = (("millimetres", 1000.0), ("centimetres", 100.0), ("inches", 25.4))
DENSITY = (1.0, 1e6)  # kg/m³: a link's mass in its mesh's bounding box
TYPICAL_DENSITY = 600.0  # the corpus median
DECISIVE_DENSITY = 1e-3  # below, the mass alone says the mesh is too large
CHILDREN = (0.05, 50.0, 1.3)  # the mesh's largest side over the farthest child joint: lowest, highest, typical
PARENT = (0.02, 100.0, 1.1)
PRIMITIVES = (1 / 20, 20.0, 1.0)
PLACEHOLDER = 0.02  # m: a shape no larger than this in any direction stands for nothing (a dot that keeps a link)
NEAR = 1e-3  # m: joint offsets below this tell nothing of size


class Band(NamedTuple):
    """Sizes (the mesh's largest side, metres) that a piece of evidence finds plausible."""

    low: float
    high: float
    typical: float
    said: str  # the evidence, as a message names it

    def judge(self, size: float) -> int:
        """-1 too small, 0 plausible, 1 too large."""
        return -1 if size < self.low else (1 if size > self.high else 0)


class UnitVerdict(NamedTuple):
    """A mesh use in a wrong unit: ``factor`` times too large (below 1: too small)."""

    unit: str
    factor: float
    size: float  # its largest side as used now, metres
    evidence: str
    scale: tuple[float, float, float]  # the scale that fixes it

    @property
    def too_large(self) -> bool:
        return self.factor > 1


def unit_verdict(loaded: Loaded, use: MeshUse) -> UnitVerdict | None:
    """Whether a mesh use is in a wrong unit; worked out once per use."""
    return once(loaded, _verdicts).get(use.shape.at)


def mis_scaled(loaded: Loaded) -> set[int]:
    """The shapes (their ``at``) whose mesh is in a wrong unit: the inertia rules leave their volume out."""
    return set(once(loaded, _verdicts))


def _verdicts(loaded: Loaded) -> dict[int, UnitVerdict]:
    """Each mesh use in a wrong unit (by its shape's ``at``), with its verdict."""
    found = {}
    for use in mesh_uses(loaded):
        verdict = _verdict(loaded, use)
        if verdict is not None:
            found[use.shape.at] = verdict
    return found


def _verdict(loaded: Loaded, use: MeshUse) -> UnitVerdict | None:
    found = summary_of(loaded, use)
    if found is None or found.low is None or 0 in use.scale:
        return None
    low, high = scaled_bounds(found, use.scale)
    sides = [h - lo for lo, h in zip(low, high)]
    size = max(sides)
    if not size > 0:
        return None
    density = _density(use.link, sides)
    bands = evidence(loaded, use.link, sides, density)
    judged = [band.judge(size) for band in bands]
    for direction in (1, -1):
        if not judged or any(j != direction for j in judged):
            continue
        decisive = density is not None and (density < DECISIVE_DENSITY if direction > 0 else density > 1e9)
        if len(judged) < 2 and not decisive:
            continue
        fitting = [(name, factor ** direction) for name, factor in UNITS if _fits(use, found, factor ** direction, size, bands, direction)]
        if fitting:
            name, factor = min(fitting, key=lambda unit: _distance(size / unit[1], bands))
            return UnitVerdict(name, factor, size, bands[0].said, tuple(s / factor for s in use.scale))  # type: ignore[arg-type]
    return None


def _fits(use: MeshUse, found: MeshSummary, factor: float, size: float, bands: list[Band], direction: int) -> bool:
    """Whether the mesh divided by ``factor`` fits every band; too small only where the
    use's scale or the file's unit shrank it that much."""
    if direction < 0:
        shrunk = (found.unit or 1.0) * math.prod(abs(s) for s in use.scale) ** (1 / 3)
        if shrunk > factor * 1.05:
            return False
    return not any(band.judge(size / factor) for band in bands)


def _distance(size: float, bands: list[Band]) -> float:
    return sum(abs(math.log10(size / band.typical)) for band in bands)


def _density(link: Link, sides: list[float]) -> float | None:
    mass = link.inertial.mass if link.inertial is not None else None
    if mass is None or mass < massprops.LIGHT:
        return None
    size = max(sides)
    return mass / math.prod(max(s, size / 100) for s in sides)


def evidence(loaded: Loaded, link: Link, sides: list[float], density: float | None) -> list[Band]:
    """The bands of plausible sizes the rest of the link gives, the strongest first
    (``density``: the link's mass in the mesh's box, None when it is too light to tell)."""
    bands = []
    if density is not None:
        size = max(sides)
        bands.append(Band(size * (density / DENSITY[1]) ** (1 / 3), size * (density / DENSITY[0]) ** (1 / 3),
                          size * (density / TYPICAL_DENSITY) ** (1 / 3), f"a {massprops.number(link.inertial.mass)} kg link"))
    children = [j for j in children_by_joint_name(loaded.robot).get(link.name, ()) if j.child != link.name]
    farthest = max(children, key=lambda j: math.hypot(*j.origin.xyz), default=None)
    if farthest is not None and math.hypot(*farthest.origin.xyz) > NEAR:
        d = math.hypot(*farthest.origin.xyz)
        bands.append(_band(d, CHILDREN, f"a link whose joint '{farthest.name}' is {d:.3g} m from its origin"))
    parent = loaded.parent_joint(link.name)
    if parent is not None and math.hypot(*parent.origin.xyz) > NEAR:
        d = math.hypot(*parent.origin.xyz)
        bands.append(_band(d, PARENT, f"a link placed {d:.3g} m from its parent by joint '{parent.name}'"))
    primitive = max((primitive_size(s.geometry) for s in (*link.visuals, *link.collisions) if s.geometry is not None), default=0.0)
    if primitive > PLACEHOLDER:
        bands.append(_band(primitive, PRIMITIVES, f"a link whose other shapes are {primitive:.3g} m across"))
    return bands


def _band(length: float, ratios: tuple[float, float, float], said: str) -> Band:
    low, high, typical = ratios
    return Band(length * low, length * high, length * typical, said)


def primitive_size(geometry) -> float:
    """The largest side of a box, cylinder or sphere (0 for a mesh or a shape without size)."""
    if geometry.kind == "box" and geometry.size:
        return max(geometry.size)
    if geometry.kind == "cylinder" and geometry.radius and geometry.length:
        return max(2 * geometry.radius, geometry.length)
    if geometry.kind == "sphere" and geometry.radius:
        return 2 * geometry.radius
    return 0.0


def is_dot(geometry) -> bool:
    """Whether a shape is a placeholder: a box, cylinder or sphere no larger than
    PLACEHOLDER in any direction (the 1 µm cylinder that keeps Gazebo from dropping a link)."""
    return geometry.kind != "mesh" and primitive_size(geometry) <= PLACEHOLDER
