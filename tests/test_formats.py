"""Every output format of check and lint, on a model with a typo and on one that is not XML."""

from __future__ import annotations

import json
import subprocess

import pytest
from conftest import run_cli

from urdfcli.rules import REGISTRY

TYPO = """<robot name="r">
  <link name="base_link">
    <visual>
      <geometry><box size="1 1 1"/></geometry>
      <material name="grey"><color rgb="0.5 0.5 0.5 1"/></material>
    </visual>
  </link>
</robot>
"""
NOT_XML = '<robot name="r">\n  <link name="a">\n</robot>\n'


@pytest.fixture
def models(tmp_path):
    typo = tmp_path / "typo.urdf"
    typo.write_text(TYPO)
    broken = tmp_path / "broken.urdf"
    broken.write_text(NOT_XML)
    return typo, broken


def run(command, fmt, *paths, env=None):
    return run_cli(command, "--format", fmt, *map(str, paths), env=env)


def test_concise_lint(models):
    typo, broken = models
    done = run("lint", "concise", typo, broken)
    assert done.stdout.decode().splitlines() == [  # one line each, the hint kept
        f"{typo}:5:7: M002 warning: material 'grey' is defined nowhere (hint: define it at the top level, or give it a <color rgba>)",
        f"{typo}:5:36: D002 warning: <color> has no attribute 'rgb'; it is ignored (hint: did you mean 'rgba'?)",
        f"{broken}:3:9: X001 error: Opening and ending tag mismatch: link line 2 and robot",
    ]
    assert done.stderr.decode() == "2 files checked: 1 error, 2 warnings\n"
    assert done.returncode == 1


def test_concise_check_reports_only_check_rules(models):
    typo, broken = models
    done = run("check", "concise", typo, broken)
    assert done.stdout.decode().splitlines() == [
        f"{typo}:5:7: M002 warning: material 'grey' is defined nowhere (hint: define it at the top level, or give it a <color rgba>)",
        f"{broken}:3:9: X001 error: Opening and ending tag mismatch: link line 2 and robot",
    ]


def test_text_has_a_source_excerpt_and_a_summary(models):
    typo, broken = models
    done = run("lint", "text", typo, broken)
    assert done.stderr == b""  # lint writes its whole report on standard output: `> report.txt` holds it
    assert done.stdout.decode().splitlines() == [
        f"{typo}:5:7: M002 warning: material 'grey' is defined nowhere",
        "    hint: define it at the top level, or give it a <color rgba>",
        '     5 |       <material name="grey"><color rgb="0.5 0.5 0.5 1"/></material>',
        "       |       ^",
        f"{typo}:5:36: D002 warning: <color> has no attribute 'rgb'; it is ignored",
        "    hint: did you mean 'rgba'?",
        '     5 |       <material name="grey"><color rgb="0.5 0.5 0.5 1"/></material>',
        "       |                                    ^",
        f"{broken}:3:9: X001 error: Opening and ending tag mismatch: link line 2 and robot",
        "     3 | </robot>",
        "       |         ^",
        "2 files checked: 1 error, 2 warnings",
    ]


def test_check_text_keeps_the_tree_on_stdout(models):
    typo, _ = models
    done = run("check", "text", typo)
    assert done.stdout.decode().splitlines()[0] == "robot name is: r"
    assert "     5 |" in done.stderr.decode()


@pytest.mark.parametrize("command", ["check", "lint"])
def test_json_contract(models, command):
    typo, broken = models
    report = json.loads(run(command, "json", typo, broken).stdout)
    assert set(report) == {"version", "files", "summary"} and report["version"] == 1
    typo_file, broken_file = report["files"]
    assert (typo_file["path"], typo_file["ok"], typo_file["robot"]) == (str(typo), True, "r")
    assert (broken_file["ok"], broken_file["robot"]) == (False, None)
    assert broken_file["diagnostics"] == [
        {"code": "X001", "severity": "error", "message": "Opening and ending tag mismatch: link line 2 and robot",
         "path": str(broken), "line": 3, "column": 9, "element": None, "subjects": [], "hint": None, "model": None, "trace": [], "fix": None}
    ]
    assert typo_file["diagnostics"][0] == {
        "code": "M002", "severity": "warning", "message": "material 'grey' is defined nowhere",
        "path": str(typo), "line": 5, "column": 7, "element": "link[@name='base_link']/visual/material", "subjects": [],
        "hint": "define it at the top level, or give it a <color rgba>", "model": None, "trace": [], "fix": None,
    }
    warnings = 2 if command == "lint" else 1
    assert report["summary"] == {"files": 2, "errors": 1, "warnings": warnings, "info": 0}


