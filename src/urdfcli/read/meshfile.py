"""A mesh file's triangles, read as the consumers of URDF read them.

STL (binary and ASCII), Wavefront OBJ and COLLADA are read here: only positions
and faces (no normals, texture coordinates or images), so that a mesh costs a
few arrays for as long as its summary is being made. Other formats trimesh
knows (PLY, OFF, glTF) go through trimesh; a format neither knows is
:class:`Unsupported`. Anything that is not a readable mesh of its format (an
empty file, a Git LFS pointer, a truncated or undecodable file) raises
:class:`MeshError`, whose message names the problem.

COLLADA's ``<unit meter>`` is returned, not applied: rviz (assimp) and Gazebo
(gz-common's ColladaLoader) scale the mesh by it, trimesh and yourdfpy do not.
``<up_axis>`` is not applied (assimp's URDF users and gz-common ignore it too).
numpy is imported only when a mesh is read.
"""

from __future__ import annotations

import os
import re
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from .xml import XmlError, parse

if TYPE_CHECKING:
    import numpy

NATIVE = ("stl", "obj", "dae")
THROUGH_TRIMESH = ("ply", "off", "glb", "gltf")
LFS_POINTER = b"version https://git-lfs.github.com/spec/"
POINTER_SIZE = 1024  # bytes: a Git LFS pointer is about 130; a file this small is worth a look at its head
MAX_BYTES = 64 << 20  # a larger file is not read (bounded memory): its summary says so


class MeshError(ValueError):
    """The file is not a mesh its format can read. ``kind``: empty, lfs, truncated, malformed."""

    def __init__(self, kind: str, message: str) -> None:
        super().__init__(message)
        self.kind = kind
        self.message = message


class Unsupported(Exception):
    """A format urdfcli does not read (such as Ogre's .mesh, which rviz reads): nothing is judged."""


class TooLarge(Exception):
    """A file larger than MAX_BYTES: not read. ``triangles`` is what a header says (binary STL), else None."""

    def __init__(self, size: int, triangles: int | None) -> None:
        super().__init__(size)
        self.size = size
        self.triangles = triangles


class Triangles(NamedTuple):
    vertices: numpy.ndarray  # (n, 3) floats (float32 for a binary STL), in the file's units
    faces: numpy.ndarray  # (m, 3) int64 indices into vertices
    unit: float | None  # metres per unit the file declares (COLLADA <unit meter>), None when it declares none
    first_object: int | None = None  # OBJ of several objects: how many of the faces (the first ones) its first object holds


def format_of(path: Path | str) -> str:
    """The format a file's name says, lowercased (``stl``, ``dae``...)."""
    return Path(path).suffix.lower().lstrip(".")


def placeholder(path: Path, size: int) -> MeshError | None:
    """What a ``stat`` (and a look at the head of a file too small to be a mesh) tells:
    an empty file, or a Git LFS pointer. Opens only files under POINTER_SIZE bytes."""
    if size == 0:
        return MeshError("empty", "the file is empty (0 bytes)")
    if size < POINTER_SIZE:
        try:
            with open(path, "rb") as file:
                head = file.read(len(LFS_POINTER))
        except OSError:
            return None
        if head == LFS_POINTER:
            return MeshError("lfs", f"the file is a Git LFS pointer ({size} bytes), not the mesh: the repository was cloned without its LFS files")
    return None


def read_mesh(path: Path) -> Triangles:
    """The triangles of a mesh file. Raises MeshError, Unsupported, TooLarge or OSError."""
    kind = format_of(path)
    if kind not in NATIVE and kind not in THROUGH_TRIMESH:
        raise Unsupported(kind)
    size = os.stat(path).st_size
    found = placeholder(path, size)
    if found is not None:
        raise found
    if size > MAX_BYTES:
        raise TooLarge(size, _binary_count(stl_header(path)) if kind == "stl" else None)
    if kind in THROUGH_TRIMESH:
        return _through_trimesh(path, kind)
    data = path.read_bytes()
    return {"stl": read_stl, "obj": read_obj, "dae": read_collada}[kind](data)


