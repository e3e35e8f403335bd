"""Mesh files read as their consumers read them: urdfcli's STL, OBJ and COLLADA readers
against trimesh (the library yourdfpy and most Python tools read meshes with) on the
same files, written here and published in example-robot-data; and every kind of file
that is not a mesh, each named for what it is."""

from __future__ import annotations

import numpy
import pytest
import trimesh
from conftest import example_robot_data
from support.meshes import LFS_POINTER, ascii_stl, binary_stl, box, fine, open_box, write

from urdfcli.model.mesh_summaries import MeshSummaries, summarise_file
from urdfcli.read.meshfile import MeshError, Unsupported, read_mesh


def trimesh_triangles(path):
    """What trimesh reads: every triangle of the scene, placed by its nodes."""
    scene = trimesh.load(str(path), force="scene", process=False)
    found = []
    for node in scene.graph.nodes_geometry:
        matrix, name = scene.graph[node]
        mesh = scene.geometry[name]
        found.append(trimesh.transform_points(mesh.vertices, matrix)[mesh.faces])
    return numpy.concatenate(found)


def same_triangles(path) -> None:
    ours = read_mesh(path)
    theirs = trimesh_triangles(path)
    corners = ours.vertices[ours.faces]
    assert len(corners) == len(theirs)
    assert numpy.allclose(corners.reshape(-1, 3).min(axis=0), theirs.reshape(-1, 3).min(axis=0))
    assert numpy.allclose(corners.reshape(-1, 3).max(axis=0), theirs.reshape(-1, 3).max(axis=0))
    assert numpy.isclose(abs(_volume(corners)), abs(_volume(theirs)))


def _volume(corners) -> float:
    return float(numpy.einsum("ij,ij->i", corners[:, 0], numpy.cross(corners[:, 1], corners[:, 2])).sum() / 6)


@pytest.mark.parametrize("name, kind", [("part.stl", None), ("part.stl", "ascii"), ("part.obj", None), ("part.dae", None)])
def test_each_format_reads_as_trimesh_reads_it(tmp_path, name, kind):
    same_triangles(write(tmp_path / name, fine((0.2, 0.1, 0.3), subdivisions=2), kind))


def test_obj_polygons_negative_indices_and_slashes(tmp_path):
    path = tmp_path / "quads.obj"
    path.write_text(
        "# a unit cube of quads, written with relative (negative) indices and v/vt/vn corners\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvt 0 0\nvn 0 0 1\n"
        "f -8/1/1 -5/1/1 -6/1/1 -7/1/1\nf 5 6 7 8\nf 1 2 6 5\nf 2//1 3//1 7//1 6//1\nf 3 4 8 7\nf 4 1 5 8\n"
    )
    found = read_mesh(path)
    assert len(found.faces) == 12
    same_triangles(path)
    summary = summarise_file(path)
    assert summary.watertight and numpy.isclose(summary.solid.volume, 1.0) and not summary.solid.hull


def test_collada_nodes_place_the_geometry_and_the_unit_is_applied(tmp_path):
    path = write(tmp_path / "part.dae", box((0.4, 0.3, 0.1)), scale=1000, unit=0.001)  # Blender's millimetres
    text = path.read_text().replace("1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1", "0 -1 0 50 1 0 0 0 0 0 1 0 0 0 0 1")  # turned 90° about z, moved 50 mm
    path.write_text(text)
    same_triangles(path)  # trimesh places nodes as urdfcli does; it leaves the unit to its caller
    summary = summarise_file(path)
    assert summary.unit == 0.001
    assert numpy.allclose(summary.size, (0.3, 0.4, 0.1))  # metres, as rviz (assimp) and Gazebo scale it
    assert numpy.allclose(summary.solid.centre, (0.05, 0, 0))
    without = summarise_file(write(tmp_path / "plain.dae", box((0.4, 0.3, 0.1)), scale=1000))
    assert without.unit is None and numpy.allclose(without.size, (400, 300, 100))


def test_mass_properties_match_trimesh_on_a_closed_mesh(tmp_path):
    mesh = fine((0.2, 0.1, 0.3), subdivisions=3)
    mesh.apply_translation((1.0, -2.0, 0.5))  # far from the origin: the sums stay accurate
    summary = summarise_file(write(tmp_path / "ellipsoid.stl", mesh))
    assert summary.watertight and not summary.solid.hull
    assert numpy.isclose(summary.solid.volume, mesh.volume, rtol=1e-6)
    assert numpy.allclose(summary.solid.centre, mesh.center_mass, atol=1e-6)
    covariance = numpy.array(summary.solid.covariance)
    tensor = numpy.trace(covariance) * numpy.eye(3) - covariance
    assert numpy.allclose(tensor, mesh.moment_inertia / mesh.volume, rtol=1e-5, atol=1e-12)


def test_an_open_mesh_is_not_watertight_and_its_hull_stands_in(tmp_path):
    summary = summarise_file(write(tmp_path / "open.stl", open_box((0.4, 0.3, 0.1))))
    assert summary.watertight is False and summary.solid.hull
    assert numpy.isclose(summary.solid.volume, 0.4 * 0.3 * 0.1)
    assert summarise_file(write(tmp_path / "closed.stl", box((0.4, 0.3, 0.1)))).watertight is True


