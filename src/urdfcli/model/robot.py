"""The robot model, read tolerantly: every problem becomes a diagnostic.

The reader follows urdfdom's parser element by element (which child it reads,
which attributes it requires, how it reads numbers), so that urdfcli rejects
what check_urdf rejects; where urdfdom stops, urdfcli records the problem,
leaves the field empty, and reads on.
"""

# No ``from __future__ import annotations`` here: typing.NamedTuple compiles each field's
# annotation written as a string, which cost 6 ms of every start.
import math
import re
from itertools import count
from typing import TYPE_CHECKING, NamedTuple

from ..diagnostics import Applicability, Diagnostic, Fix, SetAttribute
from ..read.document import Document, tag_name
from ..read.names import typo_of
from ..read.xml import Element, top_level
from .numbers import NumberError, VectorLengthError, format_number, parse_double, parse_doubles, parse_vector
from .vocabulary import KNOWN_CHILDREN

if TYPE_CHECKING:
    from .vocabulary import Unknown

Vec3 = tuple[float, float, float]
JOINT_PARTS = ("origin", "parent", "child", "axis", "limit", "mimic", "safety_controller", "dynamics")
JOINT_TYPES = ("fixed", "revolute", "continuous", "prismatic", "floating", "planar")
MOVING_AXIS_TYPES = ("revolute", "continuous", "prismatic", "planar")
INERTIA_KEYS = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
FULL_TURN = 2 * math.pi + 1e-3  # radians: no one writes an angle beyond it, everyone writes 90 or 180 in degrees
UNSAFE = Applicability.UNSAFE
ZERO_HINT = "a placeholder shape is better left out; give a real shape a positive size"


# Model parts are named tuples: built by the million on large models, where a
# frozen dataclass costs several times more. ``at`` is an element's index in
# document order (see document.py), which locates it.
class Pose(NamedTuple):
    xyz: Vec3 = (0.0, 0.0, 0.0)
    rpy: Vec3 = (0.0, 0.0, 0.0)


class Geometry(NamedTuple):
    kind: str  # box, cylinder, sphere, mesh
    at: int
    size: Vec3 | None = None
    radius: float | None = None
    length: float | None = None
    filename: str | None = None
    scale: Vec3 = (1.0, 1.0, 1.0)


class Shape(NamedTuple):
    """A ``<visual>`` or ``<collision>``."""

    at: int
    origin: Pose
    geometry: Geometry | None
    material: str | None = None
    colour: tuple[float, ...] | None = None  # the rgba of a material defined in the visual itself
    origin_at: int | None = None
    material_at: int | None = None


class Inertial(NamedTuple):
    at: int
    origin: Pose
    mass: float | None
    inertia: dict[str, float] | None  # ixx ixy ixz iyy iyz izz
    mass_at: int | None = None
    inertia_at: int | None = None
    origin_at: int | None = None


class Link(NamedTuple):
    name: str
    at: int
    inertial: Inertial | None
    visuals: tuple[Shape, ...]
    collisions: tuple[Shape, ...]


class Limit(NamedTuple):
    lower: float = 0.0
    upper: float = 0.0
    effort: float | None = None
    velocity: float | None = None
    has_lower: bool = False
    has_upper: bool = False


class Mimic(NamedTuple):
    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


class Safety(NamedTuple):
    """A joint's ``<safety_controller>``: its soft limits and gains (None when not given)."""

    soft_lower: float | None
    soft_upper: float | None
    k_position: float | None = None
    k_velocity: float | None = None


class Dynamics(NamedTuple):
    """A joint's ``<dynamics>`` (None when not given)."""

    damping: float | None
    friction: float | None


class Joint(NamedTuple):
    name: str
    at: int
    type: str | None
    parent: str | None
    child: str | None
    origin: Pose
    axis: Vec3
    limit: Limit | None
    mimic: Mimic | None
    parts: tuple[tuple[str, int], ...] = ()  # where its first <origin>, <parent>, <child>, <axis>, <limit>... are (JOINT_PARTS)
    safety: Safety | None = None
    dynamics: Dynamics | None = None

    def part(self, tag: str) -> int | None:
        """Where the joint's first ``<tag>`` is (None when it has none)."""
        return next((at for name, at in self.parts if name == tag), None)

    @property
    def moving(self) -> bool:
        return self.type not in (None, "fixed")


