"""Joint rules that need more than one element: axes, mimics and limits."""

from __future__ import annotations

import math

from ..diagnostics import Fix, SetAttribute
from ..model.numbers import format_number
from ..model.robot import MOVING_AXIS_TYPES
from .base import ERROR, INFO, PLACED, UNSAFE, WARNING, RuleSet, check, names

FULL_TURN = 2 * math.pi - 1e-3  # a range written as -3.1416..3.1416 is a full turn
UNIT_TOLERANCE = 1e-3  # an axis this close to length 1 is a unit axis written with few decimals
# two turns: a multi-turn wrist reaches +-720 degrees (4 pi); an angle written in degrees is beyond it from 13 degrees on
TWO_TURNS = 4 * math.pi + 1e-3
_NO_LIMIT_FIX = Fix("give the actuator's limits", UNSAFE, reason="no value is known: only the actuator's datasheet has its effort and speed")


@check("J007", "zero-axis", ERROR, "A moving joint whose axis is the zero vector.")
def zero_axis(loaded, given):
    """## What it does
    Flags a revolute, continuous, prismatic or planar joint whose `<axis xyz>` is `0 0 0`.

    ## Why is this bad?
    A moving joint needs a direction to move in; urdfdom accepts the zero vector,
    but KDL, MoveIt and Gazebo divide by its length.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <axis xyz="0 0 0"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <axis xyz="0 0 1"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        if joint.type in MOVING_AXIS_TYPES and not any(joint.axis):
            yield loaded.diagnostic("J007", f"{joint.type} joint '{joint.name}' has a zero axis", joint.part("axis"))


@check("J008", "mimic-joint-not-found", ERROR, "A `<mimic joint>` naming no joint.")
def mimic_not_found(loaded, given):
    """## What it does
    Flags a `<mimic joint>` that names a joint the robot does not have.

    ## Why is this bad?
    The joint a mimic follows must exist; robot_state_publisher and MoveIt fail
    to load the model otherwise.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
      <mimic joint="shoulder"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
      <mimic joint="arm_joint_2"/>
    </joint>
    <link name="forearm_link"/>
    <joint name="arm_joint_2" type="revolute">
      <parent link="arm_link"/>
      <child link="forearm_link"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        if joint.mimic and joint.mimic.joint != joint.name and joint.mimic.joint not in loaded.robot.joints:
            yield loaded.diagnostic("J008", f"joint '{joint.name}' mimics '{joint.mimic.joint}', which does not exist", joint.part("mimic"))


@check("J009", "mimic-self", ERROR, "A joint that mimics itself.")
def mimic_self(loaded, given):
    """## What it does
    Flags a joint whose `<mimic joint>` is the joint itself.

    ## Why is this bad?
    A joint cannot follow its own position: solvers loop or reject the model.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
      <mimic joint="arm_joint"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        if joint.mimic and joint.mimic.joint == joint.name:
            yield loaded.diagnostic("J009", f"joint '{joint.name}' mimics itself", joint.part("mimic"))


@check("J010", "limit-lower-above-upper", WARNING, "A joint limit whose lower bound is above its upper bound.", fix=UNSAFE,
       fix_doc="Swaps the two values where they were written (unsafe: the joint's range changes)." f" {PLACED}")
def lower_above_upper(loaded, given):
    """## What it does
    Flags a revolute or prismatic joint whose `lower` limit is above its `upper` limit.

    ## Why is this bad?
    No position satisfies lower > upper: controllers and planners refuse the joint,
    and simulators clamp it somewhere arbitrary.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="1.57" upper="-1.57" effort="10" velocity="1"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1.57" upper="1.57" effort="10" velocity="1"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        limit = joint.limit
        if joint.type in ("revolute", "prismatic") and limit and limit.lower > limit.upper:
            at = joint.part("limit")
            lower, upper = loaded.value(at, "lower"), loaded.value(at, "upper")
            changes = (SetAttribute(at, "lower", upper), SetAttribute(at, "upper", lower)) if lower and upper else ()
            yield loaded.diagnostic(
                "J010",
                f"joint '{joint.name}' has lower {format_number(limit.lower)} > upper {format_number(limit.upper)}",
                at,
                hint="swap lower and upper",
                subjects=(joint.name,),
            ).with_fix(Fix(f"swap lower and upper of joint '{joint.name}'", UNSAFE, changes=changes, reason=None if changes else "the limits are not written"))


