"""The rules on the xacro sources and the package (P001, X101-X107) and xacro's warnings
with their fix (X005), on small workspaces written here: each finding, and its clean
counterpart. The layouts are those real repositories have (tests/ros_workspace.py):
package names that differ from their folders, libraries in another repository of a
colcon ``src/``."""

from __future__ import annotations

import json
import subprocess
import textwrap
from pathlib import Path

import pytest
import xacro
from conftest import require_tool, run_cli
from ros_workspace import XACRO, edit, line_of, make_colcon_workspace, make_repository, package_xml

import urdfcli
from urdfcli.project.config import Config
from urdfcli.read.xacro_scan import macro_parameters

SOURCE_CODES = ("P001", "X101", "X102", "X103", "X104", "X105", "X106", "X107")


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))
    return path


def robot(body: str, name: str = "r") -> str:
    return f'<?xml version="1.0"?>\n<robot name="{name}" {XACRO}>\n{textwrap.dedent(body).strip()}\n</robot>\n'


def library(body: str) -> str:
    return f'<?xml version="1.0"?>\n<robot {XACRO}>\n{textwrap.dedent(body).strip()}\n</robot>\n'


def found(*paths: Path, codes=SOURCE_CODES, **settings) -> list[tuple[str, str, int, int | None]]:
    """(code, file name, line, column) of the source findings of linting ``paths``."""
    results = urdfcli.lint([str(p) for p in paths], config=Config.everything(), **settings)
    return sorted(
        (d.code, Path(d.path).name, d.line, d.column)
        for result in results for d in result.diagnostics if d.code in codes
    )


def diagnostics(path: Path, code: str, **settings):
    results = urdfcli.lint([str(path)], config=Config.everything(), **settings)
    return [d for result in results for d in result.diagnostics if d.code == code]


def column_of(path: Path, needle: str, after: str = "") -> tuple[int, int]:
    """Line and column (1-based) of ``needle`` on the first line holding ``after`` and it."""
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if needle in line and after in line:
            return number, line.index(needle, line.index(after) if after else 0) + 1
    raise AssertionError(f"{needle!r} not in {path}")


# -- P001: the packages a package uses and declares ------------------------------------
@pytest.fixture
def packages(tmp_path):
    """A repository: my_robot uses meshes of acme_meshes (in folder meshes_pkg) and
    macros of acme_parts; both can be found, neither is declared yet."""
    root = tmp_path / "repo"
    (root / ".git").mkdir(parents=True)
    write(root / "meshes_pkg" / "package.xml", package_xml("acme_meshes"))
    write(root / "meshes_pkg" / "meshes" / "arm.stl", "solid arm\nendsolid arm\n")
    write(root / "parts" / "package.xml", package_xml("acme_parts"))
    write(root / "parts" / "urdf" / "arm.xacro", library('<xacro:macro name="arm" params="parent"><link name="arm"/><joint name="arm_joint" type="fixed"><parent link="${parent}"/><child link="arm"/></joint></xacro:macro>'))
    write(root / "my_robot" / "package.xml", package_xml("my_robot"))
    return root


def model_using(root: Path, body: str) -> Path:
    return write(root / "my_robot" / "urdf" / "robot.urdf.xacro", robot(body))


def test_a_mesh_of_an_undeclared_package_is_a_warning_at_its_use_with_the_line_to_add(packages):
    model = model_using(packages, """
        <xacro:arg name="arm" default="false"/>
        <link name="base_link"/>
        <xacro:if value="$(arg arm)">
          <link name="arm_link"><visual><geometry><mesh filename="package://acme_meshes/meshes/arm.stl"/></geometry></visual></link>
          <joint name="arm_joint" type="fixed"><parent link="base_link"/><child link="arm_link"/></joint>
        </xacro:if>
        """)
    [warning] = diagnostics(model, "P001")
    assert (warning.line, warning.column) == column_of(model, "package://acme_meshes")  # in a branch not taken: a condition installs nothing
    assert warning.severity.value == "warning"
    assert "package 'acme_meshes'" in warning.message and "my_robot's package.xml does not declare it" in warning.message
    assert warning.hint.startswith("add <exec_depend>acme_meshes</exec_depend> to ")
    assert warning.hint.split(" to ")[1].split(":")[0].endswith("my_robot/package.xml")


@pytest.mark.parametrize("kind", ["depend", "exec_depend", "build_export_depend", "build_depend", "test_depend", "run_depend"])
def test_each_kind_of_dependency_declares_a_package(packages, kind):
    model = model_using(packages, '<link name="base_link"><visual><geometry><mesh filename="package://acme_meshes/meshes/arm.stl"/></geometry></visual></link>')
    assert [c for c, *_ in found(model)] == ["P001"]
    edit(packages / "my_robot" / "package.xml", "</package>", f"  <{kind}>acme_meshes</{kind}>\n</package>")
    assert found(model) == []


def test_a_doc_depend_does_not_declare_a_package(packages):
    model = model_using(packages, '<link name="base_link"><visual><geometry><mesh filename="package://acme_meshes/meshes/arm.stl"/></geometry></visual></link>')
    edit(packages / "my_robot" / "package.xml", "</package>", "  <doc_depend>acme_meshes</doc_depend>\n</package>")
    assert [c for c, *_ in found(model)] == ["P001"]


def test_an_included_package_is_a_run_dependency_and_file_find_counts(packages):
    """An included file is read where the model is expanded (a launch file, rviz), not to
    build: <exec_depend>, as for a mesh (a <depend> builds on it, and two description
    packages using each other's files would make a cycle in the build order)."""
    model = model_using(packages, """
        <xacro:include filename="$(find acme_parts)/urdf/arm.xacro"/>
        <link name="base_link"><visual><geometry><mesh filename="file://$(find acme_meshes)/meshes/arm.stl"/></geometry></visual></link>
        <xacro:arm parent="base_link"/>
        """)
    warnings = {d.message.split("'")[1]: d for d in diagnostics(model, "P001")}
    assert warnings["acme_parts"].hint.startswith("add <exec_depend>acme_parts</exec_depend>")
    assert (warnings["acme_parts"].line, warnings["acme_parts"].column) == column_of(model, "$(find acme_parts)")
    assert warnings["acme_meshes"].hint.startswith("add <exec_depend>acme_meshes</exec_depend>")


def test_one_warning_per_file_and_package_at_the_first_use(packages):
    mesh = '<mesh filename="package://acme_meshes/meshes/arm.stl"/>'
    model = model_using(packages, f"""
        <link name="base_link"><visual><geometry>{mesh}</geometry></visual><collision><geometry>{mesh}</geometry></collision></link>
        """)
    [warning] = diagnostics(model, "P001")
    assert "(and 1 more use in this file)" in warning.message


def test_its_own_package_and_a_variable_draw_nothing(packages):
    model = model_using(packages, """
        <xacro:property name="pkg" value="acme_meshes"/>
        <link name="base_link"><visual><geometry><mesh filename="package://my_robot/meshes/base.stl"/></geometry></visual></link>
        <xacro:if value="false">
          <xacro:include filename="$(find ${pkg})/urdf/x.xacro"/>
        </xacro:if>
        """)
    assert found(model, codes=("P001",)) == []


def test_a_package_found_nowhere_and_not_declared_is_a_warning_too(packages):
    """Husky's laser mount from sick_description: missing here (D005 says so) and not
    declared either, so no fresh workspace would install it."""
    model = model_using(packages, """
        <link name="base_link"><visual><geometry><mesh filename="package://sick_description/meshes/mount.stl"/></geometry></visual></link>
        <xacro:if value="false">
          <xacro:include filename="$(find no_such_package)/urdf/x.xacro"/>
        </xacro:if>
        """)
    warnings = {d.message.split("'")[1]: d for d in diagnostics(model, "P001")}
    assert set(warnings) == {"sick_description", "no_such_package"}
    assert warnings["sick_description"].hint.startswith("add <exec_depend>sick_description</exec_depend>")
    edit(packages / "my_robot" / "package.xml", "</package>", "  <exec_depend>sick_description</exec_depend>\n</package>")
    assert {d.message.split("'")[1] for d in diagnostics(model, "P001")} == {"no_such_package"}