class Material(NamedTuple):
    name: str
    at: int
    rgba: tuple[float, ...] | None
    texture: str | None
    rgba_text: str | None = None  # as written


class Resource(NamedTuple):
    """A file the model names: a ``<mesh>`` or ``<texture>``."""

    at: int
    kind: str  # mesh, texture
    uri: str


class Robot:
    def __init__(self, name: str | None, at: int | None, resources: list[Resource] | None = None) -> None:
        self.name = name
        self.at = at  # None when the root element is not <robot>
        self.links: dict[str, Link] = {}
        self.joints: dict[str, Joint] = {}
        self.materials: dict[str, Material] = {}
        self.resources: list[Resource] = resources if resources is not None else []
        self.unknown: list[Unknown] = []  # read only when asked for
        self.extensions: list[Element] = []  # top-level blocks of other formats
        self.visual_materials: list[Material] = []  # the materials written inside <visual>s, in order
        self._placed: dict[Element, int] = {}
        self.derived: dict = {}  # worked out from the rest, once (see urdfcli.read.memo)

    def blocks(self, tag: str | None = None) -> "list[Element]":
        """The top-level elements other than links, joints and materials (``<gazebo>``,
        ``<transmission>``, ``<ros2_control>``...), kept whole; with ``tag``, those of that tag."""
        return [block for block in self.extensions if tag is None or block.tag == tag]

    def place(self, element: "Element") -> int | None:
        """Where an element of one of :meth:`blocks` is."""
        return self._placed.get(element)


