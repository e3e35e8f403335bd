"""Drake 1.51's URDF parser (``Parser(plant).AddModels``): multibody/parsing/detail_urdf_parser.cc,
``ParseSpatialInertia`` in multibody/parsing/detail_common.cc, geometry in detail_urdf_geometry.cc."""

from __future__ import annotations

from ...model import massprops
from ...model.meshes import MeshFiles
from ...read.memo import once as memo
from ...read.packages import uri_package
from ...model.targets import declared_mass, mesh_extension
from .build import replaces
from ...rules.base import ERROR, INFO, WARNING, Kind, check, explain
from ...rules.targets.common import joints_of, limit_at, link_at, names, number, once
from ...rules.targets.examples import INVERTED_LIMITS, ORDERED_LIMITS, TRIANGLE_BROKEN, TRIANGLE_KEPT, meshed

_NO_BOUNDS = '<joint name="elbow" type="revolute"><parent link="arm"/><child link="forearm"/><limit effort="10" velocity="1"/></joint>'
_BOUNDS = '<joint name="elbow" type="revolute"><parent link="arm"/><child link="forearm"/><limit lower="-1.5" upper="1.5" effort="10" velocity="1"/></joint>'
CONVEX = (".obj", ".vtk", ".gltf")  # the collision meshes Drake 1.51 makes a convex hull of


@check(
    "C201", "drake-replaces-inertia", WARNING, "Drake replaces an invalid inertia with a water sphere.", kind=Kind.TARGET, target="drake",
    doc=explain(
        """With `--target drake`: finds a link whose `<inertial>` fails Drake's validity
        test (a negative mass, a zero mass with a tensor, a tensor with a negative
        principal moment or breaking the triangle inequality).""",
        """Drake warns and replaces the inertia with that of a solid sphere of water of the
        declared mass, or of 1 kg when the mass is not positive (`ParseSpatialInertia`:
        "return a prepared plausible inertia"): a negative mass becomes +1 kg, and the
        simulation runs on a body the model does not describe.""",
        TRIANGLE_BROKEN,
        TRIANGLE_KEPT,
    ),
)
def replaces_inertia(loaded, given):
    for name, link in loaded.robot.links.items():
        if not replaces(loaded, link):
            continue
        mass = declared_mass(link)
        used = mass if mass > 0 else 1.0
        why = ("its mass is negative" if mass < 0 else "it has a tensor but no mass" if mass == 0
               else "its tensor has a negative principal moment" if not massprops.is_positive_semidefinite(massprops.matrix(link.inertial.inertia))
               else "its tensor breaks the triangle inequality")
        yield loaded.diagnostic(
            "C201",
            f"Drake replaces the inertia of link '{name}' with a solid water sphere of {number(used)} kg: {why}",
            link.inertial.inertia_at or link.inertial.at,
            "fix the <inertial> (inertia --suggest prints one for its geometry)",
            subjects=(name,),
        )


@check(
    "C202", "drake-collision-mesh-format", ERROR, "Drake rejects collision meshes other than .obj, .vtk and .gltf.", kind=Kind.TARGET, target="drake",
    doc=explain(
        """With `--target drake`: finds a collision mesh whose file extension is not `.obj`,
        `.vtk` or `.gltf`. Judged by the extension; the file is not read.""",
        """Drake 1.51 makes a convex hull of each collision mesh and refuses others:
        "MakeConvexHull only applies to .obj, .vtk, and .gltf meshes" — the `.stl` and
        `.dae` meshes of most ROS packages included.""",
        meshed("base.stl"),
        meshed("base.obj"),
    ),
)
def collision_mesh_format(loaded, given):
    found: dict[str, list] = {}  # extension -> the links and meshes: said once per extension
    for name, link in loaded.robot.links.items():
        for shape in link.collisions:
            geometry = shape.geometry
            if geometry is not None and geometry.kind == "mesh" and geometry.filename and mesh_extension(geometry.filename) not in CONVEX:
                found.setdefault(mesh_extension(geometry.filename), []).append((name, geometry))
    for extension, meshes in found.items():
        yield once(loaded, "C202", meshes, extension or "extension-less", "Drake rejects link '{link}': it makes convex hulls of .obj, .vtk and .gltf collision meshes only, not",
                   "give Drake .obj copies of the collision meshes")


