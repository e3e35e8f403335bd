"""Each link's pose in the root frame at zero joint positions, through yourdfpy's scene graph
(imported only when a pose is asked for)."""

from __future__ import annotations

import contextlib
import warnings

from . import massprops
from .kinematics import roots, walk
from .load import Loaded
from .massprops import Transform
from .robot import Joint


def link_poses(loaded: Loaded) -> dict[str, Transform]:
    """Each link's pose in the root frame at zero joint positions (a mimic joint at its offset).

    yourdfpy's scene graph gives each joint's transform; urdfcli chains them down the tree,
    because a root-to-link query multiplies the whole path each time (trimesh orders that
    product at a cost that grows with the path's length cubed: 20 s on a 200-link chain).
    Only the tree's joints are given to yourdfpy; the structure rules report the others."""
    root = loaded.root
    if root is None:
        return {}
    joints = [joint for _, joint, _ in walk(loaded.robot, root) if joint is not None]
    poses = {root: massprops.ORIGIN}
    if not joints:
        return poses
    scene = kinematic_scene(loaded.robot.name or "robot", root, joints)
    for joint in joints:
        matrix = scene.get_transform(joint.child, joint.parent)
        step = (tuple(tuple(float(v) for v in row[:3]) for row in matrix[:3]), tuple(float(v) for v in matrix[:3, 3]))
        poses[joint.child] = massprops.compose(poses[joint.parent], step)
    return poses


def body_poses(loaded: Loaded, links) -> dict[str, Transform]:
    """Each of ``links`` placed in the frame of the first, an ancestor of them all, through
    the joints' origins; each pose is composed once, from its parent's (a body of 20,000
    fixed links costs 20,000 products, not one walk to the top per link)."""
    top = links[0]
    poses = {top: massprops.ORIGIN}
    for link in links:
        path = []  # the links above ``link`` whose poses are not known yet, lowest first
        while link not in poses:
            joint = loaded.parent_joint(link)
            if joint is None:  # a root reached: the top was not above (the chain up to it is kept)
                poses[link] = massprops.ORIGIN
                break
            path.append((link, joint))
            link = joint.parent
        for name, joint in reversed(path):
            poses[name] = massprops.compose(poses[joint.parent], massprops.transform(joint.origin.xyz, joint.origin.rpy))
    return poses


def kinematic_scene(name: str, root: str, joints: list[Joint]):
    """A yourdfpy model of the kinematic tree alone (no geometry), at zero joint positions.

    At zero positions only a mimic joint's offset moves a joint, so the others are given
    as fixed: yourdfpy looks each moving joint up in a list, which would make setting up
    a large robot quadratic in its joints."""
    import numpy
    import trimesh.transformations as tra
    import yourdfpy

    def joint_of(joint: Joint) -> yourdfpy.Joint:
        matrix = tra.euler_matrix(*joint.origin.rpy, axes="sxyz")
        matrix[:3, 3] = joint.origin.xyz
        # a zero axis (reported by J007) gives no direction to move along
        moves = joint.mimic is not None and joint.type in ("revolute", "continuous", "prismatic") and any(joint.axis)
        return yourdfpy.Joint(
            name=joint.name, type=joint.type if moves else "fixed", parent=joint.parent, child=joint.child, origin=matrix,
            axis=numpy.array(joint.axis) if moves else None,
            mimic=yourdfpy.Mimic(joint.mimic.joint, joint.mimic.multiplier, joint.mimic.offset) if moves else None,
        )

    links = [yourdfpy.Link(name=root)] + [yourdfpy.Link(name=joint.child) for joint in joints]
    with quiet_libraries():
        return yourdfpy.URDF(yourdfpy.Robot(name=name, links=links, joints=[joint_of(j) for j in joints]), load_meshes=False)


@contextlib.contextmanager
def quiet_libraries():
    """yourdfpy and trimesh log warnings to stderr (and yourdfpy calls a deprecated trimesh
    function); urdfcli reports the problems itself."""
    import logging  # only where a pose is worked out

    loggers = [logging.getLogger(name) for name in ("yourdfpy", "trimesh")]
    levels = [logger.level for logger in loggers]
    for logger in loggers:
        logger.setLevel(logging.CRITICAL)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            yield
    finally:
        for logger, level in zip(loggers, levels):
            logger.setLevel(level)


def zero_poses(loaded: Loaded) -> dict[str, Transform]:
    """Each link reached from a root, in that root's frame with every joint at 0 (a mimic
    joint too: its offset is not applied), composed once each from its parent's along the
    tree's walk (a link with two parents is placed through the first the walk meets)."""
    poses: dict[str, Transform] = {}
    robot = loaded.robot
    for root in roots(robot):
        for _, joint, link in walk(robot, root):
            parent = poses[joint.parent] if joint is not None else massprops.ORIGIN
            poses[link] = massprops.compose(parent, massprops.transform(joint.origin.xyz, joint.origin.rpy)) if joint is not None else parent
    return poses
