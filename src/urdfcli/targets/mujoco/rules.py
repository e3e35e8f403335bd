"""MuJoCo 4.0's URDF reader (``mujoco.MjModel.from_xml_path``): src/xml/xml_urdf.cc, its
URDF defaults (fusestatic, discardvisual) in src/xml/xml.cc, the mass checks in
src/user/user_model.cc and user_objects.cc."""

from __future__ import annotations

from ...model import massprops
from ...model.kinematics import roots
from ...model.meshes import MeshFiles
from ...model.targets import declared_tensors, mesh_extension
from .. import build
from .build import MJEPS, MJMINVAL, compiler_options, geometry_body, weighed_by_geometry
from ...read.memo import once as memo
from ...read.meshfile import stl_header
from ...rules.base import ERROR, INFO, WARNING, Kind, check, explain
from ...rules.targets.common import BOUNDED, inertial_at, joints_of, limit_at, link_at, names, number, once
from ...rules.targets.examples import INVERTED_LIMITS, ORDERED_LIMITS, TRIANGLE_BROKEN, TRIANGLE_KEPT, WRIST_BOX, arm, meshed, wrist_inertial

DECODED = (".stl", ".obj", ".msh")  # the mesh files MuJoCo 4.0 decodes without a plugin
STL_TRIANGLES = 200_000  # the most MuJoCo's STL decoder takes (src/user/user_mesh.cc)


@check(
    "C101", "mujoco-massless-body", ERROR, "MuJoCo rejects a moving body without mass or inertia.", kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`: finds a body moved by a joint whose mass, or one of
        whose principal moments, is below MuJoCo's `mjMINVAL` (1e-15). The body is the
        child link of the moving joint with every link fixed below it (MuJoCo fuses
        them, `fusestatic`); a link without `<inertial>` but with collision shapes gets
        their mass at 1000 kg/m³. Measures the declared masses and tensors; leaves alone
        links whose mass comes from a mesh (its volume is not read), and bodies with a
        link whose tensor MuJoCo refuses on its own (C103): it stops there first.""",
        """MuJoCo refuses to load the model: "mass and inertia of moving bodies must be
        larger than mjMINVAL" (src/user/user_model.cc).""",
        arm(),
        arm(wrist_inertial("0.5", "1e-3")),
    ),
)
def massless_body(loaded, given):
    refused = _not_positive(loaded)
    for body in build(loaded, given.profile).bodies:
        if body.joint is None or body.mass is None:
            continue
        if any(name in refused for name in body.links):
            continue  # MuJoCo stops at that link's tensor first: C103's
        if body.mass < MJMINVAL:
            why = f"its mass is {number(body.mass)}" if body.mass else "it has no mass"
        elif body.moments is not None and min(body.moments) < MJMINVAL:
            why = "its inertia tensor is zero" if max(body.moments) < MJMINVAL else "a principal moment of its inertia is zero"
        else:
            continue
        fused = f" (with {names(body.links[1:])} fused into it)" if len(body.links) > 1 else ""
        yield loaded.diagnostic(
            "C101",
            f"MuJoCo rejects link '{body.top}'{fused}, moved by joint '{body.joint.name}': {why}",
            inertial_at(loaded, body.top),
            "give it an <inertial> with a positive mass and tensor, or collision shapes MuJoCo can weigh",
            subjects=(*body.links, body.joint.name),
        )


@check(
    "C102", "mujoco-triangle-inequality", ERROR, "MuJoCo rejects an inertia breaking A + B >= C.", kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`: finds a declared inertia whose principal moments break
        the triangle inequality (A + B >= C), unless the model sets
        `<mujoco><compiler balanceinertia="true"/></mujoco>`.""",
        """MuJoCo refuses to load the model: "inertia must satisfy A + B >= C; use
        'balanceinertia' to fix" (src/user/user_objects.cc). No body of that shape exists.""",
        TRIANGLE_BROKEN,
        TRIANGLE_KEPT,
    ),
)
def triangle_inequality(loaded, given):
    if compiler_options(loaded).balanceinertia:
        return
    for name, declared in declared_tensors(loaded).items():
        positive = not declared.zero and declared.moments[0] > 0  # else C103's
        broken = massprops.triangle_violation(declared.written, rel_tol=1e-9, moments=declared.written_moments) if positive else None  # MuJoCo compares without a margin
        if broken is not None:
            a, b, c = broken
            yield _rejected_tensor(
                loaded, "C102", name, f"breaks the triangle inequality A + B >= C ({number(a)} + {number(b)} < {number(c)})",
                'fix the tensor, or let MuJoCo raise the small moments: <mujoco><compiler balanceinertia="true"/></mujoco>',
            )


