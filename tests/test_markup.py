"""Markup and material rules on real-world patterns: each false alarm seen on
published robots draws nothing, next to the real defect that still draws its warning."""

from __future__ import annotations

import os
import subprocess

import pytest
from conftest import lint_file, require_tool, run_cli

from urdfcli.project.config import Config

MARKUP = ("D001", "D002", "D010", "D011", "D012", "M002", "M003")


def found(tmp_path, body: str, head: str = "") -> list[tuple[str, str, str]]:
    """(code, severity, message) of the markup and material rules on a robot made of ``body``."""
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r" {head}>\n{body}\n</robot>\n')
    return [(d.code, d.severity.value, d.message) for d in lint_file(str(path), Config()).diagnostics if d.code in MARKUP]


def codes(tmp_path, body: str, head: str = "") -> list[str]:
    return [code for code, _, _ in found(tmp_path, body, head)]


def visual(material: str, link: str = "a") -> str:
    return f'<link name="{link}"><visual><geometry><box size="1 1 1"/></geometry>{material}</visual></link>'


def fixed(parent: str, child: str, name: str | None = None) -> str:
    return f'<joint name="{name or child + "_joint"}" type="fixed"><parent link="{parent}"/><child link="{child}"/></joint>'


# -- materials (M002, M003) -----------------------------------------------------------


def test_materials_without_a_name_are_never_shared(tmp_path):
    # urdfdom only shares named materials: an empty name is each visual's own colour
    body = (
        visual('<material name=""><color rgba="1 0 0 1"/></material>', "a")
        + visual('<material name=""><color rgba="0 1 0 1"/></material>', "b")
        + visual('<material name=""/>', "c")
        + fixed("a", "b") + fixed("a", "c")
    )
    assert codes(tmp_path, body) == []


def test_a_named_material_given_two_colours_is_still_flagged(tmp_path):
    body = (
        visual('<material name="grey"><color rgba="0.2 0.2 0.2 1"/></material>', "a")
        + visual('<material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>', "b")
        + fixed("a", "b")
    )
    assert codes(tmp_path, body) == ["M003"]


def test_colours_equal_to_print_precision_are_the_same_colour(tmp_path):
    body = (
        '<material name="silver"><color rgba="0.75294 0.75294 0.75294 1"/></material>'
        + visual('<material name="silver"><color rgba="0.752941176470588 0.752941176470588 0.752941176470588 1"/></material>')
    )
    assert codes(tmp_path, body) == []
    assert codes(tmp_path, body.replace("0.752941176470588", "0.9", 1)) == ["M003"]


def test_an_alpha_a_tenth_apart_is_the_same_colour(tmp_path):
    # HyQ's 'black' is given alpha 1 and 0.9; seed 002's 'black' is given 0.5 and 0.8.
    body = (
        visual('<material name="black"><color rgba="0 0 0 1"/></material>', "a")
        + visual('<material name="black"><color rgba="0 0 0 0.9"/></material>', "b")
        + fixed("a", "b")
    )
    assert codes(tmp_path, body) == []
    assert codes(tmp_path, body.replace("0 0 0 0.9", "0 0 0 0.5")) == ["M003"]


def test_an_undefined_named_material_is_still_flagged(tmp_path):
    assert codes(tmp_path, visual('<material name="FlatBlack"/>')) == ["M002"]


# -- documented extensions (D001, D002, D010) -----------------------------------------

