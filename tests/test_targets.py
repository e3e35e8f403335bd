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

import json
import math
import re
import subprocess
import sys
from functools import cache
from pathlib import Path
from typing import NamedTuple

import pytest
from conftest import IN_CI, example_robot_data, lint_file, locked, run_cli, shared_folder
from target_cases import CASES, FACTS, write_cases

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
    shared = shared_folder(tmp_path_factory, worker_id)
    folder = shared / "target-cases"
    with locked(shared / "target-cases.lock"):
        if (folder / "written").exists():
            return {name: folder / f"{name}.urdf" for name in CASES}
        folder.mkdir(exist_ok=True)
        paths = write_cases(folder)
        (folder / "written").touch()
        return paths


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


# The profiles urdfcli predicts together, one run per file: each run holds one profile per consumer,
# so that a diagnostic's code prefix says which profile it is about.
RUNS = (("mujoco", "drake", "pinocchio", "pybullet", "gazebo", "kdl", "isaac"), ("pinocchio:mimic", "pybullet:inertia-from-file"),
        ("pinocchio:free-flyer",))


def run_of(text: str) -> tuple[str, ...]:
    return next(run for run in RUNS if text in run)


@cache
def predicted_run(run: tuple[str, ...], path: str):
    """urdfcli's result on one case with the profiles of ``run``, once per worker."""
    return lint_file(path, Config.everything()._replace(targets=tuple(profile(text) for text in run)))


def predicted_for(text: str, path: str):
    """urdfcli's result on one case for one profile (and the others of its run)."""
    return predicted_run(run_of(text), path)


def predicted(path: Path, chosen: Profile):
    """urdfcli's result on one file with the target's rules on (and every other rule)."""
    return lint_file(str(path), Config.everything()._replace(targets=(chosen,)))


def target_diagnostics(result, chosen: Profile):
    return [d for d in result.diagnostics if d.code.startswith(chosen.consumer.prefix)]


def has_plain_error(result) -> bool:
    """Whether urdfcli finds an error in the model itself (a plain error): what a consumer
    that loads it anyway makes of a broken value is not predicted."""
    from urdfcli.rules import REGISTRY
    from urdfcli.rules.targets import about_the_model

    return result.robot is None or any(d.severity is Severity.ERROR and about_the_model(REGISTRY[d.code]) for d in result.diagnostics)


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
    """Bodies given other mass properties, joints given other limits (a continuous one its
    limits, one whose <limit> has no bounds none), joints whose friction Drake warns it drops
    (at the joint's line), transmissions it made no actuator of."""
    changed = set()
    for body in built["bodies"]:
        link = robot.links.get(body["name"])
        if link is None or link.inertial is None:
            continue
        if link.inertial.mass is None or moments_of(link) is None:
            continue  # a number urdfcli cannot read: the plain error is all there is to say
        if abs(body["mass"] - link.inertial.mass) > 1e-12 or apart(body["inertia"], moments_of(link), 1e-6):
            changed.add(link.name)
    for joint in built["joints"]:
        urdf = robot.joints.get(joint["name"])
        if urdf is not None and urdf.type == "continuous" and any(v is not None for v in joint["lower"]):
            changed.add(urdf.name)
        if urdf is not None and urdf.type in ("revolute", "prismatic") and urdf.limit is not None and joint["lower"] == [None]:
            changed.add(urdf.name)
    for line in built["friction_lines"]:
        changed |= {j.name for j in robot.joints.values() if j.name and f'name="{j.name}"' in line}
    transmitted = {t.find("joint").get("name") for t in robot.blocks("transmission") if t.find("joint") is not None}
    changed |= transmitted - set(built["actuators"])
    return changed


def pinocchio_changes(robot, built: dict) -> set[str]:
    """Mimic joints left free (the free flyer's root_joint is no joint of the URDF)."""
    return {j["name"] for j in built["joints"] if j["name"] in robot.joints and robot.joints[j["name"]].mimic is not None and j["type"] != "JointModelMimic"}


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
        if urdf.mimic is not None and joint["type"] != 4 and not built["constraints"]:  # nothing couples it to the joint it mimics
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
        if urdf.type in ("revolute", "prismatic") and any(abs(a - b) > 1e-9 * max(1.0, abs(b)) for a, b in zip((joint["lower"], joint["upper"]), (urdf.limit.lower, urdf.limit.upper))):
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
        link = robot.links[body["name"]]
        moved = any(j.child == link.name and j.moving for j in robot.joints.values())
        if not body["mass"] and (link.collisions or moved):  # weighed by its colliders, or a body without mass
            changed.add(body["name"])
        if body["prim"] != body["name"]:  # renamed for USD
            changed.add(body["name"])
    written = {joint["name"] for joint in built["joints"]}
    changed |= {j.name for j in robot.joints.values() if j.name not in written and j.type == "floating"}  # left out
    changed |= {joint["name"] for joint in built["joints"] if joint["prim"] != joint["name"]}
    return changed


