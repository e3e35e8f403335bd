"""`urdfcli inertia`: geometry-implied tensors, the seeds' inertia mistakes, totals, fixes."""

from __future__ import annotations

import json
import math
import re
import textwrap
import shutil

import numpy
import pytest
from conftest import FIXTURES, audited, lint_file, model, run_cli
from lxml import etree

from urdfcli.model import inertia, massprops
from urdfcli.model.poses import link_poses

CAR = FIXTURES / "urdf02_gazebo/urdf/broken_rotated_box_inertia_car.urdf.xacro"
HELLOWORLD = FIXTURES / "urdf02_gazebo/urdf/broken_invalid_inertia_helloworld.urdf"
MOBILE = FIXTURES / "seed000/my_mobile_robot.urdf"
CRANE = FIXTURES / "seed001/broken_inertia_crane.urdf"
JTBOT = FIXTURES / "seed003/jtbot.urdf"
JTBOT_XACRO = FIXTURES / "seed003/jtbot.urdf.xacro"

# A small, correct rover: a massless root, a box body, wheels rotated both ways
# (inertial rpy, or values already rotated), an offset mast, a massless frame.
ROVER = """<robot name="rover">
  <link name="base_footprint"/>
  <joint name="base_joint" type="fixed">
    <parent link="base_footprint"/><child link="base_link"/><origin xyz="0 0 0.1"/>
  </joint>
  <link name="base_link">
    <visual><geometry><box size="0.4 0.3 0.1"/></geometry></visual>
    <collision><geometry><box size="0.4 0.3 0.1"/></geometry></collision>
    <inertial><mass value="2"/><inertia ixx="0.0166667" ixy="0" ixz="0" iyy="0.0283333" iyz="0" izz="0.0416667"/></inertial>
  </link>
  <link name="left_wheel">
    <collision><origin rpy="1.5708 0 0"/><geometry><cylinder radius="0.05" length="0.02"/></geometry></collision>
    <inertial>
      <origin rpy="1.5708 0 0"/><mass value="0.5"/>
      <inertia ixx="0.000329167" ixy="0" ixz="0" iyy="0.000329167" iyz="0" izz="0.000625"/>
    </inertial>
  </link>
  <joint name="left_wheel_joint" type="continuous">
    <parent link="base_link"/><child link="left_wheel"/><origin xyz="0 0.16 0"/><axis xyz="0 1 0"/>
  </joint>
  <link name="right_wheel">
    <collision><origin rpy="1.5708 0 0"/><geometry><cylinder radius="0.05" length="0.02"/></geometry></collision>
    <inertial><mass value="0.5"/><inertia ixx="0.000329167" ixy="0" ixz="0" iyy="0.000625" iyz="0" izz="0.000329167"/></inertial>
  </link>
  <joint name="right_wheel_joint" type="continuous">
    <parent link="base_link"/><child link="right_wheel"/><origin xyz="0 -0.16 0"/><axis xyz="0 1 0"/>
  </joint>
  <link name="mast">
    <collision><origin xyz="0 0 0.25"/><geometry><box size="0.05 0.05 0.5"/></geometry></collision>
    <inertial>
      <origin xyz="0 0 0.25"/><mass value="1"/>
      <inertia ixx="0.0210417" ixy="0" ixz="0" iyy="0.0210417" iyz="0" izz="0.000416667"/>
    </inertial>
  </link>
  <joint name="mast_joint" type="fixed">
    <parent link="base_link"/><child link="mast"/><origin xyz="-0.1 0 0.05" rpy="0 0 0.3"/>
  </joint>
  <link name="camera_optical_frame">
    <inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial>
  </link>
  <joint name="camera_joint" type="fixed">
    <parent link="mast"/><child link="camera_optical_frame"/><origin xyz="0 0 0.5" rpy="-1.5708 0 -1.5708"/>
  </joint>
</robot>
"""


def codes_by_link(report) -> dict[str, set[str]]:
    return {entry.link.name: {d.code for d in entry.problems} for entry in report.links}


def one_link(tmp_path, body: str, mass: float = 1.0, name: str = "model.urdf") -> inertia.Implied:
    """What the geometry of a single link implies for the given mass."""
    path = tmp_path / name
    path.write_text(
        f'<robot name="r"><link name="l">{body}<inertial><mass value="{mass}"/>'
        '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link></robot>'
    )
    loaded = model(str(path))
    return inertia.implied(loaded, loaded.robot.links["l"])


def close(a, b, rel=1e-9, abs_=1e-15):
    assert numpy.allclose(numpy.array(a, dtype=float), numpy.array(b, dtype=float), rtol=rel, atol=abs_), (a, b)


# -- geometry-implied tensors ------------------------------------------------------------
def test_primitives_in_closed_form(tmp_path):
    close(one_link(tmp_path, '<collision><geometry><box size="0.5 0.3 0.1"/></geometry></collision>', 2).body.tensor, massprops.box(2, (0.5, 0.3, 0.1)))
    close(one_link(tmp_path, '<collision><geometry><cylinder radius="0.05" length="0.02"/></geometry></collision>', 0.5).body.tensor, massprops.cylinder(0.5, 0.05, 0.02))
    close(one_link(tmp_path, '<collision><geometry><sphere radius="0.2"/></geometry></collision>', 3).body.tensor, massprops.sphere(3, 0.2))