@check("C203", "drake-material-redefined", ERROR, "Drake rejects a material name given two colours.", kind=Kind.TARGET, target="drake")
def material_redefined(loaded, given):
    """## What it does
    With `--target drake`: finds a material name defined again with another colour
    (at the top level or inside a `<visual>`), compared value for value.

    ## Why is this bad?
    Drake refuses the model: "Material 'NAME' was previously defined"
    (detail_urdf_parser.cc), where other consumers keep the first colour.

    ## Example
    ```xml
    <robot name="r">
      <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
      <link name="base">
        <visual><geometry><box size="1 1 1"/></geometry><material name="grey"><color rgba="0.2 0.2 0.2 1"/></material></visual>
      </link>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r">
      <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
      <link name="base">
        <visual><geometry><box size="1 1 1"/></geometry><material name="dark_grey"><color rgba="0.2 0.2 0.2 1"/></material></visual>
      </link>
    </robot>
    ```
    """
    document = loaded.document
    first: dict[str, tuple] = {}
    for material in _materials(loaded):
        if not material.name or (material.rgba is None and material.texture is None):
            continue
        seen = first.setdefault(material.name, (material.rgba, material.texture, material.at))
        if (material.rgba, material.texture) != seen[:2]:
            place = document.locate(seen[2])
            yield loaded.diagnostic(
                "C203",
                f"Drake rejects material '{material.name}': it was defined at {place.file}:{place.line} with another colour",
                material.at,
                "give each colour its own material name",
                subjects=(material.name,),
            )


def _materials(loaded):
    """Every material definition, top-level and inside visuals, in document order."""
    robot = loaded.robot
    return sorted((*robot.materials.values(), *robot.visual_materials), key=lambda m: m.at)


@check(
    "C204", "drake-aborts", ERROR, "Drake aborts (SystemExit) on lower > upper or a zero-size shape.", kind=Kind.TARGET, target="drake",
    doc=explain(
        """With `--target drake`: finds what trips an assertion in Drake's parser: a joint
        whose lower limit is above its upper one (revolute, prismatic, or continuous
        with both), and a box or cylinder with a zero size.""",
        """The assertion ends in `SystemExit` in Python ("condition
        '(pos_lower_limits.array() <= pos_upper_limits.array()).all()' failed",
        multibody/tree/joint.h): a script that only catches `Exception` dies.""",
        INVERTED_LIMITS,
        ORDERED_LIMITS,
    ),
)
def aborts(loaded, given):
    for joint in loaded.robot.joints.values():
        limit = joint.limit
        kept = joint.type in ("revolute", "prismatic") or (joint.type == "continuous" and limit is not None and limit.has_lower and limit.has_upper)
        if kept and limit is not None and limit.lower > limit.upper:
            yield loaded.diagnostic(
                "C204",
                f"Drake aborts (SystemExit) on joint '{joint.name}': its lower limit {number(limit.lower)} is above its upper {number(limit.upper)}",
                limit_at(joint),
                "swap lower and upper",
                subjects=(joint.name,),
            )
    for name, link in loaded.robot.links.items():
        for shape in (*link.visuals, *link.collisions):
            geometry = shape.geometry
            if geometry is None or geometry.kind not in ("box", "cylinder"):
                continue
            sizes = geometry.size if geometry.kind == "box" else (geometry.radius, geometry.length)
            if sizes is not None and any(size == 0 for size in sizes):
                yield loaded.diagnostic(
                    "C204",
                    f"Drake aborts (SystemExit) on link '{name}': its {geometry.kind} has a zero size",
                    geometry.at,
                    "give the shape a positive size, or leave it out",
                    subjects=(name,),
                )


@check("C205", "drake-continuous-limits", WARNING, "Drake keeps the limits of a continuous joint.", kind=Kind.TARGET, target="drake")
def continuous_limits(loaded, given):
    """## What it does
    With `--target drake`: finds a continuous joint whose `<limit>` has both `lower`
    and `upper`.

    ## Why is this bad?
    URDF says a continuous joint has no position limits, and other consumers ignore
    them; Drake 1.51 makes the joint a revolute joint stopped at those limits
    (detail_urdf_parser.cc): a wheel that should turn forever stops.

    ## Example
    ```xml
    <joint name="wheel" type="continuous">
      <parent link="base"/><child link="wheel"/>
      <limit lower="-3.14" upper="3.14" effort="10" velocity="5"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <joint name="wheel" type="continuous">
      <parent link="base"/><child link="wheel"/>
      <limit effort="10" velocity="5"/>
    </joint>
    ```
    """
    for joint in loaded.robot.joints.values():
        limit = joint.limit
        if joint.type == "continuous" and limit is not None and limit.has_lower and limit.has_upper and limit.lower <= limit.upper:
            yield loaded.diagnostic(
                "C205",
                f"Drake stops continuous joint '{joint.name}' at its limits {number(limit.lower)} and {number(limit.upper)}",
                limit_at(joint),
                "leave lower and upper out of a continuous joint's <limit>, or make it revolute",
                subjects=(joint.name,),
            )


