"""A mesh file summarised: what urdfcli keeps of it, worked out once and kept per session.

A :class:`MeshSummary` is a mesh file's format, triangle count, bounding box in
metres (COLLADA's ``<unit meter>`` applied, as rviz and Gazebo apply it; a
``<mesh scale>`` is not: it belongs to each use), whether it is watertight, and
the solid it encloses (volume, centre, second moments; the convex hull's when
the mesh is open). The session's :class:`MeshSummaries` reads a file the first
time a rule asks, and again only if it changes on disk; the arrays are dropped
as soon as the summary is made.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import NamedTuple

from ..read.meshfile import MeshError, TooLarge, Triangles, Unsupported, format_of, read_mesh
from .massprops import Matrix, Vector

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
    first_volume: float | None = None  # an .obj of several objects: the volume its first object encloses, m³ (MuJoCo reads that one alone)

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
    first = _enclosed(vertices, faces[:found.first_object]) if found.first_object is not None else None
    return MeshSummary(kind, len(faces), _vector(low), _vector(high), found.unit, closed, solid, first_volume=first)


def _enclosed(vertices, faces) -> float:
    """The volume triangles enclose (their signed tetrahedra from their centre, summed), m³."""
    import numpy

    if not len(faces):
        return 0.0
    corners = vertices[faces].astype(numpy.float64)
    centre = corners.reshape(-1, 3).mean(axis=0)
    a, b, c = (corners[:, i] - centre for i in range(3))
    return abs(float(numpy.einsum("ij,ij->", a, numpy.cross(b, c)))) / 6.0


def _vector(values) -> Vector:
    return tuple(float(v) for v in values)  # type: ignore[return-value]


def _welded(vertices, faces, low, high):
    """The faces with coincident corners made one (STL repeats every corner), degenerate
    faces dropped; one vertex of each group of coincident ones that a kept face uses; and whether the surface
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
        return faces[kept], first[:0], False
    a, b, c = a[kept], b[kept], c[kept]
    del welded
    corners = first[numpy.unique(numpy.concatenate((a, b, c)))]  # only those of faces: a COLLADA file may hold others' vertices
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
    return faces[kept], corners, closed


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
