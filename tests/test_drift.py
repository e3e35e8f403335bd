"""Rule X110: a committed URDF that no longer matches the xacro file it was generated from,
on packages built as the public ones are (tests/generated_repos.py), and the cases that are
not drift: a header naming another machine's path, a URDF written another way."""

from __future__ import annotations

import re

import pytest
from conftest import lint_file, run_cli
from generated_repos import KUKA_TOOL_NOW, generate, kuka_macro, kuka_package, motoman_package
from ros_workspace import edit

from urdfcli.project.drift import header_source, regenerated


def x110(result):
    return [d for d in result.diagnostics if d.code == "X110"]


def test_kuka_urdf_lacks_the_flange_link_its_xacro_makes_now(tmp_path, monkeypatch):
    package = kuka_package(tmp_path)
    monkeypatch.chdir(package / "urdf")
    (found,) = x110(lint_file("kr16_2.urdf"))
    assert (found.path, found.line, found.column, found.severity.value) == ("kr16_2.urdf", 1, 1, "warning")
    assert found.message == (
        "kr16_2.urdf does not match kr16_2.xacro, which generated it: it lacks link 'flange' and joints "
        "'joint_a6-flange', 'flange-tool0' that kr16_2.xacro makes; it has joint 'joint_a6-tool0' that kr16_2.xacro does not make"
    )
    assert found.hint == "regenerate it: urdfcli expand kr16_2.xacro -o kr16_2.urdf, or `urdfcli diff kr16_2.urdf kr16_2.xacro` lists every difference"
    # check reports it too
    done = run_cli("check", "kr16_2.urdf", "--format", "concise", cwd=package / "urdf")
    assert "kr16_2.urdf:1:1: X110 warning: kr16_2.urdf does not match kr16_2.xacro" in done.stdout.decode() + done.stderr.decode()


def test_kuka_urdf_generated_from_the_current_sources_is_no_drift(tmp_path, monkeypatch):
    package = kuka_package(tmp_path, generated_with_flange=True)
    monkeypatch.chdir(package / "urdf")
    assert x110(lint_file("kr16_2.urdf")) == []


def test_a_changed_limit_is_summarised_with_its_values(tmp_path, monkeypatch):
    package = kuka_package(tmp_path, generated_with_flange=True)
    edit(package / "urdf" / "kr16_2_macro.xacro", "upper=\"${radians(35)}\"", "upper=\"${radians(40)}\"")
    monkeypatch.chdir(package / "urdf")
    (found,) = x110(lint_file("kr16_2.urdf"))
    assert found.message == (
        "kr16_2.urdf does not match kr16_2.xacro, which generated it: 1 joint differs "
        "(joint 'joint_a2' limit upper: 0.610865 here, 0.698132 in kr16_2.xacro)"  # radians(35) and radians(40), readable
    )


def test_motoman_materials_renamed_since_the_urdf_was_generated(tmp_path, monkeypatch):
    package = motoman_package(tmp_path)
    monkeypatch.chdir(package / "urdf")
    (found,) = x110(lint_file("sia10d.urdf"))
    assert found.message == (
        "sia10d.urdf does not match sia10d.xacro, which generated it: it calls material 'blue' what sia10d.xacro "
        "calls 'motoman_blue' and 1 more"
    )
    # the colours are the same: no visual changed colour, only the names did (a collision's material
    # is no material: urdfdom reads none there)
    difference = run_cli("diff", "sia10d.urdf", "sia10d.xacro", "--format", "json", cwd=package / "urdf")
    assert difference.returncode == 1
    import json

    changes = json.loads(difference.stdout)["changes"]
    assert {(c["kind"], c["element"], c["old"], c["new"]) for c in changes} == {
        ("renamed", "material[@name='motoman_blue']", "blue", "motoman_blue"),
        ("renamed", "material[@name='motoman_silver']", "silver", "motoman_silver"),
    }


def test_header_naming_the_generating_machines_path_and_reformatted_urdf_is_no_drift(tmp_path, monkeypatch):
    """A URDF generated from the same sources on another machine (the header names its absolute path),
    then reformatted: attributes reordered, numbers written another way, comments and indentation."""
    package = kuka_package(tmp_path, generated_with_flange=True)
    urdf = package / "urdf" / "kr16_2.urdf"
    text = generate(package / "urdf" / "kr16_2.xacro", "/home/ros/catkin_ws/src/kuka_experimental/kuka_kr16_support/urdf/kr16_2.xacro")
    text = text.replace('<origin rpy="0 0 0" xyz="0 0 0.675"/>', '<!-- A1 -->\n\t<origin xyz="0.0 0.0 0.6750"  rpy="0 0 0" />')
    text = text.replace('<mass value="2"/>', '<mass value="2.000"/>').replace('ixx="0.01"', 'ixx="1e-2"')
    text = text.replace('rpy="0 1.5707963267948966 0"', 'rpy="0 1.57079632679 0"')  # radians(90) as the public URDF writes it
    urdf.write_text(text)
    assert "0.6750" in urdf.read_text() and "1.57079632679 0" in urdf.read_text()
    monkeypatch.chdir(package / "urdf")
    assert x110(lint_file("kr16_2.urdf")) == []



