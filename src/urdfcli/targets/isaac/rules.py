"""Isaac Sim 6's URDF importer, stage 1: urdf-usd-converter 0.3.4 (_impl/urdf_parser/parser.py,
_impl/link.py, _impl/link_hierarchy.py). Isaac Sim's Kit post-processing (merging fixed joints, fixing the
base, drives) is not modelled; Isaac Sim 5.1 stopped merging fixed joints by default."""

from __future__ import annotations

import re

from .build import merged_child
from ...rules.base import INFO, WARNING, Kind, check, explain
from ...rules.targets.common import about_joint, add_limit, joints_of, link_at, names, without_limit
from ...rules.targets.examples import FIXED_JOINT, FLOATING_JOINT, NO_LIMIT, WITH_LIMIT


@check(
    "C701", "isaac-locks-joint", WARNING, "Isaac Sim locks a revolute or prismatic joint without <limit>.", kind=Kind.TARGET, target="isaac",
    doc=explain(
        """With `--target isaac`: finds a revolute or prismatic joint without `<limit>`.""",
        """urdfdom rejects it (J003), but Isaac Sim's importer takes it, writes its limits
        as lower = upper = 0 ("If limit is omitted, set to 0.0": urdf-usd-converter,
        _impl/link.py, `physics_joints`), and the joint cannot move.""",
        NO_LIMIT,
        WITH_LIMIT,
    ),
)
def locks_joint(loaded, given):
    for joint in without_limit(loaded):
        yield about_joint(
            loaded, "C701", joint,
            f"Isaac Sim locks joint '{joint.name}': without <limit> it writes lower = upper = 0",
            add_limit(joint),
        )


@check("C702", "isaac-mass-from-colliders", WARNING, "Isaac Sim weighs a massless link with colliders by their volume.", kind=Kind.TARGET, target="isaac")
def mass_from_colliders(loaded, given):
    """## What it does
    With `--target isaac`: says, once per model, which links have collision shapes but no `<inertial>`
    or with mass 0, unless the importer writes onto it the inertia of a child that has
    only an `<inertial>`, on a fixed joint (the KDL workaround for a root's inertia); and
    a link on a moving joint with neither mass nor collision shapes.

    ## Why is this bad?
    A mass of 0 is "unset" in USD physics: the physics engine gives the rigid body the
    mass of its colliders at the default density, which the model never states
    (urdf-usd-converter, _impl/link.py: `apply_inertial` writes no mass then;
    `_fixed_dummy_inertia_children` finds the child it writes instead). Without
    colliders, the moving link is a rigid body with no mass at all, left to the
    physics engine's default.

    ## Example
    ```xml
    <link name="bumper">
      <collision><geometry><box size="0.5 0.1 0.1"/></geometry></collision>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="bumper">
      <inertial><mass value="0.4"/><inertia ixx="7e-4" ixy="0" ixz="0" iyy="8.7e-3" iyz="0" izz="8.7e-3"/></inertial>
      <collision><geometry><box size="0.5 0.1 0.1"/></geometry></collision>
    </link>
    ```
    """
    weighed, massless = [], []
    for name, link in loaded.robot.links.items():
        mass = link.inertial.mass if link.inertial is not None else None
        if mass or merged_child(loaded, link) is not None:
            continue
        if link.collisions:
            weighed.append(name)
        elif (joint := loaded.parent_joint(name)) is not None and joint.moving and name != "world":
            massless.append(name)
    if weighed:
        they = _they(weighed)
        yield loaded.diagnostic(
            "C702", f"Isaac Sim gives {they['links']} the mass of {they['their']} colliders at the default density: {they['they']} no mass of {they['their']} own",
            link_at(loaded, weighed[0]), "give each an <inertial> with its real mass and tensor", subjects=tuple(weighed))
    if massless:
        they = _they(massless)
        yield loaded.diagnostic(
            "C702", f"Isaac Sim makes {they['links']}, on {they['joints']}, rigid bod{they['ies']} without mass: {they['they']} neither a mass nor a collider",
            link_at(loaded, massless[0]), "give each an <inertial> with its real mass and tensor", subjects=tuple(massless))


