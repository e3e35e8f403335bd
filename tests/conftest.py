"""Shared test helpers: the fixtures folder, running the CLI, and real tools.

Tests that need a real program (check_urdf, dot, xacro, pdfinfo...) skip
locally when it is missing, but fail in CI (CI=true), where the Makefile
installs them.
"""

from __future__ import annotations

import contextlib
import fcntl
import importlib.metadata
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures"
IN_CI = os.environ.get("CI", "").lower() in ("1", "true", "yes")


def shared_folder(tmp_path_factory, worker_id: str) -> Path:
    """A folder every xdist worker of this test run shares (the run's own, without xdist):
    for what is made once per run, under :func:`locked`."""
    base = tmp_path_factory.getbasetemp()
    return base if worker_id == "master" else base.parent


@contextlib.contextmanager
def locked(path: Path):
    """Hold an exclusive lock on ``path`` (created if missing) while the block runs."""
    with open(path, "a") as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def require_tool(name: str) -> str:
    """The path of a real program, or skip (locally) / fail (in CI)."""
    found = shutil.which(name) or (shutil.which(name, path=str(Path(sys.executable).parent)))
    if found:
        return found
    if IN_CI:
        pytest.fail(f"{name} is required in CI but is not installed")
    pytest.skip(f"{name} is not installed")


def run_cli(*args: str, input: str | bytes | None = None, cwd: Path | None = None, env: dict | None = None) -> subprocess.CompletedProcess:
    """Run `python -m urdfcli` in a subprocess: real exit codes, real stdout/stderr."""
    return subprocess.run(
        [sys.executable, "-m", "urdfcli", *args],
        input=input.encode() if isinstance(input, str) else input,
        capture_output=True,
        cwd=cwd,
        env={**os.environ, "NO_COLOR": "1", "COLUMNS": "200", **(env or {})},
        timeout=120,
    )


def example_robot_data() -> Path:
    """The installed example-robot-data folder (holding package.xml and robots/), a test
    dependency; skip (locally) or fail (in CI) when it is missing."""
    try:
        distribution = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        distribution = None
    for file in (distribution.files or ()) if distribution else ():
        if file.name == "package.xml" and "example-robot-data" in file.parts:
            return Path(distribution.locate_file(file)).parent
    if IN_CI:
        pytest.fail("example-robot-data is a test dependency: pip install -e '.[test]'")
    pytest.skip("example-robot-data is not installed")


@pytest.fixture
def cli():
    """In-process runner (fast) for tests that need no real exit of the process."""
    from urdfcli.cli import app

    runner = CliRunner()

    def invoke(*args: str, input: str | None = None):
        return runner.invoke(app, list(args), input=input, catch_exceptions=False)

    return invoke


def all_fixture_models() -> list[Path]:
    """Every complete model in fixtures/ (top-level .urdf and .urdf.xacro files)."""
    return sorted(p for p in FIXTURES.rglob("*") if p.name.endswith((".urdf", ".urdf.xacro")) and is_complete(p))


# Partial xacro files need properties or macros from the file that includes them (fixtures/README.md).
PARTIAL = {
    "urdf01_rviz/urdf/xacro/demo06_car_camera.urdf.xacro",
    "urdf01_rviz/urdf/xacro/demo07_car_laser.urdf.xacro",
    "urdf02_gazebo/urdf/demo05_car_base.urdf.xacro",
    "urdf02_gazebo/urdf/demo06_car_camera.urdf.xacro",
    "urdf02_gazebo/urdf/demo07_car_laser.urdf.xacro",
}


def is_complete(path: Path) -> bool:
    return path.relative_to(FIXTURES).as_posix() not in PARTIAL


def lint_file(path, config=None, rule_set=None):
    """One file linted with ``config`` (a urdfcli Config; the defaults when None), as
    `lint` would (or with the rules of another rule set): the Result."""
    from urdfcli.api import Target, check_target
    from urdfcli.options import Options, RuleSet
    from urdfcli.project.config import Config
    from urdfcli.session import Session

    options = Options(rule_set or RuleSet.LINT, config=config if config is not None else Config())
    with Session(options) as session:
        return check_target(Target(str(path)), session)


def load(path, rule_set=None):
    """One file checked with the default configuration and the rules of ``rule_set``
    (those of check when None): the Result."""
    from urdfcli.options import RuleSet

    return lint_file(path, None, rule_set or RuleSet.CHECK)


def model(path):
    """The model read from one file, with the tree's rules only: the Loaded."""
    from urdfcli.options import RuleSet

    return load(path, RuleSet.TREE).loaded


def audited(path, **options):
    """The mass-property audit of one file, as `urdfcli inertia` makes it."""
    from urdfcli import api
    from urdfcli.options import Options, RuleSet
    from urdfcli.project.config import Config
    from urdfcli.session import Session

    with Session(Options(RuleSet.TREE, config=Config())) as session:
        result = api.check_target(api.Target(str(path)), session)
        return api.audit(result.loaded, Config(), **options) if result.loaded is not None else None


def has_errors(path) -> bool:
    """Whether `urdfcli tree` and `graph` report an error in one file (their exit code is
    then 1): check's errors, apart from a missing or unreadable mesh, which is no error of
    the model's structure."""
    from urdfcli.rules import REGISTRY, Kind

    return any(REGISTRY[d.code].kind is not Kind.FILES for d in load(path).errors)