@pytest.mark.parametrize("written, drifted", [("1.5708", False), ("1.570796", False), ("1.57", True)])
def test_a_rotation_rounded_by_hand_is_no_drift_and_one_rounded_coarsely_is(tmp_path, monkeypatch, written, drifted):
    """ROS-Industrial's motoman sia20d.urdf writes the tool0 turn its macro computes as 3.1415926535 as
    3.1416 (7 microradians, 0.0004 degrees): the same robot. 1.57 for pi/2 is 0.046 degrees off: a change."""
    package = kuka_package(tmp_path, generated_with_flange=True)
    urdf = package / "urdf" / "kr16_2.urdf"
    urdf.write_text(urdf.read_text().replace('rpy="0 1.5707963267948966 0"', f'rpy="0 {written} 0"'))
    assert written in urdf.read_text()
    monkeypatch.chdir(package / "urdf")
    found = x110(lint_file("kr16_2.urdf"))
    assert bool(found) == drifted
    if drifted:
        assert found[0].message.endswith(f"origin rpy: 0 {written} 0 here, 0 1.5708 0 in kr16_2.xacro)")

def test_source_is_found_in_the_package_when_not_beside_the_urdf(tmp_path, monkeypatch):
    package = kuka_package(tmp_path)
    (package / "robots").mkdir()
    (package / "urdf" / "kr16_2.urdf").rename(package / "robots" / "kr16_2.urdf")
    monkeypatch.chdir(package)
    (found,) = x110(lint_file("robots/kr16_2.urdf"))
    assert found.message.startswith("kr16_2.urdf does not match urdf/kr16_2.xacro, which generated it: it lacks link 'flange'")


def test_a_xacro_of_the_same_name_beside_a_urdf_without_header(tmp_path, monkeypatch):
    package = kuka_package(tmp_path, generated_with_flange=True)
    urdf = package / "urdf" / "kr16_2.urdf"
    urdf.write_text(re.sub(r"<!--.*?-->\n", "", urdf.read_text(), flags=re.DOTALL).replace('<mass value="2"/>', '<mass value="2.5"/>', 1))
    monkeypatch.chdir(package / "urdf")
    (found,) = x110(lint_file("kr16_2.urdf"))
    assert found.message == (
        "kr16_2.urdf does not match kr16_2.xacro, beside it: 1 link differs (link 'base_link' inertial mass: 2.5 here, 2 in kr16_2.xacro)"
    )


def test_an_argument_that_may_explain_the_difference_is_named(tmp_path, monkeypatch):
    """Generated with prefix:=left_ from a model whose argument's default is '': every link is
    renamed, and the hint says the defaults were used and which argument is read there."""
    package = kuka_package(tmp_path, generated_with_flange=True)
    model = package / "urdf" / "kr16_2.xacro"
    edit(model, '<xacro:kuka_kr16_2 prefix=""/>', '<xacro:arg name="prefix" default=""/>\n  <xacro:kuka_kr16_2 prefix="$(arg prefix)"/>')
    (package / "urdf" / "kr16_2.urdf").write_text(generate(model, "kr16_2.xacro", prefix="left_"))
    monkeypatch.chdir(package / "urdf")
    (found,) = x110(lint_file("kr16_2.urdf"))
    assert found.message.startswith("kr16_2.urdf does not match kr16_2.xacro, which generated it: it calls link 'left_base_link' what kr16_2.xacro calls 'base_link' and ")
    assert found.hint == (
        "regenerate it: urdfcli expand kr16_2.xacro -o kr16_2.urdf (it was expanded with the arguments' defaults; "
        "the URDF may have been generated with other values of prefix:='': `urdfcli diff kr16_2.urdf kr16_2.xacro` shows what differs; "
        "regenerate it with the values it was made with)"
    )


