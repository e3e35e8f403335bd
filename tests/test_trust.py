"""The defects published robots still hid, and severities that match consequences:
each finding with the defect and its clean counterpart."""

from __future__ import annotations

import json
import subprocess

from conftest import lint_file, require_tool, run_cli
from ros_workspace import edit, make_repository

from urdfcli.project.config import Config


def lint(tmp_path, body: str, name: str = "robot.urdf"):
    path = tmp_path / name
    path.write_text(f'<robot name="r">{body}</robot>')
    return lint_file(path, Config.everything()).diagnostics


def found(tmp_path, body: str, *codes: str) -> list[tuple[str, str, str]]:
    return [(d.code, d.severity.value, d.message) for d in lint(tmp_path, body) if d.code in codes]


def inertial(mass, ixx, iyy, izz, ixy=0.0, ixz=0.0, iyz=0.0, xyz="0 0 0") -> str:
    return (f'<inertial><origin xyz="{xyz}"/><mass value="{mass}"/>'
            f'<inertia ixx="{ixx}" ixy="{ixy}" ixz="{ixz}" iyy="{iyy}" iyz="{iyz}" izz="{izz}"/></inertial>')


def box(size: str) -> str:
    return f'<collision><geometry><box size="{size}"/></geometry></collision>'


def child(name: str, inside: str, joint: str = "fixed", parent: str = "base", extra: str = "") -> str:
    limit = '<limit lower="-1" upper="1" effort="10" velocity="1"/>' if joint in ("revolute", "prismatic") else ""
    return (f'<link name="{name}">{inside}</link><joint name="{name}_joint" type="{joint}"><parent link="{parent}"/>'
            f'<child link="{name}"/><axis xyz="0 0 1"/>{limit}{extra}</joint>')


# TurtleBot3 Waffle Pi's base: 1.37 kg, about 0.28 x 0.3 x 0.1 m, its tensor about 0.009
BASE = '<link name="base">' + box("0.28 0.3 0.1") + inertial(1.37, 0.0087, 0.0086, 0.0145) + "</link>"


# -- A.1: a light link judged by what it does to its body ---------------------------------------
def test_a_light_fixed_link_whose_tensor_changes_its_body_is_judged(tmp_path):
    # the casters: 5 g carrying 0.001 kg·m², 11 % of the base's moment each, far beyond a 3 cm sphere
    caster = '<collision><geometry><sphere radius="0.015"/></geometry></collision>' + inertial(0.005, 0.001, 0.001, 0.001)
    diagnostics = found(tmp_path, BASE + child("caster", caster), "I009")
    assert [(c, s) for c, s, _ in diagnostics] == [("I009", "warning")] and "'caster'" in diagnostics[0][2]


def test_a_light_fixed_link_whose_tensor_is_negligible_is_left_alone(tmp_path):
    frame = '<collision><geometry><sphere radius="0.001"/></geometry></collision>' + inertial(1e-6, 1e-9, 1e-9, 1e-9)
    assert found(tmp_path, BASE + child("imu", frame), "I003", "I004", "I005", "I006", "I008", "I009") == []


def test_an_impossible_tensor_on_a_milligram_link_is_reported_where_it_matters(tmp_path):
    # 10 mg carrying a tensor that adds 0.5 kg·m² (and is no tensor at all)
    ghost = inertial(1e-5, 0.5, 0.0, 0.5, iyz=1.0)
    assert [c for c, _, _ in found(tmp_path, BASE + child("ghost", ghost), "I005")] == ["I005"]
    # the same mistake at 1e-12: lost in its body, but MuJoCo refuses the model all the same (tried):
    # a warning that says so, not the error
    tiny = inertial(1e-5, 1e-12, 0.0, 1e-12, iyz=2e-12)
    [(code, severity, message)] = found(tmp_path, BASE + child("ghost", tiny), "I005")
    assert severity == "warning" and "MuJoCo refuses the model" in message


def test_a_light_moving_body_is_judged_whatever_its_mass(tmp_path):
    # Kinova's finger links: 10 g, the moment about the long axis far below any body of that shape
    finger = box("0.015 0.015 0.045") + inertial(0.01, 1.7e-6, 1.7e-6, 1.5e-8)
    diagnostics = found(tmp_path, BASE + child("finger", finger, joint="revolute"), "I009")
    assert [c for c, _, _ in diagnostics] == ["I009"] and "smallest principal moment" in diagnostics[0][2]
    right = box("0.015 0.015 0.045") + inertial(0.01, 1.9e-6, 1.9e-6, 3.7e-7)  # a uniform body of that box
    assert found(tmp_path, BASE + child("finger", right, joint="revolute"), "I009") == []


