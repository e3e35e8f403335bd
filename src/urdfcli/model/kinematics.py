"""The kinematic tree: walks, roots, loops, rigid bodies, and a networkx DiGraph.

Links are nodes; each joint whose parent and child exist is an edge
``parent -> child`` carrying the Joint as ``joint``. Nothing here recurses,
so a 20,000-link chain is as easy as a short one.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable, Iterator, Mapping
from operator import attrgetter
from typing import TYPE_CHECKING, NamedTuple

from ..read.memo import once
from .robot import Joint, Robot

if TYPE_CHECKING:
    import networkx as nx


def build_graph(robot: Robot) -> nx.DiGraph:
    import networkx as nx  # only here: importing networkx takes longer than checking a small file

    graph = nx.DiGraph()
    graph.add_nodes_from(robot.links)
    for joint in joined(robot):
        graph.add_edge(joint.parent, joint.child, joint=joint)
    return graph


def joined(robot: Robot) -> list[Joint]:
    """The joints whose parent and child links both exist, in document order: the
    edges of the tree (a joint naming a missing link is J005's). Every tree check
    starts from these, so the links are looked up once per joint, not once per check."""
    return once(robot, _joined)


def _joined(robot: Robot) -> list[Joint]:
    links = robot.links
    return [joint for joint in robot.joints.values() if joint.parent in links and joint.child in links]


def children_by_joint_name(robot: Robot) -> dict[str, list[Joint]]:
    """Each link's child joints in check_urdf's order: sorted by joint name."""
    return once(robot, _children_by_joint_name)


def _children_by_joint_name(robot: Robot) -> dict[str, list[Joint]]:
    children: dict[str, list[Joint]] = defaultdict(list)
    for joint in sorted(joined(robot), key=attrgetter("name")):  # joint names are unique: the order of sorted(robot.joints)
        children[joint.parent].append(joint)
    return children


def roots(robot: Robot) -> list[str]:
    return once(robot, _roots)


def _roots(robot: Robot) -> list[str]:
    has_parent = {joint.child for joint in joined(robot)}
    return [name for name in robot.links if name not in has_parent]


def walk(robot: Robot, start: str, children: dict[str, list[Joint]] | None = None) -> Iterator[tuple[int, Joint | None, str]]:
    """Depth-first (depth, joint leading here, link), children in joint-name order.

    A link reached twice (two parents) is not entered again, so loops end.
    """
    for depth, joint, link, repeat in walk_all(robot, start, children):
        if not repeat:
            yield depth, joint, link


def walk_all(
    robot: Robot, start: str, children: dict[str, list[Joint]] | None = None
) -> Iterator[tuple[int, Joint | None, str, bool]]:
    """``walk``, plus each joint that reaches a link already reached (a second
    parent, or a loop closing), flagged ``repeat``; nothing below it follows."""
    children = children_by_joint_name(robot) if children is None else children
    seen: set[str] = set()
    stack: list[tuple[int, Joint | None, str]] = [(0, None, start)]
    while stack:
        depth, joint, link = stack.pop()
        repeat = link in seen  # told when it comes, not when it is queued: the first one shown is never the repeat
        seen.add(link)
        yield depth, joint, link, repeat
        if repeat:
            continue
        for child_joint in reversed(children.get(link, [])):
            stack.append((depth + 1, child_joint, child_joint.child))


def reached(children: dict[str, list[Joint]], start: str) -> list[str]:
    """The links of ``walk`` from ``start``, in its order, without its tuples: the
    walk the checks of a large model take once per link."""
    seen: set[str] = set()
    order: list[str] = []
    stack = [start]
    while stack:
        link = stack.pop()
        if link in seen:
            continue
        seen.add(link)
        order.append(link)
        stack.extend(joint.child for joint in reversed(children.get(link, ())) if joint.child not in seen)
    return order


def walks(robot: Robot) -> dict[str, list[str]]:
    """Each root's links in the order of ``walk``, worked out once."""
    return once(robot, _walks)


def _walks(robot: Robot) -> dict[str, list[str]]:
    return {root: reached(children_by_joint_name(robot), root) for root in roots(robot)}


def has_loop(robot: Robot) -> bool:
    """Whether the joints form a directed loop (without networkx). When no link has
    two parents, a loop is exactly what the roots do not reach; else Kahn's algorithm."""
    children = children_by_joint_name(robot)  # shared with the walks that follow
    joined = sum(len(joints) for joints in children.values())
    if joined == len(robot.links) - len(roots(robot)):  # one parent joint per link that has one
        return sum(len(order) for order in walks(robot).values()) < len(robot.links)
    waiting = dict.fromkeys(robot.links, 0)  # parent joints not yet visited, per link
    for joints in children.values():
        for joint in joints:
            waiting[joint.child] += 1
    ready = [link for link, count in waiting.items() if count == 0]
    visited = 0
    while ready:
        link = ready.pop()
        visited += 1
        for joint in children.get(link, ()):
            waiting[joint.child] -= 1
            if waiting[joint.child] == 0:
                ready.append(joint.child)
    return visited < len(waiting)


def depth_and_leaves(robot: Robot, root: str) -> tuple[int, list[str]]:
    children = children_by_joint_name(robot)
    depth = 0
    leaves = []
    for level, _, link in walk(robot, root, children):
        depth = max(depth, level)
        if not children.get(link):
            leaves.append(link)
    return depth, leaves


class RigidBody(NamedTuple):
    """Links joined by fixed joints: one rigid body, as simulators and Pinocchio lump them.

    ``joint`` is the moving joint that carries the body (None for the root's body, or a
    body whose top link has no parent); ``links`` starts with the top link."""

    joint: Joint | None
    links: tuple[str, ...]

    @property
    def top(self) -> str:
        return self.links[0]

    @property
    def moving(self) -> bool:
        return self.joint is not None


def rigid_bodies(robot: Robot, parent_joints: Mapping[str, Joint]) -> dict[str, RigidBody]:
    """Each link's rigid body. ``parent_joints`` gives each link's (first) parent joint."""
    links = robot.links
    # The link above each link across a joint that does not move: a body hangs from its top by these.
    above = {name: joint.parent for name, joint in parent_joints.items() if not joint.moving and joint.parent in links and name in links}
    tops: dict[str, str] = {}
    for name in links:
        path: list[str] = []
        link = name
        while link not in tops and link not in path:
            path.append(link)
            if link not in above:
                break
            link = above[link]
        top = tops.get(link, link)
        for visited in path:
            tops[visited] = top
    members: dict[str, list[str]] = defaultdict(list)
    for name, top in tops.items():
        members[top].append(name)
    bodies: dict[str, RigidBody] = {}
    for top, names in members.items():
        joint = parent_joints.get(top)
        if len(names) > 1:
            names.sort(key=lambda n: n != top)  # the top link first, the rest in file order
        body = RigidBody(joint if joint is not None and joint.moving else None, tuple(names))
        for name in names:
            bodies[name] = body
    return bodies


def subtree_masses(robot: Robot, mass: Callable[[str], float]) -> dict[str, float]:
    """Each link's mass plus the mass of every link below it, for the links the roots reach."""
    children = children_by_joint_name(robot)
    total: dict[str, float] = {}
    for order in walks(robot).values():
        for link in reversed(order):  # every link after the links below it
            carried = mass(link)
            for joint in children.get(link, ()):
                if joint.child != link:
                    carried += total.get(joint.child, 0.0)
            total[link] = carried
    return total


def bodies(loaded) -> dict[str, RigidBody]:
    """Each link's rigid body in a loaded model, worked out once."""
    return once(loaded, _bodies)


def _bodies(loaded) -> dict[str, RigidBody]:
    return rigid_bodies(loaded.robot, loaded.parent_joints)


def link_mass(robot: Robot, name: str) -> float:
    """A link's declared mass when positive, else 0."""
    inertial = robot.links[name].inertial
    mass = inertial.mass if inertial is not None else None
    return mass if mass is not None and mass > 0 else 0.0


def body_mass(loaded, body: RigidBody) -> float:
    return sum(link_mass(loaded.robot, name) for name in body.links)
