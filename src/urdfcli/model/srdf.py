"""The SRDF: MoveIt's semantic description of a robot, read with source positions.

An SRDF is a ``<robot name=...>`` whose elements name the links and joints of
a URDF of the same robot: planning groups (``<group>`` of links, joints,
chains and subgroups), named joint values (``<group_state>``), end effectors,
virtual joints, passive joints and the link pairs whose collisions are not
checked (``<disable_collisions>``). It defines no link of its own. A file is
read as one when its name ends in ``.srdf`` or ``.srdf.xacro``, or when its
root holds SRDF elements and no ``<link>`` (a xacro file expanding to one).
What srdfdom, MoveIt's SRDF reader, does not read where it is written (a
misspelt element, one of its elements in the wrong place, an unknown
attribute) is kept too, for the rule that reports it (:data:`SCHEMA`).

Each element is kept with its index in document order (the root is 0), so that
a diagnostic is located where it was written, through xacro includes and macros
as for a URDF (see :meth:`urdfcli.read.document.Document.diagnostic`).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import NamedTuple

from ..read.document import Document, tag_name
from ..read.names import typo_of
from ..read.xml import Element, parse
from .vocabulary import Unknown, is_foreign

SRDF_SUFFIXES = (".srdf", ".srdf.xacro")
# The elements only an SRDF writes at the top level (a URDF has none of them)
SRDF_TAGS = frozenset(("group", "group_state", "end_effector", "virtual_joint", "passive_joint", "disable_collisions", "disable_default_collisions", "enable_collisions"))

# What srdfdom (MoveIt's SRDF reader) reads, and where: a place (the tag of an element
# written in <robot>, "parent/tag" of one written inside such an element) -> (its
# attributes, its child elements). srdfdom skips everything else without a word; a
# <group> inside a group names a subgroup, and nothing written in it is read.
SCHEMA: dict[str, tuple[frozenset[str], frozenset[str]]] = {
    place: (frozenset(attributes), frozenset(children)) for place, attributes, children in (
        ("robot", ("name",), ("group", "group_state", "end_effector", "virtual_joint", "passive_joint", "disable_collisions",
                              "enable_collisions", "disable_default_collisions", "link_sphere_approximation", "joint_property")),
        ("group", ("name",), ("link", "joint", "chain", "group")),
        ("group/link", ("name",), ()),
        ("group/joint", ("name",), ()),
        ("group/chain", ("base_link", "tip_link"), ()),
        ("group/group", ("name",), ()),
        ("group_state", ("name", "group"), ("joint",)),
        ("group_state/joint", ("name", "value"), ()),
        ("end_effector", ("name", "group", "parent_link", "parent_group"), ()),
        ("virtual_joint", ("name", "type", "parent_frame", "child_link"), ()),
        ("passive_joint", ("name",), ()),
        ("disable_collisions", ("link1", "link2", "reason"), ()),
        ("enable_collisions", ("link1", "link2", "reason"), ()),
        ("disable_default_collisions", ("link",), ()),
        ("link_sphere_approximation", ("link",), ("sphere",)),
        ("link_sphere_approximation/sphere", ("center", "radius"), ()),
        ("joint_property", ("joint_name", "property_name", "value"), ()),
    )
}
# The attributes without which srdfdom skips an element, with an error in its log (a
# <group_state> joint's value included: the state loses the joint). A group state's
# group is not among them: Pinocchio reads group states without one as its reference
# configurations (example-robot-data's z1, kinova), and MoveIt never sees those files.
REQUIRED: dict[str, tuple[str, ...]] = {
    "group": ("name",), "group/link": ("name",), "group/joint": ("name",), "group/chain": ("base_link", "tip_link"), "group/group": ("name",),
    "group_state": ("name",), "group_state/joint": ("name", "value"), "end_effector": ("name", "group", "parent_link"),
    "virtual_joint": ("name", "child_link", "parent_frame", "type"), "passive_joint": ("name",),
    "disable_collisions": ("link1", "link2"), "enable_collisions": ("link1", "link2"), "disable_default_collisions": ("link",),
    "link_sphere_approximation": ("link",), "link_sphere_approximation/sphere": ("center", "radius"),
    "joint_property": ("joint_name", "property_name", "value"),
}
# Other readers' documented extensions of an SRDF, in <robot>: never reported, never looked into.
EXTENSIONS = {
    "rotor_params": "Pinocchio's rotor inertias and gear ratios",
    **dict.fromkeys(("gripper", "handle", "contact"), "HPP's manipulation frames (hpp-manipulation-urdf)"),
    "specificities": "the humanoid specificities (feet, hands) JRL's and HPP's tools read",
    **dict.fromkeys(("group_tcps", "group_opw", "group_rop", "group_rep", "kinematics_plugin_config", "contact_managers_plugin_config",
                     "calibration_config", "collision_margins"), "Tesseract's SRDF"),
}
EXTENSION_ATTRIBUTES = {"robot": {"version": "Tesseract's SRDF version"}}


def named_srdf(path: str) -> bool:
    """Whether a file's name says it is an SRDF."""
    return path.endswith(SRDF_SUFFIXES)