# -- STL -------------------------------------------------------------------------------
class StlHeader(NamedTuple):
    """What a ``stat`` and the first 84 bytes of an STL file say."""

    size: int  # bytes
    triangles: int | None  # the count a binary STL's header holds; None when the file is shorter than the header
    solid: bool  # it starts with 'solid', as an ASCII STL does (and some binary headers)

    @property
    def binary(self) -> bool:
        """A binary STL: the file is as long as its header's count says."""
        return self.triangles is not None and self.size == 84 + 50 * self.triangles


def stl_header(path: Path) -> StlHeader:
    """Reads 84 bytes. Raises OSError."""
    with open(path, "rb") as file:
        header = file.read(84)
    triangles = int.from_bytes(header[80:84], "little") if len(header) == 84 else None
    return StlHeader(os.stat(path).st_size, triangles, header.startswith(b"solid"))


def _binary_count(header: StlHeader) -> int | None:
    return header.triangles if header.triangles is not None and not header.solid else None


def read_stl(data: bytes) -> Triangles:
    """Binary STL when the size matches its header's triangle count (an ASCII header
    may start with ``solid`` too), else ASCII when it starts with ``solid``."""
    import numpy

    count = int.from_bytes(data[80:84], "little") if len(data) >= 84 else None
    if count is not None and len(data) >= 84 + 50 * count and not (data.startswith(b"solid") and len(data) != 84 + 50 * count):
        if count == 0:
            raise MeshError("malformed", "the binary STL holds no triangles (its header says 0)")
        record = numpy.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])
        corners = numpy.frombuffer(data, record, count, 84)["corners"]
        return _soup(numpy.ascontiguousarray(corners).reshape(-1, 3))  # float32 as written: half the memory of float64
    if data.lstrip()[:5].lower() == b"solid":
        return _read_ascii_stl(data)
    if count is not None:
        raise MeshError(
            "truncated",
            f"the binary STL is truncated: its header says {count} triangles ({84 + 50 * count:,} bytes), the file has {len(data):,} bytes",
        )
    raise MeshError("malformed", f"the file is not an STL: {len(data)} bytes, shorter than a binary STL's 84-byte header, and no 'solid' line")


_STL_VERTEX = re.compile(rb"^[ \t]*vertex[ \t]+([^\r\n]*)", re.MULTILINE)


def _read_ascii_stl(data: bytes) -> Triangles:
    lines = _STL_VERTEX.findall(data)
    if not lines:
        raise MeshError("malformed", "the ASCII STL holds no 'vertex' lines")
    corners = numbers(b" ".join(lines), "the ASCII STL's vertices").reshape(-1, 3) if _holds(lines, 3) else None
    if corners is None or len(corners) != len(lines):
        raise MeshError("malformed", "the ASCII STL has a 'vertex' line that is not three numbers")
    if len(corners) % 3 or not data.rstrip().rsplit(b"\n", 1)[-1].lstrip().lower().startswith(b"endsolid"):
        raise MeshError("truncated", f"the ASCII STL is truncated: it ends after {len(corners)} vertices, without 'endsolid'")
    return _soup(corners)


def _holds(lines: list[bytes], count: int) -> bool:
    """Whether the lines hold ``count`` numbers in all (a quick test of their words)."""
    return sum(len(line.split()) for line in lines) == count * len(lines)


def numbers(text: bytes | str, what: str, dtype=float):
    """The numbers of a text, parsed by numpy's C loop (no list of words: a large mesh's
    text would take several times its size as Python strings). Raises MeshError."""
    import warnings

    import numpy

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", DeprecationWarning)  # numpy stops, and warns, at a word that is no number
            return numpy.fromstring(text, dtype=numpy.float64 if dtype is float else numpy.int64, sep=" ")
    except (ValueError, DeprecationWarning):
        raise MeshError("malformed", f"{what} hold something that is not a number") from None


