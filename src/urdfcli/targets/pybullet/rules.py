"""PyBullet 3.2.7's URDF importer (``pybullet.loadURDF``): examples/Importers/ImportURDFDemo/UrdfParser.cpp
(parseLink, parseJoint), BulletUrdfImporter.cpp (getMassAndInertia), URDF2Bullet.cpp."""

from __future__ import annotations

from ...model import massprops
from ...model.targets import declared_matrix, valid_tensor
from .. import build
from ...rules.base import ERROR, INFO, WARNING, Kind, check, explain
from ...rules.targets.common import about_joint, add_limit, inverted_limits, joints_of, limit_at, link_at, names, number, without_limit
from ...rules.targets.examples import FIXED_JOINT, FLOATING_JOINT, INVERTED_LIMITS, NO_LIMIT, ORDERED_LIMITS, TRIANGLE_BROKEN, TRIANGLE_KEPT, WITH_LIMIT

RECOMPUTED_APART = 0.1  # a recomputed tensor further than this (relative) from the declared one is a change worth saying


@check("C401", "pybullet-default-inertial", WARNING, "PyBullet gives a link without <inertial> 1 kg.", kind=Kind.TARGET, target="pybullet")
def default_inertial(loaded, given):
    """## What it does
    With `--target pybullet`: finds a link without `<inertial>` (other than one named
    `world`).

    ## Why is this bad?
    PyBullet gives it a mass of 1 kg and a unit inertia tensor ("No inertial data for
    link, using mass=1, localinertiadiagonal = 1,1,1", BulletUrdfImporter.cpp): every
    massless tool or sensor frame adds a kilogram at its place. A 30-link arm with
    five such frames weighs 5 kg more than its model.

    ## Example
    ```xml
    <robot name="arm">
      <link name="base"><inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
      <link name="tool0"/>
      <joint name="flange" type="fixed"><parent link="base"/><child link="tool0"/></joint>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="arm">
      <link name="base"><inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
      <link name="tool0"><inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>
      <joint name="flange" type="fixed"><parent link="base"/><child link="tool0"/></joint>
    </robot>
    ```
    """
    tensor = " and a unit inertia tensor" if "inertia-from-file" in given.profile.variants else ""
    for name, link in loaded.robot.links.items():
        if link.inertial is None and name != "world":
            yield loaded.diagnostic(
                "C401",
                f"PyBullet gives link '{name}' a mass of 1 kg{tensor}: it has no <inertial>",
                link.at,
                'give it an <inertial> (a frame: <mass value="0"/> and a zero tensor)',
                subjects=(name,),
            )


@check("C402", "pybullet-recomputes-inertia", WARNING, "PyBullet recomputes inertia tensors from collision shapes.", kind=Kind.TARGET, target="pybullet")
def recomputes_inertia(loaded, given):
    """## What it does
    With `--target pybullet` (not `pybullet:inertia-from-file`): says, once per model,
    which declared tensors PyBullet will not use, where the tensor it computes
    differs from the declared one by more than 10 %.

    ## Why is this bad?
    Without `flags=URDF_USE_INERTIA_FROM_FILE`, PyBullet ignores every `<inertia>` and
    gives each link the tensor of a box filling the bounding box of its collision
    shapes (BulletUrdfImporter.cpp, `calculateLocalInertia`): a 1 kg 10 cm box
    declared 0.01 kg·m² gets 0.00167. A link without collision shapes gets a zero
    tensor. Only the masses are kept.

    ## Example
    ```xml
    <link name="wrist">
      <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
      <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="wrist">
      <inertial><mass value="1"/><inertia ixx="0.00167" ixy="0" ixz="0" iyy="0.00167" iyz="0" izz="0.00167"/></inertial>
      <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
    </link>
    ```
    """
    if "inertia-from-file" in given.profile.variants:
        return
    changed = []
    for body in build(loaded, given.profile).bodies:
        link = loaded.robot.links[body.top]
        declared = declared_matrix(link)
        if declared is None or not body.mass:
            continue
        moments = massprops.principal_moments(declared)
        if body.moments is None:  # from a mesh's bounding box: changed, by how much the mesh says
            changed.append((body.top, moments, moments))
            continue
        scale = max(abs(m) for m in (*moments, *body.moments)) or 1.0
        if max(abs(a - b) for a, b in zip(sorted(moments), sorted(body.moments))) > RECOMPUTED_APART * scale:
            changed.append((body.top, moments, body.moments))
    if not changed:
        return
    first, declared, computed = next((c for c in changed if c[1] != c[2]), changed[0])
    example = f"; link '{first}': principal moments {' '.join(number(m) for m in declared)} become {' '.join(number(m) for m in sorted(computed))}" if declared != computed else ""
    yield loaded.diagnostic(
        "C402",
        f"PyBullet ignores the <inertia> of {len(changed)} link{'s' if len(changed) > 1 else ''} ({names(n for n, _, _ in changed)}) and recomputes it from the bounding box of the collision shapes{example}",
        loaded.robot.at,
        "load with pybullet.loadURDF(path, flags=pybullet.URDF_USE_INERTIA_FROM_FILE) (check it with --target pybullet:inertia-from-file)",
        subjects=tuple(n for n, _, _ in changed),
    )


