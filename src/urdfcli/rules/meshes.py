"""Mesh rules: each mesh file judged as rviz, Gazebo and the simulators will read it.

A mesh is read once per run (:mod:`urdfcli.model.meshes`); `check` opens none and
judges what a ``stat`` shows. A missing file is D004, a package that cannot be
found D005.
"""

from __future__ import annotations

import math
import re
from collections import defaultdict
from pathlib import Path

from ..diagnostics import Fix, SetAttribute
from ..model import massprops
from ..model.inertia import shape_bounds
from ..model.kinematics import bodies
from ..model.mesh_summaries import GeometryUnknown
from ..model.meshes import MeshUse, mesh_uses, resolved_resources, stat_problem, summary_of, uri_style
from ..model.poses import body_poses
from ..model.units import PLACEHOLDER, mis_scaled, unit_verdict
from .base import ERROR, INFO, PLACED, SAFE, UNSAFE, WARNING, Kind, RuleSet, check

HINTS = {
    "lfs": "fetch the LFS files: `git lfs install && git lfs pull` (in CI, check out with LFS, e.g. actions/checkout's `lfs: true`)",
    "empty": "export the mesh again: an empty file is what an interrupted export or copy leaves",
    "truncated": "the file was cut short (an interrupted copy, download or export): fetch or export it again",
    "malformed": "export it again from the CAD tool, or open it in a mesh viewer to see what is wrong",
    "missing": "check the file's permissions",
}


def _grouped(uses, key):
    """Uses grouped by ``key`` (None left out), in the order of their first use."""
    groups: dict = defaultdict(list)
    for use in uses:
        found = key(use)
        if found is not None:
            groups[found].append(use)
    return groups


def others_there(uris) -> str:
    """' and N other files there' for the URIs of one folder besides the first ('' for one)."""
    extra = len(set(uris)) - 1
    return f" and {extra} other {'files' if extra > 1 else 'file'} there" if extra else ""


def _others(uses: list, what: str = "use") -> str:
    extra = len(uses) - 1
    return f" (and {extra} other {what}{'s' if extra > 1 else ''})" if extra else ""


@check("F001", "mesh-unreadable", ERROR, "A mesh file that is not a mesh its format can read: empty, a Git LFS pointer, truncated or undecodable.", kind=Kind.FILES)
def mesh_unreadable(loaded, given):
    """## What it does
    Flags a mesh file that exists but that no consumer can read: an empty file, a
    Git LFS pointer (the repository was cloned without its LFS files), a binary STL
    shorter than its header says, an ASCII STL without `endsolid`, an OBJ whose
    faces name vertices it does not have, a COLLADA file that is not well-formed
    XML or names geometry it does not define, and names the problem. `check` finds
    what a `stat` and a look at the first bytes of a file under 1 KiB show (empty,
    LFS pointer); `lint` reads the file. Formats urdfcli does not read (Ogre's
    `.mesh`) are left alone; so are formats a consumer rejects (`--target` says it).

    ## Why is this bad?
    RViz logs an error and shows nothing, Gazebo and the simulators fail to load
    the robot or drop the shape: the model works on no machine that has this file.

    ## Example
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm_lfs.stl"/></geometry></visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></visual>
    </link>
    ```
    """
    uses = [use for use in mesh_uses(loaded) if use.path is not None and use.path.is_file()]
    for path, group in _grouped(uses, lambda use: use.path).items():
        problem = _problem(loaded, group[0], path)
        if problem is not None:
            yield loaded.diagnostic(
                "F001", f"mesh '{group[0].uri}'{_others(group)}: {problem.message}", group[0].shape.geometry.at, HINTS.get(problem.kind),
                subjects=tuple(dict.fromkeys(use.link.name for use in group)),
            )


def _problem(loaded, use: MeshUse, path: Path):
    if not loaded.reads_meshes:
        return stat_problem(path)
    return summary_of(loaded, use).problem


@check("F002", "mesh-path-not-portable", WARNING, "A mesh or texture named by an absolute, `file://` or relative path instead of `package://`.", rule_set=RuleSet.LINT, fix=SAFE, fix_doc="Writes the `package://` URI of each file named by a `file://` URI or an absolute path, when the file is in a package "
       "(safe: the same file is loaded). A relative path is left: MuJoCo, PyBullet and Drake read it, and not `package://`." f" {PLACED}")
