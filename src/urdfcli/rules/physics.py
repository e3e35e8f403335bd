"""Physics rules on declared mass properties (warnings: the model loads, but is wrong)."""

from __future__ import annotations

from .. import massprops
from ..numbers import format_number
from . import WARNING, check


def _inertials(loaded):
    for link in loaded.robot.links.values():
        inertial = link.inertial
        if inertial is not None and inertial.mass is not None:
            yield link, inertial


def moved_by_joint(loaded, link_name: str) -> bool:
    joint = loaded.parent_joint(link_name)
    return joint is not None and joint.moving


@check("I001", "negative-mass", WARNING, "A link with negative mass.")
def negative_mass(loaded):
    """## What it does
    Flags a link whose `<mass value>` is negative.

    ## Why is this bad?
    Mass is never negative; simulators reject the model or explode on it.

    ## Example
    ```xml
    <link name="base_link">
      <inertial><mass value="-1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="base_link">
      <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    </link>
    ```
    """
    for link, inertial in _inertials(loaded):
        if inertial.mass < 0:
            yield loaded.diagnostic("I001", f"link '{link.name}' has negative mass {format_number(inertial.mass)}", inertial.element.find("mass"))


@check("I002", "massless-moving-link", WARNING, "A link with zero mass moved by a non-fixed joint.")
def massless_moving_link(loaded):
    """## What it does
    Flags a link with no mass (no `<inertial>`, or mass 0) that a non-fixed joint moves,
    in a model where some link declares inertia. Purely kinematic models
    (no `<inertial>` anywhere) are not flagged.

    ## Why is this bad?
    A massless body driven by a joint has no dynamics: Gazebo drops it, and
    KDL's dynamic solvers cannot handle it.

    ## Example
    ```xml
    <link name="base_link">
      <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    </link>
    <link name="arm_link"/>
    <joint name="arm_joint" type="continuous">
      <parent link="base_link"/>
      <child link="arm_link"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link">
      <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    </link>
    <link name="arm_link">
      <inertial><mass value="0.5"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    </link>
    <joint name="arm_joint" type="continuous">
      <parent link="base_link"/>
      <child link="arm_link"/>
    </joint>
    ```
    """
    if not any(link.inertial is not None for link in loaded.robot.links.values()):
        return
    for link in loaded.robot.links.values():
        inertial = link.inertial
        massless = inertial is None or inertial.mass == 0
        if massless and moved_by_joint(loaded, link.name):
            element = inertial.element.find("mass") if inertial is not None else link.element
            yield loaded.diagnostic("I002", f"link '{link.name}' has no mass but is moved by joint '{loaded.parent_joint(link.name).name}'", element, hint="give it a mass and inertia, or attach it with a fixed joint")


@check("I003", "massless-with-inertia", WARNING, "A link with zero mass but a non-zero inertia tensor.")
def massless_with_inertia(loaded):
    """## What it does
    Flags a link with mass 0 and an inertia tensor that is not all zero.

    ## Why is this bad?
    A tensor without mass is contradictory: one of the two values is wrong.
    (Frame links with mass 0 and a zero tensor are fine.)

    ## Example
    ```xml
    <link name="tool_link">
      <inertial><mass value="0"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="tool_link">
      <inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial>
    </link>
    ```
    """
    for link, inertial in _inertials(loaded):
        if inertial.mass == 0 and inertial.inertia and not massprops.is_zero(massprops.matrix(inertial.inertia)):
            yield loaded.diagnostic("I003", f"link '{link.name}' has mass 0 but a non-zero inertia tensor", inertial.element.find("inertia"))


@check("I004", "point-mass", WARNING, "A link with positive mass and an all-zero inertia tensor.")
def point_mass(loaded):
    """## What it does
    Flags a link with positive mass and an all-zero inertia tensor.

    ## Why is this bad?
    A real body has extent; with a zero tensor turning it costs nothing, and
    physics engines become unstable.

    ## Example
    ```xml
    <link name="base_link">
      <inertial><mass value="2"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="base_link">
      <inertial><mass value="2"/><inertia ixx="0.02" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.02"/></inertial>
    </link>
    ```
    """
    for link, inertial in _inertials(loaded):
        if inertial.mass > 0 and inertial.inertia and massprops.is_zero(massprops.matrix(inertial.inertia)):
            yield loaded.diagnostic("I004", f"link '{link.name}' has mass {format_number(inertial.mass)} but a zero inertia tensor", inertial.element.find("inertia"))


@check("I005", "inertia-not-positive-semidefinite", WARNING, "An inertia tensor with a negative principal moment.")
def not_positive_semidefinite(loaded):
    """## What it does
    Flags an inertia tensor with a negative principal moment (it is not positive
    semi-definite), including ones made so by off-diagonal terms.

    ## Why is this bad?
    Principal moments of inertia are never negative; a simulator given such a
    tensor gains energy from nowhere.

    ## Example
    ```xml
    <link name="base_link">
      <inertial><mass value="2"/><inertia ixx="1" ixy="0" ixz="0" iyy="0" iyz="1" izz="1"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="base_link">
      <inertial><mass value="2"/><inertia ixx="0.0167" ixy="0" ixz="0" iyy="0.0433" iyz="0" izz="0.0567"/></inertial>
    </link>
    ```
    """
    for link, inertial in _inertials(loaded):
        if inertial.inertia:
            tensor = massprops.matrix(inertial.inertia)
            if not massprops.is_positive_semidefinite(tensor):
                moments = ", ".join(f"{m:.6g}" for m in massprops.principal_moments(tensor))
                yield loaded.diagnostic("I005", f"inertia of link '{link.name}' is not positive semi-definite (principal moments {moments})", inertial.element.find("inertia"))


@check("I006", "inertia-triangle-inequality", WARNING, "Principal moments that break the triangle inequality.")
def triangle_inequality(loaded):
    """## What it does
    Flags a tensor whose principal moments break the triangle inequality
    (A + B >= C for any ordering), with a small relative tolerance.

    ## Why is this bad?
    No rigid body has such moments; Gazebo and other engines reject or mishandle
    them (the PR2's `sensor_mount_link` has this mistake).

    ## Example
    ```xml
    <link name="base_link">
      <inertial><mass value="1"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.01"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="base_link">
      <inertial><mass value="1"/><inertia ixx="0.006" ixy="0" ixz="0" iyy="0.006" iyz="0" izz="0.01"/></inertial>
    </link>
    ```
    """
    for link, inertial in _inertials(loaded):
        if inertial.inertia:
            tensor = massprops.matrix(inertial.inertia)
            if massprops.is_positive_semidefinite(tensor):
                broken = massprops.triangle_violation(tensor)
                if broken:
                    a, b, c = broken
                    yield loaded.diagnostic("I006", f"inertia of link '{link.name}' breaks the triangle inequality: {a:.6g} + {b:.6g} < {c:.6g}", inertial.element.find("inertia"))