def changes(chosen: Profile, robot, real: Outcome, path: Path) -> set[str]:
    """The links and joints the consumer changed, read from what it built (and for Drake,
    from the lines its warnings name)."""
    if chosen.target == "pybullet":
        return pybullet_changes(robot, real.built, "inertia-from-file" in chosen.variants)
    if chosen.target == "drake":
        lines = path.read_text().splitlines()
        warned = [int(m.group(1)) for m in re.finditer(r":(\d+): warning: .*non-zero joint friction", real.printed)]
        return drake_changes(robot, {**real.built, "friction_lines": [lines[n - 1] for n in warned if 0 < n <= len(lines)]})
    return CHANGES[chosen.target](robot, real.built)


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
    if not real.accepted or has_plain_error(result):
        return  # nothing was built, or a model already in error: the verdict is all there is to compare
    changed = changes(chosen, declared(cases[case]), real, cases[case])
    named = {subject for d in target_diagnostics(result, chosen) for subject in d.subjects}
    assert not changed - named, (changed - named, said)
    unfounded = [(d.code, d.message) for d in target_diagnostics(result, chosen) if d.severity is Severity.WARNING and not set(d.subjects) & changed]
    assert not unfounded, (unfounded, changed)


@pytest.mark.parametrize(("case", "text", "said", "code"), FACTS, ids=[f"{t}-{c}" for c, t, _, _ in FACTS])
def test_each_fact_measured_on_real_robots_holds_with_the_consumers_own_message(case, text, said, code, cases):
    """The consumer says what the fact says, in its own words (its error, what it printed,
    sdformat's log), and urdfcli says it with the rule that encodes the fact."""
    chosen = profile(text)
    require_consumer(chosen.target)
    real = real_loads(text, str(cases[case].parent))[case]
    if said is not None:
        words = "\n".join([real.error, real.printed, *real.built.get("dropped", ())])
        assert said in words, (case, words[:2000])
    found = [d for d in target_diagnostics(predicted_for(text, str(cases[case])), chosen) if d.code == code]
    assert found, (case, code, [(d.code, d.message) for d in target_diagnostics(predicted_for(text, str(cases[case])), chosen)])


def test_every_plain_error_rule_has_a_case(cases):
    """Which consumers load a model with a plain error is measured: each error rule on the
    model (not a consumer's, not the xacro sources', not one a model that reads at all cannot have)
    is found in one of the cases."""
    from urdfcli.rules import REGISTRY
    from urdfcli.rules.targets import about_the_model

    unreadable = {"X001", "X002", "X003", "X004", "R001"}  # the model is not read: nothing to load
    expected = {code for code, rule in REGISTRY.items() if rule.severity is Severity.ERROR and about_the_model(rule)} - unreadable
    found = {d.code for name in CASES for d in lint_file(str(cases[name]), Config.everything()).diagnostics if d.severity is Severity.ERROR}
    assert expected - found == set(), expected - found


def test_a_clean_model_draws_no_warning_for_the_elements_kept(cases):
    """The baseline's changes are the conventions each consumer applies to every model
    (info); nothing there is a warning or an error."""
    for text in PROFILES:
        result = predicted(cases["baseline"], profile(text))
        serious = [d for d in target_diagnostics(result, profile(text)) if d.severity is not Severity.INFO and d.code not in ("C402", "C401")]
        assert not serious, (text, serious)


# -- the masses and tensors inertia --target predicts ------------------------------------------------

WITHIN = 0.01  # a predicted mass or principal moment is the consumer's within 1 % (of the body's largest moment)


def compare_bodies(built_bodies: list[dict], predicted_build) -> tuple[int, list]:
    """How many of the consumer's bodies urdfcli predicted within 1 %, and those it did not
    (name, what the consumer built, what urdfcli predicted); bodies urdfcli cannot tell
    (a mesh it did not read) or the consumer does not report are left out."""
    built = {b["name"]: b for b in built_bodies}
    agreed, apart_found = 0, []
    for body in predicted_build.bodies:
        found = built.get(body.top)
        if found is None or body.mass is None or body.moments is None or found.get("mass") is None or found.get("inertia") is None:
            continue
        if math.isclose(found["mass"], body.mass, rel_tol=WITHIN, abs_tol=1e-9) and not apart(found["inertia"], body.moments, WITHIN):
            agreed += 1
        else:
            apart_found.append((body.top, (found["mass"], sorted(found["inertia"])), (body.mass, sorted(body.moments))))
    return agreed, apart_found


def built_bodies(chosen: Profile, real: Outcome) -> list[dict]:
    """What the consumer reports per body: Pinocchio per joint (the moving body it carries)."""
    if chosen.target == "pinocchio":
        return [{"name": j["child"], "mass": j["mass"], "inertia": j["inertia"]} for j in real.built["joints"]]
    return real.built.get("bodies", real.built.get("links", []))


@pytest.mark.parametrize("text", ["mujoco", "drake", "pinocchio", "pybullet", "pybullet:inertia-from-file", "gazebo", "kdl", "isaac"])
def test_predicted_mass_properties_are_those_built(text, cases):
    """On every case the consumer builds, each body's mass and principal moments as
    ``inertia --target`` gives them: the consumer's, within 1 %."""
    chosen = profile(text)
    require_consumer(chosen.target)
    compared, differ = 0, []
    for case in CASES:
        real = real_loads(text, str(cases[case].parent)).get(case)
        result = predicted_for(text, str(cases[case]))
        if real is None or not real.accepted or (chosen.target, case) in CONTENT_READ or has_plain_error(result):
            continue
        agreed, apart_found = compare_bodies(built_bodies(chosen, real), build(result.loaded, chosen))
        compared += agreed + len(apart_found)
        differ += [(case, *item) for item in apart_found]
    assert compared >= len(CASES) // 3, compared
    assert not differ, differ


# -- published models ------------------------------------------------------------------------------


PACKAGE = "example-robot-data"
PUBLISHED_PROFILES = ["mujoco", "drake", "pinocchio", "pinocchio:free-flyer", "pinocchio:mimic", "pybullet", "gazebo", "kdl"]