@check("C103", "mujoco-inertia-not-positive", ERROR, "MuJoCo rejects an inertia whose smallest eigenvalue is below 1e-14.", kind=Kind.TARGET, target="mujoco")
def inertia_not_positive(loaded, given):
    """## What it does
    With `--target mujoco`: finds a declared inertia, on any link (the root and fixed
    links too), that is not all zero but has a principal moment below MuJoCo's
    `mjEPS` (1e-14): zero, negative, or positive and that small. An all-zero tensor
    is C101's.

    ## Why is this bad?
    MuJoCo reads every URDF tensor as `fullinertia` and refuses to load the model:
    "inertia must have positive eigenvalues" (`mjuu_fullInertia`, src/user/user_util.cc).
    A CAD export of a tiny part (1e-16 kg·m²) is refused as a negative one is.

    ## Example
    ```xml
    <link name="wrist">
      <inertial><mass value="1"/><inertia ixx="0.01" ixy="0.02" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="wrist">
      <inertial><mass value="1"/><inertia ixx="0.01" ixy="0.002" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    </link>
    ```
    """
    for name, smallest in _not_positive(loaded).items():
        yield _rejected_tensor(
            loaded, "C103", name, f"has a principal moment of {number(smallest)}; all must be at least 1e-14",
            "recompute the tensor (inertia --suggest prints one for its geometry)",
        )


def _rejected_tensor(loaded, code: str, name: str, why: str, hint: str):
    """A link's inertia MuJoCo refuses, at its <inertia>."""
    inertial = loaded.robot.links[name].inertial
    return loaded.diagnostic(code, f"MuJoCo rejects link '{name}': its inertia {why}", inertial.inertia_at or inertial.at, hint, subjects=(name,))


def _not_positive(loaded) -> dict[str, float]:
    """Each link whose declared tensor MuJoCo's fullinertia refuses (not all zero, a principal
    moment below mjEPS), with that moment (rounding noise as 0): the model stops there, before
    any mass check."""
    return {
        name: massprops.without_noise(declared.moments)[0]
        for name, declared in declared_tensors(loaded).items()
        if not declared.zero and declared.moments[0] < MJEPS
    }


def _meshes(loaded, discardvisual: bool) -> tuple:
    """(link, geometry) of each mesh MuJoCo reads, listed once per model for the mesh rules."""
    return memo(loaded, _mesh_list, discardvisual)


def _mesh_list(loaded, discardvisual: bool) -> tuple:
    found = []
    for name, link in loaded.robot.links.items():
        shapes = link.collisions if discardvisual else (*link.visuals, *link.collisions)
        for shape in shapes:
            geometry = shape.geometry
            if geometry is not None and geometry.kind == "mesh" and geometry.filename:
                found.append((name, geometry))
    return tuple(found)


