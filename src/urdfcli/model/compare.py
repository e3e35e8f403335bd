"""Two robots compared by meaning: what was added, removed, renamed or changed.

Numbers are compared with a relative tolerance (a vector by its length, a rotation
by the angle between the two), so that how a number is written (``0.10``,
``0.1``, ``1e-1``), the order of attributes, comments and whitespace never make
a change; an ``rpy`` written another way for the same rotation is no change
either.

Links and joints are matched by name first. A link left over in both robots is
matched by its place (the same parent, through the links already matched) and
what it holds (mass, inertia, geometry, and the joint that places it): matched,
it is *renamed*; otherwise one is *removed* and the other *added*. A joint left
over is renamed when it joins the same two links. Names in the rest of the
model (a joint's parent, a ``<gazebo reference>``) are compared through these
renames, so a rename is reported once.

What follows for the robot: its total mass, its degrees of freedom, and where
each link sits with every joint at 0 (:func:`.poses.zero_poses`): each link that
moved, by how much, in millimetres and degrees.

Each change carries the element it is about in the new robot (in the old one
for a removal), which locates it as a diagnostic is located: through xacro
includes and macro calls.
"""


import math
import os
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import Any, NamedTuple

from ..read.memo import once
from ..diagnostics import Location
from ..read.xml import Element
from . import massprops
from .kinematics import roots, walk
from .load import Loaded
from .massprops import Transform
from .numbers import NumberError, format_number, parse_double
from .poses import zero_poses
from .robot import INERTIA_KEYS, Geometry, Joint, Link, Material, Robot, Shape

TOLERANCE = 1e-6
"""Default relative tolerance: two numbers closer than this fraction of the larger are equal."""
FLOOR = 1e-12  # numbers closer than this are equal whatever their size (xacro's cos(pi/2) is 6e-17)
# a joint's elements compared value by value, their values named in this order (a whole one added
# or removed is the list of them)
PARTS = {
    "limit": ("lower", "upper", "effort", "velocity"),
    "dynamics": ("damping", "friction"),
    "safety_controller": ("soft_lower_limit", "soft_upper_limit", "k_position", "k_velocity"),
}
DOF = {"fixed": 0, "revolute": 1, "continuous": 1, "prismatic": 1, "planar": 3, "floating": 6}


class Change(NamedTuple):
    """One difference. ``element`` names the top-level element as the new robot has it
    (``link[@name='arm']``; the old name for a removal); ``field`` what of it changed
    (``limit upper``, ``visual[2]``; None for the whole element). ``old`` and ``new``
    are plain values (numbers, lists, strings; None where absent). ``relative`` is a
    number's change as a fraction of the old value; ``moved`` a pose's displacement
    (millimetres, degrees). ``location`` is where the element was written in the new
    robot's sources (the old one's for a removal); ``anchor``, for a removal, the
    closest element of the new robot (its parent link there, else the robot)."""

    kind: str
    element: str
    field: str | None = None
    old: Any = None
    new: Any = None
    relative: float | None = None
    moved: tuple[float, float] | None = None
    location: Location | None = None
    anchor: Location | None = None


class Totals(NamedTuple):
    """What one robot amounts to."""

    name: str | None
    links: int
    joints: int
    dof: int
    mass: float


class Comparison(NamedTuple):
    changes: tuple[Change, ...]
    old: Totals
    new: Totals

    @property
    def same(self) -> bool:
        return not self.changes

    def count(self, kind: str) -> int:
        """The changes of a kind, poses apart (see :attr:`moved`)."""
        return sum(1 for change in self.changes if change.kind == kind and change.field != "pose")

    @property
    def moved(self) -> int:
        """The links whose pose at zero joint positions moved."""
        return sum(1 for change in self.changes if change.field == "pose")