EXTENSIONS = """
<link name="base">
  <contact><lateral_friction value="1"/><rolling_friction value="0.01"/></contact>
  <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
  <visual><geometry><box size="0.4 0.4 0.4"/></geometry><material name="grey"><color rgba="0.5 0.5 0.5 1"/><specular rgb="1 1 1"/></material></visual>
  <collision group="1" mask="2" concave="yes">
    <geometry><box size="0.4 0.4 0.4"/></geometry>
    <material name="grey"/>
    <contact_coefficients mu="0.8" kp="1e6" kd="1"/>
    <drake:proximity_properties><drake:mu_dynamic value="0.5"/></drake:proximity_properties>
  </collision>
</link>
<link name="arm">
  <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
  <collision><geometry><box size="0.4 0.4 0.4"/></geometry></collision>
</link>
<link name="tool"/>
<joint name="shoulder" type="revolute">
  <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
  <limit lower="-1" upper="1" effort="80" velocity="2" command_effort="80" current="10" gear_velocity="7"/>
  <dynamics D="1" K="1" mu_coulomb="0" mu_viscous="0" damping="0.1"/>
  <drake:rotor_inertia value="0.01"/>
</joint>
<joint name="tool_joint" type="fixed" dont_collapse="true"><parent link="arm"/><child link="tool"/></joint>
<sensor name="ft" type="force_torque"><parent joint="shoulder"/></sensor>
<mujoco><compiler meshdir="meshes" discardvisual="false"/></mujoco>
<klampt use_vis_geom="1"/>
<gazebo reference="base"><mu1>0.9</mu1><selfCollide>true</selfCollide></gazebo>
"""
DRAKE = 'xmlns:drake="http://drake.mit.edu"'


def test_documented_extensions_draw_nothing(tmp_path):
    """PyBullet, Drake, Isaac, MuJoCo, Franka, ANYmal, urdfdom sensors, Gazebo inside <gazebo>."""
    assert found(tmp_path, EXTENSIONS, DRAKE) == []


def test_typos_next_to_the_extensions_are_warnings(tmp_path):
    body = EXTENSIONS.replace('<material name="grey"><color', '<metrial name="grey"><color').replace("</material></visual>", "</metrial></visual>")
    body = body.replace('<axis xyz="0 0 1"/>', '<axis xyz="0 0 1"/><limt effort="1"/>').replace('effort="80" velocity', 'effort="80" velocty')
    assert found(tmp_path, body, DRAKE) == [
        ("D001", "warning", "<metrial> is not a URDF element inside <visual>; it is ignored"),
        ("D010", "info", "<limt> is not URDF markup inside <joint>; URDF consumers ignore it"),
        ("D002", "warning", "<limit> has no attribute 'velocty'; it is ignored"),
    ]


def test_a_misspelt_element_that_is_already_there_is_no_typo(tmp_path):
    # <limt> next to a <limit>: the joint has its limit, so <limt> is leftover markup, not the missing one
    body = '<link name="a"/><link name="b"/><joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/><limt/></joint>'
    assert found(tmp_path, body) == [("D010", "info", "<limt> is not URDF markup inside <joint>; URDF consumers ignore it")]
    assert codes(tmp_path, body.replace("<limit ", "<limmit ")) == ["D001", "D001"]


def test_did_you_mean_never_suggests_an_attribute_already_there(tmp_path):
    body = '<material name="m"><color rgba="1 0 0 1" rgb="1 0 0"/></material><link name="a"/>'
    assert found(tmp_path, body) == [("D010", "info", "<color> has no attribute 'rgb'; URDF consumers ignore it")]
    assert codes(tmp_path, '<material name="m"><color rgba="1 0 0 1"/><color rgb="1 0 0 1"/></material><link name="a"/>') == ["D002"]


def test_unknown_markup_that_is_no_typo_is_info(tmp_path):
    body = (
        '<link name="gripper"><collision><geometry><box size="0.1 0.1 0.1"/></geometry><verbose value="Yes"/></collision>'
        '<self_filter><padding value="0.01"/></self_filter></link>'
        '<link name="frame"><origin xyz="0 0 0"/></link>' + fixed("gripper", "frame")
    )
    result = found(tmp_path, body)
    assert {(code, severity) for code, severity, _ in result} == {("D010", "info")}
    assert len(result) == 3


# -- Gazebo markup outside <gazebo> (D011) --------------------------------------------

WHEEL = """
<link name="base_link"/>
<link name="wheel_link">
  <collision><geometry><cylinder radius="0.07" length="0.05"/></geometry></collision>
  SURFACE
</link>
<joint name="wheel_joint" type="continuous"><parent link="base_link"/><child link="wheel_link"/><axis xyz="0 1 0"/></joint>
"""
SURFACE = "<surface><friction><ode><mu1>100000.0</mu1></ode></friction></surface><kinematic>0</kinematic>"