OMX = """<?xml version="1.0"?>
<robot name="omx" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <xacro:arg name="use_gazebo" default="true"/>
  <xacro:macro name="arm" params="prefix">
    <link name="${prefix}link0"/>
    <link name="${prefix}link1"/>
    <joint name="${prefix}joint1" type="revolute">
      <parent link="${prefix}link0"/><child link="${prefix}link1"/>
      <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>
    </joint>
  </xacro:macro>
  <xacro:macro name="arm_gazebo" params="prefix">
    <gazebo reference="${prefix}link0"><material>Gazebo/Grey</material></gazebo>
  </xacro:macro>
  <xacro:macro name="arm_control" params="name prefix">
    <ros2_control name="${name}" type="system"><joint name="${prefix}joint1"/></ros2_control>
  </xacro:macro>
  <xacro:arm prefix="$(arg prefix)"/>
  <xacro:arm_control name="OMXSystem" prefix="$(arg prefix)"/>
  <xacro:if value="$(arg use_gazebo)">
    <xacro:arm_gazebo prefix="$(arg prefix)"/>
  </xacro:if>
</robot>
"""


SIM = """<?xml version="1.0"?>
<robot name="omx" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="use_sim" default="false"/>
  <xacro:arg name="port_name" default="/dev/ttyUSB0"/>
  <xacro:macro name="arm_system" params="name port_name">
    <ros2_control name="${name}" type="system">
      <xacro:if value="$(arg use_sim)">
        <hardware><plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>
      </xacro:if>
      <xacro:unless value="$(arg use_sim)">
        <hardware>
          <plugin>dynamixel_hardware_interface/DynamixelHardware</plugin>
          <param name="port_name">${port_name}</param>
        </hardware>
      </xacro:unless>
      <joint name="joint1"><command_interface name="position"/></joint>
      <xacro:if value="$(arg use_sim)">
        <joint name="gripper_right_joint"><state_interface name="position"/></joint>
      </xacro:if>
    </ros2_control>
  </xacro:macro>
  <link name="link0"/>
  <link name="link1"/>
  <joint name="joint1" type="revolute">
    <parent link="link0"/><child link="link1"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="gripper_right_joint" type="fixed"><parent link="link1"/><child link="tip"/></joint>
  <link name="tip"/>
  <xacro:arm_system name="OMXSystem" port_name="$(arg port_name)"/>
</robot>
"""


def test_a_ros2_control_part_made_under_a_condition_is_said_present_and_its_condition_named(tmp_path, monkeypatch):
    """open_manipulator's omx.urdf generated with use_sim:=true has a ros2_control joint the
    defaults do not make: the summary said '(none) here, (none) in omx.urdf.xacro' of its joint, and the
    hint blamed port_name (read by a <param> the URDF lacks) instead of use_sim."""
    model = tmp_path / "omx.urdf.xacro"
    model.write_text(SIM)
    (tmp_path / "omx.urdf").write_text(generate(model, "omx.urdf.xacro", use_sim="true"))
    monkeypatch.chdir(tmp_path)
    (found,) = x110(lint_file("omx.urdf"))
    # of the parts that differ, one with a value is named: the plugin says which mode made it
    assert found.message.endswith(
        "(ros2_control 'OMXSystem' hardware/plugin: gz_ros2_control/GazeboSimSystem here, dynamixel_hardware_interface/DynamixelHardware in omx.urdf.xacro)"
    )
    assert "other values of use_sim:='false'" in found.hint and "port_name" not in found.hint
    assert found.fix.reason == "it may have been generated with other values of use_sim: regenerate it by hand with those"


def test_an_argument_passed_to_a_call_does_not_explain_an_element_always_made(tmp_path, monkeypatch):
    """open_manipulator's omx_f.urdf lacks the <gazebo> blocks and ros2_control its xacro always
    makes, with the names prefix:='' gives: the hint blamed prefix (read on the calls' lines)
    and no fix was offered. No value of prefix makes them or not: the plain hint, and the fix."""
    model = tmp_path / "omx.urdf.xacro"
    model.write_text(OMX)
    text = generate(model, "omx.urdf.xacro", use_gazebo="false")
    text = re.sub(r"\s*<ros2_control .*?</ros2_control>", "", text, flags=re.DOTALL)
    assert "<gazebo" not in text and "ros2_control" not in text
    (tmp_path / "omx.urdf").write_text(text)
    monkeypatch.chdir(tmp_path)
    (found,) = x110(lint_file("omx.urdf"))
    assert found.message.endswith("it lacks ros2_control 'OMXSystem' and the <gazebo> block for 'link0' that omx.urdf.xacro makes")
    # the gazebo block is made under $(arg use_gazebo): that argument may explain it; prefix explains nothing
    assert "other values of use_gazebo:='true'" in found.hint and "prefix" not in found.hint
    assert found.fix.reason == "it may have been generated with other values of use_gazebo: regenerate it by hand with those"
    # only the ros2_control block missing: nothing the arguments decide
    (tmp_path / "omx.urdf").write_text(generate(model, "omx.urdf.xacro").replace("<ros2_control", "<!--").replace("</ros2_control>", "-->"))
    (found,) = x110(lint_file("omx.urdf"))
    assert found.message.endswith("it lacks ros2_control 'OMXSystem' that omx.urdf.xacro makes")
    assert found.hint == "regenerate it: urdfcli expand omx.urdf.xacro -o omx.urdf, or `urdfcli diff omx.urdf omx.urdf.xacro` lists every difference"
    assert found.fix.reason is None and found.fix.edits