# -- numbers ------------------------------------------------------------------------
class Numbers:
    """Equality of numbers, vectors and rotations under one relative tolerance."""

    def __init__(self, tolerance: float = TOLERANCE) -> None:
        self.tolerance = tolerance

    def same(self, a: float | None, b: float | None) -> bool:
        if a is None or b is None:
            return a is b
        return abs(a - b) <= max(self.tolerance * max(abs(a), abs(b)), FLOOR)

    def same_vector(self, a: Iterable[float] | None, b: Iterable[float] | None) -> bool:
        if a is None or b is None:
            return a is b
        a, b = tuple(a), tuple(b)
        if len(a) != len(b):
            return False
        gap = math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))
        size = max(math.sqrt(sum(x * x for x in a)), math.sqrt(sum(y * y for y in b)))
        return gap <= max(self.tolerance * size, FLOOR)

    def same_rotation(self, a: Iterable[float], b: Iterable[float]) -> bool:
        return turn(massprops.rotation(tuple(a)), massprops.rotation(tuple(b))) <= max(self.tolerance, FLOOR)


def turn(a: massprops.Matrix, b: massprops.Matrix) -> float:
    """The angle (radians) of the rotation from a to b: from its sine and cosine both, as
    an arc cosine alone reads a trace a rounding below 3 as a turn of 1e-8 rad."""
    r = massprops.multiply(massprops.transpose(a), b)
    cosine = (r[0][0] + r[1][1] + r[2][2] - 1.0) / 2.0
    sine = math.hypot(r[2][1] - r[1][2], r[0][2] - r[2][0], r[1][0] - r[0][1]) / 2.0
    return math.atan2(sine, cosine)


def relative(old: float | None, new: float | None) -> float | None:
    """The change from old to new as a fraction of old (None when old is 0 or absent)."""
    if old is None or new is None or old == 0:
        return None
    return (new - old) / abs(old)


def shown(value: Any) -> Any:
    """A value as JSON holds it: tuples as lists, floats as they are."""
    if isinstance(value, tuple):
        return [shown(v) for v in value]
    return value


def text(value: Any, number: Callable[[float], str] = format_number) -> str:
    """A value as a person reads it: numbers shortest (or as ``number`` writes them), vectors space-separated."""
    if value is None:
        return "(none)"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return number(value)
    if isinstance(value, (list, tuple)):
        return " ".join(text(v, number) for v in value)
    return str(value)


# -- what a link, a joint and a shape hold ---------------------------------------------
def material_text(shape: Shape) -> str | None:
    """A visual's material: its name, or ``rgba R G B A`` for one without a name."""
    if shape.material:
        return shape.material
    return f"rgba {text(shape.colour)}" if shape.colour is not None else None


def geometry_text(geometry: Geometry | None) -> str | None:
    if geometry is None:
        return None
    if geometry.kind == "box":
        return f"box {text(geometry.size)}"
    if geometry.kind == "cylinder":
        return f"cylinder radius {text(geometry.radius)} length {text(geometry.length)}"
    if geometry.kind == "sphere":
        return f"sphere radius {text(geometry.radius)}"
    scale = "" if geometry.scale == (1.0, 1.0, 1.0) else f" scale {text(geometry.scale)}"
    return f"mesh {geometry.filename}{scale}"


def geometry_fields(geometry: Geometry) -> dict[str, Any]:
    """The values of a shape that its kind has."""
    if geometry.kind == "box":
        return {"size": geometry.size}
    if geometry.kind == "cylinder":
        return {"radius": geometry.radius, "length": geometry.length}
    if geometry.kind == "sphere":
        return {"radius": geometry.radius}
    return {"filename": geometry.filename, "scale": geometry.scale}


def element_name(tag: str, name: str) -> str:
    quote = "'" if "'" not in name else '"'
    return f"{tag}[@name={quote}{name}{quote}]"


