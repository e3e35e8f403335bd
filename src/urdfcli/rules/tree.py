"""The tree's structure: links that joints name, one root, one parent per link, no loop.

These run on every model read, whatever the command: a model that is not a tree
cannot be drawn or audited either.
"""

from __future__ import annotations

from ..diagnostics import Severity
from ..model.kinematics import build_graph, children_by_joint_name, has_loop, joined, reached, roots
from .base import Kind, check
from .suggestions import close_matches

ERROR = Severity.ERROR
REJECTED = "check_urdf rejects the file, and so does every tool built on urdfdom (robot_state_publisher, RViz, MoveIt, Gazebo's URDF import)."


def dangling(loaded) -> list:
    """The joints naming a link that does not exist (looked for only when there are some)."""
    robot = loaded.robot
    if len(joined(robot)) == len(robot.joints):
        return []
    links = robot.links
    return [j for j in robot.joints.values() if (j.parent is not None and j.parent not in links) or (j.child is not None and j.child not in links)]


def link_hint(missing: str, robot, other_end: str | None = None, role: str = "parent") -> str:
    """What to do about a joint naming a missing link (its ``role``): the closest link names, if any,
    never one the joint cannot join to its other end (see :func:`unjoinable`)."""
    # difflib is quadratic in names: past a few thousand links the plain hint keeps a broken model fast
    few = len(robot.links) <= 5000
    excluded = unjoinable(robot, other_end, role) if few else set()
    close = close_matches(missing, [name for name in robot.links if name not in excluded], n=3) if few else []
    if close:
        return f"did you mean {' or '.join(repr(name) for name in close)}?"
    return f'every link a joint names must be defined: add <link name="{missing}"/> or fix the name'


def unjoinable(robot, other_end: str | None, role: str) -> set[str]:
    """The links a joint cannot have in ``role`` beside ``other_end``: the other end itself (a joint
    does not join a link to itself); as parent, a link below its child (Franka's hand joint
    missing its ``${prefix}link8`` is not meant to hang the hand from its own finger: a loop); as
    child, a link above its parent (a loop) or one another joint already moves (two parents)."""
    if other_end not in robot.links:
        return {other_end}
    if role == "parent":
        return set(reached(children_by_joint_name(robot), other_end))
    parent_of = {joint.child: joint.parent for joint in joined(robot)}
    link, above = other_end, {other_end}
    while link in parent_of and parent_of[link] not in above:
        link = parent_of[link]
        above.add(link)
    return above | set(parent_of)  # the links above (every one but the root has a parent) and those with a parent


@check("J005", "joint-link-not-found", ERROR, "A joint names a parent or child link that does not exist.", urdfdom=True, kind=Kind.TREE)
def joint_link_not_found(loaded, given):
    """## What it does
    Flags a joint whose parent or child link is not defined.

    ## Why is this bad?
    The tree cannot be built. check_urdf rejects the file, and so does every tool built on urdfdom (robot_state_publisher, RViz, MoveIt, Gazebo's URDF import).

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="fixed">
      <parent link="base"/>
      <child link="arm_link"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="fixed">
      <parent link="base_link"/>
      <child link="arm_link"/>
    </joint>
    ```
    """
    robot = loaded.robot
    for joint in dangling(loaded):
        for role, link, other_end in (("parent", joint.parent, joint.child), ("child", joint.child, joint.parent)):
            if link is not None and link not in robot.links:
                yield loaded.diagnostic(
                    "J005", f"{role} link '{link}' of joint '{joint.name}' does not exist", joint.part(role),
                    link_hint(link, robot, other_end, role), subjects=(joint.name,),
                )


@check("T003", "multiple-parents", ERROR, "A link is the child of more than one joint.", kind=Kind.TREE)
def multiple_parents(loaded, given):
    """## What it does
    Flags a link that is the child of two or more joints.

    ## Why is this bad?
    URDF describes trees: check_urdf accepts it and prints the link twice, but robot_state_publisher and KDL keep only one parent and the other joint does nothing.

    ## Example
    ```xml
    <link name="a"/>
    <link name="b"/>
    <link name="c"/>
    <joint name="a_to_c" type="fixed"><parent link="a"/><child link="c"/></joint>
    <joint name="b_to_c" type="fixed"><parent link="b"/><child link="c"/></joint>
    <joint name="a_to_b" type="fixed"><parent link="a"/><child link="b"/></joint>
    ```

    ## Use instead
    ```xml
    <link name="a"/>
    <link name="b"/>
    <link name="c"/>
    <joint name="a_to_c" type="fixed"><parent link="a"/><child link="c"/></joint>
    <joint name="a_to_b" type="fixed"><parent link="a"/><child link="b"/></joint>
    ```
    """
    first_parent: dict = {}
    for joint in joined(loaded.robot):
        first = first_parent.setdefault(joint.child, joint)
        if first is not joint:
            yield loaded.diagnostic(
                "T003",
                f"link '{joint.child}' is the child of joint '{joint.name}' and also of joint '{first.name}'",
                joint.at,
                "a link has exactly one parent joint; for a closed chain, use a mimic joint or split the link",
                subjects=(joint.child,),
            )