def test_a_source_that_does_not_expand_is_said_as_info(tmp_path, monkeypatch):
    package = kuka_package(tmp_path, generated_with_flange=True)
    edit(package / "urdf" / "kr16_2.xacro", '<xacro:kuka_kr16_2 prefix=""/>', '<xacro:kuka_kr16_2 prefix="$(arg prefix)"/>')
    monkeypatch.chdir(package / "urdf")
    (found,) = x110(lint_file("kr16_2.urdf"))
    assert found.severity.value == "info"
    assert found.message == (
        "kr16_2.urdf says it was generated from kr16_2.xacro, which was not compared: its expansion needs xacro "
        "argument 'prefix'; give it in [tool.urdfcli.xacro-args]"
    )


def test_drift_fails_for_a_urdf_it_could_not_compare(tmp_path):
    """Unitree's go1.urdf, generated from robot.xacro, which needs xacro argument DEBUG: without it
    in the configuration, drift said (info) it could not compare them and exited 0, its help
    saying "Exit 0 when every generated URDF matches its source"; given, they differ. drift now
    says it as a warning and fails; check and lint keep the info."""
    package = kuka_package(tmp_path, generated_with_flange=True)
    edit(package / "urdf" / "kr16_2.xacro", '<xacro:kuka_kr16_2 prefix=""/>', '<xacro:kuka_kr16_2 prefix="$(arg prefix)"/>')
    done = run_cli("drift", "--format", "concise", cwd=package)
    out = done.stdout.decode()
    assert done.returncode == 1, out + done.stderr.decode()
    assert out.startswith("urdf/kr16_2.urdf:1:1: X110 warning: kr16_2.urdf says it was generated from urdf/kr16_2.xacro, which was not "
                          "compared: its expansion needs xacro argument 'prefix'; give it in [tool.urdfcli.xacro-args]"), out
    done = run_cli("lint", "--format", "concise", "--select", "X110", "urdf/kr16_2.urdf", cwd=package)
    assert (done.returncode, "X110 info" in done.stdout.decode()) == (0, True), done.stdout.decode()
    # given the argument, the two are compared, and match
    (package / "urdfcli.toml").write_text('[xacro-args]\n"urdf/kr16_2.xacro" = { prefix = "" }\n')
    done = run_cli("drift", cwd=package)
    assert (done.returncode, "X110" in done.stdout.decode()) == (0, False), done.stdout.decode()


def test_a_source_listed_in_models_is_compared_with_its_first_argument_set(tmp_path):
    """A UR + gripper cell names its model's arguments (the YAML files ur_control.launch.py
    passes) in [models], as the README says of models that need arguments: drift said its
    source "does not expand", as if none were given, where expand reads it with them."""
    package = kuka_package(tmp_path, generated_with_flange=True)
    edit(package / "urdf" / "kr16_2.xacro", '<xacro:kuka_kr16_2 prefix=""/>', '<xacro:kuka_kr16_2 prefix="$(arg prefix)"/>')
    (package / "urdfcli.toml").write_text('[models]\n"urdf/kr16_2.xacro" = [["prefix:="], ["prefix:=left_"]]\n')
    done = run_cli("drift", cwd=package)
    assert (done.returncode, "X110" in done.stdout.decode()) == (0, False), done.stdout.decode()
    done = run_cli("lint", "--format", "concise", "--select", "X110", "urdf/kr16_2.urdf", cwd=package)
    assert (done.returncode, done.stdout.decode()) == (0, ""), done.stdout.decode()


def test_no_generated_urdf_no_diagnostic(tmp_path):
    (tmp_path / "robot.urdf").write_text('<robot name="r"><link name="base_link"/></robot>\n')
    assert x110(lint_file(tmp_path / "robot.urdf")) == []


def test_the_rule_can_be_ignored(tmp_path, monkeypatch):
    package = kuka_package(tmp_path)
    (package / "pyproject.toml").write_text('[tool.urdfcli]\nignore = ["X110"]\n')
    done = run_cli("lint", "urdf/kr16_2.urdf", "--format", "concise", cwd=package)
    assert "X110" not in done.stdout.decode()


