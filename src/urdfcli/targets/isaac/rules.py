"""Isaac Sim 6's URDF importer, stage 1: urdf-usd-converter 0.3.4 (_impl/urdf_parser/parser.py,
_impl/link.py, _impl/link_hierarchy.py). Isaac Sim's Kit post-processing (merging fixed joints, fixing the
base, drives) is not modelled; Isaac Sim 5.1 stopped merging fixed joints by default."""

from __future__ import annotations

from .build import merged_child
from ...rules.base import WARNING, Kind, check, explain
from ...rules.targets.common import about_joint, add_limit, link_at, without_limit
from ...rules.targets.examples import NO_LIMIT, WITH_LIMIT


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
    With `--target isaac`: finds a link with collision shapes but without `<inertial>`
    or with mass 0, unless the importer writes onto it the inertia of a child that has
    only an `<inertial>`, on a fixed joint (the KDL workaround for a root's inertia).

    ## Why is this bad?
    A mass of 0 is "unset" in USD physics: the physics engine gives the rigid body the
    mass of its colliders at the default density, which the model never states
    (urdf-usd-converter, _impl/link.py: `apply_inertial` writes no mass then;
    `_fixed_dummy_inertia_children` finds the child it writes instead).

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
    for name, link in loaded.robot.links.items():
        mass = link.inertial.mass if link.inertial is not None else None
        if link.collisions and not mass and merged_child(loaded, link) is None:
            yield loaded.diagnostic(
                "C702",
                f"Isaac Sim gives link '{name}' the mass of its colliders at the default density: it has {'mass 0' if link.inertial is not None else 'no <inertial>'}",
                link_at(loaded, name),
                "give it an <inertial> with its real mass and tensor",
                subjects=(name,),
            )