def test_its_own_package_named_by_its_folder_is_no_dependency(tmp_path):
    """example-robot-data's layout: the folder example-robot-data holds the package named
    example_robot_descriptions, and its URDFs write package://example-robot-data/. The URI
    names the package itself (D005 says which name to write); declaring a dependency on
    it, as a fix would, gives rosdep a key nobody provides."""
    root = tmp_path / "example-robot-data"
    write(root / "package.xml", package_xml("example_robot_descriptions"))
    write(root / "robots" / "arm" / "meshes" / "arm.stl", "solid arm\nendsolid arm\n")
    model = write(root / "robots" / "arm" / "urdf" / "arm.urdf", """\
        <robot name="arm">
          <link name="base_link"><visual><geometry><mesh filename="package://example-robot-data/robots/arm/meshes/arm.stl"/></geometry></visual></link>
          <link name="tool"><visual><geometry><mesh filename="package://sick_description/meshes/mount.stl"/></geometry></visual></link>
          <joint name="j" type="fixed"><parent link="base_link"/><child link="tool"/></joint>
        </robot>
        """)
    assert {d.message.split("'")[1] for d in diagnostics(model, "P001")} == {"sick_description"}  # another package found nowhere still is one
    assert any("example_robot_descriptions" in (d.hint or "") for d in diagnostics(model, "D005"))
    run_cli("lint", "--fix", str(model))
    manifest = (root / "package.xml").read_text()
    assert "<exec_depend>sick_description</exec_depend>" in manifest and "example-robot-data" not in manifest


def test_its_own_package_under_a_name_no_package_has_is_no_dependency(tmp_path):
    """ROBOTIS-OP3-Common's op3_description: the package was renamed, its model still
    includes $(find robotis_op3_description)/urdf/robotis_op3.visuals.xacro, a file of its own
    package. X004 says the name is found nowhere; a 'safe' fix declaring a dependency on
    it would give rosdep a key nobody provides. A package found nowhere whose path is not
    in the file's package is still one (the file cannot tell it is its own)."""
    root = tmp_path / "op3_description"
    write(root / "package.xml", package_xml("op3_description"))
    write(root / "urdf" / "visuals.xacro", library('<xacro:macro name="body"><link name="body_link"/></xacro:macro>'))
    model = write(root / "urdf" / "robot.urdf.xacro", robot("""
        <xacro:include filename="$(find robotis_op3_description)/urdf/visuals.xacro"/>
        <xacro:include filename="$(find hector_sensors_description)/urdf/sonar.urdf.xacro"/>
        <xacro:body/>
        """))
    assert {d.message.split("'")[1] for d in diagnostics(model, "P001")} == {"hector_sensors_description"}
    run_cli("lint", "--fix", str(model))
    manifest = (root / "package.xml").read_text()
    assert "<exec_depend>hector_sensors_description</exec_depend>" in manifest and "robotis_op3_description" not in manifest


def test_a_package_a_macro_parameter_names_is_judged_at_each_call_when_every_call_names_it(packages):
    model = model_using(packages, """
        <xacro:macro name="part" params="name pkg:=my_robot">
          <link name="${name}"><visual><geometry><mesh filename="package://${pkg}/meshes/arm.stl"/></geometry></visual></link>
        </xacro:macro>
        <xacro:part name="base_link"/>
        <xacro:part name="arm" pkg="acme_meshes"/>
        <joint name="j" type="fixed"><parent link="base_link"/><child link="arm"/></joint>
        """)
    [warning] = diagnostics(model, "P001")
    assert (warning.line, warning.column) == column_of(model, "acme_meshes", 'pkg="')  # the call that names it
    edit(model, "<xacro:part name=\"base_link\"/>", "<xacro:property name=\"own\" value=\"my_robot\"/><xacro:part name=\"base_link\" pkg=\"${own}\"/>")
    assert diagnostics(model, "P001") == []  # one call computes it: nothing is certain


def test_a_macro_argument_carrying_a_folder_names_the_package_before_its_slash(packages):
    """ros2_control_demos' shape: ``package://${mesh_package}/meshes/...`` with
    mesh_package="ros2_control_demo_description/r6bot". The package is the part before
    the ``/``, here the file's own: nothing to declare, and ``--fix`` writes nothing."""
    write(packages / "my_robot" / "r6bot" / "meshes" / "link_0.stl", "solid l\nendsolid l\n")
    write(packages / "my_robot" / "r6bot" / "urdf" / "inc" / "create_link.xacro", library("""
        <xacro:macro name="create_link" params="link_name mesh_package mesh_name">
          <link name="${link_name}"><visual><geometry><mesh filename="package://${mesh_package}/meshes/${mesh_name}.stl"/></geometry></visual></link>
        </xacro:macro>
        """))
    model = model_using(packages, """
        <xacro:include filename="$(find my_robot)/r6bot/urdf/inc/create_link.xacro"/>
        <xacro:create_link link_name="base_link" mesh_package="my_robot/r6bot" mesh_name="link_0"/>
        """)
    manifest = (packages / "my_robot" / "package.xml").read_text()
    assert diagnostics(model, "P001") == []
    run_cli("lint", "--fix", "--select", "P001", str(model))
    assert (packages / "my_robot" / "package.xml").read_text() == manifest
    edit(model, 'mesh_package="my_robot/r6bot"', 'mesh_package="acme_meshes/r6bot"')  # another package's folder still needs it declared
    [warning] = diagnostics(model, "P001")
    assert "package 'acme_meshes'" in warning.message and warning.hint.startswith("add <exec_depend>acme_meshes</exec_depend>")


def test_a_plain_urdf_is_checked_through_its_meshes(packages):
    model = write(packages / "my_robot" / "urdf" / "robot.urdf", """\
        <robot name="r">
          <link name="base_link"><visual><geometry><mesh filename="package://acme_meshes/meshes/arm.stl"/></geometry></visual></link>
        </robot>
        """)
    [warning] = diagnostics(model, "P001")
    assert warning.line == 2 and warning.hint.startswith("add <exec_depend>acme_meshes</exec_depend>")


def test_a_package_of_another_repository_of_a_colcon_workspace(tmp_path):
    repo_a, repo_b = make_colcon_workspace(tmp_path)
    model = write(repo_a / "robot" / "urdf" / "robot.urdf.xacro", robot("""
        <xacro:include filename="$(find acme_wheels)/urdf/wheel.xacro"/>
        <link name="base_link"/>
        <xacro:wheel prefix="left" parent="base_link" radius="0.1"><origin xyz="0 0 0"/></xacro:wheel>
        """))
    assert found(model, codes=("P001",)) == [("P001", "robot.urdf.xacro", *column_of(model, "$(find acme_wheels)"))]
    edit(repo_a / "robot" / "package.xml", "</package>", "  <depend>acme_wheels</depend>\n</package>")
    assert found(model, codes=("P001",)) == []
    # repo_b's box_inertial serves no model of this workspace: noted, in repo_b's file
    assert found(model) == [("X104", "inertia.xacro", *column_of(repo_b / "wheels" / "urdf" / "inertia.xacro", 'box_inertial"'))]


# -- X101, X102, X104: definitions nothing uses ---------------------------------------
def test_an_argument_read_nowhere_is_a_warning_at_its_definition(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:arg name="use_gpu" default="false"/>
        <link name="base_link"/>
        """))
    [warning] = diagnostics(model, "X101")
    assert (warning.line, warning.column, warning.severity.value) == (*column_of(model, "use_gpu"), "warning")  # at the name
    assert "use_gpu:=VALUE changes nothing" in warning.message


@pytest.mark.parametrize("reading", [
    '<xacro:if value="$(arg use_gpu)"><link name="gpu"/></xacro:if>',
    '<xacro:if value="$(eval use_gpu == \'true\')"><link name="gpu"/></xacro:if>',
    '<xacro:if value="${xacro.arg(\'use_gpu\') == \'true\'}"><link name="gpu"/></xacro:if>',
    '<xacro:if value="$(arg ${\'use_\' + \'gpu\'})"><link name="gpu"/></xacro:if>',  # a computed name: any argument may be read
])
def test_an_argument_read_any_way_xacro_reads_one_is_clean(tmp_path, reading):
    model = write(tmp_path / "robot.urdf.xacro", robot(f"""
        <xacro:arg name="use_gpu" default="false"/>
        <link name="base_link"/>
        {reading}
        """))
    assert found(model, codes=("X101",)) == []


def test_an_argument_read_in_a_file_included_under_a_condition_is_clean(tmp_path):
    write(tmp_path / "gpu.xacro", library('<xacro:property name="gpu_name" value="$(arg gpu_name)"/>'))
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:arg name="gpu_name" default="none"/>
        <xacro:arg name="gpu" default="false"/>
        <link name="base_link"/>
        <xacro:if value="$(arg gpu)"><xacro:include filename="gpu.xacro"/></xacro:if>
        """))
    assert found(model, codes=("X101",)) == []  # the expansion never read gpu.xacro; its includes may