@check(
    "C104", "mujoco-mesh-format", ERROR, "MuJoCo cannot decode a mesh file of this format.", kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`: finds a collision mesh (and a visual one when the model
        sets `discardvisual="false"`) whose file extension is not one MuJoCo decodes:
        `.stl`, `.obj` or `.msh`. Judged by the extension; the file is not read.""",
        """MuJoCo refuses to load the model: "no decoder found for mesh file" (src/user/user_mesh.cc).
        COLLADA (`.dae`) meshes, common in ROS packages, are not read.""",
        meshed("base.dae"),
        meshed("base.stl"),
    ),
)
def mesh_format(loaded, given):
    found: dict[str, list] = {}  # extension -> the links and meshes: said once per extension
    for name, geometry in _meshes(loaded, compiler_options(loaded).discardvisual):
        extension = mesh_extension(geometry.filename)
        if extension not in DECODED:
            found.setdefault(extension, []).append((name, geometry))
    for extension, meshes in found.items():
        kind = extension or "extension-less"
        yield once(loaded, "C104", meshes, kind, "MuJoCo rejects link '{link}': it has no decoder for " + kind + " mesh", "convert the meshes to .stl or .obj for MuJoCo")


@check(
    "C105", "mujoco-package-uri", ERROR, "MuJoCo does not resolve package:// mesh paths.", kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`: finds a collision mesh (and a visual one when the model
        sets `discardvisual="false"`) named by a `package://` URI.""",
        """MuJoCo's URDF reader takes a mesh filename as a path relative to the model's
        folder (`strippath` is false in 4.0) and never resolves `package://`: loading
        fails on a file that does not exist (src/xml/xml_urdf.cc).""",
        meshed("package://my_robot/meshes/arm.stl"),
        meshed("../meshes/arm.stl"),
    ),
)
def package_uri(loaded, given):
    meshes = [(name, g) for name, g in _meshes(loaded, compiler_options(loaded).discardvisual) if g.filename.startswith("package://")]
    if meshes:  # said once per model
        yield once(loaded, "C105", meshes, "package://", "MuJoCo rejects link '{link}': it does not resolve",
            "give MuJoCo a copy with paths relative to the model (`urdfcli expand` then replace package://PKG/ by the package's path), or set <mujoco><compiler meshdir=.../></mujoco>",
        )


@check(
    "C109", "mujoco-stl-decoder", ERROR, "MuJoCo reads only binary STL files of at most 200,000 triangles.", kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`: finds a collision mesh (and a visual one when the model
        sets `discardvisual="false"`) whose `.stl` file is not a binary STL (an ASCII STL,
        or a file shorter or longer than its header's triangle count says), or holds more
        than 200,000 triangles. Reads the file's size and its first 84 bytes, as MuJoCo
        does before decoding; a file that cannot be found is left to D004.""",
        """MuJoCo refuses to load the model: "number of faces should be between 1 and
        200000 in STL file; perhaps this is an ASCII file?" (src/user/user_mesh.cc).
        CAD exports and older ROS packages often write ASCII STL, which RViz, Gazebo
        and PyBullet read.""",
        meshed("../meshes/arm_ascii.stl"),
        meshed("../meshes/arm.stl"),
    ),
)
def stl_decoder(loaded, given):
    files = MeshFiles.of(loaded)
    found: dict[tuple, list] = {}  # problem -> the links and meshes: said once per problem
    for name, geometry in _meshes(loaded, compiler_options(loaded).discardvisual):
        if mesh_extension(geometry.filename) != ".stl" or geometry.filename.startswith("package://"):  # C105 says package://
            continue
        path = files.path(geometry.filename)
        try:
            problem = _stl_problem(stl_header(path)) if path is not None and path.is_file() else None
        except OSError:
            continue
        if problem is not None:
            found.setdefault(problem, []).append((name, geometry))
    for (why, hint), meshes in found.items():
        yield once(loaded, "C109", meshes, "such", "MuJoCo rejects link '{link}': " + why, hint)


