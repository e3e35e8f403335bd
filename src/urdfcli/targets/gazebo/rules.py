"""Gazebo's URDF conversion by sdformat 12 (``sdf::Root::Load``, ``ign sdf -p``): src/parser_urdf.cc
(CreateSDF, CreateLink, ReduceFixedJoints). sdformat 13 and 14 print as warnings what 12 writes
only to ~/.sdformat/sdformat.log, and can turn massless fixed links into frames
(gazebosim/sdformat pull request 1238)."""

from __future__ import annotations

from ...model import massprops
from .. import build
from ...rules.base import ERROR, INFO, WARNING, Kind, check, explain
from ...rules.targets.common import about_joint, inverted_limits, joints_of, limit_at, link_at, mimics_said_once, names, number
from ...rules.targets.examples import CHASSIS, FIXED_JOINT, FLOATING_JOINT, INVERTED_LIMITS, MIMIC_GRIPPER, ONE_FINGER, ORDERED_LIMITS, TRIANGLE_BROKEN, TRIANGLE_KEPT, rover


@check(
    "C501", "gazebo-drops-link", WARNING, "Gazebo drops a massless link with its joint and subtree.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: finds a link with no `<inertial>` or a mass within 1e-6 kg
        of 0 (its fixed children's lumped in), and says which links go with it: all below
        it when its joint moves (or its fixed joint is kept with `preserveFixedJoint`),
        those below its moving joints when it is lumped into its parent. When no link is
        left, C507 says so instead.""",
        """sdformat leaves such a link out of the SDF "not modeled in sdf", with its parent
        joint and every link below it (parser_urdf.cc, `CreateSDF`); sdformat 12 writes
        this only to a debug log. A mass within 1e-6 kg of 0 counts as none
        (`ignition::math::equal`), and a massless link on a fixed joint, lumped into its
        parent, still takes the moving joints below it and their links.""",
        rover("pan", "continuous", inertial=False),
        rover("pan", "continuous"),
    ),
)
def drops_link(loaded, given):
    built = build(loaded, given.profile)
    if not built.bodies:
        return  # nothing is left: C507's
    causes: dict[str, list[str]] = {}  # the massless link -> the links that go because of it
    for link, why in built.dropped.items():
        cause = why.split(",")[0][len("below "):] if why.startswith("below ") else link
        causes.setdefault(cause, []).append(link)
    for cause, gone in causes.items():
        why = built.dropped.get(cause)
        if why is not None:
            below = gone[1:]
            also = f" and the {len(below)} link{'s' if len(below) > 1 else ''} below it ({names(below)})" if below else ""
            message = f"Gazebo drops link '{cause}'{also}: {why}"
        else:  # a massless link lumped on a fixed joint: the moving joints below it go
            massless = built.dropped[gone[0]].split(", ", 1)[1]  # "which has no <inertial>", "which has a mass of 0", ...
            message = f"Gazebo drops link{'s' if len(gone) > 1 else ''} {names(gone)}: {'they hang' if len(gone) > 1 else 'it hangs'} below '{cause}', {massless} (sdformat does not go below it)"
        yield loaded.diagnostic(
            "C501", message, link_at(loaded, cause),
            "give it an <inertial> with a small positive mass and tensor (more than 1e-6 kg)",
            subjects=(cause, *gone) if why is None else tuple(gone),
        )


@check(
    "C502", "gazebo-invalid-inertia", ERROR, "Gazebo refuses a body whose inertia is not physical.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: finds a body (a link with the fixed links lumped into it)
        whose mass is negative or whose combined tensor has a negative principal moment
        or breaks the triangle inequality.""",
        """sdformat reports "A link named NAME has invalid inertia" (`MassMatrix3::IsValid`)
        and Gazebo refuses to spawn the model.""",
        TRIANGLE_BROKEN,
        TRIANGLE_KEPT,
    ),
)
def invalid_inertia(loaded, given):
    for body in build(loaded, given.profile).bodies:
        if body.mass is None:
            continue
        if body.mass < 0:
            why = f"its mass is {number(body.mass)}"
        elif body.moments is not None and min(body.moments) < 0:
            why = f"a principal moment is {number(min(body.moments))}"
        elif body.moments is not None and massprops.triangle_violation(massprops.diagonal(*body.moments)) is not None:
            why = "its principal moments break the triangle inequality"
        else:
            continue
        lumped = f" (with {names(body.links[1:])} lumped into it)" if len(body.links) > 1 else ""
        yield loaded.diagnostic(
            "C502",
            f"Gazebo rejects link '{body.top}'{lumped}: {why}",
            link_at(loaded, body.top),
            "fix the <inertial> (inertia --suggest prints one for its geometry)",
            subjects=body.links,
        )