def test_gazebo_markup_outside_gazebo_is_dead_configuration(tmp_path):
    assert found(tmp_path, WHEEL.replace("SURFACE", SURFACE)) == [
        ("D011", "warning", "Gazebo markup <surface>, <kinematic> in <link> of 'wheel_link' is outside <gazebo>: Gazebo never reads it"),
    ]


def test_a_gazebo_material_in_a_link_is_gazebo_markup(tmp_path):
    assert [code for code, _, _ in found(tmp_path, WHEEL.replace("SURFACE", "<material>Gazebo/Black</material>"))] == ["D011"]


def test_a_gazebo_block_inside_a_link_is_dead_too(tmp_path):
    assert found(tmp_path, WHEEL.replace("SURFACE", "<gazebo><mu1>1</mu1></gazebo>")) == [
        ("D011", "warning", "Gazebo markup <gazebo> in <link> of 'wheel_link': Gazebo reads <gazebo> blocks only at the top level of <robot>"),
    ]


def test_gazebo_markup_a_macro_copies_is_said_once(tmp_path):
    """Robotnik's castor.urdf.xacro writes <surface> in the collision of the caster macro, called
    for four casters: one warning at the macro's line naming the four links, not four."""
    caster = ('<xacro:macro name="caster" params="prefix"><link name="${prefix}_wheel"><collision>'
              '<geometry><cylinder radius="0.05" length="0.02"/></geometry>'
              '<surface><bounce restitution_coefficient="1"/></surface></collision></link>'
              '<joint name="${prefix}_joint" type="continuous"><parent link="base_link"/><child link="${prefix}_wheel"/></joint>'
              '</xacro:macro>')
    calls = "".join(f'<xacro:caster prefix="{corner}"/>' for corner in ("front_left", "front_right", "rear_left", "rear_right"))
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{caster}\n<link name="base_link"/>\n{calls}\n</robot>\n')
    said = [(d.message, d.hint) for d in lint_file(str(path), Config()).diagnostics if d.code == "D011"]
    assert said == [(
        "Gazebo markup <surface> in <collision> of links 'front_left_wheel', 'front_right_wheel', 'rear_left_wheel' and 1 more"
        " is outside <gazebo>: Gazebo never reads it",
        'move it into a <gazebo reference="..."> block naming its link',
    )]


def test_gazebo_markup_inside_gazebo_draws_nothing(tmp_path):
    body = WHEEL.replace("SURFACE", "") + f'<gazebo reference="wheel_link">{SURFACE}</gazebo>'
    assert found(tmp_path, body) == []


# -- transmissions (D012, D007) -------------------------------------------------------

CASTER = """
<link name="base_link"/>
<link name="caster_link"/>
<joint name="caster_joint" type="TYPE"><parent link="base_link"/><child link="caster_link"/><axis xyz="0 0 1"/></joint>
<transmission name="caster_trans">
  <type>transmission_interface/SimpleTransmission</type>
  <joint name="JOINT"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
  <actuator name="caster_motor"><mechanicalReduction>1</mechanicalReduction></actuator>
</transmission>
"""


def test_a_transmission_driving_a_fixed_joint_is_flagged(tmp_path):
    assert found(tmp_path, CASTER.replace("TYPE", "fixed").replace("JOINT", "caster_joint")) == [
        ("D012", "warning", "transmission 'caster_trans' drives joint 'caster_joint', which is fixed"),
    ]


ROS2_CONTROL = """
<ros2_control name="base" type="system">
  <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
  <joint name="caster_joint">INTERFACES</joint>
</ros2_control>
"""


def test_ros2_control_commanding_a_fixed_joint_is_flagged_publishing_its_state_is_not(tmp_path):
    body = CASTER.split("<transmission")[0].replace("TYPE", "fixed")
    commanded = ROS2_CONTROL.replace("INTERFACES", '<command_interface name="velocity"/><state_interface name="position"/>')
    assert found(tmp_path, body + commanded) == [("D012", "warning", "ros2_control 'base' commands joint 'caster_joint', which is fixed")]
    assert found(tmp_path, body + ROS2_CONTROL.replace("INTERFACES", '<state_interface name="position"/>')) == []


