"""The SRDF against its URDF (K001-K008): every name it gives must exist there,
each chain must run down the tree, each named state must lie within the limits;
and what MoveIt's SRDF reader does not read (K009, K010).

These rules run on an SRDF (``loaded.semantic``) checked against the URDF of
the same robot (``loaded.described``, found in its package or workspace, or
given with ``--urdf``). Each finding is located at the SRDF element or
attribute that names the missing thing, through xacro includes and macros.
What MoveIt does with each mistake is in the rule's documentation: srdfdom
logs most of them and drops the element, so the planning group, state or end
effector silently goes missing at run time.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic
from ..model.kinematics import bodies
from ..model.srdf import SCHEMA, places_of
from .base import ERROR, INFO, WARNING, Given, Kind, RuleSet, check, declare, explain, joined, names
from .suggestions import close_matches

if TYPE_CHECKING:
    from ..model.load import Loaded
    from ..model.srdf import Named

URDF = """\
<robot name="example">
  <link name="base_link"/>
  <link name="link1"/>
  <link name="tool0"/>
  <joint name="joint1" type="revolute">
    <parent link="base_link"/><child link="link1"/>
    <axis xyz="0 0 1"/><limit lower="-1.5" upper="1.5" effort="10" velocity="1"/>
  </joint>
  <joint name="tool_joint" type="fixed"><parent link="link1"/><child link="tool0"/></joint>
</robot>"""
"""The URDF the rules' examples are checked against (``urdf/example.urdf`` beside them)."""


def _against(loaded: Loaded):
    """The URDF's robot (None when there is none to check against)."""
    described = loaded.described
    if described is None or not described.modelled:
        return None
    return described.robot


PAIR = "<disable_collisions>"  # what names the links of a collision pair


def _unmatched_hint(loaded: Loaded, kind: str) -> str:
    """What to do about a name no name of the URDF is close to: a xacro model expanded with its
    default arguments may be another variant than the SRDF's (TIAGo's grippers, one SRDF each)."""
    hint = f"use a {kind} of {loaded.described.path}, or check that the SRDF is for this robot"
    if loaded.described.document.is_xacro:
        hint += "; for another variant of the model, give its xacro arguments after the SRDF (NAME:=VALUE)"
    return hint


def _missing_once(loaded: Loaded, code: str, kind: str, named: list[tuple[str, Named]], known, pairs=(), colliding=None) -> Iterator[Diagnostic]:
    """Each name of a ``kind`` the URDF lacks, said once (one cause, however many elements
    give it): at the first element naming it, one of ``named`` before a collision pair of
    ``pairs`` (``(link, other)``: a warning when only pairs name it), counting the others.
    The hint is the same wherever the name is: the URDF's closest name, but those the name is
    paired with (a link does not collide with itself, so none of them is the one meant); for a
    name only pairs give, one of ``colliding`` (when given): a pair of a link without collision
    geometry disables nothing, so that link is not the one meant."""
    uses: dict[str, list[tuple[str, Named]]] = {}
    ordered = sorted(named, key=lambda use: use[1].at) + sorted(((PAIR, link) for link, _ in pairs), key=lambda use: use[1].at)
    for what, name in ordered:
        if name.name not in known:
            uses.setdefault(name.name, []).append((what, name))
    partners: dict[str, set[str]] = {}
    for link, other in pairs:
        partners.setdefault(link.name, set()).add(other.name)
    for name, found in uses.items():
        what, first = found[0]
        offered = colliding if what == PAIR and colliding is not None else known
        close = close_matches(name, [k for k in offered if k not in partners.get(name, ())])
        hint = f"did you mean '{close[0]}'?" if close else _unmatched_hint(loaded, kind)
        diagnostic = loaded.diagnostic(
            code, f"{what} names {kind} '{name}', which {loaded.described.path} does not have{_elsewhere(found)}",
            first.at, hint, attribute=first.attribute, subjects=(name,),
        )
        yield diagnostic._replace(severity=WARNING) if what == PAIR else diagnostic


def _elsewhere(found: list[tuple[str, Named]]) -> str:
    """`` (and in group 'hand' and 5 <disable_collisions>)``: the other elements that give a
    name said once at the first of ``found`` (a pair naming it twice is one)."""
    what, first = found[0]
    others = list(dict.fromkeys(w for w, _ in found[1:] if w not in (what, PAIR)))
    pairs = len({name.at for w, name in found if w == PAIR} - {first.at})
    parts = others if len(others) <= 4 else [*others[:3], f"{len(others) - 3} more"]
    parts += [f"{pairs}{' more' if what == PAIR else ''} {PAIR}"] if pairs else []
    return f" (and in {joined(parts)})" if parts else ""


