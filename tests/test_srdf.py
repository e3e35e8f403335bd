"""MoveIt's SRDF: recognised by name and by content, never checked as a URDF, and checked
against the URDF of its robot (found in its package or workspace, or given with --urdf),
each finding at the SRDF line where the name was written. The MoveIt config packages are
those of the test workspace (tests/ros_ws), built like panda_moveit_config and ur_moveit_config."""

from __future__ import annotations

import json
import shutil

import pytest
from conftest import example_robot_data, run_cli
from ros_workspace import edit, line_of, make_ros_workspace, moveit_repository

PANDA = "src/panda_moveit_config/config"


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    return make_ros_workspace(tmp_path_factory.mktemp("ros"))


@pytest.fixture
def workspace(built, tmp_path):
    """A copy of the workspace to change (its root: the folder holding src/)."""
    root = tmp_path / "ws"
    shutil.copytree(built.parent, root)
    return root


def check(*args, cwd):
    done = run_cli("check", "--format", "json", *args, cwd=cwd)
    return done, json.loads(done.stdout or b"null")


VARIANT = "for another variant of the model, give its xacro arguments after the SRDF (NAME:=VALUE)"


def found(document) -> list[tuple[str, str, int, int]]:
    return [(d["code"], d["path"], d["line"], d["column"]) for f in document["files"] for d in f["diagnostics"]]


def test_a_moveit_config_checks_clean(built):
    """panda_moveit_config: its SRDF macros (panda_arm.xacro, hand.xacro), the .srdf.xacro
    files that call them, and the generated panda.srdf: no R004 'no <link>', no note on
    <group> or <disable_collisions>, each checked against the URDF of robot 'panda'. lint
    says one thing, once: hand.xacro writes <passive_joint> inside <group> (as franka_ros2's
    does), where MoveIt does not read it."""
    files = [f"{PANDA}/panda_arm.xacro", f"{PANDA}/hand.xacro", f"{PANDA}/panda_arm.srdf.xacro", f"{PANDA}/panda_arm_hand.srdf.xacro", f"{PANDA}/panda.srdf"]
    done, document = check(*files, cwd=built.parent)
    assert done.returncode == 0 and found(document) == []
    lint = run_cli("lint", "--format", "concise", *files, cwd=built.parent)
    assert lint.returncode == 1
    assert lint.stdout.decode().splitlines() == [
        f"{PANDA}/hand.xacro:9:7: K009 warning: <passive_joint> is not read inside <group>; MoveIt ignores it "
        f"(in macro 'hand' called at {PANDA}/panda_arm_hand.srdf.xacro:11:3; hint: <passive_joint> belongs directly in <robot>)",
    ]
    text = run_cli("check", f"{PANDA}/panda.srdf", cwd=built.parent)
    assert text.stdout.decode() == (
        "SRDF of robot: panda\n3 groups, 4 group states, 1 end effector; checked against src/panda_moveit_config/config/panda.urdf.xacro\n"
    )


def test_each_name_is_checked_at_the_srdf_line_that_gives_it(workspace):
    arm, hand = workspace / PANDA / "panda_arm.xacro", workspace / PANDA / "panda_arm_hand.srdf.xacro"
    edit(arm, 'tip_link="${arm_id}_link8"', 'tip_link="${arm_id}_link9"')  # K001, in the macro
    edit(arm, '<joint name="${arm_id}_joint4" value="-2.356" />', '<joint name="${arm_id}_joint4" value="-0.01" />')  # K005
    edit(arm, 'child_link="${arm_id}_link0"', 'child_link="${arm_id}_link1"')  # K007
    edit(hand, 'group="hand" parent_group', 'group="hands" parent_group')  # K003
    edit(hand, 'link1="$(arg arm_id)_hand" link2="$(arg arm_id)_link3"', 'link1="$(arg arm_id)_hand" link2="$(arg arm_id)_link33"')  # K001
    edit(hand, "</robot>", '  <group name="wrist"><chain base_link="$(arg arm_id)_link7" tip_link="$(arg arm_id)_link5"/></group>\n'
                           '  <passive_joint name="$(arg arm_id)_finger_joint3"/>\n</robot>')  # K004, K002
    done, document = check(f"{PANDA}/panda_arm_hand.srdf.xacro", cwd=workspace)
    assert done.returncode == 1
    arm_file, hand_file = f"{PANDA}/panda_arm.xacro", f"{PANDA}/panda_arm_hand.srdf.xacro"
    assert sorted(found(document)) == sorted([
        ("K001", arm_file, line_of(arm, "_link9"), 42),  # at tip_link=, where the name is written
        ("K005", arm_file, line_of(arm, 'value="-0.01"'), 38),
        ("K007", arm_file, line_of(arm, "<virtual_joint"), 78),
        ("K003", hand_file, line_of(hand, 'group="hands"'), 63),
        ("K001", hand_file, line_of(hand, "_link33"), 50),
        ("K004", hand_file, line_of(hand, '<group name="wrist">'), 23),
        ("K002", hand_file, line_of(hand, "finger_joint3"), 18),
    ])
    messages = {d["code"]: d["message"] for f in document["files"] for d in f["diagnostics"]}
    assert messages["K005"] == "group state 'ready' sets joint 'panda_joint4' to -0.01, outside its limits [-3.0718, -0.0698] rad"
    assert messages["K007"] == f"virtual joint 'virtual_joint' has child 'panda_link1', but the root link of {PANDA}/panda.urdf.xacro is 'panda_link0'"
    assert messages["K004"] == "the chain of group 'wrist' runs from 'panda_link7' to 'panda_link5', but 'panda_link5' is not below 'panda_link7' in the URDF"
    hints = {d["code"]: d["hint"] for f in document["files"] for d in f["diagnostics"]}
    assert hints["K004"] == "swap base_link and tip_link" and hints["K003"] == "did you mean 'hand'?"
    # a macro's finding says which call made it
    trace = next(d["trace"] for f in document["files"] for d in f["diagnostics"] if d["code"] == "K005")
    assert trace[0]["path"] == hand_file and trace[0]["macro"] == "panda_arm"


def test_the_generated_srdf_is_checked_too(workspace):
    srdf = workspace / PANDA / "panda.srdf"
    edit(srdf, '<joint name="panda_finger_joint1"/>', '<joint name="panda_finger_joint_1"/>')
    done, document = check(f"{PANDA}/panda.srdf", cwd=workspace)
    assert done.returncode == 1
    assert found(document) == [("K002", f"{PANDA}/panda.srdf", line_of(srdf, "panda_finger_joint_1"), 12)]
    assert document["files"][0]["diagnostics"][0]["hint"] == "did you mean 'panda_finger_joint1'?"


def test_a_link_the_urdf_has_with_a_prefix_cut_off_is_no_suggestion(workspace):
    """Doosan's m1013.srdf names 'robotiq_85_base_link', a gripper link its URDF lacks:
    'base_link', the robot's base, is not the fix. A misspelt link still gets its hint."""
    srdf = workspace / PANDA / "panda.srdf"
    edit(srdf, "</robot>", '  <disable_collisions link1="robotiq_85_panda_hand" link2="panda_link7" reason="Never"/>\n'
                           '  <disable_collisions link1="panda_hnd" link2="panda_link6" reason="Never"/>\n</robot>')
    done, document = check(f"{PANDA}/panda.srdf", cwd=workspace)
    hints = {d["message"].split("'")[1]: d["hint"] for f in document["files"] for d in f["diagnostics"] if d["code"] == "K001"}
    assert hints == {
        "robotiq_85_panda_hand": f"use a link of {PANDA}/panda.urdf.xacro, or check that the SRDF is for this robot; {VARIANT}",
        "panda_hnd": "did you mean 'panda_hand'?",
    }


def test_urdf_option_names_the_urdf_and_a_mismatch_is_said(built):
    root = built.parent
    done, document = check("--urdf", "src/franka_ros/franka_description/robots/panda/panda.urdf", f"{PANDA}/panda.srdf", cwd=root)
    assert done.returncode == 0 and found(document) == []
    done, document = check("--urdf", "src/pr2_common/pr2_description/robots/pr2.urdf.xacro", f"{PANDA}/panda.srdf", cwd=root)
    codes = [d["code"] for d in document["files"][0]["diagnostics"]]
    assert done.returncode == 1 and codes[0] == "K008" and set(codes[1:]) == {"K001", "K002"}
    first = document["files"][0]["diagnostics"][0]
    assert first["severity"] == "warning" and first["message"] == (
        "the SRDF is for robot 'panda', but src/pr2_common/pr2_description/robots/pr2.urdf.xacro describes robot 'pr2': checked against it"
    )
    assert first["hint"] == ("if the SRDF is for robot 'pr2', write <robot name=\"pr2\"> in the SRDF (MoveIt's SRDF reader logs an error "
                             "when the names differ); else give --urdf the URDF of robot 'panda'")


def test_urdf_option_naming_the_robot_otherwise_says_the_srdf_was_checked_against_it(workspace):
    """Interbotix names every arm's URDF robot 'interbotix_arm' and its SRDF 'wx250s': given
    with --urdf, the URDF the SRDF's names all fit is the one; the way out is the name in the
    SRDF (srdfdom's Model::initXml logs an error when the names differ), not --urdf again."""
    urdf = workspace / "src/franka_ros/franka_description/robots/panda/panda.urdf"
    edit(urdf, '<robot name="panda"', '<robot name="franka_arm"')
    done, document = check("--urdf", str(urdf.relative_to(workspace)), f"{PANDA}/panda.srdf", cwd=workspace)
    [diagnostic] = document["files"][0]["diagnostics"]
    assert (diagnostic["code"], diagnostic["severity"]) == ("K008", "warning") and done.returncode == 0
    assert diagnostic["message"] == (
        "the SRDF is for robot 'panda', but src/franka_ros/franka_description/robots/panda/panda.urdf describes robot 'franka_arm': checked against it"
    )
    assert diagnostic["hint"] == "write <robot name=\"franka_arm\"> in the SRDF: MoveIt's SRDF reader logs an error when the names differ"


def test_an_srdf_without_urdf_is_one_note_and_no_error(tmp_path):
    srdf = tmp_path / "moveit" / "config" / "robot.srdf"
    srdf.parent.mkdir(parents=True)
    srdf.write_text('<robot name="lonely">\n  <group name="arm"><chain base_link="a" tip_link="b"/></group>\n</robot>\n')
    done, document = check(str(srdf), cwd=tmp_path)
    assert done.returncode == 0
    [diagnostic] = document["files"][0]["diagnostics"]
    assert (diagnostic["code"], diagnostic["severity"], diagnostic["line"]) == ("K008", "info", 1)
    assert diagnostic["message"] == "no URDF of robot 'lonely' found in the SRDF's package or workspace: its names are not checked"