def test_collision_shapes_win_over_visual_shapes(tmp_path):
    found = one_link(tmp_path, '<visual><geometry><sphere radius="1"/></geometry></visual><collision><geometry><box size="1 2 3"/></geometry></collision>')
    assert found.source == "collision box"
    close(found.body.tensor, massprops.box(1, (1, 2, 3)))
    found = one_link(tmp_path, '<visual><geometry><sphere radius="1"/></geometry></visual>')
    assert found.source == "visual sphere"


def test_a_stand_in_collision_shape_is_not_the_body(tmp_path):
    # Baxter's head: a 1 mm collision sphere on a 10 cm visual box. Filled, the sphere is a
    # point mass (2.2e-7, 21,000 times below the declared tensor); the visual box is the body.
    found = one_link(tmp_path, '<visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual><collision><geometry><sphere radius="0.001"/></geometry></collision>')
    assert found.source == "visual box, not its 50 times smaller collision geometry"
    close(found.body.tensor, massprops.box(1, (0.1, 0.1, 0.1)))
    # a collision shape a fifth of its visual's size is a coarse collision model, still the body
    found = one_link(tmp_path, '<visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual><collision><geometry><sphere radius="0.01"/></geometry></collision>')
    assert found.source == "collision sphere"


def test_the_fix_and_suggest_fill_what_the_impossible_diagnostic_measures(tmp_path):
    path = tmp_path / "head.urdf"
    path.write_text(textwrap.dedent("""\
        <robot name="head_demo">
          <link name="base"/>
          <link name="head">
            <visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual>
            <collision><geometry><sphere radius="0.001"/></geometry></collision>
            <inertial>
              <mass value="0.547767"/>
              <inertia ixx="0.004641" ixy="0.000159" ixz="0.000242" iyy="0.003295" iyz="-0.001324" izz="0.003415"/>
            </inertial>
          </link>
          <joint name="head_pan" type="revolute">
            <parent link="base"/><child link="head"/><axis xyz="0 0 1"/>
            <limit effort="50" lower="-1.39" upper="1.39" velocity="1"/>
          </joint>
        </robot>
        """))
    report = json.loads(run_cli("lint", "--format", "json", str(path)).stdout)
    (found,) = report["files"][0]["diagnostics"]
    assert found["code"] == "I009" and "inside the 0.1 x 0.1 x 0.1 m box its shapes fill: 0.00274" in found["message"]
    box = massprops.number(massprops.box(0.547767, (0.1, 0.1, 0.1))[0][0])  # 0.000912945, within the 0.00274 the box allows
    assert f'ixx="{box}"' in run_cli("inertia", "--suggest", str(path)).stdout.decode()
    assert run_cli("lint", "--fix", "--unsafe-fixes", str(path)).returncode == 0  # fixed: nothing left to say
    assert f'ixx="{box}" ixy="0" ixz="0" iyy="{box}" iyz="0" izz="{box}"' in path.read_text()


def test_rotated_geometry(tmp_path):
    found = one_link(tmp_path, '<collision><origin rpy="0 0 1.5707963267948966"/><geometry><box size="0.4 0.2 0.1"/></geometry></collision>')
    close(massprops.tidy(found.body.tensor), massprops.box(1, (0.2, 0.4, 0.1)))
    found = one_link(tmp_path, '<collision><origin rpy="0.3 -0.7 1.1"/><geometry><box size="0.4 0.2 0.1"/></geometry></collision>')
    r = numpy.array(massprops.rotation((0.3, -0.7, 1.1)))
    close(found.body.tensor, r @ numpy.array(massprops.box(1, (0.4, 0.2, 0.1))) @ r.T)


def test_offset_shape_moves_the_centre_not_the_tensor(tmp_path):
    found = one_link(tmp_path, '<collision><origin xyz="0.1 -0.2 0.3"/><geometry><box size="0.4 0.2 0.1"/></geometry></collision>')
    close(found.body.com, (0.1, -0.2, 0.3))
    close(found.body.tensor, massprops.box(1, (0.4, 0.2, 0.1)))


def test_several_shapes_compose_by_volume_with_the_parallel_axis_theorem(tmp_path):
    halves = "".join(
        f'<collision><origin xyz="{x} 0 0"/><geometry><box size="0.5 1 2"/></geometry></collision>' for x in (-0.25, 0.25)
    )
    found = one_link(tmp_path, halves, 4)
    assert found.source == "collision shapes (box, box)"
    close(found.body.com, (0, 0, 0))
    close(found.body.tensor, massprops.box(4, (1, 1, 2)))
    # unequal volumes: the mass is spread by volume
    found = one_link(tmp_path, '<collision><geometry><box size="1 1 1"/></geometry></collision>'
                     '<collision><origin xyz="2 0 0"/><geometry><box size="3 1 1"/></geometry></collision>', 4)
    close(found.body.com, (1.5, 0, 0))


def write_mesh(mesh, folder, name):
    folder.mkdir(parents=True, exist_ok=True)
    mesh.export(str(folder / name))
    return folder / name


def test_box_mesh_matches_the_closed_form_with_scale_applied(tmp_path):
    import trimesh

    write_mesh(trimesh.creation.box(extents=(0.4, 0.3, 0.1)), tmp_path / "meshes", "body.stl")
    found = one_link(tmp_path, '<collision><geometry><mesh filename="meshes/body.stl" scale="2 1 0.5"/></geometry></collision>', 2)
    assert found.source == "collision mesh"
    assert found.volume == pytest.approx(0.8 * 0.3 * 0.05, rel=1e-6)
    close(found.body.com, (0, 0, 0), abs_=1e-12)
    close(found.body.tensor, massprops.box(2, (0.8, 0.3, 0.05)), rel=1e-6, abs_=1e-12)  # STL stores float32