def _they(links: list[str]) -> dict[str, str]:
    several = len(links) > 1
    return {"links": f"links {names(links)}" if several else f"link '{links[0]}'", "their": "their" if several else "its",
            "they": "they have" if several else "it has", "ies": "ies" if several else "y",
            "joints": "moving joints" if several else "a moving joint"}


USD_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


@check("C703", "isaac-renames", WARNING, "Isaac Sim renames links and joints whose names USD cannot hold.", kind=Kind.TARGET, target="isaac")
def renames(loaded, given):
    """## What it does
    With `--target isaac`: says, once per model, which links and joints have a name that is
    not a USD identifier (letters, digits and underscores, not starting with a digit):
    spaces, dashes, dots, accented letters.

    ## Why is this bad?
    urdf-usd-converter encodes such a name into a USD prim name (`link one` becomes
    `tn__linkone_h7`), keeping the original only as a display name: code that looks the
    prim up by its URDF name (`/robot/link one`) finds nothing.

    ## Example
    ```xml
    <robot name="r">
      <link name="base"/><link name="upper arm"/>
      <joint name="shoulder-pitch" type="continuous"><parent link="base"/><child link="upper arm"/></joint>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r">
      <link name="base"/><link name="upper_arm"/>
      <joint name="shoulder_pitch" type="continuous"><parent link="base"/><child link="upper_arm"/></joint>
    </robot>
    ```
    """
    robot = loaded.robot
    renamed = [name for name in (*robot.links, *robot.joints) if name and not USD_NAME.fullmatch(name)]
    if renamed:
        first = robot.links.get(renamed[0]) or robot.joints.get(renamed[0])
        yield loaded.diagnostic(
            "C703", f"Isaac Sim renames {len(renamed)} link{'s' if len(renamed) > 1 else ''} or joint{'s' if len(renamed) > 1 else ''} for USD: {names(renamed)}",
            first.at, "use letters, digits and underscores in link and joint names", subjects=tuple(renamed),
        )


@check("C704", "isaac-writes-unchecked", INFO, "Isaac Sim writes a negative mass or moment into USD as it is.", kind=Kind.TARGET, target="isaac")
def writes_unchecked(loaded, given):
    """## What it does
    With `--target isaac`: finds a link whose mass or a diagonal moment of whose tensor is
    negative (I001 and I005 say it is wrong; this says Isaac Sim takes it).

    ## Why is this bad?
    urdf-usd-converter writes the mass and the diagonal into `physics:mass` and
    `physics:diagonalInertia` unchecked (_impl/link.py): the importer succeeds and the
    simulation runs on a body no physics engine can move sensibly.

    ## Example
    ```xml
    <link name="wrist">
      <inertial><mass value="-1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="wrist">
      <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    </link>
    ```
    """
    for name, link in loaded.robot.links.items():
        inertial = link.inertial
        if inertial is None:
            continue
        negative = [key for key in ("ixx", "iyy", "izz") if inertial.inertia is not None and inertial.inertia.get(key, 0) < 0]
        if (inertial.mass is not None and inertial.mass < 0) or negative:
            what = "its negative mass" if inertial.mass is not None and inertial.mass < 0 else f"its negative {', '.join(negative)}"
            yield loaded.diagnostic("C704", f"Isaac Sim writes {what} of link '{name}' into USD unchecked", inertial.at,
                                    "fix the <inertial> (inertia --suggest prints one for its geometry)", subjects=(name,))


@check(
    "C705", "isaac-drops-floating-joint", WARNING, "Isaac Sim leaves a floating joint out.", kind=Kind.TARGET, target="isaac",
    doc=explain(
        """With `--target isaac`: finds a floating joint.""",
        """urdf-usd-converter writes no joint for it (_impl/link_hierarchy.py): the child is a
        free rigid body of its own, outside the articulation.""",
        FLOATING_JOINT,
        FIXED_JOINT,
    ),
)
def drops_floating_joint(loaded, given):
    for joint in joints_of(loaded, ("floating",)):
        yield about_joint(loaded, "C705", joint, f"Isaac Sim leaves floating joint '{joint.name}' out: '{joint.child}' is a free body of its own",
                          "spawn the free body as an object of its own")