def test_a_xacro_file_expanding_to_an_srdf_is_one(tmp_path):
    """Named neither .srdf nor .srdf.xacro: what its expansion holds says it is an SRDF."""
    package = tmp_path / "arm_moveit_config"
    (package / "config").mkdir(parents=True)
    (package / "package.xml").write_text('<package format="3"><name>arm_moveit_config</name></package>\n')
    (package / "config" / "arm.urdf").write_text(
        '<robot name="arm"><link name="base"/><link name="tool"/>'
        '<joint name="j" type="revolute"><parent link="base"/><child link="tool"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>\n'
    )
    (package / "config" / "arm.xacro").write_text(
        '<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:property name="tip" value="tool"/>\n'
        '  <group name="arm"><chain base_link="base" tip_link="${tip}"/></group>\n'
        '  <group_state name="home" group="arm"><joint name="j" value="2"/></group_state>\n'
        "</robot>\n"
    )
    done, document = check(str(package / "config" / "arm.xacro"), cwd=tmp_path)
    assert [(d["code"], d["line"]) for d in document["files"][0]["diagnostics"]] == [("K005", 4)]
    assert done.returncode == 0  # a warning: check fails on errors only


def test_lint_finds_the_srdf_files_of_a_folder(built):
    done = run_cli("lint", "--format", "json", "src/panda_moveit_config", cwd=built.parent)
    paths = [f["path"] for f in json.loads(done.stdout)["files"]]
    assert paths == [f"src/panda_moveit_config/config/{name}" for name in ("panda.srdf", "panda.urdf.xacro", "panda_arm.srdf.xacro", "panda_arm_hand.srdf.xacro")]
    warnings = [(d["code"], d["path"]) for f in json.loads(done.stdout)["files"] for d in f["diagnostics"] if d["severity"] != "info"]
    assert warnings == [("K009", f"{PANDA}/hand.xacro")]  # its <passive_joint> inside <group>, said once


@pytest.mark.parametrize("command", ["tree", "graph", "inertia"])
def test_an_srdf_is_not_drawn_or_audited_but_says_what_to_do(built, command):
    done = run_cli(command, f"{PANDA}/panda.srdf", cwd=built.parent)
    assert done.returncode == 2 and done.stdout == b""
    assert done.stderr.decode() == (
        f"urdfcli: {PANDA}/panda.srdf: an SRDF (MoveIt's semantic description), which has no links of its own; "
        f"`urdfcli check {PANDA}/panda.srdf` checks it against its URDF\n"
    )


def test_the_library_api_checks_an_srdf(built, monkeypatch):
    import urdfcli

    monkeypatch.chdir(built.parent)
    result = urdfcli.check(f"{PANDA}/panda_arm_hand.srdf.xacro")
    assert result.diagnostics == () and result.robot is None and result.loaded.described.robot.name == "panda"


def test_ur_moveit_config_checks_clean_once_its_name_argument_is_configured(workspace):
    """ur.srdf.xacro and ur.urdf.xacro both name the robot $(arg name) before declaring
    it (xacro needs name:=...): listed in [models], the SRDF, its macro library and
    the URDF check clean, the SRDF against the URDF of robot 'ur'."""
    (workspace / "urdfcli.toml").write_text(
        '[models]\n"src/Universal_Robots_ROS2_Description/ur_description/urdf/ur.urdf.xacro" = [["name:=ur"]]\n'
        '"src/Universal_Robots_ROS2_Driver/ur_moveit_config/srdf/ur.srdf.xacro" = [["name:=ur"]]\n'
    )
    srdf = "src/Universal_Robots_ROS2_Driver/ur_moveit_config/srdf"
    done = run_cli("check", f"{srdf}/ur.srdf.xacro", f"{srdf}/ur_macro.srdf.xacro", cwd=workspace)
    assert done.returncode == 0, done.stderr.decode()
    assert "checked against src/Universal_Robots_ROS2_Description/ur_description/urdf/ur.urdf.xacro" in done.stdout.decode()
    assert done.stderr.decode().endswith("2 files checked: 0 errors, 0 warnings\n")


ARM = (
    '<robot name="{name}"><link name="base"/><link name="{tip}"/>'
    '<joint name="{joint}" type="revolute"><parent link="base"/><child link="{tip}"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>\n'
)


def test_the_urdf_nearest_the_srdf_and_named_as_it_is_chosen(tmp_path):
    """One package holding several robots of one name (example-robot-data's anymal_b and
    anymal_c, alex's three hands): the SRDF is checked against the URDF of its own folder,
    and of the variants there, the one its file is named after."""
    data = tmp_path / "robot_data"
    (data / "robots").mkdir(parents=True)
    (data / "package.xml").write_text("<package format=\"3\"><name>robot_data</name></package>\n")
    for folder, stem, tip in (("a_description/robots", "arm", "a_tip"), ("b_description/urdf", "arm", "b_tip"), ("b_description/urdf", "arm_hand", "hand")):
        (data / "robots" / folder).mkdir(parents=True, exist_ok=True)
        (data / "robots" / folder / f"{stem}.urdf").write_text(ARM.format(name="arm", tip=tip, joint="j"))
    srdf = data / "robots" / "b_description" / "srdf"
    srdf.mkdir()
    (srdf / "arm_hand.srdf").write_text('<robot name="arm">\n  <group name="arm"><chain base_link="base" tip_link="hand"/></group>\n</robot>\n')
    done, document = check(str(srdf / "arm_hand.srdf"), cwd=tmp_path)
    assert (done.returncode, found(document)) == (0, [])
    text = run_cli("check", str(srdf / "arm_hand.srdf"), cwd=tmp_path).stdout.decode()
    assert text.endswith("checked against robot_data/robots/b_description/urdf/arm_hand.urdf\n")


def test_pinocchio_reference_configurations_are_no_mistake(tmp_path):
    """example-robot-data's SRDFs name reference configurations in an empty group 'all',
    the floating base Pinocchio adds ('root_joint', seven values) among them: MoveIt's
    rules K002 and K006 leave both alone; a joint the URDF lacks is still found."""
    package = tmp_path / "biped_description"
    (package / "urdf").mkdir(parents=True)
    (package / "srdf").mkdir()
    (package / "package.xml").write_text("<package format=\"3\"><name>biped_description</name></package>\n")
    (package / "urdf" / "biped.urdf").write_text(ARM.format(name="biped", tip="leg", joint="hip"))
    (package / "srdf" / "biped.srdf").write_text(
        '<robot name="biped">\n  <group name="all"/>\n  <group_state name="standing" group="all">\n'
        '    <joint name="root_joint" value="0 0 1 0 0 0 1"/>\n    <joint name="hip" value="0.5"/>\n    <joint name="knee" value="0.5"/>\n'
        "  </group_state>\n</robot>\n"
    )
    done, document = check(str(package / "srdf" / "biped.srdf"), cwd=tmp_path)
    assert [(d["code"], d["line"]) for d in document["files"][0]["diagnostics"]] == [("K002", 6)]


def test_an_srdf_whose_robot_name_differs_from_the_urdf_beside_it_is_checked_against_it(tmp_path):
    """example-robot-data's go2.srdf says robot 'go2' where go2.urdf says 'go2_description':
    the URDF named as the SRDF, in its robot's folder, is the one; the names' mismatch (an
    error in MoveIt's SRDF reader) is a warning, and the SRDF's names are checked."""
    package = tmp_path / "go2_description"
    (package / "urdf").mkdir(parents=True)
    (package / "srdf").mkdir()
    (package / "package.xml").write_text("<package format=\"3\"><name>go2_description</name></package>\n")
    (package / "urdf" / "go2.urdf").write_text(ARM.format(name="go2_description", tip="foot", joint="knee"))
    (package / "srdf" / "go2.srdf").write_text('<robot name="go2">\n  <group name="leg"><chain base_link="base" tip_link="toe"/></group>\n</robot>\n')
    done, document = check(str(package / "srdf" / "go2.srdf"), cwd=tmp_path)
    found_here = [(d["code"], d["severity"], d["line"]) for d in document["files"][0]["diagnostics"]]
    assert found_here == [("K008", "warning", 1), ("K001", "error", 2)] and done.returncode == 1
    assert document["files"][0]["diagnostics"][0]["message"] == (
        "the SRDF is for robot 'go2', but go2_description/urdf/go2.urdf, named as it is, describes robot 'go2_description': checked against it"
    )


def test_a_moveit_configs_srdf_is_paired_with_the_urdf_named_as_it_is_in_the_robot_package_it_depends_on(tmp_path):
    """ROS-Industrial's motoman_sia20d_moveit_config: sia20d.srdf says robot 'sia20d', the
    support package it depends on holds sia20d.xacro of robot 'motoman_sia20d'. That file is
    the one (not 'no URDF found'), and the mismatch is said."""
    src = tmp_path / "src"
    support, config = src / "motoman_sia20d_support", src / "motoman_sia20d_moveit_config"
    (support / "urdf").mkdir(parents=True)
    (config / "config").mkdir(parents=True)
    (support / "package.xml").write_text('<package format="2"><name>motoman_sia20d_support</name></package>\n')
    (config / "package.xml").write_text('<package format="2"><name>motoman_sia20d_moveit_config</name>'
                                        "<exec_depend>motoman_sia20d_support</exec_depend></package>\n")
    (support / "urdf" / "sia20d.xacro").write_text(ARM.format(name="motoman_sia20d", tip="foot", joint="knee"))
    (config / "config" / "sia20d.srdf").write_text('<robot name="sia20d">\n  <group name="arm"><chain base_link="base" tip_link="foot"/></group>\n</robot>\n')
    done, document = check("src/motoman_sia20d_moveit_config/config/sia20d.srdf", cwd=tmp_path)
    [diagnostic] = document["files"][0]["diagnostics"]
    assert (diagnostic["code"], diagnostic["severity"]) == ("K008", "warning") and done.returncode == 0
    assert diagnostic["message"] == ("the SRDF is for robot 'sia20d', but src/motoman_sia20d_support/urdf/sia20d.xacro, named as it is, "
                                     "describes robot 'motoman_sia20d': checked against it")