FRANKA_MODEL = """
<transmission name="panda_franka_model">
  <type>franka_hw/FrankaModelInterface</type>
  <joint name="base_joint"><role>root</role><hardwareInterface>franka_hw/FrankaModelInterface</hardwareInterface></joint>
  <joint name="caster_joint"><role>tip</role><hardwareInterface>franka_hw/FrankaModelInterface</hardwareInterface></joint>
  <actuator name="base_motor_root"><hardwareInterface>franka_hw/FrankaModelInterface</hardwareInterface></actuator>
</transmission>
"""


def test_a_transmission_that_only_reads_a_fixed_joint_draws_nothing(tmp_path):
    """franka_description names its fixed flange as the tip of a model interface; a joint
    state interface only publishes. In the older layout the actuator holds the interface."""
    body = CASTER.split("<transmission")[0].replace("TYPE", "fixed")
    assert found(tmp_path, body + FRANKA_MODEL) == []
    state = CASTER.replace("TYPE", "fixed").replace("JOINT", "caster_joint").replace("EffortJointInterface", "JointStateInterface")
    assert found(tmp_path, state) == []
    older = CASTER.replace("TYPE", "fixed").replace("JOINT", "caster_joint").replace("<hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface>", "")
    assert found(tmp_path, older) == [("D012", "warning", "transmission 'caster_trans' drives joint 'caster_joint', which is fixed")]
    older_state = older.replace("<mechanicalReduction>", "<hardwareInterface>hardware_interface/JointStateInterface</hardwareInterface><mechanicalReduction>")
    assert found(tmp_path, older_state) == []
    mixed = state.replace("</joint></transmission>", "").replace(
        "JointStateInterface</hardwareInterface>", "JointStateInterface</hardwareInterface><hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface>"
    )
    assert found(tmp_path, mixed) == [("D012", "warning", "transmission 'caster_trans' drives joint 'caster_joint', which is fixed")]


def test_a_transmission_driving_a_moving_joint_draws_nothing(tmp_path):
    assert found(tmp_path, CASTER.replace("TYPE", "continuous").replace("JOINT", "caster_joint")) == []


def test_a_transmission_naming_no_joint_is_still_flagged(tmp_path):
    result = [(d.code) for d in _lint(tmp_path, CASTER.replace("TYPE", "continuous").replace("JOINT", "caster"))]
    assert "D007" in result and "D012" not in result


def _lint(tmp_path, body: str):
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r">\n{body}\n</robot>\n')
    return lint_file(str(path), Config()).diagnostics


# -- missing files: one cause, one diagnostic (D004, D005) ----------------------------


def meshes(*uris: str) -> str:
    return "".join(f'<link name="l{i}"><visual><geometry><mesh filename="{uri}"/></geometry></visual></link>' for i, uri in enumerate(uris)) + "".join(
        fixed("l0", f"l{i}") for i in range(1, len(uris))
    )


def resources(tmp_path, body: str) -> list[tuple[str, str]]:
    return [(d.code, d.message) for d in _lint(tmp_path, body) if d.code in ("D004", "D005")]


def test_a_missing_package_is_one_diagnostic_however_many_meshes_name_it(tmp_path):
    found_ = resources(tmp_path, meshes("package://gone/a.stl", "package://gone/b.stl", "package://gone/c.stl"))
    assert [code for code, _ in found_] == ["D005"]
    assert "(and 2 other files)" in found_[0][1]


def test_an_empty_package_name_is_said_so(tmp_path):
    assert resources(tmp_path, meshes("package:///robot/a.stl", "package:///robot/b.stl")) == [
        ("D005", "mesh 'package:///robot/a.stl' (and 1 other file): the package name is empty"),
    ]