# -- the comparison ---------------------------------------------------------------------
class Comparer:
    """Compares an old and a new loaded model (both with a robot read)."""

    def __init__(self, old: Loaded, new: Loaded, tolerance: float = TOLERANCE, place: Callable[[Path], Path] = lambda file: file) -> None:
        self.old, self.new = old, new
        self.place = place
        self.a: Robot = old.robot  # type: ignore[assignment]
        self.b: Robot = new.robot  # type: ignore[assignment]
        self.numbers = Numbers(tolerance)
        self.links: dict[str, str] = {}  # old name -> new name
        self.joints: dict[str, str] = {}
        self.materials: dict[str, str] = {}
        self.changes: list[Change] = []

    # -- locating ---------------------------------------------------------------------
    def here(self, at: int | None, attribute: str | None = None) -> Location | None:
        return self.new.document.locate(at, attribute) if at is not None else None

    def there(self, at: int | None, attribute: str | None = None) -> Location | None:
        return self.old.document.locate(at, attribute) if at is not None else None

    def change(self, kind: str, element: str, field: str | None, old: Any, new: Any, location: Location | None, **extra) -> None:
        self.changes.append(Change(kind, element, field, shown(old), shown(new), location=location, **extra))

    def removed(self, element: str, field: str | None, old: Any, at: int | None, anchor_at: int | None) -> None:
        self.change("removed", element, field, old, None, self.there(at), anchor=self.here(anchor_at if anchor_at is not None else self.b.at))

    def number(self, element: str, field: str, old: float | None, new: float | None, at: int | None, attribute: str | None = None) -> None:
        if not self.numbers.same(old, new):
            self.change("changed", element, field, old, new, self.here(at, attribute), relative=relative(old, new))

    def vector(self, element: str, field: str, old, new, at: int | None, attribute: str | None = None) -> None:
        if not self.numbers.same_vector(old, new):
            self.change("changed", element, field, old, new, self.here(at, attribute))

    def value(self, element: str, field: str, old: Any, new: Any, at: int | None, attribute: str | None = None) -> None:
        if old != new:
            self.change("changed", element, field, old, new, self.here(at, attribute))

    def origin(self, element: str, field: str, old, new, at: int | None) -> None:
        """An ``<origin>``: its translation (with the distance moved), and its rotation
        compared as a rotation (with the angle turned)."""
        if not self.numbers.same_vector(old.xyz, new.xyz):
            self.change("changed", element, f"{field} xyz", old.xyz, new.xyz, self.here(at, "xyz"), moved=(math.dist(old.xyz, new.xyz) * 1000.0, 0.0))
        if not self.numbers.same_rotation(old.rpy, new.rpy):
            angle = turn(massprops.rotation(old.rpy), massprops.rotation(new.rpy))
            self.change("changed", element, f"{field} rpy", old.rpy, new.rpy, self.here(at, "rpy"), moved=(0.0, math.degrees(angle)))

    # -- the run ----------------------------------------------------------------------
    def run(self) -> Comparison:
        a, b = self.a, self.b
        if a.name != b.name:
            self.change("changed", "robot", "name", a.name, b.name, self.here(b.at, "name"))
        self.match_materials()
        self.match_links_and_joints()
        old_poses, new_poses = zero_poses(self.old), zero_poses(self.new)
        for name, link in self.ordered(a.links, b.links, self.links):
            self.compare_link(name, link, old_poses, new_poses)
        for name, joint in self.ordered(a.joints, b.joints, self.joints):
            self.compare_joint(name, joint)
        self.compare_materials()
        self.compare_blocks()
        return Comparison(tuple(self.changes), totals(a), totals(b))

    def ordered(self, old: dict, new: dict, matched: dict[str, str]) -> Iterator[tuple[str | None, Any]]:
        """(old name or None, new element) in the new document's order, then (old name, None) for each removed."""
        back = {new_name: old_name for old_name, new_name in matched.items()}
        for name, item in sorted(new.items(), key=lambda pair: pair[1].at):
            yield back.get(name), item
        for name, item in sorted(old.items(), key=lambda pair: pair[1].at):
            if name not in matched:
                yield name, None

    # -- matching -----------------------------------------------------------------------
    def match_links_and_joints(self) -> None:
        a, b = self.a, self.b
        self.links = {name: name for name in a.links if name in b.links}
        self.joints = {name: name for name in a.joints if name in b.joints}
        if len(self.links) < len(a.links) and len(self.links) < len(b.links):
            self.match_renamed_links()
        if len(self.joints) < len(a.joints) and len(self.joints) < len(b.joints):
            self.match_renamed_joints()

    def match_renamed_links(self) -> None:
        """Top-down through the new tree: each link without a match, against the old
        links without one at the same place."""
        a, b = self.a, self.b
        new_links = set(self.links.values())
        old_parent = self.old.parent_joints
        old_children: dict[str | None, list[str]] = {}
        for name in a.links:
            if name not in self.links:
                joint = old_parent.get(name)
                old_children.setdefault(joint.parent if joint is not None else None, []).append(name)
        back = {new: old for old, new in self.links.items()}
        for root in roots(b):
            for _, joint, link in walk(b, root):
                if link in new_links:
                    continue
                # the old links at its place: under the old name of its parent ("\0": a parent the
                # old robot does not have), or the old roots for a root
                place = back.get(joint.parent, "\0") if joint is not None else None
                candidates = old_children.get(place, [])
                scored = [(self.similarity(a.links[c], old_parent.get(c), b.links[link], joint), c) for c in candidates]
                (score, content), best = max(scored, default=((0.0, 0.0), None), key=lambda pair: pair[0][0])
                if best is None or score < RENAMED or content < ALIKE:
                    continue
                candidates.remove(best)
                self.links[best] = link
                back[link] = best
                new_links.add(link)
                old_joint = old_parent.get(best)
                if joint is not None and old_joint is not None and old_joint.name not in self.joints and joint.name not in self.joints.values():
                    self.joints[old_joint.name] = joint.name

    def similarity(self, old: Link, old_joint: Joint | None, new: Link, new_joint: Joint | None) -> tuple[float, float]:
        """How alike two links at the same place are, in all and in what they hold: the
        fraction of what they hold that is equal, plus the fraction of the features of the
        joints placing them that are equal (a root counts what it holds twice), plus a half
        when that joint kept its name."""
        content = self.features_alike(link_features(old), link_features(new))
        if old_joint is None or new_joint is None:
            return 2 * content, content
        placed = self.features_alike(joint_features(old_joint), joint_features(new_joint))
        kept = 0.5 if self.joints.get(old_joint.name) == new_joint.name else 0.0
        return content + placed + kept, content

    def features_alike(self, old: tuple, new: tuple) -> float:
        return sum(1 for x, y in zip(old, new) if self.alike(x, y)) / len(old)

    def alike(self, x: Any, y: Any) -> bool:
        if isinstance(x, float) and isinstance(y, float):
            return self.numbers.same(x, y)
        if isinstance(x, tuple) and isinstance(y, tuple):
            return len(x) == len(y) and all(self.alike(p, q) for p, q in zip(x, y))
        return x == y

    def match_renamed_joints(self) -> None:
        """A joint without a match, against an old one without a match joining the same two links."""
        matched_new = set(self.joints.values())
        ends: dict[tuple, list[str]] = {}
        for name, joint in self.a.joints.items():
            if name not in self.joints:
                ends.setdefault((self.links.get(joint.parent or ""), self.links.get(joint.child or "")), []).append(name)
        for name, joint in sorted(self.b.joints.items(), key=lambda pair: pair[1].at):
            if name in matched_new:
                continue
            found = ends.get((joint.parent, joint.child))
            if found and joint.parent is not None and joint.child is not None:
                self.joints[found.pop(0)] = name

    def match_materials(self) -> None:
        """Materials by name, then an old one left over with the same colour and texture as a new one: renamed."""
        old, new = materials_of(self.a), materials_of(self.b)
        self.materials = {name: name for name in old if name in new}
        unmatched = [name for name in new if name not in old]
        for name, material in old.items():
            if name in new:
                continue
            for other in unmatched:
                if material.texture == new[other].texture and self.numbers.same_vector(material.rgba, new[other].rgba):
                    self.materials[name] = other
                    unmatched.remove(other)
                    self.change("renamed", element_name("material", other), "name", name, other, self.here(new[other].at, "name"))
                    break

    # -- links ----------------------------------------------------------------------------
    def compare_link(self, old_name: str | None, new: Link | None, old_poses: dict, new_poses: dict) -> None:
        a = self.a
        if new is None:
            link = a.links[old_name]  # type: ignore[index]
            joint = self.old.parent_joint(link.name)
            parent = self.links.get(joint.parent or "") if joint is not None else None
            self.removed(element_name("link", link.name), None, link.name, link.at, self.b.links[parent].at if parent in self.b.links else None)
            return
        element = element_name("link", new.name)
        if old_name is None:
            self.change("added", element, None, None, new.name, self.here(new.at))
            return
        old = a.links[old_name]
        if old_name != new.name:
            self.change("renamed", element, "name", old_name, new.name, self.here(new.at, "name"))
        self.compare_inertial(element, old, new)
        for tag, olds, news in (("visual", old.visuals, new.visuals), ("collision", old.collisions, new.collisions)):
            for index in range(max(len(olds), len(news))):
                field = f"{tag}[{index + 1}]" if max(len(olds), len(news)) > 1 or index else tag
                if index >= len(news):
                    self.removed(element, field, geometry_text(olds[index].geometry), olds[index].at, new.at)
                elif index >= len(olds):
                    self.change("added", element, field, None, geometry_text(news[index].geometry), self.here(news[index].at))
                else:
                    self.compare_shape(element, field, olds[index], news[index], tag == "visual")
        if old_name in old_poses and new.name in new_poses:
            self.compare_pose(element, old_poses[old_name], new_poses[new.name], new.at)

    def compare_inertial(self, element: str, old: Link, new: Link) -> None:
        i, j = old.inertial, new.inertial
        if i is None and j is None:
            return
        if j is None:
            self.removed(element, "inertial", i.mass, i.at, new.at)  # type: ignore[union-attr]
            return
        if i is None:
            self.change("added", element, "inertial", None, j.mass, self.here(j.at))
            return
        self.number(element, "inertial mass", i.mass, j.mass, j.mass_at, "value")
        self.origin(element, "inertial origin", i.origin, j.origin, j.origin_at or j.at)
        if i.inertia is None or j.inertia is None:
            if (i.inertia is None) != (j.inertia is None):
                self.change("changed", element, "inertial inertia", i.inertia and [i.inertia[k] for k in INERTIA_KEYS], j.inertia and [j.inertia[k] for k in INERTIA_KEYS], self.here(j.inertia_at or j.at))
            return
        scale = max(abs(v) for v in (*i.inertia.values(), *j.inertia.values()))
        for key in INERTIA_KEYS:
            x, y = i.inertia[key], j.inertia[key]
            # a product of inertia is judged against the tensor's size: 1e-19 against 0 is no change
            if abs(x - y) > max(self.numbers.tolerance * max(abs(x), abs(y), scale if key in ("ixy", "ixz", "iyz") else 0.0), FLOOR):
                self.change("changed", element, f"inertial inertia {key}", x, y, self.here(j.inertia_at, key), relative=relative(x, y))

    def compare_shape(self, element: str, field: str, old: Shape, new: Shape, visual: bool) -> None:
        self.origin(element, f"{field} origin", old.origin, new.origin, new.origin_at or new.at)
        g, h = old.geometry, new.geometry
        if g is None or h is None or g.kind != h.kind:
            if geometry_text(g) != geometry_text(h):
                self.change("changed", element, f"{field} geometry", geometry_text(g), geometry_text(h), self.here(h.at if h is not None else new.at))
        else:
            olds, news = geometry_fields(g), geometry_fields(h)
            for key, x in olds.items():
                y = news[key]
                if key == "filename":
                    if x != y and not self.same_file(x, y):
                        self.change("changed", element, f"{field} geometry {h.kind} {key}", x, y, self.here(h.at, key))
                elif isinstance(x, tuple):
                    self.vector(element, f"{field} geometry {h.kind} {key}", x, y, h.at, key)
                else:
                    self.number(element, f"{field} geometry {h.kind} {key}", x, y, h.at, key)
        if visual:
            # name="" (xacro macros write it) is no name: such a material is known by its colour
            old_name, new_name = old.material or None, new.material or None
            matched = self.materials.get(old_name, old_name) if old_name else None
            if matched != new_name:
                self.change("changed", element, f"{field} material", material_text(old), material_text(new), self.here(new.material_at or new.at, "name" if new_name else None))
            elif not new_name and not self.numbers.same_vector(old.colour, new.colour):
                # a material without a name is not shared: its colour is the visual's own
                self.change("changed", element, f"{field} material colour", old.colour, new.colour, self.here(new.material_at or new.at))

    def same_file(self, x: str | None, y: str | None) -> bool:
        """Two mesh file names for one file: the same package:// URI written another way, or
        two names that resolve to the same file on disk (xacro's $(find) gives an absolute path)
        or to the same place (:func:`compare`'s ``place``)."""
        if x is None or y is None:
            return False
        old_file = self.old.resolver.resolve_uri(x, self.old.document.file.parent if self.old.document.file else None)
        new_file = self.new.resolver.resolve_uri(y, self.new.document.file.parent if self.new.document.file else None)
        if old_file is not None and new_file is not None and self.place(old_file) == self.place(new_file):
            return True
        try:
            return old_file is not None and new_file is not None and old_file.exists() and old_file.samefile(new_file)
        except OSError:
            return False

    def compare_pose(self, element: str, old: Transform, new: Transform, at: int) -> None:
        (r, t), (s, u) = old, new
        distance = math.dist(t, u)
        angle = turn(r, s)
        size = max(math.hypot(*t), math.hypot(*u))
        if distance <= max(self.numbers.tolerance * size, FLOOR) and angle <= max(self.numbers.tolerance, FLOOR):
            return
        self.change(
            "changed", element, "pose", {"xyz": list(t), "rpy": list(rpy_of(r))}, {"xyz": list(u), "rpy": list(rpy_of(s))},
            self.here(at), moved=(distance * 1000.0, math.degrees(angle)),
        )

    # -- joints ---------------------------------------------------------------------------
    def compare_joint(self, old_name: str | None, new: Joint | None) -> None:
        if new is None:
            joint = self.a.joints[old_name]  # type: ignore[index]
            parent = self.links.get(joint.parent or "")
            self.removed(element_name("joint", joint.name), None, joint.name, joint.at, self.b.links[parent].at if parent in self.b.links else None)
            return
        element = element_name("joint", new.name)
        if old_name is None:
            self.change("added", element, None, None, new.name, self.here(new.at))
            return
        old = self.a.joints[old_name]
        if old_name != new.name:
            self.change("renamed", element, "name", old_name, new.name, self.here(new.at, "name"))
        self.value(element, "type", old.type, new.type, new.at, "type")
        for tag in ("parent", "child"):
            x, y = getattr(old, tag), getattr(new, tag)
            if self.links.get(x or "", x) != y:
                self.change("changed", element, tag, x, y, self.here(new.part(tag) or new.at, "link"))
        self.origin(element, "origin", old.origin, new.origin, new.part("origin") or new.at)
        if new.type not in ("fixed", "floating") or old.type not in ("fixed", "floating"):
            self.vector(element, "axis", old.axis, new.axis, new.part("axis") or new.at, "xyz")
        self.compare_limit(element, old, new)
        self.compare_parts(element, "dynamics", old.dynamics, new.dynamics, old.part("dynamics"), new)
        self.compare_parts(element, "safety_controller", old.safety, new.safety, old.part("safety_controller"), new)
        self.compare_mimic(element, old, new)

    def compare_limit(self, element: str, old: Joint, new: Joint) -> None:
        x, y = old.limit, new.limit
        if x is None and y is None:
            return
        if y is None:
            self.removed(element, "limit", [x.lower, x.upper, x.effort, x.velocity], old.part("limit"), new.at)  # type: ignore[union-attr]
            return
        if x is None:
            self.change("added", element, "limit", None, [y.lower, y.upper, y.effort, y.velocity], self.here(new.part("limit")))
            return
        for key in PARTS["limit"]:
            self.number(element, f"limit {key}", getattr(x, key), getattr(y, key), new.part("limit"), key)

    def compare_parts(self, element: str, tag: str, x, y, old_at: int | None, new: Joint) -> None:
        """A joint's ``<dynamics>`` or ``<safety_controller>``: added, removed, or each value."""
        if x is None and y is None:
            return
        if y is None:
            self.removed(element, tag, list(x), old_at, new.at)
        elif x is None:
            self.change("added", element, tag, None, list(y), self.here(new.part(tag)))
        else:
            for key, p, q in zip(PARTS[tag], x, y):
                self.number(element, f"{tag} {key}", p, q, new.part(tag), key)

    def compare_mimic(self, element: str, old: Joint, new: Joint) -> None:
        x, y = old.mimic, new.mimic
        if x is None and y is None:
            return
        if y is None:
            self.removed(element, "mimic", x.joint, old.part("mimic"), new.at)  # type: ignore[union-attr]
        elif x is None:
            self.change("added", element, "mimic", None, y.joint, self.here(new.part("mimic")))
        else:
            if self.joints.get(x.joint, x.joint) != y.joint:
                self.change("changed", element, "mimic joint", x.joint, y.joint, self.here(new.part("mimic"), "joint"))
            self.number(element, "mimic multiplier", x.multiplier, y.multiplier, new.part("mimic"), "multiplier")
            self.number(element, "mimic offset", x.offset, y.offset, new.part("mimic"), "offset")

    # -- materials ------------------------------------------------------------------------
    def compare_materials(self) -> None:
        old, new = materials_of(self.a), materials_of(self.b)
        for name, material in sorted(new.items(), key=lambda pair: pair[1].at):
            before = next((old[o] for o, n in self.materials.items() if n == name), None)
            element = element_name("material", name)
            if before is None:
                self.change("added", element, None, None, text(material.rgba) if material.rgba is not None else material.texture, self.here(material.at))
                continue
            self.vector(element, "color rgba", before.rgba, material.rgba, material.at)
            self.value(element, "texture filename", before.texture, material.texture, material.at)
        for name, material in sorted(old.items(), key=lambda pair: pair[1].at):
            if name not in self.materials:
                self.removed(element_name("material", name), None, text(material.rgba) if material.rgba is not None else material.texture, material.at, None)

    # -- gazebo, transmissions, ros2_control and other blocks -------------------------------
    def compare_blocks(self) -> None:
        old, new = self.keyed_blocks(self.a, self.renamed), self.keyed_blocks(self.b, lambda v: v)
        for key, block in new.items():
            element = block_name(key)
            if key not in old:
                self.change("added", element, None, None, key[0], self.here(self.b.place(block)))
                continue
            before = old[key]
            x, y = flatten(before, self.renamed), flatten(block, lambda v: v)
            for path, (value, holder) in x.items():
                if path not in y:
                    self.removed(element, path, value, self.a.place(holder), self.b.place(block))
            for path, (value, at_element) in y.items():
                if path not in x:
                    self.change("added", element, path, None, value, self.here(self.b.place(at_element)))
                elif not self.same_text(x[path][0], value):
                    self.change("changed", element, path, x[path][0], value, self.here(self.b.place(at_element)))
        for key, block in old.items():
            if key not in new:
                self.removed(block_name(key), None, key[0], self.a.place(block), None)

    def renamed(self, value: str) -> str:
        """A name of the old robot as the new one calls it (a link's or joint's)."""
        return self.links.get(value) or self.joints.get(value) or value

    def same_text(self, x: str | None, y: str | None) -> bool:
        """Two texts of a block: equal, the same numbers written another way, or two paths
        to one place (:func:`compare`'s ``place``)."""
        if x == y:
            return True
        if x is None or y is None:
            return False
        if os.path.isabs(x) and os.path.isabs(y) and self.place(Path(x)) == self.place(Path(y)):
            return True  # a $(find) path, in a revision's copy at one side and the working tree at the other
        p, q = numbers_in(x), numbers_in(y)
        if not p or not q or len(p) != len(q):
            return False
        return self.numbers.same(p[0], q[0]) if len(p) == 1 else self.numbers.same_vector(p, q)

    @staticmethod
    def keyed_blocks(robot: Robot, rename) -> dict[tuple[str, str, int], Element]:
        """Each top-level block by (tag, what it names, its rank among blocks naming the same)."""
        found: dict[tuple[str, str, int], Element] = {}
        counts: dict[tuple[str, str], int] = {}
        for block in robot.blocks():
            if not isinstance(block.tag, str):
                continue
            named = block.get("name") or block.get("reference") or ""
            key = (block.tag, rename(named))
            counts[key] = counts.get(key, 0) + 1
            found[(*key, counts[key])] = block
        return found


