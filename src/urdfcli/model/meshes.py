"""Mesh files as a run knows them: each read once, summarised, and let go.

A :class:`MeshSummary` is what urdfcli keeps of a mesh file: its format, triangle
count, bounding box in metres (COLLADA's ``<unit meter>`` applied, as rviz and
Gazebo apply it; a ``<mesh scale>`` is not: it belongs to each use), whether it
is watertight, and the solid it encloses (volume, centre, second moments; the
convex hull's when the mesh is open). The session's :class:`MeshSummaries` reads
a file the first time a rule asks, and again only if it changes on disk; the
arrays are dropped as soon as the summary is made. Reading is lazy: ``check``
opens no mesh (whether a file exists is a ``stat``, see :func:`placeholder`).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from ..read.meshfile import MeshError, TooLarge, Triangles, Unsupported, format_of, placeholder, read_mesh
from ..read.packages import PackageResolver
from .massprops import Matrix, Vector

if TYPE_CHECKING:
    from .load import Loaded
    from .robot import Link, Shape

Properties = tuple[float, Vector, Matrix, tuple[Vector, Vector]]  # volume, centre, tensor per unit mass, bounds

CHUNK = 1 << 18  # triangles worked on at a time: the temporary arrays stay a few tens of MB
WELD = 2e-8  # corners closer than this fraction of a mesh's extent are one vertex


class GeometryUnknown(Exception):
    """The geometry cannot give mass properties (unreadable mesh, bad size...)."""


class Solid(NamedTuple):
    """The body a mesh encloses, in metres: volume, centre, and the covariance of a
    uniform mass filling it (second moments about the centre per unit volume)."""

    volume: float
    centre: Vector
    covariance: Matrix
    hull: bool  # from the convex hull: the mesh is not watertight


class MeshSummary(NamedTuple):
    """What a run keeps of a mesh file. ``problem`` says why it is not a mesh its format
    can read; ``skipped`` why it was not read (a format urdfcli does not read, a file too
    large); either way the other facts are None where unknown."""

    format: str
    triangles: int | None = None
    low: Vector | None = None  # lowest corner of the bounding box, metres, scale not applied
    high: Vector | None = None
    unit: float | None = None  # metres per unit the file declares (COLLADA), None when it declares none
    watertight: bool | None = None
    solid: Solid | None = None
    problem: MeshError | None = None
    skipped: str | None = None

    @property
    def size(self) -> Vector | None:
        return None if self.low is None else tuple(h - lo for lo, h in zip(self.low, self.high))  # type: ignore[return-value]


class MeshSummaries:
    """A session's mesh summaries, one per file (read again when the file changes)."""

    def __init__(self) -> None:
        self._found: dict[str, tuple[tuple[int, int], MeshSummary]] = {}  # path -> (its stamp when read, summary)
        self.reads = 0  # files read, for the tests that hold it to once per file

    def summary(self, path: Path) -> MeshSummary:
        try:
            status = os.stat(path)
        except OSError as error:
            return MeshSummary(format_of(path), problem=MeshError("missing", f"cannot be read: {error.strerror}"))
        stamp = (status.st_mtime_ns, status.st_size)
        kept = self._found.get(str(path))
        if kept is None or kept[0] != stamp:  # a changed file replaces its summary: one per file, however long the session
            self.reads += 1
            kept = self._found[str(path)] = (stamp, summarise_file(path))
        return kept[1]


def summarise_file(path: Path) -> MeshSummary:
    kind = format_of(path)
    try:
        triangles = read_mesh(path)
    except MeshError as error:
        return MeshSummary(kind, problem=error)
    except Unsupported:
        return MeshSummary(kind, skipped=f"urdfcli does not read .{kind} files" if kind else "the file name has no extension")
    except TooLarge as error:
        return MeshSummary(kind, triangles=error.triangles, skipped=f"not read: {error.size / (1 << 20):.0f} MiB, larger than urdfcli reads")
    except OSError as error:
        return MeshSummary(kind, problem=MeshError("missing", f"cannot be read: {error.strerror}"))
    try:
        return summarise(kind, triangles)
    except MeshError as error:
        return MeshSummary(kind, problem=error)


