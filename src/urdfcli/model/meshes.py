"""Mesh loading: a mesh file's volume, centre, tensor per unit mass and bounds.

yourdfpy and trimesh read the mesh, with urdfcli's package resolver as the filename
handler (never from a network); numpy, trimesh and yourdfpy are imported only when a
mesh file actually resolves.
"""

from __future__ import annotations

import contextlib
import os
import warnings
from pathlib import Path
from typing import TYPE_CHECKING

from ..read.packages import PackageResolver
from .massprops import Matrix, Vector

if TYPE_CHECKING:
    from .load import Loaded

Properties = tuple[float, Vector, Matrix, tuple[Vector, Vector]]  # volume, centre, tensor per unit mass, bounds


class GeometryUnknown(Exception):
    """The geometry cannot give mass properties (unreadable mesh, bad size...)."""


class MeshSummaries:
    """What a session learnt of each mesh file it read: its mass properties, read
    once per file and scale (again when the file changes), and nothing else of it."""

    def __init__(self) -> None:
        self._found: dict[tuple, Properties | GeometryUnknown] = {}

    def properties(self, filename: str, scale: Vector, files: MeshFiles) -> Properties:
        """See :func:`mesh_properties`. Raises GeometryUnknown."""
        path = files(filename)  # a mesh that does not resolve is told before numpy, trimesh and yourdfpy load (1-2 s)
        try:
            status = os.stat(path)
            stamp = (status.st_mtime_ns, status.st_size)
        except OSError:
            stamp = None
        key = (path, stamp, scale)
        if key not in self._found:
            try:
                self._found[key] = _mesh_properties(filename, scale, files)
            except GeometryUnknown as error:
                self._found[key] = error
        found = self._found[key]
        if isinstance(found, GeometryUnknown):
            raise found
        return found


class MeshFiles:
    """yourdfpy's filename handler: a mesh's URI to a file, through urdfcli's package resolver.

    Raises GeometryUnknown, which passes through yourdfpy, when there is no such file.
    Equal for one input's shapes, so each of its meshes is read once."""

    def __init__(self, resolver: PackageResolver, base: Path | None) -> None:
        self.resolver = resolver
        self.base = base
        self._found: dict[str, tuple[str | None, str]] = {}  # each URI looked up once

    def __eq__(self, other: object) -> bool:
        return isinstance(other, MeshFiles) and (self.resolver, self.base) == (other.resolver, other.base)

    def __hash__(self) -> int:
        return hash((self.resolver, self.base))

    @classmethod
    def of(cls, loaded: Loaded) -> MeshFiles:
        return loaded.remembered(
            "mesh files", lambda: cls(loaded.resolver, loaded.document.file.resolve().parent if loaded.document.file else None)
        )

    def __call__(self, fname: str) -> str:
        if fname not in self._found:
            self._found[fname] = self._look_up(fname)
        path, why = self._found[fname]
        if path is None:
            raise GeometryUnknown(why)
        return path

    def _look_up(self, fname: str) -> tuple[str | None, str]:
        """(the file, "") or (None, why not)."""
        path = self.resolver.resolve_uri(fname, self.base)
        if path is None:
            return None, f"mesh {fname} cannot be resolved"
        if not path.is_file():
            return None, f"mesh {fname} not found ({path})"
        return str(path), ""


def mesh_properties(loaded: Loaded, filename: str, scale: Vector) -> Properties:
    """Volume, centre, tensor per unit mass and bounds (lowest and highest corner) of
    a mesh of ``loaded``, ``scale`` applied; read once per session. Raises GeometryUnknown.

    yourdfpy loads it (with trimesh) as the collision geometry of a one-link robot.
    A mesh that is not closed has no inside: its convex hull stands in."""
    return loaded.meshes.properties(filename, scale, MeshFiles.of(loaded))


def _mesh_properties(filename: str, scale: Vector, files: MeshFiles) -> Properties:
    import numpy
    import trimesh
    import yourdfpy

    name = Path(filename).name
    geometry = yourdfpy.Geometry(mesh=yourdfpy.Mesh(filename=filename, scale=numpy.array(scale)))
    robot = yourdfpy.Robot(name="mesh", links=[yourdfpy.Link(name="mesh", collisions=[yourdfpy.Collision(name="mesh", geometry=geometry)])])
    try:
        with quiet_libraries():
            scene = yourdfpy.URDF(
                robot, build_scene_graph=False, build_collision_scene_graph=True, load_collision_meshes=True, filename_handler=files
            ).collision_scene
    except GeometryUnknown:
        raise
    except Exception as error:  # noqa: BLE001  (trimesh raises many kinds)
        raise GeometryUnknown(f"mesh {name} cannot be read: {error}") from None
    meshes = [m for m in scene.geometry.values() if isinstance(m, trimesh.Trimesh) and not m.is_empty]
    if not meshes:
        raise GeometryUnknown(f"mesh {name} has no triangles")
    mesh = meshes[0]
    if not mesh.is_watertight:
        mesh = mesh.convex_hull
    if mesh.volume < 0:
        mesh.invert()
    properties = mesh.mass_properties  # density 1: mass equals volume
    volume = float(properties["volume"])
    if volume <= 0:
        raise GeometryUnknown(f"mesh {name} has no volume")
    unit = tuple(tuple(float(v) / volume for v in row) for row in properties["inertia"])
    bounds = tuple(tuple(float(v) for v in corner) for corner in mesh.bounds)
    return volume, tuple(float(c) for c in properties["center_mass"]), unit, bounds  # type: ignore[return-value]


@contextlib.contextmanager
def quiet_libraries():
    """yourdfpy and trimesh log warnings to stderr (and yourdfpy calls a deprecated trimesh
    function); urdfcli reports the problems itself."""
    import logging  # only where a mesh is read

    loggers = [logging.getLogger(name) for name in ("yourdfpy", "trimesh")]
    levels = [logger.level for logger in loggers]
    for logger in loggers:
        logger.setLevel(logging.CRITICAL)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            yield
    finally:
        for logger, level in zip(loggers, levels):
            logger.setLevel(level)
