"""What a run loads and repeats: heavy libraries only when they are used, xacro only in
its worker, each package looked up once."""

from __future__ import annotations

import subprocess
import sys

import pytest
from conftest import FIXTURES

from urdfcli.read import packages
from urdfcli.read.packages import PackageResolver

IMPORTED = (
    "import sys; from urdfcli.cli import main\n"
    "main(sys.argv[1:])\n"
    "print(sorted({m.split('.')[0] if not m.startswith('urdfcli') else m for m in sys.modules}))"
)


def imported(*args: str) -> list[str]:
    """The modules a run of ``urdfcli ARGS`` has imported when it ends."""
    done = subprocess.run([sys.executable, "-c", IMPORTED, *args], capture_output=True, text=True)
    return eval(done.stdout.strip().splitlines()[-1])  # a list literal printed by the child


@pytest.mark.parametrize("args", [["--version"], ["--help"], ["check", "--help"], ["lint", "--help"]])
def test_the_version_and_the_help_import_no_rule_and_no_library(args):
    modules = imported(*args)
    commands = [m for m in modules if m.startswith("urdfcli.cli.") and m not in ("urdfcli.cli.common", "urdfcli.cli.interrupt")]
    if args == ["--version"]:
        assert commands == []  # the version is said before any command is built
    elif args == ["--help"]:
        assert "urdfcli.cli.check" in modules and "urdfcli.cli.lsp" in modules  # every command, for the list
    else:
        assert set(commands) == {f"urdfcli.cli.{args[0]}", "urdfcli.cli.fixes"}  # that command alone (and what check and lint share)
    rules = [m for m in modules if m.startswith("urdfcli.rules.") and m not in ("urdfcli.rules.base", "urdfcli.rules.suggestions")]
    assert rules == []  # (rules.base: what a rule set is, for the options)
    assert not {"urdfcli.api", "urdfcli.session", "urdfcli.model.load", "urdfcli.project.linter", "lxml"} & set(modules)


def test_a_check_piped_to_a_file_imports_no_rich():
    modules = imported("check", str(FIXTURES / "seed000" / "my_robot.urdf"))
    assert "urdfcli.api" in modules and "rich" not in modules


MESHES = """<robot name="r">
  <link name="a">
    <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <collision><geometry><mesh filename="package://nowhere/meshes/a.stl"/></geometry></collision>
  </link>
  <link name="b">
    <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <collision><geometry><mesh filename="meshes/missing.stl"/></geometry></collision>
  </link>
  <joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>
</robot>
"""


def test_lint_loads_no_mesh_library_when_no_mesh_resolves(tmp_path):
    path = tmp_path / "robot.urdf"
    path.write_text(MESHES)
    modules = imported("lint", "--format", "concise", str(path))
    assert "urdfcli.rules.inertia" in modules  # the mass-property rules did run
    assert not {"numpy", "trimesh", "yourdfpy", "scipy"} & set(modules)


TURNED = """<robot name="r">
  <link name="base"/>
  <link name="plate">
    <inertial><mass value="1"/><inertia ixx="0.01417" ixy="0" ixz="0" iyy="0.02667" iyz="0" izz="0.01417"/></inertial>
    <collision><geometry><box size="0.4 0.4 0.1"/></geometry></collision>
  </link>
  <joint name="j" type="continuous"><parent link="base"/><child link="plate"/><axis xyz="0 0 1"/></joint>
</robot>
"""


def test_principal_axes_are_compared_without_numpy(tmp_path):
    """I009's turned-axes check works out eigenvectors in plain Python: lint on a model
    without meshes imports no numpy, even where the check runs and fires."""
    path = tmp_path / "robot.urdf"
    path.write_text(TURNED)
    done = subprocess.run([sys.executable, "-c", IMPORTED, "lint", "--format", "concise", str(path)], capture_output=True, text=True)
    assert "I009" in done.stdout and "on axes 90° away" in done.stdout
    assert "numpy" not in eval(done.stdout.strip().splitlines()[-1])


def test_each_package_is_looked_up_once_found_or_not(tmp_path, monkeypatch):
    own = tmp_path / "ws" / "src" / "own"
    (own / "urdf").mkdir(parents=True)
    (own / "package.xml").write_text("<package><name>own</name></package>")
    sibling = tmp_path / "ws" / "src" / "sibling"
    sibling.mkdir()
    (sibling / "package.xml").write_text("<package><name>sibling</name></package>")
    parsed = []
    real = packages.read_manifest
    monkeypatch.setattr(packages, "read_manifest", lambda manifest: parsed.append(manifest) or real(manifest))
    resolver = PackageResolver((), own / "urdf" / "robot.urdf", env={})
    for _ in range(3):
        assert resolver.find("missing") is None
        assert resolver.find("sibling") == sibling
        assert resolver.find("own") == own
    assert parsed and len(parsed) == len(set(parsed))  # no manifest read twice


@pytest.mark.parametrize("command", ["check", "expand"])
def test_xacro_is_imported_only_by_the_worker_that_runs_it(command):
    """The run's worker imports xacro while the run imports the model and its rules;
    the run itself never does, and still gets the expansion."""
    car = FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"
    done = subprocess.run([sys.executable, "-c", IMPORTED, command, str(car)], capture_output=True, text=True)
    modules = eval(done.stdout.strip().splitlines()[-1])
    assert not {"xacro", "urdfcli.read.expansion", "xml.dom.minidom"} & set(modules)
    expected = "root Link: base_footprint has 1 child(ren)" if command == "check" else '<joint name="laser2support" type="fixed">'
    assert expected in done.stdout
