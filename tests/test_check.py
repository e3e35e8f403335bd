"""urdfcli check: each check with a failing and a passing snippet, and the CLI contract."""

from __future__ import annotations

import json

import pytest
from conftest import FIXTURES, load, run_cli

BASE = '<link name="a"/><link name="b"/>'
FIXED = '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
INERTIA = 'ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"'


def robot(body: str, attributes: str = 'name="r"') -> str:
    return f"<robot {attributes}>{body}</robot>"


def joint(kind: str = "revolute", inner: str = '<limit effort="1" velocity="1" lower="-1" upper="1"/>') -> str:
    return BASE + f'<joint name="j" type="{kind}"><parent link="a"/><child link="b"/>{inner}</joint>'


def link_a(inner: str) -> str:
    return f'<link name="a">{inner}</link><link name="b"/>' + FIXED


def inertial(mass: str = "1", inertia: str = INERTIA, origin: str = "") -> str:
    return f'<inertial>{origin}<mass value="{mass}"/><inertia {inertia}/></inertial>'


def visual(shape: str, extra: str = "") -> str:
    return f"<visual><geometry>{shape}</geometry>{extra}</visual>"


# code: (document with the defect, the same document corrected)
CASES = {
    "X001": ("<robot name='r'><link name='a'></robot>", robot("<link name='a'/>")),
    "X002": ('<!DOCTYPE robot [<!ENTITY n "a">]><robot name="r"><link name="&n;"/></robot>', robot('<link name="a"/>')),
    "X007": (robot('<!-- old --!><link name="a"/><!-- new -->') + "\n", robot('<!-- old --><link name="a"/><!-- new -->')),
    "R001": ("<model name='r'><link name='a'/></model>", robot("<link name='a'/>")),
    "R002": ("<robot><link name='a'/></robot>", robot("<link name='a'/>")),
    "R003": (robot("<link name='a'/>", 'name="r" version="2.0"'), robot("<link name='a'/>", 'name="r" version="1.0"')),
    "R004": (robot(""), robot("<link name='a'/>")),
    "N001": (robot("<link/><link name='a'/>"), robot("<link name='a'/>")),
    "N002": (robot(BASE + '<joint type="fixed"><parent link="a"/><child link="b"/></joint>'), robot(BASE + FIXED)),
    "N003": (robot('<link name="a"/><material><color rgba="1 0 0 1"/></material>'), robot('<link name="a"/><material name="red"><color rgba="1 0 0 1"/></material>')),
    "N004": (robot('<link name="a"/><link name="a"/>'), robot('<link name="a"/>')),
    "N005": (robot(BASE + '<link name="c"/>' + FIXED + '<joint name="j" type="fixed"><parent link="a"/><child link="c"/></joint>'),
             robot(BASE + '<link name="c"/>' + FIXED + '<joint name="k" type="fixed"><parent link="a"/><child link="c"/></joint>')),
    "N006": (robot('<link name="a"/><material name="m"><color rgba="1 0 0 1"/></material><material name="m"><color rgba="1 0 0 1"/></material>'),
             robot('<link name="a"/><material name="m"><color rgba="1 0 0 1"/></material>')),
    "V001": (robot(link_a(inertial(mass="x"))), robot(link_a(inertial(mass="1")))),
    "V002": (robot(link_a(inertial(mass="nan"))), robot(link_a(inertial(mass="2")))),
    "V003": (robot(link_a(visual('<box size="1 2"/>'))), robot(link_a(visual('<box size="1 2 3"/>')))),
    "V004": (robot(link_a(visual("<sphere/>"))), robot(link_a(visual('<sphere radius="1"/>')))),
    "V005": (robot(link_a('<inertial><mass value="1"/></inertial>')), robot(link_a(inertial()))),
    "V006": (robot(link_a(visual('<cylinder radius="-0.1" length="1"/>'))), robot(link_a(visual('<cylinder radius="0.1" length="1"/>')))),
    "V008": (robot(link_a(visual('<box size="0 1 1"/>'))), robot(link_a(visual('<box size="1 1 1"/>')))),
    "V007": (robot('<link name="a"/><material name="m"><color rgba="2 0 0 1"/></material>'), robot('<link name="a"/><material name="m"><color rgba="1 0 0 1"/></material>')),
    "G001": (robot(link_a("<visual><geometry/></visual>")), robot(link_a(visual('<box size="1 1 1"/>')))),
    "G002": (robot(link_a(visual('<cone radius="1"/>'))), robot(link_a(visual('<sphere radius="1"/>')))),
    "G003": (robot(link_a(visual('<box size="1 1 1"/><sphere radius="1"/>'))), robot(link_a(visual('<box size="1 1 1"/>')))),
    # a second <geometry> or <material> in one <visual>: urdfdom reads the first
    "G004": (robot(link_a('<visual><geometry><box size="1 1 1"/></geometry><geometry><sphere radius="1"/></geometry></visual>')),
             robot(link_a(visual('<box size="1 1 1"/>') + visual('<sphere radius="1"/>')))),
    "M001": (robot('<link name="a"/><material name="m"/>'), robot('<link name="a"/><material name="m"><texture filename="t.png"/></material>')),
    "M002": (robot(link_a(visual('<box size="1 1 1"/>', '<material name="m"/>'))),
             robot('<material name="m"><color rgba="0 0 1 1"/></material>' + link_a(visual('<box size="1 1 1"/>', '<material name="m"/>')))),
    "M003": (robot(link_a(visual('<box size="1 1 1"/>', '<material name="m"><color rgba="0 0 0 1"/></material>')) + '<material name="m"><color rgba="1 1 1 1"/></material>'),
             robot(link_a(visual('<box size="1 1 1"/>', '<material name="m"><color rgba="1 1 1 1"/></material>')) + '<material name="m"><color rgba="1 1 1 1"/></material>')),
    "M004": (robot('<link name="a"/><material name="m"><color rgba="1 0 0"/></material>'), robot('<link name="a"/><material name="m"><color rgba="1 0 0 1"/></material>')),
    "M005": (robot(link_a(visual('<box size="1 1 1"/>', '<material name="m" rgba="1 0 0 1"/>'))),
             robot(link_a(visual('<box size="1 1 1"/>', '<material name="m"><color rgba="1 0 0 1"/></material>')))),
    "V009": (robot(joint("revolute", '<origin rpy="0 0 90"/><limit effort="1" velocity="1" lower="-1" upper="1"/>')),
             robot(joint("revolute", '<origin rpy="0 0 1.5708"/><limit effort="1" velocity="1" lower="-1" upper="1"/>'))),
    "V010": (robot(joint("continuous", '<dynamics damping="-0.1"/>')), robot(joint("continuous", '<dynamics damping="0.1"/>'))),
    "J001": (robot(BASE + '<joint name="j"><parent link="a"/><child link="b"/></joint>'), robot(BASE + FIXED)),
    "J002": (robot(joint("ball", "")), robot(joint("floating", ""))),
    "J003": (robot(joint("revolute", "")), robot(joint("continuous", ""))),
    "J004": (robot(BASE + '<joint name="j" type="fixed"><parent link="a"/></joint>'), robot(BASE + FIXED)),
    "J005": (robot(BASE + '<joint name="j" type="fixed"><parent link="arm"/><child link="b"/></joint>'), robot(BASE + FIXED)),
    "J006": (robot(joint("continuous", "<dynamics/>")), robot(joint("continuous", '<dynamics damping="0.1"/>'))),
    "J007": (robot(joint("continuous", '<axis xyz="0 0 0"/>')), robot(joint("continuous", '<axis xyz="0 0 1"/>'))),
    "J008": (robot(joint("continuous", '<mimic joint="elbow"/>')), robot(joint("continuous", ""))),
    "J009": (robot(joint("continuous", '<mimic joint="j"/>')), robot(joint("continuous", ""))),
    "J010": (robot(joint("revolute", '<limit effort="1" velocity="1" lower="1" upper="-1"/>')), robot(joint("revolute"))),
    "T001": (robot(BASE), robot(BASE + FIXED)),
    "T002": (robot(BASE + FIXED + '<joint name="k" type="fixed"><parent link="b"/><child link="a"/></joint>'), robot(BASE + FIXED)),
    "T003": (robot(BASE + '<link name="c"/>' + FIXED + '<joint name="k" type="fixed"><parent link="a"/><child link="c"/></joint><joint name="m" type="fixed"><parent link="b"/><child link="c"/></joint>'),
             robot(BASE + '<link name="c"/>' + FIXED + '<joint name="k" type="fixed"><parent link="a"/><child link="c"/></joint>')),
    "T004": (robot(BASE + '<link name="c"/>' + FIXED + '<joint name="k" type="fixed"><parent link="b"/><child link="c"/></joint><joint name="m" type="fixed"><parent link="c"/><child link="b"/></joint>'),
             robot(BASE + '<link name="c"/>' + FIXED + '<joint name="k" type="fixed"><parent link="b"/><child link="c"/></joint>')),
    "I001": (robot(link_a(inertial(mass="-1"))), robot(link_a(inertial(mass="1")))),
    "I002": (robot('<link name="a">' + inertial() + '</link><link name="b"><inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>' + joint("continuous", "")[len(BASE):]),
             robot('<link name="a">' + inertial() + '</link><link name="b"><inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>' + FIXED)),
    "I003": (robot(link_a(inertial(mass="0"))), robot(link_a(inertial(mass="0", inertia='ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"')))),
    "I004": (robot(link_a(inertial(inertia='ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"'))), robot(link_a(inertial()))),
    "I005": (robot(link_a(inertial(inertia='ixx="1" ixy="0" ixz="0" iyy="0" iyz="1" izz="1"'))), robot(link_a(inertial()))),
    "I006": (robot(link_a(inertial(inertia='ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.01"'))),
             robot(link_a(inertial(inertia='ixx="0.006" ixy="0" ixz="0" iyy="0.006" iyz="0" izz="0.01"')))),
}