def _one_prefix(loaded: Loaded, found: list[Diagnostic], kind: str, known, given: set[str]) -> list[Diagnostic]:
    """``found`` (one for each name the URDF lacks), or one diagnostic for them all when one prefix
    makes every name one of ``known`` that the SRDF does not give itself (``given``): the SRDF of
    the robot built with another prefix (lbr_fri_ros2_stack's robot_name) lacks every name, and one
    finding says why. A prefix that would make a name one the SRDF also gives is no such cause:
    'panda_finger_joint1' beside 'panda_joint1' is the hand the URDF lacks, not 'panda_finger' for 'panda'."""
    missing = [d.subjects[0] for d in found]  # (one each: see _missing_once)
    prefix = _prefix(missing, set(known) - given)
    if prefix is None:
        return found
    old, new = prefix
    first = found[0]
    severity = None if any(d.severity is None for d in found) else first.severity  # the rule's, unless every one is a collision pair's
    has, fix = (
        (f"with the prefix '{new}'", f"write each name with '{new}' in front") if not old
        else (f"without the prefix '{old}'", f"write each name without '{old}'") if not new
        else (f"with the prefix '{new}' in place of '{old}'", f"write each name with '{new}' in place of '{old}'")
    )
    message = f"the SRDF names {len(missing)} {kind}s that {loaded.described.path} has only {has}: {names(missing)}"
    hint = f"it is written for the robot with another prefix: {fix}, or give the xacro argument that sets the prefix after the SRDF (NAME:=VALUE)"
    return [first._replace(message=message, hint=hint, severity=severity, subjects=tuple(missing))]


def _stale(loaded: Loaded, found: list[Diagnostic], kind: str, made) -> list[Diagnostic]:
    """One diagnostic for all of ``found`` (one for each name the URDF lacks) when the xacro file that
    generated the URDF makes every one of them (``made(robot)``: its names of ``kind``), else none: the
    URDF is older than its source (motoman_bmda3_support's bmda3.urdf, generated before its joints were
    renamed, against the SRDF of the renamed robot), and the way out is to generate it again, not to
    rename the SRDF's names."""
    source = loaded.described_source
    missing = [d.subjects[0] for d in found]
    if not found or source is None or any(name not in made(source.robot) for name in missing):
        return []
    first, urdf = found[0], loaded.described.path
    makes = f"{source.path}, which generated it, makes {'them' if len(missing) > 1 else 'it'}"
    hint = f"{urdf} is older than its source ({makes}): generate it again (urdfcli expand {source.path} -o {urdf})"
    if len(found) == 1:
        return [first._replace(hint=hint)]
    severity = None if any(d.severity is None for d in found) else first.severity  # the rule's, unless every one is a collision pair's
    message = f"the SRDF names {len(missing)} {kind}s that {urdf} lacks: {names(missing)}"
    return [first._replace(message=message, hint=hint, severity=severity, subjects=tuple(missing))]


def _prefix(missing: list[str], known) -> tuple[str, str] | None:
    """The one prefix of ``missing`` (``old``, maybe empty) that, replaced by ``new`` (maybe
    empty), makes each name one of ``known``, as (old, new); None for fewer than two names,
    or none or several such prefixes."""
    if len(missing) < 2:
        return None
    first = missing[0]
    candidates = set()
    for name in known:
        same = len(os.path.commonprefix([first[::-1], name[::-1]]))  # the end both names share
        old, new = first[: len(first) - same], name[: len(name) - same]
        if same and (_word_end(old) and _word_end(new) or not first[len(old)].isalnum()):  # 'lbr_' + 'link_0', not 'panda_l' + 'nk7'
            candidates.add((old, new))
    fitting = [(old, new) for old, new in candidates if all(n.startswith(old) and new + n[len(old):] in known for n in missing)]
    return fitting[0] if len(fitting) == 1 else None


def _word_end(prefix: str) -> bool:
    """Whether a name's part ends at a word's end: empty, or ending with '_', '/', '-' or the like."""
    return not prefix or not prefix[-1].isalnum()