@check(
    "C503", "gazebo-swaps-limits", WARNING, "Gazebo swaps limits given lower > upper.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: finds a revolute or prismatic joint whose lower limit is
        above its upper one.""",
        """sdformat swaps them (parser_urdf.cc), where MuJoCo and PyBullet make the joint
        unlimited and Drake aborts: the same model moves differently in each.""",
        INVERTED_LIMITS,
        ORDERED_LIMITS,
    ),
)
def swaps_limits(loaded, given):
    for joint in inverted_limits(loaded):
        limit = joint.limit
        yield about_joint(
            loaded, "C503", joint,
            f"Gazebo swaps the limits of joint '{joint.name}' ({number(limit.lower)} > {number(limit.upper)})",
            "swap lower and upper", at=limit_at(joint),
        )


@check(
    "C504", "gazebo-lumps-fixed-links", INFO, "Gazebo lumps links on fixed joints into their parents.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: says, once per model, which links Gazebo lumps into their
        parents (fixed joints without `preserveFixedJoint`).""",
        """sdformat merges such a link's mass, inertia, visuals and collisions into its
        parent and removes the link and its joint (`ReduceFixedJoints`): a plugin or
        `<gazebo reference>` naming the link finds nothing, and sensors move to the parent.""",
        rover("camera", "fixed"),
        rover("camera", "fixed", more='<gazebo reference="camera_joint"><preserveFixedJoint>true</preserveFixedJoint></gazebo>'),
    ),
)
def lumps_fixed_links(loaded, given):
    lumped = [link for body in build(loaded, given.profile).bodies for link in body.links[1:]]
    if lumped:
        several = len(lumped) > 1
        yield loaded.diagnostic(
            "C504",
            f"Gazebo lumps {len(lumped)} link{'s' if several else ''} into {'their parents on fixed joints' if several else 'its parent on a fixed joint'}: {names(lumped)}",
            loaded.robot.at,
            'keep one with <gazebo reference="JOINT"><preserveFixedJoint>true</preserveFixedJoint></gazebo>',
            subjects=tuple(lumped),
        )


@check(
    "C505", "gazebo-floating-joint", ERROR, "Gazebo cannot load a floating or planar joint.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: finds a floating or planar joint.""",
        """SDFormat has neither: sdformat 12 leaves the joint out of the SDF but still places
        the child link relative to it, and the model fails to load ("relative_to name[j1]
        specified by link with name[link1] does not match a nested model, link, joint, or
        frame name", then "PoseRelativeToGraph error"; parser_urdf.cc, `CreateJoint`).""",
        FLOATING_JOINT,
        FIXED_JOINT,
    ),
)
def floating_joint(loaded, given):
    for joint in joints_of(loaded, ("floating", "planar")):
        yield about_joint(
            loaded, "C505", joint,
            f"Gazebo cannot load {joint.type} joint '{joint.name}': sdformat leaves it out but places '{joint.child}' relative to it",
            "spawn the free body as a model of its own; for a planar base use a Gazebo plugin (such as a planar move plugin)",
        )