def test_cylinder_mesh_through_a_package_uri_matches_the_closed_form(tmp_path):
    import trimesh

    package = tmp_path / "wheel_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text("<package format='2'><name>wheel_description</name></package>")
    write_mesh(trimesh.creation.cylinder(radius=0.05, height=0.02, sections=720), package / "meshes", "wheel.stl")
    found = one_link(package / "urdf", '<collision><origin rpy="1.5708 0 0"/><geometry><mesh filename="package://wheel_description/meshes/wheel.stl"/></geometry></collision>', 0.5)
    expected = massprops.rotate(massprops.cylinder(0.5, 0.05, 0.02), massprops.rotation((1.5708, 0, 0)))
    assert massprops.relative_difference(found.body.tensor, expected) < 1e-4  # a 720-sided prism


def test_unreadable_meshes_give_no_expected_tensor_and_no_problem(tmp_path):
    found = one_link(tmp_path, '<collision><geometry><mesh filename="meshes/missing.stl"/></geometry></collision>')
    assert found.body is None and found.source == f"mesh meshes/missing.stl not found ({tmp_path / 'meshes' / 'missing.stl'})"
    missing = (tmp_path / "gone.stl").as_uri()
    found = one_link(tmp_path, f'<collision><geometry><mesh filename="{missing}"/></geometry></collision>')
    assert found.source == f"mesh {missing} not found"  # its path once
    found = one_link(tmp_path, '<collision><geometry><mesh filename="https://example.com/arm.stl"/></geometry></collision>')
    assert found.body is None and "cannot be resolved" in found.source  # never fetched
    (tmp_path / "junk.stl").write_text("not a mesh")
    found = one_link(tmp_path, '<collision><geometry><mesh filename="junk.stl"/></geometry></collision>')
    assert found.body is None


# -- the seeds' mistakes -----------------------------------------------------------------
def test_seed002_rotated_box_macro_is_flagged_on_the_camera():
    report = audited(CAR)
    found = codes_by_link(report)
    assert "I009" in found["camera"]
    camera = next(e for e in report.links if e.link.name == "camera").assessment
    close(camera.expected, massprops.diagonal(4.16667e-6, 2.41667e-6, 2.41667e-6), rel=1e-5)
    assert {"I010"} <= found["left_wheel"] and {"I010"} <= found["right_wheel"]  # unrotated wheels
    for link in ("base_link", "front_wheel", "back_wheel", "support", "laser"):
        assert not found[link] & {"I009", "I010"}, link
    assert found["base_footprint"] == set()


def test_seed002_invalid_tensor_is_flagged():
    found = codes_by_link(audited(HELLOWORLD))
    assert {"I005", "I011"} <= found["base_link"]
    assert "I009" not in found["base_link"]  # one cause, one diagnostic: no body has that tensor


def test_seed000_unrotated_wheels_and_placeholders_are_flagged():
    found = codes_by_link(audited(MOBILE))
    for wheel in ("left_wheel", "right_wheel"):
        assert {"I006", "I010"} <= found[wheel] and "I009" not in found[wheel]  # I010 says why
    # within a factor of two of its box, like a CAD tensor: nothing the geometry proves wrong
    assert found["base_link"] == set()
    # the shared tensor sits on links of a few grams, whose inertia matters to no one
    for sensor in ("laser_link", "camera_link", "imu_link"):
        assert found[sensor] == set(), sensor


def test_seed001_crane_is_flagged():
    found = codes_by_link(audited(CRANE))
    assert {"I006", "I011"} <= found["base_link"]
    assert "I009" in found["shoulder_link_base"]  # a moment no 100 kg inside its 10 m box can reach
    assert found["shoulder_link_top"] == {"I007"}  # one cause, one diagnostic
    assert found["shoulder_link_right"] == {"I006"}
    assert "I006" in found["shoulder_link_left"]  # its mesh is missing: no expected tensor


@pytest.mark.parametrize("path", [JTBOT, JTBOT_XACRO], ids=lambda p: p.name)
def test_jtbot_base_and_wheels_are_correct_once_the_inertial_rpy_is_applied(path):
    report = audited(path)
    found = codes_by_link(report)
    for link in ("base_link", "left_wheel_link", "right_wheel_link", "caster_link"):
        assert not found[link] & {"I009", "I010"}, (link, found[link])
    assert found["base_link"] == {"I011"}
    assert "I009" in found["imu_link"]  # computed for a 0.1 m cube: more than its 6 cm box can hold
    assert found["laser"] == {"I008"} and found["camera_link"] == {"I008"}  # one diagnostic names both


def test_a_correct_model_has_no_problem(tmp_path):
    path = tmp_path / "rover.urdf"
    path.write_text(ROVER)
    report = audited(path)
    assert report.problems == ()
    frames = [e.link.name for e in report.links if e.frame]
    assert frames == ["base_footprint", "camera_optical_frame"]
    result = run_cli("inertia", str(path))
    assert result.returncode == 0, result.stderr.decode()
    assert "0 problems" in result.stderr.decode()


def test_identical_wheels_sharing_a_tensor_are_not_placeholders(tmp_path):
    path = tmp_path / "rover.urdf"
    path.write_text(ROVER.replace('iyy="0.000625" iyz="0" izz="0.000329167"', 'iyy="0.000329167" iyz="0" izz="0.000625"').replace(
        '<inertial><mass value="0.5"/>', '<inertial><origin rpy="1.5708 0 0"/><mass value="0.5"/>'))
    assert audited(path).problems == ()