@check("J011", "axis-not-unit", WARNING, "A joint axis that is not a unit vector.", rule_set=RuleSet.LINT)
def axis_not_unit(loaded, given):
    """## What it does
    Flags a moving joint whose axis is not a unit vector: its length is more than
    0.1 % from 1. Axes written with a few decimals (`0.707 0.707 0`, NAO's
    `0 0.999999 0`) are unit axes for every parser and are left alone.

    ## Why is this bad?
    urdfdom normalises the axis silently; a non-unit axis usually means a typo,
    such as `1 1 1` for a wheel that should turn about one axis.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="continuous">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <axis xyz="1 1 1"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="continuous">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <axis xyz="0 1 0"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        norm = math.sqrt(sum(c * c for c in joint.axis))
        if joint.type in MOVING_AXIS_TYPES and norm > 0 and abs(norm - 1.0) > UNIT_TOLERANCE:
            unit = " ".join(format_number(float(f"{c / norm:.6g}")) for c in joint.axis)
            hint = f'normalised: <axis xyz="{unit}"/>'
            yield loaded.diagnostic("J011", f"axis of joint '{joint.name}' has length {norm:.6g}, not 1", joint.part("axis"), hint)


@check("J012", "continuous-with-limits", WARNING, "A continuous joint given a range narrower than a turn.", rule_set=RuleSet.LINT)
def continuous_with_limits(loaded, given):
    """## What it does
    Flags a continuous joint whose `<limit>` gives both `lower` and `upper`, spanning
    less than a full turn. Left alone: a range of a turn or more (`-3.14159` to
    `3.14159`, a harmless leftover), an empty or reversed range (J010, J014), and a
    limit giving only one bound.

    ## Why is this bad?
    A continuous joint turns without end: urdfdom ignores its lower and upper, so a
    range narrower than a turn, which the author meant to hold, is not enforced.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="continuous">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        limit = joint.limit
        if joint.type != "continuous" or limit is None or not (limit.has_lower and limit.has_upper):
            continue
        span = limit.upper - limit.lower
        if 0 < span < FULL_TURN:
            yield loaded.diagnostic(
                "J012",
                f"continuous joint '{joint.name}' has the range [{format_number(limit.lower)}, {format_number(limit.upper)}], which is ignored",
                joint.part("limit"),
                hint="make it revolute to keep the range, or drop lower and upper",
            )


