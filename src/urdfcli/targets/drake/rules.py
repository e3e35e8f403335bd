"""Drake 1.51's URDF parser (``Parser(plant).AddModels``): multibody/parsing/detail_urdf_parser.cc,
``ParseSpatialInertia`` in multibody/parsing/detail_common.cc, geometry in detail_urdf_geometry.cc."""

from __future__ import annotations

from ...model import massprops
from ...model.targets import declared_mass, mesh_extension
from .build import replaces
from ...rules.base import ERROR, INFO, WARNING, Kind, check, explain
from ...rules.targets.common import limit_at, link_at, number
from ...rules.targets.examples import INVERTED_LIMITS, ORDERED_LIMITS, TRIANGLE_BROKEN, TRIANGLE_KEPT, meshed

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
        if not replaces(link):
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
    for name, link in loaded.robot.links.items():
        for shape in link.collisions:
            geometry = shape.geometry
            if geometry is None or geometry.kind != "mesh" or not geometry.filename:
                continue
            extension = mesh_extension(geometry.filename)
            if extension not in CONVEX:
                yield loaded.diagnostic(
                    "C202",
                    f"Drake rejects link '{name}': collision mesh '{geometry.filename}' is not .obj, .vtk or .gltf",
                    geometry.at,
                    "give Drake an .obj copy of the collision mesh",
                    subjects=(name,),
                )


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
