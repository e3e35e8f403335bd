"""Gazebo's URDF conversion by sdformat 12 (``sdf::Root::Load``, ``ign sdf -p``): src/parser_urdf.cc
(CreateSDF, CreateLink, ReduceFixedJoints). sdformat 13 and 14 print as warnings what 12 writes
only to ~/.sdformat/sdformat.log, and can turn massless fixed links into frames
(gazebosim/sdformat pull request 1238)."""

from __future__ import annotations

from ...model import massprops
from .. import build
from ...rules.base import ERROR, INFO, WARNING, Kind, check, explain
from ...rules.targets.common import about_joint, inverted_limits, joints_of, limit_at, link_at, mimic_at, mimic_joints, names, number
from ...rules.targets.examples import FIXED_JOINT, FLOATING_JOINT, INVERTED_LIMITS, MIMIC_GRIPPER, ONE_FINGER, ORDERED_LIMITS, TRIANGLE_BROKEN, TRIANGLE_KEPT, rover


@check(
    "C501", "gazebo-drops-link", WARNING, "Gazebo drops a massless link with its joint and subtree.", kind=Kind.TARGET, target="gazebo",
    doc=explain(
        """With `--target gazebo`: finds a link with no `<inertial>` or no positive mass that
        Gazebo does not lump into a parent (its joint moves, or its fixed joint is kept
        with `preserveFixedJoint`), and says which links below it go with it.""",
        """sdformat leaves such a link out of the SDF "not modeled in sdf", with its parent
        joint and every link below it (parser_urdf.cc, `CreateSDF`); sdformat 12 writes
        this only to a debug log. A massless root empties the model.""",
        rover("pan", "continuous", inertial=False),
        rover("pan", "continuous"),
    ),
)
def drops_link(loaded, given):
    dropped = build(loaded, given.profile).dropped
    for link, why in dropped.items():
        if why.startswith("below "):
            continue
        below = [name for name, reason in dropped.items() if reason == f"below {link}, which is dropped"]
        also = f" and the {len(below)} link{'s' if len(below) > 1 else ''} below it ({names(below)})" if below else ""
        yield loaded.diagnostic(
            "C501",
            f"Gazebo drops link '{link}'{also}: {why}",
            link_at(loaded, link),
            "give it an <inertial> with a small positive mass and tensor",
            subjects=(link, *below),
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
        yield loaded.diagnostic(
            "C504",
            f"Gazebo lumps {len(lumped)} link{'s' if len(lumped) > 1 else ''} into their parents on fixed joints: {names(lumped)}",
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
        """With `--target gazebo`: finds a joint with a `<mimic>`.""",
        """sdformat 12 does not convert `<mimic>` (SDFormat 1.9 has no mimic): the joint moves on
        its own, so a gripper's second finger does not follow the first. sdformat 14 (Gazebo
        Harmonic) converts it to `<axis><mimic>` (gazebosim/sdformat pull request 1333).""",
        MIMIC_GRIPPER,
        ONE_FINGER,
    ),
)
def drops_mimic(loaded, given):
    for joint in mimic_joints(loaded):
        yield about_joint(
            loaded, "C506", joint,
            f"Gazebo (sdformat 12) drops the <mimic> of joint '{joint.name}': it moves on its own, not with '{joint.mimic.joint}'",
            "drive it with a mimic joint plugin, or use Gazebo Harmonic (sdformat 14), which converts <mimic>", at=mimic_at(joint),
        )