RENAMED = 1.5
ALIKE = 0.6
"""How alike an old and a new link at the same place must be to be one link renamed: in
all (:meth:`Comparer.similarity`, out of 2, or 2.5 when the joint placing them kept its
name), and in what they hold (a fraction). A renamed link whose mass and tensor changed
is (1.6 and 0.6); another link in its place, of another mass, tensor and shape, is not
(what it holds: 0.4 at most)."""


def compare(old: Loaded, new: Loaded, tolerance: float = TOLERANCE, place: Callable[[Path], Path] = lambda file: file) -> Comparison:
    """What changed from ``old`` to ``new`` (both with a robot read). ``place`` gives where a
    file stands for (a file of a revision's copy: its place in the repository), for mesh
    files named by absolute paths, which ``$(find)`` gives."""
    return Comparer(old, new, tolerance, place).run()


def totals(robot: Robot) -> Totals:
    dof = sum(DOF.get(joint.type or "", 0) for joint in robot.joints.values() if joint.mimic is None)
    mass = sum(link.inertial.mass for link in robot.links.values() if link.inertial is not None and link.inertial.mass is not None)
    return Totals(robot.name, len(robot.links), len(robot.joints), dof, mass)


def link_features(link: Link) -> tuple:
    inertial = link.inertial
    return (
        inertial.mass if inertial is not None else None,
        tuple(inertial.inertia.values()) if inertial is not None and inertial.inertia else None,
        inertial.origin.xyz if inertial is not None else None,
        tuple(geometry_text(shape.geometry) for shape in link.visuals),
        tuple(geometry_text(shape.geometry) for shape in link.collisions),
    )