def test_drift_command_finds_the_urdfs_generated_from_a_changed_library(tmp_path):
    """What the pre-commit hook runs: given the macro file that changed, the URDF generated from
    the model that includes it is checked."""
    package = kuka_package(tmp_path)
    done = run_cli("drift", "urdf/kr16_2_macro.xacro", cwd=package)
    out = done.stdout.decode()
    assert done.returncode == 1, out + done.stderr.decode()
    assert out.startswith("urdf/kr16_2.urdf:1:1: X110 warning: kr16_2.urdf does not match urdf/kr16_2.xacro, which generated it: it lacks link 'flange'")
    assert out.rstrip().endswith("1 file checked: 0 errors, 1 warning")
    # a xacro file no generated URDF comes from: nothing to check
    (package / "urdf" / "other.xacro").write_text(f'<robot name="o" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="a"/></robot>\n')
    done = run_cli("drift", "urdf/other.xacro", cwd=package)
    assert (done.returncode, done.stdout, done.stderr) == (0, b"", b"")
    # the safe fixes leave it alone: regenerating it changes the robot, and would drop an edit made to the URDF
    urdf = package / "urdf" / "kr16_2.urdf"
    before = urdf.read_text()
    header = before.split("<robot", 1)[0]
    done = run_cli("lint", "--fix", "--select", "X110", "urdf/kr16_2.urdf", cwd=package)
    assert re.search(r"^0 fixed, 1 remaining", done.stdout.decode(), re.M) and urdf.read_text() == before, done.stdout.decode()
    assert "X110 warning" in done.stdout.decode()
    # fixed with the unsafe fixes: the URDF regenerated keeping its header
    done = run_cli("lint", "--fix", "--unsafe-fixes", "--select", "X110", "urdf/kr16_2.urdf", cwd=package)
    assert re.search(r"^1 fixed, 0 remaining", done.stdout.decode(), re.M), done.stdout.decode()
    text = urdf.read_text()
    assert text.split("<robot", 1)[0] == header and '<link name="flange"/>' in text
    done = run_cli("lint", "--fix", "--unsafe-fixes", "--select", "X110", "urdf/kr16_2.urdf", cwd=package)
    assert re.search(r"^0 fixed, 0 remaining", done.stdout.decode(), re.M) and urdf.read_text() == text  # nothing left to fix
    done = run_cli("drift", cwd=package)
    assert done.returncode == 0, done.stdout.decode()
    assert "1 file checked: 0 errors, 0 warnings" in done.stdout.decode()


def test_regenerated_keeps_the_header_and_takes_the_new_robot(tmp_path):
    package = kuka_package(tmp_path)
    urdf = (package / "urdf" / "kr16_2.urdf").read_text()
    expanded = generate(package / "urdf" / "kr16_2.xacro", "/elsewhere/kr16_2.xacro")
    text = regenerated(urdf, expanded)
    assert text.split("<robot", 1)[0] == urdf.split("<robot", 1)[0]
    assert header_source(text.encode()) == "kr16_2.xacro"
    assert text.split("<robot", 1)[1] == expanded.split("<robot", 1)[1]
    assert '<link name="flange"/>' in text


@pytest.mark.parametrize(
    ("head", "source"),
    [
        ("<!-- |    This document was autogenerated by xacro from kr16_2.xacro                   | -->", "kr16_2.xacro"),
        ("<!-- |    This document was autogenerated by xacro from /opt/ws/src/p/urdf/a.urdf.xacro | -->", "/opt/ws/src/p/urdf/a.urdf.xacro"),
        ("<!-- This document was autogenerated by xacro from urdf/panda.urdf.xacro|-->", "urdf/panda.urdf.xacro"),
        ("<!-- written by hand -->", None),
    ],
)
def test_header_source(head, source):
    assert header_source(f'<?xml version="1.0"?>\n{head}\n<robot name="r"/>\n'.encode()) == source


def test_kuka_macro_fixture_builds_the_flange_as_public_kuka_does():
    assert '<link name="${prefix}flange"/>' in kuka_macro(KUKA_TOOL_NOW)


