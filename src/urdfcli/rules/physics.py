"""Physics rules on declared mass properties (warnings: the model loads, but is wrong)."""

from __future__ import annotations

from ..read.memo import once
from ..model import massprops
from ..model.inertia import implied
from ..model.kinematics import bodies, body_mass, link_mass, subtree_masses, walk
from ..model.numbers import format_number
from .base import ERROR, UNSAFE, WARNING, Kind, Remedy, check


def _inertials(loaded):
    for link in loaded.robot.links.values():
        inertial = link.inertial
        if inertial is not None and inertial.mass is not None:
            yield link, inertial


def moved_by_joint(loaded, link_name: str) -> bool:
    joint = loaded.parent_joint(link_name)
    return joint is not None and joint.moving


MATERIAL = 0.05
"""A lumped link's tensor matters when it adds this much to the rest of its body's
(the largest moment): TurtleBot3's 5 g casters carrying 0.001 kg·m² add 11 % each."""


def absorbed(loaded, link) -> bool:
    """A link lighter than massprops.LIGHT fixed to a body that weighs more without it
    (a sensor frame, a dummy link) whose tensor adds nothing material to that body's:
    simulators lump it into the body, where it is lost in the noise, so its mass
    properties are left alone. One whose tensor changes the body's is judged as any link."""
    robot = loaded.robot
    own = link_mass(robot, link.name)
    if own >= massprops.LIGHT:
        return False
    body = bodies(loaded)[link.name]
    if body_mass(loaded, body) - own < massprops.LIGHT:
        return False
    inertial = link.inertial
    if inertial is None or not inertial.inertia:
        return True
    rest = sum(_largest_moment(robot.links[name]) for name in body.links if name != link.name)
    return massprops.scale_of(tensor_of(inertial)) <= MATERIAL * rest


POINT_SHARE = 0.1
"""A link with a zero tensor carrying at most this share of its body's mass is lost in it
(Stretch's 75 g laser on its 15 kg base, ROS-Industrial's 0.4 kg link_t fixed to its 4.8 kg
tool flange), unless its shapes show it would turn the body materially."""


def point_in_body(loaded, link) -> bool:
    """A zero tensor on a link fixed to heavier links with tensors of their own: simulators
    lump the link into that body, its mass counted where it is, and only its own turning is
    missing. That is lost beside the body's when the link carries a small share of the mass
    (:data:`POINT_SHARE`) and a uniform body filling its shapes, where it has measurable
    ones, would add under :data:`MATERIAL` to the rest's largest moment."""
    own = link_mass(loaded.robot, link.name)
    body = bodies(loaded)[link.name]
    total = body_mass(loaded, body)
    rest = sum(_largest_moment(loaded.robot.links[name]) for name in body.links if name != link.name)
    if own > POINT_SHARE * total or rest <= 0:
        return False
    found = implied(loaded, link)
    return found.body is None or massprops.principal_moments(found.body.tensor)[2] <= MATERIAL * rest


def _largest_moment(link) -> float:
    inertial = link.inertial
    if inertial is None or not inertial.inertia or not (inertial.mass or 0) > 0:
        return 0.0
    return max(0.0, massprops.principal_moments(tensor_of(inertial))[2])


def tensor_of(inertial):
    """The declared tensor with rounding noise (elements below massprops.ZERO_FLOOR) zeroed."""
    return massprops.floored(massprops.matrix(inertial.inertia))


def moments_text(moments) -> str:
    """Principal moments, with those that are noise next to the largest written as 0."""
    return ", ".join(f"{m:.6g}" for m in massprops.without_noise(moments))