def joint_features(joint: Joint) -> tuple:
    limit = joint.limit
    return (joint.type, joint.origin.xyz, joint.origin.rpy, joint.axis, (limit.lower, limit.upper, limit.effort, limit.velocity) if limit else None)


def materials_of(robot: Robot) -> dict[str, Material]:
    """The robot's materials by name: the top-level ones, and those a visual defines with a
    colour or texture (the first definition of a name, as urdfdom shares them)."""
    return once(robot, _materials_by_name)


def _materials_by_name(robot: Robot) -> dict[str, Material]:
    found = dict(robot.materials)
    for material in robot.visual_materials:
        if material.name and (material.rgba is not None or material.texture is not None):
            found.setdefault(material.name, material)
    return found


def rpy_of(r: massprops.Matrix) -> tuple[float, float, float]:
    """Roll, pitch and yaw of a rotation matrix (URDF's fixed axes: R = Rz Ry Rx)."""
    pitch = math.asin(max(-1.0, min(1.0, -r[2][0])))
    if abs(r[2][0]) < 1.0 - 1e-12:
        return (math.atan2(r[2][1], r[2][2]), pitch, math.atan2(r[1][0], r[0][0]))
    return (math.atan2(-r[1][2], r[1][1]), pitch, 0.0)  # gimbal lock: the yaw folded into the roll