def test_a_property_used_nowhere_is_info_and_one_used_anywhere_is_not(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:property name="wheel_width" value="0.04"/>
        <xacro:property name="wheel_radius" value="0.1"/>
        <xacro:property name="wheel_origin"><origin xyz="0 0 0"/></xacro:property>
        <link name="base_link"/>
        <link name="wheel"><visual><geometry><cylinder radius="${wheel_radius}" length="0.1"/></geometry></visual></link>
        <joint name="wheel_joint" type="fixed"><parent link="base_link"/><child link="wheel"/><xacro:insert_block name="wheel_origin"/></joint>
        """))
    [info] = diagnostics(model, "X102")
    assert info.severity.value == "info" and "'wheel_width'" in info.message and info.line == line_of(model, "wheel_width")


def test_a_property_written_without_its_dollar_is_a_warning_where_it_is_written(tmp_path):
    # Stretch's joints write spring_stiffness="{joint_spring_stiffness}": the URDF gets the braces,
    # and "used nowhere, or remove it" sent the reader to delete the property instead of the typo
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:property name="damping" value="21.75"/>
        <xacro:property name="stiffness" value="0"/>
        <xacro:property name="old_damping" value="0"/>
        <!-- {old_damping} in a comment reads nothing, and is no typo -->
        <link name="base_link"/>
        <link name="wheel"/>
        <joint name="wheel_joint" type="continuous"><parent link="base_link"/><child link="wheel"/>
          <dynamics damping="${damping}" spring_stiffness="{stiffness}"/>
        </joint>
        <xacro:macro name="arm" params="prefix reach">
          <link name="${prefix}_arm" reach="{reach}"/>
        </xacro:macro>
        <xacro:arm prefix="left" reach="1"/>
        """))
    warning, info = sorted(diagnostics(model, "X102"), key=lambda d: d.severity.value, reverse=True)
    assert info.severity.value == "info" and "'old_damping'" in info.message and "without its $" not in info.message
    assert warning.severity.value == "warning" and (warning.line, warning.column) == column_of(model, "{stiffness}", "spring_stiffness")
    assert warning.message == "property 'stiffness' is written '{stiffness}', without its $: xacro copies it as text, and the value never reaches the robot"
    assert warning.hint == "write ${stiffness}"
    [parameter] = diagnostics(model, "X103")
    assert (parameter.line, parameter.column) == column_of(model, "{reach}", "reach=") and "'{reach}', without its $" in parameter.message


def test_a_library_property_another_model_of_the_workspace_uses_is_clean(tmp_path):
    (tmp_path / ".git").mkdir()
    write(tmp_path / "sizes.xacro", library('<xacro:property name="base_size" value="0.4"/><xacro:property name="mast_height" value="1.2"/>'))
    rover = write(tmp_path / "rover.urdf.xacro", robot('<xacro:include filename="sizes.xacro"/><link name="base"><visual><geometry><box size="${base_size} 1 1"/></geometry></visual></link>'))
    assert [(c, f) for c, f, *_ in found(rover, codes=("X102",))] == [("X102", "sizes.xacro")]
    write(tmp_path / "mast.urdf.xacro", robot('<xacro:include filename="sizes.xacro"/><link name="mast"><visual><geometry><box size="1 1 ${mast_height}"/></geometry></visual></link>'))
    assert found(rover, codes=("X102",)) == []


def test_a_property_read_only_as_a_macro_parameter_of_its_name_is_used_nowhere(tmp_path):
    # myCobot's exported URDFs define 'width' and read it nowhere; another package's
    # cuboid_inertial reads its own parameter 'width', which hides any property of that name
    (tmp_path / ".git").mkdir()
    write(tmp_path / "inertial.xacro", library("""
        <xacro:macro name="cuboid_inertial" params="width mass">
          <inertial><mass value="${mass}"/><inertia ixx="${mass * width * width / 6}" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
        </xacro:macro>
        <xacro:macro name="shadowed" params="">
          <xacro:property name="width" value="1"/>
          <link name="${width}"/>
        </xacro:macro>
        """))
    model = write(tmp_path / "arm.urdf", robot("""
        <xacro:property name="width" value=".2"/>
        <link name="base"/>
        """))
    [info] = diagnostics(model, "X102")
    assert "'width'" in info.message and info.line == line_of(model, "width")
    write(tmp_path / "reader.urdf.xacro", robot("""
        <xacro:include filename="arm.urdf"/>
        <xacro:macro name="plate" params="">
          <link name="plate"><visual><geometry><box size="${width} 1 1"/></geometry></visual></link>
        </xacro:macro>
        <xacro:plate/>
        """, name="reader"))
    assert found(model, codes=("X102",)) == []  # a macro body reads it where no parameter hides it


def test_a_macro_of_a_model_nothing_calls_is_info(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="bumper" params="">
          <link name="bumper_link"/>
        </xacro:macro>
        <link name="base_link"/>
        """))
    [info] = diagnostics(model, "X104")
    assert info.severity.value == "info" and "'bumper'" in info.message and info.line == line_of(model, "bumper")


def test_a_library_macro_is_noted_only_when_no_model_of_the_workspace_calls_it(tmp_path):
    root = make_repository(tmp_path / "acme")
    (root / ".git").mkdir()
    sensor = root / "common" / "urdf" / "sensor.xacro"
    assert found(sensor) == [("X104", "sensor.xacro", *column_of(sensor, 'sensor"', "xacro:macro"))]
    edit(root / "description" / "urdf" / "rover.urdf.xacro", '<link name="base_footprint"/>',
         '<link name="base_footprint"/>\n  <xacro:include filename="$(find acme_common)/urdf/sensor.xacro"/>\n  <xacro:sensor parent="base_footprint"/>')
    assert found(sensor, codes=("X104",)) == []


def test_a_computed_macro_call_counts_as_a_call_of_any_macro(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:property name="part" value="bumper"/>
        <xacro:macro name="bumper" params=""><link name="bumper_link"/></xacro:macro>
        <xacro:macro name="mast" params=""><link name="mast_link"/></xacro:macro>
        <xacro:call macro="${part}"/>
        """))
    assert found(model, codes=("X104",)) == []


# -- X103: parameters a macro never uses ------------------------------------------------
def test_an_unused_parameter_and_a_block_never_inserted_are_warnings_where_params_names_them(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="wheel" params="prefix xyz *origin">
          <link name="${prefix}_wheel"/>
          <joint name="${prefix}_joint" type="fixed"><parent link="base_link"/><child link="${prefix}_wheel"/></joint>
        </xacro:macro>
        <link name="base_link"/>
        <xacro:wheel prefix="left" xyz="0 0.2 0"><origin xyz="0 0.2 0"/></xacro:wheel>
        """))
    warnings = diagnostics(model, "X103")
    assert [(d.line, d.column) for d in warnings] == [column_of(model, "xyz", "params="), column_of(model, "*origin", "params=")]
    assert "parameter 'xyz' of macro 'wheel'" in warnings[0].message and "*origin" in warnings[1].message
    assert warnings[1].hint.startswith('insert it with <xacro:insert_block name="origin"/>')


def test_a_parameter_written_without_its_dollar_is_found_where_it_is_written(tmp_path):
    # linorobot2's skid_steer controller: <torque>{wheel_torque}</torque> gives the plugin the text, not the torque
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="drive" params="wheel_radius wheel_torque">
          <!-- {wheel_torque} in a comment is no use -->
          <gazebo><plugin name="skid" filename="libgazebo_ros_skid_steer_drive.so">
            <wheelDiameter>${wheel_radius * 2}</wheelDiameter><torque>{wheel_torque}</torque>
          </plugin></gazebo>
        </xacro:macro>
        <link name="base_link"/>
        <xacro:drive wheel_radius="0.033" wheel_torque="20"/>
        """))
    assert "<torque>{wheel_torque}</torque>" in xacro.process_file(str(model)).toxml()  # xacro copies it as written
    (warning,) = diagnostics(model, "X103")
    assert (warning.line, warning.column) == column_of(model, "{wheel_torque}", "<torque>")
    assert "'{wheel_torque}', without its $" in warning.message and warning.hint == "write ${wheel_torque}"


