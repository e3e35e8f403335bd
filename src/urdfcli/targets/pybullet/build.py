"""PyBullet 3.2.7 (``pybullet.loadURDF``): the bodies it builds, from examples/Importers/ImportURDFDemo
(UrdfParser.cpp, BulletUrdfImporter.cpp, URDF2Bullet.cpp)."""

from __future__ import annotations

import math
import os
from pathlib import Path

from ...model import massprops
from ...model.load import Loaded
from ...model.massprops import Vector
from ...model.mesh_summaries import scaled_bounds
from ...model.meshes import MeshFiles
from ...read.meshfile import stl_header
from ...model.robot import Geometry, Link
from ...model.targets import Body, Build, Consumer, Profile, Variant, declared_mass, declared_matrix, declared_moments, joint_dof, mesh_extension, moving, tree_joints, valid_tensor


MARGIN = 0.001  # gUrdfDefaultCollisionMargin (BulletUrdfImporter.cpp): each collision shape's and each link's compound shape's
HULL = 2 * MARGIN  # a convex hull's box grows by its margin twice (its cached box holds it, btTransformAabb adds it again)
OBJ = HULL + MARGIN  # an .obj mesh is a compound of hulls, one per object of the file (createConvexHullFromShapes)


def box_moments(loaded: Loaded, link: Link, mass: float) -> Vector | None:
    """The tensor PyBullet computes without URDF_USE_INERTIA_FROM_FILE, in the inertial frame.

    URDF2Bullet.cpp puts the link's collision shapes into a compound shape (margin 1 mm),
    each placed relative to the inertial frame, and takes ``calculateLocalInertia`` of
    the compound: a solid box filling its axis-aligned bounding box grown by the margin
    (btCompoundShape.cpp). One shape placed exactly at the inertial frame is used alone:
    a box gets the box formula, a sphere the sphere formula. A cylinder is a hull of 64
    points and a mesh the hull of its vertices (BulletUrdfImporter.cpp), each boxed with
    its margins (an .obj file a compound of them). None when a mesh's bounds are unknown
    (not read, or ``check``)."""
    if not loaded.reads_meshes and any(shape.geometry is not None and shape.geometry.kind == "mesh" for shape in link.collisions):
        return None  # a mesh's bounds are not read in this run
    shapes = [shape for shape in link.collisions if extracted(loaded, shape.geometry)]
    if not shapes:  # an empty compound: a box of the margin alone
        return _diagonal(massprops.box(mass, (2 * MARGIN,) * 3))
    inertial = link.inertial
    frame = massprops.transform(inertial.origin.xyz, inertial.origin.rpy) if inertial is not None else massprops.ORIGIN
    back = (massprops.transpose(frame[0]), tuple(-v for v in massprops.apply(massprops.transpose(frame[0]), frame[1])))
    poses = [massprops.compose(back, massprops.transform(shape.origin.xyz, shape.origin.rpy)) for shape in shapes]
    if len(poses) == 1 and poses[0] == massprops.ORIGIN and shapes[0].geometry is not None:
        geometry = shapes[0].geometry
        if geometry.kind == "box" and geometry.size is not None:
            return _diagonal(massprops.box(mass, geometry.size))
        if geometry.kind == "sphere" and geometry.radius is not None:
            return _diagonal(massprops.sphere(mass, geometry.radius))
        if geometry.kind == "mesh" and mesh_extension(geometry.filename or "") == ".obj":  # the file's compound alone
            box = shape_box(loaded, geometry)
            return _diagonal(massprops.box(mass, tuple(2 * h for h in box[1]))) if box is not None else None
    low, high = [math.inf] * 3, [-math.inf] * 3
    for shape, pose in zip(shapes, poses):
        box = shape_box(loaded, shape.geometry)
        if box is None:
            return None
        centre, half = box
        rotation, offset = pose
        if shape.geometry.kind != "sphere":  # btTransformAabb: the box of the turned box
            half = tuple(sum(abs(rotation[i][j]) * half[j] for j in range(3)) for i in range(3))
        centre = massprops.place(pose, centre)
        for i in range(3):
            low[i], high[i] = min(low[i], centre[i] - half[i]), max(high[i], centre[i] + half[i])
    return _diagonal(massprops.box(mass, tuple(h - lo + 2 * MARGIN for lo, h in zip(low, high))))


