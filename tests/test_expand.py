"""urdfcli expand against the real xacro CLI, and its error handling."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from conftest import FIXTURES, run_cli
from differential import canonical, real_xacro

from urdfcli.read import packages

XACRO_FIXTURES = sorted(p for p in FIXTURES.rglob("*.xacro"))


@pytest.mark.parametrize("path", XACRO_FIXTURES, ids=lambda p: str(p.relative_to(FIXTURES)))
def test_expand_matches_the_xacro_tool(path):
    real = real_xacro(path)
    mine = run_cli("expand", str(path), "-P", str(FIXTURES))
    if real.returncode != 0:
        # The same inputs fail (partial files, undeclared arguments): one short message, exit 1.
        assert mine.returncode == 1
        assert mine.stdout == b""
        assert len(mine.stderr.decode().strip().splitlines()) <= 2
        return
    assert mine.returncode == 0, mine.stderr
    assert canonical(mine.stdout.decode()) == canonical(real.stdout)
    assert mine.stdout.decode() == real.stdout  # byte for byte, banner included


def test_arguments_are_passed_to_xacro():
    path = FIXTURES / "seed000" / "broken_xacro_robot.urdf.xacro"
    real = real_xacro(path, "use_gpu_laser:=false")
    mine = run_cli("expand", str(path), "use_gpu_laser:=false")
    assert real.returncode != 0 and mine.returncode == 1  # next it needs $(find my_robot): no such package
    assert "my_robot" in real.stderr
    assert "package 'my_robot' not found" in mine.stderr.decode()


def test_find_resolves_own_package_from_any_directory(tmp_path):
    path = FIXTURES / "urdf01_rviz" / "urdf" / "xacro" / "car_find.urdf.xacro"
    mine = run_cli("expand", str(path), cwd=tmp_path)
    assert mine.returncode == 0, mine.stderr
    assert canonical(mine.stdout.decode()) == canonical(real_xacro(path).stdout)


def test_find_uses_package_name_not_folder_name(tmp_path):
    workspace = tmp_path / "ws" / "src"
    (workspace / "folder_a" / "urdf").mkdir(parents=True)
    (workspace / "folder_b" / "urdf").mkdir(parents=True)
    (workspace / "folder_a" / "package.xml").write_text("<package format='2'><name>robot_description</name></package>")
    (workspace / "folder_b" / "package.xml").write_text("<package format='2'><name>robot_parts</name></package>")
    (workspace / "folder_b" / "urdf" / "arm.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:macro name="arm"><link name="arm"/>'
        '<joint name="j" type="fixed"><parent link="base"/><child link="arm"/></joint></xacro:macro></robot>'
    )
    top = workspace / "folder_a" / "urdf" / "robot.urdf.xacro"
    top.write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:include filename="$(find robot_parts)/urdf/arm.xacro"/><link name="base"/><xacro:arm/></robot>'
    )
    mine = run_cli("expand", str(top), cwd=tmp_path)
    assert mine.returncode == 0, mine.stderr
    assert '<link name="arm"/>' in mine.stdout.decode()
    check = run_cli("check", str(top), cwd=tmp_path)
    assert check.returncode == 0, check.stderr


@pytest.mark.parametrize(
    "manifest, name",
    [
        ("<?xml version='1.0'?>\n<?xml-model href='http://download.ros.org/schema/package_format3.xsd'?>\n"
         "<package format='3'>\n  <name> robot_parts </name>\n  <version>1.0.0</version>\n</package>\n", "robot_parts"),
        ("<!DOCTYPE package [<!ENTITY n 'robot_parts'>]><package format='2'><name>&n;</name></package>", None),
        ("<package format='2'><name>robot_parts</name>", None),
    ],
    ids=["format 3", "an entity, never expanded", "not well-formed"],
)
def test_a_package_is_known_by_the_name_its_manifest_gives(tmp_path, manifest, name):
    (tmp_path / "package.xml").write_text(manifest)
    assert packages.read_package_name(tmp_path / "package.xml") == name


def test_package_path_option_and_environment(tmp_path):
    lib = tmp_path / "elsewhere" / "lib_folder"
    lib.mkdir(parents=True)
    (lib / "package.xml").write_text("<package><name>shared_lib</name></package>")
    (lib / "m.xacro").write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="base"/></robot>')
    top = tmp_path / "top.urdf.xacro"
    top.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:include filename="$(find shared_lib)/m.xacro"/></robot>')
    assert run_cli("expand", str(top)).returncode == 1
    assert run_cli("expand", str(top), "-P", str(tmp_path / "elsewhere")).returncode == 0
    assert run_cli("expand", str(top), "-P", f"shared_lib={lib}").returncode == 0
    assert run_cli("expand", str(top), env={"ROS_PACKAGE_PATH": str(tmp_path / "elsewhere")}).returncode == 0
    share = tmp_path / "prefix" / "share" / "shared_lib"
    shutil.copytree(lib, share)
    assert run_cli("expand", str(top), env={"AMENT_PREFIX_PATH": str(tmp_path / "prefix")}).returncode == 0


XACRO_ERRORS = {
    "undefined property": ('<link name="${nope}"/>', "name 'nope' is not defined", 3),
    "undefined macro": ("<xacro:nothere/>", "unknown macro name: xacro:nothere", 3),
    "undefined argument": ('<link name="$(arg missing)"/>', "Undefined substitution argument missing", 3),
    "missing include": ('<xacro:include filename="missing.xacro"/>', "cannot include missing.xacro", 3),
    "runaway recursion": ('<xacro:macro name="loop"><xacro:loop/></xacro:macro>\n  <xacro:loop/>', "runaway recursion in macro 'loop'", 3),
}


@pytest.mark.parametrize("body,message,line", XACRO_ERRORS.values(), ids=XACRO_ERRORS.keys())
def test_xacro_errors_are_one_short_line_with_file_and_line(tmp_path, body, message, line):
    path = tmp_path / "bad.urdf.xacro"
    path.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="base"/>\n  {body}\n</robot>\n')
    out = tmp_path / "out.urdf"
    done = run_cli("expand", str(path), "-o", str(out), cwd=tmp_path)
    stderr = done.stderr.decode()
    assert done.returncode == 1
    assert message in stderr
    assert stderr.startswith(f"bad.urdf.xacro:{line}:")
    assert len(stderr.strip().splitlines()) == 1
    assert "Traceback" not in stderr
    assert not out.exists()


def test_a_warning_said_on_many_lines_is_printed_once_with_the_other_lines(tmp_path):
    args = "".join(f'  <xacro:arg name="a{n}" default="1" scope="local"/>\n' for n in range(3))
    path = tmp_path / "arm.urdf.xacro"
    path.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{args}  <link name="base"/>\n</robot>\n')
    done = run_cli("expand", str(path), cwd=tmp_path)
    stderr = done.stderr.decode()
    assert done.returncode == 0, stderr
    assert stderr.count("unknown attribute(s): scope") == 1
    assert stderr.startswith("arm.urdf.xacro:2:")
    assert "note: also at lines 3 and 4" in stderr
    assert '<link name="base"/>' in done.stdout.decode()


def test_a_chain_of_macros_nests_as_deep_as_under_the_xacro_tool(tmp_path):
    """A cable or snake robot made by a macro that calls itself for the next segment:
    200 levels, which the xacro tool expands. urdfcli's bookkeeping around xacro's calls
    made Python's recursion limit stop it at about 138 ('runaway recursion ... without
    end'). A recursion without end still is one."""
    model = tmp_path / "cable.urdf.xacro"
    model.write_text(
        '<robot name="cable" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:macro name="segment" params="i">\n'
        '    <link name="s${i}"/>\n'
        '    <joint name="j${i}" type="fixed"><parent link="s${i-1}"/><child link="s${i}"/></joint>\n'
        '    <xacro:if value="${i &lt; 200}"><xacro:segment i="${i+1}"/></xacro:if>\n'
        '  </xacro:macro>\n'
        '  <link name="s0"/>\n'
        '  <xacro:segment i="1"/>\n'
        '</robot>\n'
    )
    real = real_xacro(model)
    assert real.returncode == 0, real.stderr
    mine = run_cli("expand", str(model))
    assert mine.returncode == 0, mine.stderr
    assert mine.stdout.decode() == real.stdout
    model.write_text(model.read_text().replace("${i &lt; 200}", "true"))
    done = run_cli("expand", str(model))
    assert done.returncode == 1 and "runaway recursion in macro 'segment'" in done.stderr.decode()