@pytest.mark.parametrize("command", ["check", "lint"])
def test_github_annotations(models, command):
    typo, broken = models
    lines = run(command, "github", typo, broken).stdout.decode().splitlines()
    # the hint on a line of its own in the annotation (%0A)
    assert lines[0] == f"::warning file={typo},line=5,col=7,title=M002::material 'grey' is defined nowhere%0Ahint: define it at the top level, or give it a <color rgba>"
    assert lines[-1] == f"::error file={broken},line=3,col=9,title=X001::Opening and ending tag mismatch: link line 2 and robot"
    if command == "lint":
        assert lines[1] == f"::warning file={typo},line=5,col=36,title=D002::<color> has no attribute 'rgb'; it is ignored%0Ahint: did you mean 'rgba'?"


@pytest.mark.parametrize("command", ["check", "lint"])
def test_auto_is_github_under_github_actions(models, command):
    typo, _ = models
    under_actions = run(command, "auto", typo, env={"GITHUB_ACTIONS": "true"})
    assert under_actions.stdout.decode().startswith("::warning file=")
    elsewhere = run(command, "auto", typo, env={"GITHUB_ACTIONS": ""})
    assert "::warning" not in elsewhere.stdout.decode() + elsewhere.stderr.decode()
    report = elsewhere.stderr if command == "check" else elsewhere.stdout  # check keeps check_urdf's layout
    assert f"{typo}:5:7: M002 warning" in report.decode()


@pytest.mark.parametrize("command", ["check", "lint"])
def test_sarif_2_1_0(models, command):
    typo, broken = models
    log = json.loads(run(command, "sarif", typo, broken).stdout)
    assert log["version"] == "2.1.0" and log["$schema"].endswith("sarif-2.1.0.json")
    [sarif_run] = log["runs"]
    driver = sarif_run["tool"]["driver"]
    assert driver["name"] == "urdfcli"
    rules = driver["rules"]
    assert [r["id"] for r in rules] == sorted(REGISTRY)
    for descriptor in rules:
        assert descriptor["shortDescription"]["text"] and "## What it does" in descriptor["help"]["markdown"]
        assert descriptor["defaultConfiguration"]["level"] in ("error", "warning", "note")
    results = sarif_run["results"]
    assert [(r["ruleId"], r["level"]) for r in results] == (
        [("M002", "warning"), ("D002", "warning"), ("X001", "error")] if command == "lint" else [("M002", "warning"), ("X001", "error")]
    )
    for result in results:
        assert rules[result["ruleIndex"]]["id"] == result["ruleId"]
        location = result["locations"][0]["physicalLocation"]
        assert location["region"]["startLine"] >= 1
        assert location["artifactLocation"]["uri"].startswith("file:///")
    assert results[-1]["locations"][0]["physicalLocation"]["region"] == {"startLine": 3, "startColumn": 9}


