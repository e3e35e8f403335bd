"""What a run loads and repeats: heavy libraries only when they are used, each package
looked up once."""

from __future__ import annotations

import subprocess
import sys

import pytest
from conftest import FIXTURES

from urdfcli import packages
from urdfcli.packages import PackageResolver

IMPORTED = (
    "import sys; from urdfcli.cli import main\n"
    "sys.argv = ['urdfcli', *sys.argv[1:]]\n"
    "try:\n    main()\nexcept SystemExit:\n    pass\n"
    "print(sorted({m.split('.')[0] if not m.startswith('urdfcli') else m for m in sys.modules}))"
)


def imported(*args: str) -> list[str]:
    """The modules a run of ``urdfcli ARGS`` has imported when it ends."""
    done = subprocess.run([sys.executable, "-c", IMPORTED, *args], capture_output=True, text=True)
    return eval(done.stdout.strip().splitlines()[-1])  # a list literal printed by the child


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
    real = packages._read_package_name
    monkeypatch.setattr(packages, "_read_package_name", lambda manifest: parsed.append(manifest) or real(manifest))
    resolver = PackageResolver((), own / "urdf" / "robot.urdf", env={})
    for _ in range(3):
        assert resolver.find("missing") is None
        assert resolver.find("sibling") == sibling
        assert resolver.find("own") == own
    assert len(parsed) == len(set(parsed))  # no manifest read twice


@pytest.mark.parametrize("command", ["check", "expand"])
def test_xacro_is_imported_only_by_the_worker_that_runs_it(command):
    """The run's worker imports xacro while the run imports the model and its rules;
    the run itself never does, and still gets the expansion."""
    car = FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"
    done = subprocess.run([sys.executable, "-c", IMPORTED, command, str(car)], capture_output=True, text=True)
    modules = eval(done.stdout.strip().splitlines()[-1])
    assert not {"xacro", "urdfcli.expansion", "xml.dom.minidom"} & set(modules)
    assert not {"inspect", "dataclasses"} & set(modules)
    expected = "root Link: base_footprint has 1 child(ren)" if command == "check" else '<joint name="laser2support" type="fixed">'
    assert expected in done.stdout


WORKER_IMPORTS = (
    "import sys\nfrom pathlib import Path\nimport urdfcli.expanded\n"  # what the run has when it forks the worker
    "before = set(sys.modules)\n"
    "from urdfcli import expansion\nfrom urdfcli.packages import PackageResolver\n"
    "path = Path(sys.argv[1])\n"
    "result = expansion.expand_here(path.read_bytes(), str(path), {}, PackageResolver((), path))\n"
    "print(len(result.origins), sorted(set(sys.modules) - before))"
)


def test_the_xacro_worker_imports_neither_lxml_nor_the_model():
    """What a worker imports is on the way to every xacro answer: xacro and minidom,
    not lxml (nor typing or dataclasses, which it brings) or the model's modules, even
    to find a package by its package.xml."""
    model = FIXTURES / "urdf01_rviz" / "urdf" / "xacro" / "car_find.urdf.xacro"  # $(find urdf01_rviz)
    done = subprocess.run([sys.executable, "-c", WORKER_IMPORTS, str(model)], capture_output=True, text=True)
    elements, modules = done.stdout.split(" ", 1)
    assert int(elements) > 20, done.stderr
    assert "xacro" in modules and "xml.dom.minidom" in modules
    assert not {"lxml", "lxml.etree", "typing", "dataclasses", "inspect", "urdfcli.diagnostics", "urdfcli.rules", "urdfcli.model"} & set(eval(modules))


@pytest.mark.parametrize(
    "arguments, ahead",
    [
        (["--format", "json", "arm.urdf", "robot.urdf.xacro", "prefix:=left_", "other.xacro"], ("robot.urdf.xacro", {"prefix": "left_"})),
        (["robot.urdf.xacro", "-P", "src"], (None, {})),
        (["robot.urdf.xacro", "-Psrc"], (None, {})),
        (["--package-path=src", "robot.urdf.xacro"], (None, {})),
    ],
)
def test_the_worker_expands_ahead_the_first_xacro_input_with_the_arguments_of_the_command_line(arguments, ahead):
    """Package paths are read with the options, and from configuration: none is guessed."""
    from urdfcli.cli import _first_expansion

    assert _first_expansion(arguments) == ahead


