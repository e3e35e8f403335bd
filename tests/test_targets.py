"""urdfcli's --target predictions against the real consumers (the differential test).

Every case of tests/target_cases.py is loaded into MuJoCo, Drake, Pinocchio,
PyBullet and Isaac Sim's converter (each in a child process: urdfcli.project.consumers),
converted by sdformat for Gazebo (``ign sdf -p`` and ``-k``) and made a KDL tree by
kdl_parser (src/urdfcli/targets/kdl/kdl_tree.cpp), as ``check --load`` does (each
consumer's ``load`` module), and urdfcli checks it with ``--target``. For each consumer:

- urdfcli reports an error of that target's rules exactly when the consumer
  rejects the model (Pinocchio, sdformat and kdl_parser read URDF with urdfdom:
  check_urdf's errors count too);
- each element the consumer drops or changes (a joint left unlimited, locked or made
  fixed, its limits swapped, a body's mass or tensor replaced, a link dropped or
  lumped, a mimic joint made free, a root's inertia dropped) is named by a
  diagnostic of that target's rules, and each warning of those rules names such
  an element;
- the masses and principal moments ``inertia --target`` predicts are those the
  consumer built.

The published example-robot-data models go through MuJoCo and Pinocchio too,
with package:// rewritten to the same absolute paths for both.

The consumers are test dependencies (the ``targets`` extra and the Debian packages
of the Makefile's ``system-test``, which ``make test`` installs); locally a missing
one skips with a message, in CI it fails.
"""

from __future__ import annotations

import contextlib
import fcntl
import importlib.util
import json
import math
import re
import subprocess
import sys
import tempfile
from functools import cache
from pathlib import Path

import pytest
from conftest import IN_CI, example_robot_data, lint_file, run_cli
from target_cases import CASES, write_cases

from urdfcli.diagnostics import Severity
from urdfcli.model.targets import Profile
from urdfcli.project import consumers
from urdfcli.project.compatibility import verdict
from urdfcli.project.config import Config
from urdfcli.project.loading import Outcome
from urdfcli.targets import build, profile

PROFILES = ["mujoco", "drake", "pinocchio", "pinocchio:mimic", "pybullet", "pybullet:inertia-from-file", "gazebo", "kdl", "isaac"]
# The .dae stand-in is not a real COLLADA file: PyBullet, which reads it, segfaults on its content,
# which urdfcli does not read (MuJoCo and Drake judge the extension alone).
CONTENT_READ = {("pybullet", "dae-collision")}


def require_consumer(target: str) -> None:
    """The consumer must run here: skip locally when it cannot, fail in CI."""
    why = consumers.missing(target)
    if why is None:
        return
    message = f"{target} cannot run here ({why}): its differential test cannot run"
    if IN_CI:
        pytest.fail(message)
    pytest.skip(message)


@pytest.fixture(scope="module")
def cases(tmp_path_factory, worker_id) -> dict[str, Path]:
    """The cases, written once per test run into a folder every xdist worker shares, so
    that each consumer loads them once (the loads are kept there too: real_loads)."""
    shared = tmp_path_factory.getbasetemp() if worker_id == "master" else tmp_path_factory.getbasetemp().parent
    folder = shared / "target-cases"
    with locked(shared / "target-cases.lock"):
        if (folder / "written").exists():
            return {name: folder / f"{name}.urdf" for name in CASES}
        folder.mkdir(exist_ok=True)
        paths = write_cases(folder)
        (folder / "written").touch()
        return paths


@contextlib.contextmanager
def locked(path: Path):
    """Hold an exclusive lock on ``path`` (created if missing) while the block runs."""
    with open(path, "a") as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def load_all(chosen: Profile, paths: list[str]) -> list[Outcome]:
    return consumers.load(chosen.target, paths, chosen.variants)


@cache
def real_loads(text: str, folder: str) -> dict[str, Outcome]:
    """Every case loaded into one consumer profile, once per test run: the first worker
    to ask loads them and leaves the answers beside the cases for the others."""
    kept = Path(folder) / f"loaded-{text.replace(':', '-')}.json"
    with locked(kept.with_suffix(".lock")):
        if kept.exists():
            return {name: Outcome(**answer) for name, answer in json.loads(kept.read_text()).items()}
        paths = [str(Path(folder) / f"{name}.urdf") for name in CASES]
        found = dict(zip(CASES, load_all(profile(text), paths)))
        kept.write_text(json.dumps({name: loaded._asdict() for name, loaded in found.items()}))
        return found