def codes(tmp_path, text: str, name: str = "model.urdf") -> set[str]:
    path = tmp_path / name
    path.write_text(text)
    return {d.code for d in load(str(path)).diagnostics}


@pytest.mark.parametrize("code", sorted(CASES))
def test_each_check_flags_the_defect_and_passes_the_fix(tmp_path, code):
    bad, good = CASES[code]
    assert code in codes(tmp_path, bad)
    assert code not in codes(tmp_path, good)


def test_every_check_code_has_a_case():
    from urdfcli.rules import REGISTRY, RuleSet

    in_check = {code for code, spec in REGISTRY.items() if RuleSet.CHECK.holds(spec.rule_set) and code[0] in "XRNVGMJTI"}
    # xacro codes: tests/test_expand.py; X006 (a library and its models): tests/test_workspace.py;
    # X106 (names in macro bodies, across files): tests/test_xacro_sources.py; X110 (a URDF and the
    # xacro it was generated from): tests/test_drift.py
    untested = in_check - set(CASES) - {"X003", "X004", "X005", "X006", "X106", "X110"}
    assert not untested


@pytest.mark.parametrize("rgba, said", [("255 255 255 1", "V007"), ("1 1 x 1", "V001")])
def test_a_colour_written_but_unreadable_is_one_finding_not_also_a_material_without_one(tmp_path, rgba, said):
    """Jackal's novatel_smart6: <material name="white"><color rgba="255 255 255 1"/> in a visual
    drew V007 and M002 'defined nowhere' (hint: give it a <color rgba>); at the top level,
    M001 'has neither <color rgba> nor <texture>'. The colour is there: one mistake, one finding."""
    colour = f'<material name="white"><color rgba="{rgba}"/></material>'
    assert codes(tmp_path, robot(link_a(visual('<box size="1 1 1"/>', colour)))) == {said}
    assert codes(tmp_path, robot(colour + link_a(visual('<box size="1 1 1"/>', '<material name="white"/>')))) == {said}
    assert codes(tmp_path, robot(link_a(visual('<box size="1 1 1"/>', '<material name="white"/>')))) == {"M002"}  # no colour written