@check("C206", "drake-floating-base", INFO, "Drake lets the root link float.", kind=Kind.TARGET, target="drake")
def floating_base(loaded, given):
    """## What it does
    With `--target drake`: says, once per model, that the root link becomes a free
    body (6 degrees of freedom), unless the model joins it to a link named `world`.

    ## Why is this bad?
    A fixed arm loaded as is falls under gravity, and its state has 7 more
    positions than its joints (detail_urdf_parser.cc: only a joint to `world` fixes it).

    ## Example
    ```xml
    <robot name="arm">
      <link name="base"/>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="arm">
      <link name="world"/>
      <link name="base"/>
      <joint name="mount" type="fixed"><parent link="world"/><child link="base"/></joint>
    </robot>
    ```
    """
    root = loaded.root
    if root is None or root == "world":
        return
    yield loaded.diagnostic(
        "C206",
        f"Drake lets root link '{root}' float (6 degrees of freedom)",
        link_at(loaded, root),
        "to fix it, join it to a link named 'world' by a fixed joint (or weld it with plant.WeldFrames)",
        subjects=(root,),
    )


def _simple_transmissions(loaded) -> tuple:
    """The transmissions Drake makes actuators of: a type (its <type>, else its ``type``
    attribute) naming a SimpleTransmission; it skips the others with a warning. Listed
    once per model (C209 and C213 read them)."""
    return memo(loaded, _transmissions)


def _transmissions(loaded) -> tuple:
    found = []
    for block in loaded.robot.blocks("transmission"):
        written = block.find("type")
        kind = (written.text or "") if written is not None else block.get("type")
        if kind and "SimpleTransmission" in kind:
            found.append(block)
    return tuple(found)


def _has_colour(material) -> bool:
    return material.rgba is not None or material.texture is not None


@check("C207", "drake-material-undefined", ERROR, "Drake refuses a material with no colour that is defined nowhere.", kind=Kind.TARGET, target="drake")
def material_undefined(loaded, given):
    """## What it does
    With `--target drake`: finds a `<material>` inside a `<visual>` that gives neither a
    colour nor a texture, whose name neither a top-level `<material>` nor an earlier
    `<visual>` defines with a colour or a texture.

    ## Why is this bad?
    Drake refuses the model: "Material 'NAME' not previously defined, but has no color
    or texture information" (detail_urdf_parser.cc). urdfdom and RViz only warn (M002)
    and draw the visual in a default colour.

    ## Example
    ```xml
    <robot name="r">
      <link name="base">
        <visual><geometry><box size="1 1 1"/></geometry><material name="steel"/></visual>
      </link>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r">
      <material name="steel"><color rgba="0.6 0.6 0.6 1"/></material>
      <link name="base">
        <visual><geometry><box size="1 1 1"/></geometry><material name="steel"/></visual>
      </link>
    </robot>
    ```
    """
    robot = loaded.robot
    defined = {name for name, material in robot.materials.items() if _has_colour(material)}
    for material in robot.visual_materials:  # in document order: a visual's colour defines its name for those after it
        if material.name and _has_colour(material):
            defined.add(material.name)
        elif material.name and material.name not in defined:
            yield loaded.diagnostic(
                "C207", f"Drake refuses material '{material.name}': it has no colour or texture and no top-level material defines it",
                material.at, f'define it once at the top: <material name="{material.name}"><color rgba="..."/></material>',
                subjects=(material.name,),
            )