# -- A.4: copies of one part with masses apart ------------------------------------------------
def test_copies_of_one_part_whose_masses_differ_are_named_together(tmp_path):
    finger = '<collision><geometry><mesh filename="finger.stl"/></geometry></collision>'
    (tmp_path / "finger.stl").write_text("solid f\nendsolid f\n")
    tensor = (2.375e-6, 2.375e-6, 7.5e-7)
    body = BASE + child("left", finger + inertial(0.015, *tensor), joint="prismatic") + child("right", finger + inertial(0.15, *tensor), joint="prismatic")
    (code, severity, message), = found(tmp_path, body, "I012")
    assert severity == "warning" and "'left' (0.015 kg) and 'right' (0.15 kg)" in message and "10 times apart" in message
    same = BASE + child("left", finger + inertial(0.015, *tensor), joint="prismatic") + child("right", finger + inertial(0.015, *tensor), joint="prismatic")
    assert found(tmp_path, same, "I012") == []



def test_links_alike_only_in_their_placeholder_collision_are_not_copies(tmp_path):
    # uuv_simulator's RexROV: a magnetometer (a 10 cm box) and a camera (a mesh) each carry the
    # 1 µm cylinder that keeps Gazebo from dropping the link, and one pasted tensor
    (tmp_path / "camera.stl").write_text("solid c\nendsolid c\n")
    dot = '<collision><geometry><cylinder length="0.000001" radius="0.000001"/></geometry></collision>'
    tensor = (1e-5, 1e-5, 1e-5)
    magnetometer = '<visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual>' + dot + inertial(0.015, *tensor)
    camera = '<visual><geometry><mesh filename="camera.stl"/></geometry></visual>' + dot + inertial(0.1, *tensor)
    assert found(tmp_path, BASE + child("magnetometer", magnetometer) + child("camera", camera), "I012") == []
    # two copies of one part, dot and all, are still compared by their visuals
    twin = '<visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual>' + dot + inertial(0.1, *tensor)
    (code, _, message), = found(tmp_path, BASE + child("magnetometer", magnetometer) + child("twin", twin), "I012")
    assert "'magnetometer' (0.015 kg) and 'twin' (0.1 kg)" in message

# -- A.5: unit axes as parsers see them -----------------------------------------------------------
def test_an_axis_written_with_few_decimals_is_a_unit_axis(tmp_path):
    def axis(xyz: str) -> str:
        return child("arm", "", joint="revolute").replace('<axis xyz="0 0 1"/>', f'<axis xyz="{xyz}"/>')

    assert found(tmp_path, BASE + axis("0 0.999999 0"), "J011") == []  # NAO's six decimals
    assert found(tmp_path, BASE + axis("0.707 0.707 0"), "J011") == []
    assert [c for c, _, _ in found(tmp_path, BASE + axis("1 1 0"), "J011")] == ["J011"]


# -- B.6: what no consumer can simulate is an error ------------------------------------------------
def test_negative_mass_and_a_negative_moment_are_errors_that_fail_check(tmp_path):
    for bad in (inertial(-0.3, 0.01, 0.01, 0.01), inertial(1, 1, 0, 1, iyz=1)):
        path = tmp_path / "robot.urdf"
        path.write_text(f'<robot name="r">{BASE}{child("arm", bad, joint="revolute")}</robot>')
        done = run_cli("check", str(path))
        assert done.returncode == 1, done.stderr
        assert "I001 error" in done.stderr.decode() or "I005 error" in done.stderr.decode()
    path.write_text(f'<robot name="r">{BASE}{child("arm", inertial(0.3, 0.01, 0.01, 0.01), joint="revolute")}</robot>')
    assert run_cli("check", str(path)).returncode == 0


def test_a_negative_mass_is_not_called_none(tmp_path):
    negative = '<link name="base"/>' + child("arm", inertial(-0.3, 0.01, 0.01, 0.01), joint="revolute")
    (code, _, message), = found(tmp_path, negative, "I002")
    assert "has no positive mass (I001: a negative mass)" in message and "has none" not in message