def _soup(corners: numpy.ndarray) -> Triangles:
    """Triangles given as three corners each (STL): every corner its own vertex."""
    import numpy

    return Triangles(corners, numpy.arange(len(corners), dtype=numpy.int64).reshape(-1, 3), None)


# -- OBJ -------------------------------------------------------------------------------
_OBJ_VERTEX = re.compile(rb"^[ \t]*v[ \t]+([^\r\n]*)", re.MULTILINE)
_OBJ_FACE = re.compile(rb"^[ \t]*f[ \t]+([^\r\n]*)", re.MULTILINE)
_OBJ_SLASHES = re.compile(rb"/\S*")
_OBJ_GROUP = re.compile(rb"^[ \t]*[og](?:[ \t]|$)", re.MULTILINE)  # where an object (o) or a group (g) begins


def read_obj(data: bytes) -> Triangles:
    """``v`` and ``f`` lines (polygons fanned into triangles, ``v/vt/vn`` and negative
    indices as the format defines them); every other line is left alone."""
    import numpy

    vertices = _obj_vertices(_OBJ_VERTEX.findall(data))
    faces = [_OBJ_SLASHES.sub(b"", face) for face in _OBJ_FACE.findall(data)]
    if not faces:
        raise MeshError("malformed", f"the OBJ file has no faces ('f' lines; {len(vertices)} vertices)")
    counts = numpy.array([len(face.split()) for face in faces])
    if (counts < 3).any():
        raise MeshError("malformed", f"the OBJ file has a face with fewer than 3 vertices: 'f {faces[int(numpy.argmax(counts < 3))].decode(errors='replace')}'")
    indices = numbers(b" ".join(faces), "the OBJ file's faces", int)
    if len(indices) != counts.sum():
        raise MeshError("malformed", "the OBJ file has an 'f' line whose vertices are not whole numbers")
    if (indices < 0).any():  # a negative index counts back from the vertices written before its face
        written = numpy.array([m.start() for m in _OBJ_VERTEX.finditer(data)])
        before = numpy.searchsorted(written, [m.start() for m in _OBJ_FACE.finditer(data)])
        indices = numpy.where(indices < 0, numpy.repeat(before, counts) + indices + 1, indices)
    indices -= 1
    bad = (indices < 0) | (indices >= len(vertices))
    if bad.any():
        face = faces[int(numpy.searchsorted(numpy.cumsum(counts), int(numpy.argmax(bad)), side="right"))]
        raise MeshError(
            "truncated",
            f"the OBJ file is truncated or broken: face 'f {face.decode(errors='replace')}' names a vertex it does not have ({len(vertices)} vertices)",
        )
    return Triangles(vertices, _fans(indices, counts), None, _first_object(data, counts))


def _first_object(data: bytes, counts) -> int | None:
    """How many triangles the first object of an OBJ file holds, when an ``o`` or ``g``
    line after its first face begins another (tinyobjloader's shapes); None for one object."""
    first_face = _OBJ_FACE.search(data)
    boundary = _OBJ_GROUP.search(data, first_face.start()) if first_face is not None else None
    if boundary is None:
        return None
    polygons = len(_OBJ_FACE.findall(data, 0, boundary.start()))
    return int((counts[:polygons] - 2).sum())


def _obj_vertices(lines: list[bytes]):
    """The x y z of each ``v`` line (a fourth weight or colours after them left out)."""
    import numpy

    if _holds(lines, 3):  # the usual case, parsed in one go
        return numbers(b" ".join(lines), "the OBJ file's vertices").reshape(-1, 3)
    try:
        return numpy.array([line.split()[:3] for line in lines], dtype=numpy.float64).reshape(-1, 3)
    except ValueError:
        raise MeshError("malformed", "the OBJ file has a 'v' line whose coordinates are not three numbers") from None