def test_tolerance_passes_rounding_and_catches_swaps(tmp_path):
    rounded = ROVER.replace("0.0166667", "0.017").replace("0.0283333", "0.028").replace("0.0416667", "0.042")
    path = tmp_path / "rounded.urdf"
    path.write_text(rounded)
    assert audited(path).problems == ()
    swapped = ROVER.replace('ixx="0.0166667" ixy="0" ixz="0" iyy="0.0283333"', 'ixx="0.0283333" ixy="0" ixz="0" iyy="0.0166667"')
    path.write_text(swapped)
    assert {d.code for d in audited(path).problems} == {"I009"}
    assert audited(path, tolerance=0.5).problems == ()


# -- the whole robot ---------------------------------------------------------------------
@pytest.mark.parametrize("path", [JTBOT, MOBILE, CRANE], ids=lambda p: p.name)
def test_link_poses_match_yourdfpy_reading_the_file_itself(path):
    import yourdfpy

    reference = yourdfpy.URDF.load(str(path), build_scene_graph=True, load_meshes=False)
    loaded = model(str(path))
    poses = link_poses(loaded)
    assert set(poses) == set(loaded.robot.links)
    for name, (rotation, translation) in poses.items():
        matrix = reference.get_transform(name, loaded.root)
        close(rotation, matrix[:3, :3], abs_=1e-9)
        close(translation, matrix[:3, 3], abs_=1e-9)


def test_a_mimic_joint_sits_at_its_offset_at_zero_positions(tmp_path):
    path = tmp_path / "mimic.urdf"
    path.write_text(
        '<robot name="m"><link name="base"/><link name="a"/><link name="b"/><link name="c"/>'
        '<joint name="j1" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>'
        '<limit lower="-3" upper="3" effort="1" velocity="1"/></joint>'
        '<joint name="j2" type="revolute"><parent link="a"/><child link="b"/><origin xyz="1 0 0"/><axis xyz="0 0 1"/>'
        '<limit lower="-3" upper="3" effort="1" velocity="1"/><mimic joint="j1" multiplier="2" offset="1.5707963267948966"/></joint>'
        '<joint name="j3" type="fixed"><parent link="b"/><child link="c"/><origin xyz="1 0 0"/></joint></robot>'
    )
    poses = link_poses(model(str(path)))
    close(poses["b"][1], (1, 0, 0), abs_=1e-12)
    close(poses["c"][1], (1, 1, 0), abs_=1e-12)  # b is turned a quarter about z by the offset


def test_total_of_the_rover_against_a_hand_computation(tmp_path):
    path = tmp_path / "rover.urdf"
    path.write_text(ROVER)
    body = inertia.total(model(str(path)))
    # by hand: body at z=0.1; wheels at y=±0.16 (z 0.1); mast rotated 0.3 about z, centre 0.25 above (-0.1, 0, 0.15)
    parts = [
        (2.0, numpy.array([0, 0, 0.1]), numpy.diag([0.0166667, 0.0283333, 0.0416667])),
        (0.5, numpy.array([0, 0.16, 0.1]), numpy.diag([0.000329167, 0.000625, 0.000329167])),
        (0.5, numpy.array([0, -0.16, 0.1]), numpy.diag([0.000329167, 0.000625, 0.000329167])),
        (1.0, numpy.array([-0.1, 0, 0.4]), numpy.diag([0.0210417, 0.0210417, 0.000416667])),  # symmetric about z: turning changes nothing
    ]
    mass = sum(m for m, _, _ in parts)
    com = sum(m * c for m, c, _ in parts) / mass
    tensor = sum(t + m * ((c - com) @ (c - com) * numpy.eye(3) - numpy.outer(c - com, c - com)) for m, c, t in parts)
    assert body.mass == pytest.approx(4.0)
    close(body.com, com, rel=1e-6, abs_=1e-6)
    close(body.tensor, tensor, rel=1e-4, abs_=1e-8)


def test_total_with_density_weighs_each_link_by_its_geometry(tmp_path):
    path = tmp_path / "rover.urdf"
    path.write_text(ROVER)
    loaded = model(str(path))
    body = inertia.total(loaded, density=1000)
    # body box 0.4 x 0.3 x 0.1; wheels r 0.05 l 0.02; mast 0.05 x 0.05 x 0.5 (collision shapes)
    volumes = 0.4 * 0.3 * 0.1 + 2 * math.pi * 0.05**2 * 0.02 + 0.05 * 0.05 * 0.5
    assert body.mass == pytest.approx(1000 * volumes)
    assert inertia.total(loaded).mass == pytest.approx(4.0)


def test_total_rotates_each_link_tensor_into_the_root_frame(tmp_path):
    """A box turned a quarter turn by its joint: its ixx and iyy swap in the root frame."""
    path = tmp_path / "turned.urdf"
    path.write_text(
        '<robot name="t"><link name="root"/><link name="plate"><inertial><mass value="1"/>'
        '<inertia ixx="1" ixy="0" ixz="0" iyy="2" iyz="0" izz="3"/></inertial></link>'
        '<joint name="j" type="revolute"><parent link="root"/><child link="plate"/><origin xyz="1 0 0" rpy="0 0 1.5707963267948966"/>'
        '<axis xyz="0 0 1"/><limit effort="1" velocity="1" lower="-1" upper="1"/></joint></robot>'
    )
    body = inertia.total(model(str(path)))
    close(body.com, (1, 0, 0), abs_=1e-12)
    close(body.tensor, massprops.diagonal(2, 1, 3), abs_=1e-12)