def test_a_second_material_in_a_visual_is_said_and_a_mesh_scaled_to_nothing_too(tmp_path):
    two = robot(link_a(visual('<box size="1 1 1"/>', '<material name="red"><color rgba="1 0 0 1"/></material><material name="blue"><color rgba="0 0 1 1"/></material>')))
    assert "G004" in codes(tmp_path, two)
    (tmp_path / "part.stl").write_bytes(b"solid part\nendsolid part\n")
    flat = codes(tmp_path, robot(link_a(visual('<mesh filename="part.stl" scale="0 0 0"/>'))))
    assert "V008" in flat  # MuJoCo and Drake refuse it
    mirrored = codes(tmp_path, robot(link_a(visual('<mesh filename="part.stl" scale="1 -1 1"/>'))))
    assert "V008" not in mirrored and "V006" not in mirrored  # TALOS mirrors its arms' meshes so


@pytest.mark.parametrize("shape", ['<box size="0 0 0"/>', '<sphere radius="0"/>', '<cylinder radius="0.1" length="-0"/>'])
def test_a_zero_dimension_is_a_warning_that_check_urdf_accepts_a_negative_one_an_error(tmp_path, shape):
    from differential import check_urdf

    zero = tmp_path / "zero.urdf"
    zero.write_text(robot(link_a(visual(shape))))
    done = run_cli("check", str(zero))
    assert done.returncode == 0 and b"V008 warning" in done.stderr and b"V006" not in done.stderr
    assert not check_urdf(zero).rejects  # urdfdom (and ROS, MoveIt) load it
    negative = tmp_path / "negative.urdf"
    negative.write_text(robot(link_a(visual(shape.replace('"0', '"-1').replace('"-0', '"-1')))))
    done = run_cli("check", str(negative))
    assert done.returncode == 1 and b"V006 error" in done.stderr and b"V008" not in done.stderr