@check("C208", "drake-package-not-found", ERROR, "Drake refuses a package:// file of a package it is not given.", kind=Kind.TARGET, target="drake")
def package_not_found(loaded, given):
    """## What it does
    With `--target drake`: finds a mesh or texture named by a `package://` URI whose
    package urdfcli cannot find (`-P`, `ROS_PACKAGE_PATH`, `AMENT_PREFIX_PATH`, the
    packages around the model). Drake is given what urdfcli finds (`--load` passes it
    as the parser's package map); a program of your own must add the same packages
    (`parser.package_map().Add(NAME, PATH)`).

    ## Why is this bad?
    Drake refuses the model: "URI 'package://PKG/...' refers to unknown package 'PKG'"
    (multibody/parsing/package_map.cc), for a visual's texture as for a mesh.

    ## Example
    ```xml
    <link name="base">
      <visual><geometry><mesh filename="package://no_such_robot/meshes/base.obj"/></geometry></visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="base">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></visual>
    </link>
    ```
    """
    files = MeshFiles.of(loaded)
    looked_up: set[str] = set()  # each package looked up once, through its first URI: found or said
    for at, kind, uri in loaded.robot.resources:
        package = uri_package(uri)
        if package is None:
            continue
        if package in looked_up:
            continue
        looked_up.add(package)
        if files.path(uri) is not None:
            continue
        yield loaded.diagnostic(
            "C208", f"Drake refuses {kind} '{uri}': it knows no package '{package}' (urdfcli finds none)", at,
            f"give urdfcli and Drake the package: -P {package or 'NAME'}=DIR here, parser.package_map().Add('{package or 'NAME'}', DIR) in Drake",
        )


@check("C209", "drake-duplicate-actuator", ERROR, "Drake refuses two transmissions naming one actuator.", kind=Kind.TARGET, target="drake")
def duplicate_actuator(loaded, given):
    """## What it does
    With `--target drake`: finds an actuator name that two `<transmission>` elements of
    type SimpleTransmission give (Drake skips the other types).

    ## Why is this bad?
    Drake makes a joint actuator of each transmission's actuator and refuses the model:
    "Model instance 'NAME' already contains a joint actuator named 'ACTUATOR'"
    (detail_urdf_parser.cc, multibody/tree). ros2_control reads the transmissions as
    independent and takes it.

    ## Example
    ```xml
    <transmission name="t1"><type>transmission_interface/SimpleTransmission</type>
      <joint name="shoulder"/><actuator name="motor"/></transmission>
    <transmission name="t2"><type>transmission_interface/SimpleTransmission</type>
      <joint name="elbow"/><actuator name="motor"/></transmission>
    ```

    ## Use instead
    ```xml
    <transmission name="t1"><type>transmission_interface/SimpleTransmission</type>
      <joint name="shoulder"/><actuator name="shoulder_motor"/></transmission>
    <transmission name="t2"><type>transmission_interface/SimpleTransmission</type>
      <joint name="elbow"/><actuator name="elbow_motor"/></transmission>
    ```
    """
    first: dict[str, str] = {}
    for block in _simple_transmissions(loaded):
        actuator = block.find("actuator")
        name = actuator.get("name") if actuator is not None else None
        if not name:
            continue
        if name in first:
            yield loaded.diagnostic(
                "C209", _shared_actuator_message(block.get("name") or "", first[name], name),
                loaded.robot.place(actuator) or loaded.robot.place(block), _shared_actuator_hint(block.get("name") or "", first[name]),
                subjects=(name,),
            )
        else:
            first[name] = block.get("name") or ""


def _shared_actuator_message(transmission: str, earlier: str, actuator: str) -> str:
    # A transmission written again under its own name (one per hardware interface, as
    # franka_description does for Gazebo) is a repeat, not a second transmission.
    if transmission == earlier:
        return f"Drake refuses transmission '{transmission}', written twice: both make actuator '{actuator}'"
    return f"Drake refuses transmission '{transmission}': actuator '{actuator}' is already transmission '{earlier}''s"


def _shared_actuator_hint(transmission: str, earlier: str) -> str:
    if transmission == earlier:
        return "write the transmission once, with one <hardwareInterface> per interface in its <joint>, or name each actuator apart"
    return "give each transmission an actuator of its own name"


@check(
    "C210", "drake-fixed-mimic", ERROR, "Drake refuses a <mimic> on a fixed joint.", kind=Kind.TARGET, target="drake",
    doc=explain(
        """With `--target drake`: finds a fixed joint with a `<mimic>`.""",
        """Drake refuses the model: "Joint 'NAME' which has 0 DOF cannot mimic joint 'OTHER'
        which has 1 DOF" (detail_urdf_parser.cc); urdfdom and the ROS tools ignore the
        mimic of a joint that cannot move.""",
        '<joint name="tip" type="fixed"><parent link="finger"/><child link="pad"/><mimic joint="finger_joint"/></joint>',
        '<joint name="tip" type="fixed"><parent link="finger"/><child link="pad"/></joint>',
    ),
)
def fixed_mimic(loaded, given):
    for joint in loaded.robot.joints.values():
        if joint.type == "fixed" and joint.mimic is not None:
            yield loaded.diagnostic(
                "C210", f"Drake refuses joint '{joint.name}': a fixed joint cannot mimic '{joint.mimic.joint}'",
                joint.part("mimic") or joint.at, "leave the <mimic> out of the fixed joint", subjects=(joint.name,),
            )


