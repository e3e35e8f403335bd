"""The pre-commit hooks: their file filters, and the real `pre-commit try-repo` on a clean and a flagged model."""

from __future__ import annotations

import os
import re
import shutil
import subprocess

import pytest
import yaml

from conftest import ROOT, require_tool

HOOKS = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
CLEAN = '<robot name="r">\n  <link name="base_link"/>\n</robot>\n'
FLAGGED = (  # warnings only: lint fails, check passes
    '<robot name="r">\n  <link name="base_link">\n    <visual>\n      <geometry><box size="1 1 1"/></geometry>\n'
    '      <material name="grey"><color rgb="0.5 0.5 0.5 1"/></material>\n    </visual>\n  </link>\n</robot>\n'
)


def test_hooks_are_declared_as_documented():
    by_id = {hook["id"]: hook for hook in HOOKS}
    assert set(by_id) == {"urdfcli-check", "urdfcli-lint"}
    assert by_id["urdfcli-check"]["entry"] == "urdfcli check"
    assert by_id["urdfcli-lint"]["entry"] == "urdfcli lint"
    assert all(hook["language"] == "python" for hook in HOOKS)


@pytest.mark.parametrize("hook", HOOKS, ids=lambda h: h["id"])
@pytest.mark.parametrize(
    ("name", "matches"),
    [
        ("robot.urdf", True),
        ("description/urdf/robot.urdf.xacro", True),
        ("urdf/macros.xacro", True),
        ("robot.urdf.bak", False),
        ("package.xml", False),
        ("robot.sdf", False),
        ("urdf.py", False),
    ],
)
def test_hook_filters_match_robot_descriptions_only(hook, name, matches):
    assert bool(re.search(hook["files"], name)) is matches


def git(*args, cwd):
    subprocess.run(
        ["git", "-c", "user.name=urdfcli tests", "-c", "user.email=tests@urdfcli.invalid", "-c", "commit.gpgsign=false", *args],
        cwd=cwd, check=True, capture_output=True,
    )


def snapshot_of_this_checkout(destination):
    """A git repository holding this checkout's files as they are now (committed or not):
    try-repo installs the hooks from a repository's HEAD."""
    listed = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=ROOT, check=True, capture_output=True).stdout
    for name in filter(None, listed.decode().split("\0")):
        source = ROOT / name
        if source.is_file():
            target = destination / name
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target)
    git("init", "-q", cwd=destination)
    git("add", "-A", cwd=destination)
    git("commit", "-q", "-m", "snapshot", cwd=destination)


def test_pre_commit_try_repo_passes_a_clean_model_and_fails_a_flagged_one(tmp_path):
    pre_commit = require_tool("pre-commit")
    require_tool("git")
    hooks_repo, project = tmp_path / "hooks", tmp_path / "project"
    hooks_repo.mkdir()
    project.mkdir()
    snapshot_of_this_checkout(hooks_repo)
    git("init", "-q", cwd=project)
    (project / "robot.urdf").write_text(CLEAN)
    git("add", "robot.urdf", cwd=project)
    env = {**os.environ, "PRE_COMMIT_HOME": str(tmp_path / "cache"), "NO_COLOR": "1", "GITHUB_ACTIONS": ""}

    def try_repo(hook):
        return subprocess.run([pre_commit, "try-repo", str(hooks_repo), hook, "--all-files"], cwd=project, env=env, capture_output=True, timeout=900)

    clean = try_repo("urdfcli-lint")
    assert clean.returncode == 0, clean.stdout.decode() + clean.stderr.decode()
    assert re.search(r"urdfcli lint\.+Passed", clean.stdout.decode())

    (project / "broken.urdf").write_text(FLAGGED)
    git("add", "broken.urdf", cwd=project)
    flagged = try_repo("urdfcli-lint")
    out = flagged.stdout.decode()
    assert flagged.returncode == 1, out
    assert re.search(r"urdfcli lint\.+Failed", out)
    assert "broken.urdf:5:29: D002 warning: <color> has no attribute 'rgb'; it is ignored" in out
    assert "hint: did you mean 'rgba'?" in out

    check = try_repo("urdfcli-check")  # warnings only: check passes
    assert check.returncode == 0, check.stdout.decode()