def test_massless_frame_links_on_fixed_joints_get_no_diagnostic(tmp_path):
    frames = (
        '<link name="base_link">' + inertial() + '</link>'
        '<link name="tool0"/>'
        '<link name="camera_optical_frame"><inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>'
        '<joint name="tool" type="fixed"><parent link="base_link"/><child link="tool0"/></joint>'
        '<joint name="optical" type="fixed"><parent link="tool0"/><child link="camera_optical_frame"/></joint>'
    )
    assert codes(tmp_path, robot(frames)) == set()


def test_all_problems_in_one_run(tmp_path):
    text = robot(
        '<link name="a"><inertial><mass value="x"/><inertia ' + INERTIA + "/></inertial>"
        + visual('<box size="1 1"/>') + "</link><link name=\"b\"/><link name=\"c\"/>"
        '<joint name="j" type="revolute"><parent link="a"/><child link="b"/></joint>'
        '<joint name="k" type="fixed"><parent link="a"/><child link="zz"/></joint>'
    )
    assert {"V001", "V003", "J003", "J005", "T001"} <= codes(tmp_path, text)


def test_text_output_tree_on_stdout_diagnostics_on_stderr(tmp_path):
    path = tmp_path / "two.urdf"
    path.write_text('<robot name="r">\n  <link name="a"/>\n  <link name="b"/>\n</robot>\n')
    done = run_cli("check", str(path))
    assert done.returncode == 1
    assert done.stdout == b""
    lines = done.stderr.decode().splitlines()
    assert lines[0] == f"{path}:3:3: T001 error: 2 links have no parent: 'a', 'b'"
    assert lines[1].startswith("    hint: ")
    assert lines[-1] == "1 file checked: 1 error, 0 warnings"


def test_check_urdf_format_on_the_bundled_example():
    done = run_cli("check", "--format", "check_urdf", str(FIXTURES / "urdf02_gazebo/urdf/car.urdf.xacro"))
    assert done.returncode == 0
    assert done.stdout.decode().splitlines()[:3] == [
        "robot name is: mycar",
        "---------- Successfully Parsed XML ---------------",
        "root Link: base_footprint has 1 child(ren)",
    ]