def test_a_urdf_whose_named_source_is_gone_is_said_not_compared(tmp_path):
    """abb_irb2400_support's irb2400.urdf: its header names irb2400.xacro, which the package no
    longer has. drift asked about it says it cannot compare it, and fails (it cannot say the URDF
    matches its source); check and lint, which run X110 on every URDF, say nothing of it."""
    package = tmp_path / "abb_irb2400_support"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text('<package format="2"><name>abb_irb2400_support</name></package>\n')
    (package / "urdf" / "irb2400.urdf").write_text(
        '<?xml version="1.0" ?>\n<!-- | This document was autogenerated by xacro from irb2400.xacro | -->\n'
        '<robot name="irb2400"><link name="base_link"/></robot>\n')
    done = run_cli("drift", "urdf/irb2400.urdf", cwd=package)
    assert done.returncode == 1
    assert done.stdout.decode().startswith("urdf/irb2400.urdf:1:1: X110 warning: irb2400.urdf says it was generated from irb2400.xacro, "
                                           "which is neither beside it nor in its package: not compared")
    done = run_cli("lint", "--isolated", "urdf/irb2400.urdf", cwd=package)
    assert "X110" not in done.stdout.decode()


def test_a_colour_the_urdf_lacks_is_said_by_its_value(tmp_path):
    """kuka_experimental's kr16.urdf has no colour where kuka_resources' macro writes
    <material name=""><color rgba="${246/255} ..."/>: the summary said '(none) here,  in kr16.xacro'."""
    urdf_dir = tmp_path / "urdf"
    urdf_dir.mkdir()
    source = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
              '  <link name="base_link"><visual><geometry><box size="1 1 1"/></geometry>'
              '<material name=""><color rgba="${246/255} ${120/255} ${40/255} 1"/></material></visual></link>\n</robot>\n')
    (urdf_dir / "r.xacro").write_text(source)
    (urdf_dir / "r.urdf").write_text('<?xml version="1.0" ?>\n<!-- | This document was autogenerated by xacro from r.xacro | -->\n'
                                     '<robot name="r">\n  <link name="base_link"><visual><geometry><box size="1 1 1"/></geometry></visual></link>\n</robot>\n')
    done = run_cli("drift", "--format", "concise", "urdf/r.urdf", cwd=tmp_path)
    out = done.stdout.decode()
    assert done.returncode == 1, out
    assert "1 link differs (link 'base_link' visual material colour: (none) here, 0.964706 0.470588 0.156863 1 in r.xacro)" in out


def test_the_summary_names_the_difference_that_moves_the_robot_and_says_gazebo_blocks_plainly(tmp_path):
    """fanuc's lrmate200id.urdf: a base colour differs first in the file, joint_6's axis
    is flipped later; the summary's example is the axis. Blocks the URDF lacks are said as
    <gazebo> blocks for a link, not 'gazebos'."""
    urdf_dir = tmp_path / "urdf"
    urdf_dir.mkdir()
    source = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
              '  <link name="base_link"><visual><geometry><box size="1 1 1"/></geometry><material name=""><color rgba="0.2 0.2 0.2 1"/></material></visual></link>\n'
              '  <link name="link_6"/>\n'
              '  <joint name="joint_6" type="revolute"><parent link="base_link"/><child link="link_6"/><axis xyz="-1 0 0"/>'
              '<limit lower="-1" upper="1" effort="0" velocity="1"/></joint>\n'
              '  <gazebo reference="link_6"><mu1>0.5</mu1></gazebo>\n  <gazebo><static>false</static></gazebo>\n</robot>\n')
    (urdf_dir / "r.xacro").write_text(source)
    generated = ('<?xml version="1.0" ?>\n<!-- | This document was autogenerated by xacro from r.xacro | -->\n'
                 + source.replace(' xmlns:xacro="http://www.ros.org/wiki/xacro"', "").replace("0.2 0.2 0.2 1", "0.9 0.9 0.9 1")
                 .replace('xyz="-1 0 0"', 'xyz="1 0 0"').replace('  <gazebo reference="link_6"><mu1>0.5</mu1></gazebo>\n  <gazebo><static>false</static></gazebo>\n', ""))
    (urdf_dir / "r.urdf").write_text(generated)
    done = run_cli("drift", "--format", "concise", "urdf/r.urdf", cwd=tmp_path)
    out = done.stdout.decode()
    assert done.returncode == 1, out
    assert ("it lacks the <gazebo> block for 'link_6' and a <gazebo> block for the robot that r.xacro makes; "
            "1 link and 1 joint differ (joint 'joint_6' axis: 1 0 0 here, -1 0 0 in r.xacro)") in out


SYSTEM = """<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="mode" default="mock"/>
  <xacro:macro name="joint_interface" params="name mode">
    <joint name="${name}">
      <command_interface name="position"/>
      <xacro:unless value="${mode == 'gazebo'}"><command_interface name="effort"/></xacro:unless>
    </joint>
  </xacro:macro>
  <xacro:macro name="system" params="mode">
    <ros2_control name="sys" type="system">
      <xacro:if value="${mode == 'gazebo'}"><hardware><plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware></xacro:if>
      <xacro:joint_interface name="j1" mode="${mode}"/>
    </ros2_control>
  </xacro:macro>
  <link name="base"/>
  <link name="arm"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <xacro:system mode="$(arg mode)"/>
</robot>
"""