def test_include_cycle(tmp_path):
    (tmp_path / "a.urdf.xacro").write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n<xacro:include filename="b.xacro"/></robot>')
    (tmp_path / "b.xacro").write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n\n<xacro:include filename="a.urdf.xacro"/></robot>')
    done = run_cli("expand", "a.urdf.xacro", cwd=tmp_path)
    assert done.returncode == 1
    assert done.stderr.decode().strip() == "b.xacro:3:1: X003 error: include cycle: a.urdf.xacro -> b.xacro -> a.urdf.xacro"


def test_error_inside_macro_of_included_file_points_at_the_included_file(tmp_path):
    (tmp_path / "parts.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:macro name="wheel" params="side">\n'
        '    <link name="${side}_wheel"/>\n'
        '    <joint name="${side}_joint" type="continuous">\n'
        '      <parent link="chassis"/>\n'
        '      <child link="${side}_wheel"/>\n'
        "    </joint>\n"
        "  </xacro:macro>\n"
        "</robot>\n"
    )
    (tmp_path / "robot.urdf.xacro").write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:include filename="parts.xacro"/>\n'
        '  <link name="base"/>\n'
        '  <xacro:wheel side="left"/>\n'
        "</robot>\n"
    )
    done = run_cli("check", "robot.urdf.xacro", cwd=tmp_path)
    assert done.returncode == 1
    assert "parts.xacro:5:7: J005 error: parent link 'chassis' of joint 'left_joint' does not exist" in done.stderr.decode()