def test_json_format_follows_the_contract(tmp_path):
    good = FIXTURES / "seed003" / "jtbot.urdf"
    bad = tmp_path / "bad.urdf"
    bad.write_text(robot(joint("revolute", "")))
    done = run_cli("check", "--format", "json", str(good), str(bad))
    assert done.returncode == 1
    report = json.loads(done.stdout)
    assert report["version"] == 1
    assert [f["path"] for f in report["files"]] == [str(good), str(bad)]
    assert [f["ok"] for f in report["files"]] == [True, False]
    assert report["files"][0]["robot"] == "jtbot"
    diagnostic = report["files"][1]["diagnostics"][0]
    assert set(diagnostic) == {"code", "severity", "message", "path", "line", "column", "element", "subjects", "hint", "model", "trace", "fix"}
    assert (diagnostic["code"], diagnostic["severity"], diagnostic["line"], diagnostic["element"]) == ("J003", "error", 1, "joint[@name='j']")
    errors = sum(d["severity"] == "error" for f in report["files"] for d in f["diagnostics"])
    warnings = sum(d["severity"] == "warning" for f in report["files"] for d in f["diagnostics"])
    info = sum(d["severity"] == "info" for f in report["files"] for d in f["diagnostics"])
    assert report["summary"] == {"files": 2, "errors": errors, "warnings": warnings, "info": info}


def test_strict_fails_on_warnings(tmp_path):
    path = tmp_path / "w.urdf"
    path.write_text(robot(link_a(inertial(inertia='ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.01"'))))  # I006, a warning
    assert run_cli("check", str(path)).returncode == 0
    assert run_cli("check", "--strict", str(path)).returncode == 1


def test_standard_input(tmp_path):
    done = run_cli("check", "-", input=robot(BASE + FIXED))
    assert done.returncode == 0
    assert done.stdout.decode().startswith("robot name is: r\n")
    xacro_input = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property name="n" value="a"/><link name="${n}"/></robot>'
    done = run_cli("check", "-", input=xacro_input)
    assert done.returncode == 0, done.stderr
    assert "root Link: a has 0 child(ren)" in done.stdout.decode()


def test_could_not_run_is_exit_2_with_one_line(tmp_path):
    missing = run_cli("check", str(tmp_path / "missing.urdf"))
    assert missing.returncode == 2
    assert missing.stderr.decode().splitlines() == [f"urdfcli: {tmp_path / 'missing.urdf'}: no such file"]
    directory = run_cli("check", str(tmp_path))  # a folder is searched for models: none here
    assert directory.returncode == 2 and "no robot model in this folder" in directory.stderr.decode()
    option = run_cli("check", "--no-such-option", "x.urdf")
    assert option.returncode == 2 and b"Traceback" not in option.stderr
    bad_format = run_cli("check", "--format", "yaml", str(FIXTURES / "seed003" / "jtbot.urdf"))
    assert bad_format.returncode == 2


def test_many_files_each_get_a_verdict_worst_exit_code_wins(tmp_path):
    good = tmp_path / "good.urdf"
    good.write_text(robot(BASE + FIXED))
    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot")
    done = run_cli("check", "--format", "json", str(good), str(bad))
    assert done.returncode == 1
    assert [f["ok"] for f in json.loads(done.stdout)["files"]] == [True, False]
    done = run_cli("check", "--format", "json", str(good), str(tmp_path / "missing.urdf"))
    assert done.returncode == 2
    assert [f["ok"] for f in json.loads(done.stdout)["files"]] == [True]


def test_xacro_diagnostic_without_origin_says_so(tmp_path):
    # xacro:element builds a tag from an expression: its origin is lost, the expanded line is given.
    path = tmp_path / "dyn.urdf.xacro"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n<link name="a"/>\n<xacro:element xacro:name="link"/>\n</robot>\n')
    done = run_cli("check", str(path))
    assert "N001" in done.stderr.decode()
    assert "(line in the xacro-expanded document)" in done.stderr.decode()