# Where a consumer and urdfcli still disagree on a published model, with the consumer's own reason:
# what it reads and urdfcli does not. Every other verdict must agree.
DISAGREEMENTS: dict[tuple[str, str], str] = {}  # (profile, model) -> the consumer's own words (none left)


class Published(NamedTuple):
    package: Path  # the example-robot-data folder
    models: dict[str, Path]  # name -> the model as published (package://example-robot-data/...)
    copies: dict[str, Path]  # name -> the model with package:// made absolute, for MuJoCo, which resolves none
    folder: Path  # where the loads are kept for every worker


def published_in(folder: Path, package: Path) -> Published:
    models = {f"{m.parent.parent.name}__{m.name}": m for m in sorted((package / "robots").rglob("*.urdf"))}
    return Published(package, models, {name: folder / name for name in models}, folder)


@pytest.fixture(scope="module")
def published(tmp_path_factory, worker_id) -> Published:
    """example-robot-data's 69 URDFs. Each consumer that resolves packages is given the
    package urdfcli resolves (-P example-robot-data=FOLDER): Drake's package map, PyBullet's
    search path; MuJoCo, which resolves none, and urdfcli for MuJoCo read a copy whose
    package:// URIs are made absolute paths."""
    package = example_robot_data()
    shared = shared_folder(tmp_path_factory, worker_id) / "published"
    found = published_in(shared, package)
    with locked(shared.with_suffix(".lock")):
        shared.mkdir(exist_ok=True)
        for name, model in found.models.items():
            if not found.copies[name].exists():
                found.copies[name].write_text(re.sub(r"package:///?example-robot-data/", str(package) + "/", model.read_text(errors="replace")))
    return found


def model_paths(found: Published, text: str) -> dict[str, Path]:
    return found.copies if profile(text).target == "mujoco" else found.models


def published_loads(text: str, found: Published) -> dict[str, Outcome]:
    return _published_loads(text, found.folder, found.package)


@cache
def _published_loads(text: str, folder: Path, package: Path) -> dict[str, Outcome]:
    """Every published model loaded into one profile, once per test run (kept for the other workers)."""
    found = published_in(folder, package)
    kept = found.folder / f"loaded-{text.replace(':', '-')}.json"
    with locked(kept.with_suffix(".lock")):
        if kept.exists():
            return {name: Outcome(**answer) for name, answer in json.loads(kept.read_text()).items()}
        paths = model_paths(found, text)
        outcomes = consumers.load(profile(text).target, [str(p) for p in paths.values()], profile(text).variants, {PACKAGE: str(found.package)})
        loads = dict(zip(paths, outcomes))
        kept.write_text(json.dumps({name: outcome._asdict() for name, outcome in loads.items()}))
        return loads


@cache
def published_prediction(run: tuple[str, ...], path: Path, package: Path):
    """urdfcli's result on a published model with the profiles of ``run``, the package resolved."""
    from urdfcli.api import Target, check_target
    from urdfcli.options import Options, RuleSet
    from urdfcli.session import Session

    config = Config.everything()._replace(targets=tuple(profile(text) for text in run))
    with Session(Options(RuleSet.LINT, package_paths=(f"{PACKAGE}={package}",), config=config)) as session:
        return check_target(Target(str(path)), session)


def published_verdicts(text: str, found: Published):
    """(name, what the consumer did, urdfcli's result) for each published model."""
    reals = published_loads(text, found)
    for name, path in model_paths(found, text).items():
        yield name, reals[name], published_prediction(run_of(text), path, found.package)


@pytest.mark.parametrize("text", PUBLISHED_PROFILES)
def test_published_models_verdicts_match(text, published):
    """urdfcli's verdict is the consumer's on every published model, but those listed with
    the consumer's own reason."""
    chosen = profile(text)
    require_consumer(chosen.target)
    disagreements = []
    for name, real, result in published_verdicts(text, published):
        if (text, name) in DISAGREEMENTS:
            assert DISAGREEMENTS[text, name] in real.error, (name, real.error)
            continue
        if predicted_rejection(result, chosen) != (not real.accepted):
            said = [(d.code, d.message) for d in result.diagnostics if d.severity is Severity.ERROR]
            disagreements.append((name, real.error[:300] or "accepted", said[:2]))
    assert len(published.models) >= 60
    assert not disagreements, disagreements


@pytest.mark.parametrize("text", PUBLISHED_PROFILES)
def test_published_models_changes_are_named(text, published):
    """On every published model the consumer builds, each link or joint it drops or changes is
    named by a diagnostic of its rules."""
    chosen = profile(text)
    require_consumer(chosen.target)
    unnamed = []
    for name, real, result in published_verdicts(text, published):
        if not real.accepted:
            continue
        changed = changes(chosen, result.robot, real, model_paths(published, text)[name])
        named = {subject for d in target_diagnostics(result, chosen) for subject in d.subjects}
        if changed - named:
            unnamed.append((name, sorted(changed - named)[:5]))
    assert not unnamed, unnamed


@pytest.mark.parametrize("text", [t for t in PUBLISHED_PROFILES if t not in ("pinocchio:free-flyer", "pinocchio:mimic")])
def test_published_models_mass_properties_are_those_built(text, published):
    """On every published model the consumer builds, each body's mass and principal moments as
    ``inertia --target`` gives them are the consumer's within 1 % (docs/targets.md gives the counts)."""
    chosen = profile(text)
    require_consumer(chosen.target)
    compared, differ = 0, []
    for name, real, result in published_verdicts(text, published):
        if not real.accepted:
            continue
        agreed, apart_found = compare_bodies(built_bodies(chosen, real), build(result.loaded, chosen))
        compared += agreed + len(apart_found)
        differ += [(name, *item) for item in apart_found]
    assert compared >= 200, compared
    assert not differ, differ[:10]


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


