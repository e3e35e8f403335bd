"""`urdfcli lint` end to end: exit codes, folders, parallel runs, suppressions."""

from __future__ import annotations

import json
import textwrap

from conftest import FIXTURES, lint_file, run_cli

from urdfcli.options import Options
from urdfcli.project.config import Config

CLEAN = FIXTURES / "urdf01_rviz/urdf/urdf/demo01_helloworld.urdf"
TYPO = FIXTURES / "urdf01_rviz/urdf/urdf/demo03_joint.urdf"  # <color rgb=...>: D002 and M002, warnings only


def write(folder, name, text):
    path = folder / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))
    return path


def concise(*args, cwd=None):
    done = run_cli("lint", "--format", "concise", *args, cwd=cwd)
    return done, done.stdout.decode().splitlines()


def test_exit_codes(tmp_path):
    assert run_cli("lint", str(CLEAN)).returncode == 0
    assert run_cli("lint", str(TYPO)).returncode == 1
    assert run_cli("check", str(TYPO)).returncode == 0  # check fails on errors only
    assert run_cli("lint", "--exit-zero", str(TYPO)).returncode == 0
    missing = run_cli("lint", "--exit-zero", str(tmp_path / "missing.urdf"))
    assert missing.returncode == 2
    assert missing.stderr.decode().splitlines()[0] == f"urdfcli: {tmp_path / 'missing.urdf'}: no such file"
    broken = write(tmp_path, "broken.urdf", '<robot name="r"><link name="a"></robot>\n')
    assert run_cli("lint", str(broken)).returncode == 1
    assert run_cli("lint", "--format", "nope", str(CLEAN)).returncode == 2


def test_the_documented_fixture_mistakes_are_found():
    _, lines = concise(str(TYPO))
    assert lines == [
        f"{TYPO}:1:1: D003 info: no link has a <collision>: the model can be displayed, not simulated or planned with"
        " (hint: add collision shapes to the moving links if it is meant for simulation or planning)",
        f"{TYPO}:9:13: M002 warning: material 'car_color' is defined nowhere (hint: define it at the top level, or give it a <color rgba>)",
        f"{TYPO}:10:24: D002 warning: <color> has no attribute 'rgb'; it is ignored (hint: did you mean 'rgba'?)",
    ]
    jtbot = FIXTURES / "seed003/jtbot.urdf"
    _, lines = concise("--select", "D", str(jtbot))
    assert lines[0].startswith(f"{jtbot}:382:3: D006 warning: <gazebo reference='camera_depth_link'> names no link or joint (hint: ") and len(lines) == 1


def test_a_correct_plugin_model_has_no_description_warnings():
    done, lines = concise("--select", "D", str(FIXTURES / "urdf02_gazebo/urdf/car_with_plugins.urdf.xacro"))
    assert done.returncode == 0 and lines == []