def test_deps_lists_included_files(tmp_path):
    path = FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"
    done = run_cli("expand", "--deps", str(path))
    assert done.returncode == 0
    listed = {Path(line).name for line in done.stdout.decode().split()}
    real = {Path(name).name for name in real_xacro(path, "--deps").stdout.split()}
    assert listed == real == {"head.xacro", "demo05_car_base.urdf.xacro", "demo06_car_camera.urdf.xacro", "demo07_car_laser.urdf.xacro"}


def test_output_file_is_written_and_input_is_never_overwritten(tmp_path):
    source = FIXTURES / "urdf01_rviz" / "urdf" / "xacro" / "car.urdf.xacro"
    copy = tmp_path / "car"
    shutil.copytree(source.parent, copy)
    target = copy / "car.urdf.xacro"
    before = target.read_bytes()
    refused = run_cli("expand", str(target), "-o", str(target))
    assert refused.returncode == 2
    assert "refusing to overwrite the input" in refused.stderr.decode()
    assert target.read_bytes() == before
    out = tmp_path / "car.urdf"
    assert run_cli("expand", str(target), "-o", str(out)).returncode == 0
    assert canonical(out.read_text()) == canonical(real_xacro(source).stdout)
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []  # no temporary file left


YAML_MODEL = (
    '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
    "  <xacro:property name=\"p\" value=\"${xacro.load_yaml('params.yaml')}\"/>\n"
    "  <link name=\"${p['arm']['name']}\">\n"
    "    <visual><geometry><cylinder radius=\"${p['arm']['offsets'][0]}\" length=\"${p['arm']['length']}\"/></geometry></visual>\n"
    "  </link>\n"
    "  <link name=\"second\"/>\n"
    "</robot>\n"
)
CDATA_MODEL = (
    '<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
    '  <xacro:property name="w" value="1"/>\n  <xacro:include filename="part.xacro"/>\n'
    '  <link name="a"/>\n'
    '  <gazebo><plugin name="p"><![CDATA[ a < b ${w} ]]></plugin><x>t <![CDATA[<c>]]> u</x></gazebo>\n</robot>\n'
)


@pytest.mark.parametrize(
    "files, printed",
    [
        (
            {"params.yaml": "arm:\n  name: upper_arm\n  length: 0.35\n  offsets: [0.1, 0.2]\n", "model.urdf.xacro": YAML_MODEL},
            ['name="upper_arm"', 'length="0.35"'],
        ),
        (
            {
                "part.xacro": '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><gazebo reference="a"><![CDATA[ <sdf> & ]]></gazebo></robot>\n',
                "model.urdf.xacro": CDATA_MODEL,
            },
            ["<![CDATA[ a < b ${w} ]]>", "<![CDATA[ <sdf> & ]]>"],
        ),
    ],
    ids=["yaml loaded by xacro.load_yaml", "CDATA sections"],
)
def test_what_xacro_prints_is_printed_byte_for_byte(tmp_path, files, printed):
    """xacro.load_yaml (yaml is imported only when a model uses it); CDATA sections,
    which gazebo plugins and ros2_control blocks sometimes carry, printed as written
    (not as escaped text) in the file given and in the files it includes."""
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    path = tmp_path / "model.urdf.xacro"
    real = real_xacro(path, cwd=tmp_path)
    mine = run_cli("expand", str(path), cwd=tmp_path)
    assert real.returncode == 0, real.stderr
    assert mine.returncode == 0, mine.stderr
    assert all(text in real.stdout for text in printed)
    assert mine.stdout.decode() == real.stdout