@cache
def predicted_for(text: str, path: str):
    """urdfcli's result on one case for one profile, once per worker."""
    return predicted(Path(path), profile(text))


def predicted(path: Path, chosen: Profile):
    """urdfcli's result on one file with the target's rules on (and every other rule)."""
    return lint_file(str(path), Config.everything()._replace(targets=(chosen,)))


def target_diagnostics(result, chosen: Profile):
    return [d for d in result.diagnostics if d.code.startswith(chosen.consumer.prefix)]


def predicted_rejection(result, chosen: Profile) -> bool:
    """An error of the target's rules, or a plain error it does not load anyway."""
    return verdict(result.diagnostics, chosen).refuses


# (profile, case) pairs; a consumer that reads the content of a stand-in file is not asked about it
PAIRS = [(text, case) for text in PROFILES for case in CASES if (profile(text).target, case) not in CONTENT_READ]


# -- what each consumer changed, read from what it built -----------------------------------------


def declared(path: Path):
    return lint_file(str(path), Config()).robot


def moments_of(link) -> tuple[float, ...] | None:
    from urdfcli.model import massprops
    from urdfcli.model.targets import declared_matrix

    tensor = declared_matrix(link)
    return tuple(sorted(massprops.principal_moments(tensor))) if tensor is not None else None


def apart(a, b, tolerance: float) -> bool:
    scale = max([abs(v) for v in (*a, *b)] + [1e-12])
    return any(abs(x - y) > tolerance * scale for x, y in zip(sorted(a), sorted(b)))


def mujoco_changes(robot, built: dict) -> set[str]:
    changed = set()
    bodies = {b["name"] for b in built["bodies"]}
    changed |= {name for name in robot.links if name not in bodies}  # fused away
    for joint in built["joints"]:
        urdf = robot.joints.get(joint["name"])
        if urdf is not None and urdf.type in ("revolute", "prismatic") and urdf.limit is not None and not joint["limited"]:
            changed.add(urdf.name)
    for body in built["bodies"]:
        link = robot.links.get(body["name"])
        if link is not None and link.inertial is None and link.collisions:  # weighed by its geometry
            changed.add(link.name)
    return changed


def drake_changes(robot, built: dict) -> set[str]:
    changed = set()
    for body in built["bodies"]:
        link = robot.links.get(body["name"])
        if link is None or link.inertial is None:
            continue
        if abs(body["mass"] - link.inertial.mass) > 1e-12 or apart(body["inertia"], moments_of(link), 1e-6):
            changed.add(link.name)
    for joint in built["joints"]:
        urdf = robot.joints.get(joint["name"])
        if urdf is not None and urdf.type == "continuous" and any(v is not None for v in joint["lower"]):
            changed.add(urdf.name)
    return changed


def pinocchio_changes(robot, built: dict) -> set[str]:
    return {j["name"] for j in built["joints"] if robot.joints[j["name"]].mimic is not None and j["type"] != "JointModelMimic"}


def pybullet_changes(robot, built: dict, from_file: bool) -> set[str]:
    changed = set()
    for entry in built["links"]:
        link = robot.links[entry["name"]]
        mass = link.inertial.mass if link.inertial is not None else (0.0 if link.name == "world" else None)  # world: the fixed base
        if mass is None or abs(entry["mass"] - mass) > 1e-12:
            changed.add(link.name)
        moments = moments_of(link)
        if moments is not None and link.inertial.mass and apart(entry["inertia"], moments, 0.1 if not from_file else 1e-6):
            changed.add(link.name)
    for joint in built["joints"]:
        urdf = robot.joints[joint["name"]]
        if joint["type"] == 4 and urdf.type != "fixed":  # JOINT_FIXED
            changed.add(urdf.name)
        if urdf.type in ("revolute", "prismatic") and joint["lower"] > joint["upper"]:  # Bullet's "no limit"
            changed.add(urdf.name)
    return changed