# -- B.7: the CAD sign convention of the products of inertia ----------------------------------------
def test_products_of_inertia_of_the_other_sign_convention_are_said_so(tmp_path):
    # Allegro's link_3.0: invalid as written, valid with ixy, ixz, iyz negated
    flipped = inertial(0.0388, 4.70125e-06, 3.64931e-06, 4.70125e-06, ixy=1.25597e-06, ixz=1.2936e-06, iyz=1.7622e-06)
    diagnostics = [d for d in lint(tmp_path, BASE + child("tip", flipped, joint="revolute")) if d.code == "I006"]
    assert len(diagnostics) == 1 and "products of inertia negated it is valid" in diagnostics[0].message
    assert 'ixy="-1.25597e-06" ixz="-1.2936e-06"' in diagnostics[0].hint
    invalid = inertial(1, 0.001, 0.001, 0.01)  # invalid whatever the signs: no such note
    diagnostics = [d for d in lint(tmp_path, BASE + child("tip", invalid, joint="revolute")) if d.code == "I006"]
    assert len(diagnostics) == 1 and "negated" not in diagnostics[0].message and diagnostics[0].hint is None


# -- B.8: rpy in degrees ---------------------------------------------------------------------------------
def test_rpy_in_degrees_is_flagged_with_the_radians(tmp_path):
    turned = child("camera", "").replace("<axis", '<origin xyz="0 0 0.1" rpy="3.14159 0 180"/><axis')
    diagnostics = [d for d in lint(tmp_path, BASE + turned) if d.code == "V009"]
    assert len(diagnostics) == 1 and diagnostics[0].hint == 'in radians: rpy="3.14159 0 3.141593"'
    within = child("camera", "").replace("<axis", '<origin xyz="0 0 0.1" rpy="3.14159 0 -1.5708"/><axis')
    assert found(tmp_path, BASE + within, "V009") == []


# -- B.9: margins where the bound is loose ------------------------------------------------------------
def test_a_moment_a_little_over_the_box_bound_is_rounding_and_units_are_suggested_only_far_off(tmp_path):
    # a 1 kg body in a 0.1 m cube, centred: each moment at most 1 * (0.05² + 0.05²) = 0.005
    def over(factor: float):
        return [d for d in lint(tmp_path, BASE + child("part", box("0.1 0.1 0.1") + inertial(1, *[0.005 * factor] * 3), joint="revolute")) if d.code == "I009"]

    assert over(1.2) == []  # FR3's link2, UR3e's wrist_2: CAD rounding
    [near] = over(2.0)
    assert "(units?)" not in near.hint
    [far] = over(500.0)
    assert "(units?)" in far.hint


# -- B.11: ros2_control and limits ------------------------------------------------------------------------
def test_a_ros2_control_joint_naming_no_joint_is_an_error_in_check(tmp_path):
    control = ('<ros2_control name="arm" type="system"><hardware><plugin>mock_components/GenericSystem</plugin></hardware>'
               '<joint name="{}"><command_interface name="position"/></joint></ros2_control>')
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r">{BASE}{child("arm", "", joint="revolute")}{control.format("arm_jiont")}</robot>')
    done = run_cli("check", str(path))
    assert done.returncode == 1 and "D013 error: ros2_control 'arm' names joint 'arm_jiont', which does not exist" in done.stderr.decode()
    assert "did you mean 'arm_joint'?" in done.stderr.decode()
    path.write_text(f'<robot name="r">{BASE}{child("arm", "", joint="revolute")}{control.format("arm_joint")}</robot>')
    assert run_cli("check", str(path)).returncode == 0


def test_soft_limits_outside_the_hard_limits(tmp_path):
    def safety(lower: str, upper: str) -> str:
        return child("arm", "", joint="revolute", extra=f'<safety_controller soft_lower_limit="{lower}" soft_upper_limit="{upper}" k_velocity="10"/>')

    (code, severity, message), = found(tmp_path, BASE + safety("-1.2", "0.9"), "J015")
    assert severity == "warning" and "soft_lower_limit -1.2 is below lower -1" in message
    assert found(tmp_path, BASE + safety("-0.9", "0.9"), "J015") == []


def test_negative_damping_or_friction_is_an_error(tmp_path):
    def dynamics(damping: str) -> str:
        return child("arm", "", joint="continuous", extra=f'<dynamics damping="{damping}" friction="0.1"/>')

    assert [(c, s) for c, s, _ in found(tmp_path, BASE + dynamics("-0.5"), "V010")] == [("V010", "error")]
    assert found(tmp_path, BASE + dynamics("0.5"), "V010") == []


# -- C.12-19: first contact --------------------------------------------------------------------------------
XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
TRIANGLE = '<inertial><mass value="1"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="{izz}"/></inertial>'