@check(
    "C403", "pybullet-unlimited-joint", WARNING, "PyBullet treats lower > upper as no limit.", kind=Kind.TARGET, target="pybullet",
    doc=explain(
        """With `--target pybullet`: finds a revolute or prismatic joint whose lower limit is
        above its upper one.""",
        """Bullet reads lower > upper as "no limit" (URDF2Bullet.cpp): the joint turns freely,
        without a word.""",
        INVERTED_LIMITS,
        ORDERED_LIMITS,
    ),
)
def unlimited_joint(loaded, given):
    for joint in inverted_limits(loaded):
        limit = joint.limit
        yield about_joint(
            loaded, "C403", joint,
            f"PyBullet leaves joint '{joint.name}' unlimited: its lower limit {number(limit.lower)} is above its upper {number(limit.upper)}",
            "swap lower and upper", at=limit_at(joint),
        )


@check(
    "C404", "pybullet-floating-joint", WARNING, "PyBullet makes a floating joint fixed.", kind=Kind.TARGET, target="pybullet",
    doc=explain(
        """With `--target pybullet`: finds a floating joint.""",
        """PyBullet has no floating joint inside a multibody: it prints "joint unsupported,
        creating a fixed joint instead" (URDF2Bullet.cpp) and the child is welded to its parent.""",
        FLOATING_JOINT,
        FIXED_JOINT,
    ),
)
def floating_joint(loaded, given):
    for joint in joints_of(loaded, ("floating",)):
        yield about_joint(
            loaded, "C404", joint,
            f"PyBullet makes floating joint '{joint.name}' fixed: '{joint.child}' is welded to '{joint.parent}'",
            "load the free body as a model of its own (its own URDF, loaded with loadURDF)",
        )


@check(
    "C405", "pybullet-zeroes-inertia", WARNING, "PyBullet zeroes a tensor it finds invalid.", kind=Kind.TARGET, target="pybullet:inertia-from-file",
    doc=explain(
        """With `--target pybullet:inertia-from-file`: finds a declared tensor that is not
        positive semi-definite or breaks the triangle inequality.""",
        """With `URDF_USE_INERTIA_FROM_FILE`, PyBullet prints "Bad inertia tensor properties,
        setting inertia to zero" (BulletUrdfImporter.cpp) and the link turns as a point mass.""",
        TRIANGLE_BROKEN,
        TRIANGLE_KEPT,
    ),
)
def zeroes_inertia(loaded, given):
    if "inertia-from-file" not in given.profile.variants:
        return
    for name, link in loaded.robot.links.items():
        tensor = declared_matrix(link)
        if tensor is None or link.inertial.mass is None or massprops.is_zero(tensor):
            continue
        if not valid_tensor(link.inertial.mass, tensor):
            yield loaded.diagnostic(
                "C405",
                f"PyBullet sets the inertia of link '{name}' to zero: its tensor is not physical",
                link.inertial.inertia_at or link.inertial.at,
                "fix the tensor (inertia --suggest prints one for its geometry)",
                subjects=(name,),
            )


@check("C406", "pybullet-floating-base", INFO, "PyBullet lets the base link float.", kind=Kind.TARGET, target="pybullet")
def floating_base(loaded, given):
    """## What it does
    With `--target pybullet` (not `pybullet:fixed-base`): says, once per model, that the
    base link is free unless it is named `world` or has mass 0.

    ## Why is this bad?
    `loadURDF` makes the base a free body unless called with `useFixedBase=True`: a
    fixed arm falls over under gravity.

    ## Example
    ```xml
    <robot name="arm">
      <link name="base"><inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="arm">
      <link name="world"/>
      <link name="base"><inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
      <joint name="mount" type="fixed"><parent link="world"/><child link="base"/></joint>
    </robot>
    ```
    """
    built = build(loaded, given.profile)
    root = loaded.root
    if root is not None and built.base == "floating":
        yield loaded.diagnostic(
            "C406",
            f"PyBullet lets base link '{root}' float: it falls under gravity",
            link_at(loaded, root),
            "load with useFixedBase=True for a fixed robot (check it with --target pybullet:fixed-base)",
            subjects=(root,),
        )


@check(
    "C407", "pybullet-joint-without-limit", ERROR, "PyBullet refuses a revolute or prismatic joint without <limit>.", kind=Kind.TARGET, target="pybullet",
    doc=explain(
        """With `--target pybullet`: finds a revolute or prismatic joint without `<limit>`.""",
        """PyBullet's own URDF parser, like urdfdom's (J003), refuses it: "Joint is of type
        REVOLUTE but it does not specify limits" (UrdfParser.cpp, `parseJoint`), and
        `loadURDF` raises "Cannot load URDF file.". MuJoCo, Drake and Isaac Sim take the
        same file, so a model checked only with them fails here.""",
        NO_LIMIT,
        WITH_LIMIT,
    ),
)
def joint_without_limit(loaded, given):
    for joint in without_limit(loaded):
        yield about_joint(
            loaded, "C407", joint,
            f"PyBullet refuses joint '{joint.name}': a {joint.type} joint without <limit>",
            add_limit(joint),
        )