def _stl_problem(header) -> tuple[str, str] | None:
    """Why MuJoCo's STL decoder refuses a file, and the fix; None when it reads it."""
    if header.binary and 1 <= header.triangles <= STL_TRIANGLES:
        return None
    if header.binary and header.triangles > STL_TRIANGLES:
        return (f"its STL decoder takes at most {STL_TRIANGLES:,} triangles per file, exceeded by",
                "decimate the mesh (a collision mesh needs a few thousand triangles, or use a convex hull)")
    if header.binary:
        return ("its STL decoder needs at least one triangle, and there is none in", "re-export the mesh")
    if header.solid:
        return ("it reads only binary STL, not the ASCII STL",
                "convert the file to binary STL (for example: trimesh.load(path).export(path), or MeshLab)")
    return ("it reads only binary STL whose size matches its header, unlike", "re-export the mesh as binary STL")


@check(
    "C106", "mujoco-unlimited-joint", WARNING, "MuJoCo drops a joint's limits when lower >= upper.", kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`: finds a revolute or prismatic joint whose lower limit is
        not below its upper one.""",
        """MuJoCo makes the joint unlimited: without a word when lower > upper, with the
        warning "equal lower and upper limits, limit ignored" when they are equal
        (src/xml/xml_urdf.cc). A joint meant to be stopped turns freely.""",
        INVERTED_LIMITS,
        ORDERED_LIMITS,
    ),
)
def unlimited_joint(loaded, given):
    for joint in joints_of(loaded, BOUNDED):
        limit = joint.limit
        if limit is not None and limit.lower >= limit.upper:
            how = "they are equal" if limit.lower == limit.upper else "lower is above upper"
            yield loaded.diagnostic(
                "C106",
                f"MuJoCo makes joint '{joint.name}' unlimited: its limits are {number(limit.lower)} and {number(limit.upper)}, and {how}",
                limit_at(joint),
                "give lower < upper; a joint that must not move is a fixed joint",
                subjects=(joint.name,),
            )


@check(
    "C107", "mujoco-mass-from-geometry", WARNING, "MuJoCo weighs a moving link without <inertial> by its collision shapes.", kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`: finds a moving body none of whose links has an
        `<inertial>`, but which has collision shapes, while `inertiafromgeom` is `auto`
        (the URDF default) or `true`. One diagnostic names every such link, at the first
        written, with the mass MuJoCo gives them in all (that of a mesh is not worked out).""",
        """MuJoCo gives the body the mass and inertia of its collision shapes filled at
        1000 kg/m³ (src/user/user_objects.cc, `inertiafromgeom`): a 10 cm box weighs
        1 kg, a hollow shell as much as a solid. Other consumers see no mass at all.""",
        arm(WRIST_BOX),
        arm(wrist_inertial("0.3", "5e-4"), WRIST_BOX),
    ),
)
def mass_from_geometry(loaded, given):
    options = compiler_options(loaded)
    moving = {name for body in build(loaded, given.profile).bodies if body.joint is not None for name in body.links}
    weighed = [link for name, link in loaded.robot.links.items() if name in moving and weighed_by_geometry(link, options)]
    if not weighed:
        return
    masses = [found[0] for found in map(geometry_body, weighed) if found is not None]  # (a mesh's is not known here)
    if len(weighed) == 1:
        weight = f"{number(masses[0])} kg" if masses else "the mass of its meshes"
        message = f"MuJoCo gives link '{weighed[0].name}' {weight}: it has no <inertial>, so its collision shapes are filled at 1000 kg/m³"
    else:  # one cause: one diagnostic, as an exported arm without a single <inertial> has it on every link
        total = "" if not masses else f": {number(sum(masses))} kg in all" if len(masses) == len(weighed) else f": {number(sum(masses))} kg in their primitive shapes, and what their meshes weigh"
        message = f"MuJoCo gives {len(weighed)} links without <inertial> ({names(link.name for link in weighed)}) the mass of their collision shapes filled at 1000 kg/m³{total}"
    yield loaded.diagnostic(
        "C107", message, weighed[0].at, "give each link an <inertial> with its real mass and tensor" if len(weighed) > 1 else "give the link an <inertial> with its real mass and tensor",
        subjects=tuple(link.name for link in weighed),
    )


@check("C108", "mujoco-fixed-base", INFO, "MuJoCo welds the root link to the world.", kind=Kind.TARGET, target="mujoco")
def fixed_base(loaded, given):
    """## What it does
    With `--target mujoco`: says, once per model, that the root link is welded to the
    world and fused into the world body, and names the links fused into their
    moving parents (fixed joints, `fusestatic`).

    ## Why is this bad?
    `from_xml_path` adds no free joint: a mobile robot or a humanoid loaded from its
    URDF cannot move its base, and the root's mass leaves the model. A fused link's
    name no longer exists in the model, so code asking MuJoCo for that body fails
    (src/xml/xml.cc sets `fusestatic` for URDF).

    ## Example
    ```xml
    <robot name="rover">
      <link name="chassis"><inertial><mass value="5"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="rover">
      <link name="world"/>
      <link name="chassis"><inertial><mass value="5"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
      <joint name="free" type="floating"><parent link="world"/><child link="chassis"/></joint>
    </robot>
    ```
    """
    tops = [root for root in roots(loaded.robot)]
    if not tops:
        return
    root = tops[0]
    built = build(loaded, given.profile)
    fused = [link for body in built.bodies for link in body.links[1:]] + [link for link in built.dropped if link not in (*tops, "world")]
    if tops == ["world"] and not fused:
        return
    several = len(fused) > 1
    also = f"{'links' if several else 'link'} {names(fused)} {'are' if several else 'is'} fused into {'their' if several else 'its'} parent body" if fused else ""
    welded = [top for top in tops if top != "world"]
    welds = (f"MuJoCo welds root link{'s' if len(welded) > 1 else ''} {names(welded)} to the world and fuses {'them' if len(welded) > 1 else 'it'} into the world body"
             if welded else "In MuJoCo, ")
    yield loaded.diagnostic(
        "C108",
        welds + ("; " if fused and welded else "") + also,
        link_at(loaded, root),
        "; ".join(part for part in (
            welded and "for a free base, join the root to a massless 'world' link by a floating joint",
            fused and 'keep fused links with <mujoco><compiler fusestatic="false"/></mujoco>',
        ) if part),  # (a root already named world is fixed on purpose: Shadow's hand)
        subjects=(*tops, *fused),
    )


@check(
    "C110", "mujoco-mesh-missing", ERROR, "MuJoCo refuses a collision mesh file that does not exist.", kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`: finds a collision mesh (and a visual one when the model
        sets `discardvisual="false"`) named by a path that leads to no file (relative paths
        from the model's folder, as MuJoCo reads them; `package://` is C105's): one
        diagnostic for the model, at the first, naming the links whose files are missing.""",
        """MuJoCo refuses to load the model: "Error opening file" (src/user/user_mesh.cc).
        A missing visual mesh is no matter to MuJoCo, which drops the visuals.""",
        meshed("../meshes/gone.stl"),
        meshed("../meshes/arm.stl"),
    ),
)
def mesh_missing(loaded, given):
    files = MeshFiles.of(loaded)
    missing = []
    for name, geometry in _meshes(loaded, compiler_options(loaded).discardvisual):
        if "://" in geometry.filename and not geometry.filename.startswith("file://"):
            continue
        path = files.path(geometry.filename)
        if path is not None and not path.exists():
            missing.append((name, geometry, path))
    if not missing:
        return
    name, geometry, _ = missing[0]  # one cause, one refusal: MuJoCo stops at the first file it cannot open
    links = list(dict.fromkeys(link for link, _, _ in missing))
    what = f"link '{name}'" if len(links) == 1 else f"{len(links)} links ({names(links)})"
    more = len({path for _, _, path in missing}) - 1  # files, not references: a servo's mesh serves five links
    files_said = f"mesh file '{geometry.filename}' does not exist" + (f" (nor {more} more file{'s' if more > 1 else ''})" if more else "")
    yield loaded.diagnostic(
        "C110", f"MuJoCo rejects {what}: {files_said}", geometry.at,
        "fix the path (relative to the model's folder) or add the file", subjects=tuple(links),
    )