def path_not_portable(loaded, given):
    """## What it does
    Flags a `<mesh filename>` or `<texture filename>` that names an existing file by
    a `file://` URI, an absolute path or a path relative to the URDF, and names the
    `package://` URI that works (the package holding the file, found by its
    `package.xml`). One diagnostic per folder and kind of path. A file that does not
    exist is D004's.

    ## Why is this bad?
    An absolute path works on one machine only. ROS reads meshes through
    resource_retriever, which takes only `package://` and `file://` URIs
    (`FilesystemRetriever::can_handle` in ros/resource_retriever): RViz and
    MoveIt show nothing for a plain or relative path, although MuJoCo, PyBullet
    and Drake take a relative path from the URDF's folder. A `file://$(find pkg)/...`
    written in a xacro source is left alone: the source is portable (each machine's
    expansion names its own folder), and Gazebo is given the file so on purpose.

    ## Example
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="../meshes/arm.stl"/></geometry></visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></visual>
    </link>
    ```
    """
    groups: dict = defaultdict(list)
    for at, kind, uri, path in resolved_resources(loaded):
        style = uri_style(uri)
        if style is not None and path is not None and path.is_file() and not (style == "file" and written_with_find(loaded, at)):
            groups[(style, path.parent)].append((at, kind, uri, path))
    for (style, _), found in groups.items():
        at, kind, uri, path = found[0]
        extra = others_there(u for _, _, u, _ in found)
        portable = package_uri(loaded, path)
        fix = f"write {portable}" if portable else "put the files in a ROS package (a folder with a package.xml) and write package://PACKAGE/..."
        if style == "relative":
            message = f"{kind} '{uri}'{extra}: a relative path, which RViz and MoveIt cannot load (only package:// and file:// URIs)"
        elif style == "file":
            message = f"{kind} '{uri}'{extra}: a file:// URI works on this machine only"
        else:
            message = f"{kind} '{uri}'{extra}: an absolute path works on this machine only, and RViz reads only package:// and file:// URIs"
        yield loaded.diagnostic("F002", message, at, fix).with_fix(_portable_fix(loaded, style, found))


def _portable_fix(loaded, style: str, found) -> Fix:
    if style == "relative":
        return Fix("write package:// URIs", SAFE, reason="a relative path is what MuJoCo, PyBullet and Drake read: write package:// by hand if the model is for ROS")
    changes = []
    for at, _, _, path in found:
        portable = package_uri(loaded, path)
        if portable is None:
            return Fix("write package:// URIs", SAFE, reason=f"{path} is in no ROS package (no package.xml in a folder above it)")
        changes.append(SetAttribute(at, "filename", portable))
    title = f"write {changes[0].value}" + (f" and {len(changes) - 1} more package:// URI{'s' if len(changes) > 2 else ''}" if len(changes) > 1 else "")
    return Fix(title, SAFE, changes=tuple(changes))


_FILENAME = re.compile(r"""\bfilename\s*=\s*(["'])(.*?)\1""", re.DOTALL)


def written_with_find(loaded, at: int) -> bool:
    """Whether the xacro source wrote the URI with ``$(find ...)``: a file:// URI made on each
    machine from its own package folder, which is portable."""
    location = loaded.document.locate(at)
    if not loaded.document.is_xacro or location.expanded or not location.line:
        return False
    source = loaded.document.files.get(location.file)
    start = source.offset(location.line, location.column) if source is not None else None
    if start is None:
        return False
    end = source.text.find(">", start)
    written = _FILENAME.search(source.text, start, end if end >= 0 else None)
    return written is not None and "$(find" in written.group(2)


def package_uri(loaded, path: Path) -> str | None:
    """The package:// URI of a file inside a ROS package, or None."""
    index = loaded.resolver.index
    folder = index.enclosing_package(path.resolve().parent)
    name = index.package_name(folder / "package.xml") if folder is not None else None
    return f"package://{name}/{path.resolve().relative_to(folder).as_posix()}" if name else None