def test_the_hull_of_an_open_mesh_holds_only_the_vertices_its_faces_use(tmp_path):
    """romeo's TrunkYaw.dae holds 5,691 vertices of which its faces use 882: the hull of them
    all put the trunk's centre 10 cm above the mesh, and the inertia fix wrote it there."""
    mesh = open_box((0.4, 0.3, 0.1))
    lines = [f"v {x} {y} {z}" for x, y, z in mesh.vertices] + ["v 0 0 2", "v 0 0 3"]  # vertices no face uses
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in mesh.faces]
    path = tmp_path / "open.obj"
    path.write_text("\n".join(lines) + "\n")
    summary = summarise_file(path)
    assert summary.solid.hull and summary.high[2] == pytest.approx(0.05)
    assert summary.solid.volume == pytest.approx(0.4 * 0.3 * 0.1)
    assert summary.solid.centre == pytest.approx(tuple(mesh.convex_hull.center_mass), abs=1e-12)


def test_watertightness_agrees_with_trimesh_on_published_meshes():
    robots = example_robot_data() / "robots"
    files = sorted(p for p in robots.rglob("*") if p.suffix.lower() in (".stl", ".obj", ".dae"))[::9]  # a sample: 80 files
    assert len(files) > 50
    agree = 0
    for path in files:
        ours = read_mesh(path)
        mesh = trimesh.Trimesh(ours.vertices, ours.faces, process=False)
        mesh.merge_vertices(merge_tex=True, merge_norm=True)  # welded by position, as urdfcli welds
        agree += summarise_file(path).watertight == mesh.is_watertight
    assert agree >= len(files) - 2


@pytest.mark.parametrize(
    "name, content, kind, said",
    [
        ("empty.stl", b"", "empty", "the file is empty (0 bytes)"),
        ("pointer.stl", LFS_POINTER.encode(), "lfs", "Git LFS pointer"),
        ("pointer.dae", LFS_POINTER.encode(), "lfs", "Git LFS pointer"),
        ("cut.stl", binary_stl(box().vertices, box().faces)[:-70], "truncated", "header says 12 triangles"),
        ("cut_ascii.stl", ascii_stl(box().vertices, box().faces)[:300].encode(), "truncated", "without 'endsolid'"),
        ("cut.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n", "truncated", "names a vertex it does not have (3 vertices)"),
        ("words.obj", b"v 0 0 zero\nf 1 2 3\n", "malformed", "not a number"),
        ("bad.dae", b"<COLLADA><asset></COLLADA>", "malformed", "not well-formed XML (line 1)"),
        ("other.dae", b"<robot name='r'/>", "malformed", "not COLLADA: its root is <robot>"),
        ("tiny.stl", b"GARBAGE", "malformed", "not an STL"),
    ],
)
def test_what_is_not_a_mesh_is_named(tmp_path, name, content, kind, said):
    path = tmp_path / name
    path.write_bytes(content)
    with pytest.raises(MeshError) as raised:
        read_mesh(path)
    assert raised.value.kind == kind and said in raised.value.message
    assert summarise_file(path).problem.kind == kind


def test_a_collada_reference_to_nothing_is_named(tmp_path):
    path = write(tmp_path / "part.dae", box())
    path.write_text(path.read_text().replace('url="#part-mesh"', 'url="#gone"'))
    with pytest.raises(MeshError, match="names geometry '#gone', which it does not define"):
        read_mesh(path)


def test_a_collada_file_padded_with_nul_bytes_is_read_and_other_trailing_data_is_not(tmp_path):
    """Some exporters pad a COLLADA file with NUL bytes after </COLLADA>: assimp and
    tinyxml2 stop there and read it; so does urdfcli. Markup after it is still broken."""
    path = write(tmp_path / "part.dae", box())
    path.write_bytes(path.read_bytes() + b"\0" * 300)
    assert len(read_mesh(path).faces) == 12
    assert summarise_file(path).problem is None
    path.write_bytes(path.read_bytes().rstrip(b"\0") + b"<extra/>")
    with pytest.raises(MeshError, match="not well-formed"):
        read_mesh(path)


def test_a_format_urdfcli_does_not_read_is_left_alone(tmp_path):
    path = tmp_path / "Torso.mesh"  # Ogre's binary mesh: rviz reads it
    path.write_bytes(b"\x00\x10[MeshSerializer_v1.41]")
    with pytest.raises(Unsupported):
        read_mesh(path)
    found = summarise_file(path)
    assert found.problem is None and found.skipped == "urdfcli does not read .mesh files" and found.triangles is None


def test_a_file_is_read_once_per_session_and_again_when_it_changes(tmp_path):
    path = write(tmp_path / "part.stl", box())
    summaries = MeshSummaries()
    first = summaries.summary(path)
    assert summaries.summary(path) is first and summaries.reads == 1
    write(path, box((0.2, 0.2, 0.2)), kind="ascii")
    assert numpy.allclose(summaries.summary(path).size, (0.2, 0.2, 0.2)) and summaries.reads == 2


def test_hostile_files_are_not_expanded_nor_waited_for(tmp_path):
    entities = tmp_path / "bomb.dae"
    entities.write_text('<?xml version="1.0"?><!DOCTYPE c [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;">]><COLLADA>&b;</COLLADA>')
    assert summarise_file(entities).problem.kind == "malformed"  # entities are refused, never expanded
    loop = write(tmp_path / "loop.dae", box())
    loop.write_text(loop.read_text().replace('<instance_geometry url="#part-mesh" name="part"/>', '<instance_node url="#part"/>'))
    assert "nests nodes more than 64 deep" in summarise_file(loop).problem.message
    large = tmp_path / "large.stl"
    with large.open("wb") as file:  # sparse: 65 MiB that cost nothing to write
        file.truncate(65 << 20)
    found = summarise_file(large)
    assert found.problem is None and found.skipped == "not read: 65 MiB, larger than urdfcli reads"