def write(folder, name: str, text: str):
    path = folder / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def lint_concise(*args: str, cwd):
    done = run_cli("lint", "--format", "concise", "--isolated", "--select", "ALL", *args, cwd=cwd)
    return done, done.stdout.decode().splitlines()


def part_model(izz: str, heavy: str = "true") -> str:
    return (f'<robot name="r" {XACRO_NS}><xacro:include filename="part.xacro"/><link name="base"/>'
            f'<xacro:part name="a" heavy="{heavy}" izz="{izz}"/></robot>')


PART = f'''<robot {XACRO_NS}>
  <xacro:macro name="part" params="name heavy izz">
    <link name="${{name}}">
      <xacro:if value="${{heavy}}">
        <!-- urdfcli: noqa: I006 -->
        {TRIANGLE.format(izz="${izz}")}
      </xacro:if>
    </link>
    <joint name="${{name}}_joint" type="fixed"><parent link="base"/><child link="${{name}}"/></joint>
  </xacro:macro>
</robot>
'''


def test_a_noqa_in_a_macro_is_useless_only_when_useless_at_every_call(tmp_path):
    write(tmp_path, "part.xacro", PART)
    write(tmp_path, "breaks.urdf.xacro", part_model("0.01"))  # the noqa silences I006 here
    write(tmp_path, "fits.urdf.xacro", part_model("0.001"))  # and nothing here
    write(tmp_path, "light.urdf.xacro", part_model("0.01", heavy="false"))  # the element is never made here
    _, both = lint_concise("breaks.urdf.xacro", "fits.urdf.xacro", cwd=tmp_path)
    assert not [line for line in both if "U001" in line or "I006" in line]
    _, alone = lint_concise("fits.urdf.xacro", cwd=tmp_path)
    assert [line.split(": ")[1] for line in alone if "U001" in line] == ["U001 info"]  # useless for the only model that uses it
    _, never = lint_concise("light.urdf.xacro", cwd=tmp_path)
    assert not [line for line in never if "U001" in line]


def test_messages_name_files_relative_to_the_working_directory(tmp_path):
    body = '<link name="base"/><xacro:macro name="w"><link name="wheel"/></xacro:macro><xacro:w/><xacro:w/>'
    path = write(tmp_path, "dup.urdf.xacro", f'<robot name="r" {XACRO_NS}>{body}</robot>')
    done = run_cli("lint", str(path), cwd=tmp_path)
    assert "dup.urdf.xacro:1:" in done.stdout.decode() and str(tmp_path) not in done.stdout.decode()


def test_a_name_defined_by_two_macro_calls_shows_both_calls(tmp_path):
    wheel = ('<xacro:macro name="wheel"><link name="wheel"/><joint name="wheel_joint" type="continuous"><parent link="base"/>'
             '<child link="wheel"/><axis xyz="0 1 0"/></joint></xacro:macro>')
    lines = f'<robot name="r" {XACRO_NS}>\n{wheel}\n<link name="base"/>\n<xacro:wheel/>\n<xacro:wheel/>\n</robot>\n'
    write(tmp_path, "twice.urdf.xacro", lines)
    done = run_cli("check", "--format", "json", "twice.urdf.xacro", cwd=tmp_path)
    found = {d["code"]: d for d in json.loads(done.stdout)["files"][0]["diagnostics"]}
    for code in ("N004", "N005"):
        assert found[code]["trace"][0]["line"] == 5  # the second call
        assert found[code]["hint"].startswith("first defined at twice.urdf.xacro:2 (in macro 'wheel' called at twice.urdf.xacro:4:1); ")
        assert "prefix parameter" in found[code]["hint"]
    plain = '<robot name="r"><link name="base"/><link name="a"/><joint name="j" type="fixed"><parent link="base"/><child link="a"/></joint>\n<joint name="j" type="fixed"><parent link="base"/><child link="a"/></joint></robot>'
    write(tmp_path, "plain.urdf", plain)
    [n005] = [d for d in json.loads(run_cli("check", "--format", "json", "plain.urdf", cwd=tmp_path).stdout)["files"][0]["diagnostics"] if d["code"] == "N005"]
    assert n005["hint"] == "first defined at plain.urdf:1; rename one of them"