@check("F003", "mesh-units", WARNING, "A mesh in millimetres, centimetres or inches used as if in metres (or scaled down twice).", rule_set=RuleSet.LINT, fix=UNSAFE, fix_doc="Writes the mesh's `scale` that makes it metres, where the mesh was written (unsafe: the shape's size changes)." f" {PLACED}")
def mesh_units(loaded, given):
    """## What it does
    Flags a mesh whose size, after its `scale` and COLLADA's `<unit meter>` (which
    RViz and Gazebo apply: assimp's `ColladaLoader::InternReadFile` scales the root
    node by it, gz-common's `ColladaLoader::Load` the mesh), is about 1000, 100 or
    25.4 times off the size the rest of its link implies, and names the likely unit
    and the `scale` that fixes it. Each piece of evidence gives a band for the
    mesh's largest side, set from the 2,141 mesh uses of the 69 published
    example-robot-data models (all in metres) with a margin of three to ten:

    - the link's mass (20 g or more) in the mesh's bounding box: 1 to 1,000,000 kg/m³
      (the corpus spans 10 to 50,000);
    - the farthest child joint, `d` from the link's origin: 0.05 d to 50 d (corpus 0.16 d to 17 d);
    - the link's own joint, `p` from its parent: 0.02 p to 100 p (corpus 0.13 p to 35 p);
    - its boxes, cylinders and spheres (larger than 2 cm): 1/20 to 20 times their size.

    It is reported only when every band finds the mesh too large (the mass alone
    when the mesh would make the link a thousand times lighter than air, else two
    pieces of evidence) and the mesh divided by the unit fits every band; the unit
    nearest the middle of the bands is named. A mesh that fits any band is never
    reported. Other meshes are no evidence (exported together, they share a unit),
    nor is the declared tensor (too often wrong: I009). Too small is said only when
    a `scale` or `<unit>` shrank the mesh that much (a scale of 0.001 on a mesh
    already in metres). The inertia rules and `inertia --suggest` leave such a mesh
    out. On the corpus read as if in millimetres, 95 % of the meshes are found,
    99.4 % of those named millimetres; inches are seldom found (the bands are wider
    than 25.4 times).

    ## Why is this bad?
    CAD tools export millimetres by default. Used as metres, the mesh is a thousand
    times too large: RViz shows a robot the size of a building, collision checking
    finds collisions everywhere, and a simulator that derives mass properties from
    the mesh explodes.

    ## Example
    ```xml
    <link name="arm">
      <inertial>
        <mass value="5"/>
        <inertia ixx="0.0708" ixy="0" ixz="0" iyy="0.0708" iyz="0" izz="0.0083"/>
      </inertial>
      <visual><geometry><mesh filename="package://my_robot/meshes/arm_mm.stl"/></geometry></visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <inertial>
        <mass value="5"/>
        <inertia ixx="0.0708" ixy="0" ixz="0" iyy="0.0708" iyz="0" izz="0.0083"/>
      </inertial>
      <visual><geometry><mesh filename="package://my_robot/meshes/arm_mm.stl" scale="0.001 0.001 0.001"/></geometry></visual>
    </link>
    ```
    """
    flagged = [(use, verdict) for use in mesh_uses(loaded) if (verdict := unit_verdict(loaded, use)) is not None]
    groups = _grouped(flagged, lambda found: (found[0].path, found[0].scale, found[1].unit))
    for group in groups.values():
        use, verdict = group[0]
        scale = " ".join(f"{s:.6g}" for s in verdict.scale)
        if verdict.too_large:
            message = f"mesh '{use.name}' looks like {verdict.unit}: {verdict.size:.3g} m across on {verdict.evidence}{_others(group)}"
            hint = f'add scale="{scale}"' if use.scale == (1.0, 1.0, 1.0) else f'make its scale "{scale}"'
        else:
            message = f"mesh '{use.name}' is {1 / verdict.factor:.4g} times too small: {verdict.size:.3g} m across on {verdict.evidence}{_others(group)}"
            hint = f'its scale or <unit> converts from {verdict.unit} a mesh already in metres: make its scale "{scale}"'
        changes = tuple(dict.fromkeys(SetAttribute(u.shape.geometry.at, "scale", scale) for u, _ in group))
        fix = Fix(f'write scale="{scale}" on the mesh' + (f" ({len(changes)} uses)" if len(changes) > 1 else ""), UNSAFE, changes=changes)
        yield loaded.diagnostic("F003", message, use.shape.geometry.at, hint, subjects=tuple(dict.fromkeys(u.link.name for u, _ in group))).with_fix(fix)


SIZE_RATIO = 2.5  # bounding-box diagonals this many times apart: not a simplification
HEAVY = 20_000  # triangles