def test_check_imports_no_heavy_library():
    """Meshes, numpy and Graphviz are for the commands and rules that need them."""
    import subprocess
    import sys

    code = (
        "import sys; from urdfcli.cli import main\n"
        "main(['check', sys.argv[1]])\n"
        "heavy = ('yourdfpy', 'trimesh', 'scipy', 'graphviz', 'numpy', 'networkx')\n"
        "print(sorted(m for m in heavy if m in sys.modules))"
    )
    # the last one warns while its model is read (M003), before `check` loads its rules
    models = ("seed003/jtbot.urdf.xacro", "urdf02_gazebo/urdf/car.urdf.xacro", "urdf01_rviz/urdf/xacro/car.urdf.xacro")
    for model in (FIXTURES / name for name in models):
        done = subprocess.run([sys.executable, "-c", code, str(model)], capture_output=True, text=True)
        assert done.stdout.strip().splitlines()[-1] == "[]", done.stdout


# -- xacro found by content, whatever the file is named --------------------------------------
XACRO_NS = "http://www.ros.org/wiki/xacro"
LINK_BY_MACRO = '<xacro:macro name="m"><link name="made"/></xacro:macro><xacro:m/>'
LINK_BY_PROPERTY_BELOW = f'<xacro:property xmlns:xacro="{XACRO_NS}" name="n" value="made"/><link name="${{n}}"/>'  # bound below the root


@pytest.mark.parametrize(
    "text, encoding",
    [
        (f'<robot name="r" xmlns:xacro="{XACRO_NS}">{LINK_BY_MACRO}</robot>', "utf-8"),
        (f'<robot name="r">{LINK_BY_PROPERTY_BELOW}</robot>', "utf-8"),
        (f'<?xml version="1.0" encoding="UTF-16"?><robot name="r">{LINK_BY_PROPERTY_BELOW}</robot>', "utf-16"),
    ],
    ids=["namespace-on-root", "prefix-below-root", "utf-16"],
)
def test_a_urdf_named_file_with_xacro_in_it_is_expanded(tmp_path, text, encoding):
    path = tmp_path / "robot.urdf"
    path.write_bytes(text.encode(encoding))
    loaded = load(str(path))
    assert loaded.loaded.document.is_xacro
    assert "made" in loaded.robot.links


def test_a_plain_urdf_is_not_expanded(tmp_path):
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r"><link name="plain"/><!-- xacro is not used here --></robot>')
    loaded = load(str(path))
    assert not loaded.loaded.document.is_xacro
    assert list(loaded.robot.links) == ["plain"]


def test_xacro_found_by_content_expands_as_when_named_xacro(tmp_path):
    """Its white space is kept for xacro, though a plain URDF's is dropped when read."""
    text = f'<robot name="r" xmlns:xacro="{XACRO_NS}">\n  <xacro:macro name="unused"><link name="a"/></xacro:macro>\n</robot>\n'
    (tmp_path / "robot.urdf").write_text(text)
    (tmp_path / "robot.urdf.xacro").write_text(text)

    def expanded(name):
        lines = load(str(tmp_path / name)).loaded.document.expanded_text.splitlines()
        return [line for line in lines if "autogenerated by xacro from" not in line]

    assert expanded("robot.urdf") == expanded("robot.urdf.xacro")
    assert expanded("robot.urdf")[-2:] == ['<robot name="r">', "</robot>"]  # as xacro writes it, white space kept


def test_links_all_cut_off_by_a_missing_parent_are_not_many_roots(tmp_path):
    """A part read alone whose links all hang from a link its includer makes (Clearpath's
    w200.urdf.xacro: four wheels on diff units its macro makes): the J005 says it, once."""
    path = tmp_path / "wheels.urdf"
    path.write_text('<robot name="r"><link name="left_wheel"/><link name="right_wheel"/>'
                    '<joint name="left" type="fixed"><parent link="axle"/><child link="left_wheel"/></joint>'
                    '<joint name="right" type="fixed"><parent link="axle"/><child link="right_wheel"/></joint></robot>')
    done = run_cli("check", "--format", "json", str(path))
    assert {d["code"] for d in json.loads(done.stdout)["files"][0]["diagnostics"]} == {"J005"}