def test_a_yaml_file_the_model_loads_hides_no_name_from_the_source_rules(tmp_path):
    # a ros2_control macro fed by initial_positions.yaml, as MoveIt's setup assistant writes it:
    # xacro lists the YAML with its includes, and it defines and uses no xacro name
    (tmp_path / ".git").mkdir()
    write(tmp_path / "config" / "initial_positions.yaml", "initial_positions:\n  joint1: 0\n")
    control = write(tmp_path / "config" / "control.xacro", library("""
        <xacro:macro name="control" params="name initial_positions_file slowdown:=2.0">
          <xacro:property name="initial" value="${xacro.load_yaml(initial_positions_file)['initial_positions']}"/>
          <ros2_control name="${name}" type="system">
            <joint name="joint1"><state_interface name="position"><param name="initial_value">${initial['joint1']}</param></state_interface></joint>
          </ros2_control>
        </xacro:macro>
        """))
    model = write(tmp_path / "config" / "robot.urdf.xacro", robot("""
        <xacro:arg name="initial_positions_file" default="initial_positions.yaml"/>
        <xacro:include filename="control.xacro"/>
        <link name="base_link"/>
        <link name="arm"/>
        <joint name="joint1" type="continuous"><parent link="base_link"/><child link="arm"/></joint>
        <xacro:control name="FakeSystem" initial_positions_file="$(arg initial_positions_file)" slowdown="3"/>
        """))
    assert found(model, codes=("X103",)) == [("X103", "control.xacro", *column_of(control, "slowdown", "params="))]


def test_parameters_used_in_nested_macros_by_callees_or_forwarded_are_clean(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="hub" params=""><link name="${prefix}_hub"/></xacro:macro>
        <xacro:macro name="tyre" params="prefix:=^ width"><link name="${prefix}_tyre_${width}"/></xacro:macro>
        <xacro:macro name="wheel" params="prefix size *origin">
          <xacro:macro name="rim" params=""><link name="${prefix}_rim_${size}"/></xacro:macro>
          <xacro:rim/>
          <xacro:hub/>
          <xacro:tyre width="1"/>
          <joint name="${prefix}_joint" type="fixed"><parent link="base_link"/><child link="${prefix}_hub"/><xacro:insert_block name="origin"/></joint>
        </xacro:macro>
        <link name="base_link"/>
        <xacro:wheel prefix="left" size="2"><origin xyz="0 0 0"/></xacro:wheel>
        """))
    assert found(model, codes=("X103",)) == []


# The Robotiq 2F grippers' shape (ros-industrial robotiq): each variant's package defines
# the same finger macros; a shared caller passes `stroke`, which only the 140 uses.
FINGER_CALLER = '<xacro:macro name="finger_links" params="prefix stroke"><xacro:outer_knuckle prefix="${prefix}" stroke="${stroke}"/></xacro:macro>'


def gripper(root: Path, size: str, knuckle_mesh: str) -> Path:
    package = root / f"gripper_{size}"
    write(package / "package.xml", package_xml(f"gripper_{size}"))
    write(package / "urdf" / "fingers.xacro", library(FINGER_CALLER))
    write(package / "urdf" / f"model_{size}_macro.xacro", library(f"""
        <xacro:include filename="fingers.xacro"/>
        <xacro:macro name="outer_knuckle" params="prefix stroke">
          <link name="${{prefix}}outer_knuckle"><visual><geometry><mesh filename="{knuckle_mesh}"/></geometry></visual></link>
        </xacro:macro>
        <xacro:macro name="gripper_{size}" params="prefix"><xacro:finger_links prefix="${{prefix}}" stroke="{size}"/></xacro:macro>
        """))
    return write(package / "urdf" / f"model_{size}.urdf.xacro", robot(f'<xacro:include filename="model_{size}_macro.xacro"/><xacro:gripper_{size} prefix=""/>'))


def test_a_parameter_a_same_named_variant_of_the_macro_uses_is_its_interface_not_a_mistake(tmp_path):
    root = tmp_path / "robotiq"
    (root / ".git").mkdir(parents=True)
    small = gripper(root, "85", "package://gripper_85/meshes/outer_knuckle.stl")
    assert found(small, codes=("X103",)) == [("X103", "model_85_macro.xacro", *column_of(small.with_name("model_85_macro.xacro"), "stroke", "params="))]
    gripper(root, "140", "package://gripper_140/meshes/robotiq_arg2f_${stroke}_outer_knuckle.stl")
    assert found(small, codes=("X103",)) == []


def test_a_parameter_a_macro_of_the_same_parameter_list_uses_is_left_alone_where_a_call_is_computed(tmp_path):
    # clearpath's shape: every platform macro takes wheel:='default', one generic call picks the platform
    (tmp_path / ".git").mkdir()
    j100 = write(tmp_path / "j100.urdf.xacro", library('<xacro:macro name="j100" params="wheel:=\'default\'"><link name="base_link"/></xacro:macro>'))
    write(tmp_path / "a200.urdf.xacro", library('<xacro:macro name="a200" params="wheel:=\'default\'"><link name="base_link"/><link name="${wheel}_wheel"/></xacro:macro>'))
    robot_file = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:include filename="j100.urdf.xacro"/>
        <xacro:property name="platform" value="j100"/>
        <xacro:call macro="${platform}" wheel="default"/>
        """))
    assert found(j100, codes=("X103",)) == []
    edit(robot_file, '<xacro:call macro="${platform}" wheel="default"/>', '<xacro:j100 wheel="default"/>')
    assert found(j100, codes=("X103",)) == [("X103", "j100.urdf.xacro", *column_of(j100, "wheel", "params="))]


def test_a_parameter_no_macro_of_its_name_or_interface_uses_is_still_a_warning(tmp_path):
    (tmp_path / ".git").mkdir()
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="wheel" params="prefix xyz *origin">
          <link name="${prefix}_wheel"/>
          <joint name="${prefix}_joint" type="fixed"><parent link="base_link"/><child link="${prefix}_wheel"/></joint>
        </xacro:macro>
        <xacro:macro name="caster" params="prefix xyz *origin">
          <link name="${prefix}_caster"/>
        </xacro:macro>
        <link name="base_link"/>
        <xacro:property name="part" value="wheel"/>
        <xacro:call macro="${part}" prefix="left" xyz="0 0.2 0"><origin xyz="0 0.2 0"/></xacro:call>
        <xacro:caster prefix="rear" xyz="0 0 0"><origin xyz="0 0 0"/></xacro:caster>
        """))
    write(tmp_path / "other.urdf.xacro", library('<xacro:macro name="wheel" params="prefix"><link name="${prefix}_wheel"/></xacro:macro>'))
    warnings = diagnostics(model, "X103")
    assert [(d.severity.value, d.line, d.column) for d in warnings] == [
        ("warning", *column_of(model, "xyz", 'name="wheel"')), ("warning", *column_of(model, "*origin", 'name="wheel"')),
        ("warning", *column_of(model, "xyz", 'name="caster"')), ("warning", *column_of(model, "*origin", 'name="caster"')),
    ]


# -- X105: names that do not depend on a parameter --------------------------------------
NAMED_MACRO = """
    <xacro:macro name="wheel" params="side y">
      <link name="{link}"/>
      <joint name="${{side}}_wheel_joint" type="continuous">
        <parent link="base_link"/><child link="{link}"/><origin xyz="0 ${{y}} 0"/>
      </joint>
    </xacro:macro>
    <link name="base_link"/>