@check("F004", "collision-visual-mismatch", WARNING, "A collision far smaller or larger than its visual, or away from it.", rule_set=RuleSet.LINT)
def collision_visual_mismatch(loaded, given):
    """## What it does
    Compares the bounding box of the collision shapes with that of the visual shapes:
    of each rigid body (links joined by fixed joints, a collision on a fixed child
    counts), a collision whose box diagonal is more than 2.5 times smaller or larger
    than the visual's; of each link with both, a collision whose box centre is
    farther from the visual's than either box is large (a wrong `<origin>`). Left
    alone: placeholder shapes of 2 cm or less in every direction (a dot that keeps
    Gazebo from dropping a link, or a collision-only link), meshes in a wrong unit
    (F003), shapes that cannot be measured (a missing mesh), and simplified
    collisions within 2.5 times of the visual (the published Panda's reach 2.4).
    Displaced means farther than the visual is large too: Baxter carries part of
    a rolling link's collision on its parent, 1.3 times the collision's own size
    from the visual, on purpose.

    ## Why is this bad?
    The simulator and the planner see the collision, people see the visual. A
    collision twice too large stops the arm short of what it looks able to reach; a
    collision too small or in the wrong place lets the robot drive through
    obstacles it seems to touch.

    ## Example
    ```xml
    <link name="arm">
      <visual><geometry><box size="0.1 0.1 0.4"/></geometry></visual>
      <collision><geometry><box size="0.4 0.4 1.6"/></geometry></collision>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <visual><geometry><box size="0.1 0.1 0.4"/></geometry></visual>
      <collision><geometry><box size="0.1 0.1 0.4"/></geometry></collision>
    </link>
    ```
    """
    skipped = mis_scaled(loaded)
    boxes = {name: (_link_box(loaded, link.visuals, skipped), _link_box(loaded, link.collisions, skipped)) for name, link in loaded.robot.links.items()}
    displaced = set()
    for link in loaded.robot.links.values():
        visual, collision = boxes[link.name]
        if not visual or not collision:
            continue
        apart = math.dist(_centre(visual), _centre(collision))
        if apart > max(_diagonal(visual), _diagonal(collision)):
            displaced.add(link.name)
            yield loaded.diagnostic(
                "F004",
                f"collision of link '{link.name}' is {apart:.3g} m from its visual, farther than either is large "
                f"({_diagonal(collision):.3g} and {_diagonal(visual):.3g} m across)",
                link.collisions[0].at, "is the collision's <origin> wrong (an rpy written as xyz, a forgotten offset)?", subjects=(link.name,),
            )
    seen = set()
    for body in bodies(loaded).values():
        if body.top in seen or displaced.intersection(body.links):
            continue
        seen.add(body.top)
        if len(body.links) == 1:
            visual, collision = boxes[body.top]
        else:
            poses = body_poses(loaded, body.links)
            visual, collision = (_placed([(boxes[name][role], poses[name]) for name in body.links]) for role in (0, 1))
        if not visual or not collision:
            continue
        ratio = _diagonal(collision) / _diagonal(visual)
        if ratio > SIZE_RATIO or ratio < 1 / SIZE_RATIO:
            where = next(link for link in (loaded.robot.links[n] for n in body.links) if link.collisions)
            fixed = f" (with the links fixed to it: {', '.join(repr(n) for n in body.links[1:])})" if len(body.links) > 1 else ""
            size = f"{ratio:.3g} times larger" if ratio > 1 else f"{1 / ratio:.3g} times smaller"
            yield loaded.diagnostic(
                "F004",
                f"collision of link '{body.top}'{fixed} is {size} than its visual: {_diagonal(collision):.3g} against {_diagonal(visual):.3g} m across",
                where.collisions[0].at, "check the collision's size, scale and file: a simplified shape stays within a few times of the visual",
                subjects=body.links,
            )


UNMEASURED = ()  # a box that cannot be known: some shape cannot be measured (a missing mesh)


def _link_box(loaded, shapes, skipped: set[int]):
    """The box (link frame) holding the shapes, placeholders and mis-scaled meshes left out:
    None when none is left, UNMEASURED when one cannot be measured."""
    lows, highs = [], []
    for shape in shapes:
        if shape.geometry is None or shape.at in skipped:
            continue
        try:
            low, high = shape_bounds(loaded, shape)
        except GeometryUnknown:
            return UNMEASURED
        if high[0] - low[0] > PLACEHOLDER or high[1] - low[1] > PLACEHOLDER or high[2] - low[2] > PLACEHOLDER:
            lows.append(low)
            highs.append(high)
    if len(lows) < 2:  # (most links: none, or one shape's own box)
        return (lows[0], highs[0]) if lows else None
    return tuple(map(min, zip(*lows))), tuple(map(max, zip(*highs)))


