"""Hints that finish the job: each names the fix, and following it works."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import example_robot_data, run_cli


def diagnostics(*args: str, cwd: Path | None = None, env: dict | None = None) -> list[dict]:
    """Each diagnostic of the text output: its code, message and hint."""
    done = run_cli(*args, cwd=cwd, env=env)
    found = []
    report = done.stdout if args[0] == "lint" else done.stderr  # lint writes its report on standard output
    for line in report.decode().splitlines():
        match = re.match(r"\S+:\d+:\d+: (\w+) \w+: (.*)$", line)
        if match:
            found.append({"code": match.group(1), "message": match.group(2), "hint": None})
        elif line.startswith("    hint: "):
            found[-1]["hint"] = line.removeprefix("    hint: ")
    return found


def test_non_unit_axis_hint_gives_the_normalised_axis(tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="continuous">'
                    '<parent link="a"/><child link="b"/><axis xyz="1 1 0"/></joint></robot>')
    [found] = diagnostics("lint", "--select", "J011", str(path))
    assert found["hint"] == 'normalised: <axis xyz="0.707107 0.707107 0"/>'


def missing_link_hints(path: Path) -> dict[str, str]:
    """Each missing link J005 names -> its hint."""
    return {d["message"].split("'")[1]: d["hint"] for d in diagnostics("check", str(path)) if d["code"] == "J005"}


def test_missing_link_hint_names_the_closest_links(tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="base_link"/><link name="left_wheel"/><link name="right_wheel"/>'
                    '<joint name="j" type="fixed"><parent link="base_lnk"/><child link="left_wheel"/></joint>'
                    '<joint name="k" type="fixed"><parent link="base_link"/><child link="rigth_wheel"/></joint>'
                    '<joint name="m" type="fixed"><parent link="base_link"/><child link="zzz"/></joint></robot>')
    hints = missing_link_hints(path)
    assert hints["base_lnk"] == "did you mean 'base_link'?"
    assert hints["rigth_wheel"].startswith("did you mean 'right_wheel'")
    assert hints["zzz"] == 'every link a joint names must be defined: add <link name="zzz"/> or fix the name'
    # never the joint's other end: a joint does not join a link to itself
    path.write_text('<robot name="r"><link name="base"/><link name="wrist_1_link"/><link name="wrist_2_link"/>'
                    '<joint name="j" type="fixed"><parent link="base"/><child link="wrist_2_link"/></joint>'
                    '<joint name="k" type="fixed"><parent link="wrist_1_lnk"/><child link="wrist_2_link"/></joint></robot>')
    hints = missing_link_hints(path)
    assert hints["wrist_1_lnk"] == "did you mean 'wrist_1_link'?"


def test_missing_link_hint_names_no_link_that_would_close_a_loop_or_give_two_parents(tmp_path):
    """franka_description with no_prefix:=true: the hand joint names 'fr3_link8', the arm's
    flange is 'link8', and the closest name was the hand's own finger, which hangs below
    the hand: a loop. A missing child is never a link above the parent, nor one another
    joint already moves."""
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="link7"/><link name="link8"/><link name="fr3_hand"/><link name="fr3_leftfinger"/>'
                    '<joint name="joint8" type="fixed"><parent link="link7"/><child link="link8"/></joint>'
                    '<joint name="fr3_hand_joint" type="fixed"><parent link="fr3_link8"/><child link="fr3_hand"/></joint>'
                    '<joint name="fr3_finger_joint1" type="fixed"><parent link="fr3_hand"/><child link="fr3_leftfinger"/></joint></robot>')
    hints = missing_link_hints(path)
    assert hints["fr3_link8"] == 'every link a joint names must be defined: add <link name="fr3_link8"/> or fix the name'
    path.write_text('<robot name="r"><link name="base_link"/><link name="arm_link"/><link name="arm_link_2"/><link name="tool_link"/>'
                    '<joint name="a" type="fixed"><parent link="base_link"/><child link="arm_link"/></joint>'
                    '<joint name="b" type="fixed"><parent link="arm_link"/><child link="arm_lnk_2"/></joint>'
                    '<joint name="c" type="fixed"><parent link="base_link"/><child link="tool_link"/></joint></robot>')
    hints = missing_link_hints(path)
    assert hints["arm_lnk_2"] == "did you mean 'arm_link_2'?"  # a root of its own: no loop, one parent
    path.write_text(path.read_text().replace('<child link="arm_lnk_2"/>', '<child link="bse_link"/>'))
    hints = missing_link_hints(path)
    assert not hints["bse_link"].startswith("did you mean"), hints  # base_link is above arm_link: a loop


def test_a_parameter_the_macro_lacks_is_named_with_the_one_meant(tmp_path):
    """franka_description's franka_robot macro calls ee_with_one_link with rpy=..., whose
    parameter is rpy_ee: xacro says only 'Invalid parameter "rpy"'. The hint names the macro
    and the parameter meant, else the parameters it has (never a block, given as content)."""
    path = tmp_path / "r.urdf.xacro"
    macro = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
             '  <xacro:macro name="ee_with_one_link" params="arm_id rpy_ee:=\'0 0 0\' **geometry"><link name="${arm_id}_ee"/></xacro:macro>\n'
             '  <xacro:ee_with_one_link arm_id="fr3" CALL><geometry/></xacro:ee_with_one_link>\n</robot>\n')
    path.write_text(macro.replace("CALL", 'rpy="0 0 0"'))
    [found] = diagnostics("check", str(path))
    assert (found["code"], found["message"]) == ("X003", 'Invalid parameter "rpy"')
    assert found["hint"] == "macro 'ee_with_one_link' has no parameter 'rpy': did you mean 'rpy_ee'?"
    path.write_text(macro.replace("CALL", 'colour="red"'))
    [found] = diagnostics("check", str(path))
    assert found["hint"] == "macro 'ee_with_one_link' has no parameter 'colour'; its parameters: arm_id, rpy_ee"


def test_undefined_argument_hint_works_on_the_command_line_and_in_pyproject(tmp_path):
    path = tmp_path / "arm.urdf.xacro"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="$(arg prefix)base"/>\n</robot>\n')
    [found] = diagnostics("check", str(path), cwd=tmp_path)
    assert found["code"] == "X003" and "pass prefix:=VALUE" in found["message"]
    snippet = '[tool.urdfcli.xacro-args] "arm.urdf.xacro" = { prefix = "VALUE" }'
    assert snippet in found["hint"]
    assert run_cli("check", str(path), "prefix:=left_", cwd=tmp_path).returncode == 0
    table, entry = snippet.split("] ", 1)
    (tmp_path / "pyproject.toml").write_text(f"{table}]\n{entry.replace('VALUE', 'left_')}\n")
    done = run_cli("tree", str(path), cwd=tmp_path)
    assert done.returncode == 0 and done.stdout.decode().startswith("left_base")


def package(folder: Path, name: str) -> Path:
    folder.mkdir(parents=True)
    (folder / "package.xml").write_text(f"<package format='3'><name>{name}</name></package>")
    (folder / "meshes").mkdir()
    (folder / "meshes" / "a.stl").write_text("solid a\nendsolid a\n")
    return folder


def model(folder: Path, uri: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "r.urdf"
    path.write_text(f'<robot name="r"><link name="a"><visual><geometry><mesh filename="{uri}"/></geometry></visual></link></robot>')
    return path


def test_package_named_by_its_folder_says_which_package_the_folder_holds(tmp_path):
    folder = package(tmp_path / "share" / "my-robot-data", "my_robot_descriptions")
    path = model(tmp_path / "elsewhere", "package://my-robot-data/meshes/a.stl")
    [found] = diagnostics("lint", "--select", "D005", "-P", str(tmp_path / "share"), str(path))
    assert f"the folder {folder} holds the package named 'my_robot_descriptions'" in found["hint"]
    fixed = model(tmp_path / "fixed", "package://my_robot_descriptions/meshes/a.stl")
    assert diagnostics("lint", "--select", "D004,D005", "-P", str(tmp_path / "share"), str(fixed)) == []


@pytest.mark.parametrize(
    ("layout", "uri", "folder"),
    [
        ("onshape-to-robot: the meshes in assets/ beside the URDF", "package://assets/a.stl", "robot/assets"),
        ("a package without package.xml, the URDF in urdf/", "package://arm_description/meshes/a.stl", "robot"),
    ],
)
def test_an_export_whose_package_is_its_own_folder_is_told_the_folder_to_give(tmp_path, layout, uri, folder):
    """Following the hint finds the mesh: the diagnostic is gone."""
    mesh = tmp_path / "robot" / ("assets/a.stl" if "assets" in uri else "meshes/a.stl")
    mesh.parent.mkdir(parents=True)
    mesh.write_text("solid a\nendsolid a\n")
    path = model(tmp_path / "robot" / ("" if "assets" in uri else "urdf"), uri)
    [found] = diagnostics("lint", "--select", "D005", str(path.relative_to(tmp_path)), cwd=tmp_path, env={"AMENT_PREFIX_PATH": "", "ROS_PACKAGE_PATH": ""})
    package_name = uri.split("/")[2]
    assert found["hint"] == f"the folder {folder} holds {uri.split('/', 3)[3]}: give -P {package_name}={folder}"
    given = diagnostics("lint", "--select", "D004,D005", "-P", f"{package_name}={folder}", str(path.relative_to(tmp_path)), cwd=tmp_path)
    assert given == []


def test_example_robot_data_folder_holds_example_robot_descriptions():
    path = example_robot_data() / "robots" / "ur_description" / "urdf" / "ur5_robot.urdf"
    found = diagnostics("lint", "--select", "D005", str(path), env={"AMENT_PREFIX_PATH": "", "ROS_PACKAGE_PATH": ""})
    assert len(found) == 1 and "package 'example-robot-data' not found" in found[0]["message"]
    assert "holds the package named 'example_robot_descriptions'" in found[0]["hint"]


@pytest.mark.parametrize("where", ["package-path", "ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH", "next to the input"])
def test_empty_package_name_is_one_diagnostic_in_every_look_up(tmp_path, where):
    prefix = tmp_path / "prefix"
    package(prefix / "share" / "meshes_pkg", "meshes_pkg")
    args, env = [], {"AMENT_PREFIX_PATH": "", "ROS_PACKAGE_PATH": ""}
    if where == "package-path":
        args = ["-P", str(prefix / "share")]
    elif where == "ROS_PACKAGE_PATH":
        env["ROS_PACKAGE_PATH"] = str(prefix / "share")
    elif where == "AMENT_PREFIX_PATH":
        env["AMENT_PREFIX_PATH"] = str(prefix)  # PREFIX/share/ exists: it must not answer an empty name
    folder = prefix / "share" / "meshes_pkg" / "urdf" if where == "next to the input" else tmp_path / "alone"
    path = model(folder, "package:///meshes/a.stl")
    found = diagnostics("lint", "--select", "D004,D005", *args, str(path), env=env)
    assert [(d["code"], d["message"].split(": ")[-1]) for d in found] == [("D005", "the package name is empty")]


def test_a_package_uri_in_a_xacro_include_hint_gives_the_find_that_works(tmp_path):
    """xacro joins an <xacro:include> filename to the including file's folder and reads no
    package:// URI there (example-robot-data's quadrotor_base.xacro): the real xacro fails as
    urdfcli does, the hint names $(find PKG)/..., and with it written both expand the model."""
    from differential import PACKAGES, canonical, real_xacro

    source = (Path(PACKAGES["urdf01_rviz"]) / "urdf" / "xacro" / "car_find.urdf.xacro").read_text()
    path = tmp_path / "car.urdf.xacro"
    path.write_text(source.replace("$(find urdf01_rviz)/urdf/xacro/demo05", "package://urdf01_rviz/urdf/xacro/demo05"))
    real = real_xacro(path)
    assert real.returncode != 0 and "package://urdf01_rviz/urdf/xacro/demo05_car_base.urdf.xacro" in real.stderr
    packages = [arg for name, folder in PACKAGES.items() for arg in ("-P", f"{name}={folder}")]
    [found] = diagnostics("check", *packages, str(path), cwd=tmp_path)
    # the URI as written, not the path xacro made of it ('package:/urdf01_rviz/...' beside the file)
    assert found["code"] == "X003" and found["message"] == "cannot include package://urdf01_rviz/urdf/xacro/demo05_car_base.urdf.xacro: No such file or directory"
    assert found["hint"] == "xacro reads no package:// URI in <xacro:include>: write $(find urdf01_rviz)/urdf/xacro/demo05_car_base.urdf.xacro"
    path.write_text(source.replace("$(find urdf01_rviz)/urdf/xacro/demo05", found["hint"].split("write ")[1].removesuffix("demo05_car_base.urdf.xacro") + "demo05"))
    mine = run_cli("expand", *packages, str(path), cwd=tmp_path)
    assert mine.returncode == 0 and canonical(mine.stdout.decode()) == canonical(real_xacro(path).stdout)
    # any other include that is not there says no more than xacro does
    path.write_text(source.replace("$(find urdf01_rviz)/urdf/xacro/demo05", "urdf/xacro/demo05"))
    [found] = diagnostics("check", *packages, str(path), cwd=tmp_path)
    assert found["code"] == "X003" and found["hint"] is None


def test_undefined_argument_hint_names_a_file_whose_name_others_share_by_its_path(tmp_path):
    """unitree_ros has a robot.xacro per robot, each needing DEBUG: the hint's glob "robot.xacro"
    would give every one of them the value. It names the file by its path from the folder of
    the configuration (the repository's, when there is none), and the snippet works as shown."""
    (tmp_path / ".git").mkdir()
    for name in ("go1", "a1"):
        folder = tmp_path / "robots" / f"{name}_description" / "xacro"
        folder.mkdir(parents=True)
        (folder / "robot.xacro").write_text(f'<robot name="{name}" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                            '  <link name="base"/>\n  <xacro:if value="$(arg DEBUG)"><link name="world"/></xacro:if>\n</robot>\n')
    go1 = "robots/go1_description/xacro/robot.xacro"
    [found] = diagnostics("check", "go1_description/xacro/robot.xacro", cwd=tmp_path / "robots")  # from the repository's folder, wherever it runs
    snippet = f'[tool.urdfcli.xacro-args] "{go1}" = {{ DEBUG = "VALUE" }}'
    assert found["code"] == "X003" and found["message"].endswith("pass DEBUG:=VALUE, or give it in the configuration")
    assert snippet in found["hint"], found["hint"]
    table, entry = snippet.split("] ", 1)
    (tmp_path / "pyproject.toml").write_text(f"{table}]\n{entry.replace('VALUE', 'false')}\n")
    assert run_cli("check", go1, cwd=tmp_path).returncode == 0
    [found] = diagnostics("check", "robots/a1_description/xacro/robot.xacro", cwd=tmp_path)  # the other robot is not given it
    assert found["code"] == "X003" and "\"robots/a1_description/xacro/robot.xacro\" = { DEBUG = \"VALUE\" }" in found["hint"]


@pytest.mark.parametrize("where", ["included", "own"])
def test_a_name_given_by_a_property_without_the_xacro_prefix_says_where_that_tag_is(tmp_path, where):
    """Hey5's deg_to_rad.urdf.xacro defines <property name="deg_to_rad">, xacro 1's spelling,
    which xacro 2 copies unread: the expression using it fails, and its hint names that tag
    (check runs no X107); written with the prefix, as the hint says, the model expands."""
    definition = '  <property name="deg_to_rad" value="0.017453293"/>\n'
    (tmp_path / "d.xacro").write_text(f'<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n{definition}</robot>\n')
    model = tmp_path / "r.urdf.xacro"
    head = '  <xacro:include filename="d.xacro"/>\n' if where == "included" else definition
    model.write_text(
        f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{head}'
        '  <link name="a"/><link name="b"/>\n'
        '  <joint name="j" type="fixed"><parent link="a"/><child link="b"/><origin rpy="0 ${90 * deg_to_rad} 0"/></joint>\n</robot>\n'
    )
    [found] = diagnostics("check", "r.urdf.xacro", cwd=tmp_path)
    place = "d.xacro:2" if where == "included" else "r.urdf.xacro:2"
    assert (found["code"], found["hint"]) == ("X003", f'<property name="deg_to_rad"> ({place}) is written without xacro:, which xacro 2 copies unread: write <xacro:property>')
    for file in (tmp_path / "d.xacro", model):
        file.write_text(file.read_text().replace("<property ", "<xacro:property "))
    assert diagnostics("check", "r.urdf.xacro", cwd=tmp_path) == []


def test_a_macro_called_above_its_definition_is_said_to_be_defined_below(tmp_path):
    """The Allegro hand's description calls <xacro:finger> at the top and defines it at the
    bottom, as xacro.py of ROS 1 read it; xacro 2 reads in order and knows no such macro yet.
    The hint says where the definition is; moved above the call, the model expands."""
    call = '  <xacro:finger n="0"/>\n'
    definition = '  <xacro:macro name="finger" params="n">\n    <link name="link_${n}"/>\n  </xacro:macro>\n'
    model = tmp_path / "r.urdf.xacro"
    model.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{call}{definition}</robot>\n')
    [found] = diagnostics("check", "r.urdf.xacro", cwd=tmp_path)
    assert (found["code"], found["hint"]) == (
        "X003", "macro 'finger' is defined below this call, at line 3: xacro reads a file from top to bottom; move the definition above its first call")
    model.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{definition}{call}</robot>\n')
    assert diagnostics("check", "r.urdf.xacro", cwd=tmp_path) == []
    model.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{call}</robot>\n')
    [found] = diagnostics("check", "r.urdf.xacro", cwd=tmp_path)
    assert found["code"] == "X003" and found["hint"] is None  # a macro defined nowhere: nothing to move
