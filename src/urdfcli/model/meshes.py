"""A model's meshes: which file each mesh URI names, each use of a file by a link,
and what a run read of each file (see :mod:`.mesh_summaries`). Reading is lazy:
``check`` opens no mesh (whether a file exists is a ``stat``, see
:func:`urdfcli.read.meshfile.placeholder`).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from ..read.meshfile import MeshError, format_of, placeholder
from ..read.packages import PackageResolver
from ..read.memo import once
from .massprops import Vector
from .mesh_summaries import GeometryUnknown, MeshSummary, Properties, scaled_properties

if TYPE_CHECKING:
    from .load import Loaded
    from .robot import Link, Shape


# -- a model's meshes ------------------------------------------------------------------
class MeshFiles:
    """A model's mesh URIs to files, through its package resolver, each looked up once."""

    def __init__(self, resolver: PackageResolver, base: Path | None) -> None:
        self.resolver = resolver
        self.base = base
        self._found: dict[str, Path | None] = {}

    @classmethod
    def of(cls, loaded: Loaded) -> MeshFiles:
        return once(loaded, _mesh_files)

    def path(self, uri: str) -> Path | None:
        """The file a URI names (which may not exist), or None when it cannot be resolved."""
        if uri not in self._found:
            self._found[uri] = self.resolver.resolve_uri(uri, self.base)
        return self._found[uri]


def input_folder(loaded: Loaded) -> Path | None:
    """The folder relative paths are taken from: the input's."""
    return loaded.document.file.parent if loaded.document.file else None


def resolved_resources(loaded: Loaded):
    """(at, kind, uri, path) for each mesh and texture the model names; ``path`` is None when
    the URI cannot be resolved (a package not found, a network address)."""
    files = MeshFiles.of(loaded)
    for at, kind, uri in loaded.robot.resources:
        yield at, kind, uri, files.path(uri)


def uri_style(uri: str) -> str | None:
    """How a URI names a local file: "file" (file://), "absolute" or "relative"; None for
    package:// and network addresses."""
    if uri.startswith("file://"):
        return "file"
    if "://" in uri or not uri:
        return None
    return "absolute" if os.path.isabs(uri) or (len(uri) > 2 and uri[1] == ":" and uri[2] in "/\\") else "relative"


class MeshUse(NamedTuple):
    """One ``<mesh>`` of a link's visual or collision, and the file it names."""

    link: Link
    role: str  # visual or collision
    index: int  # among the link's shapes of that role
    shape: Shape
    uri: str
    path: Path | None  # None when the URI cannot be resolved (D005 says why)

    @property
    def scale(self) -> Vector:
        return tuple(self.shape.geometry.scale)  # type: ignore[return-value]

    @property
    def name(self) -> str:
        return Path(self.uri).name


def mesh_uses(loaded: Loaded) -> list[MeshUse]:
    """Every mesh of the model's links, in document order of links; worked out once."""
    return once(loaded, _mesh_uses)


def _mesh_files(loaded: Loaded) -> MeshFiles:
    return MeshFiles(loaded.resolver, input_folder(loaded))


def _mesh_uses(loaded: Loaded) -> list[MeshUse]:
    return list(_each_mesh_use(loaded))


def _each_mesh_use(loaded: Loaded):
    files = MeshFiles.of(loaded)
    for link in loaded.robot.links.values():
        for role, shapes in (("visual", link.visuals), ("collision", link.collisions)):
            for index, shape in enumerate(shapes):
                geometry = shape.geometry
                if geometry is not None and geometry.kind == "mesh" and geometry.filename:
                    yield MeshUse(link, role, index, shape, geometry.filename, files.path(geometry.filename))


def summary_of(loaded: Loaded, use: MeshUse) -> MeshSummary | None:
    """The summary of a use's file, read once per session; None when the file is not
    there or this run reads no mesh (``check``)."""
    if use.path is None or not loaded.reads_meshes or not use.path.is_file():
        return None
    return loaded.meshes.summary(use.path)