@check("I001", "negative-mass", ERROR, "A link with negative mass.", kind=Kind.MASS, remedy=Remedy.INERTIAL)
def negative_mass(loaded, given):
    """## What it does
    Flags a link whose `<mass value>` is negative: an error, like a negative size.

    ## Why is this bad?
    Mass is never negative and no consumer can simulate it: MuJoCo and
    Gazebo refuse the model, Drake replaces the body with a 1 kg sphere,
    Pinocchio and PyBullet load it and their dynamics diverge.

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
            yield loaded.diagnostic("I001", f"link '{link.name}' has negative mass {format_number(inertial.mass)}", inertial.mass_at, subjects=(link.name,))


@check("I002", "massless-moving-link", WARNING, "A joint that moves only massless links.", kind=Kind.MASS, remedy=Remedy.INERTIAL)
def massless_moving_link(loaded, given):
    """## What it does
    Flags a moving joint when nothing it moves has mass: the link it carries and every
    link below it are massless (no `<inertial>`, or mass 0). Reported once, at the
    highest such joint, naming the links; the joints further down the same massless
    branch are not reported again. A massless link between two joints is fine when the
    links beyond it have mass (a ball joint written as three revolute joints), and so
    are massless frames on fixed joints. Purely kinematic models (no `<inertial>`
    anywhere) are not flagged.

    ## Why is this bad?
    A joint that moves no mass has no dynamics: the mass matrix is singular, so
    forward dynamics (Pinocchio, KDL, Drake) fails, and Gazebo drops the links.

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
    robot = loaded.robot
    if not any(link.inertial is not None for link in robot.links.values()):
        return
    if all(link_mass(robot, name) > 0 for name in robot.links):
        return  # every joint moves some mass (the common case, told without walking the tree)
    carried = subtree_masses(robot, lambda name: link_mass(robot, name))
    for joint in robot.joints.values():
        if not joint.moving or joint.child not in carried or joint.parent not in robot.links or carried[joint.child] > 0:
            continue
        above = bodies(loaded)[joint.parent].joint
        if above is not None and carried.get(above.child, 1.0) == 0:
            continue  # reported at the joint above, which moves this branch too
        branch = _branch(robot, joint.child)
        link = robot.links[joint.child]
        names = ", ".join(f"'{n}'" for n in branch[:4]) + (f" and {len(branch) - 4} more" if len(branch) > 4 else "")
        what = f"link {names}" if len(branch) == 1 else f"links {names}"
        negative = [n for n in branch if (robot.links[n].inertial and robot.links[n].inertial.mass or 0) < 0]
        none = "no positive mass (I001: a negative mass)" if negative else "none"
        at = link.inertial.mass_at if link.inertial is not None else None
        yield loaded.diagnostic(
            "I002",
            f"joint '{joint.name}' moves no mass: {what} {'has' if len(branch) == 1 else 'have'} {none}, so the mass matrix is singular",
            at if at is not None else link.at,
            hint="give the moving links their mass and inertia, or make the joint fixed",
            subjects=(joint.child, joint.name),
        )


def _branch(robot, top: str) -> list[str]:
    """The link and every link below it, depth first."""
    return [link for _, _, link in walk(robot, top)]