def gazebo_changes(robot, built: dict) -> set[str]:
    """Links left out of the SDF (dropped or lumped; a link named world is the world itself),
    joints whose limits or mimic changed."""
    links = {b["name"] for b in built["bodies"]}
    changed = {name for name in robot.links if name not in links and name != "world"}
    for joint in built["joints"]:
        urdf = robot.joints.get(joint["name"])
        if urdf is None:
            continue
        if urdf.type in ("revolute", "prismatic") and (joint["lower"], joint["upper"]) != (urdf.limit.lower, urdf.limit.upper):
            changed.add(urdf.name)
        if urdf.mimic is not None and not joint["mimic"]:
            changed.add(urdf.name)
    return changed


def kdl_changes(robot, built: dict) -> set[str]:
    """Joints made fixed, and a root whose mass the tree has no place for."""
    changed = {s["joint"] for s in built["bodies"] if s["type"] in ("Fixed", "None") and robot.joints[s["joint"]].type != "fixed"}
    root = robot.links[built["root"]]
    if root.inertial is not None and root.inertial.mass:
        changed.add(root.name)
    return changed


def isaac_changes(robot, built: dict) -> set[str]:
    """Joints whose limits are not the declared ones, bodies left to be weighed by their colliders."""
    changed = set()
    for joint in built["joints"]:
        urdf = robot.joints.get(joint["name"])
        if urdf is None or urdf.type not in ("revolute", "prismatic"):
            continue
        declared = (urdf.limit.lower, urdf.limit.upper) if urdf.limit is not None else (None, None)
        if any(a is None or b is None or abs(a - b) > 1e-6 for a, b in zip(declared, (joint["lower"], joint["upper"]))):
            changed.add(urdf.name)
    for body in built["bodies"]:
        if not body["mass"] and robot.links[body["name"]].collisions:
            changed.add(body["name"])
    return changed


def changes(chosen: Profile, robot, built: dict) -> set[str]:
    if chosen.target == "pybullet":
        return pybullet_changes(robot, built, "inertia-from-file" in chosen.variants)
    return CHANGES[chosen.target](robot, built)


CHANGES = {"mujoco": mujoco_changes, "drake": drake_changes, "pinocchio": pinocchio_changes, "gazebo": gazebo_changes,
           "kdl": kdl_changes, "isaac": isaac_changes}


@pytest.mark.parametrize(("text", "case"), PAIRS)
def test_the_prediction_matches_what_the_consumer_did(text, case, cases):
    """An error of the target's rules exactly when the consumer rejects the model; where it
    builds the model, each element it drops or changes is named by a diagnostic of those
    rules, and each of their warnings names such an element."""
    chosen = profile(text)
    require_consumer(chosen.target)
    real = real_loads(text, str(cases[case].parent))[case]
    result = predicted_for(text, str(cases[case]))
    said = [(d.code, d.message) for d in target_diagnostics(result, chosen)]
    assert predicted_rejection(result, chosen) == (not real.accepted), (real.error or "accepted", said)
    if not real.accepted:
        return  # nothing was built: the verdict is all there is to compare
    changed = changes(chosen, declared(cases[case]), real.built)
    named = {subject for d in target_diagnostics(result, chosen) for subject in d.subjects}
    assert not changed - named, (changed - named, said)
    unfounded = [(d.code, d.message) for d in target_diagnostics(result, chosen) if d.severity is Severity.WARNING and not set(d.subjects) & changed]
    assert not unfounded, (unfounded, changed)


def test_a_clean_model_draws_no_warning_for_the_elements_kept(cases):
    """The baseline's changes are the conventions each consumer applies to every model
    (info); nothing there is a warning or an error."""
    for text in PROFILES:
        result = predicted(cases["baseline"], profile(text))
        serious = [d for d in target_diagnostics(result, profile(text)) if d.severity is not Severity.INFO and d.code not in ("C402", "C401")]
        assert not serious, (text, serious)


# -- the masses and tensors inertia --target predicts ------------------------------------------------