"""


def test_a_fixed_name_made_by_two_calls_is_an_error_naming_both_calls(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot(NAMED_MACRO.format(link="wheel_link") + """
        <xacro:wheel side="left" y="0.2"/>
        <xacro:wheel side="right" y="-0.2"/>
        """))
    [error] = diagnostics(model, "X105")
    calls = ["{}:{}:{}".format(model.name, *column_of(model, f'<xacro:wheel side="{side}"')) for side in ("left", "right")]
    assert error.severity.value == "error" and (error.line, error.column) == column_of(model, 'wheel_link"', "<link")
    assert f"its two calls (at {calls[0]} and {calls[1]})" in error.message.replace(str(tmp_path) + "/", "")
    assert "N004" in [d.code for d in urdfcli.lint([str(model)])[0].diagnostics]  # the duplicate link, as urdfdom sees it


def test_a_fixed_name_made_by_one_call_is_info(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot(NAMED_MACRO.format(link="wheel_link") + '<xacro:wheel side="left" y="0.2"/>'))
    [info] = diagnostics(model, "X105")
    assert info.severity.value == "info" and "can be called once per robot" in info.message and "${" in info.hint


def test_the_fixed_names_of_a_macro_called_once_are_one_info_at_the_first(tmp_path):
    """A vendor's robot macro names every link and joint, on purpose: one note for the
    macro, naming how many and which, not one per name (13 lines for Doosan's m1013)."""
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="arm" params="parent">
          <link name="arm_base"/>
          <joint name="arm_base_joint" type="fixed"><parent link="${parent}"/><child link="arm_base"/></joint>
          <link name="arm_tip"/>
          <joint name="arm_tip_joint" type="fixed"><parent link="arm_base"/><child link="arm_tip"/></joint>
        </xacro:macro>
        <link name="base_link"/>
        <xacro:arm parent="base_link"/>
        """))
    [info] = diagnostics(model, "X105")
    assert info.severity.value == "info" and (info.line, info.column) == column_of(model, 'arm_base"', "<link")
    assert info.message == (
        "macro 'arm' names 4 links and joints ('arm_base', 'arm_base_joint', 'arm_tip' and 1 more) whatever its parameters: it can be called once per robot"
    )
    assert info.hint == 'build the names from a parameter, such as name="${prefix}arm_base"'


def test_the_fixed_names_two_calls_make_twice_are_one_error_naming_them(tmp_path):
    """The error names what the calls make twice; a name only one call makes (under a
    condition) is not among them."""
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="wheel" params="side">
          <link name="wheel_link"/>
          <joint name="wheel_joint" type="continuous"><parent link="base_link"/><child link="wheel_link"/></joint>
          <xacro:if value="${side == 'left'}"><link name="left_only"/></xacro:if>
        </xacro:macro>
        <link name="base_link"/>
        <xacro:wheel side="left"/>
        <xacro:wheel side="right"/>
        """))
    [error] = diagnostics(model, "X105")
    calls = ["{}:{}:{}".format(model.name, *column_of(model, f'<xacro:wheel side="{side}"')) for side in ("left", "right")]
    assert error.severity.value == "error" and (error.line, error.column) == column_of(model, 'wheel_link"', "<link")
    assert error.message.replace(str(tmp_path) + "/", "") == (
        f"macro 'wheel' names 2 links and joints ('wheel_link', 'wheel_joint') whatever its parameters: its two calls (at {calls[0]} and {calls[1]}) make each of them twice"
    )


@pytest.mark.parametrize("link", ["${side}_wheel_link", "${prefix}wheel_link"])
def test_a_name_built_from_a_parameter_or_a_property_that_differs_between_calls_is_clean(tmp_path, link):
    model = write(tmp_path / "robot.urdf.xacro", robot(NAMED_MACRO.format(link=link) + """
        <xacro:property name="prefix" value="left_"/>
        <xacro:wheel side="left" y="0.2"/>
        <xacro:property name="prefix" value="right_"/>
        <xacro:wheel side="right" y="-0.2"/>
        """))
    assert found(model, codes=("X105", "N004", "N005")) == []



ATTACHED_MACRO = """
    <xacro:arg name="with_world" default="true"/>
    <xacro:macro name="arm" params="prefix attach_to create_attach_link:=true">
      <xacro:if value="{condition}">
        <link name="world"/>
        <joint name="${{prefix}}world_joint" type="fixed"><parent link="world"/><child link="${{prefix}}base"/></joint>
      </xacro:if>
      <link name="${{prefix}}base"/>
    </xacro:macro>
"""


@pytest.mark.parametrize("condition", ["${attach_to == 'world' and create_attach_link}", "${prefix == 'left_'}"])
def test_a_fixed_name_under_a_condition_on_the_parameters_is_left_alone(tmp_path, condition):
    """xArm's xarm_device macro writes <link name="world"/> under a condition on its
    parameters, and its dual arm calls the macro twice, attached to "ground": whether a
    call makes the link depends on the call, not 'whatever its parameters'."""
    model = write(tmp_path / "robot.urdf.xacro", robot(ATTACHED_MACRO.format(condition=condition) + """
        <xacro:arm prefix="left_" attach_to="world"/>
        <link name="ground"/>
        <joint name="ground_joint" type="fixed"><parent link="left_base"/><child link="ground"/></joint>
        <xacro:arm prefix="right_" attach_to="ground" create_attach_link="false"/>
        <joint name="right_joint" type="fixed"><parent link="ground"/><child link="right_base"/></joint>
        """))
    assert found(model, codes=("X105", "N004", "N005")) == []


def test_a_fixed_name_under_a_condition_on_an_argument_is_still_info(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot(ATTACHED_MACRO.format(condition="$(arg with_world)") + '<xacro:arm prefix="" attach_to="world"/>'))
    [info] = diagnostics(model, "X105")
    assert info.severity.value == "info" and info.message.startswith("macro 'arm' names link 'world' whatever its parameters")


def test_a_fixed_name_two_calls_make_under_a_condition_on_the_parameters_is_left_to_n004(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot(ATTACHED_MACRO.format(condition="${attach_to == 'world'}") + """
        <xacro:arm prefix="left_" attach_to="world"/>
        <xacro:arm prefix="right_" attach_to="world"/>
        """))
    assert [code for code, *_ in found(model, codes=("X105", "N004"))] == ["N004"]

# -- X106: names in macro bodies --------------------------------------------------------
def test_an_undefined_name_in_a_library_nothing_includes_is_a_warning_at_its_column(tmp_path):
    """A library bug: a warning at the library's line (the model loads while nothing
    evaluates the name); xacro's own error (X003) where an expansion does."""
    (tmp_path / ".git").mkdir()
    lib = write(tmp_path / "parts.xacro", library("""
        <xacro:property name="wheel_radius" value="0.1"/>
        <xacro:macro name="wheel" params="prefix">
          <link name="${prefix}_wheel"><visual><geometry><cylinder radius="${wheel_raduis}" length="${y}"/></geometry></visual></link>
        </xacro:macro>
        """))
    done = run_cli("check", "--format", "json", str(lib), cwd=tmp_path)
    assert done.returncode == 0, done.stderr.decode()
    report = json.loads(done.stdout)
    found_x106 = [d for d in report["files"][0]["diagnostics"] if d["code"] == "X106"]
    line, column = column_of(lib, "${y}")
    assert [(d["line"], d["column"], d["severity"]) for d in found_x106] == [(*column_of(lib, "wheel_raduis"), "warning"), (line, column + 2, "warning")]
    # the message says all it means: the macro is called by nothing
    assert found_x106[0]["message"] == "name 'wheel_raduis' is defined neither in macro 'wheel' nor for the whole document (nothing calls the macro)"
    [api] = diagnostics(lib, "X106")[:1]
    assert api.hint == "did you mean 'wheel_radius'?"


def test_a_model_that_never_evaluates_an_undefined_name_passes_check(tmp_path):
    """KUKA's common_materials.xacro: a macro no arm calls names a property nothing
    defines; rosbot's camera: a branch the call does not take. The models load in
    xacro and check_urdf: a warning at the library line, no error."""
    (tmp_path / ".git").mkdir()
    write(tmp_path / "materials.xacro", library("""
        <xacro:macro name="material_kuka_ral_golden"><material name="golden"><color rgba="${ral_golden}"/></material></xacro:macro>
        <xacro:macro name="camera" params="name kind">
          <link name="${name}_link"/>
          <xacro:if value="${kind == 'astra'}"><link name="${frame_id}"/></xacro:if>
        </xacro:macro>
        """))
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:include filename="materials.xacro"/>
        <link name="base_link"/>
        <xacro:camera name="front" kind="realsense"/>
        <joint name="j" type="fixed"><parent link="base_link"/><child link="front_link"/></joint>
        """))
    done = run_cli("check", "--format", "json", str(model), cwd=tmp_path)
    assert done.returncode == 0, done.stdout.decode()
    diagnostics_found = json.loads(done.stdout)["files"][0]["diagnostics"]
    assert sorted((d["code"], d["severity"], d["line"]) for d in diagnostics_found) == [
        ("X106", "warning", line_of(tmp_path / "materials.xacro", "ral_golden")),
        ("X106", "warning", line_of(tmp_path / "materials.xacro", "frame_id")),
    ]
    # an expansion that evaluates it: xacro's error, at that line, and nothing more
    write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:include filename="materials.xacro"/>
        <link name="base_link"/>
        <xacro:camera name="front" kind="astra"/>
        """))
    done = run_cli("check", "--format", "concise", str(model), cwd=tmp_path)
    assert done.returncode == 1 and " X003 error: name 'frame_id' is not defined" in done.stdout.decode()


