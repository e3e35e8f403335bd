"""MuJoCo's own load (``check --target mujoco --load``, the differential test):
``mujoco.MjModel.from_xml_path`` on the file, and the bodies and joints it compiled."""

from __future__ import annotations

from ...project.loading import Loader, Outcome, Packages, Said, lines_of, python_package, refusal


def built(path: str, variants: frozenset[str], packages: Packages) -> dict:
    """The compiled model: each body (mass, principal moments, parent), each joint (kind,
    range). MuJoCo resolves no ``package://`` (it is given none)."""
    import mujoco

    model = mujoco.MjModel.from_xml_path(path)

    def name(kind, i):
        return mujoco.mj_id2name(model, kind, i)

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


def said(outcome: Outcome, path: str) -> list[Said]:
    """Its error (``Error: ...`` and ``Element name 'NAME', id N``: one message) and its
    ``WARNING:`` lines."""
    found = []
    if not outcome.accepted:
        found.append(refusal(outcome.error, path))
    found += [m for m in lines_of(outcome.printed, "warning", path) if m.text.upper().startswith("WARNING")]
    return found


LOADER = Loader("mujoco", python_package("mujoco", "mujoco"), said, built=built)