@check(
    "C112", "mujoco-obj-first-object", ERROR, "MuJoCo reads the first object of an .obj file alone: it refuses one that encloses no volume.",
    kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`, where mesh files are read (`lint`, `inertia`; `check`
        reads none): finds a collision mesh (and a visual one when the model sets
        `discardvisual="false"`) whose `.obj` file holds several objects (an `o` or `g` line
        after its first faces) and whose first object encloses less than 1e-15 m³, its
        scale applied: a flat plate or a single sheet exported first.""",
        """MuJoCo 4.0 reads the first object of an `.obj` file alone, and refuses to load
        the model: "mesh volume is too small" (src/user/user_mesh.cc). PyBullet, Drake,
        RViz and Gazebo read every object of the file, so the file looks right everywhere
        else.""",
        meshed("../meshes/arm_parts.obj"),
        meshed("../meshes/arm.obj"),
    ),
)
def obj_first_object(loaded, given):
    if not loaded.reads_meshes:
        return
    files = MeshFiles.of(loaded)
    for name, geometry in _meshes(loaded, compiler_options(loaded).discardvisual):
        if mesh_extension(geometry.filename) != ".obj" or geometry.filename.startswith("package://"):  # C105 says package://
            continue
        path = files.path(geometry.filename)
        if path is None or not path.is_file():
            continue
        first = loaded.meshes.summary(path).first_volume
        scale = abs(geometry.scale[0] * geometry.scale[1] * geometry.scale[2])
        if first is not None and first * scale < MJMINVAL:
            yield loaded.diagnostic(
                "C112", f"MuJoCo rejects link '{name}': it reads only the first object of '{geometry.filename}', which encloses no volume",
                geometry.at, "put the solid object first in the file, or merge the file's objects into one", subjects=(name,),
            )


@check(
    "C111", "mujoco-shape-size", ERROR, "MuJoCo refuses a collision shape of zero or negative size.", kind=Kind.TARGET, target="mujoco",
    doc=explain(
        """With `--target mujoco`: finds a collision box, cylinder or sphere (and a visual one
        when the model sets `discardvisual="false"`) with a size, radius or length of 0 or
        less.""",
        """MuJoCo refuses to load the model: "size 0 must be positive in geom"
        (src/user/user_objects.cc); urdfdom and RViz take a zero size (V008 only warns).""",
        '<link name="plate">\n  <collision><geometry><box size="0.4 0.4 0"/></geometry></collision>\n</link>',
        '<link name="plate">\n  <collision><geometry><box size="0.4 0.4 0.01"/></geometry></collision>\n</link>',
    ),
)
def shape_size(loaded, given):
    discardvisual = compiler_options(loaded).discardvisual
    for name, link in loaded.robot.links.items():
        for shape in link.collisions if discardvisual else (*link.visuals, *link.collisions):
            geometry = shape.geometry
            if geometry is None or geometry.kind not in ("box", "cylinder", "sphere"):
                continue
            sizes = geometry.size if geometry.kind == "box" else (geometry.radius, geometry.length) if geometry.kind == "cylinder" else (geometry.radius,)
            if sizes is not None and any(size is not None and size <= 0 for size in sizes):
                yield loaded.diagnostic(
                    "C111", f"MuJoCo rejects link '{name}': its {geometry.kind} has a size of {number(min(v for v in sizes if v is not None))}",
                    geometry.at, "give the shape a positive size, or leave it out", subjects=(name,),
                )