def test_names_xacro_provides_and_names_an_expression_binds_are_clean(tmp_path):
    lib = write(tmp_path / "parts.xacro", library("""
        <xacro:macro name="part" params="n">
          <link name="p${n}"><visual><origin rpy="${pi/2} ${radians(90)} ${math.cos(0)}"/><geometry><box size="${' '.join(str(x) for x in [1, 2, 3])}"/></geometry></visual></link>
          <xacro:property name="half" value="${python.len([1]) / 2}"/>
          <link name="q${half}"/>
          <link name="r${(lambda v: v * 2)(n)}"/>
        </xacro:macro>
        """))
    assert found(lib, codes=("X106",)) == []


def test_a_name_every_call_defines_is_clean_and_one_a_call_lacks_is_an_error(tmp_path):
    (tmp_path / ".git").mkdir()
    write(tmp_path / "parts.xacro", library('<xacro:macro name="hub" params=""><link name="${side}_hub"/></xacro:macro>'))
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:include filename="parts.xacro"/>
        <xacro:macro name="wheel" params="side"><xacro:hub/></xacro:macro>
        <link name="base_link"/>
        <xacro:wheel side="left"/>
        """))
    assert found(model, codes=("X106",)) == []
    write(tmp_path / "other.urdf.xacro", robot('<xacro:include filename="parts.xacro"/><xacro:macro name="caster" params=""><xacro:hub/></xacro:macro>'))
    assert found(model, codes=("X106",)) == [("X106", "parts.xacro", *column_of(tmp_path / "parts.xacro", "side"))]


def test_an_include_that_cannot_be_followed_leaves_names_alone(tmp_path):
    lib = write(tmp_path / "parts.xacro", library("""
        <xacro:include filename="$(arg config_file)"/>
        <xacro:macro name="part" params=""><link name="${configured_name}"/></xacro:macro>
        """))
    assert found(lib, codes=("X106", "X104", "X102")) == []


def test_the_undefined_names_are_those_xacro_cannot_evaluate(tmp_path):
    """Each name judged by X106 against the real xacro: a call of the macro fails
    with NameError exactly when X106 flags the name."""
    names = ["pi", "radians", "load_yaml", "python", "xacro", "math", "sorted", "wheel_size", "prefix", "undefined_thing", "Pi", "cos", "inf"]
    flagged, failed = [], []
    for name in names:
        macro = f"""
            <xacro:property name="wheel_size" value="1"/>
            <xacro:macro name="part" params="prefix"><link name="l"><visual><geometry><box size="${{str({name})[0:1]}} 1 1"/></geometry></visual></link></xacro:macro>
            """
        lib = write(tmp_path / name / "lib" / "parts.xacro", library(macro))  # nothing calls it: only X106 can tell
        flagged += [name] if found(lib, codes=("X106",)) else []
        model = write(tmp_path / name / "model" / "robot.urdf.xacro", robot(macro + '<xacro:part prefix="a"/>'))
        xacro = subprocess.run([require_tool("xacro"), str(model)], capture_output=True, text=True)
        failed += [name] if xacro.returncode != 0 and f"name '{name}' is not defined" in xacro.stderr else []
    assert flagged == failed == ["undefined_thing", "Pi"]


def test_the_name_suggested_for_an_undefined_one_is_one_the_macro_can_see(tmp_path):
    """LMS1xx's sick_lms1xx macro reads ${mass}: the hint offered 'body_mass', a property of
    create3_sim's robot in another repository of the workspace. Only the names of the
    macro's files, and of those they include, are offered."""
    src = tmp_path / "ws" / "src"
    write(src / "create3" / "package.xml", package_xml("create3"))
    write(src / "create3" / "urdf" / "create3.urdf.xacro", robot('<xacro:property name="body_mass" value="2.3"/><link name="base_link"/>', name="create3"))
    write(src / "lms1xx" / "package.xml", package_xml("lms1xx"))
    lib = write(src / "lms1xx" / "urdf" / "sick_lms1xx.urdf.xacro", library("""
        <xacro:macro name="sick_lms1xx" params="frame">
          <link name="${frame}"><inertial><mass value="${mass}"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
        </xacro:macro>
        """))
    [warning] = diagnostics(lib, "X106")
    assert "mass" in warning.message and warning.hint == "add it to the params of macro 'sick_lms1xx', or define it with <xacro:property>"
    write(src / "lms1xx" / "urdf" / "masses.xacro", library('<xacro:property name="body_mass" value="1.1"/>'))
    edit(lib, '<xacro:macro name="sick_lms1xx"', '<xacro:include filename="masses.xacro"/><xacro:macro name="sick_lms1xx"')
    [warning] = diagnostics(lib, "X106")
    assert warning.hint == "did you mean 'body_mass'?"  # a file it includes: in its scope


def test_a_name_an_unprefixed_property_defines_is_x107s_alone(tmp_path):
    """KUKA's kr210l150_macro.xacro: <property name="deg"/> without xacro:, and ${185*deg} in
    the macro. xacro fails on the name (X003, once); the fix is the prefix (X107): no X106
    at each use, whose hint offered 'degrees'."""
    (tmp_path / ".git").mkdir()
    write(tmp_path / "arm.xacro", library("""
        <property name="deg" value="0.017453293"/>
        <xacro:macro name="arm" params="prefix">
          <link name="${prefix}base"/>
          <link name="${prefix}link_1"/>
          <joint name="${prefix}joint_a1" type="revolute">
            <parent link="${prefix}base"/><child link="${prefix}link_1"/>
            <limit lower="${-185*deg}" upper="${185*deg}" effort="0" velocity="${123*deg}"/>
          </joint>
          <link name="${prefix}link_2"/>
          <joint name="${prefix}joint_a2" type="revolute">
            <parent link="${prefix}link_1"/><child link="${prefix}link_2"/>
            <limit lower="${-45*deg}" upper="${85*deg}" effort="0" velocity="${115*deg}"/>
          </joint>
        </xacro:macro>
        """))
    model = write(tmp_path / "robot.urdf.xacro", robot('<xacro:include filename="arm.xacro"/><xacro:arm prefix=""/>'))
    real = subprocess.run([require_tool("xacro"), str(model)], capture_output=True, text=True, cwd=tmp_path)
    assert real.returncode != 0 and "name 'deg' is not defined" in real.stderr
    lib = tmp_path / "arm.xacro"
    assert found(model, codes=("X003", "X106", "X107")) == [
        ("X003", "arm.xacro", *column_of(lib, "<limit")), ("X107", "arm.xacro", line_of(lib, "<property"), 1),
    ]
    edit(lib, "<property", "<xacro:property")
    assert found(model, codes=("X003", "X106", "X107")) == []


@pytest.mark.parametrize("params", [
    "prefix parent *origin **content",
    "x:=1 y:=^ z:=^|d w:=${a * 2} v:='a b' u:=\"c d\" t:=$(arg t)",
    "\n    name\n    tf_prefix\n    initial_positions:=${dict(a=0.0,b=-1.57)}\n    keep_alive_count:=2",
    "a= b:=1 c",
])
def test_macro_parameters_are_split_as_xacro_splits_them(params):
    expected, rest = [], params
    while rest and rest.strip():
        name, value, rest = xacro.parse_macro_arg(rest)
        forward, default = value if value is not None else (None, None)
        expected.append((name.lstrip("*"), name.startswith("*"), default, forward is not None))
    assert [tuple(p) for p in macro_parameters(params)] == expected


def test_the_names_xacro_provides_come_from_xacro_in_the_worker():
    from urdfcli.session import Session

    with Session() as session:
        names = session.expander.global_names()
    assert {"pi", "radians", "load_yaml", "xacro", "python", "math", "cos"} <= names.names
    assert {"load_yaml", "arg"} <= names.members["xacro"] and "vars" not in names.members["python"]  # as the guard leaves them


