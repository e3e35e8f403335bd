"""The URDF vocabulary, and the markup outside it, found while the model is read.

Which elements and attributes URDF and the documented extensions define where,
and the classification of everything else (a typo, Gazebo markup out of its
block, or unknown markup) that the description rules D001, D002, D010 and D011
report.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from typing import TYPE_CHECKING, NamedTuple

from ..read.document import tag_name
from ..read.names import typo_of
from .numbers import parse_double

if TYPE_CHECKING:
    from ..read.xml import Element

# What the URDF format allows: element -> (attributes, child elements). Elements
# whose contents belong to another format (gazebo, transmission, ros2_control)
# are not looked into; <geometry> shapes are G002's business. Newer urdfdom
# releases read `quat_xyzw` (URDF 1.1) and acceleration limits (URDF 1.2).
ORIGIN = ({"xyz", "rpy", "quat_xyzw"}, set())
SCHEMA: dict[str, tuple[set[str], set[str]]] = {
    "robot": ({"name", "version"}, {"link", "joint", "material", "transmission", "gazebo", "ros2_control"}),
    "link": ({"name", "type"}, {"inertial", "visual", "collision"}),
    "inertial": (set(), {"origin", "mass", "inertia"}),
    "origin": ORIGIN,
    "mass": ({"value"}, set()),
    "inertia": ({"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}, set()),
    "visual": ({"name"}, {"origin", "geometry", "material"}),
    "collision": ({"name"}, {"origin", "geometry"}),
    "geometry": (set(), None),  # shapes: checked by G001/G002
    "box": ({"size"}, set()),
    "cylinder": ({"radius", "length"}, set()),
    "sphere": ({"radius"}, set()),
    "mesh": ({"filename", "scale"}, set()),
    "material": ({"name"}, {"color", "texture"}),
    "color": ({"rgba"}, set()),
    "texture": ({"filename"}, set()),
    "joint": ({"name", "type"}, {"origin", "parent", "child", "axis", "calibration", "dynamics", "limit", "mimic", "safety_controller"}),
    "parent": ({"link"}, set()),
    "child": ({"link"}, set()),
    "axis": ({"xyz"}, set()),
    "calibration": ({"rising", "falling", "reference_position"}, set()),
    "dynamics": ({"damping", "friction"}, set()),
    "limit": ({"lower", "upper", "effort", "velocity", "acceleration", "deceleration", "jerk"}, set()),
    "mimic": ({"joint", "multiplier", "offset"}, set()),
    "safety_controller": ({"soft_lower_limit", "soft_upper_limit", "k_position", "k_velocity"}, set()),
}
OPAQUE = {"gazebo", "transmission", "ros2_control"}
# Elements a URDF holds more than once: a typo of one is a typo even when another is there.
REPEATED = {"link", "joint", "material", "transmission", "gazebo", "ros2_control", "visual", "collision"}

# Documented extensions other consumers read: never typos, never reported.
# element -> (attributes, child elements), each with who reads it.
EXTENSIONS: dict[str, tuple[dict[str, str], dict[str, str]]] = {
    "robot": ({}, {
        "sensor": "urdfdom's and iDynTree's sensor extension",
        "mujoco": "MuJoCo's compiler options",
        "deformable": "PyBullet's soft bodies",
        "klampt": "Klampt's robot settings",
    }),
    "link": ({}, {
        "contact": "PyBullet's contact parameters",
        "audio_source": "PyBullet's audio source",
    }),
    "collision": ({"group": "PyBullet's collision filter", "mask": "PyBullet's collision filter", "concave": "PyBullet's concave meshes"}, {
        "material": "exporters that write one material for visual and collision; harmless",
        "contact_coefficients": "the ROS URDF tutorial's contact coefficients (mu, kp, kd)",
    }),
    "material": ({}, {"specular": "PyBullet's specular colour"}),
    "joint": ({"dont_collapse": "Isaac Sim's URDF importer (keeps a fixed joint)"}, {}),
    "dynamics": ({"K": "Franka's joint friction model", "D": "Franka's joint friction model",
                  "mu_coulomb": "Franka's joint friction model", "mu_viscous": "Franka's joint friction model"}, {}),
    "limit": ({"command_effort": "ANYmal's actuator limits", "current": "ANYmal's actuator limits",
               "gear_velocity": "ANYmal's actuator limits"}, {}),
}

# The children ros2_control's parser reads in each component of a <ros2_control> block
# (hardware_interface's component_parser): it looks them up by name and skips the rest,
# so a misspelt <command_interface> leaves the joint without it. Only typos of these are said.
ROS2_CONTROL_CHILDREN = {
    "hardware": frozenset({"plugin", "param"}),
    "joint": frozenset({"command_interface", "state_interface", "param"}),
    "sensor": frozenset({"state_interface", "param"}),
    "gpio": frozenset({"command_interface", "state_interface", "param"}),
}

# Gazebo's URDF extension keys and the SDFormat elements Gazebo reads in a
# <gazebo reference> block (sdformat's URDF to SDF conversion): written anywhere
# else, Gazebo never sees them.
GAZEBO_TAGS = {
    "gazebo", "plugin", "static", "turnGravityOff", "dampingFactor", "maxVel", "minDepth", "mu1", "mu2", "fdir1",
    "kp", "kd", "selfCollide", "maxContacts", "laserRetro", "springReference", "springStiffness", "stopCfm",
    "stopErp", "fudgeFactor", "provideFeedback", "canonicalBody", "cfmDamping", "implicitSpringDamper",
    "disableFixedJointLumping", "preserveFixedJoint",
    "gravity", "kinematic", "self_collide", "enable_wind", "velocity_decay", "must_be_base_link", "sensor",
    "surface", "laser_retro", "max_contacts", "cast_shadows", "transparency", "physics",
}

# What each element may carry: URDF's own names and the documented extensions', computed once.
KNOWN_ATTRIBUTES = {tag: frozenset(attributes | set(EXTENSIONS.get(tag, ({}, {}))[0])) for tag, (attributes, _) in SCHEMA.items()}
KNOWN_CHILDREN = {tag: frozenset(children | set(EXTENSIONS.get(tag, ({}, {}))[1])) for tag, (_, children) in SCHEMA.items() if children is not None}
# The children read as URDF (walked into): those of the schema, other formats' blocks aside.
WALKED = {tag: frozenset(c for c in children if c in SCHEMA and c not in OPAQUE) for tag, children in KNOWN_CHILDREN.items()}


class Unknown(NamedTuple):
    """Markup that neither URDF nor a known extension defines where it is written."""

    at: int  # the unknown child, or the element carrying the unknown attribute
    parent: str  # the tag of the element it is written in (or on)
    name: str
    attribute: bool
    typo_of: str | None = None  # a name missing there that it is one or two edits from
    gazebo: bool = False  # Gazebo markup outside <gazebo>
    holder: int = 0  # the element it is written in
    owner: str | None = None  # the link or joint it is written in, if any
    format: str = "URDF"  # the format whose element it is written in


def is_foreign(name: str) -> bool:
    """Namespaced names (``xacro:``, ``drake:``, ``{uri}``) belong to other formats."""
    return ":" in name or name.startswith("{")


def _gazebo_material(element) -> bool:
    """Gazebo's ``<material>Gazebo/Grey</material>``: a script name as text, no name attribute."""
    return tag_name(element) == "material" and element.get("name") is None and bool((element.text or "").strip())