def test_files_in_a_missing_folder_are_one_diagnostic_a_missing_file_one_each(tmp_path):
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "arm.stl").write_text("solid arm\nendsolid arm\n")
    body = meshes("/nowhere/romeo/Torso.mesh", "/nowhere/romeo/Head.mesh", "meshes/arm.stl", "meshes/Arm.STL", "meshes/leg.stl")
    found_ = resources(tmp_path, body)
    assert [code for code, _ in found_] == ["D004", "D004", "D004"]
    assert found_[0][1] == "mesh '/nowhere/romeo/Torso.mesh' and 1 other file there: folder /nowhere/romeo does not exist"


def test_an_inertia_writing_its_lower_triangle_is_one_note_not_three(tmp_path):
    """kortex's robotiq_2f_85_macro.xacro writes iyx, izx and izy beside ixy, ixz and iyz: URDF
    reads the upper triangle only. One D010 per <inertia>, naming the three."""
    body = ('<link name="a"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1" '
            'iyx="0" izx="0" izy="0"/></inertial></link>')
    assert found(tmp_path, body) == [("D010", "info", "<inertia> has no attributes 'iyx', 'izx' and 'izy'; URDF consumers ignore them")]


def test_a_lower_triangle_value_that_is_not_the_upper_ones_is_a_mistyped_moment(tmp_path):
    """Fetch's fingers write iyx="0.002" and izx="0.002" beside ixy="0", ixz="0", iyy="0" and
    izz="0": the diagonal moments typed one letter off, which URDF never reads. A warning
    naming the moment meant; izy, repeating iyz, stays the note of a CAD exporter's habit."""
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r"><link name="finger"><inertial><mass value="0.0798"/>'
                    '<inertia ixx="0.002" ixy="0" ixz="0" iyx="0.002" iyy="0" iyz="0" izx="0.002" izy="0" izz="0"/>'
                    '</inertial></link></robot>\n')
    line = path.read_text()
    shown = [(d.code, d.severity.value, d.message, d.hint, line[d.column - 1:d.column + 2]) for d in lint_file(str(path), Config()).diagnostics if d.code in MARKUP]
    assert shown == [
        ("D002", "warning", "<inertia> has no attribute 'iyx', and its value '0.002' differs from ixy's '0': no repeated product of inertia; it is ignored",
         "probably a mistyped 'iyy' (one letter away), which URDF reads as '0'", "iyx"),
        ("D002", "warning", "<inertia> has no attribute 'izx', and its value '0.002' differs from ixz's '0': no repeated product of inertia; it is ignored",
         "probably a mistyped 'izz' (one letter away), which URDF reads as '0'", "izx"),
        ("D010", "info", "<inertia> has no attribute 'izy'; URDF consumers ignore it", "<inertia> takes ixx, ixy, ixz, iyy, iyz, izz", "izy"),
    ]
    # the same values written alike ('-0.0' for '0', a CAD exporter's rounding) are a repeat
    body = ('<link name="a"><inertial><mass value="1"/><inertia ixx="0.0129" ixy="0.0002" ixz="0.0007" iyy="0.0095" iyz="0" izz="0.0184" '
            'iyx="2e-4" izx="0.00070000001" izy="-0.0"/></inertial></link>')
    assert found(tmp_path, body) == [("D010", "info", "<inertia> has no attributes 'iyx', 'izx' and 'izy'; URDF consumers ignore them")]


def shown(path, *options: str) -> list[str]:
    """What `lint` prints of D002 and D010: each first line, and the note saying where else."""
    out = run_cli("lint", "--isolated", "--select", "D002,D010", *options, str(path)).stdout.decode().splitlines()
    return [line.removeprefix(f"{path}:") if ": D0" in line else line.strip() for line in out if ": D0" in line or "also at" in line]