def _fans(indices: numpy.ndarray, counts: numpy.ndarray) -> numpy.ndarray:
    """Polygons of ``counts`` corners each, their corners in a row, as triangle fans."""
    import numpy

    if (counts == 3).all():
        return indices.reshape(-1, 3)
    starts = numpy.concatenate(([0], numpy.cumsum(counts)[:-1]))
    first = numpy.repeat(starts, counts - 2)  # each polygon gives counts - 2 triangles
    step = numpy.arange(len(first)) - numpy.repeat(numpy.cumsum(counts - 2) - (counts - 2), counts - 2)
    return numpy.stack([indices[first], indices[first + step + 1], indices[first + step + 2]], axis=1)


# -- COLLADA ---------------------------------------------------------------------------
MAX_NODE_DEPTH = 64  # <instance_node> may refer back up the scene: a loop is cut here


def read_collada(data: bytes) -> Triangles:
    """The triangles of the geometries the visual scene instantiates, each placed by its
    node's transforms (``matrix``, ``translate``, ``rotate``, ``scale``), and the
    document's ``<unit meter>``."""
    import numpy

    try:
        root = parse(data, huge=True)
    except XmlError as error:
        padded = data.rstrip(b"\0 \t\r\n")  # NUL bytes after </COLLADA> (an exporter's padding): assimp and tinyxml2 stop at the first
        if len(padded) == len(data.rstrip()) or not padded.endswith(b">"):
            raise MeshError("malformed", f"the COLLADA file is not well-formed XML (line {error.line}): {error.message}") from None
        try:
            root = parse(padded, huge=True)
        except XmlError:
            raise MeshError("malformed", f"the COLLADA file is not well-formed XML (line {error.line}): {error.message}") from None
    reader = _Collada(root)
    reader.read_scene()
    if not reader.parts:
        raise MeshError("malformed", "the COLLADA file has no triangles in its visual scene")
    vertices = numpy.concatenate([v for v, _ in reader.parts])
    offsets = numpy.cumsum([0] + [len(v) for v, _ in reader.parts[:-1]])
    faces = numpy.concatenate([f + offset for (_, f), offset in zip(reader.parts, offsets)])
    return Triangles(vertices, faces, reader.unit())