@check("J013", "limit-without-range", WARNING, "A revolute or prismatic joint whose <limit> gives neither lower nor upper.", rule_set=RuleSet.LINT)
def limit_without_range(loaded, given):
    """## What it does
    Flags a revolute or prismatic joint whose `<limit>` has neither `lower` nor `upper`.
    A limit giving one of the two is left alone (the other is 0, which can be meant).

    ## Why is this bad?
    urdfdom reads both as 0: the range is [0, 0], so every consumer that honours limits
    (MoveIt, ros2_control, Gazebo, Pinocchio) holds the joint still. Wheels written as
    revolute joints and knees copied without their range stop moving.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="wheel"/>
    <joint name="wheel_joint" type="revolute">
      <parent link="base_link"/>
      <child link="wheel"/>
      <axis xyz="0 1 0"/>
      <limit effort="10" velocity="5"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="wheel"/>
    <joint name="wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="wheel"/>
      <axis xyz="0 1 0"/>
      <limit effort="10" velocity="5"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        limit = joint.limit
        if joint.type in ("revolute", "prismatic") and limit is not None and not limit.has_lower and not limit.has_upper:
            turn = "make it continuous, or " if joint.type == "revolute" else ""
            yield loaded.diagnostic(
                "J013",
                f"{joint.type} joint '{joint.name}' has no lower or upper limit: urdfdom reads its range as [0, 0], so it cannot move",
                joint.part("limit"),
                hint=f'{turn}give the range: <limit lower="..." upper="..."/>',
            )


@check("J014", "limit-effort-velocity-zero", WARNING, "A moving joint whose effort or velocity limit is zero or negative.", rule_set=RuleSet.LINT)
def effort_velocity_zero(loaded, given):
    """## What it does
    Flags a revolute, continuous or prismatic joint, not a mimic, whose `<limit>` gives
    `effort` or `velocity` as 0 or less. A joint that no `<transmission>` and no
    `<ros2_control>` names is passive (a caster, a propeller spun by a plugin, a
    pendulum): zero limits there say it has no actuator, and are only noted (info),
    in one note for all such joints of the model (a description of the kinematics
    alone, as ROS-Industrial's arms are, writes `effort="0"` on every joint);
    a negative limit is flagged wherever it is. Driven joints with the same limits
    are named in one warning. Mimic joints are left alone: they follow another joint
    and are not driven.

    ## Why is this bad?
    The limits bound what a controller may command and what a simulator lets the joint do:
    ros2_control's joint limiter clamps commands to them, Gazebo's motor has no force with a
    zero effort, and MoveIt, which reads no effort, cannot time a trajectory over a joint
    without a velocity limit: the actuator the transmission describes moves nothing.
    A negative limit is meaningless.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="finger"/>
    <joint name="finger_joint" type="revolute">
      <parent link="base_link"/>
      <child link="finger"/>
      <limit lower="0" upper="1" effort="0" velocity="0"/>
    </joint>
    <transmission name="finger_transmission">
      <type>transmission_interface/SimpleTransmission</type>
      <joint name="finger_joint"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    </transmission>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="finger"/>
    <joint name="finger_joint" type="revolute">
      <parent link="base_link"/>
      <child link="finger"/>
      <limit lower="0" upper="1" effort="2" velocity="1.5"/>
    </joint>
    <transmission name="finger_transmission">
      <type>transmission_interface/SimpleTransmission</type>
      <joint name="finger_joint"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    </transmission>
    ```
    """
    driven = driven_joints(loaded)
    passive = []  # (joint, its zero limits) of the joints nothing drives
    stalled = {}  # the limits written, and the limit names, -> the driven joints that have them
    for joint in loaded.robot.joints.values():
        limit = joint.limit
        if joint.type not in ("revolute", "continuous", "prismatic") or limit is None or joint.mimic is not None:
            continue
        values = [(name, value) for name, value in (("effort", limit.effort), ("velocity", limit.velocity)) if value is not None and value <= 0]
        if not values:
            continue
        bad = " and ".join(f"{name}={format_number(value)}" for name, value in values)
        if joint.name in driven or any(value < 0 for _, value in values):
            stalled.setdefault((bad, tuple(name for name, _ in values)), []).append(joint)
        else:
            passive.append((joint, bad))
    for (bad, limited), joints in stalled.items():  # an arm's joints often share one placeholder: one warning for them all
        listed = [joint.name for joint in joints]
        what = f"joint '{listed[0]}' has" if len(listed) == 1 else f"{len(listed)} joints ({names(listed)}) have"
        them = "it" if len(listed) == 1 else "them"
        message = (f"{what} {bad}: a controller that honours its limits ({_honouring(limited)}) "
                   f"commands {them} {_nothing(limited)}, so it cannot move {them}")
        yield loaded.diagnostic("J014", message, joints[0].part("limit"), "give the actuator's real effort and velocity limits (the datasheet's peak torque or force, and speed)",
                                subjects=tuple(listed)).with_fix(_NO_LIMIT_FIX)
    if len(passive) == 1:
        joint, bad = passive[0]
        message = f"joint '{joint.name}' has {bad}: no transmission or ros2_control drives it, so it is taken as passive (no actuator)"
        yield loaded.diagnostic("J014", message, joint.part("limit"), "if an actuator drives it, give its real effort and velocity limits",
                                subjects=(joint.name,))._replace(severity=INFO).with_fix(_NO_LIMIT_FIX)
    elif passive:  # one note for the model: a description of the kinematics alone (ROS-Industrial's arms) writes effort="0" on every joint
        listed = [joint.name for joint, _ in passive]
        message = f"{len(listed)} joints ({names(listed)}) have a zero effort or velocity limit and no transmission or ros2_control drives them, so they are taken as passive (no actuator)"
        yield loaded.diagnostic("J014", message, passive[0][0].part("limit"), "if actuators drive them, give their real effort and velocity limits",
                                subjects=tuple(listed))._replace(severity=INFO).with_fix(_NO_LIMIT_FIX)


def _nothing(limited) -> str:
    """What a controller clamped to these limits ('effort', 'velocity') commands."""
    return " and ".join("no torque or force" if name == "effort" else "no speed" for name in limited)


def _honouring(limited) -> str:
    """The consumers that honour these limits: MoveIt reads no effort, only velocity."""
    readers = ["ros2_control's limiter"]
    if "velocity" in limited:
        readers.append("MoveIt")
    if "effort" in limited:
        readers.append("Gazebo's motor")
    return ", ".join(readers)


def driven_joints(loaded) -> set[str]:
    """The joints a <transmission> or a <ros2_control> block names."""
    robot = loaded.robot
    return {element.get("name") for tag in ("transmission", "ros2_control") for block in robot.blocks(tag) for element in block.iterfind("joint")}


@check("J015", "soft-limits-outside-limits", WARNING, "A safety controller's soft limits outside the joint's limits.", rule_set=RuleSet.LINT)
def soft_limits_outside_limits(loaded, given):
    """## What it does
    Flags a revolute or prismatic joint whose `<safety_controller>` sets
    `soft_lower_limit` below its `<limit lower>`, or `soft_upper_limit` above its
    `<limit upper>`. Soft limits at or within the hard limits are left alone.

    ## Why is this bad?
    The safety controller (pr2_controller_manager, ros_control's joint limits
    interface) lets the joint go as far as its soft limits before it pushes back: soft
    limits beyond the hard ones never act, and the joint meets its hard stop at full
    speed. They were meant to sit a little inside.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1.5" upper="1.5" effort="10" velocity="1"/>
      <safety_controller soft_lower_limit="-1.6" soft_upper_limit="1.6" k_position="100" k_velocity="10"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1.5" upper="1.5" effort="10" velocity="1"/>
      <safety_controller soft_lower_limit="-1.4" soft_upper_limit="1.4" k_position="100" k_velocity="10"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        limit, safety = joint.limit, joint.safety
        if joint.type not in ("revolute", "prismatic") or limit is None or safety is None or not (limit.has_lower or limit.has_upper):
            continue
        outside = []
        if safety.soft_lower is not None and limit.has_lower and safety.soft_lower < limit.lower:
            outside.append(f"soft_lower_limit {format_number(safety.soft_lower)} is below lower {format_number(limit.lower)}")
        if safety.soft_upper is not None and limit.has_upper and safety.soft_upper > limit.upper:
            outside.append(f"soft_upper_limit {format_number(safety.soft_upper)} is above upper {format_number(limit.upper)}")
        if outside:
            yield loaded.diagnostic(
                "J015", f"joint '{joint.name}': {' and '.join(outside)}, so the safety controller never acts before the hard stop",
                joint.part("safety_controller"), "put the soft limits at or inside the <limit> range", subjects=(joint.name,),
            )


@check("J016", "limit-in-degrees", WARNING, "A revolute joint's limit written in degrees.", rule_set=RuleSet.LINT, fix=UNSAFE,
       fix_doc="Writes each limit beyond two turns in radians, where it was written (unsafe: the joint's range changes)." f" {PLACED}")
def limit_in_degrees(loaded, given):
    """## What it does
    Flags a revolute joint whose `lower` or `upper` limit is beyond two turns
    (4 pi, 720 degrees): such a number is degrees where URDF takes radians
    (`upper="90"`). Multi-turn wrists reach +-720 degrees (4 pi) at most, and
    are left alone; a limit of 12 degrees or less written in degrees cannot be
    told from radians and is left alone too, and so is a number beyond 720,
    which is no angle in degrees (`1e16`: a limit that means none).

    ## Why is this bad?
    `upper="90"` lets the joint turn 90 radians, about 14 turns: planners and
    simulators take the joint as free, and the real joint hits its stop.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-90" upper="90" effort="10" velocity="1"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1.570796" upper="1.570796" effort="10" velocity="1"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        limit = joint.limit
        if joint.type != "revolute" or limit is None:
            continue
        beyond = [(name, value) for name, value, given in (("lower", limit.lower, limit.has_lower), ("upper", limit.upper, limit.has_upper))
                  if given and TWO_TURNS < abs(value) <= 720]
        if not beyond:
            continue
        at = joint.part("limit")
        radians = {name: format_number(round(math.radians(value), 6)) for name, value in beyond}
        written = " and ".join(f"{name}={format_number(value)}" for name, value in beyond)
        yield loaded.diagnostic(
            "J016", f"joint '{joint.name}' has {written}: beyond two turns, degrees where URDF takes radians", at,
            "in radians: " + " ".join(f'{name}="{value}"' for name, value in radians.items()), subjects=(joint.name,),
        ).with_fix(Fix(f"write the limits of joint '{joint.name}' in radians", UNSAFE, changes=tuple(SetAttribute(at, name, value) for name, value in radians.items())))