def test_of_the_urdfs_that_may_be_its_robot_the_one_its_names_fit_is_chosen(tmp_path):
    """Built as example-robot-data's alex_description and solo_description: an SRDF that kept
    another variant's robot name (alex_psyonic_hands.srdf says 'alex_nub_hands') is checked
    against the URDF beside it named as it is, whose joints it names, with a warning for the
    name; an SRDF of a robot two URDFs share (solo.urdf and solo12.urdf, both 'solo') is checked
    against the one whose joints it names, not the one named as it is. A name neither has is
    still found."""
    data = tmp_path / "robot_data"
    (data / "robots").mkdir(parents=True)
    (data / "package.xml").write_text("<package format=\"3\"><name>robot_data</name></package>\n")
    hands, quad = data / "robots" / "hands_description", data / "robots" / "quad_description"
    files = {
        hands / "urdf" / "nub_hands.urdf": ARM.format(name="nub_hands", tip="nub", joint="wrist"),
        hands / "urdf" / "psyonic_hands.urdf": ARM.format(name="psyonic_hands", tip="index", joint="index_q1"),
        hands / "srdf" / "psyonic_hands.srdf": '<robot name="nub_hands">\n  <group name="hand"><joint name="index_q1"/></group>\n'
        '  <group_state name="open" group="hand"><joint name="index_q1" value="0"/></group_state>\n</robot>\n',
        quad / "robots" / "quad.urdf": ARM.format(name="quad", tip="upper_leg", joint="hfe"),
        quad / "robots" / "quad12.urdf": ARM.format(name="quad", tip="shoulder", joint="haa"),
        quad / "srdf" / "quad.srdf": '<robot name="quad">\n  <group name="leg"><joint name="haa"/><joint name="kfe"/></group>\n'
        '  <disable_collisions link1="base" link2="shoulder" reason="Adjacent"/>\n</robot>\n',
    }
    for path, text in files.items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    done, document = check(str(hands / "srdf" / "psyonic_hands.srdf"), str(quad / "srdf" / "quad.srdf"), cwd=tmp_path)
    assert [(d["code"], d["severity"], d["line"]) for d in document["files"][0]["diagnostics"]] == [("K008", "warning", 1)]
    assert document["files"][0]["diagnostics"][0]["message"] == (
        "the SRDF is for robot 'nub_hands', but robot_data/robots/hands_description/urdf/psyonic_hands.urdf, named as it is, "
        "describes robot 'psyonic_hands': checked against it"
    )
    assert [(d["code"], d["line"], d["message"]) for d in document["files"][1]["diagnostics"]] == [
        ("K002", 2, "group 'leg' names joint 'kfe', which robot_data/robots/quad_description/robots/quad12.urdf does not have")
    ]
    text = run_cli("check", str(quad / "srdf" / "quad.srdf"), cwd=tmp_path).stdout.decode()
    assert "checked against robot_data/robots/quad_description/robots/quad12.urdf\n" in text


ARM_WITH_HAND = (  # the hand only with hand:=true, as franka's panda_arm.urdf.xacro
    '<robot name="panda" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:arg name="hand" default="false"/>\n'
    '  <link name="panda_link0"/><link name="panda_link8"/>\n'
    '  <joint name="panda_joint1" type="revolute"><parent link="panda_link0"/><child link="panda_link8"/>'
    '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n'
    '  <xacro:if value="$(arg hand)"><link name="panda_hand"/>'
    '<joint name="panda_hand_joint" type="fixed"><parent link="panda_link8"/><child link="panda_hand"/></joint></xacro:if>\n</robot>\n'
)


def test_the_command_lines_xacro_arguments_are_the_urdfs(tmp_path):
    """check panda.srdf --urdf panda_arm.urdf.xacro hand:=true: the hand's links exist only
    with hand:=true; the argument given is the URDF's, not dropped (25 false K001 and K002)."""
    (tmp_path / "arm.urdf.xacro").write_text(ARM_WITH_HAND)
    (tmp_path / "panda.srdf").write_text('<robot name="panda">\n  <group name="hand"><link name="panda_hand"/></group>\n</robot>\n')
    done, document = check("panda.srdf", "--urdf", "arm.urdf.xacro", "hand:=true", cwd=tmp_path)
    assert done.returncode == 0 and found(document) == [], document
    done, document = check("panda.srdf", "--urdf", "arm.urdf.xacro", cwd=tmp_path)
    assert done.returncode == 1 and [d["code"] for d in document["files"][0]["diagnostics"]] == ["K001"]


def test_the_srdfs_own_argument_defaults_are_the_urdfs(tmp_path):
    """franka_ros2: panda_arm.srdf.xacro declares hand (default true) and names the hand's links;
    panda_arm.urdf.xacro declares hand too (default false). Its launch file passes hand:=true to
    both: the SRDF's default is the URDF's argument (6 false K001 and K002). An argument given on
    the command line or in the configuration still wins."""
    (tmp_path / "arm.urdf.xacro").write_text(ARM_WITH_HAND)
    (tmp_path / "panda.srdf.xacro").write_text(
        '<robot name="panda" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:arg name="hand" default="true"/>\n'
        '  <group name="arm"><chain base_link="panda_link0" tip_link="panda_link8"/></group>\n'
        '  <xacro:if value="$(arg hand)"><group name="hand"><link name="panda_hand"/></group></xacro:if>\n</robot>\n')
    done, document = check("panda.srdf.xacro", cwd=tmp_path)
    assert done.returncode == 0 and found(document) == [], document
    assert document["files"][0]["checked_against"] == "arm.urdf.xacro"
    # hand:=false on the command line is the SRDF's and the URDF's: no hand group, no hand link, clean too
    done, document = check("panda.srdf.xacro", "hand:=false", cwd=tmp_path)
    assert done.returncode == 0 and found(document) == [], document
    # the URDF's configured value wins over the SRDF's default
    (tmp_path / "pyproject.toml").write_text('[tool.urdfcli.xacro-args]\n"arm.urdf.xacro" = { hand = "false" }\n')
    done, document = check("panda.srdf.xacro", cwd=tmp_path)
    assert [d["code"] for d in document["files"][0]["diagnostics"]] == ["K001"]


@pytest.mark.parametrize(("kind", "severity"), [("fixed", "info"), ("floating", "error")])
def test_a_virtual_joint_to_a_link_the_urdf_fixes_to_world_is_a_note_when_fixed(tmp_path, kind, severity):
    """moveit_resources' panda: the URDF fixes panda_link0 to a 'world' link (for Gazebo) and the
    SRDF's fixed virtual joint names panda_link0. MoveIt skips the virtual joint and the robot
    stands as the URDF puts it: a note. A floating one would leave a mobile base fixed: an error."""
    (tmp_path / "panda.urdf").write_text(
        '<robot name="panda"><link name="world"/><link name="panda_link0"/><link name="panda_link1"/>'
        '<joint name="world_joint" type="fixed"><parent link="world"/><child link="panda_link0"/></joint>'
        '<joint name="panda_joint1" type="revolute"><parent link="panda_link0"/><child link="panda_link1"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>\n')
    (tmp_path / "panda.srdf").write_text(
        f'<robot name="panda">\n  <virtual_joint name="virtual_joint" type="{kind}" parent_frame="world" child_link="panda_link0"/>\n</robot>\n')
    done, document = check("panda.srdf", "--urdf", "panda.urdf", cwd=tmp_path)
    [diagnostic] = document["files"][0]["diagnostics"]
    assert (diagnostic["code"], diagnostic["severity"]) == ("K007", severity)
    assert done.returncode == (0 if severity == "info" else 1)


def test_the_json_of_an_srdf_names_its_robot_and_the_urdf_it_was_checked_against(tmp_path):
    (tmp_path / "panda.urdf").write_text(ARM.format(name="panda", tip="foot", joint="knee"))
    (tmp_path / "panda.srdf").write_text('<robot name="panda">\n  <group name="leg"><chain base_link="base" tip_link="foot"/></group>\n</robot>\n')
    _, document = check("panda.srdf", cwd=tmp_path)
    entry = document["files"][0]
    assert (entry["robot"], entry["checked_against"]) == ("panda", "panda.urdf")
    (tmp_path / "panda.urdf").unlink()
    _, document = check("panda.srdf", cwd=tmp_path)
    assert (document["files"][0]["robot"], document["files"][0]["checked_against"]) == ("panda", None)


def test_a_package_in_no_repository_or_workspace_is_searched_alone(tmp_path):
    """example-robot-data unpacked in /tmp (or installed in a venv's share/): the folder holding
    the package is not its workspace. An SRDF whose URDF the package lacks is one note; it is not
    checked against another project's URDF of the same robot name there, nor stopped by that
    project's broken configuration."""
    data = tmp_path / "robot_data"
    (data / "robots" / "arm_description" / "srdf").mkdir(parents=True)
    (data / "package.xml").write_text('<package format="3"><name>robot_data</name></package>\n')
    srdf = data / "robots" / "arm_description" / "srdf" / "arm.srdf"
    srdf.write_text('<robot name="arm">\n  <group name="arm"><chain base_link="base" tip_link="a_tip"/></group>\n</robot>\n')
    elsewhere = tmp_path / "someone_elses_test"
    elsewhere.mkdir()
    (elsewhere / "arm.urdf").write_text(ARM.format(name="arm", tip="other_tip", joint="j"))
    (elsewhere / "urdfcli.toml").write_text("selct = ['J']\n")
    done, document = check(str(srdf), cwd=tmp_path)
    assert done.returncode == 0, done.stderr.decode()
    [diagnostic] = document["files"][0]["diagnostics"]
    assert diagnostic["code"] == "K008" and "no URDF of robot 'arm' found" in diagnostic["message"]
    (data / "robots" / "arm_description" / "urdf").mkdir()
    (data / "robots" / "arm_description" / "urdf" / "arm.urdf").write_text(ARM.format(name="arm", tip="a_tip", joint="j"))
    done, document = check(str(srdf), cwd=tmp_path)
    assert (done.returncode, found(document)) == (0, [])


def test_a_collision_pair_of_a_link_the_urdf_lacks_is_a_warning_whose_hint_is_never_the_pair(workspace):
    """Stretch's SRDF keeps 42 pairs of a fingertip link its xacro no longer has: MoveIt logs
    each and skips it (srdfdom's loadCollisionPairs: a warning), so a warning, not an error;
    'did you mean' never offers the other link of the pair (a link beside itself)."""
    srdf = workspace / PANDA / "panda.srdf"
    edit(srdf, "</robot>", '  <disable_collisions link1="panda_link7" link2="panda_lnk7" reason="Adjacent"/>\n</robot>')
    done, document = check(f"{PANDA}/panda.srdf", cwd=workspace)
    [k001] = [d for f in document["files"] for d in f["diagnostics"] if d["code"] == "K001"]
    assert k001["severity"] == "warning" and done.returncode == 0  # (check fails on errors only)
    assert k001["message"].startswith("<disable_collisions> names link 'panda_lnk7'") and "panda_link7'" not in k001["hint"], k001


def test_a_urdf_given_that_cannot_be_read_is_a_warning_saying_why(tmp_path):
    """xArm: --urdf xarm_device.urdf.xacro, which needs robot_type: the SRDF is not checked, so
    lint fails (it passed as an info), and the reason is the argument, not 'it holds no robot'."""
    (tmp_path / "arm.urdf.xacro").write_text(
        '<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="$(arg robot_type)_base"/>\n</robot>\n')
    (tmp_path / "arm.srdf").write_text('<robot name="arm">\n  <group name="g"><link name="xarm_base"/></group>\n</robot>\n')
    done, document = check("arm.srdf", "--urdf", "arm.urdf.xacro", cwd=tmp_path)
    [k008] = document["files"][0]["diagnostics"]
    assert (k008["code"], k008["severity"]) == ("K008", "warning")
    assert run_cli("lint", "arm.srdf", "--urdf", "arm.urdf.xacro", cwd=tmp_path).returncode == 1
    assert k008["message"] == "the URDF given with --urdf cannot be read: it needs xacro argument 'robot_type'"
    assert k008["hint"].startswith("give robot_type:=VALUE after the SRDF")
    assert check("arm.srdf", "--urdf", "arm.urdf.xacro", "robot_type:=xarm", cwd=tmp_path)[0].returncode == 0