def block_name(key: tuple[str, str, int]) -> str:
    """``gazebo[@reference='arm']``, ``transmission[@name='t1']``, ``gazebo[2]``: a block as its key names it."""
    tag, named, rank = key
    base = element_name(tag, named).replace("@name", "@reference") if named and tag == "gazebo" else element_name(tag, named) if named else tag
    return f"{base}[{rank}]" if rank > 1 else base


def flatten(block: Element, rename) -> dict[str, tuple[str | None, Element]]:
    """A block's elements, attributes and texts by path (``plugin[@name='x']/update_rate``,
    ``joint[@name='j']/command_interface[@name='position']``, ``sensor@type``), each with its
    value (an element's text, an attribute's value) and the element holding it; names of
    links and joints given through ``rename``, in values and paths alike."""
    found: dict[str, tuple[str | None, Element]] = {}

    def visit(element: Element, path: str, named: bool) -> None:
        for attribute, value in sorted(element.attrib.items()):
            if named and attribute in ("name", "reference"):
                continue  # in the path already
            found[f"{path}@{attribute}"] = (rename(value), element)
        counts: dict[str, int] = {}
        for child in element:
            if not isinstance(child.tag, str):
                continue  # a comment or processing instruction
            name = child.get("name")
            tag = child.tag.rpartition("}")[2]
            if name is not None:
                step = element_name(tag, rename(name))
            else:
                counts[tag] = counts.get(tag, 0) + 1
                same = sum(1 for c in element if c.tag == child.tag and c.get("name") is None)
                step = f"{tag}[{counts[tag]}]" if same > 1 else tag
            step = f"{path}/{step}" if path else step
            text = (child.text or "").strip()
            found[step] = (rename(text) if text else None, child)
            visit(child, step, name is not None)

    visit(block, "", True)
    text = (block.text or "").strip()
    if text:
        found["text"] = (text, block)
    return found


def numbers_in(value: str) -> list[float] | None:
    """The numbers a text holds (``0.1 0 0``), or None when it holds anything else."""
    try:
        return [parse_double(piece) for piece in value.split()]
    except NumberError:
        return None
