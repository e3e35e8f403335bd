"""urdfcli as a library: check and lint from Python as the command line does, never
printing or exiting, and giving back what it took when a session ends."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import FIXTURES, run_cli

import urdfcli

CAR = FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"
CRANE = FIXTURES / "seed001" / "broken_inertia_crane.urdf"
XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def test_the_readme_example(tmp_path):
    model = tmp_path / "urdf" / "robot.urdf.xacro"
    model.parent.mkdir()
    model.write_text(
        f'<robot name="r" {XACRO}><xacro:arg name="ur_type" default="ur3"/><link name="$(arg ur_type)_base"/></robot>'
    )
    result = urdfcli.check(str(model), "ur_type:=ur5e")
    assert not result.errors, urdfcli.text_report(result)
    assert list(result.robot.links) == ["ur5e_base"]
    results = urdfcli.lint([CRANE, CAR])
    assert [r.path for r in results] == [str(CRANE), str(CAR)]
    assert results[0].warnings and results[0].robot.name


def test_a_result_is_what_check_prints(tmp_path, capsys):
    result = urdfcli.check(CRANE)  # a Path is an input too
    assert capsys.readouterr() == ("", "")  # nothing printed
    done = run_cli("check", "--format", "json", str(CRANE))
    [printed] = json.loads(done.stdout)["files"]
    assert [(d.code, d.severity.value, d.message, d.path, d.line, d.column) for d in result.diagnostics] == [
        (d["code"], d["severity"], d["message"], d["path"], d["line"], d["column"]) for d in printed["diagnostics"]
    ]
    # the crane names meshes of its author's machine: missing files, the only errors
    assert {d.code for d in result.errors} == {"D004"} and not result.ok
    assert result.warnings == [d for d in result.diagnostics if d.code != "D004"]
    first = result.diagnostics[0]
    assert first.hint is None or isinstance(first.hint, str)
    assert first.trace == ()
    assert set(result.robot.joints) and all(joint.parent in result.robot.links for joint in result.robot.joints.values())


def test_the_report_is_the_text_format():
    result = urdfcli.check(CRANE)
    report = urdfcli.text_report(result)
    summary = f"1 file checked: {len(result.errors)} error, {len(result.warnings)} warnings\n"
    # then what --fix could do: the crane's inertias, from its geometry (unsafe fixes)
    assert report.endswith(summary + "2 fixes available with --fix --unsafe-fixes\n")
    assert f"{CRANE}:" in report and "    hint: " in report and "^" in report
    assert report == run_cli("lint", "--select", ",".join(sorted({d.code for d in result.diagnostics})), str(CRANE)).stdout.decode()


def test_a_macro_call_is_in_the_trace(tmp_path):
    (tmp_path / "robot.urdf.xacro").write_text(
        f'<robot name="r" {XACRO}>\n<xacro:macro name="wheel"><link name="w"/><joint name="j" type="continuous">'
        '<parent link="nowhere"/><child link="w"/></joint></xacro:macro>\n<link name="base"/>\n<xacro:wheel/>\n</robot>'
    )
    result = urdfcli.check(tmp_path / "robot.urdf.xacro")
    [error] = result.errors
    assert error.code == "J005" and error.line == 2
    assert [(call.macro, call.line) for call in error.trace] == [("wheel", 4)]


def test_problems_with_the_input_raise_and_nothing_exits(tmp_path):
    with pytest.raises(urdfcli.UsageError, match="no such file"):
        urdfcli.check(tmp_path / "missing.urdf")
    with pytest.raises(urdfcli.UsageError, match="not a directory"):
        urdfcli.check(CRANE, package_paths=[str(tmp_path / "nowhere")])
    with pytest.raises(urdfcli.UsageError, match="NAME:=VALUE"):
        urdfcli.check(CRANE, "oops")
    (tmp_path / "urdfcli.toml").write_text("selectt = []\n")
    (tmp_path / "r.urdf").write_text('<robot name="r"><link name="a"/></robot>')
    with pytest.raises(urdfcli.UsageError, match="unknown key 'selectt'"):
        urdfcli.lint([tmp_path / "r.urdf"])


def test_configuration_is_found_as_the_command_line_finds_it(tmp_path):
    (tmp_path / "pyproject.toml").write_text('[tool.urdfcli]\nextend-select = ["S001"]\n')
    (tmp_path / "robot.urdf").write_text('<robot name="r"><link name="base"/></robot>')
    [result] = urdfcli.lint([tmp_path])
    assert [d.code for d in result.diagnostics] == ["S001"]
    assert urdfcli.lint([tmp_path], isolated=True)[0].diagnostics == ()


def test_one_session_serves_many_calls_and_is_given_back():
    with urdfcli.Session() as session:
        first = urdfcli.check(CAR, session=session)
        second = urdfcli.check(CAR, session=session)
        assert session.expander.worker._process is not None  # one xacro worker for both
    assert session.expander.worker._process is None
    assert first.diagnostics == second.diagnostics


CHECKS = """
import os, sys, urdfcli
folder = sys.argv[1]
models = sorted(os.listdir(folder))