@check(
    "C506", "gazebo-drops-mimic", WARNING, "Gazebo (sdformat 12) drops <mimic>.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: says, once per model, which joints have a `<mimic>`, but
        those a mimic joint plugin in a `<gazebo>` block drives (`<mimicJoint>NAME</mimicJoint>`
        in a plugin whose file name says mimic, as roboticsgroup's), and those Gazebo's
        ros2_control system drives (a `<ros2_control>` joint with `<param name="mimic">` whose
        hardware plugin is gz_ros2_control's, ign_ros2_control's or gazebo_ros2_control's).""",
        """sdformat 12 does not convert `<mimic>` (SDFormat 1.9 has no mimic): the joint moves on
        its own, so a gripper's second finger does not follow the first. sdformat 14 (Gazebo
        Harmonic) converts it to `<axis><mimic>` (gazebosim/sdformat pull request 1333).""",
        MIMIC_GRIPPER,
        ONE_FINGER,
    ),
)
def drops_mimic(loaded, given):
    yield from mimics_said_once(
        loaded, "C506", "Gazebo (sdformat 12) drops the <mimic> of {joints}: {they} freely",
        "drive them with a mimic joint plugin, or use Gazebo Harmonic (sdformat 14), which converts <mimic>",
        plugin_mimics(loaded) | ros2_control_mimics(loaded),
    )


# The ros2_control hardware of Gazebo's plugins (gz, Ignition and Gazebo classic): each
# commands a joint that has <param name="mimic"> after the joint it names.
GAZEBO_SYSTEMS = ("gz_ros2_control/", "ign_ros2_control/", "gazebo_ros2_control/")


def ros2_control_mimics(loaded) -> frozenset[str]:
    """The joints a Gazebo ros2_control system drives as mimic joints (gz_ros2_control's
    gripper demo: ``<joint name="left_finger_joint"><param name="mimic">right_finger_joint</param>``)."""
    return frozenset(
        joint.get("name")
        for block in loaded.robot.blocks("ros2_control")
        if any((plugin.text or "").strip().startswith(GAZEBO_SYSTEMS) for plugin in block.iterfind("hardware/plugin"))
        for joint in block.iterfind("joint") if any(param.get("name") == "mimic" for param in joint.iterfind("param"))
    )


def plugin_mimics(loaded) -> frozenset[str]:
    """The joints a mimic joint plugin in a <gazebo> block drives (roboticsgroup's and its
    forks: ``<plugin filename="lib..._mimic_joint_plugin.so"><mimicJoint>NAME</mimicJoint>``)."""
    return frozenset(
        (element.text or "").strip()
        for block in loaded.robot.blocks("gazebo") for plugin in block.iter("plugin") if "mimic" in (plugin.get("filename") or "")
        for element in plugin.iter("mimicJoint")
    )


@check(
    "C507", "gazebo-empty-model", ERROR, "Gazebo refuses a model in which no link keeps a mass.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: finds a model whose root (or each link on a joint from
        `world`) has no `<inertial>` or a mass within 1e-6 kg of 0 once its fixed
        children are lumped into it: sdformat drops it and everything below it.""",
        """sdformat leaves nothing in the model and Gazebo refuses it: "A model must have at
        least one link" (parser_urdf.cc, `CreateSDF`; sdf/Model.cc). The ROS-Industrial arms
        (ABB, FANUC, KUKA, Motoman support packages) have no `<inertial>` at all: they
        display in RViz and cannot be spawned.""",
        rover("pan", "continuous").replace(CHASSIS, '<link name="chassis"/>'),
        rover("pan", "continuous"),
    ),
)
def empty_model(loaded, given):
    built = build(loaded, given.profile)
    root = loaded.root
    if built.bodies or root is None:
        return
    links = [name for name in loaded.robot.links if name != "world"]
    yield loaded.diagnostic(
        "C507",
        f"Gazebo refuses the model: no link keeps a mass ({built.dropped.get(root, 'the links below world have none')} for root link '{root}'), "
        f"so sdformat drops all {len(links)} links and finds none ('A model must have at least one link')",
        link_at(loaded, root),
        "give the links <inertial> elements with their masses (at least the root and every link on a moving joint)",
        subjects=tuple(links),
    )


@check(
    "C508", "gazebo-nan-pose", ERROR, "Gazebo refuses a link whose lumped centre of mass is NaN.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: finds a link into which sdformat lumps, through fixed joints,
        a child whose `<inertial>` has mass 0 while the mass lumped so far is 0 too.""",
        """sdformat's lumping divides by the sum of the two masses (`dMassAdd` in
        parser_urdf.cc): 0/0 makes the centre of mass NaN, which every later lumping keeps,
        and Gazebo refuses the model ("Pose values must be finite"). Massless frames with
        a zero `<inertial>` chained on fixed joints do it (talos, anymal).""",
        rover("camera", "fixed", more='<link name="lens"><inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>\n  '
              '<joint name="lens_joint" type="fixed"><parent link="camera"/><child link="lens"/></joint>').replace('<mass value="0.1"/>', '<mass value="0"/>'),
        rover("camera", "fixed", more='<link name="lens"/>\n  <joint name="lens_joint" type="fixed"><parent link="camera"/><child link="lens"/></joint>').replace('<mass value="0.1"/>', '<mass value="0"/>'),
    ),
)
def nan_pose(loaded, given):
    for top, why in build(loaded, given.profile).broken.items():
        yield loaded.diagnostic(
            "C508", f"Gazebo refuses link '{top}': {why} ('Pose values must be finite')", link_at(loaded, top),
            "leave the <inertial> out of massless frame links (or give them a small mass)",
            subjects=(top,),
        )


@check(
    "C509", "gazebo-name-collision", ERROR, "Gazebo refuses a link and a joint of one name.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: finds a link and a joint with the same name, both kept in
        the SDF model (the link not lumped or dropped, the joint not lumped).""",
        """URDF keeps links and joints apart, SDFormat does not: Gazebo refuses the model
        ("Joint with name [NAME] ... has a name collision. Please rename this joint";
        sdf/Model.cc).""",
        rover("gripper", "continuous").replace('name="gripper_joint"', 'name="gripper"'),
        rover("gripper", "continuous"),
    ),
)
def name_collision(loaded, given):
    built = build(loaded, given.profile)
    for body in built.bodies:
        joint = loaded.robot.joints.get(body.top)
        if joint is not None and joint.child not in built.dropped and any(joint.child == b.top for b in built.bodies):
            yield about_joint(
                loaded, "C509", joint, f"Gazebo refuses joint '{joint.name}': link '{body.top}' has the same name",
                "rename the joint (such as '{}_joint')".format(joint.name),
            )