# -- the command -------------------------------------------------------------------------
def test_the_principal_moments_of_a_singular_tensor_are_said_without_rounding_noise(tmp_path):
    """Sawyer's right_hand: all six elements 1e-08, moments exactly 0, 0, 3e-08. The solve
    gives -6.6e-24 and 6.6e-24 for the zeros; text and JSON say 0, as the I006 beside them does."""
    path = tmp_path / "hand.urdf"
    path.write_text(
        '<robot name="r"><link name="hand"><inertial><mass value="1e-08"/>'
        '<inertia ixx="1e-08" ixy="1e-08" ixz="1e-08" iyy="1e-08" iyz="1e-08" izz="1e-08"/></inertial></link></robot>'
    )
    text = run_cli("inertia", str(path)).stdout.decode()
    assert re.search(r"principal +0 0 3e-08\n", text), text
    [link] = json.loads(run_cli("inertia", "--format", "json", str(path)).stdout)["links"]
    assert link["principal"] == [0, 0, pytest.approx(3e-08)]


def test_json_has_exactly_the_documented_shape():
    result = run_cli("inertia", "--format", "json", str(CAR))
    assert result.returncode == 1
    data = json.loads(result.stdout)
    assert set(data) == {"robot", "links", "total"} and data["robot"] == "mycar"
    tensor_keys = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}
    for link in data["links"]:
        assert set(link) == {"name", "path", "line", "column", "mass", "mass_used", "com", "inertia", "principal", "expected", "expected_from", "problems"}
        for problem in link["problems"]:
            assert set(problem) == {"code", "severity", "message", "path", "line", "column", "element", "subjects", "hint", "model", "trace", "fix"}
    camera = next(link for link in data["links"] if link["name"] == "camera")
    assert camera["mass"] == pytest.approx(0.01) and camera["com"] == [0, 0, 0]
    assert set(camera["inertia"]) == tensor_keys and set(camera["expected"]) == tensor_keys
    assert camera["expected"]["ixx"] == pytest.approx(4.16667e-6, rel=1e-5)
    assert camera["principal"] == pytest.approx(sorted([2.41667e-6, 2.41667e-6, 4.16667e-6]), rel=1e-5)
    assert camera["expected_from"] == "collision box"
    # the seed's rotated Box_inertial_matrix, shown on a 10 g camera: info, as on any link of a few grams
    assert [p["code"] for p in camera["problems"]] == ["I009"] and camera["problems"][0]["severity"] == "info"
    frame = next(link for link in data["links"] if link["name"] == "base_footprint")
    assert frame.pop("path").endswith(".urdf.xacro") and frame.pop("line") > 0
    assert frame == {"name": "base_footprint", "column": frame["column"], "mass": None, "mass_used": None, "com": None, "inertia": None, "principal": None,
                     "expected": None, "expected_from": "massless frame link", "problems": []}
    assert set(data["total"]) == {"mass", "com", "inertia"} and data["total"]["mass"] == pytest.approx(2.38)
    assert set(data["total"]["inertia"]) == tensor_keys


def test_text_output_lists_links_problems_and_total():
    result = run_cli("inertia", str(CAR))
    out, err = result.stdout.decode(), result.stderr.decode()
    assert result.returncode == 1
    assert "base_footprint  massless frame link" in out
    assert "I009 inertia-geometry-mismatch" in out and "total  mass 2.38" in out
    assert re.search(r"broken_rotated_box_inertia_head\.xacro:\d+:\d+: I009 info: inertia of link 'camera'", err)
    assert "1 file audited: 3 problems" in err


def test_a_tensor_many_times_off_says_how_many_times(tmp_path):
    """1 kg filling a 10 cm cube: a uniform body has 0.00167 about each axis. 0.1 (60 times)
    and 3.33e-05 (a 50th) read 98.3 % and 98 % apart as a fraction of the larger tensor,
    as 20 times would (95 %): they are said in times; 0.0025 (1.5 times) in percent."""
    def cube(name: str, moment: str) -> str:
        return (f'<link name="{name}"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision><inertial><mass value="1"/>'
                f'<inertia ixx="{moment}" ixy="0" ixz="0" iyy="{moment}" iyz="0" izz="{moment}"/></inertial></link>'
                f'<joint name="{name}_joint" type="fixed"><parent link="root"/><child link="{name}"/></joint>')
    path = tmp_path / "cubes.urdf"
    path.write_text(f'<robot name="cubes"><link name="root"/>{cube("heavy", "0.1")}{cube("light", "0.0000333")}{cube("near", "0.0025")}</robot>\n')
    rows = [line.strip() for line in run_cli("inertia", str(path)).stdout.decode().splitlines() if line.strip().startswith("expected")]
    assert rows == [
        "expected   ixx=0.00167 iyy=0.00167 izz=0.00167  (collision box; declared 60 times larger)",
        "expected   ixx=0.00167 iyy=0.00167 izz=0.00167  (collision box; declared 50 times smaller)",
        "expected   ixx=0.00167 iyy=0.00167 izz=0.00167  (collision box; 33.3% apart)",
    ]
    # the rules word it alike: I009 at a density (water: 1 kg per litre, the declared mass)
    err = run_cli("inertia", "--density", "1000", str(path)).stderr.decode()
    assert "inertia of link 'light': it is 50 times smaller than what its collision box implies at density 1000: " in err
    assert "inertia of link 'near': it is 33% off what its collision box implies at density 1000: " in err