@pytest.mark.parametrize("attribute", ["${xacro.load_yaml('gone.yaml')['mass']}", "${load_yaml('gone.yaml')['mass']}"])
def test_a_yaml_file_that_is_not_there_is_named_as_xacro_names_it(tmp_path, attribute):
    """load_yaml read in an attribute: xacro wraps the OSError without a message of its own."""
    (tmp_path / "model.urdf.xacro").write_text(
        f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="base">\n'
        f'    <inertial><mass value="{attribute}"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>\n'
        "  </link>\n</robot>\n"
    )
    real = real_xacro(tmp_path / "model.urdf.xacro", cwd=tmp_path)
    assert real.returncode != 0 and "No such file or directory: " in real.stderr and "gone.yaml'" in real.stderr
    done = run_cli("check", "model.urdf.xacro", cwd=tmp_path)
    assert done.returncode == 1
    first = done.stderr.decode().splitlines()[0]
    assert first.startswith("model.urdf.xacro:3:15: X003 error: [Errno 2] No such file or directory: ") and "gone.yaml' when evaluating expression" in first, first


UNITREE_ROBOT = """<?xml version="1.0"?>
<robot name="{name}" xmlns:xacro="http://www.ros.org/wiki/xacro">
    <link name="base"/>
    <xacro:if value="$(arg DEBUG)">
        <link name="world"/>
        <joint name="base_static_joint" type="fixed"><parent link="world"/><child link="base"/></joint>
    </xacro:if>
</robot>
"""


def test_expand_reads_the_configured_xacro_arguments(tmp_path):
    """unitree_ros: each robot's xacro/robot.xacro needs argument DEBUG, given in urdfcli.toml.
    check, lint, tree and drift read it there; expand stopped at X003 Undefined substitution
    argument DEBUG, so the command X110's hint gives failed. It expands as the xacro tool does
    with the configured value; the command line wins; --isolated and --config are accepted."""
    for name in ("go1", "a1"):
        (tmp_path / "robots" / f"{name}_description" / "xacro").mkdir(parents=True)
        (tmp_path / "robots" / f"{name}_description" / "xacro" / "robot.xacro").write_text(UNITREE_ROBOT.format(name=name))
    (tmp_path / "urdfcli.toml").write_text('[xacro-args]\n"robots/go1_description/xacro/robot.xacro" = { DEBUG = "false" }\n')
    go1 = "robots/go1_description/xacro/robot.xacro"
    done = run_cli("expand", go1, "-o", "go1.urdf", cwd=tmp_path)
    assert done.returncode == 0, done.stderr.decode()
    assert (tmp_path / "go1.urdf").read_text() == real_xacro(Path(go1), "DEBUG:=false", cwd=tmp_path).stdout
    done = run_cli("expand", go1, "DEBUG:=true", cwd=tmp_path)
    assert done.stdout.decode() == real_xacro(Path(go1), "DEBUG:=true", cwd=tmp_path).stdout and "world" in done.stdout.decode()
    # the other robot is not configured, and without the configuration neither is go1
    for args in (["robots/a1_description/xacro/robot.xacro"], ["--isolated", go1]):
        done = run_cli("expand", *args, cwd=tmp_path)
        assert done.returncode == 1 and "Undefined substitution argument DEBUG" in done.stderr.decode(), done.stderr.decode()
    (tmp_path / "debug.toml").write_text('[xacro-args]\n"robot.xacro" = { DEBUG = "true" }\n')
    done = run_cli("expand", "--config", "debug.toml", go1, cwd=tmp_path)
    assert done.stdout.decode() == real_xacro(Path(go1), "DEBUG:=true", cwd=tmp_path).stdout