def summarise(kind: str, found: Triangles) -> MeshSummary:
    """The summary of a mesh's triangles (in metres once its declared unit is applied)."""
    import numpy

    vertices = found.vertices * found.unit if found.unit not in (None, 1.0) else found.vertices
    faces = found.faces
    used = numpy.zeros(len(vertices), dtype=bool)
    used[faces.reshape(-1)] = True
    points = vertices if used.all() else vertices[used]
    if not numpy.isfinite(points).all():
        raise MeshError("malformed", "some vertex coordinates are not finite numbers")
    low, high = points.min(axis=0).astype(float), points.max(axis=0).astype(float)
    del used, points
    kept, corners, closed = _welded(vertices, faces, low, high)
    solid = _tetrahedra(vertices, kept, (low + high) / 2, hull=False) if closed else _hull(vertices[corners])
    return MeshSummary(kind, len(faces), _vector(low), _vector(high), found.unit, closed, solid)


def _vector(values) -> Vector:
    return tuple(float(v) for v in values)  # type: ignore[return-value]


def _welded(vertices, faces, low, high):
    """The faces with coincident corners made one (STL repeats every corner), degenerate
    faces dropped; one vertex of each group of coincident ones; and whether the surface
    is watertight: every edge shared by exactly two faces, wound opposite ways (as
    trimesh's ``is_watertight``, with corners welded by position only)."""
    import numpy

    extent = float((high - low).max()) or 1.0
    # corners within WELD of the extent are one (trimesh welds within 1e-8 m): cells with their edges
    # off the round numbers coordinates often are, each hashed into one 64-bit key
    keys = numpy.zeros(len(vertices), dtype=numpy.uint64)
    for axis, mixer in enumerate((0x9E3779B97F4A7C15, 0xC2B2AE3D27D4EB4F, 0x165667B19E3779F9)):  # a column at a time: bounded memory
        cell = numpy.floor((vertices[:, axis] - low[axis]) * (1 / (WELD * extent)) + 0.3719).astype(numpy.uint64)
        keys ^= cell * numpy.uint64(mixer)
    _, first, same = numpy.unique(keys, return_index=True, return_inverse=True)
    del keys  # (a large mesh's arrays are let go as soon as they are used: the peak is what counts)
    count = len(first)
    welded = same.reshape(-1)[faces]
    del same
    a, b, c = welded[:, 0], welded[:, 1], welded[:, 2]
    kept = (a != b) & (b != c) & (a != c)
    if not kept.any():
        return faces[kept], first, False
    a, b, c = a[kept], b[kept], c[kept]
    del welded
    # each edge as its two ends, lower first, and a last bit for the way it runs: a closed
    # surface has every edge twice, once each way, and no third time
    edges = numpy.concatenate([(numpy.minimum(x, y) * count + numpy.maximum(x, y)) * 2 + (x < y) for x, y in ((a, b), (b, c), (c, a))])
    del a, b, c
    edges.sort()
    pairs = edges[0::2] // 2
    closed = bool(
        len(edges) % 2 == 0 and (pairs == edges[1::2] // 2).all() and (edges[0::2] % 2 == 0).all() and (edges[1::2] % 2 == 1).all()
        and (pairs[1:] != pairs[:-1]).all()
    )
    return faces[kept], first, closed


def _hull(points) -> Solid | None:
    """The convex hull's body (qhull): what an open mesh is taken to enclose. None when the
    points are flat or too few to enclose anything."""
    from scipy.spatial import ConvexHull, QhullError

    try:
        hull = ConvexHull(points, qhull_options="Q12")  # scipy's default adds Qc and Qz, which a hull's volume does not need (a third slower)
    except (QhullError, ValueError):
        return None
    inside = hull.points[hull.vertices].mean(axis=0)
    return _tetrahedra(hull.points, hull.simplices, inside, hull=True)


def _tetrahedra(vertices, faces, reference, hull: bool) -> Solid | None:
    """Volume, centre and covariance of the body the faces enclose: each face with
    ``reference`` makes a tetrahedron, of signed volume for a closed surface, of positive
    volume for a hull (``reference`` inside; qhull does not wind its faces consistently).
    Worked in chunks, so that memory stays bounded on large meshes."""
    import numpy

    volume, first, second = 0.0, numpy.zeros(3), numpy.zeros((3, 3))
    for start in range(0, len(faces), CHUNK):
        corners = vertices[faces[start:start + CHUNK]] - reference  # (m, 3, 3)
        p, q, r = corners[:, 0], corners[:, 1], corners[:, 2]
        six = numpy.einsum("ij,ij->i", p, numpy.cross(q, r))  # six times each signed volume
        if hull:
            six = numpy.abs(six)
        total = p + q + r
        volume += six.sum() / 6
        first += (six[:, None] * total).sum(axis=0) / 24
        # the integral of x xᵀ over a tetrahedron (0, p, q, r): V/20 (p pᵀ + q qᵀ + r rᵀ + s sᵀ), s = p + q + r
        second += numpy.einsum("i,ij,ik->jk", six, p, p) + numpy.einsum("i,ij,ik->jk", six, q, q)
        second += numpy.einsum("i,ij,ik->jk", six, r, r) + numpy.einsum("i,ij,ik->jk", six, total, total)
    second /= 120  # six volumes, over 20
    if volume < 0:  # wound inside out: the same body
        volume, first, second = -volume, -first, -second
    extent = float(numpy.abs(vertices[faces].reshape(-1, 3) - reference).max()) if len(faces) else 0.0
    if not volume > 1e-12 * extent**3:
        return None
    centre = first / volume
    covariance = second / volume - numpy.outer(centre, centre)
    return Solid(float(volume), _vector(centre + reference), tuple(_vector(row) for row in covariance), hull)  # type: ignore[arg-type]


# -- a mesh as one use scales it ------------------------------------------------------
def scaled_bounds(summary: MeshSummary, scale: Vector) -> tuple[Vector, Vector]:
    corners = [tuple(v * s for v, s in zip(corner, scale)) for corner in (summary.low, summary.high)]
    return tuple(min(a, b) for a, b in zip(*corners)), tuple(max(a, b) for a, b in zip(*corners))  # type: ignore[return-value]


def scaled_properties(summary: MeshSummary, scale: Vector) -> Properties:
    """Volume, centre, tensor per unit mass and bounds of the mesh scaled by ``scale``:
    a uniform body stays uniform under scaling, its covariance C becomes S C S."""
    solid = summary.solid
    volume = solid.volume * abs(scale[0] * scale[1] * scale[2])
    centre = tuple(c * s for c, s in zip(solid.centre, scale))
    covariance = [[solid.covariance[i][j] * scale[i] * scale[j] for j in range(3)] for i in range(3)]
    trace = covariance[0][0] + covariance[1][1] + covariance[2][2]
    tensor = tuple(tuple((trace if i == j else 0.0) - covariance[i][j] for j in range(3)) for i in range(3))
    return volume, centre, tensor, scaled_bounds(summary, scale)  # type: ignore[return-value]


# -- a model's meshes ------------------------------------------------------------------
class MeshFiles:
    """A model's mesh URIs to files, through its package resolver, each looked up once."""

    def __init__(self, resolver: PackageResolver, base: Path | None) -> None:
        self.resolver = resolver
        self.base = base
        self._found: dict[str, Path | None] = {}

    @classmethod
    def of(cls, loaded: Loaded) -> MeshFiles:
        return loaded.remembered("mesh files", lambda: cls(loaded.resolver, input_folder(loaded)))

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
    return loaded.remembered("mesh uses", lambda: list(_mesh_uses(loaded)))


def _mesh_uses(loaded: Loaded):
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
    name = Path(filename).name
    path = MeshFiles.of(loaded).path(filename)
    if path is None:
        raise GeometryUnknown(f"mesh {filename} cannot be resolved")
    if not path.is_file():
        raise GeometryUnknown(f"mesh {filename} not found ({path})")
    found = loaded.meshes.summary(path)
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