def test_a_material_defined_twice_by_a_file_included_twice_says_so(tmp_path):
    # aubo_description: materials.xacro is included by aubo.gazebo.xacro and by the model itself;
    # urdfdom refuses the second 'black', at the one line that defines it
    write(tmp_path, "materials.xacro", f'<robot {XACRO_NS}>\n<material name="black"><color rgba="0 0 0 1"/></material>\n</robot>\n')
    write(tmp_path, "gazebo.xacro", f'<robot {XACRO_NS}>\n<xacro:include filename="materials.xacro"/>\n</robot>\n')
    model = f'<robot name="r" {XACRO_NS}>\n<xacro:include filename="gazebo.xacro"/>\n<xacro:include filename="materials.xacro"/>\n<link name="a"/>\n</robot>\n'
    write(tmp_path, "robot.urdf.xacro", model)
    done = run_cli("check", "--format", "json", "robot.urdf.xacro", cwd=tmp_path)
    [n006] = [d for d in json.loads(done.stdout)["files"][0]["diagnostics"] if d["code"] == "N006"]
    assert (n006["path"], n006["line"]) == ("materials.xacro", 2)
    assert n006["hint"] == "first defined at materials.xacro:2; materials.xacro is included twice: include it once"


def test_a_part_two_included_files_define_says_to_include_one_of_them(tmp_path):
    # articubot_one: camera.xacro and depth_camera.xacro each write camera_joint and camera_link,
    # alternatives of which the model should include one; renaming would make two cameras
    part = '<robot {ns}>\n<joint name="camera_joint" type="fixed"><parent link="base"/><child link="camera_link"/></joint>\n<link name="camera_link"/>\n</robot>\n'
    write(tmp_path, "camera.xacro", part.format(ns=XACRO_NS))
    write(tmp_path, "depth_camera.xacro", part.format(ns=XACRO_NS))
    model = f'<robot name="r" {XACRO_NS}>\n<link name="base"/>\n<xacro:include filename="camera.xacro"/>\n<xacro:include filename="depth_camera.xacro"/>\n</robot>\n'
    write(tmp_path, "robot.urdf.xacro", model)
    done = run_cli("check", "--format", "json", "robot.urdf.xacro", cwd=tmp_path)
    found = {d["code"]: d for d in json.loads(done.stdout)["files"][0]["diagnostics"]}
    assert (found["N005"]["path"], found["N005"]["line"]) == ("depth_camera.xacro", 2)
    assert found["N005"]["hint"] == (
        "first defined at camera.xacro:2; depth_camera.xacro defines it again: include only one of camera.xacro and depth_camera.xacro, or rename one of them"
    )
    assert found["N004"]["hint"].startswith("first defined at camera.xacro:3; depth_camera.xacro defines it again: ")


def test_an_attribute_written_on_its_own_line_is_pointed_at(tmp_path):
    joint = ('<link name="base"/><link name="arm"/><joint name="j" type="revolute"><parent link="base"/><child link="arm"/>'
             '<axis xyz="0 0 1"/>\n<limit\n    lower="-1"\n    upper="1,5"\n    effort="1" velocity="1"/></joint>')
    write(tmp_path, "ml.urdf", f'<robot name="r">{joint}</robot>')
    done = run_cli("check", "ml.urdf", cwd=tmp_path)
    err = done.stderr.decode()
    assert "ml.urdf:4:5: V001 error: limit upper: '1,5' is not a number" in err
    assert '     4 |     upper="1,5"\n       |     ^' in err
    fine = write(tmp_path, "fine.urdf", f'<robot name="r">{joint.replace("1,5", "1.5")}</robot>')
    assert "V001" not in run_cli("check", str(fine)).stderr.decode()


def test_package_paths_are_listed_once_and_a_missing_named_folder_is_an_error(tmp_path):
    model = write(tmp_path, "m.urdf.xacro", f'<robot name="r" {XACRO_NS}><xacro:include filename="$(find nopkg)/x.xacro"/></robot>')
    done = run_cli("check", "-P", str(tmp_path), "-P", f"{tmp_path}/", str(model))
    assert f"(looked in {tmp_path})" in done.stderr.decode()
    missing = run_cli("check", "-P", f"nopkg={tmp_path / 'nowhere'}", str(model))
    assert missing.returncode == 2
    assert missing.stderr.decode() == f"urdfcli: --package-path 'nopkg={tmp_path / 'nowhere'}': '{tmp_path / 'nowhere'}' is not a directory\n"


def mesh_model(package: str) -> str:
    return (f'<robot name="r"><link name="base"><visual><geometry><mesh filename="package://{package}/meshes/base.stl"/></geometry>'
            '</visual></link></robot>')


