"""Pinocchio's own load (``check --target pinocchio --load``, the differential test):
``pinocchio.buildModelFromUrdf`` (with ``JointModelFreeFlyer()``, ``mimic=True`` for the
variants), and the joints and frames of the model."""

from __future__ import annotations

from ...project.loading import Loader, Outcome, Packages, Said, lines_of, python_package, refusal


def built(path: str, variants: frozenset[str], packages: Packages) -> dict:
    import pinocchio

    arguments: list = [path]
    if "free-flyer" in variants:
        arguments.append(pinocchio.JointModelFreeFlyer())
    model = pinocchio.buildModelFromUrdf(*arguments, mimic=True) if "mimic" in variants else pinocchio.buildModelFromUrdf(*arguments)
    bodies = {}  # each joint's first body frame: the link it moves (the links fixed to it come after)
    for frame in model.frames:
        if str(frame.type).endswith("BODY"):
            bodies.setdefault(frame.parentJoint, frame.name)
    joints = [{"name": model.names[i], "type": model.joints[i].shortname(), "nq": model.joints[i].nq, "nv": model.joints[i].nv,
               "child": bodies.get(i), "mass": float(model.inertias[i].mass), "inertia": [float(v) for v in _principal(model.inertias[i])]}
              for i in range(1, model.njoints)]
    frames = [{"name": f.name, "type": str(f.type).rsplit(".", 1)[-1]} for f in model.frames]
    universe = model.inertias[0]
    return {"joints": joints, "frames": frames, "nq": model.nq, "nv": model.nv, "universe_mass": float(universe.mass),
            "mass": float(sum(i.mass for i in model.inertias))}


def _principal(inertia) -> list[float]:
    import numpy

    return sorted(float(v) for v in numpy.linalg.eigvalsh(inertia.inertia))


def said(outcome: Outcome, path: str) -> list[Said]:
    """Its exception (urdfdom's or Pinocchio's own), and what urdfdom printed."""
    found = [] if outcome.accepted else [refusal(outcome.error, path)]
    return found + [m for m in lines_of(outcome.printed, "warning", path) if "warn" in m.text.lower() or "error" in m.text.lower()]


LOADER = Loader("pinocchio", python_package("pinocchio", "pin"), said, built=built)