def test_check_modules_hold_every_rule_check_runs():
    from urdfcli import rules

    run_by_check = {spec.function.__module__ for spec in rules.load_all().values() if spec.function is not None and spec.in_check}
    assert run_by_check <= {f"urdfcli.rules.{name}" for name in rules.CHECK_MODULES}


@pytest.mark.parametrize("command", ["check", "tree", "expand"])
def test_plain_output_of_a_small_file_imports_neither_rich_nor_rules_that_do_not_run(command):
    from urdfcli import rules

    modules = set(imported(command, str(FIXTURES / "seed000" / "my_robot.urdf")))
    assert "rich" not in modules
    assert "typer" not in modules  # a plain command line is read without it (urdfcli.cli.fast)
    assert not {"urdfcli.inertia", "urdfcli.meshes", "urdfcli.poses", "urdfcli.fixes", "numpy", "networkx"} & modules
    assert not {"json", "difflib", "tomllib"} & modules  # for JSON output, a misspelt name, a configuration file
    assert "tempfile" not in modules  # for writing a file atomically (--output), not standard output
    assert not {"inspect", "dataclasses"} & modules  # a tenth of a start: records are named tuples
    assert "xacro" not in modules  # expand runs it always, as the xacro tool does, but in the worker
    loaded_rules = {m.rpartition(".")[2] for m in modules if m.startswith("urdfcli.rules.")}
    assert loaded_rules <= set(rules.CHECK_MODULES)


@pytest.mark.parametrize("command", ["check", "lint", "tree", "expand"])
@pytest.mark.parametrize("model", ["seed000/my_robot.urdf", "urdf02_gazebo/urdf/car.urdf.xacro"])
def test_small_documents_are_read_without_lxml(command, model):
    """Importing lxml takes longer than reading a small document: expat reads it
    (urdfcli.lightxml), and lxml is never imported. A large one is read by lxml."""
    assert "lxml" not in imported(command, str(FIXTURES / model))


def test_a_large_document_is_read_by_lxml(tmp_path):
    from urdfcli import xmlsafe

    links = "".join(f'<link name="l{i}"/><joint name="j{i}" type="fixed"><parent link="l{i}"/><child link="l{i + 1}"/></joint>' for i in range(1500))
    path = tmp_path / "large.urdf"
    path.write_text(f'<robot name="r">{links}<link name="l1500"/></robot>')
    assert path.stat().st_size > xmlsafe.EXPAT_BUDGET
    assert "lxml" in imported("check", str(path))


ANSWERED_FIRST = (
    "import sys, time\nfrom urdfcli import expanded\n"
    "with expanded.started(sys.argv[1], {}):\n"
    "    deadline = time.monotonic() + 60\n"
    "    while not expanded.answered_ahead() and time.monotonic() < deadline:\n"
    "        time.sleep(0.01)\n"
    "    from urdfcli.load import load\n"
    "    codes = [d.code for d in load(sys.argv[1]).diagnostics]\n"
    "print(codes, sorted({'urdfcli.model', 'urdfcli.kinematics'} & set(sys.modules)))"
)


def test_a_xacro_error_answered_before_it_is_asked_for_is_reported_without_the_model():
    """The model's modules are imported while the worker expands; when its answer is
    in first and is an error, they are not needed, and not imported."""
    model = FIXTURES / "urdf02_gazebo" / "urdf" / "demo05_car_base.urdf.xacro"  # calls a macro defined elsewhere
    done = subprocess.run([sys.executable, "-c", ANSWERED_FIRST, str(model)], capture_output=True, text=True)
    assert done.stdout.split() == ["['X003']", "[]"], done.stderr