def test_a_ros2_control_block_generated_for_another_mode_names_its_plugin_and_the_argument(tmp_path, monkeypatch):
    """lbr_fri_ros2_stack's iiwa14.xacro expanded with mode:=gazebo: its ros2_control has a
    <hardware> block the default mode does not make, and no effort command interface. The
    summary said 'hardware: (none) here, (none) in iiwa14.xacro'; the hint did not name mode
    (read by the conditions around the parts, through the macro calls), and the unsafe fix
    would have written the URDF again for the default mode."""
    model = tmp_path / "r.xacro"
    model.write_text(SYSTEM)
    (tmp_path / "r.urdf").write_text(generate(model, "r.xacro", mode="gazebo"))
    monkeypatch.chdir(tmp_path)
    (found,) = x110(lint_file("r.urdf"))
    assert found.message == (
        "r.urdf does not match r.xacro, which generated it: 1 ros2_control differs "
        "(ros2_control 'sys' hardware/plugin: gz_ros2_control/GazeboSimSystem here, (none) in r.xacro)"
    )
    assert "the URDF may have been generated with other values of mode:='mock'" in found.hint
    assert found.fix.reason == "it may have been generated with other values of mode: regenerate it by hand with those"
    # a part without a value alone is said present on its side
    (tmp_path / "r.urdf").write_text(generate(model, "r.xacro", mode="gazebo").replace("<plugin>gz_ros2_control/GazeboSimSystem</plugin>", ""))
    (found,) = x110(lint_file("r.urdf"))
    assert found.message.endswith("(ros2_control 'sys' hardware: present here, absent in r.xacro)")


def test_a_find_path_of_the_generating_machine_names_the_same_file_here(tmp_path, monkeypatch):
    """articubot_one's URDF, generated from its install space: gazebo_ros2_control's
    $(find articubot_one)/config/my_controllers.yaml is written as that machine's absolute
    path. The same file of the package here is no drift; another file is."""
    package = tmp_path / "src" / "bot"
    (package / "config").mkdir(parents=True)
    (package / "config" / "controllers.yaml").write_text("controller_manager: {}\n")
    (package / "package.xml").write_text('<package format="3"><name>bot</name></package>\n')
    model = package / "robot.urdf.xacro"
    model.write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="base"/>\n'
        '  <gazebo><plugin name="gazebo_ros2_control" filename="libgazebo_ros2_control.so">'
        '<parameters>$(find bot)/config/controllers.yaml</parameters></plugin></gazebo>\n</robot>\n'
    )
    theirs = generate(model, "/home/them/ws/src/bot/robot.urdf.xacro").replace(str(package), "/home/them/ws/install/bot/share/bot")
    assert "/home/them/ws/install/bot/share/bot/config/controllers.yaml" in theirs
    (package / "robot.urdf").write_text(theirs)
    monkeypatch.chdir(package)
    assert x110(lint_file("robot.urdf")) == []
    (package / "robot.urdf").write_text(theirs.replace("controllers.yaml", "other.yaml"))
    (found,) = x110(lint_file("robot.urdf"))
    assert "/parameters: /home/them/ws/install/bot/share/bot/config/other.yaml here" in found.message


def test_a_urdf_without_header_is_not_said_to_name_its_source(tmp_path, monkeypatch):
    """mir_robot's mir.urdf, a hand-written stub with no xacro header, sits beside mir.urdf.xacro,
    which needs xacro argument mir_hook: the info said "mir.urdf says it was generated from
    mir.urdf.xacro", which the file never says. It is paired with the xacro file by its name."""
    (tmp_path / "mir.urdf.xacro").write_text(
        '<robot name="mir" xmlns:xacro="http://ros.org/wiki/xacro">\n'
        '  <xacro:property name="hook" value="$(arg mir_hook)"/>\n  <link name="base_link"/>\n'
        '  <xacro:if value="${hook}"><link name="hook_link"/></xacro:if>\n</robot>\n'
    )
    (tmp_path / "mir.urdf").write_text('<?xml version="1.0"?>\n<robot name="mir">\n  <link name="base_link"/>\n</robot>\n')
    monkeypatch.chdir(tmp_path)
    (found,) = x110(lint_file("mir.urdf"))
    assert found.message == (
        "mir.urdf has mir.urdf.xacro beside it, which was not compared: its expansion needs xacro "
        "argument 'mir_hook'; give it in [tool.urdfcli.xacro-args]"
    )