def test_collision_meshes_mujoco_cannot_open_are_one_refusal(tmp_path):
    """ros2_robotiq_gripper without its meshes: nine links' collision files missing. MuJoCo
    stops at the first file it cannot open; D004 already names the folder once. One C110
    names the links, at the first mesh, not nine errors of one cause."""
    model = tmp_path / "gripper.urdf"
    parts = "".join(
        f'<link name="{name}"><inertial><mass value="0.1"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" iyz="0"/></inertial>'
        f'<collision><geometry><mesh filename="meshes/{name}.stl"/></geometry></collision></link>'
        f'<joint name="{name}_joint" type="fixed"><parent link="base"/><child link="{name}"/></joint>'
        for name in ("knuckle", "finger", "tip")
    )
    model.write_text(f'<robot name="r"><link name="base"/>{parts}</robot>')
    found = [d for d in predicted(model, profile("mujoco")).diagnostics if d.code == "C110"]
    assert [d.message for d in found] == [
        "MuJoCo rejects 3 links ('knuckle', 'finger', 'tip'): mesh file 'meshes/knuckle.stl' does not exist (nor 2 more files)"
    ]
    assert found[0].line == 1 and found[0].subjects == ("knuckle", "finger", "tip")


def test_a_missing_mesh_several_links_share_is_counted_once(tmp_path):
    """SO-101 without its assets/ folder: the servo's sts3215_03a_v1.stl is the collision of
    five links, 17 references to 13 files. C110 counts the files missing, not the references."""
    model = tmp_path / "arm.urdf"
    parts = "".join(
        f'<link name="{name}"><inertial><mass value="0.1"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" iyz="0"/></inertial>'
        f'<collision><geometry><mesh filename="assets/{name}.stl"/></geometry></collision>'
        '<collision><geometry><mesh filename="assets/sts3215.stl"/></geometry></collision></link>'
        f'<joint name="{name}_joint" type="fixed"><parent link="base"/><child link="{name}"/></joint>'
        for name in ("shoulder", "upper_arm", "lower_arm")
    )
    model.write_text(f'<robot name="r"><link name="base"/>{parts}</robot>')
    found = [d.message for d in predicted(model, profile("mujoco")).diagnostics if d.code == "C110"]
    assert found == [
        "MuJoCo rejects 3 links ('shoulder', 'upper_arm', 'lower_arm'): mesh file 'assets/shoulder.stl' does not exist (nor 3 more files)"
    ]


def test_links_mujoco_weighs_by_their_shapes_are_one_warning(tmp_path):
    """myCobot's exported arms have no <inertial> at all: MuJoCo fills each moving link's
    collision shapes at 1000 kg/m³. One C107 names the links, at the first written, not a warning
    per link, with the mass MuJoCo gives them in all (romeo_laas_small's collision links weigh
    62 kg so); a link of meshes has no mass worked out here, and the total says so."""
    def chain(names, shape='<box size="0.1 0.1 0.1"/>'):
        return "".join(
            f'<link name="{name}"><collision><geometry>{shape}</geometry></collision></link>'
            f'<joint name="{name}_joint" type="revolute"><parent link="{parent}"/><child link="{name}"/><axis xyz="0 0 1"/>'
            '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
            for parent, name in zip(("base", *names), names)
        )
    require_consumer("mujoco")
    import mujoco

    model = tmp_path / "arm.urdf"
    model.write_text(f'<robot name="r"><link name="base"/>{chain(("link1", "link2", "link3", "link4"))}</robot>')
    found = [d for d in predicted(model, profile("mujoco")).diagnostics if d.code == "C107"]
    assert [d.message for d in found] == [
        "MuJoCo gives 4 links without <inertial> ('link1', 'link2', 'link3' and 1 more) the mass of their collision shapes filled at 1000 kg/m³: 4 kg in all"
    ]
    assert found[0].line == 1 and found[0].subjects == ("link1", "link2", "link3", "link4")
    assert sum(mujoco.MjModel.from_xml_path(str(model)).body_mass) == pytest.approx(4.0)
    model.write_text(f'<robot name="r"><link name="base"/>{chain(("link1",))}</robot>')
    found = [d.message for d in predicted(model, profile("mujoco")).diagnostics if d.code == "C107"]
    assert found == ["MuJoCo gives link 'link1' 1 kg: it has no <inertial>, so its collision shapes are filled at 1000 kg/m³"]
    assert mujoco.MjModel.from_xml_path(str(model)).body_mass[1] == pytest.approx(1.0)
    model.write_text(f'<robot name="r"><link name="base"/>{chain(("link1",))}'
                     + chain(("link2",), '<mesh filename="link2.stl"/>').replace('parent link="base"', 'parent link="link1"') + "</robot>")
    found = [d.message for d in predicted(model, profile("mujoco")).diagnostics if d.code == "C107"]
    assert found == ["MuJoCo gives 2 links without <inertial> ('link1', 'link2') the mass of their collision shapes filled at 1000 kg/m³: "
                     "1 kg in their primitive shapes, and what their meshes weigh"]


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


def load_lines(*args: str) -> list[str]:
    done = run_cli("check", "--format", "concise", "--load", *args)
    return done.stdout.decode().splitlines()