class Reader:
    """Builds a Robot from a Document, collecting diagnostics. Each element written
    at the top level is read whole, in document order, and no tree is kept once the
    robot is read (a large document is streamed: see read.xml.top_level)."""

    def __init__(self, document: Document, vocabulary: bool = False):
        self.document = document
        self.vocabulary = vocabulary  # classify markup against URDF's vocabulary too
        self.diagnostics: list[Diagnostic] = []
        self.resources: list[Resource] = []
        self._index: dict[Element, int] = {}  # the elements being read -> their index
        # Values read from texts seen before in this document: models repeat a few texts
        # over and over. Only texts read without a diagnostic are kept, and values are
        # never changed (an inertia dict is shared by the links that write the same text).
        self._numbers: dict[str, float] = {}
        self._vectors: dict[str, Vec3] = {}
        self._poses: dict[tuple[str | None, str | None], Pose] = {}
        self._tensors: dict[tuple[str | None, ...], dict[str, float]] = {}
        self._limits: dict[tuple[str | None, ...], Limit] = {}
        self._misplaced_colours: set[int] = set()  # materials whose colour is written on <material> (M005)

    def at(self, element: "Element | None") -> int | None:
        return self._index[element] if element is not None else None

    # -- reporting -------------------------------------------------------------
    def report(
        self, code: str, message: str, element: "Element | None", hint: str | None = None, attribute: str | None = None, fix: Fix | None = None,
        subjects: tuple[str, ...] = (),
    ) -> None:
        """``subjects``: the joint the message names (copies of one macro line, one per call, are then said once)."""
        self.diagnostics.append(self.document.diagnostic(code, message, self.at(element), hint, attribute, subjects).with_fix(fix))

    # -- values ----------------------------------------------------------------
    def number(self, element: "Element", attribute: str, required: bool = False, joint: str | None = None) -> float | None:
        """The attribute's value; ``joint``: the name of the joint it belongs to, said in a report."""
        text = element.get(attribute)
        value = self._numbers.get(text)
        if value is not None:
            return value
        what, subjects = (f" (joint '{joint}')", (joint,)) if joint is not None else ("", ())
        if text is None:
            if required:
                self.report("V004", f"<{tag_name(element)}> has no '{attribute}' attribute{what}", element, subjects=subjects)
            return None
        try:
            value = parse_double(text)
        except NumberError as error:
            self.report(error.code, f"{tag_name(element)} {attribute}: {error.reason}{what}", element, attribute=attribute, subjects=subjects)
            return None
        self._numbers[text] = value
        return value

    def vector(self, element: "Element", attribute: str, default: Vec3 | None = None) -> Vec3 | None:
        text = element.get(attribute)
        if text is None:
            return default
        known = self._vectors.get(text)
        if known is not None:
            return known
        try:
            value = self._vectors[text] = parse_vector(text)  # type: ignore[assignment]
            return value  # type: ignore[return-value]
        except NumberError as error:
            self.report(error.code, f"{tag_name(element)} {attribute}: component {error.reason}", element, attribute=attribute)
        except VectorLengthError as error:
            hint = "components are separated by single spaces" if ("\t" in text or "\n" in text or "," in text) else None
            self.report("V003", f"{tag_name(element)} {attribute}: {error.reason}", element, hint, attribute)
        return None

    def pose(self, origin: "Element | None") -> Pose:
        if origin is None:
            return IDENTITY
        key = (origin.get("xyz"), origin.get("rpy"))
        pose = self._poses.get(key)
        if pose is None:
            reported = len(self.diagnostics)
            pose = Pose(self.vector(origin, "xyz", (0.0, 0.0, 0.0)) or (0.0, 0.0, 0.0), self.vector(origin, "rpy", (0.0, 0.0, 0.0)) or (0.0, 0.0, 0.0))
            self.radians(origin, pose.rpy)
            if len(self.diagnostics) == reported:
                self._poses[key] = pose
        return pose

    def radians(self, origin: "Element", rpy: Vec3) -> None:
        """V009: an angle beyond a full turn is written in degrees (``rpy="0 0 90"``)."""
        if all(abs(angle) <= FULL_TURN for angle in rpy):
            return
        radians = " ".join(format_number(round(math.radians(a), 6)) if abs(a) > FULL_TURN else format_number(a) for a in rpy)
        written = origin.get("rpy")
        angles = iter(rpy)
        # each angle beyond a turn converted, the others and the spaces kept as written
        radians_written = re.sub(r"\S+", lambda part: format_number(round(math.radians(a), 6)) if abs(a := next(angles, 0.0)) > FULL_TURN else part.group(), written)
        fix = Fix(f'write rpy="{radians}" (radians)', UNSAFE, changes=(SetAttribute(self._index[origin], "rpy", radians_written),))
        self.report(
            "V009", f"origin rpy '{written}' has an angle beyond a full turn: degrees, where URDF takes radians",
            origin, f'in radians: rpy="{radians}"', "rpy", fix,
        )

    def positive(self, element: "Element", attribute: str, value: float | None) -> None:
        """A negative dimension is an error (V006); zero is a warning (V008): ROS loads it, physics engines do not."""
        if value is not None and value < 0:
            self.report("V006", f"{tag_name(element)} {attribute} is {format_number(value)}; it must be positive", element, attribute=attribute)
        elif value == 0:
            self.report("V008", f"{tag_name(element)} {attribute} is 0: the shape has no volume", element, ZERO_HINT, attribute)

    # -- elements --------------------------------------------------------------
    def rgba(self, material: "Element", color: "Element") -> tuple[float, ...] | None:
        text = color.get("rgba")
        name = material.get("name", "")
        values = []
        for piece in (p for p in text.split(" ") if p):
            try:
                value = parse_double(piece)
            except NumberError as error:
                self.report(error.code, f"material '{name}' rgba: component {error.reason}", color, attribute="rgba")
                return None
            if not 0.0 <= value <= 1.0:
                self.report("V007", f"material '{name}' rgba component {piece} is outside [0, 1]", color, attribute="rgba")
                return None
            values.append(value)
        if len(values) != 4:
            self.report("M004", f"material '{name}' rgba '{text}' has {len(values)} components, 4 expected", color)
        return tuple(values)

    def material(self, element: "Element", top_level: bool) -> Material | None:
        name = element.get("name")
        if name is None:
            self.report("N003", "<material> has no 'name' attribute", element)
            return None
        found = first_children(element)
        texture = found.get("texture")
        texture_file = texture.get("filename") if texture is not None else None
        if texture_file:
            self.resources.append(Resource(self._index[texture], "texture", texture_file))
        color = found.get("color")
        rgba = self.rgba(element, color) if color is not None and color.get("rgba") is not None else None
        misplaced = element.get("rgba")  # a colour every parser ignores: it belongs in a <color> child
        moved = f'write it in a <color> child: <material name="{name}"><color rgba="{misplaced}"/></material>' if misplaced is not None else None
        unreadable = rgba is None and color is not None and color.get("rgba") is not None  # V007 or a number error said why
        if top_level and rgba is None and texture_file is None and not unreadable:
            hint = "did you mean rgba=?" if color is not None and color.get("rgb") is not None else moved
            self.report("M001", f"material '{name}' has neither <color rgba> nor <texture filename>", element, hint)
        elif misplaced is not None and color is None:
            self.report("M005", f"material '{name}' has rgba=\"{misplaced}\" on the <material> element, where every parser ignores it", element, moved, "rgba")
            self._misplaced_colours.add(self.at(element))
        return Material(name, self.at(element), rgba, texture_file, color.get("rgba") if color is not None else None)

    def geometry(self, parent: "Element", element: "Element | None") -> Geometry | None:
        if element is None:
            self.report("V005", f"<{tag_name(parent)}> has no <geometry>", parent, _lost_to_a_copy(parent, "geometry", self.document.is_xacro))
            return None
        shapes = element[:]  # comments are not read
        if not shapes:
            self.report("G001", "<geometry> holds no shape (box, cylinder, sphere or mesh)", element)
            return None
        shape = shapes[0]
        if len(shapes) > 1:
            self.report("G003", f"<geometry> holds {len(shapes)} shapes; only the first, <{tag_name(shape)}>, is used", shapes[1])
        kind = tag_name(shape)
        if kind == "sphere":
            radius = self.number(shape, "radius", required=True)
            self.positive(shape, "radius", radius)
            return Geometry(kind, self.at(shape), radius=radius) if radius is not None else None
        if kind == "box":
            text = shape.get("size")
            if text is None:
                self.report("V004", "<box> has no 'size' attribute", shape)
                return None
            size = self.vector(shape, "size")
            if size is None:
                return None
            smallest = min(size)
            if smallest < 0:
                self.report("V006", f"box size '{text}' has a negative component", shape, attribute="size")
            elif smallest == 0:
                self.report("V008", f"box size '{text}' has a zero component: the box has no volume", shape, ZERO_HINT, "size")
            return Geometry(kind, self._index[shape], size)
        if kind == "cylinder":
            if shape.get("radius") is None or shape.get("length") is None:
                missing = " and ".join(a for a in ("radius", "length") if shape.get(a) is None)
                self.report("V004", f"<cylinder> has no '{missing}' attribute", shape)
                return None
            length = self.number(shape, "length")
            radius = self.number(shape, "radius")
            self.positive(shape, "length", length)
            self.positive(shape, "radius", radius)
            return Geometry(kind, self.at(shape), radius=radius, length=length) if None not in (length, radius) else None
        if kind == "mesh":
            filename = shape.get("filename")
            if filename is None:
                self.report("V004", "<mesh> has no 'filename' attribute", shape)
                return None
            scale = self.vector(shape, "scale", (1.0, 1.0, 1.0))
            if scale is not None and 0.0 in scale:  # a negative one mirrors the mesh (TALOS's arms): that is meant
                self.report("V008", f"mesh scale '{shape.get('scale')}' has a zero component: the mesh has no volume", shape,
                            "MuJoCo and Drake refuse the model; give each axis its scale (1 1 1 for a mesh in metres)", "scale")
            if filename:
                self.resources.append(Resource(self._index[shape], "mesh", filename))
            return Geometry(kind, self.at(shape), filename=filename, scale=scale) if scale is not None else None
        self.report("G002", f"unknown shape <{kind}> in <geometry>", shape, "URDF shapes are box, cylinder, sphere and mesh")
        return None

    def first_children(self, element: "Element", repeated: tuple[str, ...]) -> "dict[str, Element]":
        """The first child of each tag (see :func:`first_children`), and G004 for a second
        child of one of ``repeated``, which every parser leaves unread: one pass over the children."""
        found: dict[str, Element] = {}
        for child in element[:]:  # (see first_children)
            tag = child.tag
            if tag not in found:
                found[tag] = child
            elif tag in repeated:
                self.report("G004", f"<{tag_name(element)}> holds a second <{tag}>; only the first is used", child)
        return found

    def shape(self, element: "Element", visual: bool) -> Shape:
        found = self.first_children(element, ("origin", "geometry", "material") if visual else ("origin", "geometry"))
        origin = self.pose(found.get("origin"))
        geometry = self.geometry(element, found.get("geometry"))
        material_name = colour = material_at = None
        if visual:
            material = found.get("material")
            if material is not None:
                parsed = self.material(material, top_level=False)
                if parsed is not None:
                    material_name, colour, material_at = parsed.name, parsed.rgba, parsed.at
                    self._inline_materials.append(parsed)
        return Shape(self._index[element], origin, geometry, material_name, colour, self.at(found.get("origin")), material_at)

    def inertial(self, element: "Element") -> Inertial:
        found = self.first_children(element, ("origin", "mass", "inertia"))
        origin = self.pose(found.get("origin"))
        mass_element = found.get("mass")
        mass = None
        if mass_element is None:
            self.report("V005", "<inertial> has no <mass>", element, _lost_to_a_copy(element, "mass", self.document.is_xacro))
        else:
            mass = self.number(mass_element, "value", required=True)
        inertia_element = found.get("inertia")
        inertia = None
        if inertia_element is None:
            self.report("V005", "<inertial> has no <inertia>", element, _lost_to_a_copy(element, "inertia", self.document.is_xacro))
        else:
            texts = tuple(map(inertia_element.get, INERTIA_KEYS))
            inertia = self._tensors.get(texts)
            if inertia is None:
                plain = parse_doubles(texts)  # the common case: six plain numbers, read in one step
                if plain is not None:
                    inertia = self._tensors[texts] = dict(zip(INERTIA_KEYS, plain))
                else:  # each value read on its own, for its diagnostic
                    values = {key: self.number(inertia_element, key, required=True) for key in INERTIA_KEYS}
                    if None not in values.values():
                        inertia = self._tensors[texts] = values
        return Inertial(self._index[element], origin, mass, inertia, self.at(mass_element), self.at(inertia_element), self.at(found.get("origin")))  # type: ignore[arg-type]

    def link(self, element: "Element") -> Link:
        name = element.get("name")
        if name is None:
            self.report("N001", "<link> has no 'name' attribute", element)
            name = ""
        inertial = None
        visuals: list[Shape] = []
        collisions: list[Shape] = []
        for child in element[:]:  # one pass, in the order written (see first_children)
            tag = child.tag
            if tag == "visual":
                visuals.append(self.shape(child, visual=True))
            elif tag == "collision":
                collisions.append(self.shape(child, visual=False))
            elif tag == "inertial" and inertial is None:  # the first, as urdfdom reads it
                inertial = self.inertial(child)
        return Link(name, self._index[element], inertial, tuple(visuals), tuple(collisions))

    def joint_limit(self, joint_name: str | None, element: "Element") -> Limit:
        key = (element.get("lower"), element.get("upper"), element.get("effort"), element.get("velocity"))
        limit = self._limits.get(key)
        if limit is not None:
            return limit
        reported = len(self.diagnostics)
        lower = self.number(element, "lower", joint=joint_name)
        upper = self.number(element, "upper", joint=joint_name)
        effort = self.number(element, "effort", required=True, joint=joint_name)
        velocity = self.number(element, "velocity", required=True, joint=joint_name)
        limit = Limit(
            lower if lower is not None else 0.0,
            upper if upper is not None else 0.0,
            effort,
            velocity,
            key[0] is not None,
            key[1] is not None,
        )
        if len(self.diagnostics) == reported:
            self._limits[key] = limit
        return limit

    def joint(self, element: "Element") -> Joint:
        name = element.get("name")
        if name is None:
            self.report("N002", "<joint> has no 'name' attribute", element)
        shown = name if name is not None else "?"
        subjects = (name,) if name is not None else ()
        joint_type = element.get("type")
        if joint_type is None:
            self.report("J001", f"joint '{shown}' has no 'type' attribute", element, f"the types are {', '.join(JOINT_TYPES)}", subjects=subjects)
        elif joint_type not in JOINT_TYPES:
            self.report("J002", f"joint '{shown}' has unknown type '{joint_type}'", element, f"the types are {', '.join(JOINT_TYPES)}", subjects=subjects)
            joint_type = None
        found = first_children(element)
        origin = self.pose(found.get("origin"))
        axis: Vec3 = (1.0, 0.0, 0.0)
        axis_element = found.get("axis")
        if axis_element is not None and joint_type not in ("fixed", "floating"):
            axis = self.vector(axis_element, "xyz", (1.0, 0.0, 0.0)) or axis
        limit_element = found.get("limit")
        limit = self.joint_limit(name, limit_element) if limit_element is not None else None
        if limit_element is None and joint_type in ("revolute", "prismatic"):
            hint = _lost_to_a_copy(element, "limit", self.document.is_xacro) or 'add <limit lower="..." upper="..." effort="..." velocity="..."/>'
            self.report("J003", f"{joint_type} joint '{shown}' has no <limit>", element, hint, subjects=subjects)
        safety = None
        safety_element = found.get("safety_controller")
        if safety_element is not None:
            safety = Safety(
                self.number(safety_element, "soft_lower_limit", joint=name), self.number(safety_element, "soft_upper_limit", joint=name),
                self.number(safety_element, "k_position", joint=name), self.number(safety_element, "k_velocity", required=True, joint=name),
            )
        calibration = found.get("calibration")
        if calibration is not None:
            for attribute in ("reference_position", "rising", "falling"):
                self.number(calibration, attribute, joint=name)
        mimic = None
        mimic_element = found.get("mimic")
        if mimic_element is not None:
            multiplier = self.number(mimic_element, "multiplier", joint=name)
            offset = self.number(mimic_element, "offset", joint=name)
            target = mimic_element.get("joint")
            if target is None:
                self.report("V004", f"<mimic> of joint '{shown}' has no 'joint' attribute", mimic_element, subjects=subjects)
            else:
                mimic = Mimic(target, 1.0 if multiplier is None else multiplier, offset or 0.0)
        dynamics = None
        dynamics_element = found.get("dynamics")
        if dynamics_element is not None:
            if dynamics_element.get("damping") is None and dynamics_element.get("friction") is None:
                self.report("J006", f"<dynamics> of joint '{shown}' has neither damping nor friction", dynamics_element, subjects=subjects)
            values = []
            for attribute in ("damping", "friction"):
                value = self.number(dynamics_element, attribute, joint=name)
                values.append(value)
                if value is not None and value < 0:
                    self.report("V010", f"joint '{shown}' has {attribute} {format_number(value)}; it must not be negative", dynamics_element,
                                f"a {attribute} coefficient is 0 or more", attribute, subjects=subjects)
            dynamics = Dynamics(*values)
        parent = self._link_ref(found.get("parent"))
        child = self._link_ref(found.get("child"))
        if parent is None or child is None:
            missing = " and ".join(t for t, v in (("<parent link>", parent), ("<child link>", child)) if v is None)
            self.report("J004", f"joint '{shown}' has no {missing}", element, subjects=subjects)
        parts = tuple([(tag, self._index[found[tag]]) for tag in JOINT_PARTS if tag in found])
        return Joint(name if name is not None else "", self._index[element], joint_type, parent, child, origin, axis, limit, mimic, parts, safety, dynamics)

    @staticmethod
    def _link_ref(element: "Element | None") -> str | None:
        value = element.get("link") if element is not None else None
        return value or None  # urdfdom treats an empty name as missing

    # -- robot -----------------------------------------------------------------
    def robot(self) -> Robot:
        """The robot, read from the document's elements as they come; raises
        XmlError when the document turns out not to be well-formed."""
        stream = top_level(self.document.data, self.document.tree)
        self.document.tree = None  # its elements are taken out as they are read
        root = next(stream)
        self._index = {root: 0}
        self._inline_materials: list[Material] = []
        if tag_name(root) != "robot":
            self.report("R001", f"the root element is <{tag_name(root)}>, not <robot>", root)
            for _ in stream:  # the rest must still be well-formed
                pass
            return Robot(None, None)
        name = root.get("name")
        if name is None:
            self.report("R002", "<robot> has no 'name' attribute", root)
        self.version(root)
        robot = Robot(name, 0, resources=self.resources)
        if self.vocabulary:
            from . import vocabulary  # only lint's rules read what it finds

            robot.unknown.extend(vocabulary.unknown_attributes(root, 0))
        numbers = count(1)
        tops = self.document.tops
        for element in stream:
            self._index = index = dict(zip(element.iter(), numbers))
            tops.append(index[element])
            index[root] = 0
            self.top_level(robot, element)
            if self.vocabulary:
                robot.unknown.extend(vocabulary.unknown_markup(element, index))
        if not robot.links:
            self.report("R004", "the robot has no <link>", root)
        robot.visual_materials = self._inline_materials
        self.check_materials(robot)
        return robot

    def top_level(self, robot: Robot, element: "Element") -> None:
        """Read one element written directly in ``<robot>``."""
        tag = element.tag
        if tag == "link":
            link = self.link(element)
            if link.name in robot.links:
                self.report("N004", f"link '{link.name}' is defined twice", element, _twice(self.document, robot.links[link.name].at, self._index[element]))
            else:
                robot.links[link.name] = link
        elif tag == "joint":
            joint = self.joint(element)
            if element.get("name") is None:
                return
            if joint.name in robot.joints:
                self.report("N005", f"joint '{joint.name}' is defined twice", element, _twice(self.document, robot.joints[joint.name].at, self._index[element]))
            else:
                robot.joints[joint.name] = joint
        elif tag == "material":
            material = self.material(element, top_level=True)
            if material is None:
                return
            if material.name in robot.materials:
                self.report("N006", f"material '{material.name}' is defined twice", element, _twice(self.document, robot.materials[material.name].at, self._index[element]))
            else:
                robot.materials[material.name] = material
        else:
            robot.extensions.append(element)
            robot._placed.update(self._index)
            found = element.iter("mesh", "texture")  # (in document order, told apart by lxml)
            self.resources.extend(Resource(self._index[e], e.tag, uri) for e in found if (uri := e.get("filename")))

    def version(self, root: "Element") -> None:
        version = root.get("version")
        if version is None:
            return
        parts = version.split(".")
        if len(parts) != 2 or not all(p.isdigit() for p in parts):
            self.report("R003", f"robot version '{version}' is not of the form 'x.y'", root)
        elif (int(parts[0]), int(parts[1])) != (1, 0):
            self.report("R003", f"robot version '{version}' is not supported; only 1.0 is", root)

    def check_materials(self, robot: Robot) -> None:
        """M002 and M003 as urdfdom shares materials: by name, the first definition
        winning. A visual material with an empty name is never shared (urdfdom skips
        it), so it can neither be undefined nor clash."""
        seen: dict[str, Material] = {m.name: m for m in robot.materials.values() if m.rgba is not None and len(m.rgba) == 4}
        for material in self._inline_materials:
            if not material.name:
                continue
            if material.rgba is not None and len(material.rgba) != 4:
                continue  # urdfdom cannot read that colour (M004) and takes the name's other definition: no clash
            if material.rgba is None and material.texture is None:
                # a colour written but unreadable (V007), or written on <material> (M005): one mistake, said once
                unread = material.rgba_text is not None or material.at in self._misplaced_colours
                if material.name not in robot.materials and material.name not in seen and not unread:
                    self.diagnostics.append(self.document.diagnostic("M002", f"material '{material.name}' is defined nowhere", material.at, "define it at the top level, or give it a <color rgba>"))
                continue
            first = seen.setdefault(material.name, material)
            if first.rgba is not None and material.rgba is not None and not same_colour(first.rgba, material.rgba):
                self.diagnostics.append(self.document.diagnostic(
                    "M003",
                    f"material '{material.name}' has rgba '{material.rgba_text}' here but '{first.rgba_text}' at {_where(self.document, first.at)}",
                    material.at,
                    "consumers keep one colour per name: give each colour its own name",
                ))