@check("I003", "massless-with-inertia", WARNING, "A link with zero mass but a non-zero inertia tensor.", kind=Kind.MASS, remedy=Remedy.INERTIAL)
def massless_with_inertia(loaded, given):
    """## What it does
    Flags a link with mass 0 and an inertia tensor that is not all zero. A massless
    link fixed to a body with mass, whose tensor adds less than 5 % to the body's
    largest moment, is left alone: lumped into that body it changes nothing (Bolt's
    feet: 5e-7 kg·m² on a lower leg).

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
        if inertial.mass != 0 or not inertial.inertia:
            continue
        tensor = massprops.matrix(inertial.inertia)
        if not massprops.is_zero(tensor) and not absorbed(loaded, link):
            yield loaded.diagnostic("I003", f"link '{link.name}' has mass 0 but a non-zero inertia tensor", inertial.inertia_at, subjects=(link.name,))


@check("I004", "point-mass", WARNING, "A link with positive mass and an all-zero inertia tensor.", kind=Kind.MASS, remedy=Remedy.INERTIAL, fix=UNSAFE)
def point_mass(loaded, given):
    """## What it does
    Flags a link with positive mass and an all-zero inertia tensor. Elements below
    1e-12 kg·m² count as zero (rounding noise such as `2.4e-35`). Left alone: a link
    lighter than 20 g fixed to a heavier body (a sensor or tool frame), and a link fixed
    to links with tensors of their own, carrying a tenth of their body's mass or less,
    whose shapes (where they can be measured) would add under 5 % to the body's largest
    moment (Stretch's 75 g laser on its base): lumped into that body, its mass counted
    where it is, its zero tensor changes nothing material.

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
        if inertial.mass > 0 and inertial.inertia and verdict(loaded, inertial)[0] == "I004" and not absorbed(loaded, link) and not point_in_body(loaded, link):
            zero = "a zero" if massprops.is_zero(massprops.matrix(inertial.inertia)) else "a near-zero"
            yield loaded.diagnostic(
                "I004",
                f"link '{link.name}' has mass {format_number(inertial.mass)} but {zero} inertia tensor: a point mass",
                inertial.inertia_at,
                "`urdfcli inertia --suggest` prints the tensor of a uniform body filling its geometry",
                subjects=(link.name,),
            )


@check("I005", "inertia-not-positive-semidefinite", ERROR, "An inertia tensor with a negative principal moment.", kind=Kind.MASS, remedy=Remedy.INERTIAL, fix=UNSAFE)
def not_positive_semidefinite(loaded, given):
    """## What it does
    Flags an inertia tensor with a negative principal moment (it is not positive
    semi-definite), including ones made so by off-diagonal terms. Elements below
    1e-12 kg·m² count as zero; a tensor made only of such noise is a point mass (I004).
    An error whatever the link's mass; on a link lighter than 20 g fixed to a heavier
    body, whose tensor adds less than 5 % to the body's largest moment, a warning that
    names MuJoCo, which refuses the model whatever the lumping, and Drake, which replaces the
    tensor (TIAGo's 1 mg antennas).

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
    for link, moments in invalid_tensors(loaded)["I005"]:
        sign, hint = sign_convention(link.inertial)
        yield _light(loaded, link, "I005", f"inertia of link '{link.name}' is not positive semi-definite (principal moments {moments_text(moments)}){sign}", hint)


@check("I006", "inertia-triangle-inequality", WARNING, "Principal moments that break the triangle inequality.", kind=Kind.MASS, remedy=Remedy.INERTIAL, fix=UNSAFE)
def triangle_inequality(loaded, given):
    """## What it does
    Flags a tensor whose principal moments break the triangle inequality
    (A + B >= C for any ordering), with a small relative tolerance. Elements below
    1e-12 kg·m² count as zero; a tensor made only of such noise is a point mass (I004).
    A link lighter than 20 g fixed to a heavier body, whose tensor adds less than 5 % to
    the body's largest moment, is a warning naming MuJoCo, which refuses the model, and
    Drake, which replaces the tensor.

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
    for link, moments in invalid_tensors(loaded)["I006"]:
        a, b, c = moments_text(moments).split(", ")
        sign, hint = sign_convention(link.inertial)
        yield _light(loaded, link, "I006", f"inertia of link '{link.name}' breaks the triangle inequality: {a} + {b} < {c}{sign}", hint)


SIGN_CONVENTION = "; with its products of inertia negated it is valid: the other sign convention for them (∫xy dm for -∫xy dm), which some CAD tools export"


def sign_convention(inertial) -> tuple[str, str | None]:
    """What to add to the message, and the hint, when negating the products of inertia
    (ixy, ixz, iyz) makes an invalid tensor valid: a CAD sign convention, not a made-up tensor."""
    negated = massprops.negated_products(tensor_of(inertial))
    if _tensor_verdict(negated)[0] is not None:
        return "", None
    return SIGN_CONVENTION, f"negate the products of inertia: {massprops.inertia_element(negated)}"


def invalid_tensors(loaded) -> dict[str, list]:
    """For I005 and I006: (link, principal moments) for each tensor no body can have;
    worked out once (the placeholder rules leave these links to them)."""
    return once(loaded, _invalid_tensors)


def _invalid_tensors(loaded) -> dict[str, list]:
    """Each impossible tensor, whatever the link's mass: a light link fixed to a heavier
    body (see :func:`absorbed`) is listed in "light", which makes a warning."""
    found: dict[str, list] = {"I005": [], "I006": [], "light": []}
    for link, inertial in _inertials(loaded):
        if not inertial.inertia:
            continue
        code, detail = verdict(loaded, inertial)
        if code in ("I005", "I006"):
            found[code].append((link, detail))
            if absorbed(loaded, link):
                found["light"].append(link.name)
    return found


LUMPED = ("; MuJoCo refuses the model (it checks each link's tensor before it lumps fixed links) and Drake replaces the tensor, "
          "though lumped into its body the link changes little elsewhere")


def _light(loaded, link, code: str, message: str, hint: str | None):
    """I005 or I006 on a link: an error (I006 a warning); a warning naming the consumer that
    refuses it on a light link fixed to a heavier body, where lumping makes it harmless."""
    if link.name not in invalid_tensors(loaded)["light"]:
        return loaded.diagnostic(code, message, link.inertial.inertia_at, hint, subjects=(link.name,))
    found = loaded.diagnostic(code, message + LUMPED, link.inertial.inertia_at, hint, subjects=(link.name,))
    return found.with_severity(WARNING)


def _judged(loaded) -> dict:
    return {}


def verdict(loaded, inertial) -> tuple[str | None, tuple | None]:
    """What I004, I005 and I006 find in a declared tensor (see :func:`_tensor_verdict`).
    Links that write the same text share its tensor: it is judged once."""
    judged = once(loaded, _judged)
    key = id(inertial.inertia)
    if key not in judged:
        judged[key] = _tensor_verdict(tensor_of(inertial))
    return judged[key]


def _tensor_verdict(tensor) -> tuple[str | None, tuple | None]:
    """("I004", None) for a point mass, ("I005", principal moments), ("I006", the moments
    breaking the triangle), or (None, None) for a tensor a body can have."""
    if massprops.is_negligible(tensor):
        return "I004", None
    moments = massprops.principal_moments(tensor)  # worked out once for both questions
    if not massprops.is_positive_semidefinite(tensor, moments=moments):
        return "I005", moments
    broken = massprops.triangle_violation(tensor, moments=moments)
    return ("I006", broken) if broken is not None else (None, None)