def unknown_attributes(element: Element, at: int, tag: str | None = None) -> Iterator[Unknown]:
    """The attributes of ``element`` (at ``at``, of ``tag``) that its tag does not take."""
    tag = tag or tag_name(element)
    known = KNOWN_ATTRIBUTES[tag]
    names = element.keys()
    if known.issuperset(names):
        return  # the common case, decided in one step
    for name in names:
        if name not in known and not is_foreign(name):
            meant = typo_of(name, known - set(names)) or (mistyped_moment(name, element.get) if tag == "inertia" else None)
            yield Unknown(at, tag, name, True, meant)


LOWER_TRIANGLE = {"iyx": "ixy", "izx": "ixz", "izy": "iyz"}  # not URDF; the upper triangle's name for each
SAME_PRODUCT = 1e-3  # a lower-triangle value this close (relative to the tensor's largest) to its counterpart repeats it


def mistyped_moment(name: str, value: Callable[[str], str | None]) -> str | None:
    """For an ``<inertia>`` attribute ``name`` of the lower triangle (``iyx``, ``izx``, ``izy``)
    whose value differs from its upper-triangle counterpart's (``ixy``...): the diagonal
    moment of its row (``iyy``, ``izz``), one letter away, that it was typed for (Fetch's
    fingers: ``iyx="0.002"`` beside ``ixy="0"`` and ``iyy="0"``). None when it repeats the
    counterpart (a CAD exporter writing the whole matrix), or the counterpart is not written.
    ``value`` gives an attribute's text."""
    counterpart = LOWER_TRIANGLE.get(name)
    written, other = value(name), value(counterpart) if counterpart else None
    if counterpart is None or written is None or other is None:
        return None
    try:
        numbers = [parse_double(text) for key in (*SCHEMA["inertia"][0], *LOWER_TRIANGLE) if (text := value(key)) is not None]
        apart = abs(parse_double(written) - parse_double(other)) > SAME_PRODUCT * max(abs(n) for n in numbers)
    except ValueError:  # not numbers (V001 says so for the upper triangle): as texts
        apart = written.strip() != other.strip()
    return f"i{name[1]}{name[1]}" if apart else None