@check(
    "K001", "srdf-unknown-link", ERROR, "An SRDF names a link its URDF does not have", kind=Kind.SEMANTIC,
    doc=explain(
        """
        Finds each link an SRDF names that the URDF of its robot does not have:
        in a group (`<link>`, a chain's `base_link` and `tip_link`), an end
        effector's `parent_link`, a virtual joint's `child_link` and a
        `<disable_collisions>` pair. Each missing link is said once, where it is
        first named (a group, end effector or virtual joint before a pair), with
        how many more elements name it. Named by pairs only, it is a warning:
        MoveIt logs it and goes on (a link the URDF lacks collides with nothing;
        a typo leaves the two links meant checked). When one prefix, added to
        each name the URDF lacks, taken from each or put in place of another,
        makes them all its names, one finding names them: the SRDF was written
        for the robot built with another prefix. When the URDF is one xacro
        generated and the xacro file makes every link it lacks, the hint is to
        generate it again (one finding for several).
        """,
        """
        MoveIt's SRDF reader logs the unknown name and drops what holds it: the
        group is built without that link (a chain not at all), the end effector
        or virtual joint is skipped, the collision pair is checked after all:
        when the name is a typo, the two links meant are checked, and a pair
        always in contact makes every start state collide.
        It is a typo, or the SRDF of another version of the robot.
        """,
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool_0"/></group>\n</robot>',
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n</robot>',
    ),
)
def unknown_link(loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
    robot = _against(loaded)
    if robot is None:
        return
    links = robot.links
    pairs = [(link, other) for pair in loaded.semantic.disabled for link, other in (pair, pair[::-1])]
    named = loaded.semantic.named_links()
    given = {name.name for _, name in named} | {link.name for link, _ in pairs}
    colliding = [name for name, link in links.items() if link.collisions]
    found = list(_missing_once(loaded, "K001", "link", named, links, pairs, colliding))
    yield from _stale(loaded, found, "link", lambda robot: robot.links) or _one_prefix(loaded, found, "link", links, given)


@check(
    "K002", "srdf-unknown-joint", ERROR, "An SRDF names a joint its URDF does not have", kind=Kind.SEMANTIC,
    doc=explain(
        """
        Finds each joint an SRDF names that the URDF of its robot does not have:
        in a group, in a group state, or as a passive joint. A virtual joint's
        name is the SRDF's own and counts as a joint, and so does a group state's
        joint given seven values (a position and a quaternion): the floating base
        a loader adds, as Pinocchio's `root_joint` (its SRDFs set it without a
        virtual joint). Each missing joint is said once, where it is first named,
        with how many more elements name it. When one prefix, added to each name
        the URDF lacks, taken from each or put in place of another, makes them
        all its names, one finding names them. When the URDF is one xacro
        generated and the xacro file makes every joint it lacks, the hint is to
        generate it again (one finding for several).
        """,
        """
        MoveIt logs the unknown joint and leaves it out: the group lacks a degree
        of freedom, the named state does not set it, the passive joint is
        planned for as if it were driven.
        """,
        '<robot name="example">\n  <group name="arm"><joint name="joint_1"/></group>\n</robot>',
        '<robot name="example">\n  <group name="arm"><joint name="joint1"/></group>\n</robot>',
    ),
)
def unknown_joint(loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
    robot = _against(loaded)
    if robot is None:
        return
    joints = set(robot.joints) | loaded.semantic.own_joints
    named = loaded.semantic.named_joints()
    given = {name.name for _, name in named}
    found = list(_missing_once(loaded, "K002", "joint", named, joints))
    yield from _stale(loaded, found, "joint", lambda robot: set(robot.joints) | loaded.semantic.own_joints) or _one_prefix(loaded, found, "joint", joints, given)


@check(
    "K003", "srdf-unknown-group", ERROR, "An SRDF refers to a group it does not define", kind=Kind.SEMANTIC,
    doc=explain(
        """
        Finds each group an SRDF refers to but does not define: a subgroup, the
        group of a group state, an end effector's `group` and `parent_group`.
        """,
        """
        MoveIt skips the group state or end effector whose group is unknown, and
        builds the group without the missing subgroup: `setNamedTarget("home")`
        fails at run time with a state that is in the file.
        """,
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n'
        '  <group_state name="home" group="manipulator"><joint name="joint1" value="0"/></group_state>\n</robot>',
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n'
        '  <group_state name="home" group="arm"><joint name="joint1" value="0"/></group_state>\n</robot>',
    ),
)
def unknown_group(loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
    semantic = loaded.semantic
    groups = semantic.group_names
    named = [(f"group '{group.name}'", sub) for group in semantic.groups for sub in group.subgroups]
    named += [(f"group state '{state.name}'", state.group) for state in semantic.states]
    named += [(f"end effector '{e.name}'", g) for e in semantic.end_effectors for g in (e.group, e.parent_group) if g]
    for what, group in named:
        if group.name not in groups:
            close = close_matches(group.name, list(groups))
            hint = f"did you mean '{close[0]}'?" if close else "define the group, or name one the SRDF defines"
            yield loaded.diagnostic("K003", f"{what} names group '{group.name}', which the SRDF does not define", group.at, hint, attribute=group.attribute)


@check(
    "K004", "srdf-broken-chain", ERROR, "A group's chain does not run from its base link down to its tip link", kind=Kind.SEMANTIC,
    doc=explain(
        """
        Finds each `<chain>` whose `tip_link` is not below its `base_link` in the
        URDF's tree (both links exist: K001 reports a missing one).
        """,
        """
        MoveIt builds a chain group by walking up from the tip to the base; when
        the base is not on that path the group is not built and every plan for
        it fails. The two links are swapped, or belong to different branches.
        """,
        '<robot name="example">\n  <group name="arm"><chain base_link="tool0" tip_link="base_link"/></group>\n</robot>',
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n</robot>',
    ),
)
def broken_chain(loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
    robot = _against(loaded)
    if robot is None:
        return
    parents = _parents(loaded)
    for group in loaded.semantic.groups:
        for chain in group.chains:
            base, tip = chain.base.name, chain.tip.name
            if base not in robot.links or tip not in robot.links or base in _ancestors(tip, parents) or base == tip:
                continue
            swapped = tip in _ancestors(base, parents)
            hint = "swap base_link and tip_link" if swapped else "give a base_link above the tip_link, on its branch of the tree"
            yield loaded.diagnostic(
                "K004", f"the chain of group '{group.name}' runs from '{base}' to '{tip}', but '{tip}' is not below '{base}' in the URDF",
                chain.at, hint, subjects=(base, tip),
            )


def _parents(loaded: Loaded) -> dict[str, str]:
    """Each link's parent link in the URDF (the first joint naming it as child)."""
    return {child: joint.parent for child, joint in loaded.described.parent_joints.items() if joint.parent is not None}


def _ancestors(link: str, parents: dict[str, str]) -> list[str]:
    found, seen = [], {link}
    while (link := parents.get(link)) is not None and link not in seen:
        found.append(link)
        seen.add(link)
    return found


@check(
    "K005", "srdf-state-outside-limits", WARNING, "A group state sets a joint outside its limits", kind=Kind.SEMANTIC,
    doc=explain(
        """
        Finds each value of a `<group_state>` outside the limits its joint has in
        the URDF (a revolute or prismatic joint's `lower` and `upper`), and each
        value that is not a number. A joint given no value is K010's.
        """,
        """
        MoveIt loads the state, but the robot cannot reach it: a plan to it is
        refused as out of bounds. A limit was tightened in the URDF, or the value
        is in degrees.
        """,
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n'
        '  <group_state name="home" group="arm"><joint name="joint1" value="90"/></group_state>\n</robot>',
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n'
        '  <group_state name="home" group="arm"><joint name="joint1" value="1.2"/></group_state>\n</robot>',
    ),
)
def state_outside_limits(loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
    robot = _against(loaded)
    if robot is None:
        return
    for state in loaded.semantic.states:
        for joint_name, text in state.values:
            joint = robot.joints.get(joint_name.name)
            if joint is None or joint.type not in ("revolute", "prismatic", "continuous") or text is None:
                continue  # an unknown joint is K002's, no value K010's; a planar or floating joint takes several values
            try:
                value = float(text)
            except ValueError:
                yield loaded.diagnostic("K005", f"group state '{state.name}' gives joint '{joint.name}' the value '{text}', which is not a number", joint_name.at, attribute="value", subjects=(joint.name,))
                continue
            limit = joint.limit
            if joint.type == "continuous" or limit is None:
                continue
            tolerance = 1e-9 * max(1.0, abs(limit.lower), abs(limit.upper))
            if limit.lower - tolerance <= value <= limit.upper + tolerance:
                continue
            unit, units = ("m", "metres for a prismatic joint") if joint.type == "prismatic" else ("rad", "radians for a revolute joint")
            yield loaded.diagnostic(
                "K005", f"group state '{state.name}' sets joint '{joint.name}' to {text}, outside its limits [{limit.lower:g}, {limit.upper:g}] {unit}",
                joint_name.at, f"give a value within the joint's limits ({units})", attribute="value", subjects=(joint.name,),
            )


@check(
    "K006", "srdf-state-joint-outside-group", WARNING, "A group state sets a joint that is not in its group", kind=Kind.SEMANTIC,
    doc=explain(
        """
        Finds the joints a `<group_state>` sets that its group does not hold, said
        once per state at the first of them. A group holds its joints, the parent
        joint of each of its links, the joints of its chains (and the parent joint
        of each chain's base), and those of its subgroups. A group that holds
        nothing at all is left alone: Pinocchio's SRDFs write an empty `all` group
        to name reference configurations, and Pinocchio reads every joint of the
        state.
        """,
        """
        MoveIt refuses such a state: it reports that the joint is not part of
        the group and the named state is not there at run time.
        """,
        '<robot name="example">\n  <group name="tool"><link name="tool0"/></group>\n'
        '  <group_state name="home" group="tool"><joint name="joint1" value="0"/></group_state>\n</robot>',
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n'
        '  <group_state name="home" group="arm"><joint name="joint1" value="0"/></group_state>\n</robot>',
    ),
)
def state_joint_outside_group(loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
    robot = _against(loaded)
    if robot is None:
        return
    groups = {group.name: group for group in loaded.semantic.groups}
    for state in loaded.semantic.states:
        if state.group.name not in groups:
            continue  # K003's
        group = groups[state.group.name]
        if not (group.links or group.joints or group.chains or group.subgroups):
            continue  # an empty group names a configuration of the whole robot (Pinocchio's reference configurations)
        members = _group_joints(loaded, groups, state.group.name)
        if members is None:
            continue  # a group MoveIt cannot build as written: K001, K003 or K004 says why
        outside = [joint for joint, _ in state.values if joint.name in robot.joints and joint.name not in members]
        if outside:
            names = ", ".join(f"'{joint.name}'" for joint in outside[:4]) + (f" and {len(outside) - 4} more" if len(outside) > 4 else "")
            joints = "joint" if len(outside) == 1 else f"{len(outside)} joints"
            yield loaded.diagnostic(
                "K006", f"group state '{state.name}' sets {joints} {names}, not in group '{state.group.name}'",
                outside[0].at, f"set only the joints of group '{state.group.name}', or add the joints to it",
                subjects=tuple(joint.name for joint in outside),
            )


def _group_joints(loaded: Loaded, groups: dict, name: str, seen: frozenset = frozenset()) -> set[str] | None:
    """The joints a group holds, as MoveIt builds it; None when a name in it (or in a
    subgroup) is unknown, or a chain does not run down the tree."""
    group = groups.get(name)
    if group is None:
        return None
    if name in seen:
        return set()
    robot = loaded.described.robot
    parent_joints = loaded.described.parent_joints
    parents = _parents(loaded)
    if any(joint.name not in robot.joints for joint in group.joints) or any(link.name not in robot.links for link in group.links):
        return None
    joints = {joint.name for joint in group.joints}
    links = {link.name for link in group.links}
    for chain in group.chains:
        above = _ancestors(chain.tip.name, parents)
        if chain.base.name not in above or chain.tip.name not in robot.links:
            return None
        links.update([chain.tip.name, *above[: above.index(chain.base.name) + 1]])
    joints.update(parent_joints[link].name for link in links if link in parent_joints)
    for sub in group.subgroups:
        found = _group_joints(loaded, groups, sub.name, seen | {name})
        if found is None:
            return None
        joints |= found
    return joints


@check(
    "K007", "srdf-virtual-joint-not-at-root", ERROR, "A virtual joint's child is not the URDF's root link", kind=Kind.SEMANTIC,
    doc=explain(
        """
        Finds each `<virtual_joint>` whose `child_link` exists in the URDF but is
        not its root link. A fixed virtual joint whose child the URDF already
        fixes to its root (a Gazebo-style `world` link, `world` -> `panda_link0`)
        is only noted (info): MoveIt skips it, and the robot stands as the URDF
        says, which is what the fixed joint meant.
        """,
        """
        A virtual joint attaches the robot to the world: MoveIt uses it only when
        its child is the root of the tree, and otherwise plans with the robot
        fixed at the origin, whatever the joint's type says (a mobile base that
        never moves in the planning scene).
        """,
        '<robot name="example">\n  <virtual_joint name="world_joint" type="fixed" parent_frame="world" child_link="link1"/>\n</robot>',
        '<robot name="example">\n  <virtual_joint name="world_joint" type="fixed" parent_frame="world" child_link="base_link"/>\n</robot>',
    ),
)
def virtual_joint_not_at_root(loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
    robot = _against(loaded)
    root = loaded.described.root if robot is not None else None
    if root is None:
        return
    for virtual in loaded.semantic.virtual_joints:
        child = virtual.child
        if child is None or child.name not in robot.links or child.name == root:
            continue
        if virtual.type == "fixed" and bodies(loaded.described)[child.name].top == root:  # fixed to the root
            # a Gazebo-style URDF fixes the base to its 'world' link: MoveIt skips the virtual joint, and the robot stands as it says
            yield loaded.diagnostic(
                "K007", f"virtual joint '{virtual.name}' has child '{child.name}', which {loaded.described.path} already fixes to its root link '{root}': "
                "MoveIt skips the virtual joint, and the robot stands where the URDF puts it",
                child.at, f"remove the virtual joint, or give child_link=\"{root}\"", attribute=child.attribute, subjects=(child.name,),
            )._replace(severity=INFO)
            continue
        yield loaded.diagnostic(
            "K007", f"virtual joint '{virtual.name}' has child '{child.name}', but the root link of {loaded.described.path} is '{root}'",
            child.at, f"give child_link=\"{root}\"", attribute=child.attribute, subjects=(child.name,),
        )


K008 = declare(
    "K008", "srdf-without-urdf", INFO, "No URDF of the SRDF's robot was found to check it against",
    explain(
        """
        Says that an SRDF could not be checked against a URDF: no URDF or xacro
        file of its package or workspace describes a robot of its name, or the
        one found cannot be read or expanded (it needs xacro arguments). A
        warning says when the URDF it was checked against names its robot
        otherwise: the URDF given with `--urdf`, or the URDF beside the SRDF
        named as it is (`go2.urdf` for `go2.srdf`, in its robot's folder), which
        may be its robot's whatever name it gives, and is taken when it is the
        one whose links and joints the SRDF names.
        """,
        """
        Without a URDF the SRDF's names are not checked at all. MoveIt pairs the
        SRDF with the `robot_description` of the same robot, and its SRDF reader
        (srdfdom) logs an error when the two robot names differ.
        """,
        '<robot name="no_such_robot">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n</robot>',
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n</robot>',
    ),
    kind=Kind.READING,
)

@check(
    "K009", "srdf-unknown-markup", WARNING, "An SRDF element or attribute MoveIt does not read where it is written",
    kind=Kind.SEMANTIC, rule_set=RuleSet.LINT,
    doc=explain(
        """
        Flags an element of an SRDF that MoveIt's SRDF reader (srdfdom) does not
        read where it is written: a misspelt one (`<linkk>` in a `<group>`, with
        the element meant), or one of its elements in the wrong place (a
        `<passive_joint>` inside a `<group>`, a `<chain>` outside one, anything
        inside a subgroup's `<group>`, which only names the subgroup), with where
        it belongs; and an attribute it does not read (`<chain tip="...">`, with
        the attribute meant when it is one or two letters away; a misspelt
        attribute srdfdom needs is K010's, which `check` reports too). Other unknown
        markup, neither misspelt nor misplaced, is only noted (info): it may be
        meant for another reader. Pinocchio's `<rotor_params>`, HPP's
        `<gripper>`, `<handle>` and `<contact>`, the humanoid `<specificities>`
        of example-robot-data's SRDFs and Tesseract's extensions (`<group_tcps>`,
        `<kinematics_plugin_config>`, `<collision_margins>`, ..., `<robot version>`)
        draw nothing, nor does anything prefixed (`xacro:`).
        """,
        """
        srdfdom skips what it does not know without a word: the misspelt link is
        not in the group, the joint of a `<passive_joint>` written in a group is
        planned for as if it were driven (franka_ros2's hand SRDF did this), the
        chain written outside a group belongs to no group.
        """,
        '<robot name="example">\n  <group name="arm">\n    <chain base_link="base_link" tip_link="tool0"/>\n    <passive_joint name="tool_joint"/>\n  </group>\n</robot>',
        '<robot name="example">\n  <group name="arm">\n    <chain base_link="base_link" tip_link="tool0"/>\n  </group>\n  <passive_joint name="tool_joint"/>\n</robot>',
    ),
)
def unknown_markup(loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
    required = {(missing.at, missing.misspelt) for missing in loaded.semantic.missing}
    for unknown in loaded.semantic.unknown:
        if unknown.attribute and (unknown.at, unknown.name) in required:
            continue  # a required attribute misspelt: K010 says the element lacks it, in check too
        where, name = _shown(unknown.parent), unknown.name
        if unknown.attribute:
            hint = f"did you mean '{unknown.typo_of}'?" if unknown.typo_of else f"{where} takes {', '.join(sorted(SCHEMA[unknown.parent][0]))}"
            diagnostic = loaded.diagnostic("K009", f"{where} has no attribute '{name}'; MoveIt ignores it", unknown.at, hint, attribute=name)
            misplaced = False
        else:
            places = places_of(name)
            misplaced = bool(places)
            if misplaced:
                hint = f"<{name}> belongs " + " or ".join("directly in <robot>" if p == "robot" else f"in {_shown(p)}" for p in places)
                hint += "; a <group> inside a group only names a subgroup" if unknown.parent == "group/group" else ""
            elif unknown.typo_of:
                hint = f"did you mean <{unknown.typo_of}>?"
            else:
                held = SCHEMA[unknown.parent][1]
                hint = f"{where} may hold " + ", ".join(f"<{c}>" for c in sorted(held)) if held else f"{where} holds no elements"
            diagnostic = loaded.diagnostic("K009", f"<{name}> is not read inside {where}; MoveIt ignores it", unknown.at, hint)
        yield diagnostic if unknown.typo_of or misplaced else diagnostic._replace(severity=INFO)  # neither: maybe another reader's


@check(
    "K010", "srdf-attribute-missing", ERROR, "An SRDF element without an attribute MoveIt needs to read it", kind=Kind.SEMANTIC,
    doc=explain(
        """
        Finds each element MoveIt's SRDF reader (srdfdom) reads that lacks an
        attribute it needs: a `<group>`, group state, end effector or passive
        joint without `name`, a `<chain>` without `base_link` or `tip_link`, a
        group state's joint without `value`, a
        virtual joint without `child_link`, `parent_frame` or `type`, a collision
        pair without `link1` or `link2`, ... (the attribute meant, when one
        written is it misspelt: K009 leaves that one to it). An attribute
        written empty is present; what it names is checked by K001-K003.
        Left alone: a group state without `group`, which Pinocchio reads as a
        reference configuration (its SRDFs are not MoveIt's).
        """,
        """
        srdfdom logs an error and skips the element: the chain is not in its
        group (a group left empty plans for nothing), the state lacks the joint
        (moving to it leaves that joint where it is), the collision pair is
        checked after all.
        """,
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip="tool0"/></group>\n</robot>',
        '<robot name="example">\n  <group name="arm"><chain base_link="base_link" tip_link="tool0"/></group>\n</robot>',
    ),
)
def attribute_missing(loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
    for missing in loaded.semantic.missing:
        tag = missing.place.rsplit("/", 1)[-1]
        what = f"<{tag}>" + (f" '{missing.name}'" if missing.name else "") + (f" in {missing.within}" if missing.within else "")
        if missing.misspelt:
            hint = f"did you mean {missing.attribute}=\"...\"? '{missing.misspelt}' is no attribute of <{tag}>"
        else:
            hint = f"give {missing.attribute}=\"...\""
        yield loaded.diagnostic("K010", f"{what} has no '{missing.attribute}'; MoveIt skips it", missing.at, hint, attribute=missing.misspelt)


def _shown(place: str) -> str:
    """A place of srdfdom's vocabulary as a reader says it: ``<joint> in <group_state>``."""
    *outer, tag = place.split("/")
    return f"<{tag}>" + (f" in <{outer[0]}>" if outer else "")


__all__ = ["URDF"]