class _Collada:
    def __init__(self, root) -> None:
        if not root.tag.endswith("COLLADA"):
            raise MeshError("malformed", f"the file is XML but not COLLADA: its root is <{root.tag.split('}')[-1]}>")
        self.ns = root.tag[: -len("COLLADA")]
        self.root = root
        self.ids = {element.get("id"): element for element in root.iter() if element.get("id")}
        self.positions_of: dict = {}
        self.parts: list = []  # (vertices placed in the scene, faces)

    def find(self, element, path: str):
        return element.find("/".join(self.ns + step for step in path.split("/")))

    def findall(self, element, tag: str):
        return element.findall(self.ns + tag)

    def unit(self) -> float | None:
        unit = self.find(self.root, "asset/unit")
        try:
            meter = float(unit.get("meter")) if unit is not None else None
        except (TypeError, ValueError):
            return None
        return meter if meter is not None and meter > 0 else None

    def referenced(self, url: str | None, what: str):
        element = self.ids.get((url or "").lstrip("#"))
        if element is None:
            raise MeshError("malformed", f"the COLLADA file names {what} '{url}', which it does not define")
        return element

    def read_scene(self) -> None:
        import numpy

        scene = self.find(self.root, "scene/instance_visual_scene")
        if scene is None:
            for geometry in self.root.iter(self.ns + "geometry"):  # no scene: every geometry, where it is
                self.add(geometry, numpy.eye(4))
            return
        for node in self.findall(self.referenced(scene.get("url"), "visual scene"), "node"):
            self.visit(node, numpy.eye(4), 0)

    def visit(self, node, parent, depth: int) -> None:
        if depth > MAX_NODE_DEPTH:
            raise MeshError("malformed", f"the COLLADA scene nests nodes more than {MAX_NODE_DEPTH} deep (a loop of <instance_node>?)")
        placed = parent @ self.transform(node)
        for instance in self.findall(node, "instance_geometry"):
            self.add(self.referenced(instance.get("url"), "geometry"), placed)
        for instance in self.findall(node, "instance_node"):
            self.visit(self.referenced(instance.get("url"), "node"), placed, depth + 1)
        for child in self.findall(node, "node"):
            self.visit(child, placed, depth + 1)

    def transform(self, node):
        import numpy

        matrix = numpy.eye(4)
        for step in node:
            tag = step.tag[len(self.ns):]
            if tag not in ("matrix", "translate", "rotate", "scale"):
                continue
            values = self.numbers(step.text, f"<{tag}>")
            expected = {"matrix": 16, "translate": 3, "rotate": 4, "scale": 3}[tag]
            if len(values) != expected:
                raise MeshError("malformed", f"a COLLADA <{tag}> has {len(values)} numbers, not {expected}")
            matrix = matrix @ _step_matrix(tag, values)
        return matrix

    def numbers(self, text: str | None, what: str, dtype=float):
        return numbers(text or "", f"a COLLADA {what}", dtype)

    def positions(self, source_id: str):
        """A source's points (x, y, z), read once however many primitives use them."""
        if source_id not in self.positions_of:
            source = self.referenced(source_id, "source")
            if source.tag == self.ns + "vertices":  # <vertices> names the source of its POSITION input
                found = next((i for i in self.findall(source, "input") if i.get("semantic") == "POSITION"), None)
                if found is None:
                    raise MeshError("malformed", f"the COLLADA <vertices id='{source_id}'> has no POSITION input")
                self.positions_of[source_id] = self.positions(found.get("source", "").lstrip("#"))
                return self.positions_of[source_id]
            array = self.find(source, "float_array")
            accessor = self.find(source, "technique_common/accessor")
            values = self.numbers(array.text if array is not None else None, "<float_array>")
            stride = int(accessor.get("stride", "1")) if accessor is not None else 3
            if stride < 3:
                raise MeshError("malformed", f"the COLLADA positions '{source_id}' have a stride of {stride}, fewer than x, y and z")
            self.positions_of[source_id] = values[: len(values) // stride * stride].reshape(-1, stride)[:, :3]
        return self.positions_of[source_id]

    def add(self, geometry, placed) -> None:
        mesh = self.find(geometry, "mesh")
        if mesh is None:
            return  # a spline or convex hull definition: no triangles
        vertices = self.find(mesh, "vertices")
        if vertices is None:
            raise MeshError("malformed", f"the COLLADA geometry '{geometry.get('id')}' has no <vertices>")
        points = self.positions(vertices.get("id"))
        for primitive in mesh:
            faces = self.faces(primitive)
            if faces is None or not len(faces):
                continue
            if faces.min() < 0 or faces.max() >= len(points):
                raise MeshError(
                    "truncated", f"the COLLADA file is truncated or broken: geometry '{geometry.get('id')}' names vertex {int(faces.max())} of {len(points)}"
                )
            self.parts.append((points @ placed[:3, :3].T + placed[:3, 3], faces))

    def faces(self, primitive):
        """The triangles of a <triangles>, <polylist>, <polygons>, <trifans> or <tristrips>
        (lines and points have none), as indices of positions."""
        import numpy

        tag = primitive.tag[len(self.ns):]
        if tag not in ("triangles", "polylist", "polygons", "trifans", "tristrips"):
            return None
        inputs = self.findall(primitive, "input")
        vertex = next((i for i in inputs if i.get("semantic") == "VERTEX"), None)
        if vertex is None:
            raise MeshError("malformed", f"a COLLADA <{tag}> has no VERTEX input")
        width = max(int(i.get("offset", "0")) for i in inputs) + 1
        offset = int(vertex.get("offset", "0"))
        lists = [self.numbers(p.text, "<p>", numpy.int64)[offset::width] for p in self.findall(primitive, "p")]
        if tag == "triangles":
            corners = numpy.concatenate(lists) if lists else numpy.zeros(0, numpy.int64)
            if len(corners) % 3:
                raise MeshError("truncated", f"the COLLADA file is truncated or broken: a <triangles> has {len(corners)} corners, not a multiple of 3")
            return corners.reshape(-1, 3)
        if tag == "polylist":
            counts = self.numbers(getattr(self.find(primitive, "vcount"), "text", ""), "<vcount>", numpy.int64)
            corners = numpy.concatenate(lists) if lists else numpy.zeros(0, numpy.int64)
            if counts.sum() != len(corners) or (counts < 3).any():
                raise MeshError("truncated", f"the COLLADA file is truncated or broken: a <polylist> counts {int(counts.sum())} corners and lists {len(corners)}")
            return _fans(corners, counts)
        if tag == "tristrips":
            return numpy.concatenate([_strip(corners) for corners in lists]) if lists else None
        return numpy.concatenate([_fans(c, numpy.array([len(c)])) for c in lists if len(c) >= 3]) if lists else None  # polygons, trifans


def _strip(corners):
    import numpy

    n = len(corners) - 2
    if n < 1:
        return numpy.zeros((0, 3), numpy.int64)
    faces = numpy.stack([corners[:-2], corners[1:-1], corners[2:]], axis=1)
    faces[1::2] = faces[1::2][:, [1, 0, 2]]  # every other triangle of a strip is wound the other way
    return faces


def _step_matrix(tag: str, values):
    import numpy

    matrix = numpy.eye(4)
    if tag == "matrix":
        return values.reshape(4, 4)
    if tag == "translate":
        matrix[:3, 3] = values
    elif tag == "scale":
        matrix[:3, :3] = numpy.diag(values)
    else:  # rotate: axis x y z, angle in degrees
        axis, angle = values[:3], numpy.radians(values[3])
        length = numpy.linalg.norm(axis)
        if length > 0:
            x, y, z = axis / length
            c, s, t = numpy.cos(angle), numpy.sin(angle), 1 - numpy.cos(angle)
            matrix[:3, :3] = [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
                              [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
                              [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]
    return matrix


# -- other formats ---------------------------------------------------------------------
def _through_trimesh(path: Path, kind: str) -> Triangles:
    """PLY, OFF and glTF through trimesh, geometry only (no textures), placed by the scene."""
    import logging

    import numpy
    import trimesh

    logging.getLogger("trimesh").setLevel(logging.CRITICAL)  # urdfcli reports what matters itself
    try:
        scene = trimesh.load(str(path), file_type=kind, force="scene", process=False)
    except Exception as error:  # noqa: BLE001  (trimesh raises many kinds)
        raise MeshError("malformed", f"the {kind.upper()} file cannot be read: {error}") from None
    vertices, faces, count = [], [], 0
    for node in scene.graph.nodes_geometry:
        matrix, name = scene.graph[node]
        mesh = scene.geometry.get(name)
        if isinstance(mesh, trimesh.Trimesh) and len(mesh.faces):
            vertices.append(numpy.asarray(mesh.vertices, dtype=numpy.float64) @ matrix[:3, :3].T + matrix[:3, 3])
            faces.append(numpy.asarray(mesh.faces, dtype=numpy.int64) + count)
            count += len(mesh.vertices)
    if not faces:
        raise MeshError("malformed", f"the {kind.upper()} file holds no triangles")
    return Triangles(numpy.concatenate(vertices), numpy.concatenate(faces), None)