@check("T004", "kinematic-loop", ERROR, "The joints form a loop.", kind=Kind.TREE)
def kinematic_loop(loaded, given):
    """## What it does
    Flags joints that form a closed loop anywhere in the model, even below a proper root.

    ## Why is this bad?
    check_urdf never finishes on a loop below a root (it prints forever); solvers recurse without end.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="a"/>
    <link name="b"/>
    <joint name="base_to_a" type="fixed"><parent link="base_link"/><child link="a"/></joint>
    <joint name="a_to_b" type="fixed"><parent link="a"/><child link="b"/></joint>
    <joint name="b_to_a" type="fixed"><parent link="b"/><child link="a"/></joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="a"/>
    <link name="b"/>
    <joint name="base_to_a" type="fixed"><parent link="base_link"/><child link="a"/></joint>
    <joint name="a_to_b" type="fixed"><parent link="a"/><child link="b"/></joint>
    ```
    """
    robot = loaded.robot
    if not has_loop(robot):  # rare: only then is networkx worth importing
        return
    import networkx as nx

    graph = build_graph(robot)
    for component in nx.strongly_connected_components(graph):
        if len(component) == 1:
            (node,) = component
            if not graph.has_edge(node, node):
                continue
        cycle = nx.find_cycle(graph.subgraph(component))
        first_joint = graph.edges[cycle[0][0], cycle[0][1]]["joint"]
        path = " -> ".join([cycle[0][0], *(v for _, v in cycle)])
        yield loaded.diagnostic("T004", f"the joints form a loop: {path}", first_joint.at, "URDF describes trees: remove one joint of the loop",
                                subjects=tuple(v for _, v in cycle))


def _roots(loaded) -> list[str]:
    """The links with no parent; a link whose joint names a missing parent is cut off by
    that J005 alone, not a second root (nor, when every one is, are they many roots: a
    part whose includer gives the links it hangs from, read alone)."""
    robot = loaded.robot
    links = robot.links
    cut_off = {j.child for j in dangling(loaded) if j.parent is not None and j.parent not in links}
    return [root for root in roots(robot) if root not in cut_off]


@check("T001", "multiple-roots", ERROR, "More than one link has no parent.", urdfdom=True, kind=Kind.TREE)
def multiple_roots(loaded, given):
    """## What it does
    Flags a model whose links do not form one tree: more than one link is the child of no joint.

    ## Why is this bad?
    A URDF has exactly one root link (check_urdf: "Two root links found"). check_urdf rejects the file, and so does every tool built on urdfdom (robot_state_publisher, RViz, MoveIt, Gazebo's URDF import).

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="sensor_link"/>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="sensor_link"/>
    <joint name="sensor_joint" type="fixed">
      <parent link="base_link"/>
      <child link="sensor_link"/>
    </joint>
    ```
    """
    robot = loaded.robot
    found = _roots(loaded) if robot.links else []
    if len(found) > 1:
        names = ", ".join(f"'{r}'" for r in found[:5]) + (" ..." if len(found) > 5 else "")
        yield loaded.diagnostic(
            "T001", f"{len(found)} links have no parent: {names}", robot.links[found[1]].at,
            "connect every link to the tree with a joint, or remove the unused ones", subjects=tuple(found),
        )


@check("T002", "no-root", ERROR, "Every link has a parent: there is no root.", urdfdom=True, kind=Kind.TREE)
def no_root(loaded, given):
    """## What it does
    Flags a model in which every link is the child of some joint, so no link is the root.

    ## Why is this bad?
    The joints form a loop through every link. check_urdf rejects the file, and so does every tool built on urdfdom (robot_state_publisher, RViz, MoveIt, Gazebo's URDF import).

    ## Example
    ```xml
    <link name="a"/>
    <link name="b"/>
    <joint name="a_to_b" type="fixed"><parent link="a"/><child link="b"/></joint>
    <joint name="b_to_a" type="fixed"><parent link="b"/><child link="a"/></joint>
    ```

    ## Use instead
    ```xml
    <link name="a"/>
    <link name="b"/>
    <joint name="a_to_b" type="fixed"><parent link="a"/><child link="b"/></joint>
    ```
    """
    robot = loaded.robot
    if robot.links and not roots(robot):
        yield loaded.diagnostic("T002", "every link has a parent, so there is no root link", robot.at, "the joints form a loop")