def looks_semantic(root: Element) -> bool:
    """Whether a parsed document is an SRDF: a ``<robot>`` holding SRDF elements and no ``<link>``."""
    if tag_name(root) != "robot":
        return False
    tags = {child.tag for child in root}
    return bool(tags & SRDF_TAGS) and "link" not in tags


def places_of(tag: str) -> list[str]:
    """The places where srdfdom reads an element ``tag`` (see :data:`SCHEMA`)."""
    return [place for place, (_, children) in SCHEMA.items() if tag in children]


def _read_elements(root: Element) -> Iterator[tuple[Element, str, Element | None]]:
    """Each element srdfdom reads, with its place (of :data:`SCHEMA`) and the element of
    ``<robot>`` it is written in (None for those themselves)."""
    yield root, "robot", None
    for child in root:
        tag = tag_name(child)
        if tag not in SCHEMA["robot"][1]:
            continue
        yield child, tag, None
        for inner in child:
            if tag_name(inner) in SCHEMA[tag][1]:
                yield inner, f"{tag}/{tag_name(inner)}", child


def unknown_markup(root: Element, index: dict[Element, int]) -> list[Unknown]:
    """What srdfdom does not read where it is written, in document order: an element
    (misspelt, or one of its elements in the wrong place) or an attribute. Each
    ``Unknown``'s ``parent`` is the place (of :data:`SCHEMA`) it is written in, or on."""
    found: list[Unknown] = []
    for element, place, _ in _read_elements(root):
        known = SCHEMA[place][0] | EXTENSION_ATTRIBUTES.get(place, {}).keys()
        written = [name for name in element.keys() if not is_foreign(name)]
        found.extend(Unknown(index[element], place, name, True, typo_of(name, known - set(written)), holder=index[element])
                     for name in written if name not in known)
        children = SCHEMA[place][1]
        for child in element:
            tag = tag_name(child)
            if tag not in children and not is_foreign(tag) and not (place == "robot" and tag in EXTENSIONS):
                meant = None if places_of(tag) else typo_of(tag, children)
                found.append(Unknown(index[child], place, tag, False, meant, holder=index[element]))
    return sorted(found, key=lambda unknown: unknown.at)  # (stable: an element's attributes as written)


class Missing(NamedTuple):
    """A required attribute (of :data:`REQUIRED`) an element srdfdom reads lacks."""

    at: int
    place: str
    attribute: str
    name: str | None  # the element's own name, if it has one
    within: str | None  # the element of <robot> it is written in, as a reader says it: "<group> 'arm'"
    misspelt: str | None  # an attribute written on it that is this one misspelt


def missing_attributes(root: Element, index: dict[Element, int], unknown: list[Unknown]) -> list[Missing]:
    """Each required attribute an element srdfdom reads lacks, in document order."""
    found = []
    for element, place, outer in _read_elements(root):
        within = None if outer is None else f"<{tag_name(outer)}>" + (f" '{outer.get('name')}'" if outer.get("name") else "")
        at = index[element]
        lacking = [attribute for attribute in REQUIRED.get(place, ()) if element.get(attribute) is None]
        written = [u for u in unknown if u.at == at and u.attribute] if lacking else []
        found.extend(Missing(at, place, attribute, element.get("name"), within, _written_for(attribute, written)) for attribute in lacking)
    return found


def _written_for(attribute: str, written: list[Unknown]) -> str | None:
    """The unknown attribute of ``written`` (those of one element) that stands for a missing
    ``attribute``: its misspelling, else the one alone that is it cut short or run on
    (``tip`` for ``tip_link``)."""
    for unknown in written:
        if unknown.typo_of == attribute:
            return unknown.name
    cut = [u.name for u in written if not u.typo_of and (attribute.startswith(u.name) or u.name.startswith(attribute))]
    return cut[0] if len(cut) == 1 else None


class Named(NamedTuple):
    """A name an SRDF element gives, and where: element ``at``, attribute ``attribute``."""

    name: str
    at: int
    attribute: str = "name"


class Chain(NamedTuple):
    base: Named
    tip: Named
    at: int


class Group(NamedTuple):
    name: str
    at: int
    links: tuple[Named, ...]
    joints: tuple[Named, ...]
    chains: tuple[Chain, ...]
    subgroups: tuple[Named, ...]


class State(NamedTuple):
    """A ``<group_state>``: named values of joints."""

    name: str
    group: Named
    at: int
    values: tuple[tuple[Named, str | None], ...]  # (joint, value as written; None when there is none)


class EndEffector(NamedTuple):
    name: str
    at: int
    group: Named | None
    parent_link: Named | None
    parent_group: Named | None