def test_a_link_cut_off_by_a_missing_parent_is_not_a_second_root(tmp_path):
    path = tmp_path / "cut.urdf"
    path.write_text('<robot name="r"><link name="base_link"/><link name="upper_arm"/><link name="forearm"/><link name="spare"/>'
                    '<joint name="shoulder" type="fixed"><parent link="base_link"/><child link="upper_arm"/></joint>'
                    '<joint name="elbow" type="fixed"><parent link="upper_arms"/><child link="forearm"/></joint></robot>')
    done = run_cli("check", "--format", "json", str(path))
    found = [(d["code"], d["message"]) for d in json.loads(done.stdout)["files"][0]["diagnostics"]]
    # the J005 alone explains 'forearm'; 'spare' is a second root of its own
    assert sorted(found) == [("J005", "parent link 'upper_arms' of joint 'elbow' does not exist"), ("T001", "2 links have no parent: 'base_link', 'spare'")]


def test_an_error_the_model_reports_with_xacro_error_fails_the_check(tmp_path):
    """Shadow's hand validates its arguments and calls xacro.error() on a wrong one (fingers:=th,xx):
    xacro prints the error and writes the URDF anyway. The check fails on it, at the element
    that reported it, and passes with a valid argument; xacro.warning() stays a warning."""
    (tmp_path / "hand.urdf.xacro").write_text(
        f'<robot name="r" xmlns:xacro="{XACRO_NS}">\n'
        '  <xacro:arg name="fingers" default="th"/>\n'
        "  <xacro:unless value=\"${'$(arg fingers)' in ['th', 'ff']}\">${xacro.error('Unknown finger specifier: $(arg fingers)')}</xacro:unless>\n"
        "  ${xacro.warning('Parameter lf is deprecated')}\n"
        '  <link name="palm"/>\n</robot>\n'
    )
    done = run_cli("check", "hand.urdf.xacro", "fingers:=xx", "--format", "json", cwd=tmp_path)
    found = {d["code"] + " " + d["severity"]: d for d in json.loads(done.stdout)["files"][0]["diagnostics"]}
    assert done.returncode == 1
    assert sorted(found) == ["X005 error", "X005 warning"]
    assert (found["X005 error"]["message"], found["X005 error"]["line"]) == ("Unknown finger specifier: xx", 3)
    assert found["X005 warning"]["message"] == "Parameter lf is deprecated"
    done = run_cli("check", "hand.urdf.xacro", "fingers:=ff", "--format", "json", cwd=tmp_path)
    assert done.returncode == 0 and [d["severity"] for d in json.loads(done.stdout)["files"][0]["diagnostics"]] == ["warning"]


def test_what_the_model_reported_with_xacro_error_before_its_expansion_stopped_is_said_too(tmp_path):
    """Shadow's hand given hand_type:=hand_g with the E3M5 version: its check of the pair says why
    (xacro.error()), then the include of the G hand's file fails; both are said, the cause too."""
    (tmp_path / "hand.urdf.xacro").write_text(
        f'<robot name="r" xmlns:xacro="{XACRO_NS}">\n'
        '  <xacro:arg name="hand_type" default="hand_e"/>\n'
        "  <xacro:unless value=\"${'$(arg hand_type)' == 'hand_e'}\">${xacro.error('hand_type $(arg hand_type) does not fit version E3M5')}</xacro:unless>\n"
        '  <xacro:include filename="$(arg hand_type).xacro"/>\n'
        '  <link name="palm"/>\n</robot>\n'
    )
    (tmp_path / "hand_e.xacro").write_text(f'<robot xmlns:xacro="{XACRO_NS}"/>\n')
    done = run_cli("check", "hand.urdf.xacro", "hand_type:=hand_g", "--format", "json", cwd=tmp_path)
    found = [(d["code"], d["line"], d["message"]) for d in json.loads(done.stdout)["files"][0]["diagnostics"]]
    assert done.returncode == 1
    assert ("X005", 3, "hand_type hand_g does not fit version E3M5") in found and [code for code, _, _ in found].count("X003") == 1