def test_a_package_name_that_the_build_registers_is_never_called_a_typo(tmp_path):
    # folder acme_description, package.xml says acme; CMakeLists.txt's project(acme_description) installs it as acme_description
    package = tmp_path / "ws" / "src" / "acme_description"
    write(package, "package.xml", '<package format="3"><name>acme</name></package>')
    model = write(package, "urdf/robot.urdf", mesh_model("acme_description"))
    write(package, "CMakeLists.txt", "cmake_minimum_required(VERSION 3.8)\nproject(acme_description)\n")
    hint = next(d.hint for d in lint_file(model, Config.everything()).diagnostics if d.code == "D005")
    assert "installs as 'acme_description'" in hint and "write package://acme/" not in hint
    (package / "CMakeLists.txt").write_text("project(acme)\n")  # the build registers acme: the URI is wrong
    hint = next(d.hint for d in lint_file(model, Config.everything()).diagnostics if d.code == "D005")
    assert "write package://acme/" in hint
    # once built, the install space's ament index resolves it
    install = tmp_path / "ws" / "install" / "acme"
    write(install, "share/ament_index/resource_index/packages/acme_description", "")
    write(install, "share/acme_description/meshes/base.stl", "solid x\nendsolid x\n")
    assert [d for d in lint_file(model, Config.everything()).diagnostics if d.code == "D005"] == []


def test_libraries_share_one_checked_through_line_and_quiet_keeps_only_diagnostics(tmp_path):
    repository = make_repository(tmp_path / "acme_robots")
    (repository / ".git").mkdir()
    libraries = ("common/urdf/wheel.xacro", "common/urdf/inertia.xacro")
    err = run_cli("check", *libraries, cwd=repository).stderr.decode()
    assert err.count("checked through") == 1
    assert "2 xacro libraries, checked through description/urdf/arm.urdf.xacro [arm_type:=small], " in err
    model = "description/urdf/rover.urdf.xacro"
    loud = run_cli("check", model, *libraries, cwd=repository)
    quiet = run_cli("check", "--quiet", model, *libraries, cwd=repository)
    assert loud.stdout.decode().startswith("==> ") and quiet.stdout == b""  # no tree
    assert quiet.stderr.decode().splitlines() == ["3 files checked: 0 errors, 0 warnings"]
    edit(repository / "common/urdf/wheel.xacro", '<axis xyz="0 0 1"/>', '<axis xyz="0 0 2"/>')
    quiet = run_cli("lint", "-q", "--format", "concise", *libraries, cwd=repository)
    assert "checked through" not in quiet.stderr.decode() and "J011" in quiet.stdout.decode()


def test_a_diagnostic_in_a_library_names_its_model_in_every_format(tmp_path):
    repository = make_repository(tmp_path / "acme_robots")
    (repository / ".git").mkdir()
    edit(repository / "common/urdf/wheel.xacro", '<axis xyz="0 0 1"/>', '<axis xyz="0 0 2"/>')
    args = ("--isolated", "--select", "J011", "common/urdf/wheel.xacro", "description/urdf/rover.urdf.xacro")

    def lint_as(fmt: str) -> str:
        return run_cli("lint", "--format", fmt, *args, cwd=repository).stdout.decode()

    model = "description/urdf/rover.urdf.xacro"
    text, concise = lint_as("text"), lint_as("concise")
    assert "J011" in text and "J011" in concise
    # the library's result: the model whose expansion found it, unless its call in that model says so already
    [entry] = [f for f in json.loads(lint_as("json"))["files"] if f["path"] == "common/urdf/wheel.xacro"]
    [found] = entry["diagnostics"]
    named = found["model"] == model or any(call["path"] == model for call in found["trace"])
    assert named
    assert model in concise.splitlines()[0] and model in lint_as("github").splitlines()[0]
    sarif = json.loads(lint_as("sarif"))["runs"][0]["results"][0]
    assert model in json.dumps(sarif)


def test_check_urdf_format_prints_the_tree_whenever_check_urdf_does(tmp_path):
    path = tmp_path / "negative.urdf"
    path.write_text(f'<robot name="r">{BASE}{child("arm", inertial(-0.3, 0.001, 0.001, 0.001), joint="revolute")}</robot>')
    real = subprocess.run([require_tool("check_urdf"), str(path)], capture_output=True, text=True)
    assert real.returncode == 0  # urdfdom does not check the sign of a mass
    mine = run_cli("check", "--format", "check_urdf", str(path))
    assert mine.stdout.decode() == real.stdout
    assert mine.returncode == 1 and " I001 error: " in mine.stderr.decode()