def _placed(boxes):
    """The box (body-top frame) holding each (link box, link pose): UNMEASURED if one is."""
    if any(box == UNMEASURED for box, _ in boxes):
        return UNMEASURED
    corners = [massprops.place(pose, (x, y, z)) for (low, high), pose in ((b, p) for b, p in boxes if b) for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])]
    if not corners:
        return None
    return tuple(map(min, zip(*corners))), tuple(map(max, zip(*corners)))


def _centre(box) -> tuple[float, ...]:
    (x0, y0, z0), (x1, y1, z1) = box
    return ((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2)


def _diagonal(box) -> float:
    return math.dist(*box)


@check("F005", "collision-mesh-heavy", INFO, "A visual mesh of more than 20,000 triangles reused as the collision mesh.", rule_set=RuleSet.LINT)
def collision_mesh_heavy(loaded, given):
    """## What it does
    Notes (info) a link whose collision uses the same mesh file as its visual when
    that mesh has more than 20,000 triangles.

    ## Why is this bad?
    Collision checking costs grow with the triangles: planners and simulators slow
    down, and a simulator that needs a convex shape takes the hull anyway. A convex
    or decimated collision mesh (or a few primitives) is as good for contact.

    ## Example
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm_fine.stl"/></geometry></visual>
      <collision><geometry><mesh filename="package://my_robot/meshes/arm_fine.stl"/></geometry></collision>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm_fine.stl"/></geometry></visual>
      <collision><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></collision>
    </link>
    ```
    """
    uses = mesh_uses(loaded)
    shown = {(use.link.name, use.path) for use in uses if use.role == "visual" and use.path is not None}
    for use in uses:
        if use.role == "collision" and (use.link.name, use.path) in shown:
            found = summary_of(loaded, use)
            if found is not None and (found.triangles or 0) > HEAVY:
                yield loaded.diagnostic(
                    "F005", f"link '{use.link.name}' collides with its visual mesh '{use.name}', {found.triangles:,} triangles",
                    use.shape.geometry.at, "use a convex or decimated mesh, or primitives, for the collision", subjects=(use.link.name,),
                )


@check("F006", "collision-mesh-open", INFO, "A collision mesh that is not watertight where its volume is needed.", rule_set=RuleSet.LINT)
def collision_mesh_open(loaded, given):
    """## What it does
    Notes (info) a collision mesh that is not watertight (an edge not shared by
    exactly two faces wound opposite ways, corners within 2e-8 of the mesh's size
    welded, as trimesh's `is_watertight` after `merge_vertices`) on a link whose
    mass properties come from it: a link with mass (urdfcli's inertia estimate,
    which the inertia rules and `inertia --suggest` use) or a link without
    `<inertial>` (MuJoCo's URDF reader then infers its mass from the collision
    geoms, `inertiafromgeom`). Said once per model, at the first such mesh,
    naming the links of all of them: a CAD export often leaves every mesh open.
    PyBullet's inertia from collision shapes uses a mesh's bounding box, so an
    open mesh changes nothing there.

    ## Why is this bad?
    An open surface has no inside: its volume, and every inertia computed from it,
    is an artefact of where the holes are. urdfcli takes the convex hull instead;
    consumers each do something else.

    ## Example
    ```xml
    <link name="arm">
      <collision><geometry><mesh filename="package://my_robot/meshes/arm_open.stl"/></geometry></collision>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <collision><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></collision>
    </link>
    ```
    """
    needed = [use for use in mesh_uses(loaded) if use.role == "collision" and (use.link.inertial is None or (use.link.inertial.mass or 0) > 0)]
    open_meshes = [group for group in _grouped(needed, lambda use: use.path).values() if _is_open(loaded, group[0])]
    if open_meshes:  # one note per model: a CAD export often leaves every mesh open
        first = open_meshes[0][0]
        others = len(open_meshes) - 1
        more = f" and {others} other collision mesh{'es' if others > 1 else ''}" if others else ""
        yield loaded.diagnostic(
            "F006", f"collision mesh '{first.name}'{more} {'are' if others else 'is'} not watertight: volume and inertia are taken from the convex hull",
            first.shape.geometry.at, "close the meshes (or use convex ones) where mass properties are computed from them",
            subjects=tuple(dict.fromkeys(use.link.name for group in open_meshes for use in group)),
        )


def _is_open(loaded, use) -> bool:
    found = summary_of(loaded, use)
    return found is not None and found.watertight is False