def test_a_library_named_as_the_robot_is_no_urdf_that_could_not_be_read(tmp_path):
    """xArm's xarm7_robot_macro.xacro is <robot name="xarm7"> holding macros only: it is no
    candidate URDF of robot 'xarm7', not one that 'describes another robot'."""
    (tmp_path / "package.xml").write_text('<package format="3"><name>arm_data</name></package>\n')
    (tmp_path / "urdf").mkdir()
    (tmp_path / "urdf" / "arm_macro.xacro").write_text(
        '<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:macro name="arm" params="prefix"><link name="${prefix}base"/></xacro:macro>\n</robot>\n')
    (tmp_path / "arm.srdf").write_text('<robot name="arm">\n  <group name="g"><link name="base"/></group>\n</robot>\n')
    done, document = check("arm.srdf", cwd=tmp_path)
    [k008] = document["files"][0]["diagnostics"]
    assert k008["code"] == "K008" and "arm_macro.xacro" not in k008["message"], k008


def test_srdfs_option_checks_the_srdfs_of_the_robot_a_changed_library_builds(tmp_path):
    """The arm's joint renamed in its macro library breaks the MoveIt config's SRDF, which
    still names it: with --srdfs (as the pre-commit hooks run), checking the library (or the
    model) checks it through its model and the SRDF of robot 'cell' too, not another robot's;
    without it, only the model, which is fine on its own."""
    moveit_repository(tmp_path / "cell")
    library = "cell/cell_description/urdf/arm.xacro"
    edit(tmp_path / library, 'name="${prefix}elbow"', 'name="${prefix}joint_2"')
    done, document = check(library, cwd=tmp_path)
    assert (done.returncode, [f["path"] for f in document["files"]], found(document)) == (0, [library], [])
    for given in (library, "cell/cell_description/urdf/cell.urdf.xacro"):
        done, document = check("--srdfs", given, cwd=tmp_path)
        assert done.returncode == 1
        assert [f["path"] for f in document["files"]][1:] == ["cell/cell_moveit_config/config/cell.srdf"]
        assert [(code, path, line) for code, path, line, _ in found(document)] == [("K002", "cell/cell_moveit_config/config/cell.srdf", 3)]


def test_srdfs_option_adds_an_srdf_given_already_once(tmp_path):
    moveit_repository(tmp_path / "cell")
    model, srdf = "cell/cell_description/urdf/cell.urdf.xacro", "cell/cell_moveit_config/config/cell.srdf"
    for given in ([model, srdf], [srdf, model]):
        done, document = check("--srdfs", *given, cwd=tmp_path)
        assert done.returncode == 0, done.stderr.decode()
        assert sorted(f["path"] for f in document["files"]) == [model, srdf]


def test_srdfs_option_finds_an_srdf_naming_its_robot_with_an_argument_in_another_repository(workspace):
    """UR's ur.srdf.xacro (robot $(arg name), in ur_moveit_config of another repository of
    the workspace) is added for ur.urdf.xacro, whose robot is named by the same argument."""
    (workspace / "urdfcli.toml").write_text(
        '[models]\n"src/Universal_Robots_ROS2_Description/ur_description/urdf/ur.urdf.xacro" = [["name:=ur", "ur_type:=ur5e"]]\n'
        '"src/Universal_Robots_ROS2_Driver/ur_moveit_config/srdf/ur.srdf.xacro" = [["name:=ur"]]\n'
    )
    model, srdf = "src/Universal_Robots_ROS2_Description/ur_description/urdf/ur.urdf.xacro", "src/Universal_Robots_ROS2_Driver/ur_moveit_config/srdf/ur.srdf.xacro"
    done, document = check("--srdfs", model, cwd=workspace)
    assert done.returncode == 0, done.stderr.decode()
    assert [f["path"] for f in document["files"]] == [model, srdf]


def _setup_assistant_workspace(root, xacro_args: str):
    """Built as ros2_kortex: robots/gen3.xacro includes arms/gen3/${dof}dof/arm.xacro, dof defaults
    to "" (no file), and kinova_gen3_7dof_moveit_config's .setup_assistant names gen3.xacro with
    the arguments that choose the arm: the URDF moveit_configs_utils builds for the SRDF."""
    src = root / "src"
    robot, config = src / "kortex_description", src / "kinova_gen3_7dof_moveit_config"
    (robot / "robots").mkdir(parents=True)
    (robot / "arms" / "gen3" / "7dof").mkdir(parents=True)
    (config / "config").mkdir(parents=True)
    (robot / "package.xml").write_text('<package format="3"><name>kortex_description</name></package>\n')
    (config / "package.xml").write_text('<package format="3"><name>kinova_gen3_7dof_moveit_config</name>'
                                        "<exec_depend>kortex_description</exec_depend></package>\n")
    (robot / "robots" / "gen3.xacro").write_text(
        '<robot name="gen3" xmlns:xacro="http://ros.org/wiki/xacro">\n  <xacro:arg name="dof" default=""/>\n'
        '  <xacro:arg name="tool" default="false"/>\n'
        '  <xacro:include filename="$(find kortex_description)/arms/gen3/$(arg dof)dof/arm.xacro"/>\n</robot>\n')
    (robot / "arms" / "gen3" / "7dof" / "arm.xacro").write_text(
        '<robot xmlns:xacro="http://ros.org/wiki/xacro">\n  <link name="base_link"/><link name="bracelet_link"/>\n'
        '  <joint name="joint_7" type="continuous"><parent link="base_link"/><child link="bracelet_link"/></joint>\n'
        '  <xacro:if value="$(arg tool)"><link name="tool_link"/>'
        '<joint name="tool_joint" type="fixed"><parent link="bracelet_link"/><child link="tool_link"/></joint></xacro:if>\n'
        '</robot>\n')
    (config / ".setup_assistant").write_text(
        "moveit_setup_assistant_config:\n  urdf:\n    package: kortex_description\n    relative_path: robots/gen3.xacro\n"
        f"    xacro_args:\n      {xacro_args}\n  srdf:\n    relative_path: config/gen3.srdf\n")
    (config / "config" / "gen3.srdf").write_text(
        '<robot name="gen3">\n  <group name="arm"><chain base_link="base_link" tip_link="tool_link"/></group>\n</robot>\n')
    return "src/kinova_gen3_7dof_moveit_config/config/gen3.srdf"


def test_the_urdf_and_xacro_arguments_a_setup_assistant_file_names_are_the_srdfs(tmp_path):
    """The SRDF is checked against the URDF its .setup_assistant names, expanded with its
    xacro_args (a folded scalar over two lines), not left unchecked because the model needs
    an argument; an argument it does not give leaves that part out, and the SRDF's name of
    a link only that part has is then an error."""
    srdf = _setup_assistant_workspace(tmp_path, "dof:=7\n      tool:=true")
    done, document = check(srdf, cwd=tmp_path)
    assert done.returncode == 0 and found(document) == [], document
    assert document["files"][0]["checked_against"] == "src/kortex_description/robots/gen3.xacro"
    srdf = _setup_assistant_workspace(tmp_path / "without_tool", "dof:=7")
    done, document = check(srdf, cwd=tmp_path / "without_tool")
    assert done.returncode == 1 and [d["code"] for d in document["files"][0]["diagnostics"]] == ["K001"], document


def test_an_srdf_whose_own_urdf_needs_arguments_is_not_checked_against_another_variant(tmp_path):
    """A UR + gripper cell: the MoveIt config's cell.srdf (robot 'arm', as UR's SRDF macro
    names it) belongs to the cell's cell.urdf.xacro, which needs an argument; the bare arm's
    arm.urdf elsewhere in the repository gives robot 'arm' too but lacks the gripper. The SRDF
    is not checked against the arm (a K001 for each gripper link): one K008 says its own URDF
    needs an argument. Given it, the SRDF is checked against the cell: only the robot's other
    name is said."""
    repo = tmp_path / "cell"
    (repo / ".git").mkdir(parents=True)
    packages = {"cell_description": "", "cell_moveit_config": "<exec_depend>cell_description</exec_depend>", "arm_description": ""}
    for package, depends in packages.items():
        (repo / package / "urdf").mkdir(parents=True)
        (repo / package / "package.xml").write_text(f'<package format="3"><name>{package}</name>{depends}</package>\n')
    (repo / "arm_description/urdf/arm.urdf").write_text(ARM.format(name="arm", tip="tip", joint="j"))
    (repo / "cell_description/urdf/cell.urdf.xacro").write_text(
        '<robot name="cell" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <link name="base"/><link name="tip"/><link name="$(arg gripper)_finger"/>\n'
        '  <joint name="j" type="revolute"><parent link="base"/><child link="tip"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n'
        '  <joint name="f" type="fixed"><parent link="tip"/><child link="$(arg gripper)_finger"/></joint>\n</robot>\n'
    )
    (repo / "cell_moveit_config/config").mkdir()
    srdf = "cell/cell_moveit_config/config/cell.srdf"
    (tmp_path / srdf).write_text(
        '<robot name="arm">\n  <group name="arm"><chain base_link="base" tip_link="tip"/></group>\n'
        '  <group name="gripper"><link name="robotiq_finger"/></group>\n'
        '  <disable_collisions link1="tip" link2="robotiq_finger" reason="Adjacent"/>\n</robot>\n'
    )
    done, document = check(srdf, cwd=tmp_path)
    [k008] = document["files"][0]["diagnostics"]
    assert (done.returncode, k008["code"], k008["severity"]) == (0, "K008", "info"), k008
    assert "cell/cell_description/urdf/cell.urdf.xacro: it needs xacro argument 'gripper'" in k008["message"]
    done, document = check(srdf, "gripper:=robotiq", cwd=tmp_path)
    assert (done.returncode, [(d["code"], d["severity"]) for d in document["files"][0]["diagnostics"]]) == (0, [("K008", "warning")])
    assert document["files"][0]["checked_against"] == "cell/cell_description/urdf/cell.urdf.xacro"


def _two_generations(root, tip: str = "tip") -> str:
    """A workspace holding two generations of one vendor's packages: arm_moveit_config depends on
    arm_description, whose arm.urdf.xacro (its tool link ``tip``) needs namespace:=; arm_description2,
    of another repository, gives robot 'arm' too, with the link and joint names the SRDF gives.
    The SRDF's path."""
    src = root / "src"
    robot, config = robot_and_moveit_config(src / "arm_ros1", "arm_description", "xacro", "arm_moveit_config")
    (robot / "xacro" / "arm.urdf.xacro").write_text(
        '<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <gazebo><plugin name="control" filename="libcontrol.so"><robotNamespace>$(arg namespace)</robotNamespace></plugin></gazebo>\n'
        + ARM.format(name="arm", tip=tip, joint="j").split(">", 1)[1])
    (config / "config" / "arm.srdf").write_text('<robot name="arm">\n  <group name="arm"><chain base_link="base" tip_link="tip"/></group>\n</robot>\n')
    other = src / "arm_ros2" / "arm_description2"
    (other / "xacro").mkdir(parents=True)
    (other / "package.xml").write_text('<package format="3"><name>arm_description2</name></package>\n')
    (other / "xacro" / "arm.urdf.xacro").write_text(ARM.format(name="arm", tip="tip", joint="j"))
    for repository in ("arm_ros1", "arm_ros2"):
        (src / repository / ".git").mkdir()
    return "src/arm_ros1/arm_moveit_config/config/arm.srdf"


