"""The pre-commit hooks: their file filters, the real `pre-commit run` on a clean and a
flagged model, and real `git commit`s through installed hooks on a ROS description repository."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess

import pytest
import yaml
from conftest import ROOT, locked, require_tool, run_cli, shared_folder
from generated_repos import generate, kuka_package
from ros_workspace import box_stl, edit, line_of, make_repository, moveit_repository

from urdfcli.project.drift import regenerated
from urdfcli.read.revision import deleted_files

HOOKS = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
CLEAN = '<robot name="r">\n  <link name="base_link"/>\n</robot>\n'
FLAGGED = (  # warnings only: lint fails, check passes
    '<robot name="r">\n  <link name="base_link">\n    <visual>\n      <geometry><box size="1 1 1"/></geometry>\n'
    '      <material name="grey"><color rgb="0.5 0.5 0.5 1"/></material>\n    </visual>\n  </link>\n</robot>\n'
)


def test_hooks_are_declared_as_documented():
    by_id = {hook["id"]: hook for hook in HOOKS}
    assert set(by_id) == {"urdfcli-check", "urdfcli-lint", "urdfcli-drift", "urdfcli-fix"}
    # a changed model has the SRDFs of its robot checked too, and the models including a deleted file
    # (pre-commit passes none: the hooks run on every commit, a commit that only deletes one included)
    assert by_id["urdfcli-check"]["entry"] == "urdfcli check --srdfs --git-deletions"
    assert by_id["urdfcli-lint"]["entry"] == "urdfcli lint --srdfs --git-deletions"
    assert [name for name, hook in by_id.items() if hook.get("always_run")] == ["urdfcli-check", "urdfcli-lint"]
    assert by_id["urdfcli-drift"]["entry"] == "urdfcli drift"
    # the safe fixes; fails when it changed a file, whatever remains (the lint hook judges that)
    assert by_id["urdfcli-fix"]["entry"] == "urdfcli lint --fix --exit-zero --exit-non-zero-on-fix"
    assert all(hook["language"] == "python" for hook in HOOKS)
    # every changed file in one run, so that a library and its models are seen together
    assert all(hook["require_serial"] for hook in HOOKS)
    # check and lint read SRDFs too (MoveIt's); drift compares generated URDFs with their xacro
    assert [by_id[name]["files"] for name in ("urdfcli-check", "urdfcli-lint", "urdfcli-drift")] == [r"\.(urdf|xacro|srdf)$"] * 2 + [r"\.(urdf|xacro)$"]


@pytest.mark.parametrize("hook", HOOKS, ids=lambda h: h["id"])
@pytest.mark.parametrize(
    ("name", "matches"),
    [
        ("robot.urdf", True),
        ("description/urdf/robot.urdf.xacro", True),
        ("urdf/macros.xacro", True),
        ("config/panda.srdf", True),  # MoveIt's SRDF, checked against its URDF
        ("srdf/ur.srdf.xacro", True),
        ("robot.urdf.bak", False),
        ("package.xml", False),
        ("robot.sdf", False),
        ("urdf.py", False),
    ],
)
def test_hook_filters_match_robot_descriptions_only(hook, name, matches):
    if hook["id"] in ("urdfcli-drift", "urdfcli-fix") and name.endswith(".srdf"):
        matches = False  # drift is about generated URDFs, and no fix edits an SRDF
    assert bool(re.search(hook["files"], name)) is matches


def git(*args, cwd):
    subprocess.run(
        ["git", "-c", "user.name=urdfcli tests", "-c", "user.email=tests@urdfcli.invalid", "-c", "commit.gpgsign=false", *args],
        cwd=cwd, check=True, capture_output=True,
    )


def snapshot_of_this_checkout(destination):
    """A git repository holding this checkout's files as they are now (committed or not):
    pre-commit installs the hooks from a commit of a repository."""
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


@pytest.fixture(scope="module")
def hooks(tmp_path_factory, worker_id):
    """This checkout as a hooks repository, and one pre-commit cache, both shared by the
    xdist workers: the hook environment is built once per test run (pre-commit locks
    its cache while it builds one)."""
    pre_commit = require_tool("pre-commit")
    require_tool("git")
    base = shared_folder(tmp_path_factory, worker_id) / "pre-commit"
    hooks_repo = base / "hooks"
    with locked(base.with_suffix(".lock")):
        if not (base / "snapshot-made").exists():
            shutil.rmtree(hooks_repo, ignore_errors=True)
            hooks_repo.mkdir(parents=True)
            snapshot_of_this_checkout(hooks_repo)
            (base / "snapshot-made").touch()
    env = {**os.environ, "PRE_COMMIT_HOME": str(base / "cache"), "NO_COLOR": "1", "GITHUB_ACTIONS": "", "PYTHONPATH": ""}
    return pre_commit, hooks_repo, env


def installed(repo, hooks, *hook_ids):
    """``repo`` made a git repository with these hooks of this checkout installed; the
    function that commits in it (the paths given, else everything) and gives back the
    exit code and what the hooks printed."""
    pre_commit, hooks_repo, env = hooks
    rev = subprocess.run(["git", "rev-parse", "HEAD"], cwd=hooks_repo, capture_output=True, text=True, check=True).stdout.strip()
    listed = "".join(f"      - id: {hook}\n" for hook in hook_ids)
    (repo / ".pre-commit-config.yaml").write_text(f"repos:\n  - repo: {hooks_repo}\n    rev: {rev}\n    hooks:\n{listed}")
    git("init", "-q", cwd=repo)
    subprocess.run([pre_commit, "install"], cwd=repo, env=env, check=True, capture_output=True, timeout=120)

    def commit(message, *paths):
        git("add", *(paths or ("-A",)), cwd=repo)
        done = subprocess.run(
            ["git", "-c", "user.name=t", "-c", "user.email=t@urdfcli.invalid", "-c", "commit.gpgsign=false", "commit", "-m", message],
            cwd=repo, env=env, capture_output=True, timeout=900,
        )
        return done.returncode, done.stdout.decode() + done.stderr.decode()

    return commit


def run_hook(project, hooks, hook):
    """``pre-commit run HOOK --all-files`` in the git repository ``project``, the hooks of
    this checkout configured as a user configures them (a repository and its rev). (Not
    ``try-repo``: it builds the hook environment again on each run, in a store of its own.)"""
    pre_commit, hooks_repo, env = hooks
    rev = subprocess.run(["git", "rev-parse", "HEAD"], cwd=hooks_repo, capture_output=True, text=True, check=True).stdout.strip()
    (project / ".pre-commit-config.yaml").write_text(f"repos:\n  - repo: {hooks_repo}\n    rev: {rev}\n    hooks:\n      - id: {hook}\n")
    return subprocess.run([pre_commit, "run", hook, "--all-files"], cwd=project, env=env, capture_output=True, timeout=900)


def test_pre_commit_passes_a_clean_model_and_fails_a_flagged_one(tmp_path, hooks):
    project = tmp_path / "project"
    project.mkdir()
    git("init", "-q", cwd=project)
    (project / "robot.urdf").write_text(CLEAN)
    git("add", "robot.urdf", cwd=project)

    clean = run_hook(project, hooks, "urdfcli-lint")
    assert clean.returncode == 0, clean.stdout.decode() + clean.stderr.decode()
    assert re.search(r"urdfcli lint\.+Passed", clean.stdout.decode())

    (project / "broken.urdf").write_text(FLAGGED)
    git("add", "broken.urdf", cwd=project)
    flagged = run_hook(project, hooks, "urdfcli-lint")
    out = flagged.stdout.decode()
    assert flagged.returncode == 1, out
    assert re.search(r"urdfcli lint\.+Failed", out)
    assert "broken.urdf:5:36: D002 warning: <color> has no attribute 'rgb'; it is ignored" in out

    check = run_hook(project, hooks, "urdfcli-check")  # warnings only: check passes
    assert check.returncode == 0, check.stdout.decode()


FIXABLE = (  # a mesh named in another case than its file: the safe fix names the file
    '<robot name="r">\n  <link name="base_link">\n    <visual><geometry><mesh filename="meshes/base.STL"/></geometry></visual>\n'
    '  </link>\n</robot>\n'
)


def test_the_fix_hook_fails_when_it_fixed_a_file_and_passes_once_staged(tmp_path, hooks):
    project = tmp_path / "project"
    (project / "meshes").mkdir(parents=True)
    (project / "meshes" / "base.stl").write_bytes(b"solid base\nendsolid base\n")
    git("init", "-q", cwd=project)
    (project / "robot.urdf").write_text(FIXABLE)
    git("add", "-A", cwd=project)

    fixed = run_hook(project, hooks, "urdfcli-fix")
    out = fixed.stdout.decode()
    assert fixed.returncode == 1, out
    assert re.search(r"urdfcli fix\.+Failed", out) and "files were modified by this hook" in out
    assert "1 fixed, " in out
    assert (project / "robot.urdf").read_text() == FIXABLE.replace("meshes/base.STL", "meshes/base.stl")
    git("add", "-A", cwd=project)
    again = run_hook(project, hooks, "urdfcli-fix")
    assert again.returncode == 0, again.stdout.decode()  # what remains is the lint hook's to judge
    assert re.search(r"urdfcli fix\.+Passed", again.stdout.decode())


def test_commits_to_a_ros_repository_check_libraries_through_their_models(tmp_path, hooks):
    """Installed hooks on real commits: a library is checked through the models that include
    it from another package ($(find) of a package.xml name that is not its folder's), one of
    them with the argument sets of [tool.urdfcli] models."""
    repo = make_repository(tmp_path / "acme_robots")
    commit = installed(repo, hooks, "urdfcli-check", "urdfcli-lint")
    wheel, sensor = repo / "common/urdf/wheel.xacro", repo / "common/urdf/sensor.xacro"

    def undo():
        git("reset", "-q", "--hard", "HEAD", cwd=repo)

    code, out = commit("the clean repository")
    assert code == 0, out
    assert re.search(r"urdfcli check\.+Passed", out) and re.search(r"urdfcli lint\.+Passed", out)

    # the macro broken in the library alone: located in the library, found through its models
    edit(wheel, 'radius="${radius}"', 'radius="${wheel_radius}"')
    code, out = commit("wheel radius", "common/urdf/wheel.xacro")
    assert code == 1, out
    assert re.search(r"urdfcli check\.+Failed", out)
    assert f"common/urdf/wheel.xacro:{line_of(wheel, 'wheel_radius')}:19: X003 error: name 'wheel_radius' is not defined" in out
    assert "common/urdf/wheel.xacro: xacro library, checked through description/urdf/arm.urdf.xacro [arm_type:=small], " in out
    assert "R002" not in out and "R004" not in out
    undo()

    # a joint in the macro whose parent link does not exist: located in the library
    edit(wheel, '<parent link="${parent}"/>', '<parent link="${parent}_mount"/>')
    code, out = commit("wheel mount", "common/urdf/wheel.xacro")
    assert code == 1, out
    assert f"common/urdf/wheel.xacro:{line_of(wheel, '_mount')}:7: J005 error: parent link 'base_link_mount'" in out
    assert out.count(": J005 error") == 2  # once per hook, however many models and calls made the joint
    undo()

    # a library no model includes passes, unless its own xacro is wrong
    edit(sensor, '<xacro:property name="sensor_size" value="0.05"/>', '<xacro:property name="sensor_size" value="0.06"/>')
    code, out = commit("sensor size", "common/urdf/sensor.xacro")
    assert code == 0, out  # (pre-commit shows nothing of a hook that passes)
    edit(sensor, '<xacro:property name="sensor_size" value="0.06"/>', '<xacro:include filename="camera.xacro"/>')
    code, out = commit("sensor camera", "common/urdf/sensor.xacro")
    assert code == 1, out
    assert f"common/urdf/sensor.xacro:{line_of(sensor, 'camera.xacro')}:" in out and "X003 error" in out
    undo()

    # a change to a file that is not a robot description checks nothing (the hooks run, for a deletion)
    (repo / "description/README.md").write_text("# acme rover\n\nWheels and an arm.\n")
    code, out = commit("readme", "description/README.md")
    assert code == 0, out
    assert re.search(r"urdfcli check\.+Passed", out) and re.search(r"urdfcli lint\.+Passed", out)


def test_the_fix_hook_keeps_an_edit_made_to_a_generated_urdf_and_the_drift_hook_says_it(tmp_path, hooks):
    """A limit changed by hand in a committed generated URDF: regenerating it (X110's fix,
    unsafe) would silently drop the edit, so the fix hook leaves the file as staged; the
    drift hook fails the commit, naming the difference."""
    repo = tmp_path / "kuka_experimental"
    package = kuka_package(repo, generated_with_flange=True)
    commit = installed(repo, hooks, "urdfcli-fix", "urdfcli-drift")
    urdf = package / "urdf" / "kr16_2.urdf"
    code, out = commit("the package, its URDF generated from its xacro")
    assert code == 0, out

    edited = urdf.read_text().replace('upper="0.6108652381980153"', 'upper="0.7"', 1)
    assert edited != urdf.read_text()
    urdf.write_text(edited)
    code, out = commit("joint a2 reaches further, in the URDF", "kuka_kr16_support/urdf/kr16_2.urdf")
    assert code == 1, out
    assert re.search(r"urdfcli fix\.+Passed", out) and urdf.read_text() == edited  # the edit kept
    assert re.search(r"urdfcli drift\.+Failed", out) and "X110 warning: kr16_2.urdf does not match" in out


def test_drift_hook_fails_a_commit_whose_xacro_leaves_the_generated_urdf_behind(tmp_path, hooks):
    """urdfcli-drift on real commits to a package built like kuka_kr16_support: a change to the
    macro file alone fails (the URDF generated from the model including it no longer matches);
    the URDF regenerated and committed with it passes; a change elsewhere checks nothing."""
    repo = tmp_path / "kuka_experimental"
    package = kuka_package(repo, generated_with_flange=True)
    commit = installed(repo, hooks, "urdfcli-drift")
    macro, urdf = package / "urdf" / "kr16_2_macro.xacro", package / "urdf" / "kr16_2.urdf"

    code, out = commit("the package, its URDF generated from its xacro")
    assert code == 0, out
    assert re.search(r"urdfcli drift\.+Passed", out)

    edit(macro, 'upper="${radians(35)}"', 'upper="${radians(40)}"')
    code, out = commit("joint a2 reaches further", "kuka_kr16_support/urdf/kr16_2_macro.xacro")
    assert code == 1, out
    assert re.search(r"urdfcli drift\.+Failed", out)
    assert ("kuka_kr16_support/urdf/kr16_2.urdf:1:1: X110 warning: kr16_2.urdf does not match kuka_kr16_support/urdf/kr16_2.xacro, "
            "which generated it: 1 joint differs (joint 'joint_a2' limit upper: 0.610865 here, 0.698132 in kr16_2.xacro)") in out

    urdf.write_text(regenerated(urdf.read_text(), generate(package / "urdf" / "kr16_2.xacro", "unused")))
    code, out = commit("joint a2 reaches further, the URDF regenerated")
    assert code == 0, out

    (repo / "README.md").write_text("# KUKA KR 16-2\n")
    code, out = commit("readme", "README.md")
    assert code == 0 and re.search(r"urdfcli drift\.+\(no files to check\)Skipped", out), out


def test_a_commit_renaming_a_joint_its_moveit_config_still_names_fails(tmp_path, hooks):
    """The check hook on a commit of the arm's macro library alone: the joint it renames is
    still named by the MoveIt config's SRDF, which the commit leaves as it was; the commit
    fails there, and passes once the SRDF is changed with it."""
    repo = tmp_path / "cell"
    moveit_repository(repo)
    commit = installed(repo, hooks, "urdfcli-check")
    code, out = commit("the cell and its MoveIt config")
    assert code == 0, out

    edit(repo / "cell_description/urdf/arm.xacro", 'name="${prefix}elbow"', 'name="${prefix}joint_2"')
    code, out = commit("the elbow is joint 2", "cell_description/urdf/arm.xacro")
    assert code == 1, out
    assert "cell_moveit_config/config/cell.srdf:3:47: K002 error: group state 'home' names joint 'arm_elbow'" in out

    edit(repo / "cell_moveit_config/config/cell.srdf", 'name="arm_elbow"', 'name="arm_joint_2"')
    code, out = commit("the elbow is joint 2, in the MoveIt config too")
    assert code == 0, out


def test_git_names_the_files_a_commit_deletes_a_rename_deleting_its_old_name(tmp_path):
    require_tool("git")
    repo = tmp_path / "repo"
    (repo / "urdf").mkdir(parents=True)
    for name in ("a.xacro", "b.xacro", "c.xacro"):
        (repo / "urdf" / name).write_text(CLEAN)
    git("init", "-q", cwd=repo)
    git("add", "-A", cwd=repo)
    git("commit", "-q", "-m", "three", cwd=repo)
    git("rm", "-q", "urdf/a.xacro", cwd=repo)
    git("mv", "urdf/b.xacro", "urdf/renamed.xacro", cwd=repo)
    (repo / "urdf" / "c.xacro").unlink()  # deleted, not staged: not the commit's
    assert sorted(deleted_files(repo / "urdf")) == [repo / "urdf" / "a.xacro", repo / "urdf" / "b.xacro"]
    git("commit", "-q", "-m", "a deleted, b renamed", cwd=repo)
    assert deleted_files(repo) == []
    assert sorted(deleted_files(repo, ("HEAD~1", "HEAD"))) == [repo / "urdf" / "a.xacro", repo / "urdf" / "b.xacro"]
    assert deleted_files(repo, ("--output=x", "HEAD")) == [] and not (repo / "x").exists()  # an option is never passed to git
    outside = tmp_path / "outside"
    outside.mkdir()
    assert deleted_files(outside) == []


def test_check_and_lint_with_git_deletions_check_the_models_including_a_deleted_file(tmp_path):
    """What the hooks run on a commit that only deletes a library: no file given, the models
    that include it fail at their include; outside git, or with nothing deleted, nothing is
    checked; without --git-deletions a file is still required."""
    require_tool("git")
    repo = make_repository(tmp_path / "acme_robots")
    rover = repo / "description/urdf/rover.urdf.xacro"
    git("init", "-q", cwd=repo)
    git("add", "-A", cwd=repo)
    git("commit", "-q", "-m", "the repository", cwd=repo)
    no_refs = {"PRE_COMMIT_FROM_REF": "", "PRE_COMMIT_TO_REF": ""}
    for command in ("check", "lint"):
        done = run_cli(command, "--git-deletions", "--format", "concise", cwd=repo, env=no_refs)
        assert done.returncode == 0 and done.stdout + done.stderr == b"", done.stderr.decode()
    done = run_cli("check", "--git-deletions", "--format", "json", cwd=repo, env=no_refs)  # a report of no file
    assert done.returncode == 0 and json.loads(done.stdout)["files"] == []
    git("rm", "-q", "common/urdf/wheel.xacro", cwd=repo)
    line = line_of(rover, "wheel.xacro")
    for command in ("check", "lint"):
        done = run_cli(command, "--srdfs", "--git-deletions", "--format", "concise", cwd=repo, env=no_refs)
        out = done.stdout.decode() + done.stderr.decode()
        assert done.returncode == 1, out
        assert f"description/urdf/rover.urdf.xacro:{line}:3: X003 error: cannot include common/urdf/wheel.xacro" in out
        assert "description/urdf/arm.urdf.xacro:3:3: X003 error: cannot include common/urdf/wheel.xacro" in out
    outside = tmp_path / "outside"
    outside.mkdir()
    done = run_cli("check", "--git-deletions", cwd=outside, env=no_refs)
    assert done.returncode == 0 and done.stdout + done.stderr == b""
    done = run_cli("check", cwd=repo)
    assert done.returncode == 2 and "Missing argument" in done.stderr.decode()


def test_a_commit_deleting_or_renaming_a_library_its_models_include_fails(tmp_path, hooks):
    """Installed hooks on real commits: pre-commit passes no deleted file, so a commit that
    deletes a library (or renames it) would leave the models that include it broken; the
    models fail at their include. Renamed with the includes, the commit passes."""
    repo = make_repository(tmp_path / "acme_robots")
    commit = installed(repo, hooks, "urdfcli-check", "urdfcli-lint")
    rover, arm = repo / "description/urdf/rover.urdf.xacro", repo / "description/urdf/arm.urdf.xacro"
    code, out = commit("the clean repository")
    assert code == 0, out
    failing = [f"description/urdf/rover.urdf.xacro:{line_of(rover, 'wheel.xacro')}:3: X003 error: cannot include common/urdf/wheel.xacro",
               f"description/urdf/arm.urdf.xacro:{line_of(arm, 'wheel.xacro')}:3: X003 error: cannot include common/urdf/wheel.xacro"]

    git("rm", "-q", "common/urdf/wheel.xacro", cwd=repo)
    code, out = commit("no wheel library")
    assert code == 1, out
    assert re.search(r"urdfcli check\.+Failed", out) and re.search(r"urdfcli lint\.+Failed", out)
    assert all(out.count(text) == 2 for text in failing), out  # once per hook
    git("reset", "-q", "--hard", "HEAD", cwd=repo)

    git("mv", "common/urdf/wheel.xacro", "common/urdf/wheels.xacro", cwd=repo)
    code, out = commit("the wheel library renamed")
    assert code == 1, out
    assert all(out.count(text) == 2 for text in failing), out

    for model in (rover, arm):
        edit(model, "urdf/wheel.xacro", "urdf/wheels.xacro")
    code, out = commit("the wheel library renamed, and included by its new name")
    assert code == 0, out


def test_a_commit_deleting_or_renaming_a_mesh_or_yaml_file_a_model_names_fails(tmp_path, hooks):
    """A mesh named in a library the models include, and a YAML file a model loads: a commit
    that deletes one (or renames the mesh, as a case change does) fails at the models that name it.
    A deleted mesh that no model names runs the hooks on nothing."""
    repo = make_repository(tmp_path / "acme_robots")
    (repo / "common/meshes").mkdir()
    (repo / "common/meshes/wheel.stl").write_bytes(box_stl((0.2, 0.2, 0.04), (0, 0, 0)))
    (repo / "common/meshes/spare.stl").write_bytes(box_stl((0.2, 0.2, 0.04), (0, 0, 0)))
    edit(repo / "common/urdf/wheel.xacro", '<visual>\n        <geometry><cylinder radius="${radius}" length="${wheel_length}"/></geometry>',
         '<visual>\n        <geometry><mesh filename="package://acme_common/meshes/wheel.stl" scale="${radius * 5} ${radius * 5} 1"/></geometry>')
    (repo / "description/config").mkdir()
    (repo / "description/config/body.yaml").write_text("mass: 5\n")
    rover = repo / "description/urdf/rover.urdf.xacro"
    edit(rover, '<xacro:box_inertial mass="5"', '<xacro:box_inertial mass="${xacro.load_yaml(\'$(find acme_rover_description)/config/body.yaml\')[\'mass\']}"')
    commit = installed(repo, hooks, "urdfcli-check")
    code, out = commit("the clean repository")
    assert code == 0, out

    git("rm", "-q", "common/meshes/wheel.stl", cwd=repo)
    code, out = commit("no wheel mesh")
    assert code == 1 and re.search(r"urdfcli check\.+Failed", out), out
    wheel_line = line_of(repo / "common/urdf/wheel.xacro", "wheel.stl")
    # the library's line, once, through a model that names it
    assert out.count(f"common/urdf/wheel.xacro:{wheel_line}:") == 1 and "D004 error: mesh 'package://acme_common/meshes/wheel.stl' not found" in out, out
    assert "found through model description/urdf/" in out, out
    git("reset", "-q", "--hard", "HEAD", cwd=repo)

    git("mv", "common/meshes/wheel.stl", "common/meshes/Wheel.stl", cwd=repo)
    code, out = commit("the wheel mesh renamed")
    assert code == 1 and "D004 error: mesh 'package://acme_common/meshes/wheel.stl' not found" in out, out
    git("reset", "-q", "--hard", "HEAD", cwd=repo)

    git("rm", "-q", "description/config/body.yaml", cwd=repo)
    code, out = commit("no body parameters")
    assert code == 1 and f"description/urdf/rover.urdf.xacro:{line_of(rover, 'body.yaml')}:" in out and "body.yaml" in out, out
    git("reset", "-q", "--hard", "HEAD", cwd=repo)

    git("rm", "-q", "common/meshes/spare.stl", cwd=repo)
    code, out = commit("an unused mesh removed")
    assert code == 0 and "D004" not in out, out