def extracted(loaded: Loaded, geometry: Geometry | None) -> bool:
    """Whether Bullet makes a shape of a collision geometry: it leaves out ("cannot extract
    mesh") an STL file that is not a binary STL of at least one triangle (LoadMeshFromSTL.h)."""
    if geometry is None or geometry.kind != "mesh" or not geometry.filename or mesh_extension(geometry.filename) != ".stl" or not loaded.reads_meshes:
        return True
    path = MeshFiles.of(loaded).path(geometry.filename)
    try:
        header = stl_header(path) if path is not None and path.is_file() else None
    except OSError:
        return True
    return header is None or (bool(header.triangles) and header.binary)


def _diagonal(tensor) -> Vector:
    return (tensor[0][0], tensor[1][1], tensor[2][2])


def shape_box(loaded: Loaded, geometry: Geometry | None) -> tuple[Vector, Vector] | None:
    """A collision shape's bounding box in its own frame as Bullet has it: centre and half sizes."""
    if geometry is None:
        return None
    if geometry.kind == "box" and geometry.size is not None:
        return (0.0, 0.0, 0.0), tuple(d / 2.0 for d in geometry.size)  # type: ignore[return-value]
    if geometry.kind == "sphere" and geometry.radius is not None:
        return (0.0, 0.0, 0.0), (geometry.radius,) * 3
    if geometry.kind == "cylinder" and geometry.radius is not None and geometry.length is not None:
        return (0.0, 0.0, 0.0), (geometry.radius + HULL, geometry.radius + HULL, geometry.length / 2.0 + HULL)
    if geometry.kind == "mesh" and geometry.filename:
        bounds = mesh_bounds(loaded, geometry)
        if bounds is None:
            return None
        low, high = bounds
        grown = OBJ if mesh_extension(geometry.filename) == ".obj" else HULL
        return tuple((a + b) / 2.0 for a, b in zip(low, high)), tuple((b - a) / 2.0 + grown for a, b in zip(low, high))  # type: ignore[return-value]
    return None


def mesh_bounds(loaded: Loaded, geometry: Geometry) -> tuple[Vector, Vector] | None:
    """The box of a mesh's vertices, its scale applied; None when this run does not read meshes."""
    path = MeshFiles.of(loaded).path(geometry.filename) if loaded.reads_meshes else None
    if path is None or not path.is_file():
        return None
    summary = loaded.meshes.summary(path)
    if summary.low is None:
        return None
    return scaled_bounds(summary, tuple(geometry.scale))  # type: ignore[arg-type]


MESH_READERS = (".dae", ".stl", ".obj", ".cdf")  # the last four characters UrdfFindMeshFile.h takes


def missing_mesh(uri: str, files: MeshFiles, model: Path | None, folders_with: dict[str, list[str]] | None = None) -> str | None:
    """Why PyBullet cannot find a mesh (UrdfFindMeshFile.h), None when it finds it: the
    extension (its last four characters) must be one it reads; ``package://`` or
    ``model://`` is dropped and the rest looked up under the packages it is given (those
    urdfcli resolves) and under each folder above the model. A plain path that leads
    nowhere is D004's. ``folders_with`` keeps, per first name of a path, the folders above
    the model that hold it (each folder looked at once per model)."""
    if len(uri) <= 4 or uri[-4:].lower() not in MESH_READERS:
        return f"it has no reader for mesh '{uri}' (it reads .stl, .obj, .dae and .cdf files)"
    for prefix in ("package://", "model://"):
        if not uri.startswith(prefix):
            continue
        path = files.path(uri)
        if path is not None and path.exists():
            return None
        rest = uri[len(prefix):].lstrip("/")
        first = rest.split("/", 1)[0]
        found = folders_with if folders_with is not None else {}
        if first not in found:  # (plain os.path: this runs for every mesh of every model)
            above = [str(folder) for folder in (model.parent, *model.parent.parents)] if model is not None else []
            found[first] = [folder for folder in above if os.path.exists(os.path.join(folder, first))]
        if not any(os.path.isfile(os.path.join(folder, rest)) for folder in found[first]) and not os.path.isfile(rest):
            return f"it cannot find mesh '{uri}' ('cannot find ... in any directory in urdf path')"
    return None