def unknown_markup(top: Element, positions: Mapping[Element, int]) -> list[Unknown]:
    """What is unknown in one element written at the top level of ``<robot>``, in
    document order: the element itself as a child of ``<robot>``, and inside it the
    URDF elements (not other formats' blocks). ``positions`` holds each element of
    ``top``, in document order, with its index (other elements may follow)."""
    index = positions.__getitem__
    name = tag_name(top)
    if name not in KNOWN_CHILDREN["robot"]:
        if not is_foreign(name):
            gazebo = name in GAZEBO_TAGS or _gazebo_material(top)
            return [Unknown(index(top), "robot", name, False, None if gazebo else typo_of(name, KNOWN_CHILDREN["robot"]), gazebo)]
        return []
    if name == "ros2_control":
        return _ros2_control_typos(top, index)
    if name not in SCHEMA or name in OPAQUE:
        return []
    owner = top.get("name") if name in ("link", "joint") else None
    found: list[Unknown] = []
    walked: dict[Element, str] = {}  # the elements whose children are examined -> their tag
    # One pass over the elements as the reader numbered them (a parent comes before its
    # children), not a walk down the tree: lxml hands out children slowly.
    for element in positions:
        parent = element.getparent()
        tag = "robot" if element is top else walked.get(parent)
        if tag is None:
            continue  # inside an element not walked into, or not in top at all
        name = element.tag
        if "{" in name:
            name = tag_name(element)
        if name in WALKED[tag]:
            if not KNOWN_ATTRIBUTES[name].issuperset(element.keys()):  # most elements: decided here
                found.extend(unknown_attributes(element, index(element), name))
            if name in KNOWN_CHILDREN:
                walked[element] = name
        elif name not in KNOWN_CHILDREN[tag] and not is_foreign(name):
            if name in GAZEBO_TAGS or _gazebo_material(element):
                found.append(Unknown(index(element), tag, name, False, gazebo=True, holder=index(parent), owner=owner))
            else:
                present = {tag_name(c) for c in parent}
                missing = {c for c in KNOWN_CHILDREN[tag] if c in REPEATED or c not in present}
                found.append(Unknown(index(element), tag, name, False, typo_of(name, missing), holder=index(parent), owner=owner))
    return found


def _ros2_control_typos(top: Element, index: Callable[[Element], int]) -> list[Unknown]:
    """The children of a <ros2_control> block's components that are one or two letters
    from a name ros2_control reads there (``<comand_interface>``)."""
    found = []
    for component in top:
        known = ROS2_CONTROL_CHILDREN.get(component.tag) if isinstance(component.tag, str) else None
        for child in component if known is not None else ():
            name = child.tag if isinstance(child.tag, str) else None
            meant = typo_of(name, known) if name is not None and name not in known and not is_foreign(name) else None
            if meant is not None:
                found.append(Unknown(index(child), component.tag, name, False, meant, holder=index(component), owner=component.get("name"), format="ros2_control"))
    return found