EXACT = {"baseline", "zero-mass", "no-inertial-box", "triangle", "negative-mass", "mass-zero-with-tensor", "not-positive-definite",
         "massless-with-fixed-mass", "no-collision", "world-root"}


SINGLE_PRECISION = {"isaac"}  # USD keeps masses and moments as 32-bit floats


@pytest.mark.parametrize("text", ["mujoco", "drake", "pybullet", "pybullet:inertia-from-file", "gazebo", "kdl", "isaac"])
def test_predicted_mass_properties_are_those_built(text, cases):
    """For each case the consumer builds (its rejections are the verdict test's), every
    body's mass and principal moments."""
    chosen = profile(text)
    require_consumer(chosen.target)
    tolerance = 1e-6 if chosen.target in SINGLE_PRECISION else 1e-9
    built_cases = 0
    for case in sorted(EXACT):
        real = real_loads(text, str(cases[case].parent))[case]
        if not real.accepted:
            continue
        built_cases += 1
        loaded = lint_file(str(cases[case]), Config()).loaded
        built = {b["name"]: b for b in real.built.get("bodies", real.built.get("links", []))}
        compared = 0
        for body in build(loaded, chosen).bodies:
            found = built.get(body.top)
            if found is None or body.mass is None or body.moments is None:
                continue
            compared += 1
            assert math.isclose(found["mass"], body.mass, rel_tol=tolerance, abs_tol=1e-12), (case, body.top, found, body)
            if text != "mujoco" or loaded.robot.links[body.top].inertial is not None:  # MuJoCo's geometry tensor is not predicted
                assert not apart(found["inertia"], body.moments, 1e-6), (case, body.top, found["inertia"], body.moments)
        assert compared, case
    assert built_cases >= len(EXACT) // 2, built_cases


# -- published models ------------------------------------------------------------------------------


def published(tmp_path_factory) -> list[Path]:
    """example-robot-data's URDFs, with package://example-robot-data/ made an absolute path."""
    folder = example_robot_data()
    out = tmp_path_factory.mktemp("published")
    found = []
    for model in sorted((folder / "robots").rglob("*.urdf")):
        text = model.read_text(errors="replace")
        text = re.sub(r"package:///?example-robot-data/", str(folder) + "/", text)
        copy = out / f"{model.parent.parent.name}__{model.name}"
        copy.write_text(text)
        found.append(copy)
    return found


@pytest.fixture(scope="module")
def published_models(tmp_path_factory):
    return published(tmp_path_factory)


# MuJoCo rejects this one for the volume of a mesh, which its compiler works out and
# urdfcli's MuJoCo rules do not: the rejection must be for that reason, and every other
# model must agree (simple_humanoid's ASCII STL meshes are C109's).
MESH_CONTENT = {
    "alex_description__alex_nub_hands.urdf": "mesh volume is too small",
}


@pytest.mark.parametrize("text", ["mujoco", "pinocchio"])
def test_published_models_verdicts_match(text, published_models):
    chosen = profile(text)
    require_consumer(chosen.target)
    reals = consumers.load(chosen.target, [str(p) for p in published_models])
    disagreements = []
    for path, real in zip(published_models, reals):
        if chosen.target == "mujoco" and path.name in MESH_CONTENT:
            assert MESH_CONTENT[path.name] in real.error, (path.name, real.error)
            continue
        result = predicted(path, chosen)
        if predicted_rejection(result, chosen) != (not real.accepted):
            said = [(d.code, d.message) for d in target_diagnostics(result, chosen) if d.severity is Severity.ERROR]
            disagreements.append((path.name, real.error[:200] or "accepted", said[:2]))
    assert len(published_models) >= 60
    assert not disagreements, disagreements