def paste_suggestions(source: str, suggestions: str) -> str:
    """The URDF with each suggested <inertial> pasted over the link's own."""
    root = etree.fromstring(source.encode())
    for name, block in re.findall(r"<!-- link '([^']+)': a uniform body filling its [^>]*-->\n(<inertial>.*?</inertial>)", suggestions, re.S):
        link = root.find(f"link[@name='{name}']")
        old = link.find("inertial")
        link.replace(old, etree.fromstring(block)) if old is not None else link.append(etree.fromstring(block))
    return etree.tostring(root, encoding="unicode")


@pytest.mark.parametrize("path", [MOBILE, JTBOT, HELLOWORLD, CRANE], ids=lambda p: p.name)
def test_pasting_the_suggested_blocks_fixes_the_flagged_links(path, tmp_path):
    result = run_cli("inertia", "--suggest", str(path))
    fixed = tmp_path / path.name
    fixed.write_text(paste_suggestions(path.read_text(), result.stdout.decode()))
    remaining = {d.code for d in audited(fixed).problems}
    unfixable = {"I011"} | ({"I006"} if path == CRANE else set())  # the crane's shoulder_link_left mesh is missing
    assert remaining <= unfixable, remaining


def test_suggest_says_why_when_it_cannot(tmp_path):
    result = run_cli("inertia", "--suggest", str(CRANE))
    assert "<!-- link 'shoulder_link_left': no suggestion: mesh /home/user/catkin_ws/src/sim_api/model/meshes/car_link.stl not found" in result.stdout.decode()


def test_xacro_names_the_macro_and_the_call_that_fixes_it(tmp_path):
    package = tmp_path / "urdf02_gazebo"
    shutil.copytree(FIXTURES / "urdf02_gazebo", package)
    car = package / "urdf" / CAR.name
    out = run_cli("inertia", "--suggest", "--xacro", str(car)).stdout.decode()
    assert re.search(r"<!-- link 'camera': its <inertial> comes from xacro macro 'Box_inertial_matrix' \(\S+broken_rotated_box_inertia_head\.xacro:23\), "
                     r"called at \S+demo06_car_camera\.urdf\.xacro:25 as <xacro:Box_inertial_matrix", out)
    call = re.search(r'<xacro:Box_inertial_matrix m="0.01" [^>]*/>', out.split("the call that gives")[1]).group(0)
    assert "no call of 'cylinder_inertial_matrix' gives the geometry's values" in out  # the wheels need a rotation
    # the printed call, pasted in place of the original one, fixes the camera
    camera_file = package / "urdf" / "demo06_car_camera.urdf.xacro"
    camera_file.write_text(re.sub(r"<xacro:Box_inertial_matrix [^>]*/>", call, camera_file.read_text()))
    found = codes_by_link(audited(car))
    assert not found["camera"]


def test_xacro_finds_the_right_call_for_jtbots_imu():
    out = run_cli("inertia", "--suggest", "--xacro", str(JTBOT_XACRO)).stdout.decode()
    assert "macro 'box_inertia'" in out
    call = re.search(r"<xacro:box_inertia m=\"0.1\" [^>]*/>\n", out.split("<!-- link 'imu_link'")[1]).group(0)
    assert sorted(re.findall(r'[whd]="([\d.]+)"', call)) == ["0.03", "0.03", "0.06"]


def test_xacro_finds_the_call_of_a_macro_with_a_block_parameter_and_keeps_its_block(tmp_path):
    """An inertial macro taking *origin (the tutorials' `inertial_cylinder`): the call is
    tried with the block the model gives, whose rpy turns the tensor with the cylinder."""
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(textwrap.dedent("""\
        <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
          <xacro:macro name="inertial_cylinder" params="m r h *origin">
            <inertial>
              <xacro:insert_block name="origin"/>
              <mass value="${m}"/>
              <inertia ixx="${m*(3*r*r+h*h)/12}" ixy="0" ixz="0" iyy="${m*(3*r*r+h*h)/12}" iyz="0" izz="${m*r*r/2}"/>
            </inertial>
          </xacro:macro>
          <link name="base"/>
          <link name="roller">
            <xacro:inertial_cylinder m="2" r="0.1" h="0.5"><origin xyz="0 0 0" rpy="0 1.5708 0"/></xacro:inertial_cylinder>
            <collision><origin rpy="0 1.5708 0"/><geometry><cylinder radius="0.1" length="0.05"/></geometry></collision>
          </link>
          <joint name="roller_joint" type="continuous"><parent link="base"/><child link="roller"/><axis xyz="1 0 0"/></joint>
        </robot>
        """))
    assert codes_by_link(audited(path))["roller"]
    out = run_cli("inertia", "--suggest", "--xacro", str(path)).stdout.decode()
    assert f'called at {path}:11 as <xacro:inertial_cylinder m="2" r="0.1" h="0.5"><origin xyz="0 0 0" rpy="0 1.5708 0"/></xacro:inertial_cylinder> -->' in out
    call = out.split("<!-- the call that gives the geometry's values: -->\n")[1].splitlines()[0]
    assert call == '<xacro:inertial_cylinder m="2" r="0.1" h="0.05"><origin xyz="0 0 0" rpy="0 1.5708 0"/></xacro:inertial_cylinder>'
    # pasted in place of the call, it fixes the link as xacro expands it
    path.write_text(re.sub(r"<xacro:inertial_cylinder m=.*</xacro:inertial_cylinder>", call, path.read_text()))
    assert not codes_by_link(audited(path))["roller"]