# -- X107, X005: what xacro does not read, and its warnings ------------------------------
def test_an_unprefixed_include_is_a_warning_and_a_prefixed_one_or_a_plugin_tag_is_not(tmp_path):
    write(tmp_path / "arm.xacro", library('<xacro:property name="size" value="1"/>'))
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <include filename="arm.xacro"/>
        <link name="base_link"/>
        <gazebo><plugin name="p" filename="libp.so"><include filename="x"/></plugin></gazebo>
        """))
    [warning] = diagnostics(model, "X107")
    assert (warning.line, warning.column) == column_of(model, "<include")
    assert warning.hint.startswith("write <xacro:include")
    edit(model, "<include filename", "<xacro:include filename")
    assert found(model, codes=("X107",)) == []



@pytest.mark.parametrize("tag", ['<property name="deg_to_rad" value="0.017453293"/>', '<include filename="arm.xacro"/>'])
def test_a_xacro_tag_without_the_prefix_that_the_model_expands_past_is_x107s_alone(tmp_path, tag):
    """Hey5's deg_to_rad.urdf.xacro: <property> without xacro:, copied into the URDF unread.
    X107 says so at the tag; D010 'not URDF markup' on the element it left would say it again."""
    write(tmp_path / "arm.xacro", library('<xacro:property name="size" value="1"/>'))
    model = write(tmp_path / "robot.urdf.xacro", robot(f'{tag}<link name="base_link"/>'))
    codes = [d["code"] for d in json.loads(run_cli("lint", "--format", "json", "--isolated", str(model)).stdout)["files"][0]["diagnostics"]]
    assert codes == ["X107"]

def test_a_macro_called_without_the_prefix_is_a_warning_at_the_call_not_a_macro_called_nowhere(tmp_path):
    """turtlebot3_manipulation's <RefLink ref="link1"/>: xacro 2 copies it into the URDF and
    never calls the macro (its <gazebo> friction is lost). X107 at the call; no X104 'called
    nowhere', no D010 'not URDF markup' for the same element."""
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="RefLink" params="ref">
          <gazebo reference="${ref}"><mu1>0.2</mu1></gazebo>
        </xacro:macro>
        <link name="link1"/>
        <RefLink ref="link1"/>
        """))
    real = subprocess.run([require_tool("xacro"), str(model)], capture_output=True, text=True, cwd=tmp_path)
    assert real.returncode == 0 and '<RefLink ref="link1"/>' in real.stdout and "<mu1>" not in real.stdout  # never called
    [warning] = diagnostics(model, "X107")
    assert (warning.line, warning.column) == column_of(model, "<RefLink")
    assert warning.message == "<RefLink> calls macro 'RefLink' without the xacro: prefix: xacro copies it into the URDF and never calls the macro"
    codes = [d["code"] for d in json.loads(run_cli("lint", "--format", "json", "--isolated", str(model)).stdout)["files"][0]["diagnostics"]]
    assert codes == ["X107"]
    edit(model, "<RefLink ref", "<xacro:RefLink ref")
    assert found(model, codes=("X107", "X104")) == []


def test_macros_called_without_the_prefix_inside_an_uncalled_macro_are_not_called_nowhere(tmp_path):
    """turtlebot_arm's ROS 1 arm.xacro: its macro's body calls the parts of arm_hardware.xacro
    as <dynamixel_AX12_fixed .../>, and the model calls the arm as <turtlebot_arm .../>.
    xacro 2 expands none of them: X107 at the model's call says so. The parts are called
    (without the prefix) in arm.xacro, not 'called nowhere: call them, or remove them'."""
    write(tmp_path / "hardware.xacro", library("""
        <xacro:macro name="servo" params="parent name">
          <link name="${name}_link"/>
          <joint name="${name}_joint" type="fixed"><parent link="${parent}"/><child link="${name}_link"/></joint>
        </xacro:macro>
        """))
    write(tmp_path / "arm.xacro", library("""
        <xacro:include filename="hardware.xacro"/>
        <xacro:macro name="arm" params="parent">
          <servo parent="${parent}" name="pan_servo"/>
        </xacro:macro>
        """))
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:include filename="arm.xacro"/>
        <link name="base_link"/>
        <arm parent="base_link"/>
        """))
    assert found(model, codes=("X104", "X107")) == [("X107", "robot.urdf.xacro", *column_of(model, "<arm "))]


def test_an_unprefixed_insert_block_inside_a_joint_is_one_x107_at_the_tag_not_an_x103_on_the_macro(tmp_path):
    """Hey5's palm: <joint><insert_block name="origin"/></joint> in a macro's body. xacro 2
    copies the tag unread and the call's pose is lost. The mistake is the missing prefix,
    at the tag (X107, whose fix makes xacro insert the block); X103 'never inserted' on
    the macro's *origin would say the same thing again, at the wrong place."""
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="palm" params="name parent *origin">
          <joint name="${name}_joint" type="fixed">
            <parent link="${parent}"/>
            <child link="${name}_link"/>
            <insert_block name="origin"/>
          </joint>
          <link name="${name}_link"/>
        </xacro:macro>
        <link name="base_link"/>
        <xacro:palm name="palm" parent="base_link"><origin xyz="0 0.13 0"/></xacro:palm>
        """))
    real = subprocess.run([require_tool("xacro"), str(model)], capture_output=True, text=True, cwd=tmp_path)
    assert real.returncode == 0 and '<insert_block name="origin"/>' in real.stdout and "0.13" not in real.stdout
    assert found(model, codes=("X103", "X107")) == [("X107", "robot.urdf.xacro", *column_of(model, "<insert_block"))]
    run_cli("lint", "--fix", "--unsafe-fixes", "--isolated", str(model))
    assert '<xacro:insert_block name="origin"/>' in model.read_text()
    assert found(model, codes=("X103", "X107")) == []


def test_xacros_deprecation_is_located_at_the_call_with_its_fix(tmp_path):
    write(tmp_path / "c.yaml", "a: 1\n")
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:property name="cfg" value="${load_yaml('c.yaml')}"/>
        <link name="base_link"><visual><geometry><box size="${cfg['a']} 1 1"/></geometry></visual></link>
        """))
    [warning] = [d for d in diagnostics(model, "X005") if "load_yaml" in d.message]
    real = subprocess.run([require_tool("xacro"), str(model)], capture_output=True, text=True, cwd=tmp_path)
    assert warning.message in real.stderr  # xacro's own words
    assert (warning.line, warning.column) == column_of(model, "load_yaml(")
    assert warning.hint.startswith("write xacro.load_yaml(...)")


def test_a_deprecated_call_kept_for_an_older_xacro_beside_the_new_form_is_not_rewritten(tmp_path):
    """xArm's xarm7.urdf.xacro writes xacro.load_yaml() under xacro:if use_xacro_load_yaml and
    load_yaml() under its xacro:unless, for the xacro of ROS Melodic and early Noetic, which has
    no xacro.load_yaml(): the condition is what to set, and the fix would make both branches one."""
    write(tmp_path / "c.yaml", "a: 1\n")
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:property name="use_xacro_load_yaml" value="false"/>
        <xacro:if value="${use_xacro_load_yaml}">
          <xacro:property name="cfg" value="${xacro.load_yaml('c.yaml')}"/>
        </xacro:if>
        <xacro:unless value="${use_xacro_load_yaml}">
          <xacro:property name="cfg" value="${load_yaml('c.yaml')}"/>
        </xacro:unless>
        <link name="base_link"><visual><geometry><box size="${cfg['a']} 1 1"/></geometry></visual></link>
        """))
    before = model.read_text()
    [warning] = [d for d in diagnostics(model, "X005") if "load_yaml" in d.message]
    assert (warning.line, warning.column) == column_of(model, "load_yaml(", "${load_yaml")
    assert "make ${use_xacro_load_yaml} true" in warning.hint and warning.fix.edits == ()
    run_cli("lint", "--fix", "--isolated", str(model))
    assert model.read_text() == before


def test_expand_takes_inorder_and_says_it_does_nothing(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot('<link name="base_link"/>'))
    plain, inorder = run_cli("expand", str(model)), run_cli("expand", "--inorder", str(model))
    assert inorder.returncode == 0 and inorder.stdout == plain.stdout
    assert "--inorder does nothing" in inorder.stderr.decode() and "drop the option" in inorder.stderr.decode()


# -- selection, configuration and noqa apply as to any rule ------------------------------
def test_select_noqa_and_per_file_ignores_apply_to_source_rules(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:property name="unused_a" value="1"/>
        <xacro:property name="unused_b" value="2"/>  <!-- urdfcli: noqa: X102 -->
        <xacro:arg name="unused_arg" default="1"/>
        <link name="base_link"/>
        """))
    done = run_cli("lint", "--format", "json", "--select", "X102", str(model), cwd=tmp_path)
    codes = [(d["code"], d["line"]) for d in json.loads(done.stdout)["files"][0]["diagnostics"]]
    assert codes == [("X102", line_of(model, "unused_a"))]
    done = run_cli("lint", "--format", "json", "--select", "X101,X102", str(model), cwd=tmp_path)
    assert done.returncode == 1 and {d["code"] for d in json.loads(done.stdout)["files"][0]["diagnostics"]} == {"X101", "X102"}
    write(tmp_path / "pyproject.toml", '[tool.urdfcli.per-file-ignores]\n"robot.urdf.xacro" = ["X101"]\n')
    done = run_cli("lint", "--format", "json", "--select", "X101,X102", str(model), cwd=tmp_path)
    assert done.returncode == 0 and {d["code"] for d in json.loads(done.stdout)["files"][0]["diagnostics"]} == {"X102"}