@pytest.mark.parametrize(("count", "said"), [
    (200_001, "its STL decoder takes at most 200,000 triangles per file, exceeded by 'dense.stl'"),
    (0, "its STL decoder needs at least one triangle, and there is none in 'dense.stl'"),
])
def test_an_stl_of_a_triangle_count_mujoco_refuses_is_rejected_by_both(tmp_path, count, said):
    """Only the header and the size are read, by urdfcli as by MuJoCo: a binary STL of
    200,001 zero triangles (10 MB) stands for a dense CAD export."""
    require_consumer("mujoco")
    with open(tmp_path / "dense.stl", "wb") as file:
        file.write(b"\0" * 80 + count.to_bytes(4, "little"))
        file.truncate(84 + 50 * count)
    model = tmp_path / "dense.urdf"
    model.write_text(
        '<robot name="r"><link name="base"/><link name="l"><inertial><mass value="1"/>'
        '<inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>'
        '<collision><geometry><mesh filename="dense.stl"/></geometry></collision></link>'
        '<joint name="j" type="revolute"><parent link="base"/><child link="l"/><axis xyz="0 0 1"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>'
    )
    [real] = consumers.load("mujoco", [str(model)])
    assert not real.accepted and "200000" in real.error, real
    found = [d.message for d in predicted(model, profile("mujoco")).diagnostics if d.code == "C109"]
    assert found == [f"MuJoCo rejects link 'l': {said}"]


# -- check --load ----------------------------------------------------------------------------------


def test_load_reports_the_consumers_own_error_at_the_element_it_names(cases):
    require_consumer("mujoco")
    done = run_cli("check", "--format", "concise", "--target", "mujoco", "--load", str(cases["triangle"]))
    lines = done.stdout.decode().splitlines()
    rejected = [line for line in lines if " C001 error: MuJoCo refuses the model" in line]
    assert rejected and "A + B >= C" in rejected[0], lines
    link1 = next(n for n, line in enumerate(cases["triangle"].read_text().splitlines(), 1) if 'name="link1"' in line)
    assert rejected[0].split(":")[1] == str(link1)  # where link1 was written
    assert not any(" C002 " in line for line in lines)  # the prediction agreed
    assert done.returncode == 1


def test_load_says_what_the_consumer_warned(cases):
    require_consumer("mujoco")
    done = run_cli("check", "--format", "concise", "--target", "mujoco", "--load", str(cases["lower-equals-upper"]))
    warned = [line for line in done.stdout.decode().splitlines() if " C003 " in line]
    assert warned and "equal lower and upper limits" in warned[0]


def test_load_without_a_target_is_one_line_and_exit_2(cases):
    done = run_cli("check", "--load", str(cases["baseline"]))
    assert done.returncode == 2
    assert done.stderr.decode().strip().splitlines() == ["urdfcli: --load loads the model into the --target consumers: name one, such as --target mujoco"]


def test_unknown_target_is_one_line_and_exit_2(cases):
    done = run_cli("check", "--target", "mujoko", str(cases["baseline"]))
    assert done.returncode == 2
    assert "unknown target 'mujoko'" in done.stderr.decode() and len(done.stderr.decode().strip().splitlines()) == 1


def test_the_target_help_lists_the_registry():
    """--target's help is written out (so that --help imports no consumer); it says what the registry holds."""
    from urdfcli import targets
    from urdfcli.cli.common import TargetOption

    [option] = [meta for meta in TargetOption.__metadata__ if hasattr(meta, "help")]
    assert f"rejects, changes or warns about: {targets.help_text()}. Repeatable" in option.help


def test_predictions_import_no_consumer(cases):
    """--target costs no import of any consumer: predictions are urdfcli's own."""
    code = (
        "import sys, urdfcli\n"
        f"urdfcli.check({str(cases['triangle'])!r}, targets=['mujoco', 'drake', 'pinocchio', 'pybullet'])\n"
        "print(sorted(m for m in ('mujoco', 'pydrake', 'pinocchio', 'pybullet') if m in sys.modules))"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.stdout.strip() == "[]", done.stderr


def test_targets_in_the_configuration(tmp_path):
    model = tmp_path / "arm.urdf"
    model.write_text(CASES["lower-above-upper"])
    (tmp_path / "urdfcli.toml").write_text('targets = ["drake"]\n')
    done = run_cli("check", "--format", "concise", str(model))
    assert " C204 error: Drake aborts" in done.stdout.decode() + done.stderr.decode()
    (tmp_path / "urdfcli.toml").write_text('targets = ["drak"]\n')
    done = run_cli("check", str(model))
    assert done.returncode == 2 and "unknown target 'drak'" in done.stderr.decode()