def test_load_runs_gazebo_and_kdl_too(cases):
    """Gazebo through sdformat's tool, KDL through kdl_parser: their own words, and no
    disagreement with the prediction."""
    require_consumer("gazebo")
    require_consumer("kdl")
    lines = load_lines("--target", "gazebo", "--target", "kdl", str(cases["all-massless"]))
    refused = [line for line in lines if " C001 error: Gazebo refuses the model" in line]
    assert refused and any("A model must have at least one link" in line for line in refused), lines
    assert not any(" C001 " in line and "KDL" in line for line in lines), lines
    assert not any(" C002 " in line for line in lines), lines


def test_load_of_a_consumer_not_installed_is_a_one_line_notice(cases, tmp_path):
    """Without sdformat's tool on the PATH, --load --target gazebo says so in one line (C004), never nothing."""
    done = run_cli("check", "--format", "concise", "--load", "--target", "gazebo", str(cases["baseline"]), env={"PATH": str(tmp_path)})
    notices = [line for line in done.stdout.decode().splitlines() if " C004 " in line]
    assert notices == [f"{cases['baseline']}:1:1: C004 info: Gazebo cannot be loaded here: sdformat's tool is not installed "
                       "(`gz sdf` or `ign sdf`; Debian 12: apt install ignition-tools libsdformat-dev)"], done.stdout.decode()
    assert done.returncode == 0 and "Traceback" not in done.stderr.decode()


def test_load_gives_drake_and_pybullet_the_packages_urdfcli_resolved(tmp_path):
    """A package:// mesh of a package found with -P: Drake (its package map) and PyBullet
    (its search path) find it, as urdfcli does."""
    require_consumer("drake")
    require_consumer("pybullet")
    package = tmp_path / "src" / "my_arm"
    (package / "meshes").mkdir(parents=True)
    (package / "package.xml").write_text("<package format='2'><name>my_arm</name></package>\n")
    from target_cases import write_meshes

    write_meshes(package / "meshes")
    model = tmp_path / "arm.urdf"
    model.write_text(CASES["baseline"].replace('<box size="0.1 0.1 0.1"/></geometry></collision></link>\n<link name="link1">',
                                               '<mesh filename="package://my_arm/meshes/part.obj"/></geometry></collision></link>\n<link name="link1">', 1))
    assert "package://my_arm" in model.read_text()
    lines = load_lines("-P", str(package.parent), "--target", "drake", "--target", "pybullet", str(model))
    assert not any(" C001 " in line or " C002 " in line for line in lines), lines


@pytest.mark.parametrize(("target", "case", "said"), [
    ("pybullet", "loop", "C001 error: PyBullet refuses the model: pybullet crashed"),  # a segfault inside its package folder
    ("isaac", "rgba-out-of-range", "C001 error: Isaac Sim refuses the model: ErrorException"),  # urdf-usd-converter's stage, left as it fails
])
def test_a_consumer_leaves_nothing_in_the_temporary_folder(cases, tmp_path, target, case, said):
    """What a consumer leaves in the temporary folder, even when it crashes, goes with the
    working folder of its child process, which urdfcli removes."""
    require_consumer(target)
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    done = run_cli("check", "--format", "concise", "--load", "--target", target, str(cases[case]), env={"TMPDIR": str(temporary)})
    assert said in done.stdout.decode() and " C002 " not in done.stdout.decode(), done.stdout.decode()
    assert list(temporary.iterdir()) == []


def test_mujocos_fixed_base_note_hints_only_what_applies(tmp_path):
    """C108: a robot fixed to a 'world' link on purpose (Shadow's hand) is not told to free its
    base, and a robot with no fixed child is not told how to keep fused links."""
    inertial = '<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>'
    hand = tmp_path / "hand.urdf"
    hand.write_text(f'<robot name="hand"><link name="world"/><link name="palm">{inertial}</link><link name="palm_frame"/>'
                    '<joint name="w" type="fixed"><parent link="world"/><child link="palm"/></joint>'
                    '<joint name="f" type="fixed"><parent link="palm"/><child link="palm_frame"/></joint></robot>\n')
    rover = tmp_path / "rover.urdf"
    rover.write_text(f'<robot name="rover"><link name="chassis">{inertial}</link></robot>\n')
    for path, hint in ((hand, 'keep fused links with <mujoco><compiler fusestatic="false"/></mujoco>'),
                       (rover, "for a free base, join the root to a massless 'world' link by a floating joint")):
        done = run_cli("check", "--format", "json", "--target", "mujoco", str(path))
        [found] = [d for d in json.loads(done.stdout)["files"][0]["diagnostics"] if d["code"] == "C108"]
        assert found["hint"] == hint, found


def test_a_transmission_written_twice_is_said_to_be_a_repeat(cases):
    """C209: franka_description writes each joint's transmission once per hardware interface,
    under one name; the message names the repeat instead of a transmission 'already' itself."""
    done = run_cli("check", "--format", "json", "--target", "drake", str(cases["repeated-transmission"]))
    [found] = [d for d in json.loads(done.stdout)["files"][0]["diagnostics"] if d["code"] == "C209"]
    assert found["message"] == "Drake refuses transmission 'j1_transmission', written twice: both make actuator 'j1_motor'", found
    assert "one <hardwareInterface> per interface" in found["hint"], found
    done = run_cli("check", "--format", "json", "--target", "drake", str(cases["shared-actuator"]))
    [found] = [d for d in json.loads(done.stdout)["files"][0]["diagnostics"] if d["code"] == "C209"]
    assert found["message"] == "Drake refuses transmission 't2': actuator 'motor' is already transmission 't1''s", found