class VirtualJoint(NamedTuple):
    name: str
    at: int
    type: str | None
    child: Named | None


class Semantic(NamedTuple):
    """An SRDF as read: its robot's name (None when not given) and its elements."""

    name: str | None
    at: int
    groups: tuple[Group, ...]
    states: tuple[State, ...]
    end_effectors: tuple[EndEffector, ...]
    virtual_joints: tuple[VirtualJoint, ...]
    passive_joints: tuple[Named, ...]
    disabled: tuple[tuple[Named, Named], ...]  # link pairs whose collisions are not checked
    unknown: tuple[Unknown, ...] = ()  # what srdfdom does not read (see unknown_markup)
    missing: tuple[Missing, ...] = ()  # required attributes not written (see missing_attributes)

    @property
    def group_names(self) -> set[str]:
        return {group.name for group in self.groups}

    @property
    def own_joints(self) -> set[str]:
        """The joints the SRDF defines itself: its virtual joints."""
        return {virtual.name for virtual in self.virtual_joints}

    def named_links(self) -> list[tuple[str, Named]]:
        """Each link of its URDF the SRDF names, with what names it: a group's links and chains'
        ends, an end effector's parent link, a virtual joint's child (collision pairs: :attr:`disabled`)."""
        named = []
        for group in self.groups:
            named += [(f"group '{group.name}'", link) for link in group.links]
            named += [(f"the chain of group '{group.name}'", end) for chain in group.chains for end in (chain.base, chain.tip)]
        named += [(f"end effector '{e.name}'", e.parent_link) for e in self.end_effectors if e.parent_link]
        named += [(f"virtual joint '{v.name}'", v.child) for v in self.virtual_joints if v.child]
        return named

    def named_joints(self) -> list[tuple[str, Named]]:
        """Each joint the SRDF names, with what names it: a group's joints, a group state's (but
        one given seven values, a position and a quaternion: the floating base a loader adds), a passive joint."""
        named = [(f"group '{group.name}'", joint) for group in self.groups for joint in group.joints]
        named += [(f"group state '{state.name}'", joint) for state in self.states for joint, value in state.values if len((value or "").split()) != 7]
        named += [("<passive_joint>", joint) for joint in self.passive_joints]
        return named


def read_semantic(document: Document, root: Element | None = None) -> Semantic:
    """The SRDF of a read document (its data parsed here unless ``root`` is given).
    Raises XmlError when the data is not well-formed."""
    root = root if root is not None else parse(document.data)
    index = {element: at for at, element in enumerate(root.iter())}
    document.tops.extend(index[child] for child in root)

    def named(element: Element, attribute: str = "name") -> Named | None:
        value = element.get(attribute)
        return Named(value, index[element], attribute) if value else None

    groups, states, effectors, virtuals, passive, disabled = [], [], [], [], [], []
    for element in root:
        tag = element.tag
        if tag == "group":
            links, joints, chains, subgroups = [], [], [], []
            for child in element:
                found = named(child)
                if child.tag == "link" and found:
                    links.append(found)
                elif child.tag == "joint" and found:
                    joints.append(found)
                elif child.tag == "group" and found:
                    subgroups.append(found)
                elif child.tag == "chain":
                    base, tip = named(child, "base_link"), named(child, "tip_link")
                    if base and tip:
                        chains.append(Chain(base, tip, index[child]))
            groups.append(Group(element.get("name") or "", index[element], tuple(links), tuple(joints), tuple(chains), tuple(subgroups)))
        elif tag == "group_state":
            group = named(element, "group")
            values = tuple((joint, child.get("value")) for child in element if child.tag == "joint" and (joint := named(child)))
            if group:
                states.append(State(element.get("name") or "", group, index[element], values))
        elif tag == "end_effector":
            effectors.append(EndEffector(element.get("name") or "", index[element], named(element, "group"), named(element, "parent_link"), named(element, "parent_group")))
        elif tag == "virtual_joint":
            virtuals.append(VirtualJoint(element.get("name") or "", index[element], element.get("type"), named(element, "child_link")))
        elif tag == "passive_joint":
            if found := named(element):
                passive.append(found)
        elif tag == "disable_collisions":
            first, second = named(element, "link1"), named(element, "link2")
            if first and second:
                disabled.append((first, second))
    unknown = unknown_markup(root, index)
    return Semantic(root.get("name"), 0, tuple(groups), tuple(states), tuple(effectors), tuple(virtuals), tuple(passive), tuple(disabled),
                    tuple(unknown), tuple(missing_attributes(root, index, unknown)))


__all__ = ["EXTENSIONS", "SCHEMA", "SRDF_SUFFIXES", "SRDF_TAGS", "Chain", "EndEffector", "Group", "Missing", "Named", "Semantic", "State", "VirtualJoint", "looks_semantic", "missing_attributes", "named_srdf", "places_of", "read_semantic", "unknown_markup"]
