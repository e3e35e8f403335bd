"""KDL as robot_state_publisher builds it: kdl_parser 1.14 ``treeFromUrdfModel`` (kdl_parser/src/kdl_parser.cpp)."""

from __future__ import annotations

from ...rules.base import INFO, WARNING, Kind, check
from ...rules.targets.common import about_joint, inertial_at, joints_of


@check("C601", "kdl-fixed-floating-joint", WARNING, "KDL turns floating and planar joints into fixed ones.", kind=Kind.TARGET, target="kdl")
def fixed_floating_joint(loaded, given):
    """## What it does
    With `--target kdl`: finds a floating or planar joint.

    ## Why is this bad?
    KDL has neither: kdl_parser logs "Converting unknown joint type of joint 'NAME'
    into a fixed joint" (`toKdl`), and robot_state_publisher publishes the child as a
    static transform that never moves.

    ## Example
    ```xml
    <joint name="base_motion" type="planar">
      <parent link="world"/><child link="base"/><axis xyz="0 0 1"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <joint name="base_yaw" type="continuous">
      <parent link="world"/><child link="base"/><axis xyz="0 0 1"/>
    </joint>
    ```
    """
    for joint in joints_of(loaded, ("floating", "planar")):
        yield about_joint(
            loaded, "C601", joint,
            f"KDL makes {joint.type} joint '{joint.name}' fixed: robot_state_publisher will never move '{joint.child}'",
            "publish the base's motion from odometry or a joint_state of your own; KDL models joints of one degree of freedom",
        )


@check("C602", "kdl-root-inertia", INFO, "KDL drops the root link's inertia.", kind=Kind.TARGET, target="kdl")
def root_inertia(loaded, given):
    """## What it does
    With `--target kdl`: finds a root link with a positive mass.

    ## Why is this bad?
    The root is the KDL tree's base, not a segment: kdl_parser 1.14 warns "The root
    link NAME has an inertia specified in the URDF, but KDL does not support a root
    link with an inertia" and drops it; the ROS 2 kdl_parser (`TreeParser`) returns
    an error instead. Dynamics computed with KDL miss that mass.

    ## Example
    ```xml
    <robot name="arm">
      <link name="base"><inertial><mass value="4"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="arm">
      <link name="base_footprint"/>
      <link name="base"><inertial><mass value="4"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
      <joint name="base_joint" type="fixed"><parent link="base_footprint"/><child link="base"/></joint>
    </robot>
    ```
    """
    root = loaded.root
    if root is None:
        return
    inertial = loaded.robot.links[root].inertial
    if inertial is not None and inertial.mass is not None and inertial.mass > 0:
        yield loaded.diagnostic(
            "C602",
            f"KDL drops the inertia of root link '{root}' (the ROS 2 kdl_parser refuses it)",
            inertial_at(loaded, root),
            "add a massless root link above it, joined by a fixed joint",
            subjects=(root,),
        )