def link_inertia(loaded: Loaded, link: Link, from_file: bool) -> tuple[float | None, Vector | None, str]:
    """Mass, principal moments and their source, as PyBullet sets them for one link."""
    inertial = link.inertial
    if inertial is None:
        if link.name == "world":
            return 0.0, (0.0, 0.0, 0.0), "none (a link named world is the fixed base)"
        if from_file:
            return 1.0, (1.0, 1.0, 1.0), "the default 1 kg and unit tensor (no <inertial>)"
        return 1.0, box_moments(loaded, link, 1.0), "the default 1 kg (no <inertial>), tensor from the collision shapes' bounding box"
    mass = inertial.mass
    if from_file:
        tensor = declared_matrix(link)
        if tensor is None or mass is None:
            return mass, None, "declared"
        moments = declared_moments(loaded, link)
        if not valid_tensor(mass, tensor, moments=moments):
            return mass, (0.0, 0.0, 0.0), "zero (the declared tensor is not physical)"
        return mass, moments, "declared"
    if mass is None:
        return None, None, "declared mass"
    return mass, box_moments(loaded, link, mass), "declared mass, tensor from the collision shapes' bounding box"


def build(loaded: Loaded, chosen: Profile) -> Build:
    from_file = "inertia-from-file" in chosen.variants
    bodies = []
    for name, link in loaded.robot.links.items():
        mass, moments, source = link_inertia(loaded, link, from_file)
        joint = loaded.parent_joint(name)
        bodies.append(Body((name,), joint if moving(joint) else None, mass, moments, source))
    changed, dof = {}, 0
    for joint in tree_joints(loaded):
        limit = joint.limit
        if joint.type == "floating":
            changed[joint.name] = "fixed (PyBullet does not support floating joints)"
            continue
        if joint.type in ("revolute", "prismatic") and limit is not None and limit.lower > limit.upper:
            changed[joint.name] = "unlimited (lower > upper)"
        elif joint.type in ("revolute", "prismatic") and limit is not None and not limit.has_lower and not limit.has_upper:
            changed[joint.name] = "unlimited (its <limit> has no lower and upper)"
        if joint.mimic is not None:
            changed[joint.name] = "a free degree of freedom (<mimic> ignored)"
        dof += joint_dof(joint)
    root = loaded.root
    base_mass = declared_mass(loaded.robot.links[root]) if root is not None and loaded.robot.links[root].inertial is not None else None
    fixed = "fixed-base" in chosen.variants or root == "world" or base_mass == 0
    return Build(chosen, tuple(bodies), {}, "fixed" if fixed else "floating", dof + (0 if fixed else 6), changed)


# The plain errors whose models it loads all the same (tests/target_cases.py: PLAIN_ERRORS, one case each)
LOADS_ANYWAY = frozenset({
    "D013", "F001", "I001", "I005", "J007", "J008", "J009", "M001", "N003", "N006", "R003", "V001", "V002", "V003",
    "V006", "V007", "V010", "X002",
})

CONSUMER = Consumer("pybullet", "PyBullet", "C4", "pybullet 3.2.7 (PyPI), pybullet.loadURDF in DIRECT mode", (Variant("inertia-from-file", "loadURDF(path, flags=URDF_USE_INERTIA_FROM_FILE)"), Variant("fixed-base", "loadURDF(path, useFixedBase=True)")), build, LOADS_ANYWAY)