def test_folders_are_searched_for_models_only(tmp_path):
    for name in ("a.urdf", "sub/b.urdf.xacro", ".hidden/c.urdf", "build/d.urdf"):
        write(tmp_path, name, '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="Bad"/></robot>\n')
    # ROS 1's ur5.xacro: a model named *.xacro, calling the macro its library defines
    write(tmp_path, "sub/macros.xacro", '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:macro name="arm"><link name="Bad"/></xacro:macro></robot>\n')
    write(tmp_path, "sub/ur5.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:include filename="macros.xacro"/><xacro:arm/></robot>\n')
    for command in ("lint", "check"):
        done = run_cli(command, "--format", "concise", "--isolated", *(["--select", "S003"] if command == "lint" else []), str(tmp_path))
        summary = done.stderr.decode().splitlines()[-1]
        assert summary.startswith("3 files checked"), (command, summary)  # a.urdf, b.urdf.xacro, ur5.xacro: not the library, hidden or build folders
    _, lines = concise("--select", "S003", str(tmp_path))
    assert [line.split(":")[0] for line in lines] == [str(tmp_path / "a.urdf"), str(tmp_path / "sub/b.urdf.xacro"), str(tmp_path / "sub/macros.xacro")]
    assert lines[2].endswith(f"(in macro 'arm' called at {tmp_path / 'sub/ur5.xacro'}:1:101)")
    _, lines = concise("--select", "S003", str(tmp_path / "sub/macros.xacro"))
    assert len(lines) == 1  # named explicitly, a library is linted through its model
    empty = tmp_path / "empty"
    empty.mkdir()
    for command in ("lint", "check"):
        done = run_cli(command, str(empty))
        assert done.returncode == 2 and done.stderr.decode() == f"urdfcli: {empty}: no robot model in this folder (*.urdf, *.urdf.xacro, *.srdf, or a *.xacro file that makes a robot)\n"


def test_parallel_runs_print_the_same_output_in_the_same_order():
    one = run_cli("lint", "--format", "concise", str(FIXTURES))
    four = run_cli("lint", "--format", "concise", "-j", "4", str(FIXTURES))
    assert one.stdout.decode().count("\n") > 50
    assert (one.returncode, one.stdout, one.stderr) == (four.returncode, four.stdout, four.stderr)
    every_cpu = run_cli("lint", "--format", "json", "-j", "0", str(FIXTURES))
    # every model, but not the car's parts (demo05-07), which the car models include: they are checked through them
    parts = [p for p in FIXTURES.rglob("demo0[567]_car_*.urdf.xacro")]
    assert len(parts) == 6
    assert json.loads(every_cpu.stdout)["summary"]["files"] == len([p for p in FIXTURES.rglob("*") if p.name.endswith((".urdf", ".urdf.xacro"))]) - len(parts)


def test_standard_input(tmp_path):
    text = TYPO.read_text()
    done = run_cli("lint", "--format", "concise", "-", input=text)
    assert done.returncode == 1
    line = done.stdout.decode().splitlines()[2]
    assert line.startswith("<stdin>:10:") and line.endswith(": D002 warning: <color> has no attribute 'rgb'; it is ignored (hint: did you mean 'rgba'?)")


# -- suppressions ------------------------------------------------------------------
SUPPRESSED = """\
<robot name="r">
  <material name="a"><color rgba="1 0 0 1"/><color rgb="1 0 0 1"/></material> <!-- urdfcli: noqa: D002 -->
  <!-- urdfcli: noqa: D002, M004 -->
  <material name="b"><color rgba="1 0 0 1"/><color rgb="1 0 0 1"/></material>
  <material name="c"><color rgba="1 0 0 1"/><color rgb="1 0 0 1"/></material>
  <!-- urdfcli: noqa: S001 -->
  <link name="base_link"/>
  <!-- urdfcli: noqa: D099 -->
</robot>
"""


def test_noqa_on_the_line_and_the_line_above(tmp_path):
    model = write(tmp_path, "robot.urdf", SUPPRESSED)
    found = [(d.line, d.code, d.severity.value, d.message) for d in lint_file(str(model), Config()).diagnostics]
    assert found == [
        (3, "U001", "info", "'noqa: M004' silences nothing: no M004 on the element at line 4"),
        (5, "D002", "warning", "<color> has no attribute 'rgb'; it is ignored"),
        (8, "U002", "warning", "'noqa: D099' names no rule"),
    ]
    # S001 is off by default: its suppression is not reported as unused
    selected = [(d.line, d.code) for d in lint_file(str(model), Config(extend_select=("S001",))).diagnostics]
    assert (6, "U001") in selected


def test_noqa_file_silences_a_code_everywhere_in_its_file(tmp_path):
    model = write(tmp_path, "robot.urdf", SUPPRESSED.replace("<robot name=\"r\">", "<robot name=\"r\"> <!-- urdfcli: noqa-file: D002, D003 -->"))
    found = [(d.line, d.code, d.message) for d in lint_file(str(model), Config()).diagnostics]
    assert (5, "D002", "<color> has no attribute 'rgb'; it is ignored") not in found
    assert (1, "U001", "'noqa-file: D003' silences nothing: no D003 in this file") in found
    assert all(code != "D002" for _, code, _ in found)


def test_only_info_left_exits_0(tmp_path):
    model = write(tmp_path, "robot.urdf", '<robot name="r">\n  <!-- urdfcli: noqa: D002 -->\n  <link name="base_link"/>\n</robot>\n')
    done, lines = concise(str(model))
    assert lines == [f"{model}:2:3: U001 info: 'noqa: D002' silences nothing: no D002 on the element at line 3 (hint: remove it)"]
    assert done.returncode == 0


def test_suppressions_in_an_included_xacro_file(tmp_path):
    write(
        tmp_path,
        "parts.xacro",
        """\
        <robot xmlns:xacro="http://www.ros.org/wiki/xacro">
          <xacro:macro name="part" params="name">
            <!-- urdfcli: noqa: D002 -->
            <link name="${name}" typ="red"/>
          </xacro:macro>
        </robot>
        """,
    )
    model = write(
        tmp_path,
        "robot.urdf.xacro",
        """\
        <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
          <xacro:include filename="parts.xacro"/>
          <xacro:part name="a"/>
          <link name="b" typ="blue"/>
        </robot>
        """,
    )
    found = [(d.file, d.line, d.code) for d in lint_file(str(model), Config(select=("D002", "U"))).diagnostics]
    assert found == [(str(model), 4, "D002")]


def test_progress_bar_only_on_a_terminal_for_a_long_run(monkeypatch):
    import importlib
    import io

    from rich.console import Console

    from urdfcli import api
    from urdfcli.report.console import Output
    from urdfcli.session import Session

    lint_command = importlib.import_module("urdfcli.cli.lint")  # the module, not the command it defines

    paths = [str(path) for path in sorted(FIXTURES.rglob("*.urdf"))[:3]]
    monkeypatch.setattr(lint_command, "PROGRESS_AFTER", 0.0)
    terminal = io.StringIO()
    with Session(Options(config=Config())) as session, lint_command.Progress(Output(Console(), Console(file=terminal, force_terminal=True, width=100))) as progress:
        found = api.run(paths, session, progress=progress.update)
    assert [r.path for r in found.results] == paths
    assert "linting" in terminal.getvalue()
    piped = io.StringIO()
    with Session(Options(config=Config())) as session, lint_command.Progress(Output(Console(), Console(file=piped, force_terminal=False))) as progress:
        api.run(paths, session, progress=progress.update)
    assert piped.getvalue() == ""


# -- noise: warnings and errors only, statistics ------------------------------------
def test_no_info_shows_warnings_and_errors_and_counts_the_info(tmp_path):
    done, lines = concise("--no-info", str(TYPO))
    assert [line.split(": ")[1].split()[0] for line in lines] == ["M002", "D002"]  # not D003, an info
    assert done.stderr.decode() == "1 file checked: 0 errors, 2 warnings, 1 info (not shown)\n"
    # the configuration says so too, and --info overrides it
    write(tmp_path, "pyproject.toml", "[tool.urdfcli]\nshow-info = false\n")
    model = write(tmp_path, "robot.urdf", TYPO.read_text())
    _, lines = concise(str(model))
    assert len(lines) == 2
    _, lines = concise("--info", str(model))
    assert len(lines) == 3
    text = run_cli("lint", str(model))
    assert " D003 " not in text.stdout.decode() and text.stdout.decode().endswith("1 file checked: 0 errors, 2 warnings, 1 info (not shown)\n")
    # every format: a note hidden from the text is no code-scanning alert or JSON entry either; the summaries count it
    document = json.loads(run_cli("lint", "--format", "json", str(model)).stdout)
    assert [d["code"] for d in document["files"][0]["diagnostics"]] == ["M002", "D002"] and document["summary"]["info"] == 1
    sarif = json.loads(run_cli("lint", "--format", "sarif", str(model)).stdout)
    assert [r["ruleId"] for r in sarif["runs"][0]["results"]] == ["M002", "D002"]
    assert "D003" not in run_cli("lint", "--format", "github", str(model)).stdout.decode()
    assert "D003" in run_cli("lint", "--info", "--format", "sarif", str(model)).stdout.decode()
    write(tmp_path, "pyproject.toml", '[tool.urdfcli]\nshow-info = "no"\n')
    bad = run_cli("lint", str(model))
    assert bad.returncode == 2 and "show-info: expected true or false, not 'no'" in bad.stderr.decode()


def test_statistics_count_each_code(tmp_path):
    done = run_cli("lint", "--statistics", str(TYPO), str(FIXTURES / "seed003/jtbot.urdf"))
    lines = done.stdout.decode().splitlines()
    rows = [line.split() for line in lines[:-1]]
    assert all(row[2] in ("error", "warning", "info") for row in rows) and [int(row[0]) for row in rows] == sorted((int(row[0]) for row in rows), reverse=True)
    assert ["1", "M002", "warning", "material-undefined"] in rows
    assert lines[-1].startswith("2 files checked:")
    total = sum(int(row[0]) for row in rows)
    listed = json.loads(run_cli("lint", "--format", "json", str(TYPO), str(FIXTURES / "seed003/jtbot.urdf")).stdout)
    assert total == sum(len(f["diagnostics"]) for f in listed["files"])
    as_json = json.loads(run_cli("lint", "--statistics", "--format", "json", str(TYPO)).stdout)
    assert {"code": "M002", "name": "material-undefined", "severity": "warning", "count": 1} in as_json