def test_the_same_unknown_attributes_on_many_elements_are_shown_once_for_the_file(tmp_path):
    """Fetch's fetch.urdf.xacro writes iyx, izx and izy on each of its 17 <inertia> (a CAD
    exporter's habit): shown once, at the first, saying where else (the JSON keeps each).
    Other attributes, or the same on another tag, are shown apart; a typo stays D002's
    warning. A noqa comment on the first silences its own note only."""
    def link(name: str, inertia: str = "", mass: str = "", comment: str = "") -> str:
        moments = 'ixx="1" ixy="0" ixz="0" iyy="1" iyz="0"' + ("" if "izzz" in inertia else ' izz="1"')
        return f'<link name="{name}">{comment}<inertial><mass value="1" {mass}/><inertia {moments} {inertia}/></inertial></link>'
    triangle = 'iyx="0" izx="0" izy="0"'
    lines = [link("a", triangle), link("b", triangle), link("c", triangle), link("d", 'izy="0"'), link("e", mass='unit="kg"'),
             link("f", mass='unit="kg"'), link("g", 'izzz="1"'), link("h", 'izzz="1"')]
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r">\n' + "\n".join(lines) + "\n</robot>\n")
    assert shown(path) == [
        "2:101: D010 info: <inertia> has no attributes 'iyx', 'izx' and 'izy'; URDF consumers ignore them", "note: also at lines 3 and 4",
        "5:101: D010 info: <inertia> has no attribute 'izy'; URDF consumers ignore it",
        "6:42: D010 info: <mass> has no attribute 'unit'; URDF consumers ignore it", "note: also at line 7",
        "8:93: D002 warning: <inertia> has no attribute 'izzz'; it is ignored", "note: also at line 9",
    ]
    assert len([d for d in lint_file(str(path), Config()).diagnostics if d.code == "D010"]) == 6  # each place, for the formats that list them
    lines[0] = link("a", triangle, comment="<!-- urdfcli: noqa: D010 -->")
    path.write_text('<robot name="r">\n' + "\n".join(lines) + "\n</robot>\n")
    assert shown(path)[:2] == ["3:101: D010 info: <inertia> has no attributes 'iyx', 'izx' and 'izy'; URDF consumers ignore them", "note: also at line 4"]


def test_unknown_attributes_a_macro_writes_count_the_places_written(tmp_path):
    """A macro called twice writes its <inertia> once: one place, shown once; with a second
    <inertia> written elsewhere, the note names that line, not the expansion's elements."""
    macro = ('<xacro:macro name="part" params="n"><link name="${n}"><inertial><mass value="1"/>'
             '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1" iyx="0"/></inertial></link></xacro:macro>')
    path = tmp_path / "robot.urdf.xacro"
    calls = '<xacro:part n="a"/>\n<xacro:part n="b"/>'
    path.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{macro}\n{calls}\n</robot>\n')
    assert [line for line in shown(path) if "also" in line] == []
    written = '<link name="c"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1" iyx="0"/></inertial></link>'
    path.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{macro}\n{calls}\n{written}\n</robot>\n')
    assert [line for line in shown(path) if "also" in line] == ["note: also at line 5"]


def test_a_gazebo_reference_whose_expression_lost_its_dollar_says_so(tmp_path):
    """unitree go1's leg.xacro: <gazebo reference="{name}_thigh"> in a macro called for four legs.
    Not 'did you mean RR_thigh?' (one leg of four): the $ is missing."""
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r"><link name="FR_thigh"/><link name="RR_thigh"/><gazebo reference="{name}_thigh"><mu1>0.2</mu1></gazebo></robot>\n')
    [diagnostic] = [d for d in lint_file(str(path), Config()).diagnostics if d.code == "D006"]
    assert diagnostic.hint == "'{name}' lacks its $: xacro copies it as written; write '${name}'"