def resident():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")

for i, name in enumerate(models):
    with urdfcli.Session() as session:
        result = urdfcli.check(os.path.join(folder, name), session=session)
    assert result.robot is not None and result.warnings, name
    if i == 49:
        start = resident()
print((resident() - start) / 2**20)
"""


def test_checking_500_models_one_session_each_does_not_grow(tmp_path):
    """A long-lived caller gets back what each session took: 500 different models of
    100 links each (a quarter of them xacro) leave the process within 50 MB of where
    it stood after the first 50. A result kept alive would hold about 0.9 MB each (390 MB
    over the 450)."""
    folder = tmp_path / "models"
    folder.mkdir()
    for i in range(500):
        links = "".join(
            f'<link name="l{i}_{k}"><inertial><mass value="{1 + k % 7}"/>'
            f'<inertia ixx="{0.01 * (k + 1)}" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.5"/></inertial>'
            f'<visual><geometry><box size="0.1 0.2 {0.1 + k / 1000}"/></geometry></visual></link>'
            + (f'<joint name="j{i}_{k}" type="revolute"><parent link="l{i}_{k - 1}"/><child link="l{i}_{k}"/>'
               f'<limit lower="-1" upper="1" effort="10" velocity="1"/></joint>' if k else "")
            for k in range(100)
        )
        xacro = i % 4 == 0
        name = f"m{i:03}.urdf.xacro" if xacro else f"m{i:03}.urdf"
        (folder / name).write_text(f'<robot name="r{i}"{" " + XACRO if xacro else ""}>{links}</robot>')
    done = subprocess.run([sys.executable, "-c", CHECKS, str(folder)], capture_output=True, text=True, timeout=600,
                          env={**os.environ, "PYTHONPATH": str(Path(urdfcli.__file__).parent.parent)})
    assert done.returncode == 0, done.stderr
    grown = float(done.stdout.strip())
    assert grown < 50, f"grew by {grown:.1f} MB"


def test_every_name_the_readme_gives_is_there_and_robot_is_none_for_what_holds_no_robot(tmp_path):
    """The README's API: urdfcli.drift(paths) among them; result.robot is None when no robot
    could be read (a package.xml given by mistake: R001), not a robot without a root."""
    for name in ("check", "lint", "diff", "drift", "text_report", "Session", "Options", "UsageError", "Result"):
        assert getattr(urdfcli, name) is not None
    manifest = tmp_path / "package.xml"
    manifest.write_text('<package format="3"><name>p</name></package>\n')
    result = urdfcli.check(manifest)
    assert [d.code for d in result.diagnostics] == ["R001"] and result.robot is None
    urdf = tmp_path / "r.urdf"
    urdf.write_text('<robot name="r"><link name="a"/></robot>\n')
    assert urdfcli.drift([urdf]) == [] and list(urdfcli.check(urdf).robot.links) == ["a"]