def test_density_computes_masses_from_volume(tmp_path):
    path = tmp_path / "cube.urdf"
    path.write_text('<robot name="c"><link name="root"/><link name="cube"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>'
                    '<inertial><mass value="1"/><inertia ixx="0.00166667" ixy="0" ixz="0" iyy="0.00166667" iyz="0" izz="0.00166667"/></inertial></link>'
                    '<joint name="j" type="fixed"><parent link="root"/><child link="cube"/></joint></robot>')
    assert run_cli("inertia", "--density", "1000", str(path)).returncode == 0  # 1 kg of water: as declared
    result = run_cli("inertia", "--density", "2700", "--suggest", str(path))  # aluminium
    assert result.returncode == 1
    assert '<mass value="2.7"/>' in result.stdout.decode()
    assert 'ixx="0.0045"' in result.stdout.decode()


def test_density_rows_show_the_mass_used_and_the_total_adds_them(tmp_path):
    path = tmp_path / "two.urdf"
    cube = '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>'
    path.write_text('<robot name="c"><link name="root"><inertial><mass value="3"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>'
                    f'<link name="cube">{cube}<inertial><mass value="1"/><inertia ixx="0.00166667" ixy="0" ixz="0" iyy="0.00166667" iyz="0" izz="0.00166667"/></inertial></link>'
                    f'<link name="shell">{cube}</link>'
                    '<joint name="j" type="fixed"><parent link="root"/><child link="cube"/></joint>'
                    '<joint name="k" type="fixed"><parent link="root"/><child link="shell"/></joint></robot>')
    out = run_cli("inertia", "--density", "2700", str(path)).stdout.decode()
    assert "cube  mass 2.7 from density (declared 1)" in out
    assert "shell  mass 2.7 from density (none declared)" in out  # a massless link with geometry counts too
    assert "root  mass 3  com" in out  # no geometry: its declared mass
    assert re.search(r"^total  mass 8.4 ", out, re.M)
    report = json.loads(run_cli("inertia", "--density", "2700", "--format", "json", str(path)).stdout)
    used = {link["name"]: link["mass_used"] for link in report["links"]}
    assert used == pytest.approx({"root": 3, "cube": 2.7, "shell": 2.7})
    assert report["total"]["mass"] == pytest.approx(sum(used.values()))