def test_an_srdf_whose_own_urdf_needs_arguments_is_not_checked_against_another_packages_robot_of_its_name(tmp_path):
    """The config does not load arm_description2's robot: the SRDF is not checked against it, and
    one K008 says its own URDF needs the argument. Given it, the SRDF is checked against its own URDF."""
    srdf = _two_generations(tmp_path)
    done, document = check(srdf, cwd=tmp_path)
    [k008] = document["files"][0]["diagnostics"]
    assert (done.returncode, k008["code"], k008["severity"]) == (0, "K008", "info"), k008
    assert "src/arm_ros1/arm_description/xacro/arm.urdf.xacro: it needs xacro argument 'namespace'" in k008["message"]
    assert k008["hint"] == "give namespace:=VALUE after the SRDF (the arguments are the URDF's too), or in [tool.urdfcli.xacro-args]"
    assert document["files"][0]["checked_against"] is None
    done, document = check(srdf, "namespace:=dsr", cwd=tmp_path)
    assert done.returncode == 0 and found(document) == [], document
    assert document["files"][0]["checked_against"] == "src/arm_ros1/arm_description/xacro/arm.urdf.xacro"


def test_a_link_renamed_in_the_srdfs_own_urdf_is_found_although_another_packages_robot_still_has_it(tmp_path):
    """The tool link of arm_description's model renamed: the SRDF's chain names a link its own URDF
    lacks. arm_description2's robot of the same name still has it, and fits the SRDF better; it
    is still not the URDF the config loads, so the K001 is said, not hidden."""
    srdf = _two_generations(tmp_path, tip="tool")
    done, document = check(srdf, "namespace:=dsr", cwd=tmp_path)
    assert [d["code"] for d in document["files"][0]["diagnostics"]] == ["K001"], document
    assert document["files"][0]["checked_against"] == "src/arm_ros1/arm_description/xacro/arm.urdf.xacro"


def robot_and_moveit_config(root, robot: str, models: str, config: str, depends: bool = True):
    """A robot package (its models in ``models/``) and a MoveIt config package beside it under
    ``root`` (its SRDF in ``config/``), whose package.xml depends on the robot's unless not
    ``depends``: the two package folders."""
    (root / robot / models).mkdir(parents=True)
    (root / config / "config").mkdir(parents=True)
    (root / robot / "package.xml").write_text(f'<package format="3"><name>{robot}</name></package>\n')
    depend = f"<exec_depend>{robot}</exec_depend>" if depends else ""
    (root / config / "package.xml").write_text(f'<package format="3"><name>{config}</name>{depend}</package>\n')
    return root / robot, root / config

def test_the_urdf_a_setup_assistant_wrote_in_its_config_package_is_the_one_the_srdf_describes(tmp_path):
    """spot_moveit_config: the Setup Assistant added ros2_control to the robot and wrote
    config/spot.urdf.xacro, which sets arm:=true and includes spot_description's model, whose
    arm is off by default; its .setup_assistant still names that model. moveit_configs_utils
    loads config/spot.urdf.xacro, so the SRDF's arm is checked against the robot with its arm,
    not said missing."""
    robot, config = robot_and_moveit_config(tmp_path / "src", "spot_description", "urdf", "spot_moveit_config")
    (robot / "urdf" / "spot.urdf.xacro").write_text(
        '<robot name="spot" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:arg name="arm" default="false"/>\n'
        '  <link name="body"/>\n  <xacro:if value="$(arg arm)"><link name="arm_link_sh0"/>'
        '<joint name="arm_sh0" type="continuous"><parent link="body"/><child link="arm_link_sh0"/></joint></xacro:if>\n</robot>\n')
    (config / "config" / "spot.urdf.xacro").write_text(
        '<robot name="spot" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:arg name="arm" default="true"/>\n'
        '  <xacro:include filename="$(find spot_description)/urdf/spot.urdf.xacro"/>\n</robot>\n')
    (config / ".setup_assistant").write_text(
        "moveit_setup_assistant_config:\n  urdf:\n    package: spot_description\n    relative_path: urdf/spot.urdf.xacro\n"
        "  srdf:\n    relative_path: config/spot.srdf\n  modified_urdf:\n    xacros:\n      - control_xacro\n")
    (config / "config" / "spot.srdf").write_text(
        '<robot name="spot">\n  <group name="arm"><chain base_link="body" tip_link="arm_link_sh0"/></group>\n</robot>\n')
    done, document = check("src/spot_moveit_config/config/spot.srdf", cwd=tmp_path)
    assert done.returncode == 0 and found(document) == [], document
    assert document["files"][0]["checked_against"] == "src/spot_moveit_config/config/spot.urdf.xacro"


def test_a_moveit_1_setup_assistant_file_with_its_keys_in_capitals_names_the_urdf(tmp_path):
    """MoveIt 1's Setup Assistant writes URDF: and SRDF: in capitals. abb_irb6640_moveit_config's
    SRDF says robot 'abb_irb6640', the model it names says 'abb_irb6640_185_280', and no file is
    named as the SRDF: the SRDF is checked against that model, with a warning on the names and
    on the link of its <disable_collisions> that the model lacks."""
    robot, config = robot_and_moveit_config(tmp_path / "src", "abb_irb6640_support", "urdf", "abb_irb6640_moveit_config", depends=False)
    (robot / "urdf" / "irb6640_185_280.xacro").write_text(
        '<robot name="abb_irb6640_185_280" xmlns:xacro="http://ros.org/wiki/xacro">\n  <link name="base_link"/><link name="tool0"/>\n'
        '  <joint name="joint_1" type="continuous"><parent link="base_link"/><child link="tool0"/></joint>\n</robot>\n')
    (config / ".setup_assistant").write_text(
        "moveit_setup_assistant_config:\n  URDF:\n    package: abb_irb6640_support\n    relative_path: urdf/irb6640_185_280.xacro\n"
        "  SRDF:\n    relative_path: config/abb_irb6640.srdf\n  CONFIG:\n    generated_timestamp: 1402076423\n")
    (config / "config" / "abb_irb6640.srdf").write_text(
        '<robot name="abb_irb6640">\n  <group name="manipulator"><chain base_link="base_link" tip_link="tool0"/></group>\n'
        '  <disable_collisions link1="base_link" link2="link_cylinder" reason="Never"/>\n</robot>\n')
    done, document = check("src/abb_irb6640_moveit_config/config/abb_irb6640.srdf", cwd=tmp_path)
    checked = document["files"][0]
    assert checked["checked_against"] == "src/abb_irb6640_support/urdf/irb6640_185_280.xacro", document
    assert [(d["code"], d["severity"]) for d in checked["diagnostics"]] == [("K008", "warning"), ("K001", "warning")], document
    assert ".setup_assistant" in checked["diagnostics"][0]["message"] and "'link_cylinder'" in checked["diagnostics"][1]["message"]


def test_a_setup_assistant_urdf_without_a_robot_name_is_said_to_have_none(tmp_path):
    """open_manipulator_p_with_gripper_moveit's .setup_assistant names
    open_manipulator_p_with_gripper.urdf.xacro, the part that ..._robot.urdf.xacro includes:
    its <robot> has no name. K008 said it "describes robot 'None'" and offered
    <robot name="None">; it says the file gives its robot no name."""
    robot, config = robot_and_moveit_config(tmp_path / "src", "arm_description", "urdf", "arm_moveit_config")
    (robot / "urdf" / "arm.urdf.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="link1"/><link name="link2"/>\n'
        '  <joint name="joint1" type="continuous"><parent link="link1"/><child link="link2"/></joint>\n</robot>\n')
    (config / ".setup_assistant").write_text(
        "moveit_setup_assistant_config:\n  URDF:\n    package: arm_description\n    relative_path: urdf/arm.urdf.xacro\n"
        "  SRDF:\n    relative_path: config/arm.srdf\n")
    (config / "config" / "arm.srdf").write_text('<robot name="arm">\n  <group name="arm"><joint name="joint1"/></group>\n</robot>\n')
    done, document = check("src/arm_moveit_config/config/arm.srdf", cwd=tmp_path)
    said = [(d["code"], d["message"], d.get("hint")) for d in document["files"][0]["diagnostics"]]
    assert said == [("K008", "the SRDF is for robot 'arm', but src/arm_description/urdf/arm.urdf.xacro, which its .setup_assistant names, "
                             "gives its <robot> no name: checked against it",
                     "check it against the model that includes this file, with --urdf FILE: MoveIt's URDF reader refuses a <robot> without a name")], document


def test_the_argument_set_models_lists_for_an_srdf_is_its_urdfs_too(tmp_path):
    """ros_kortex: one gen3.xacro makes the 6- and 7-dof arms (dof defaults to 7), and the 6-dof
    MoveIt config's SRDF names the 6-dof arm's links. Checked against the default, its names
    are missing (K001); the SRDF's argument set in [tool.urdfcli] models is its URDF's too,
    as arguments given after it on the command line are, and then it checks clean."""
    (tmp_path / ".git").mkdir()
    robot, config = robot_and_moveit_config(tmp_path, "arm_description", "robots", "arm_moveit_config")
    (robot / "robots" / "arm.xacro").write_text(
        '<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:arg name="dof" default="7"/>\n'
        '  <link name="base"/><link name="tip"/>\n'
        '  <xacro:if value="${\'$(arg dof)\' == \'6\'}"><link name="bicep_link"/>'
        '<joint name="b" type="fixed"><parent link="base"/><child link="bicep_link"/></joint></xacro:if>\n'
        '  <joint name="j" type="revolute"><parent link="base"/><child link="tip"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n</robot>\n'
    )
    srdf = "arm_moveit_config/config/arm.srdf"
    (tmp_path / srdf).write_text('<robot name="arm">\n  <group name="arm"><chain base_link="base" tip_link="tip"/></group>\n'
                                 '  <disable_collisions link1="base" link2="bicep_link" reason="Adjacent"/>\n</robot>\n')
    done, document = check(srdf, cwd=tmp_path)
    diagnostics = document["files"][0]["diagnostics"]
    assert [(d["code"], d["severity"], d["message"]) for d in diagnostics] == [
        ("K001", "warning", "<disable_collisions> names link 'bicep_link', which arm_description/robots/arm.xacro does not have")]
    done, document = check(srdf, "dof:=6", cwd=tmp_path)
    assert (done.returncode, found(document)) == (0, [])
    (tmp_path / "pyproject.toml").write_text(f'[tool.urdfcli]\nmodels = {{ "{srdf}" = [["dof:=6"]] }}\n')
    done, document = check(srdf, cwd=tmp_path)
    assert (done.returncode, found(document)) == (0, [])