def mesh_properties(loaded: Loaded, filename: str, scale: Vector) -> Properties:
    """Volume, centre, tensor per unit mass and bounds (lowest and highest corner) of
    a mesh of ``loaded``, ``scale`` applied; its file read once per session. Raises
    GeometryUnknown. A mesh that is not closed has no inside: its convex hull stands in."""
    path = MeshFiles.of(loaded).path(filename)
    if path is None:
        raise GeometryUnknown(f"mesh {filename} cannot be resolved")
    if not path.is_file():
        where = "" if str(path) in filename else f" ({path})"  # (a file:// URI names its path already)
        raise GeometryUnknown(f"mesh {filename} not found{where}")
    found = loaded.meshes.summary(path)
    name = Path(filename).name  # (for the messages below)
    if found.problem is not None:
        raise GeometryUnknown(f"mesh {name} cannot be read: {found.problem.message}")
    if found.skipped is not None:
        raise GeometryUnknown(f"mesh {name}: {found.skipped}")
    if found.solid is None:
        raise GeometryUnknown(f"mesh {name} has no volume")
    return scaled_properties(found, scale)


def stat_problem(path: Path) -> MeshError | None:
    """What a ``stat`` tells of an existing file: empty, or a Git LFS pointer."""
    try:
        size = os.stat(path).st_size
    except OSError:
        return None
    return placeholder(path, size)


# -- a file that is not where a URI says -----------------------------------------------
SEARCHED_UP = 3  # folders above the missing file's whose meshes/ folder is looked in


def near_misses(path: Path) -> list[Path]:
    """Files that a missing ``path`` probably meant: one in its folder that differs only
    in case or extension (the first loads on macOS and Windows, not on Linux), else one
    of its name in a ``meshes/`` folder beside a folder above it (up to SEARCHED_UP)."""
    name, stem = path.name.lower(), path.stem.lower()
    folder = path.parent
    here = _entries(folder)
    found = [p for p in here if p.name.lower() == name] or [p for p in here if p.stem.lower() == stem and p.is_file()]
    if found:
        return sorted(found)
    for above in list(folder.parents)[:SEARCHED_UP]:
        meshes = above / "meshes"
        if meshes.is_dir() and meshes != folder:
            found = [p for p in _entries(meshes) if p.name.lower() == name]
            found += [p for sub in _entries(meshes) if sub.is_dir() for p in _entries(sub) if p.name.lower() == name]
            if found:
                return sorted(found)
    return []


def _entries(folder: Path) -> list[Path]:
    try:
        return list(folder.iterdir())
    except OSError:
        return []


# -- what lint tells of each mesh (JSON) ----------------------------------------------
class MeshFileUse(NamedTuple):
    """One use of a mesh file: the link, its role (visual or collision), the scale, and
    the unit the file looks like it was written in, when F003 says so."""

    link: str
    role: str
    scale: tuple[float, float, float]
    looks_like: str | None


class MeshFile(NamedTuple):
    """A mesh file the model names, as ``lint`` read it: its URI, the file, format,
    triangle count, declared unit (metres per unit, COLLADA), size in metres (unit
    applied, scale not), whether it is watertight, why it could not be read; and its uses."""

    uri: str
    path: str | None
    format: str | None
    triangles: int | None
    unit: float | None
    size: tuple[float, ...] | None
    watertight: bool | None
    problem: str | None
    uses: tuple[MeshFileUse, ...]

    def as_dict(self) -> dict:
        return {
            **self._asdict(),
            "size": list(self.size) if self.size is not None else None,
            "uses": [{**use._asdict(), "scale": list(use.scale)} for use in self.uses],
        }


def mesh_files(loaded: Loaded, verdicts=None) -> list[MeshFile]:
    """Each mesh file the model names (first use first), with its uses (``verdicts(use)``:
    F003's verdict on a use, if any)."""
    found: dict[str, MeshFile] = {}
    for use in mesh_uses(loaded):
        if use.uri not in found:
            summary = summary_of(loaded, use)
            found[use.uri] = MeshFile(
                use.uri,
                str(use.path) if use.path is not None else None,
                summary.format if summary is not None else format_of(use.uri),
                summary.triangles if summary is not None else None,
                summary.unit if summary is not None else None,
                tuple(float(f"{v:.6g}") for v in summary.size) if summary is not None and summary.size is not None else None,
                summary.watertight if summary is not None else None,
                (summary.problem.message if summary.problem else summary.skipped) if summary is not None else None,
                (),
            )
        verdict = verdicts(use) if verdicts is not None else None
        entry = found[use.uri]
        found[use.uri] = entry._replace(uses=(*entry.uses, MeshFileUse(use.link.name, use.role, tuple(use.scale), verdict.unit if verdict is not None else None)))
    return list(found.values())
