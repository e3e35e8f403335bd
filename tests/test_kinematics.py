"""The kinematic walks and rigid bodies on arbitrary joint graphs: trees, links with
two parents, loops (of fixed joints too) and joints naming missing links."""

from __future__ import annotations

import networkx as nx
from hypothesis import given, settings
from hypothesis import strategies as st

from urdfcli.model.kinematics import build_graph, children_by_joint_name, has_loop, reached, rigid_bodies, roots, subtree_masses, walk
from urdfcli.model.load import Loaded
from urdfcli.model.robot import IDENTITY, Joint, Link, Robot
from urdfcli.read.document import Document

LINKS = [f"l{i}" for i in range(8)]
# a parent or child may name a link that does not exist ("gone"), or none at all
ENDS = st.sampled_from([*LINKS, "gone", None])


def _robot(links: int, joints: list[tuple[str | None, str | None, str | None]]) -> Robot:
    robot = Robot("r", 0)
    for name in LINKS[:links]:
        robot.links[name] = Link(name, len(robot.links) + 1, None, (), ())
    for number, (kind, parent, child) in enumerate(joints):
        name = f"j{number}"
        robot.joints[name] = Joint(name, 100 + number, kind, parent, child, IDENTITY, (1.0, 0.0, 0.0), None, None)
    return robot


GRAPHS = st.builds(
    _robot,
    st.integers(1, len(LINKS)),
    st.lists(st.tuples(st.sampled_from(["fixed", "revolute", None]), ENDS, ENDS), max_size=12),
)


def _parent_joints(robot: Robot) -> dict[str, Joint]:
    return Loaded(Document("robot.urdf", None), robot=robot).parent_joints


@settings(max_examples=300, deadline=None)
@given(GRAPHS)
def test_reached_is_the_walk_in_its_order(robot):
    children = children_by_joint_name(robot)
    for start in robot.links:
        assert reached(children, start) == [link for _, _, link in walk(robot, start, children)]


@settings(max_examples=300, deadline=None)
@given(GRAPHS)
def test_links_joined_by_joints_that_do_not_move_share_a_body(robot):
    parents = _parent_joints(robot)
    bodies = rigid_bodies(robot, parents)
    assert set(bodies) == set(robot.links)
    for name, body in bodies.items():
        assert name in body.links and body.links.count(name) == 1
        assert all(bodies[member] is body for member in body.links)
        joint = parents.get(name)
        if joint is not None and not joint.moving and joint.parent in robot.links:
            assert bodies[joint.parent] is body
        top_joint = parents.get(body.top)
        assert body.joint is (top_joint if top_joint is not None and top_joint.moving else None)


@settings(max_examples=300, deadline=None)
@given(GRAPHS, st.lists(st.floats(0, 10), min_size=len(LINKS), max_size=len(LINKS)))
def test_subtree_mass_of_a_tree_root_is_the_mass_of_what_it_reaches(robot, masses):
    mass = dict(zip(LINKS, masses)).__getitem__
    totals = subtree_masses(robot, mass)
    children = children_by_joint_name(robot)
    has_two_parents = any(
        sum(1 for joints in children.values() for joint in joints if joint.child == link) > 1 for link in robot.links
    )
    for root in roots(robot):
        below = reached(children, root)
        assert set(below) <= set(totals)
        if not has_two_parents:  # in a tree each link's mass is carried once
            assert abs(totals[root] - sum(mass(link) for link in below)) < 1e-6 * (1 + totals[root])


@settings(max_examples=300, deadline=None)
@given(GRAPHS)
def test_a_loop_is_found_as_networkx_finds_one(robot):
    assert has_loop(robot) is not nx.is_directed_acyclic_graph(build_graph(robot))


@settings(max_examples=300, deadline=None)
@given(GRAPHS)
def test_children_and_roots_are_those_of_the_joints_naming_two_links(robot):
    links = robot.links
    edges = [robot.joints[name] for name in sorted(robot.joints) if robot.joints[name].parent in links and robot.joints[name].child in links]
    children = children_by_joint_name(robot)
    for link in links:
        assert children.get(link, []) == [joint for joint in edges if joint.parent == link]
    assert set(children) <= set(links)
    assert roots(robot) == [link for link in links if not any(joint.child == link for joint in edges)]