def test_a_urdf_generated_into_another_folder_of_its_package_says_only_what_its_source_does_not(tmp_path):
    """unitree_ros's go2_description: urdf/go2_description.urdf was generated from
    xacro/robot.xacro (its header names robot.xacro, found in its package, as X110 finds it).
    Linting the package says the stale <gazebo reference> once, at the xacro line that
    writes it, not again at the copy."""
    package = tmp_path / "go2_description"
    (package / "xacro").mkdir(parents=True)
    (package / "urdf").mkdir()
    (package / "package.xml").write_text('<package format="2"><name>go2_description</name></package>\n')
    (package / "xacro" / "robot.xacro").write_text(
        '<robot name="go2" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="trunk"/>\n'
        '  <gazebo reference="stick_link"><mu1>0.2</mu1></gazebo>\n</robot>\n')
    done = run_cli("expand", "robot.xacro", "-o", "../urdf/go2_description.urdf", cwd=package / "xacro")
    assert done.returncode == 0 and "autogenerated by xacro from robot.xacro" in (package / "urdf" / "go2_description.urdf").read_text()
    done = run_cli("lint", "--isolated", "--format", "concise", ".", cwd=package)
    said = [line.split(" warning")[0] for line in done.stdout.decode().splitlines() if " D006 " in line]
    assert said == ["xacro/robot.xacro:3:3: D006"], done.stdout.decode()


def test_a_urdf_whose_header_names_a_gone_source_is_compared_with_the_xacro_of_its_name_beside_it(tmp_path):
    """Neobotix rox_description's rox.urdf: copied from mpo_700's package, its header still says xacro
    made it from mpo_700.urdf.xacro, which rox_description does not have; rox.urdf.xacro sits beside
    it. lint said nothing and drift only that the header's source is gone, though the xacro of its
    name beside it makes another robot: a URDF with that xacro beside it is generated from it."""
    package = tmp_path / "rox_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text('<package format="3"><name>rox_description</name></package>\n')
    (package / "urdf" / "rox.urdf").write_text(
        '<?xml version="1.0" ?>\n<!-- |    This document was autogenerated by xacro from mpo_700.urdf.xacro | -->\n'
        '<robot name="mpo_700"><link name="base_link"/></robot>\n')
    (package / "urdf" / "rox.urdf.xacro").write_text(
        '<?xml version="1.0"?>\n<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="rox">\n'
        '  <link name="base_link"/>\n  <link name="base_footprint"/>\n'
        '  <joint name="base_footprint_joint" type="fixed"><parent link="base_link"/><child link="base_footprint"/></joint>\n'
        '</robot>\n')
    for command in ("lint", "drift"):
        done = run_cli(command, "--isolated", "--format", "concise", "urdf/rox.urdf", cwd=package)
        out = done.stdout.decode()
        assert done.returncode == 1, out + done.stderr.decode()
        assert out.startswith("urdf/rox.urdf:1:1: X110 warning: rox.urdf does not match urdf/rox.urdf.xacro, beside it: "
                              "it lacks link 'base_footprint'"), out
        assert "robot name: mpo_700 here, rox in rox.urdf.xacro" in out, out


def test_a_urdf_still_written_in_xacro_is_no_output_of_the_xacro_beside_it(tmp_path):
    """MoveIt's panda_description: panda.urdf reads its meshes through $(find ...), and panda.urdf.xacro
    beside it is the same arm under a 'world' link. Neither file was made from the other: xacro's output
    holds no substitution. lint said panda.urdf drifted from panda.urdf.xacro, and offered to overwrite it."""
    package = tmp_path / "panda_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text('<package format="3"><name>panda_description</name></package>\n')
    arm = ('<link name="panda_link0"><visual><geometry><mesh filename="file://$(find panda_description)/meshes/link0.stl"/>'
           '</geometry></visual></link>\n')
    (package / "urdf" / "panda.urdf").write_text(
        '<?xml version="1.0" ?>\n<!-- |    This document was autogenerated by xacro from /opt/ros/kinetic/share/panda_description/urdf/panda.urdf | -->\n'
        f'<robot name="panda" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{arm}</robot>\n')
    (package / "urdf" / "panda.urdf.xacro").write_text(
        f'<?xml version="1.0" ?>\n<robot name="panda" xmlns:xacro="http://www.ros.org/wiki/xacro">\n<link name="world"/>\n'
        f'<joint name="world_fixed" type="fixed"><parent link="world"/><child link="panda_link0"/></joint>\n{arm}</robot>\n')
    for command in ("lint", "drift"):
        done = run_cli(command, "--isolated", "--format", "concise", "urdf/panda.urdf", cwd=package)
        assert "X110" not in done.stdout.decode(), done.stdout.decode()
