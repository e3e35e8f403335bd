"""Loading a model into a real consumer (MuJoCo, Drake, Pinocchio, PyBullet, Isaac Sim's
converter), for ``check --target NAME --load`` and the differential tests.

The consumer runs in a child process (``python -m urdfcli.project.consumers NAME
VARIANTS FILE``): PyBullet segfaults on some models and Drake turns some inputs
into ``SystemExit``, neither of which may take urdfcli down. The child prints
one JSON object: whether the consumer accepted the model, its error, what it
printed, and what it built (bodies with their mass and principal moments,
joints with their kind and range, degrees of freedom). Nothing here is
imported by a prediction: only the child imports the consumer.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from typing import Any, NamedTuple

PACKAGES = {"mujoco": "mujoco", "drake": "pydrake", "pinocchio": "pinocchio", "pybullet": "pybullet", "isaac": "urdf_usd_converter"}
INSTALL = {"mujoco": "mujoco", "drake": "drake", "pinocchio": "pin", "pybullet": "pybullet", "isaac": "urdf-usd-converter"}
TIMEOUT = 120.0  # seconds a consumer may take to load one model


class ConsumerLoad(NamedTuple):
    """What a consumer did with a model. ``crashed`` is the signal that killed it."""

    accepted: bool
    error: str = ""
    printed: str = ""  # what the consumer wrote to its standard output and error
    built: dict[str, Any] = {}
    crashed: int | None = None


def installed(target: str) -> bool:
    """Whether the consumer's Python package can be imported here (without importing it)."""
    import importlib.util

    return importlib.util.find_spec(PACKAGES[target]) is not None


def install_hint(target: str) -> str:
    return f"pip install {INSTALL[target]}"


def load(target: str, path: str, variants: tuple[str, ...] = ()) -> ConsumerLoad:
    """Load ``path`` (a plain URDF file) into ``target`` in a child process."""
    return load_many(target, [path], variants)[0]


def load_many(target: str, paths: list[str], variants: tuple[str, ...] = ()) -> list[ConsumerLoad]:
    """Load each of ``paths`` into ``target``, in one child process (PyBullet: one per
    file, since it may crash): one :class:`ConsumerLoad` per path, in order."""
    if target == "pybullet" and len(paths) > 1:
        return [load(target, path, variants) for path in paths]
    command = [sys.executable, "-m", "urdfcli.project.consumers", target, ",".join(variants), *map(os.path.abspath, paths)]
    try:
        with tempfile.TemporaryDirectory(prefix="urdfcli-load-") as folder:  # where MuJoCo writes MUJOCO_LOG.TXT
            done = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT * len(paths), errors="replace", cwd=folder)
    except subprocess.TimeoutExpired:
        return [ConsumerLoad(False, f"{target} did not finish loading in {TIMEOUT:.0f} s")] * len(paths)
    answers = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    found = [ConsumerLoad(a["accepted"], a.get("error", ""), a.get("printed", ""), a.get("built", {})) for a in answers]
    if len(found) < len(paths):  # the child died on the next one
        why = f"{target} crashed (signal {-done.returncode})" if done.returncode < 0 else f"{target} exited with status {done.returncode}"
        found.append(ConsumerLoad(False, why, done.stderr[-2000:], crashed=-done.returncode if done.returncode < 0 else None))
        found += load_many(target, paths[len(found):], variants) if len(found) < len(paths) else []
    return found


# -- in the child process ----------------------------------------------------------------


@contextlib.contextmanager
def captured() -> Iterator[list[str]]:
    """What C and Python code write to file descriptors 1 and 2 while the block runs."""
    found: list[str] = []
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with tempfile.TemporaryFile() as sink:
        os.dup2(sink.fileno(), 1)
        os.dup2(sink.fileno(), 2)
        try:
            yield found
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])
            sink.seek(0)
            found.append(sink.read().decode(errors="replace"))


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def _mujoco(path: str, variants: tuple[str, ...]) -> dict:
    import mujoco

    model = mujoco.MjModel.from_xml_path(path)
    name = lambda kind, i: mujoco.mj_id2name(model, kind, i)  # noqa: E731
    bodies = [
        {"name": name(mujoco.mjtObj.mjOBJ_BODY, i), "mass": float(model.body_mass[i]), "inertia": [float(v) for v in model.body_inertia[i]],
         "parent": name(mujoco.mjtObj.mjOBJ_BODY, int(model.body_parentid[i]))}
        for i in range(model.nbody)
    ]
    kinds = {0: "free", 1: "ball", 2: "slide", 3: "hinge"}
    joints = [
        {"name": name(mujoco.mjtObj.mjOBJ_JOINT, i), "type": kinds[int(model.jnt_type[i])], "limited": bool(model.jnt_limited[i]),
         "range": [float(v) for v in model.jnt_range[i]]}
        for i in range(model.njnt)
    ]
    return {"bodies": bodies, "joints": joints, "nq": model.nq, "nv": model.nv, "ngeom": model.ngeom, "equalities": model.neq}


