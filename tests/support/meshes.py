"""Real mesh files for the tests, written as the tools that export them write them.

Binary and ASCII STL, OBJ and COLLADA are written here from a trimesh mesh (the
library that builds the shapes), so that each test reads a file like one a CAD
tool or Blender exports.
"""

from __future__ import annotations

import struct
from pathlib import Path

import numpy
import trimesh

LFS_POINTER = "version https://git-lfs.github.com/spec/v1\noid sha256:4d7a214614ab2935c943f9e0ff69d22eadbb8f32b1258daaa5e2ca24d17e2393\nsize 12345\n"


def box(size=(0.1, 0.1, 0.4)) -> trimesh.Trimesh:
    return trimesh.creation.box(extents=size)


def open_box(size=(0.1, 0.1, 0.4)) -> trimesh.Trimesh:
    """A box missing one of its twelve triangles: not watertight."""
    mesh = box(size)
    return trimesh.Trimesh(mesh.vertices, mesh.faces[1:], process=False)


def fine(size=(0.1, 0.1, 0.4), subdivisions: int = 5) -> trimesh.Trimesh:
    """An ellipsoid of 20 * 4^subdivisions triangles (20,480 by default) filling ``size``."""
    mesh = trimesh.creation.icosphere(subdivisions=subdivisions)
    mesh.apply_scale(numpy.array(size) / 2)
    return mesh


def write(path: Path, mesh: trimesh.Trimesh, kind: str | None = None, scale: float = 1.0, unit: float | None = None) -> Path:
    """``mesh`` (its coordinates times ``scale``) as ``path``, in the format its suffix names
    (``kind`` "ascii" for an ASCII STL); COLLADA with ``<unit meter=unit>`` when given."""
    path.parent.mkdir(parents=True, exist_ok=True)
    vertices, faces = numpy.asarray(mesh.vertices) * scale, numpy.asarray(mesh.faces)
    suffix = path.suffix.lower()
    if suffix == ".stl" and kind == "ascii":
        path.write_text(ascii_stl(vertices, faces))
    elif suffix == ".stl":
        path.write_bytes(binary_stl(vertices, faces))
    elif suffix == ".obj":
        path.write_text(obj(vertices, faces))
    elif suffix == ".dae":
        path.write_text(collada(vertices, faces, unit))
    else:
        raise ValueError(suffix)
    return path


def binary_stl(vertices, faces) -> bytes:
    corners = vertices[faces].astype("<f4")
    records = b"".join(struct.pack("<3f", 0, 0, 0) + c.tobytes() + b"\0\0" for c in corners)
    return b"exported by a test".ljust(80, b" ") + struct.pack("<I", len(faces)) + records


def ascii_stl(vertices, faces) -> str:
    lines = ["solid part"]
    for face in faces:
        lines += ["  facet normal 0 0 0", "    outer loop"]
        lines += [f"      vertex {x:.9g} {y:.9g} {z:.9g}" for x, y, z in vertices[face]]
        lines += ["    endloop", "  endfacet"]
    return "\n".join(lines + ["endsolid part", ""])


def obj(vertices, faces) -> str:
    lines = ["# exported by a test", "o part"]
    lines += [f"v {x:.9g} {y:.9g} {z:.9g}" for x, y, z in vertices]
    lines += ["vn 0 0 1"]
    lines += ["f " + " ".join(f"{i + 1}//1" for i in face) for face in faces]
    return "\n".join(lines) + "\n"


def collada(vertices, faces, unit: float | None = None) -> str:
    """A COLLADA 1.4.1 document as Blender writes one: the geometry placed by a node's <matrix>."""
    asset = f'<unit name="custom" meter="{unit}"/>' if unit is not None else ""
    positions = " ".join(f"{v:.9g}" for v in vertices.reshape(-1))
    indices = " ".join(str(i) for i in faces.reshape(-1))
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><contributor><authoring_tool>a test</authoring_tool></contributor>{asset}<up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="part-mesh" name="part">
      <mesh>
        <source id="part-positions">
          <float_array id="part-positions-array" count="{vertices.size}">{positions}</float_array>
          <technique_common><accessor source="#part-positions-array" count="{len(vertices)}" stride="3">
            <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common>
        </source>
        <vertices id="part-vertices"><input semantic="POSITION" source="#part-positions"/></vertices>
        <triangles count="{len(faces)}"><input semantic="VERTEX" source="#part-vertices" offset="0"/><p>{indices}</p></triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="Scene" name="Scene">
      <node id="part" name="part" type="NODE">
        <matrix sid="transform">1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</matrix>
        <instance_geometry url="#part-mesh" name="part"/>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
"""


def example_package(root: Path) -> Path:
    """The ROS package the documented examples are written into (tests/test_rules_examples.py):
    ``my_robot`` with a 0.1 x 0.1 x 0.4 m arm in metres and its variants."""
    meshes = root / "meshes"
    write(meshes / "arm.stl", box())
    write(meshes / "arm_mm.stl", box(), scale=1000)
    write(meshes / "arm_ascii.stl", box(), "ascii")
    write(meshes / "arm_open.stl", open_box())
    write(meshes / "arm_fine.stl", fine())
    (meshes / "arm_lfs.stl").write_text(LFS_POINTER)
    write(meshes / "arm.obj", box())
    plate = "o plate\nv 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0\nv 0 0.1 0\nf 1 2 3\nf 1 3 4\n"  # a flat object first, then the arm
    arm = box()
    (meshes / "arm_parts.obj").write_text(plate + "o arm\n" + "".join(f"v {x:.9g} {y:.9g} {z:.9g}\n" for x, y, z in arm.vertices)
                                          + "".join("f " + " ".join(str(i + 5) for i in face) + "\n" for face in arm.faces))
    return root