@check(
    "C211", "drake-unbounded-limit", WARNING, "Drake makes a joint whose <limit> has no lower and upper unlimited.", kind=Kind.TARGET, target="drake",
    doc=explain(
        """With `--target drake`: finds a revolute or prismatic joint whose `<limit>` gives
        neither `lower` nor `upper`.""",
        """URDF reads the missing bounds as 0 (urdfdom, Pinocchio, Gazebo and KDL keep the
        joint at [0, 0]); Drake leaves the joint unlimited (detail_urdf_parser.cc): the
        same file moves in Drake and not elsewhere.""",
        _NO_BOUNDS,
        _BOUNDS,
    ),
)
def unbounded_limit(loaded, given):
    for joint in joints_of(loaded, ("revolute", "prismatic")):
        limit = joint.limit
        if limit is not None and not limit.has_lower and not limit.has_upper:
            yield loaded.diagnostic(
                "C211", f"Drake leaves joint '{joint.name}' unlimited: its <limit> has no lower and no upper (other consumers read [0, 0])",
                limit_at(joint), "give lower and upper, or make it continuous", subjects=(joint.name,),
            )


@check(
    "C212", "drake-ignores-friction", WARNING, "Drake drops a joint's <dynamics friction>.", kind=Kind.TARGET, target="drake",
    doc=explain(
        """With `--target drake`: says, once per model, which joints have a `<dynamics>` friction other than 0.""",
        """Drake warns "MultibodyPlant does not currently support non-zero joint friction"
        and simulates the joint without it (detail_urdf_parser.cc); only the damping is kept.""",
        '<joint name="elbow" type="continuous"><parent link="arm"/><child link="forearm"/><dynamics damping="0.1" friction="0.5"/></joint>',
        '<joint name="elbow" type="continuous"><parent link="arm"/><child link="forearm"/><dynamics damping="0.1"/></joint>',
    ),
)
def ignores_friction(loaded, given):
    joints = [joint for joint in loaded.robot.joints.values() if joint.dynamics is not None and joint.dynamics.friction and joint.type != "fixed"]
    if joints:
        first = joints[0]
        yield loaded.diagnostic(
            "C212", f"Drake drops the <dynamics friction> of {len(joints)} joint{'s' if len(joints) > 1 else ''} ({names(j.name for j in joints)}): it has no joint friction",
            first.part("dynamics") or first.at, "model the friction in your controller, or leave it out for Drake", subjects=tuple(j.name for j in joints),
        )


@check(
    "C213", "drake-no-actuator", WARNING, "Drake skips the transmission of a joint whose effort limit is 0.", kind=Kind.TARGET, target="drake",
    doc=explain(
        """With `--target drake`: finds a SimpleTransmission whose joint's `<limit effort>` is 0.""",
        """Drake makes no actuator of it ("Skipping transmission since it's attached to joint
        ... which has a zero effort limit", detail_urdf_parser.cc): the joint cannot be driven.""",
        '<joint name="elbow" type="revolute"><parent link="arm"/><child link="forearm"/><limit lower="-1" upper="1" effort="0" velocity="1"/></joint>\n'
        '<transmission name="t"><type>transmission_interface/SimpleTransmission</type><joint name="elbow"/><actuator name="m"/></transmission>',
        '<joint name="elbow" type="revolute"><parent link="arm"/><child link="forearm"/><limit lower="-1" upper="1" effort="20" velocity="1"/></joint>\n'
        '<transmission name="t"><type>transmission_interface/SimpleTransmission</type><joint name="elbow"/><actuator name="m"/></transmission>',
    ),
)
def no_actuator(loaded, given):
    for block in _simple_transmissions(loaded):
        element = block.find("joint")
        joint = loaded.robot.joints.get(element.get("name")) if element is not None else None
        if joint is not None and joint.limit is not None and joint.limit.effort == 0:
            yield loaded.diagnostic(
                "C213", f"Drake makes no actuator for joint '{joint.name}': its effort limit is 0, so transmission '{block.get('name')}' is skipped",
                loaded.robot.place(block), "give the joint its real effort limit", subjects=(joint.name,),
            )