# Components closer than a tenth look alike in a viewer: 0.75294 is 192/255 rounded, and
# an alpha of 0.9 against 1 is not a second colour; 0.5 against 0.8 is.
COLOUR_TOLERANCE = 0.1 + 1e-9


def same_colour(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return len(a) == len(b) and all(abs(x - y) <= COLOUR_TOLERANCE for x, y in zip(a, b))


IDENTITY = Pose()


def _lost_to_a_copy(element: "Element", missing: str, expanded: bool) -> str | None:
    """Why ``element`` lacks its <``missing``>: a misspelt <``missing``>, or, in a model
    xacro ``expanded``, an <insert_block> or a macro call written without the xacro: prefix,
    which xacro copies as written instead of inserting what the caller gave (an origin lost
    so is silently zero). None when it holds no such element."""
    known = KNOWN_CHILDREN.get(tag_name(element), frozenset())
    unknown = [child for child in element[:] if isinstance(child.tag, str) and child.tag not in known]
    blocks = [f'<insert_block name="{child.get("name", "")}"/>' for child in unknown if child.tag == "insert_block"]
    if blocks and expanded:
        return f"xacro copied its {', '.join(blocks)} as written (without the xacro: prefix) instead of inserting the blocks; write <xacro:insert_block>"
    for child in unknown:
        if typo_of(child.tag, (missing,)):
            return f"did you mean <{missing}>? it holds <{child.tag}>"
    calls = [child.tag for child in unknown if not child.tag.startswith("{")]
    if calls and expanded:
        return (f"it holds <{calls[0]}>, which URDF does not read: a xacro macro called without the xacro: prefix is copied as "
                f"written; write <xacro:{calls[0]} .../>")
    return None

def first_children(element: "Element") -> "dict[str, Element]":
    """The first child of each tag, as ``element.find(tag)`` gives it, in one pass
    over the children (a model has millions of these lookups)."""
    found: dict[str, Element] = {}
    for child in element[:]:  # (a slice: lxml makes it in one step, faster than it iterates)
        found.setdefault(child.tag, child)
    return found


def _where(document: Document, at: int) -> str:
    """Where an element was written, and the macro call that made it."""
    location = document.locate(at)
    called = f" ({location.trace[0].phrase})" if location.trace else ""
    return f"{location.file}:{location.line}{called}"


def _twice(document: Document, first: int, again: int) -> str:
    """The hint of a name defined twice: where first, and the way out."""
    location, repeated = document.locate(first), document.locate(again)
    same_place = (location.file, location.line) == (repeated.file, repeated.line)
    if same_place and location.trace and repeated.trace:
        fix = "give the macro a prefix parameter and put it in the names it makes"
    elif same_place and location.file != document.shown:
        fix = f"{location.file} is included twice: include it once"
    elif location.file != repeated.file and document.shown not in (location.file, repeated.file) and not location.trace and not repeated.trace:
        # two included files that write the same part (a camera and a depth camera): usually alternatives
        fix = f"{repeated.file} defines it again: include only one of {location.file} and {repeated.file}, or rename one of them"
    else:
        fix = "rename one of them"
    return f"first defined at {_where(document, first)}; {fix}"


def read(document: Document, vocabulary: bool = False) -> tuple[Robot, list[Diagnostic]]:
    """The robot and what reading it found; with ``vocabulary``, markup URDF does not
    define is classified too (``Robot.unknown``). Raises XmlError."""
    reader = Reader(document, vocabulary)
    robot = reader.robot()
    return robot, reader.diagnostics