def _drake(path: str, variants: tuple[str, ...]) -> dict:
    from pydrake.multibody.parsing import Parser
    from pydrake.multibody.plant import AddMultibodyPlantSceneGraph
    from pydrake.multibody.tree import BodyIndex, JointIndex
    from pydrake.systems.framework import DiagramBuilder

    builder = DiagramBuilder()
    plant, _ = AddMultibodyPlantSceneGraph(builder, 1e-3)
    Parser(plant).AddModels(path)
    plant.Finalize()
    bodies = []
    for i in range(1, plant.num_bodies()):
        body = plant.get_body(BodyIndex(i))
        inertia = body.default_spatial_inertia()
        moments = inertia.CalcRotationalInertia().CalcPrincipalMomentsOfInertia()
        bodies.append({"name": body.name(), "mass": float(body.default_mass()), "inertia": [float(m) for m in moments]})
    joints = []
    for i in range(plant.num_joints()):
        joint = plant.get_joint(JointIndex(i))
        lower, upper = joint.position_lower_limits(), joint.position_upper_limits()
        joints.append({"name": joint.name(), "type": joint.type_name(), "lower": [_finite(v) for v in lower], "upper": [_finite(v) for v in upper]})
    return {"bodies": bodies, "joints": joints, "nq": plant.num_positions(), "nv": plant.num_velocities()}


def _pinocchio(path: str, variants: tuple[str, ...]) -> dict:
    import pinocchio

    arguments: list = [path]
    if "free-flyer" in variants:
        arguments.append(pinocchio.JointModelFreeFlyer())
    model = pinocchio.buildModelFromUrdf(*arguments, mimic="mimic" in variants) if "mimic" in variants else pinocchio.buildModelFromUrdf(*arguments)
    joints = [{"name": model.names[i], "type": model.joints[i].shortname(), "nq": model.joints[i].nq, "nv": model.joints[i].nv,
               "mass": float(model.inertias[i].mass)} for i in range(1, model.njoints)]
    frames = [{"name": f.name, "type": str(f.type).rsplit(".", 1)[-1]} for f in model.frames]
    return {"joints": joints, "frames": frames, "nq": model.nq, "nv": model.nv, "mass": float(sum(i.mass for i in model.inertias))}


def _pybullet(path: str, variants: tuple[str, ...]) -> dict:
    import pybullet

    client = pybullet.connect(pybullet.DIRECT)
    flags = pybullet.URDF_USE_INERTIA_FROM_FILE if "inertia-from-file" in variants else 0
    body = pybullet.loadURDF(path, flags=flags, useFixedBase="fixed-base" in variants, physicsClientId=client)
    base = pybullet.getDynamicsInfo(body, -1, physicsClientId=client)
    links = [{"name": pybullet.getBodyInfo(body, physicsClientId=client)[0].decode(), "mass": base[0], "inertia": list(base[2])}]
    joints = []
    for i in range(pybullet.getNumJoints(body, physicsClientId=client)):
        info = pybullet.getJointInfo(body, i, physicsClientId=client)
        dynamics = pybullet.getDynamicsInfo(body, i, physicsClientId=client)
        links.append({"name": info[12].decode(), "mass": dynamics[0], "inertia": list(dynamics[2])})
        joints.append({"name": info[1].decode(), "type": int(info[2]), "lower": info[8], "upper": info[9]})
    return {"links": links, "joints": joints}


def _isaac(path: str, variants: tuple[str, ...]) -> dict:
    """Isaac Sim 6's importer, stage 1: the USD stage urdf-usd-converter writes, read back:
    its rigid bodies (mass None where none is authored: the physics engine weighs the
    colliders) and its joints (limits in radians or metres, None where there is none)."""
    from pxr import Usd, UsdPhysics
    from urdf_usd_converter import Converter

    with tempfile.TemporaryDirectory() as folder:
        stage = Usd.Stage.Open(Converter(layer_structure=False, scene=False).convert(path, folder).path)
        bodies, joints = [], []
        for prim in stage.Traverse():
            name = prim.GetDisplayName() or prim.GetName()  # a name USD cannot hold is kept as the display name
            if prim.HasAPI(UsdPhysics.RigidBodyAPI):
                bodies.append({"name": name, "mass": _authored(UsdPhysics.MassAPI(prim).GetMassAttr()),
                               "inertia": _authored(UsdPhysics.MassAPI(prim).GetDiagonalInertiaAttr())})
            elif prim.IsA(UsdPhysics.Joint):
                joints.append({"name": name, "type": prim.GetTypeName(), **_usd_limits(prim)})
        return {"bodies": bodies, "joints": joints}