def test_massless_moving_link_gets_a_suggestion_only_with_density(tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(ROVER.replace('<link name="mast">', '<link name="mast_unused">').replace(
        '<link name="base_footprint"/>', '<link name="base_footprint"/><link name="mast"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>'
    ).replace('<joint name="mast_joint" type="fixed">', '<joint name="mast_joint" type="continuous"><axis xyz="0 0 1"/>'))
    result = run_cli("inertia", "--suggest", str(path))
    assert "no suggestion: it declares no mass (give --density)" in result.stdout.decode()
    assert '<mass value="1"/>' in run_cli("inertia", "--suggest", "--density", "1000", str(path)).stdout.decode()


def test_check_leaves_the_geometry_rules_to_inertia_and_lint():
    result = run_cli("check", str(CAR))
    assert result.returncode == 0
    assert not re.search(r"I0(07|08|09|10|11)", result.stderr.decode())  # numpy and the rest stay out: test_check


@pytest.mark.parametrize(
    "args,message",
    [
        (["--tolerance", "0"], "--tolerance must be a positive fraction"),
        (["--density", "-3"], "--density must be a positive number"),
        (["--format", "json", "--suggest"], "--suggest and --xacro print XML"),
    ],
)
def test_bad_options_exit_2_in_one_line(args, message):
    result = run_cli("inertia", *args, str(JTBOT))
    assert result.returncode == 2
    assert message in result.stderr.decode() and "Traceback" not in result.stderr.decode()


@pytest.mark.parametrize("output_format", ["text", "json"])
def test_missing_file_exits_2(output_format):
    result = run_cli("inertia", "--format", output_format, "no/such.urdf")
    assert result.returncode == 2 and "no such file" in result.stderr.decode()
    assert "Traceback" not in result.stderr.decode() and result.stdout == b""


def test_malformed_input_exits_1_with_its_error(tmp_path):
    path = tmp_path / "bad.urdf"
    path.write_text("<robot name='x'><link name='a'></robot>")
    result = run_cli("inertia", "--format", "json", str(path))
    assert result.returncode == 1
    assert json.loads(result.stdout) == {"robot": None, "links": [], "total": None}
    assert "X001" in result.stderr.decode()


def test_angles_in_messages_are_readable():
    found = [d for d in audited(MOBILE).problems if d.code == "I010"]
    assert found and "rpy 1.5708 0 0" in found[0].message
    assert math.isclose(float(found[0].message.split("rpy ")[1].split()[0]), 1.5708)


def test_json_for_several_files_is_a_list():
    result = run_cli("inertia", "--format", "json", str(JTBOT), str(MOBILE))
    data = json.loads(result.stdout)
    assert [d["robot"] for d in data] == ["jtbot", "my_mobile_robot"]


def test_an_info_alone_does_not_fail_the_audit(tmp_path):
    """A root link with mass (I011, info: only KDL ignores it) is shown, and the exit is 0."""
    path = tmp_path / "root.urdf"
    path.write_text(
        '<robot name="r"><link name="base"><inertial><mass value="1"/>'
        '<inertia ixx="0.0017" ixy="0" ixz="0" iyy="0.0017" iyz="0" izz="0.0017"/></inertial>'
        '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link></robot>\n'
    )
    result = run_cli("inertia", str(path))
    assert "I011 info" in result.stderr.decode()
    assert result.returncode == 0, result.stderr.decode()


def test_xacro_never_offers_to_replace_a_macro_that_makes_the_whole_link(tmp_path):
    """A gripper macro writes its links and their <inertial>s: the fix is in the macro's
    body, not a call of the gripper replaced by an <inertial>."""
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(textwrap.dedent("""\
        <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
          <xacro:macro name="gripper" params="prefix parent">
            <link name="${prefix}_finger">
              <inertial><mass value="0.1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
              <collision><geometry><box size="0.02 0.02 0.08"/></geometry></collision>
            </link>
            <joint name="${prefix}_finger_joint" type="prismatic"><parent link="${parent}"/><child link="${prefix}_finger"/>
              <axis xyz="0 1 0"/><limit lower="0" upper="0.04" effort="10" velocity="0.1"/></joint>
          </xacro:macro>
          <link name="base"/>
          <xacro:gripper prefix="left" parent="base"/>
        </robot>
        """))
    out = run_cli("inertia", "--suggest", "--xacro", str(path)).stdout.decode()
    assert f"<!-- link 'left_finger': its <inertial> is written at {path}:4, in the body of xacro macro 'gripper': replace it there with -->" in out
    assert "replace the call" not in out and "<xacro:gripper" not in out.split("left_finger")[1]
    assert "<inertial>" in out.split("left_finger")[-1]


def test_links_written_alike_are_each_named_and_judged_in_their_own_body(tmp_path):
    """Links written alike share one verdict, but each is named in its own diagnostic, and one
    lost in a heavier body it is fixed to is a note where the moving ones are warnings."""
    finger = """
  <link name="{name}">
    <collision><geometry><box size="0.02 0.02 0.1"/></geometry></collision>
    <inertial><mass value="0.01"/><inertia ixx="6.66667e-07" ixy="0" ixz="0" iyy="8.66667e-06" iyz="0" izz="8.66667e-06"/></inertial>
  </link>
  <joint name="{name}_joint" type="{kind}"><parent link="palm"/><child link="{name}"/>{limit}</joint>"""
    limit = '<axis xyz="0 1 0"/><limit lower="0" upper="1" effort="1" velocity="1"/>'
    fingers = "".join(finger.format(name=name, kind=kind, limit=limit if kind == "revolute" else "")
                      for name, kind in (("finger_1", "revolute"), ("finger_2", "revolute"), ("finger_fixed", "fixed")))
    path = tmp_path / "hand.urdf"
    path.write_text(f"""<robot name="hand">
  <link name="palm">
    <collision><geometry><box size="0.1 0.1 0.02"/></geometry></collision>
    <inertial><mass value="1"/><inertia ixx="0.000866667" ixy="0" ixz="0" iyy="0.000866667" iyz="0" izz="0.00166667"/></inertial>
  </link>{fingers}
</robot>
""")
    found = {d.subjects: d for d in lint_file(path).diagnostics if d.code == "I009"}
    assert set(found) == {("finger_1",), ("finger_2",), ("finger_fixed",)}
    for name, diagnostic in found.items():
        assert diagnostic.message.startswith(f"inertia of link '{name[0]}': "), diagnostic.message
    for moving in ("finger_1", "finger_2"):  # a warning: more than 10 g can reach in the box
        assert found[(moving,)].severity == "warning" and "4.3 times the most 0.01 kg can reach" in found[(moving,)].message
    fixed = found[("finger_fixed",)]  # lost in the palm: only its turned axes are said, as a note
    assert fixed.severity == "info" and "on axes 90° away" in fixed.message, fixed.message


def test_a_model_without_masses_is_said_to_be_one_and_its_shaped_links_not_called_frames(tmp_path):
    """ROS-Industrial's support packages: meshes and joints, no <inertial> anywhere. A link that
    collides, or that a joint moves, is a part without <inertial>, not a frame; the total says
    the model has no masses."""
    path = tmp_path / "arm.urdf"
    path.write_text(
        '<robot name="arm">\n  <link name="base_link"><collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision></link>\n'
        '  <link name="link_1"><visual><geometry><cylinder radius="0.05" length="0.3"/></geometry></visual></link>\n'
        '  <link name="tool0"/>\n'
        '  <joint name="joint_1" type="revolute"><parent link="base_link"/><child link="link_1"/><axis xyz="0 0 1"/>'
        '<limit lower="-3" upper="3" effort="0" velocity="2"/></joint>\n'
        '  <joint name="joint_tool0" type="fixed"><parent link="link_1"/><child link="tool0"/></joint>\n</robot>\n'
    )
    out = run_cli("inertia", str(path)).stdout.decode()
    assert "base_link  massless: no <inertial>" in out and "link_1  massless: no <inertial>" in out
    assert "tool0  massless frame link" in out
    assert "total  no link declares a mass: a kinematic model" in out
    data = json.loads(run_cli("inertia", "--format", "json", str(path)).stdout)
    assert [link["expected_from"] for link in data["links"]] == ["massless: no <inertial>", "massless: no <inertial>", "massless frame link"]


def test_one_value_computed_two_ways_reads_the_same_in_declared_and_expected():
    """ros2_control_demos' diffbot: a wheel's izz written as m/2*r*r by xacro is
    3.3749999999999994e-05, the cylinder's m*r**2/2 is 3.375e-05; the table showed
    'izz=3.37e-05' declared and 'izz=3.38e-05' expected, 0.0% apart."""
    written, implied = (((0, 0, 0), (0, 0, 0), (0, 0, izz)) for izz in (0.3 / 2.0 * 0.015 * 0.015, 0.3 * 0.015**2 / 2))
    assert massprops.tensor_text(written) == massprops.tensor_text(implied) == "ixx=0 iyy=0 izz=3.38e-05"