def test_a_name_the_urdf_lacks_is_said_once_with_the_number_of_elements_giving_it(tmp_path):
    """ros_kortex's 6-dof SRDF checked against the 7-dof arm: 'bicep_link' is in several
    <disable_collisions> pairs, each beside another link. One diagnostic per missing name, at
    the first element giving it (a group's before a pair's), counting the others; its hint
    the same whichever pair comes first (no partner of the name is the link meant)."""
    (tmp_path / "arm.urdf").write_text(
        '<robot name="arm"><link name="base_link"/><link name="forearm_link"/><link name="bracelet_link"/>'
        '<joint name="j1" type="continuous"><parent link="base_link"/><child link="forearm_link"/></joint>'
        '<joint name="j2" type="continuous"><parent link="forearm_link"/><child link="bracelet_link"/></joint></robot>\n')
    (tmp_path / "arm.srdf").write_text(
        '<robot name="arm">\n  <group name="arm"><chain base_link="base_link" tip_link="bracelet_link"/></group>\n'
        '  <group name="wrist"><link name="wrist_link"/></group>\n'
        '  <group_state name="home" group="arm"><joint name="j3" value="0"/></group_state>\n'
        '  <group_state name="up" group="arm"><joint name="j3" value="1"/></group_state>\n'
        '  <disable_collisions link1="base_link" link2="bicep_link" reason="Never"/>\n'
        '  <disable_collisions link1="bicep_link" link2="forearm_link" reason="Adjacent"/>\n'
        '  <disable_collisions link1="bracelet_link" link2="bicep_link" reason="Never"/>\n'
        '  <disable_collisions link1="wrist_link" link2="forearm_link" reason="Never"/>\n</robot>\n')
    done, document = check("arm.srdf", "--urdf", "arm.urdf", cwd=tmp_path)
    assert done.returncode == 1
    assert [(d["code"], d["severity"], d["line"], d["message"], d["hint"]) for d in document["files"][0]["diagnostics"]] == [
        ("K001", "error", 3, "group 'wrist' names link 'wrist_link', which arm.urdf does not have (and in 1 <disable_collisions>)",
         "use a link of arm.urdf, or check that the SRDF is for this robot"),  # (not base_link: a wrist is no base misspelt)
        ("K002", "error", 4, "group state 'home' names joint 'j3', which arm.urdf does not have (and in group state 'up')",
         "use a joint of arm.urdf, or check that the SRDF is for this robot"),
        ("K001", "warning", 6, "<disable_collisions> names link 'bicep_link', which arm.urdf does not have (and in 2 more <disable_collisions>)",
         "use a link of arm.urdf, or check that the SRDF is for this robot"),
    ]
    concise = run_cli("check", "--format", "concise", "arm.srdf", "--urdf", "arm.urdf", cwd=tmp_path).stdout.decode()
    assert concise.count("'bicep_link'") == 1 and concise.count("'j3'") == 1, concise


def test_a_collision_pair_naming_a_link_the_urdf_lacks_is_offered_only_links_that_collide(tmp_path):
    """rosbot_xl_manipulation's SRDF pairs 'left_antenna_link' with the body, the URDF has one
    antenna: 'antenna_link' under 'antenna_connector_link', which has only a visual. A pair of a
    link without collision geometry disables nothing: it is no suggestion for a name that only
    pairs give, however close ('camera_body_link', a frame, for 'camera_link' beside the
    'camera_mount_link' that collides)."""
    box = '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>'
    visual = '<visual><geometry><box size="0.01 0.01 0.01"/></geometry></visual>'
    links = {"base_link": box, "antenna_connector_link": visual, "antenna_link": box, "camera_body_link": "", "camera_mount_link": box}
    (tmp_path / "rover.urdf").write_text(
        '<robot name="rover">' + "".join(f'<link name="{name}">{shapes}</link>' for name, shapes in links.items())
        + "".join(f'<joint name="to_{name}" type="fixed"><parent link="base_link"/><child link="{name}"/></joint>' for name in list(links)[1:])
        + "</robot>\n")
    (tmp_path / "rover.srdf").write_text(
        '<robot name="rover">\n'
        '  <disable_collisions link1="left_antenna_link" link2="base_link" reason="Adjacent"/>\n'
        '  <disable_collisions link1="camera_link" link2="base_link" reason="Adjacent"/>\n</robot>\n')
    done, document = check("rover.srdf", "--urdf", "rover.urdf", cwd=tmp_path)
    assert done.returncode == 0
    assert [(d["code"], d["subjects"], d["hint"]) for d in document["files"][0]["diagnostics"]] == [
        ("K001", ["left_antenna_link"], "use a link of rover.urdf, or check that the SRDF is for this robot"),
        ("K001", ["camera_link"], "did you mean 'camera_mount_link'?"),
    ]


def test_an_srdf_written_without_the_prefix_of_every_urdf_name_is_one_finding_per_kind(tmp_path):
    """lbr_fri_ros2_stack's iiwa7.srdf names link_0 ... link_ee and A1 ... A7, its iiwa7.xacro
    makes them with robot_name:=lbr in front: 16 errors and 50 warnings, each 'did you mean
    lbr_...?'. One prefix explains every name: one finding for the links, one for the joints.
    A name no prefix explains keeps each its own."""
    (tmp_path / ".git").mkdir()
    description, config = tmp_path / "lbr_description", tmp_path / "iiwa_moveit_config"
    (description / "urdf").mkdir(parents=True)
    (config / "config").mkdir(parents=True)
    for package, depends in ((description, ""), (config, "<exec_depend>lbr_description</exec_depend>")):
        (package / "package.xml").write_text(f'<package format="3"><name>{package.name}</name>{depends}</package>\n')
    joints = "".join(
        f'  <joint name="$(arg robot_name)_A{i}" type="revolute"><parent link="$(arg robot_name)_link_{i - 1}"/>'
        f'<child link="$(arg robot_name)_link_{i}"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n'
        for i in (1, 2, 3))
    (description / "urdf" / "iiwa.xacro").write_text(
        '<robot name="iiwa" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:arg name="robot_name" default="lbr"/>\n'
        + "".join(f'  <link name="$(arg robot_name)_link_{i}"/>\n' for i in range(4)) + joints + "</robot>\n")
    srdf = config / "config" / "iiwa.srdf"
    srdf.write_text(
        '<robot name="iiwa">\n  <group name="arm"><chain base_link="link_0" tip_link="link_3"/></group>\n'
        '  <group_state name="zero" group="arm"><joint name="A1" value="0"/><joint name="A2" value="0"/><joint name="A3" value="0"/></group_state>\n'
        '  <disable_collisions link1="link_0" link2="link_1" reason="Adjacent"/>\n'
        '  <disable_collisions link1="link_1" link2="link_2" reason="Adjacent"/>\n</robot>\n')
    done, document = check(str(srdf), cwd=tmp_path)
    diagnostics = [d for f in document["files"] for d in f["diagnostics"]]
    assert [(d["code"], d["severity"], d["line"], d["column"]) for d in diagnostics] == [("K001", "error", 2, 28), ("K002", "error", 3, 47)]
    assert diagnostics[0]["message"] == (
        "the SRDF names 4 links that lbr_description/urdf/iiwa.xacro has only with the prefix 'lbr_': 'link_0', 'link_3', 'link_1' and 1 more")
    assert diagnostics[0]["hint"].startswith("it is written for the robot with another prefix: write each name with 'lbr_' in front")
    assert diagnostics[1]["message"] == "the SRDF names 3 joints that lbr_description/urdf/iiwa.xacro has only with the prefix 'lbr_': 'A1', 'A2', 'A3'"
    # a name no prefix makes one of the URDF's: each its own finding, as before
    edit(srdf, 'name="A3"', 'name="A4"')
    done, document = check(str(srdf), cwd=tmp_path)
    k002 = [d for f in document["files"] for d in f["diagnostics"] if d["code"] == "K002"]
    assert [d["message"] for d in k002] == [f"group state 'zero' names joint '{name}', which lbr_description/urdf/iiwa.xacro does not have" for name in ("A1", "A2", "A4")]
    # the same misspelling twice is no prefix: each its own finding
    srdf.write_text('<robot name="iiwa">\n  <group name="arm"><chain base_link="lbr_lnk_0" tip_link="lbr_lnk_3"/></group>\n</robot>\n')
    done, document = check(str(srdf), cwd=tmp_path)
    assert [d["hint"] for f in document["files"] for d in f["diagnostics"]] == ["did you mean 'lbr_link_0'?", "did you mean 'lbr_link_3'?"]
    # names with a prefix the URDF's lack: one finding too
    srdf.write_text('<robot name="iiwa">\n  <group name="arm"><chain base_link="lbr_lbr_link_0" tip_link="lbr_lbr_link_3"/></group>\n</robot>\n')
    done, document = check(str(srdf), cwd=tmp_path)
    [k001] = [d for f in document["files"] for d in f["diagnostics"]]
    assert k001["message"] == "the SRDF names 2 links that lbr_description/urdf/iiwa.xacro has only without the prefix 'lbr_': 'lbr_lbr_link_0', 'lbr_lbr_link_3'"
    # the URDF expanded with another robot_name: one prefix in place of the other
    srdf.write_text('<robot name="iiwa">\n  <group name="arm"><chain base_link="lbr_link_0" tip_link="lbr_link_3"/></group>\n</robot>\n')
    done, document = check(str(srdf), "robot_name:=left", cwd=tmp_path)
    [k001] = [d for f in document["files"] for d in f["diagnostics"]]
    assert k001["message"] == "the SRDF names 2 links that lbr_description/urdf/iiwa.xacro has only with the prefix 'left' in place of 'lbr': 'lbr_link_0', 'lbr_link_3'"
    assert k001["hint"].startswith("it is written for the robot with another prefix: write each name with 'left' in place of 'lbr'")