def test_a_link_property_under_a_joint_name_is_said_dropped_and_the_child_link_named(tmp_path):
    """AgileX's Limo sets its wheels' friction in <gazebo reference="front_left_wheel">, the joint's
    name: sdformat gives <mu1> to a link only, and drops it there (its own conversion shows it). A
    joint's own properties (<provideFeedback>, Shadow's hand) and a block naming the link are left alone."""
    inertial = '<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>'
    joint = (f'<link name="base_link">{inertial}</link><link name="front_left_wheel_link">{inertial}'
             '<collision><geometry><sphere radius="0.1"/></geometry></collision></link><joint name="front_left_wheel" type="continuous">'
             '<parent link="base_link"/><child link="front_left_wheel_link"/></joint>')
    sdformat = require_tool("ign")
    for reference, kept in (("front_left_wheel", False), ("front_left_wheel_link", True)):
        path = tmp_path / f"{reference}.urdf"
        path.write_text(f'<robot name="r">{joint}<gazebo reference="{reference}"><mu1>0.123</mu1></gazebo></robot>\n')
        converted = subprocess.run([sdformat, "sdf", "-p", str(path)], capture_output=True, text=True, env={**os.environ, "HOME": str(tmp_path)})
        assert ("0.123" in converted.stdout) is kept, converted.stdout  # (the friction value, wherever it is written)
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r">{joint}<gazebo reference="front_left_wheel"><mu1>0.1</mu1><mu2>0.1</mu2>'
                    '<provideFeedback>true</provideFeedback></gazebo></robot>\n')
    [diagnostic] = [d for d in lint_file(str(path), Config()).diagnostics if d.code == "D006"]
    assert diagnostic.message == "<gazebo reference='front_left_wheel'> names a joint, and Gazebo gives <mu1>, <mu2> to links only: it drops them"
    assert diagnostic.hint == "write reference='front_left_wheel_link', the joint's child link"
    for block in ('<gazebo reference="front_left_wheel"><provideFeedback>true</provideFeedback></gazebo>',
                  '<gazebo reference="front_left_wheel_link"><mu1>0.1</mu1></gazebo>'):
        path.write_text(f'<robot name="r">{joint}{block}</robot>\n')
        assert [d for d in lint_file(str(path), Config()).diagnostics if d.code == "D006"] == []


def test_a_link_property_written_twice_in_one_gazebo_block_is_said_at_the_value_gazebo_ignores(tmp_path):
    """ROBOTIS OP3's ankle: <mu1>9000</mu1>, then <mu1>1.5</mu1> in one block. sdformat keeps
    the last without a word (its own conversion shows it). The same value twice, and a value
    set again in a second block for the link (an override sdformat warns of), are left alone."""
    inertial = '<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>'
    link = f'<link name="foot">{inertial}<collision><geometry><sphere radius="0.1"/></geometry></collision></link>'
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r">\n{link}\n<gazebo reference="foot">\n<mu1>0.9123</mu1>\n<mu2>0.5</mu2>\n<mu1>0.4567</mu1>\n<mu2>0.5</mu2>\n</gazebo>\n</robot>\n')
    converted = subprocess.run([require_tool("ign"), "sdf", "-p", str(path)], capture_output=True, text=True, env={**os.environ, "HOME": str(tmp_path)})
    assert "0.4567" in converted.stdout and "0.9123" not in converted.stdout, converted.stdout
    [diagnostic] = [d for d in lint_file(str(path), Config()).diagnostics if d.code == "D014"]
    assert diagnostic.message == "<gazebo reference='foot'> sets <mu1> twice, to 0.9123 and then 0.4567: Gazebo keeps 0.4567"
    assert diagnostic.line == 4
    for blocks in ('<gazebo reference="foot"><mu1>0.5</mu1><mu1>0.5</mu1></gazebo>',
                   '<gazebo reference="foot"><mu1>0.9</mu1></gazebo><gazebo reference="foot"><mu1>0.4</mu1></gazebo>'):
        path.write_text(f'<robot name="r">{link}{blocks}</robot>\n')
        assert [d for d in lint_file(str(path), Config()).diagnostics if d.code == "D014"] == []


TF_PREFIXED = """<robot name="mir">
  <link name="robot1/base_link"/>
  <link name="robot1/front_laser_link"/>
  <joint name="robot1/laser_joint" type="fixed"><parent link="robot1/base_link"/><child link="robot1/front_laser_link"/></joint>
  <gazebo reference="robot1/front_laser_link">
    <sensor type="ray" name="laser">
      <plugin name="laser_controller" filename="FILENAME">
        FRAME
      </plugin>
    </sensor>
  </gazebo>
</robot>
"""