def test_sarif_relative_paths_stay_relative(models):
    typo, _ = models
    log = json.loads(run_cli("lint", "--format", "sarif", typo.name, cwd=typo.parent).stdout)
    assert log["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == "typo.urdf"


# -- paths GitHub finds: from the top of the repository ------------------------------------
@pytest.fixture
def workspace(tmp_path):
    """A colcon workspace whose src/ holds a git repository with a model in a package."""
    repository = tmp_path / "ws" / "src" / "my_robot"
    urdf = repository / "my_robot_description" / "urdf"
    urdf.mkdir(parents=True)
    (urdf / "typo.urdf").write_text(TYPO)
    subprocess.run(["git", "init", "-q", str(repository)], check=True)
    return tmp_path / "ws", repository


NO_WORKSPACE = {"GITHUB_WORKSPACE": ""}


def sarif_locations(done) -> tuple[list[dict], dict | None]:
    [sarif_run] = json.loads(done.stdout)["runs"]
    return [r["locations"][0]["physicalLocation"]["artifactLocation"] for r in sarif_run["results"]], sarif_run.get("originalUriBaseIds")


@pytest.mark.parametrize("where", ["above", "inside"])
def test_github_and_sarif_name_files_from_the_top_of_their_repository(workspace, where):
    """Jackal linted from its colcon workspace was annotated at src/jackal/..., from a folder
    of it at jackal.gazebo: GitHub reads both from the repository's top, where neither is."""
    folder, repository = workspace
    cwd, target = (folder, "src/my_robot") if where == "above" else (repository / "my_robot_description" / "urdf", ".")
    annotations = run_cli("lint", "--format", "github", target, cwd=cwd, env=NO_WORKSPACE).stdout.decode().splitlines()
    assert [line.split(",")[0] for line in annotations] == ["::warning file=my_robot_description/urdf/typo.urdf"] * 2
    locations, bases = sarif_locations(run_cli("lint", "--format", "sarif", target, cwd=cwd, env=NO_WORKSPACE))
    assert locations == [{"uri": "my_robot_description/urdf/typo.urdf", "uriBaseId": "%SRCROOT%"}] * 2
    assert bases == {"%SRCROOT%": {"uri": repository.as_uri() + "/"}}


def test_sarif_gives_each_repository_its_base(workspace):
    folder, repository = workspace
    other = folder / "src" / "other_robot"
    other.mkdir()
    (other / "typo.urdf").write_text(TYPO)
    subprocess.run(["git", "init", "-q", str(other)], check=True)
    locations, bases = sarif_locations(run_cli("lint", "--format", "sarif", "--select", "M002", "src/my_robot", "src/other_robot", cwd=folder, env=NO_WORKSPACE))
    assert locations == [{"uri": "my_robot_description/urdf/typo.urdf", "uriBaseId": "%SRCROOT%"}, {"uri": "typo.urdf", "uriBaseId": "%SRCROOT2%"}]
    assert bases == {"%SRCROOT%": {"uri": repository.as_uri() + "/"}, "%SRCROOT2%": {"uri": other.as_uri() + "/"}}


def test_a_checkout_without_git_is_named_from_github_workspace(models):
    """actions/checkout downloads the repository without .git when git is too old: GITHUB_WORKSPACE is its top."""
    typo, _ = models
    inside = typo.parent / "urdf"
    inside.mkdir()
    typo.rename(inside / "typo.urdf")
    env = {"GITHUB_WORKSPACE": str(typo.parent)}
    annotation = run_cli("lint", "--format", "github", "--select", "M002", "typo.urdf", cwd=inside, env=env).stdout.decode()
    assert annotation.startswith("::warning file=urdf/typo.urdf,line=5")
    # a file in no repository and outside the workspace keeps its name
    elsewhere = run_cli("lint", "--format", "github", "--select", "M002", "typo.urdf", cwd=inside, env=NO_WORKSPACE).stdout.decode()
    assert elsewhere.startswith("::warning file=typo.urdf,line=5")


def test_diff_annotations_name_files_from_the_top_of_their_repository(workspace):
    folder, repository = workspace
    urdf = repository / "my_robot_description" / "urdf"
    (urdf / "new.urdf").write_text(TYPO.replace('size="1 1 1"', 'size="1 1 2"'))
    done = run_cli("diff", "--format", "github", "src/my_robot/my_robot_description/urdf/typo.urdf",
                   "src/my_robot/my_robot_description/urdf/new.urdf", cwd=folder, env=NO_WORKSPACE)
    assert done.returncode == 1, done.stderr
    assert done.stdout.decode().startswith("::notice file=my_robot_description/urdf/new.urdf,line=4,")