def test_load_reports_pybullets_own_reason(cases):
    """PyBullet's exception says only "Cannot load URDF file."; its reason is on its b3Warning lines."""
    require_consumer("pybullet")
    lines = load_lines("--target", "pybullet", str(cases["visual-mesh-format"]))
    refused = [line for line in lines if " C001 error: PyBullet refuses the model: " in line]
    assert any("invalid mesh filename extension" in line for line in refused), lines
    assert not any(" C002 " in line for line in lines), lines


def test_load_counts_the_plain_errors_the_consumer_refuses(cases):
    """Pinocchio refuses a revolute joint without <limit> (J003, a plain error): urdfcli predicted it."""
    require_consumer("pinocchio")
    lines = load_lines("--target", "pinocchio", str(cases["revolute-no-limit"]))
    assert any(" C001 error: Pinocchio refuses the model" in line for line in lines), lines
    assert not any(" C002 " in line for line in lines), lines


def test_load_of_a_xacro_model_writes_nothing_beside_its_sources(tmp_path):
    require_consumer("mujoco")
    from target_cases import write_meshes

    write_meshes(tmp_path)
    model = tmp_path / "arm.urdf.xacro"
    model.write_text(CASES["stl-collision"].replace('<robot name="r">', '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property name="m" value="1"/>'))
    before = sorted(p.name for p in tmp_path.iterdir())
    lines = load_lines("--target", "mujoco", str(model))
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    assert not any(" C001 " in line or " C002 " in line for line in lines), lines  # its relative mesh found from the temporary file


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
    (tmp_path / "urdfcli.toml").write_text('targets = ["all"]\n')
    done = run_cli("check", "--format", "json", str(model))
    assert [row["target"] for row in json.loads(done.stdout)["files"][0]["compatibility"]] == ["mujoco", "drake", "pinocchio", "pybullet", "gazebo", "kdl", "isaac"]
    (tmp_path / "urdfcli.toml").write_text('targets = ["drak"]\n')
    done = run_cli("check", str(model))
    assert done.returncode == 2 and "unknown target 'drak'" in done.stderr.decode()


def test_docs_targets_md_holds_the_registry():
    """docs/targets.md's list of consumers and of the plain errors each loads is made from the registry."""
    from conftest import ROOT

    from urdfcli.report.targets import registry_markdown

    text = (ROOT / "docs" / "targets.md").read_text(encoding="utf-8")
    section = text[text.index("<!-- registry -->\n") + len("<!-- registry -->\n"):text.index("<!-- end of registry -->")]
    assert section == registry_markdown(), "docs/targets.md is stale: paste urdfcli.report.targets.registry_markdown() between its registry markers"


def test_check_target_all_ends_with_the_compatibility_table(cases):
    """One row per consumer (loads / loads with N changes / refuses), the first reason at its
    file:line; JSON carries the same."""
    done = run_cli("check", "--target", "all", str(cases["lower-above-upper"]))
    lines = done.stderr.decode().splitlines()
    start = next(n for n, line in enumerate(lines) if line.startswith("Compatibility of "))
    rows = {line.split()[0]: line for line in lines[start + 1:start + 8]}
    assert set(rows) == {"MuJoCo", "Drake", "Pinocchio", "PyBullet", "Gazebo", "KDL", "Isaac"}, rows
    line = next(n for n, text in enumerate(cases["lower-above-upper"].read_text().splitlines(), 1) if 'lower="1"' in text)
    assert "refuses" in rows["Drake"] and f"lower-above-upper.urdf:{line}: C204 Drake aborts" in rows["Drake"], rows["Drake"]
    assert "loads with 1 change" in rows["MuJoCo"] and "C106" in rows["MuJoCo"], rows["MuJoCo"]
    assert rows["KDL"].split()[1:] == ["loads"], rows["KDL"]
    document = json.loads(run_cli("check", "--target", "all", "--format", "json", str(cases["lower-above-upper"])).stdout)
    table = {row["target"]: row for row in document["files"][0]["compatibility"]}
    assert table["drake"]["verdict"] == "refuses" and table["drake"]["reason"]["code"] == "C204" and table["drake"]["reason"]["line"] == line
    assert table["mujoco"] == {**table["mujoco"], "verdict": "loads with changes", "changes": 1}
    assert table["kdl"]["verdict"] == "loads" and table["kdl"]["reason"] is None


def test_a_plain_error_counts_only_for_the_consumers_that_refuse_it(cases):
    """J003 (a revolute joint without <limit>): urdfdom's consumers and PyBullet refuse the
    model, MuJoCo, Drake and Isaac Sim load it (Isaac Sim locks the joint)."""
    document = json.loads(run_cli("check", "--target", "all", "--format", "json", str(cases["revolute-no-limit"])).stdout)
    verdicts = {row["target"]: row["verdict"] for row in document["files"][0]["compatibility"]}
    assert verdicts == {"mujoco": "loads", "drake": "loads", "pinocchio": "refuses", "pybullet": "refuses", "gazebo": "refuses",
                        "kdl": "refuses", "isaac": "loads with changes"}


