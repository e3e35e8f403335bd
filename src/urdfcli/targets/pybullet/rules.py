"""PyBullet 3.2.7's URDF importer (``pybullet.loadURDF``): examples/Importers/ImportURDFDemo/UrdfParser.cpp
(parseLink, parseJoint), BulletUrdfImporter.cpp (getMassAndInertia), URDF2Bullet.cpp."""

from __future__ import annotations

from ...model import massprops
from ...model.meshes import MeshFiles
from ...model.targets import declared_matrix, declared_moments, declared_tensors, mesh_extension, valid_tensor
from .. import build
from .build import missing_mesh
from ...rules.base import ERROR, INFO, WARNING, Kind, check, explain
from ...rules.targets.common import about_joint, inverted_limits, joints_of, limit_at, link_at, mimics_said_once, names, number, once
from ...rules.targets.examples import FIXED_JOINT, FLOATING_JOINT, INVERTED_LIMITS, MIMIC_GRIPPER, ONE_FINGER, ORDERED_LIMITS, TRIANGLE_BROKEN, TRIANGLE_KEPT

RECOMPUTED_APART = 0.1  # a recomputed tensor further than this (relative) from the declared one is a change worth saying


@check("C401", "pybullet-default-inertial", WARNING, "PyBullet gives a link without <inertial> 1 kg.", kind=Kind.TARGET, target="pybullet")
def default_inertial(loaded, given):
    """## What it does
    With `--target pybullet`: says, once per model, which links have no `<inertial>`
    (other than one named `world`).

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
    links = [link for name, link in loaded.robot.links.items() if link.inertial is None and name != "world"]
    if links:
        several = len(links) > 1
        yield loaded.diagnostic(
            "C401",
            f"PyBullet gives {len(links)} link{'s' if several else ''} without <inertial> ({names(link.name for link in links)}) a mass of 1 kg{tensor} {'each' if several else ''}".rstrip(),
            links[0].at,
            'give each an <inertial> (a frame: <mass value="0"/> and a zero tensor)',
            subjects=tuple(link.name for link in links),
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
    tensors = declared_tensors(loaded)
    for body in build(loaded, given.profile).bodies:
        declared = tensors.get(body.top)
        if declared is None or not body.mass:
            continue
        moments = declared.moments
        if body.moments is None:  # from a mesh's bounding box: changed, by how much the mesh says
            changed.append((body.top, moments, moments))
            continue
        scale = max(massprops.ZERO_FLOOR, *(abs(m) for m in (*moments, *body.moments)))  # a frame's 0 made 1e-16 is no change
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
        if not valid_tensor(link.inertial.mass, tensor, moments=declared_moments(loaded, link)):
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
    "C408", "pybullet-mesh-not-found", ERROR, "PyBullet refuses a mesh it cannot find or has no reader for.", kind=Kind.TARGET, target="pybullet",
    doc=explain(
        """With `--target pybullet`: finds a visual or collision mesh whose file name does not
        end in `.stl`, `.obj`, `.dae` or `.cdf`, or that PyBullet cannot find the way it
        looks: it drops `package://` and tries the rest under the packages it is given (`--load`
        gives it those urdfcli finds) and under each folder above the model
        (UrdfFindMeshFile.h). A missing file with a plain path is D004's.""",
        """`loadURDF` raises "Cannot load URDF file." and says why only on its `b3Warning` lines
        ("cannot find '...' in any directory in urdf path", "invalid mesh filename extension").
        Ogre `.mesh` files and packages PyBullet is not told of are common in ROS models.""",
        '<link name="torso">\n  <visual><geometry><mesh filename="package://my_robot/meshes/torso.mesh"/></geometry></visual>\n</link>',
        '<link name="torso">\n  <visual><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></visual>\n</link>',
    ),
)
def mesh_not_found(loaded, given):
    files = MeshFiles.of(loaded)
    model = loaded.document.file
    problems: dict[str, str | None] = {}  # uri -> why PyBullet cannot find it: each looked up once
    folders: dict[str, list] = {}
    found: dict[tuple[str, str], list] = {}  # (why, package or extension) -> the links and meshes: said once each
    for name, link in loaded.robot.links.items():
        for shape in (*link.visuals, *link.collisions):
            geometry = shape.geometry
            if geometry is None or geometry.kind != "mesh" or not geometry.filename:
                continue
            uri = geometry.filename
            if uri not in problems:
                problems[uri] = missing_mesh(uri, files, model, folders)
            if problems[uri] is not None:
                kind = uri.split("://", 1)[1].split("/", 1)[0] if "://" in uri and "find" in problems[uri] else mesh_extension(uri)
                found.setdefault((problems[uri].split("'")[0], kind), []).append((name, geometry))
    for (why, kind), meshes in found.items():
        reader = "reader" in why
        yield once(
            loaded, "C408", meshes, kind if reader else f"package '{kind}'",
            "PyBullet refuses link '{link}': " + (f"it has no reader for {kind} meshes, such as" if reader else "it cannot find (in any folder above the model, nor among the packages urdfcli finds)"),
            "convert the mesh to .stl or .obj" if reader else "give PyBullet the package (pybullet.setAdditionalSearchPath), or a path it can find",
        )


@check(
    "C409", "pybullet-unbounded-limit", WARNING, "PyBullet leaves a joint whose <limit> has no lower and upper unlimited.", kind=Kind.TARGET, target="pybullet",
    doc=explain(
        """With `--target pybullet`: finds a revolute or prismatic joint whose `<limit>` gives
        neither `lower` nor `upper`.""",
        """PyBullet's parser reads the missing bounds as 0 and -1 (UrdfParser.cpp), which Bullet
        takes for "no limit": the joint turns freely, where urdfdom, Pinocchio, Gazebo and KDL
        hold it at [0, 0].""",
        '<joint name="wheel" type="revolute"><parent link="base"/><child link="wheel"/><limit effort="35" velocity="20"/></joint>',
        '<joint name="wheel" type="continuous"><parent link="base"/><child link="wheel"/><limit effort="35" velocity="20"/></joint>',
    ),
)
def unbounded_limit(loaded, given):
    for joint in joints_of(loaded, ("revolute", "prismatic")):
        limit = joint.limit
        if limit is not None and not limit.has_lower and not limit.has_upper:
            yield about_joint(loaded, "C409", joint, f"PyBullet leaves joint '{joint.name}' unlimited: its <limit> has no lower and no upper",
                              "give lower and upper, or make it continuous", at=limit_at(joint))


@check(
    "C410", "pybullet-ignores-mimic", WARNING, "PyBullet ignores <mimic>.", kind=Kind.TARGET, target="pybullet",
    doc=explain(
        """With `--target pybullet`: says, once per model, which joints have a `<mimic>`.""",
        """PyBullet's parser does not read `<mimic>` (UrdfParser.cpp) and `loadURDF` makes no
        constraint for it: the joint moves on its own, so a gripper's second finger (the
        OpenMANIPULATOR-X's `gripper_right_joint`) does not follow the first, and falls
        under gravity unless a motor holds it. A script couples it after loading
        (`createConstraint` with `JOINT_GEAR`) or
        commands both joints.""",
        MIMIC_GRIPPER,
        ONE_FINGER,
    ),
)
def ignores_mimic(loaded, given):
    yield from mimics_said_once(
        loaded, "C410", "PyBullet ignores the <mimic> of {joints}: {they} freely",
        "couple them after loadURDF (createConstraint with JOINT_GEAR), or command each joint",
    )