def test_an_srdf_of_the_names_a_stale_generated_urdf_lacks_and_its_xacro_makes_is_one_finding_per_kind(tmp_path):
    """motoman_bmda3: the .setup_assistant names bmda3.urdf, generated from bmda3.xacro before its
    joints were renamed (waist, then torso_joint_b1); the SRDF names the new joints and links. Not a
    'did you mean' per joint that would rename the SRDF's back: one finding per kind, to generate the URDF again."""
    (tmp_path / ".git").mkdir()
    support, config = tmp_path / "arm_support", tmp_path / "arm_moveit_config"
    (support / "urdf").mkdir(parents=True)
    (config / "config").mkdir(parents=True)
    (support / "package.xml").write_text("<package><name>arm_support</name></package>\n")
    (config / "package.xml").write_text("<package><name>arm_moveit_config</name><run_depend>arm_support</run_depend></package>\n")
    (config / ".setup_assistant").write_text(
        "moveit_setup_assistant_config:\n  URDF:\n    package: arm_support\n    relative_path: urdf/arm.urdf\n"
        "  SRDF:\n    relative_path: config/arm.srdf\n")

    def robot(joint: str, link: str) -> str:
        return (f'<robot name="arm">\n  <link name="base_link"/>\n  <link name="{link}"/>\n'
                f'  <joint name="{joint}" type="revolute"><parent link="base_link"/><child link="{link}"/>'
                '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n</robot>\n')

    (support / "urdf" / "arm.xacro").write_text(robot("torso_joint_b1", "torso_link_b1").replace("<robot ", '<robot xmlns:xacro="http://ros.org/wiki/xacro" '))
    (support / "urdf" / "arm.urdf").write_text(
        '<?xml version="1.0" ?>\n<!-- |    This document was autogenerated by xacro from arm.xacro    | -->\n' + robot("waist", "waist_link"))
    srdf = config / "config" / "arm.srdf"
    srdf.write_text('<robot name="arm">\n  <group name="torso"><joint name="torso_joint_b1"/></group>\n'
                    '  <disable_collisions link1="base_link" link2="torso_link_b1" reason="Adjacent"/>\n</robot>\n')
    done, document = check(str(srdf), cwd=tmp_path)
    diagnostics = [d for f in document["files"] for d in f["diagnostics"]]
    assert [(d["code"], d["severity"], d["line"]) for d in diagnostics] == [("K002", "error", 2), ("K001", "warning", 3)]
    assert diagnostics[0]["message"] == "group 'torso' names joint 'torso_joint_b1', which arm_support/urdf/arm.urdf does not have"
    assert diagnostics[0]["hint"] == (
        "arm_support/urdf/arm.urdf is older than its source (arm_support/urdf/arm.xacro, which generated it, makes it): "
        "generate it again (urdfcli expand arm_support/urdf/arm.xacro -o arm_support/urdf/arm.urdf)")
    assert diagnostics[1]["hint"] == diagnostics[0]["hint"]
    # several names: one finding per kind
    edit(srdf, "</group>", '<joint name="torso_joint_b2"/></group>')
    edit(support / "urdf" / "arm.xacro", "</robot>", '<link name="torso_link_b2"/><joint name="torso_joint_b2" type="fixed"><parent link="base_link"/><child link="torso_link_b2"/></joint></robot>')
    done, document = check(str(srdf), cwd=tmp_path)
    [k002] = [d for f in document["files"] for d in f["diagnostics"] if d["code"] == "K002"]
    assert (k002["line"], k002["message"]) == (2, "the SRDF names 2 joints that arm_support/urdf/arm.urdf lacks: 'torso_joint_b1', 'torso_joint_b2'")
    assert k002["hint"].startswith("arm_support/urdf/arm.urdf is older than its source (arm_support/urdf/arm.xacro, which generated it, makes them)")
    # a name the xacro file does not make either: each its own finding, as before
    edit(srdf, "</group>", '<joint name="elbow"/></group>')
    done, document = check(str(srdf), cwd=tmp_path)
    k002 = [d["message"] for f in document["files"] for d in f["diagnostics"] if d["code"] == "K002"]
    assert k002 == [f"group 'torso' names joint '{name}', which arm_support/urdf/arm.urdf does not have" for name in ("torso_joint_b1", "torso_joint_b2", "elbow")]

def test_a_setup_assistant_urdf_that_cannot_be_read_is_named_once(tmp_path):
    """TALOS: the .setup_assistant names talos_full_v2.urdf.xacro, which includes a package not
    in the workspace. The K008 says why it could not be read once, not a second time for the
    same file found again in the robot's package."""
    robot, config = robot_and_moveit_config(tmp_path / "src", "talos_description", "robots", "talos_moveit_config")
    (robot / "robots" / "talos_full_v2.urdf.xacro").write_text(
        '<robot name="talos" xmlns:xacro="http://ros.org/wiki/xacro">\n'
        '  <xacro:include filename="$(find talos_description_calibration)/urdf/leg.xacro"/>\n  <link name="base_link"/>\n</robot>\n')
    (config / ".setup_assistant").write_text(
        "moveit_setup_assistant_config:\n  URDF:\n    package: talos_description\n    relative_path: robots/talos_full_v2.urdf.xacro\n"
        "    xacro_args: \"\"\n  SRDF:\n    relative_path: config/talos.srdf\n")
    (config / "config" / "talos.srdf").write_text('<robot name="talos">\n  <group name="torso"><link name="base_link"/></group>\n</robot>\n')
    done, document = check("src/talos_moveit_config/config/talos.srdf", cwd=tmp_path)
    [k008] = document["files"][0]["diagnostics"]
    assert (done.returncode, k008["code"]) == (0, "K008"), document
    assert k008["message"].count("talos_full_v2.urdf.xacro") == 1, k008["message"]
    assert "which its .setup_assistant names: package 'talos_description_calibration' not found" in k008["message"]


def test_names_a_prefix_would_make_ones_the_srdf_gives_itself_are_no_prefix(tmp_path):
    """franka_ros2's SRDF with its hand, checked against the arm alone: 'panda_finger_joint1'
    and 'panda_finger_joint2' are 'panda_joint1' and 'panda_joint2' with 'panda' in place of
    'panda_finger', but the SRDF names those two itself: the hand is missing, not a prefix."""
    (tmp_path / "arm.urdf").write_text(
        '<robot name="panda">\n  <link name="panda_link0"/>\n  <link name="panda_link1"/>\n  <link name="panda_link2"/>\n'
        + "".join(f'  <joint name="panda_joint{i}" type="revolute"><parent link="panda_link{i - 1}"/><child link="panda_link{i}"/>'
                  '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n' for i in (1, 2))
        + "</robot>\n")
    (tmp_path / "arm.srdf").write_text(
        '<robot name="panda">\n  <group name="arm"><chain base_link="panda_link0" tip_link="panda_link2"/></group>\n'
        '  <group_state name="ready" group="arm"><joint name="panda_joint1" value="0"/><joint name="panda_joint2" value="0"/></group_state>\n'
        '  <group name="hand"><joint name="panda_finger_joint1"/><joint name="panda_finger_joint2"/></group>\n</robot>\n')
    done, document = check("arm.srdf", "--urdf", "arm.urdf", cwd=tmp_path)
    assert [(d["code"], d["line"], d["message"]) for d in document["files"][0]["diagnostics"]] == [
        ("K002", 4, f"group 'hand' names joint 'panda_finger_joint{i}', which arm.urdf does not have") for i in (1, 2)]
    # a prefix whose names the SRDF does not give is still one finding: the SRDF of a robot built with another prefix
    (tmp_path / "arm.srdf").write_text(
        '<robot name="panda">\n  <group name="hand"><joint name="panda_finger_joint1"/><joint name="panda_finger_joint2"/></group>\n</robot>\n')
    done, document = check("arm.srdf", "--urdf", "arm.urdf", cwd=tmp_path)
    [k002] = document["files"][0]["diagnostics"]
    assert k002["message"] == "the SRDF names 2 joints that arm.urdf has only with the prefix 'panda' in place of 'panda_finger': 'panda_finger_joint1', 'panda_finger_joint2'"


def test_a_urdf_that_needs_a_package_this_machine_lacks_is_said_so_with_the_way_to_give_it(tmp_path):
    """TALOS's model includes its calibration package, not in the workspace: the K008 hint names
    the package path, not xacro arguments; given with -P, the SRDF is checked against it."""
    robot, config = robot_and_moveit_config(tmp_path / "src", "talos_description", "robots", "talos_moveit_config")
    (robot / "robots" / "talos.urdf.xacro").write_text(
        '<robot name="talos" xmlns:xacro="http://ros.org/wiki/xacro">\n'
        '  <xacro:include filename="$(find talos_description_calibration)/urdf/calibration.xacro"/>\n  <link name="base_link"/>\n</robot>\n')
    (config / "config" / "talos.srdf").write_text('<robot name="talos">\n  <group name="torso"><link name="base_link"/></group>\n</robot>\n')
    done, document = check("src/talos_moveit_config/config/talos.srdf", cwd=tmp_path)
    [k008] = document["files"][0]["diagnostics"]
    assert k008["code"] == "K008" and "package 'talos_description_calibration' not found" in k008["message"], k008
    assert k008["hint"] == "build and source the workspace that has the package, or give its folder with -P NAME=DIR (package-paths in [tool.urdfcli])"
    calibration = tmp_path / "vendor" / "talos_description_calibration"
    (calibration / "urdf").mkdir(parents=True)
    (calibration / "package.xml").write_text('<package format="3"><name>talos_description_calibration</name></package>\n')
    (calibration / "urdf" / "calibration.xacro").write_text('<robot xmlns:xacro="http://ros.org/wiki/xacro"/>\n')
    done, document = check("-P", "vendor", "src/talos_moveit_config/config/talos.srdf", cwd=tmp_path)
    assert (done.returncode, document["files"][0]["diagnostics"]) == (0, []), document


HAND_URDF = """<robot name="hand">
  <link name="hand"/><link name="left"/><link name="right"/>
  <joint name="finger_joint1" type="prismatic"><parent link="hand"/><child link="left"/><axis xyz="0 1 0"/><limit lower="0" upper="0.04" effort="1" velocity="1"/></joint>
  <joint name="finger_joint2" type="prismatic"><parent link="hand"/><child link="right"/><axis xyz="0 -1 0"/><limit lower="0" upper="0.04" effort="1" velocity="1"/><mimic joint="finger_joint1"/></joint>
</robot>
"""


def lint_srdf(tmp_path, srdf: str) -> tuple[int, list[tuple[str, str, int, int, str, str | None]]]:
    (tmp_path / "hand.urdf").write_text(HAND_URDF)
    (tmp_path / "hand.srdf").write_text(srdf)
    done = run_cli("lint", "--format", "json", "hand.srdf", "--urdf", "hand.urdf", cwd=tmp_path)
    document = json.loads(done.stdout)
    return done.returncode, [(d["code"], d["severity"], d["line"], d["column"], d["message"], d["hint"]) for f in document["files"] for d in f["diagnostics"]]


def test_a_passive_joint_written_inside_a_group_is_said_to_belong_in_robot(tmp_path):
    """franka_ros2's srdf/hand.xacro writes <passive_joint> inside <group>: srdfdom reads passive
    joints only in <robot>, so MoveIt plans for the finger joint as if it were driven. lint says
    so, at the element; check (a drop-in for what MoveIt rejects) says nothing."""
    srdf = ('<robot name="hand">\n  <group name="hand">\n    <link name="hand"/>\n    <joint name="finger_joint1"/>\n'
            '    <passive_joint name="finger_joint2"/>\n  </group>\n</robot>\n')
    code, found_here = lint_srdf(tmp_path, srdf)
    assert code == 1 and found_here == [
        ("K009", "warning", 5, 5, "<passive_joint> is not read inside <group>; MoveIt ignores it", "<passive_joint> belongs directly in <robot>"),
    ]
    assert run_cli("check", "hand.srdf", "--urdf", "hand.urdf", cwd=tmp_path).returncode == 0
    code, found_here = lint_srdf(tmp_path, srdf.replace("    <passive_joint name=\"finger_joint2\"/>\n  </group>\n", "  </group>\n  <passive_joint name=\"finger_joint2\"/>\n"))
    assert (code, found_here) == (0, [])