def test_gazebo_mimic_joints_a_mimic_plugin_drives_are_not_said_to_move_freely(tmp_path):
    """robotiq_arg2f_85.gazebo.xacro: sdformat drops <mimic>, and keeps the <gazebo> plugin
    (roboticsgroup's mimic joint plugin) that drives the joint in Gazebo; C506 names only the
    mimic joints no such plugin drives."""
    require_consumer("gazebo")
    from urdfcli.targets.gazebo.load import command

    body = ('<robot name="gripper"><link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>'
            '</inertial></link>{fingers}{plugin}</robot>\n')
    finger = ('<link name="{n}"><inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial></link>'
              '<joint name="{n}_joint" type="revolute"><parent link="base"/><child link="{n}"/><axis xyz="0 0 1"/>'
              '<limit lower="0" upper="1" effort="1" velocity="1"/>{mimic}</joint>')
    fingers = (finger.format(n="left", mimic="") + finger.format(n="right", mimic='<mimic joint="left_joint"/>')
               + finger.format(n="pad", mimic='<mimic joint="left_joint"/>'))
    plugin = ('<gazebo><plugin filename="libroboticsgroup_gazebo_mimic_joint_plugin.so" name="mimic_right">'
              '<joint>left_joint</joint><mimicJoint>right_joint</mimicJoint></plugin></gazebo>')
    path = tmp_path / "gripper.urdf"
    path.write_text(body.format(fingers=fingers, plugin=plugin))
    converted = subprocess.run([*command(), "-p", str(path)], capture_output=True, text=True, timeout=60)
    assert "<mimicJoint>right_joint</mimicJoint>" in converted.stdout and "libroboticsgroup_gazebo_mimic_joint_plugin.so" in converted.stdout
    assert "<mimic" not in converted.stdout.replace("<mimicJoint>", "")  # the <mimic> itself is dropped
    done = run_cli("lint", "--isolated", "--format", "json", "--target", "gazebo", str(path))
    said = [d["message"] for d in json.loads(done.stdout)["files"][0]["diagnostics"] if d["code"] == "C506"]
    assert said == ["Gazebo (sdformat 12) drops the <mimic> of mimic joint 'pad_joint' (of 'left_joint'): it moves freely"]


def test_gazebo_says_why_a_lumped_link_counts_as_massless(tmp_path):
    """Spot's arm_link_hr0: a link on a fixed joint with a mass of 1e-6 kg. sdformat 12 counts
    it as massless and drops the moving joints below it; C501 gives the mass it has, not
    "no mass", which its <inertial> would contradict."""
    inertia = '<inertia ixx="1e-9" ixy="0" ixz="0" iyy="1e-9" iyz="0" izz="1e-9"/>'
    body = '<link name="{n}"><inertial><mass value="{m}"/>' + inertia + '</inertial></link>'
    moving = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
    text = ('<robot name="arm">' + body.format(n="base", m="1")
            + '<link name="shoulder"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>'
            + '<joint name="sh0" type="revolute"><parent link="base"/><child link="shoulder"/><axis xyz="0 0 1"/>' + moving + '</joint>'
            + '{roll}<joint name="hr0" type="fixed"><parent link="shoulder"/><child link="roll"/></joint>'
            + body.format(n="elbow", m="0.7")
            + '<joint name="el0" type="revolute"><parent link="roll"/><child link="elbow"/><axis xyz="0 1 0"/>' + moving + '</joint></robot>\n')
    said = {}
    for name, roll in (("tiny", body.format(n="roll", m="1e-06")), ("none", '<link name="roll"/>')):
        path = tmp_path / f"{name}.urdf"
        path.write_text(text.replace("{roll}", roll))
        done = run_cli("check", "--isolated", "--format", "json", "--target", "gazebo", str(path))
        said[name] = [d["message"] for d in json.loads(done.stdout)["files"][0]["diagnostics"] if d["code"] == "C501"]
    assert said == {
        "tiny": ["Gazebo drops link 'elbow': it hangs below 'roll', which has a mass of 1e-06 kg, within 1e-6 of 0 (sdformat does not go below it)"],
        "none": ["Gazebo drops link 'elbow': it hangs below 'roll', which has no <inertial> (sdformat does not go below it)"],
    }


def test_gazebo_lumping_one_link_is_said_in_the_singular(tmp_path):
    """ROBOTIS OP3's head: one camera frame on a fixed joint. C504 names it as one link
    lumped into its parent, and two such frames as links lumped into their parents."""
    inertial = '<inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>'
    frame = '<link name="{n}"/><joint name="{n}_joint" type="fixed"><parent link="head"/><child link="{n}"/></joint>'
    said = {}
    for frames in (["cam_link"], ["cam_link", "imu_link"]):
        path = tmp_path / f"head{len(frames)}.urdf"
        path.write_text(f'<robot name="op3"><link name="head">{inertial}</link>' + "".join(frame.format(n=n) for n in frames) + "</robot>\n")
        done = run_cli("check", "--isolated", "--format", "json", "--target", "gazebo", str(path))
        said[len(frames)] = [d["message"] for d in json.loads(done.stdout)["files"][0]["diagnostics"] if d["code"] == "C504"]
    assert said == {
        1: ["Gazebo lumps 1 link into its parent on a fixed joint: 'cam_link'"],
        2: ["Gazebo lumps 2 links into their parents on fixed joints: 'cam_link', 'imu_link'"],
    }


def test_a_moving_link_whose_tensor_mujoco_refuses_is_one_error(tmp_path):
    """Fetch's gripper fingers: ixx alone, iyy = izz = 0, on a prismatic joint. MuJoCo stops
    at the tensor ("inertia must have positive eigenvalues"), before its mass check: C103
    says so, and C101 does not say it again of the same link."""
    model = tmp_path / "gripper.urdf"
    model.write_text(
        '<robot name="r"><link name="palm"><inertial><mass value="1"/>'
        '<inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>'
        '<link name="finger"><inertial><mass value="0.08"/>'
        '<inertia ixx="0.002" iyy="0" izz="0" ixy="0" ixz="0" iyz="0"/></inertial></link>'
        '<joint name="finger_joint" type="prismatic"><parent link="palm"/><child link="finger"/><axis xyz="0 1 0"/>'
        '<limit lower="0" upper="0.05" effort="60" velocity="0.05"/></joint></robot>'
    )
    found = [(d.code, d.subjects) for d in predicted(model, profile("mujoco")).diagnostics if d.code in ("C101", "C103")]
    assert found == [("C103", ("finger",))]
    require_consumer("mujoco")
    [real] = consumers.load("mujoco", [str(model)])
    assert not real.accepted and "inertia must have positive eigenvalues" in real.error, real