@pytest.mark.parametrize(
    ("filename", "frame", "reported"),
    [
        ("libgazebo_ros_gpu_laser.so", "<frameName>front_laser_link</frameName>", False),  # the plugin adds the tf_prefix
        ("libgazebo_ros_gpu_laser.so", "<frameName>/front_laser_link</frameName>", True),  # an absolute name gets none
        ("libgazebo_ros_ray_sensor.so", "<frame_name>front_laser_link</frame_name>", True),  # ROS 2: no tf_prefix
        ("libgazebo_ros_gpu_laser.so", "<frameName>rear_laser_link</frameName>", True),
    ],
)
def test_a_ros1_frame_name_without_the_tf_prefix_its_plugin_adds(tmp_path, filename, frame, reported):
    """mir_robot's sick_s300.urdf.xacro writes <frameName>${link}</frameName> unprefixed
    ("plugin always uses a tf_prefix"): with tf_prefix:=robot1 its links are robot1/..., and
    D009 said the frame names no link. ROS 1's gazebo_ros laser and camera plugins resolve
    frameName against the tf_prefix, so it names robot1/front_laser_link there."""
    path = tmp_path / "mir.urdf"
    path.write_text(TF_PREFIXED.replace("FILENAME", filename).replace("FRAME", frame))
    found = [d for d in lint_file(str(path), Config()).diagnostics if d.code == "D009"]
    assert bool(found) is reported, [d.message for d in found]


def test_a_misspelt_interface_in_a_ros2_control_block_is_a_typo(tmp_path):
    """ros2_control's parser reads a component's <command_interface>, <state_interface>,
    <param> and its hardware's <plugin> by name and skips the rest: <comand_interface>
    leaves the wheel without a command. Parameters and unknown markup are its own business."""
    robot = ('<link name="base"/><link name="wheel"/><joint name="wheel_joint" type="continuous"><parent link="base"/><child link="wheel"/>'
             '<axis xyz="0 1 0"/></joint><ros2_control name="DiffBot" type="system"><hardware><plugin>mock_components/GenericSystem</plugin>'
             '<param name="calculate_dynamics">true</param></hardware><joint name="wheel_joint"><command_interface name="velocity"/>'
             '<state_interface name="position"/><!-- odometry --><custom_tag/></joint><sensor name="imu"><state_interface name="orientation.x"/></sensor></ros2_control>')
    assert found(tmp_path, robot) == []
    typos = robot.replace("<command_interface ", "<comand_interface ").replace("<plugin>mock_components/GenericSystem</plugin>", "<plugn>mock_components/GenericSystem</plugn>")
    assert found(tmp_path, typos.replace('<sensor name="imu"><state_interface', '<sensor name="imu"><state_inteface')) == [
        ("D001", "warning", "<plugn> is not a ros2_control element inside <hardware>; it is ignored"),
        ("D001", "warning", "<comand_interface> is not a ros2_control element inside <joint>; it is ignored"),
        ("D001", "warning", "<state_inteface> is not a ros2_control element inside <sensor>; it is ignored"),
    ]


def test_a_colour_missing_its_alpha_is_said_once_not_as_a_second_colour(tmp_path):
    # aubo_i5l: the top-level 'black' has an alpha, each link's own 'black' lacks it. urdfdom cannot
    # read the three numbers and takes the top-level colour: M004 says so, and nothing clashes.
    body = (
        '<material name="black"><color rgba="0.25098 0.25098 0.25098 1"/></material>'
        + visual('<material name="black"><color rgba="0.25098 0.25098 0.25098"/></material>', "a")
        + visual('<material name="black"><color rgba="0.25098 0.25098 0.25098"/></material>', "b")
        + fixed("a", "b")
    )
    assert codes(tmp_path, body) == []
    assert "M004" in [d.code for d in lint_file(str(tmp_path / "robot.urdf"), Config()).diagnostics]
    assert codes(tmp_path, body.replace('0.25098 0.25098 0.25098"/>', '0.9 0.9 0.9 1"/>', 1)) == ["M003"]