def test_a_misspelt_srdf_element_or_attribute_is_a_warning_naming_the_one_meant(tmp_path):
    srdf = ('<robot name="hand">\n  <group name="hand"><linkk name="left"/><joint name="finger_joint1"/></group>\n'
            '  <disable_colisions link1="left" link2="right" reason="Never"/>\n'
            '  <end_effector name="eef" group="hand" parent_link="hand" parent_grup="arm"/>\n'
            '  <group name="fingers"><chain base_link="hand" tip_link="left"/></group>\n  <chain base_link="hand" tip_link="right"/>\n</robot>\n')
    code, found_here = lint_srdf(tmp_path, srdf)
    assert code == 1 and found_here == [
        ("K009", "warning", 2, 22, "<linkk> is not read inside <group>; MoveIt ignores it", "did you mean <link>?"),
        ("K009", "warning", 3, 3, "<disable_colisions> is not read inside <robot>; MoveIt ignores it", "did you mean <disable_collisions>?"),
        ("K009", "warning", 4, 60, "<end_effector> has no attribute 'parent_grup'; MoveIt ignores it", "did you mean 'parent_group'?"),
        ("K009", "warning", 6, 3, "<chain> is not read inside <robot>; MoveIt ignores it", "<chain> belongs in <group>"),
    ]


def test_markup_of_another_reader_is_a_note_and_known_extensions_draw_nothing(tmp_path):
    """<foo> may be some other tool's: a note (info), as unknown URDF markup is (D010). Pinocchio's
    <rotor_params>, Tesseract's <group_tcps> and version, and xacro's namespace draw nothing; a
    subgroup's <group> holds nothing srdfdom reads."""
    srdf = ('<robot name="hand" version="1.0.0" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
            '  <group name="hand"><joint name="finger_joint1"/></group>\n'
            '  <group name="all"><group name="hand"><link name="right"/></group></group>\n'
            '  <rotor_params><joint name="finger_joint1" mass="0.1" gear_ratio="10"/></rotor_params>\n'
            '  <group_tcps group="hand"><tcp name="tip" xyz="0 0 0.1" wxyz="1 0 0 0"/></group_tcps>\n'
            '  <foo/>\n  <end_effector name="eef" group="hand" parent_link="hand" color="red"/>\n</robot>\n')
    code, found_here = lint_srdf(tmp_path, srdf)
    assert code == 1 and found_here == [
        ("K009", "warning", 3, 40, "<link> is not read inside <group> in <group>; MoveIt ignores it",
         "<link> belongs in <group>; a <group> inside a group only names a subgroup"),
        ("K009", "info", 6, 3, "<foo> is not read inside <robot>; MoveIt ignores it",
         "<robot> may hold <disable_collisions>, <disable_default_collisions>, <enable_collisions>, <end_effector>, <group>, <group_state>, "
         "<joint_property>, <link_sphere_approximation>, <passive_joint>, <virtual_joint>"),
        ("K009", "info", 7, 60, "<end_effector> has no attribute 'color'; MoveIt ignores it", "<end_effector> takes group, name, parent_group, parent_link"),
    ]


def test_the_published_srdfs_draw_no_k009_nor_k010():
    """example-robot-data's 38 SRDFs: Pinocchio's, HPP's (<gripper>) and the humanoid <specificities>
    are other readers' markup, written on purpose; nothing in them is misspelt or misplaced. Their
    group states without a group (z1, kinova) are Pinocchio's reference configurations."""
    data = example_robot_data()
    srdfs = sorted(str(path) for path in (data / "robots").glob("*/srdf/*.srdf"))
    assert len(srdfs) >= 30
    done = run_cli("lint", "--select", "K009,K010", "--format", "json", "-P", f"example-robot-data={data}", *srdfs)
    document = json.loads(done.stdout)
    assert [d for f in document["files"] for d in f["diagnostics"]] == []

def test_an_element_without_an_attribute_srdfdom_needs_is_one_error_in_check_and_lint(tmp_path):
    """srdfdom logs an error and skips an element without an attribute it needs (a state's
    joint without a value, a chain without its tip, a nameless group). A misspelt or cut-short
    attribute is one cause: K010 (which check runs) names the attribute written, K009 says
    nothing more. An attribute K009 knows no use for stays K009's."""
    srdf = ('<robot name="hand">\n  <group name="hand"><joint name="finger_joint1"/><chain base_link="hand" tip="right"/></group>\n'
            '  <group_state name="open" group="hand"><joint name="finger_joint1" valeu="0.04"/></group_state>\n'
            '  <group_state name="closed" group="hand"><joint name="finger_joint1"/></group_state>\n'
            '  <group><link name="left"/></group>\n'
            '  <disable_collisions link1="left" reason="Never" colour="red"/>\n</robot>\n')
    expected = [
        ("K010", "error", 2, 75, "<chain> in <group> 'hand' has no 'tip_link'; MoveIt skips it", "did you mean tip_link=\"...\"? 'tip' is no attribute of <chain>"),
        ("K010", "error", 3, 69, "<joint> 'finger_joint1' in <group_state> 'open' has no 'value'; MoveIt skips it",
         "did you mean value=\"...\"? 'valeu' is no attribute of <joint>"),
        ("K010", "error", 4, 43, "<joint> 'finger_joint1' in <group_state> 'closed' has no 'value'; MoveIt skips it", "give value=\"...\""),
        ("K010", "error", 5, 3, "<group> has no 'name'; MoveIt skips it", "give name=\"...\""),
        ("K010", "error", 6, 3, "<disable_collisions> has no 'link2'; MoveIt skips it", "give link2=\"...\""),
    ]
    colour = ("K009", "info", 6, 51, "<disable_collisions> has no attribute 'colour'; MoveIt ignores it", "<disable_collisions> takes link1, link2, reason")
    code, found_here = lint_srdf(tmp_path, srdf)
    assert code == 1 and sorted(found_here, key=lambda d: d[2:4]) == sorted([*expected, colour], key=lambda d: d[2:4])
    done, document = check("hand.srdf", "--urdf", "hand.urdf", cwd=tmp_path)
    assert done.returncode == 1
    assert [(d["code"], d["line"], d["message"]) for d in document["files"][0]["diagnostics"]] == [e[:1] + e[2:3] + e[4:5] for e in expected]


def test_every_element_srdfdom_reads_draws_nothing(tmp_path):
    srdf = """<robot name="hand">
  <virtual_joint name="world_joint" type="fixed" parent_frame="world" child_link="hand"/>
  <group name="fingers"><link name="left"/><joint name="finger_joint1"/><chain base_link="hand" tip_link="right"/></group>
  <group name="hand"><group name="fingers"/></group>
  <group_state name="open" group="fingers"><joint name="finger_joint1" value="0.04"/></group_state>
  <end_effector name="eef" group="fingers" parent_link="hand" parent_group="hand"/>
  <passive_joint name="finger_joint2"/>
  <disable_collisions link1="left" link2="right" reason="Never"/>
  <enable_collisions link1="left" link2="hand" reason="Default"/>
  <disable_default_collisions link="right"/>
  <link_sphere_approximation link="left"><sphere center="0 0 0" radius="0.01"/></link_sphere_approximation>
  <joint_property joint_name="finger_joint1" property_name="motion_model" value="holonomic"/>
</robot>
"""
    assert lint_srdf(tmp_path, srdf) == (0, [])


def test_an_srdf_for_another_variant_of_a_xacro_model_is_told_to_give_its_arguments(tmp_path):
    """TIAGo's MoveIt config holds one SRDF per end effector; its model takes end_effector:=,
    and expanded with the default (the hand) it lacks every gripper link the SRDF names. The
    hint says how to check the SRDF against its own variant, and doing so checks it clean."""
    (tmp_path / "tiago.urdf.xacro").write_text(
        '<robot name="tiago" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:arg name="end_effector" default="hand"/>\n'
        '  <link name="arm_link"/>\n'
        '  <link name="$(arg end_effector)_link"/>\n'
        '  <joint name="tool" type="fixed"><parent link="arm_link"/><child link="$(arg end_effector)_link"/></joint>\n'
        '</robot>\n')
    (tmp_path / "tiago_gripper.srdf").write_text(
        '<robot name="tiago">\n  <group name="gripper"><link name="gripper_link"/></group>\n</robot>\n')
    done, document = check("--urdf", "tiago.urdf.xacro", "tiago_gripper.srdf", cwd=tmp_path)
    assert [(d["code"], d["hint"]) for d in document["files"][0]["diagnostics"]] == [
        ("K001", f"use a link of tiago.urdf.xacro, or check that the SRDF is for this robot; {VARIANT}")]
    done, document = check("--urdf", "tiago.urdf.xacro", "tiago_gripper.srdf", "end_effector:=gripper", cwd=tmp_path)
    assert done.returncode == 0 and found(document) == []
    (tmp_path / "tiago.urdf").write_text('<robot name="tiago"><link name="arm_link"/></robot>\n')
    done, document = check("--urdf", "tiago.urdf", "tiago_gripper.srdf", cwd=tmp_path)
    assert [d["hint"] for d in document["files"][0]["diagnostics"]] == ["use a link of tiago.urdf, or check that the SRDF is for this robot"]


def test_a_finger_state_outside_its_limits_is_hinted_in_metres(tmp_path):
    """Piper's gripper_open sets both fingers to 0.035, but joint8 moves over [-0.038, 0]:
    the hint of a prismatic joint speaks of metres, not of a revolute joint's radians."""
    package = tmp_path / "arm_moveit_config"
    (package / "config").mkdir(parents=True)
    (package / "package.xml").write_text('<package format="3"><name>arm_moveit_config</name></package>\n')
    (package / "config" / "arm.urdf").write_text(
        '<robot name="arm"><link name="base"/><link name="finger"/>'
        '<joint name="joint8" type="prismatic"><parent link="base"/><child link="finger"/><axis xyz="0 0 1"/>'
        '<limit lower="-0.038" upper="0" effort="1" velocity="1"/></joint></robot>\n'
    )
    (package / "config" / "arm.srdf").write_text(
        '<robot name="arm">\n  <group name="gripper"><joint name="joint8"/></group>\n'
        '  <group_state name="gripper_open" group="gripper"><joint name="joint8" value="0.035"/></group_state>\n</robot>\n'
    )
    _, document = check(str(package / "config" / "arm.srdf"), cwd=tmp_path)
    [said] = [d for d in document["files"][0]["diagnostics"] if d["code"] == "K005"]
    assert said["message"] == "group state 'gripper_open' sets joint 'joint8' to 0.035, outside its limits [-0.038, 0] m"
    assert said["hint"] == "give a value within the joint's limits (metres for a prismatic joint)"