def test_a_singular_tensor_mujoco_refuses_is_said_to_have_a_zero_moment_not_rounding_noise(tmp_path):
    """Sawyer's right_hand: all six elements 1e-08, exactly singular (moments 0, 0, 3e-08).
    The eigen solve gives -7e-24 for a 0; C103 says 0, as I006 does, not a negative moment."""
    model = tmp_path / "hand.urdf"
    model.write_text(
        '<robot name="r"><link name="base"/><link name="l6"><inertial><mass value="0.3"/>'
        '<inertia ixx="3e-4" iyy="2e-4" izz="3.5e-4" ixy="0" ixz="0" iyz="0"/></inertial></link>'
        '<joint name="j6" type="revolute"><parent link="base"/><child link="l6"/><axis xyz="0 0 1"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        '<link name="hand"><inertial><mass value="1e-08"/>'
        '<inertia ixx="1e-08" ixy="1e-08" ixz="1e-08" iyy="1e-08" iyz="1e-08" izz="1e-08"/></inertial></link>'
        '<joint name="hand_joint" type="fixed"><parent link="l6"/><child link="hand"/></joint></robot>'
    )
    found = [d.message for d in predicted(model, profile("mujoco")).diagnostics if d.code == "C103"]
    assert found == ["MuJoCo rejects link 'hand': its inertia has a principal moment of 0; all must be at least 1e-14"]
    require_consumer("mujoco")
    [real] = consumers.load("mujoco", [str(model)])
    assert not real.accepted and "inertia must have positive eigenvalues" in real.error, real


def test_gazebo_mimic_joints_gz_ros2_control_drives_are_not_said_to_move_freely(tmp_path):
    """gz_ros2_control's gripper demo: the mimic finger is a ros2_control joint with
    <param name="mimic">, which GazeboSimSystem commands after the finger it follows; C506
    names only the mimic joints no Gazebo plugin drives."""
    finger = ('<link name="{n}"><inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial></link>'
              '<joint name="{n}_joint" type="prismatic"><parent link="base"/><child link="{n}"/><axis xyz="0 1 0"/>'
              '<limit lower="0" upper="0.4" effort="1" velocity="1"/>{mimic}</joint>')
    control = ('<ros2_control name="GazeboSimSystem" type="system"><hardware><plugin>{plugin}</plugin></hardware>'
               '<joint name="left_joint"><command_interface name="position"/></joint>'
               '<joint name="right_joint"><param name="mimic">left_joint</param><command_interface name="position"/></joint>'
               '<joint name="pad_joint"><command_interface name="position"/></joint></ros2_control>')
    text = ('<robot name="gripper"><link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>'
            '</inertial></link>' + finger.format(n="left", mimic="") + finger.format(n="right", mimic='<mimic joint="left_joint"/>')
            + finger.format(n="pad", mimic='<mimic joint="left_joint"/>') + '{control}</robot>\n')
    said = {}
    for plugin in ("gz_ros2_control/GazeboSimSystem", "mock_components/GenericSystem"):
        path = tmp_path / f"{plugin.split('/')[0]}.urdf"
        path.write_text(text.replace("{control}", control.format(plugin=plugin)))
        done = run_cli("lint", "--isolated", "--format", "json", "--target", "gazebo", str(path))
        said[plugin] = [d["message"] for d in json.loads(done.stdout)["files"][0]["diagnostics"] if d["code"] == "C506"]
    assert said == {
        "gz_ros2_control/GazeboSimSystem": ["Gazebo (sdformat 12) drops the <mimic> of mimic joint 'pad_joint' (of 'left_joint'): it moves freely"],
        "mock_components/GenericSystem": ["Gazebo (sdformat 12) drops the <mimic> of 2 mimic joints ('right_joint', 'pad_joint'): they move freely"],
    }


def test_pybullet_recomputing_a_frames_zero_tensor_as_rounding_noise_is_no_change(tmp_path):
    """onshape-to-robot's frames (SO-101's baseframe, gripperframe): mass 1e-9 and a zero
    tensor, no collision. PyBullet's box for them has moments near 1e-16, rounding noise as
    the zero it replaces: C402 names the link whose tensor really changes, and gives it as
    the example, not the frame."""
    model = tmp_path / "arm.urdf"
    model.write_text(
        '<robot name="arm"><link name="base"><inertial><mass value="0.15"/>'
        '<inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>'
        '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>'
        '<link name="baseframe"><inertial><mass value="1e-9"/>'
        '<inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>'
        '<joint name="baseframe_frame" type="fixed"><parent link="base"/><child link="baseframe"/></joint></robot>\n'
    )
    found = [(d.message, d.subjects) for d in predicted(model, profile("pybullet")).diagnostics if d.code == "C402"]
    assert found == [(
        "PyBullet ignores the <inertia> of 1 link ('base') and recomputes it from the bounding box of the collision shapes;"
        " link 'base': principal moments 0.0001 0.0001 0.0001 become 0.00025 0.00025 0.00025",
        ("base",),
    )]