def _authored(attribute) -> Any:
    """An attribute's value as JSON, None where the converter wrote none."""
    if not attribute.HasAuthoredValue():
        return None
    value = attribute.Get()
    return [float(v) for v in value] if hasattr(value, "__len__") else float(value)


def _usd_limits(prim) -> dict:
    """A revolute joint's limits back in radians (USD keeps degrees), a prismatic one's in metres."""
    lower, upper = (prim.GetAttribute(f"physics:{side}Limit") for side in ("lower", "upper"))
    scale = math.radians(1.0) if prim.GetTypeName() == "PhysicsRevoluteJoint" else 1.0
    found = {side: _authored(attribute) for side, attribute in (("lower", lower), ("upper", upper)) if attribute}
    return {side: None if value is None or not math.isfinite(value) else value * scale for side, value in found.items()}


LOADERS = {"mujoco": _mujoco, "drake": _drake, "pinocchio": _pinocchio, "pybullet": _pybullet, "isaac": _isaac}


def main(argv: list[str]) -> int:
    """Load each file named after the target and its variants; one JSON line per file."""
    target, variants = argv[0], tuple(v for v in argv[1].split(",") if v)
    for path in argv[2:]:
        answer: dict[str, Any] = {"accepted": True}
        with captured() as printed:
            try:
                answer["built"] = LOADERS[target](path, variants)
            except BaseException as error:  # noqa: BLE001 -- Drake's asserts raise SystemExit
                answer = {"accepted": False, "error": f"{type(error).__name__}: {error}".strip()}
        answer["printed"] = printed[0] if printed else ""
        print(json.dumps(answer), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))


# -- --load: the real load beside the prediction -------------------------------------------------

WARNING_LINE = ("warning", "b3warning")


def verify(loaded_model, diagnostics: list, chosen) -> list:
    """Load a model into ``chosen``'s consumer and say what it did: its error (C001) and
    warnings (C003), placed at the link or joint they name, and C002 when its verdict is
    not urdfcli's (an error of the target's rules). ``loaded_model`` is a model.load.ConsumerLoad."""
    from ..model.targets import CODES

    document = loaded_model.document
    with _as_file(document) as path:
        real = load(chosen.target, path, tuple(sorted(chosen.variants)))
    found = []
    robot = loaded_model.robot
    if not real.accepted:
        first = real.error.splitlines()[0] if real.error else "refused the model"
        found.append(_placed(loaded_model, "C001", f"{chosen.name} refuses the model: {first}", real.error))
    for line in real.printed.splitlines():
        if line.lower().lstrip().startswith(WARNING_LINE) or ": warning:" in line.lower():
            found.append(_placed(loaded_model, "C003", f"{chosen.name} warns: {line.strip()[:300]}", line))
    predicted = any(d.code.startswith(CODES[chosen.target]) and d.severity is not None and d.severity.value == "error" for d in diagnostics)
    if predicted == real.accepted:
        said = "rejects" if predicted else "accepts"
        did = "accepted it" if real.accepted else "refused it"
        found.append(loaded_model.diagnostic("C002", f"urdfcli predicted that {chosen.name} {said} the model, but {did}", robot.at))
    return found


def _placed(loaded_model, code: str, message: str, text: str):
    """A diagnostic at the first link or joint the consumer's text names ('link1'), else at <robot>."""
    import re

    robot = loaded_model.robot
    for name in re.findall(r"'([^']+)'", text):
        element = robot.links.get(name) or robot.joints.get(name)
        if element is not None:
            return loaded_model.diagnostic(code, message, element.at, subjects=(name,))
    return loaded_model.diagnostic(code, message, robot.at)


@contextlib.contextmanager
def _as_file(document) -> Iterator[str]:
    """The model as a file the consumer can read: the input itself, or a xacro input's
    expansion written beside it (so that relative mesh paths still resolve), removed after."""
    if not document.is_xacro and document.file is not None:
        yield str(document.file)
        return
    folder = os.path.dirname(os.path.abspath(document.file)) if document.file is not None else None
    handle, path = tempfile.mkstemp(prefix=".urdfcli-load-", suffix=".urdf", dir=folder)
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as out:
            out.write(document.expanded_text or "")
        yield path
    finally:
        os.unlink(path)