def test_a_model_that_does_not_expand_still_has_its_sources_linted_and_configured(tmp_path):
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:arg name="unused_arg" default="1"/>
        <xacro:macro name="m" params=""><link name="${nowhere}"/></xacro:macro>
        <link name="${undefined_at_top}"/>
        """))
    codes = [d.code for d in urdfcli.lint([str(model)], config=Config.everything())[0].diagnostics]
    assert codes.count("X003") == 1 and "X101" in codes and "X106" in codes
    codes = [d.code for d in urdfcli.lint([str(model)], select=["X003"])[0].diagnostics]
    assert codes == ["X003"]  # why nothing was checked is always said; the source rules are selected away


# -- the real layouts of the suite ---------------------------------------------------------
def test_the_repository_layouts_draw_no_source_finding_until_a_mistake_is_made(tmp_path):
    root = make_repository(tmp_path / "acme_robots")
    (root / ".git").mkdir()
    models = [root / "description/urdf/rover.urdf.xacro"]
    wheel = root / "common/urdf/wheel.xacro"
    before = found(*models, wheel)
    assert before == [], before
    edit(wheel, 'params="prefix parent radius *origin"', 'params="prefix parent radius offset *origin"')
    edit(wheel, '<axis xyz="0 0 1"/>', '<axis xyz="0 0 1"/>\n      <limit effort="${max_effort}" velocity="1"/>')
    assert found(wheel) == [
        ("X103", "wheel.xacro", *column_of(wheel, "offset", "params=")),
        ("X106", "wheel.xacro", *column_of(wheel, "max_effort")),
    ]


def test_a_urdf_file_written_in_xacro_is_a_note_and_one_that_only_declares_the_namespace_is_not(tmp_path):
    """TurtleBot3's ROS 2 turtlebot3_burger.urdf reads $(arg namespace): check_urdf, given the
    file, names the link '$(arg namespace)base_link', urdfcli its expansion 'base_link'."""
    text = ('<robot name="tb" xmlns:xacro="http://ros.org/wiki/xacro">\n  <xacro:arg name="namespace" default=""/>\n'
            '  <link name="$(arg namespace)base_link"/>\n</robot>\n')
    for name, expected in (("tb.urdf", ["X108"]), ("tb.urdf.xacro", [])):
        path = write(tmp_path / name, text)
        assert [code for code, *_ in found(path, codes=("X108",))] == expected, name
    real = subprocess.run([require_tool("check_urdf"), str(tmp_path / "tb.urdf")], capture_output=True, text=True)
    assert "root Link: $(arg namespace)base_link" in real.stdout
    declared = write(tmp_path / "plain.urdf", '<robot name="p" xmlns:xacro="http://ros.org/wiki/xacro"><link name="base_link"/></robot>\n')
    assert found(declared, codes=("X108",)) == []


def test_a_urdf_named_as_xacro_output_is_told_the_xacro_name(tmp_path):
    """gz_ros2_control's demos: test_diff_drive.xacro.urdf reads $(arg namespace); its xacro
    name is test_diff_drive.urdf.xacro, not test_diff_drive.xacro.urdf.xacro."""
    text = ('<robot name="d" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:arg name="namespace" default=""/>\n'
            '  <link name="$(arg namespace)chassis"/>\n</robot>\n')
    hints = {}
    for name in ("test_diff_drive.xacro.urdf", "tb.urdf"):
        [note] = diagnostics(write(tmp_path / name, text), "X108")
        hints[name] = note.hint
    assert hints == {
        "test_diff_drive.xacro.urdf": "name it test_diff_drive.urdf.xacro, and give readers its expansion (urdfcli expand test_diff_drive.xacro.urdf)",
        "tb.urdf": "name it tb.urdf.xacro, and give readers its expansion (urdfcli expand tb.urdf)",
    }


def test_the_fixed_names_of_a_macro_without_parameters_are_not_said_to_ignore_them(tmp_path):
    """ros2_control_demos' r6bot_description takes no parameters: the note says so, and its
    hint does not ask to build the names from a parameter it lacks."""
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="arm">
          <link name="arm_base"/>
          <joint name="arm_base_joint" type="fixed"><parent link="base_link"/><child link="arm_base"/></joint>
        </xacro:macro>
        <link name="base_link"/>
        <xacro:arm/>
        """))
    [info] = diagnostics(model, "X105")
    assert (info.severity.value, info.message, info.hint) == (
        "info",
        "macro 'arm' names 2 links and joints ('arm_base', 'arm_base_joint') and takes no parameters: it can be called once per robot",
        'give it a parameter and build the names from it, such as name="${prefix}arm_base"',
    )


def test_a_urdf_whose_only_xacro_is_a_property_nothing_reads_is_told_to_drop_it_not_to_be_renamed(tmp_path):
    """myCobot's exported URDFs start with <xacro:property name="width" value=".2"/> and read it
    nowhere: readers skip the element and load what xacro makes, so only X102 has something to say."""
    text = ('<robot name="firefighter" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:property name="width" value=".2"/>\n'
            '  <link name="base"/>\n  <link name="link1"/>\n'
            '  <joint name="j1" type="continuous"><parent link="base"/><child link="link1"/></joint>\n</robot>\n')
    model = write(tmp_path / "arm.urdf", text)
    assert [code for code, *_ in found(model, codes=("X102", "X108"))] == ["X102"]
    real = subprocess.run([require_tool("check_urdf"), str(model)], capture_output=True, text=True)
    assert real.returncode == 0 and "root Link: base has 1 child(ren)" in real.stdout
    read = write(tmp_path / "read.urdf", text.replace('<link name="link1"/>', '<link name="link1"><visual><geometry><box size="${width} 1 1"/></geometry></visual></link>'))
    assert [code for code, *_ in found(read, codes=("X102", "X108"))] == ["X108"]
    condition = write(tmp_path / "condition.urdf", text.replace('<link name="link1"/>', '<xacro:if value="false"><link name="extra"/></xacro:if><link name="link1"/>'))
    assert "X108" in [code for code, *_ in found(condition, codes=("X108",))]


def test_parameters_a_file_included_in_the_body_reads_are_used(tmp_path):
    # the RexROV's shape (uuv_simulator): rexrov_base includes its sensors file inside the
    # macro, and that file's top level reads the macro's parameters
    write(tmp_path / "sensors.xacro", library("""
        <link name="${namespace}/imu_link"/>
        <joint name="${namespace}/imu_joint" type="fixed">
          <parent link="${namespace}/base_link"/><child link="${namespace}/imu_link"/>
          <origin xyz="0 0 0" rpy="0 0 0"/>
        </joint>
        <gazebo><plugin name="imu" filename="libimu.so"><frame>${inertial_reference_frame}</frame></plugin></gazebo>
        """))
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="base" params="namespace inertial_reference_frame unused">
          <link name="${namespace}/base_link"/>
          <xacro:include filename="sensors.xacro"/>
        </xacro:macro>
        <xacro:base namespace="rov" inertial_reference_frame="world" unused="1"/>
        """))
    assert found(model, codes=("X103",)) == [("X103", "robot.urdf.xacro", *column_of(model, "unused", "params="))]


def test_a_macro_parameter_named_like_a_global_symbol_is_named_as_a_parameter(tmp_path):
    # uuv_simulator's pressure sensor macro takes `range` (its saturation, kPa): xacro warns
    # at the call, and the name to change is the macro's parameter, not a property
    model = write(tmp_path / "robot.urdf.xacro", robot("""
        <xacro:macro name="pressure" params="range">
          <link name="pressure_link"><visual><geometry><box size="0.1 0.1 ${range / 300000}"/></geometry></visual></link>
        </xacro:macro>
        <xacro:pressure range="30000"/>
        """))
    [warning] = [d for d in diagnostics(model, "X005") if "range" in d.message]
    assert (warning.line, warning.column) == column_of(model, "<xacro:pressure ")
    assert warning.hint.startswith("rename parameter 'range' of macro 'pressure'") and "property" not in warning.hint
    redefined = write(tmp_path / "property.urdf.xacro", robot("""
        <xacro:property name="range" value="3"/>
        <link name="base_link"/>
        """))
    [warning] = [d for d in diagnostics(redefined, "X005") if "range" in d.message]
    assert warning.hint.startswith("rename the property")
