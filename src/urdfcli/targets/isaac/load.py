"""Isaac Sim 6's importer, stage 1 (``check --target isaac --load``, the differential test):
the USD stage urdf-usd-converter writes (in the system's temporary folder), read back."""

from __future__ import annotations

import math
import tempfile
from typing import Any

from ...project.loading import Loader, Outcome, Packages, Said, lines_of, python_package, refusal


def built(path: str, variants: frozenset[str], packages: Packages) -> dict:
    """Its rigid bodies (mass None where none is authored: the physics engine weighs the
    colliders) and its joints (limits in radians or metres, None where there is none)."""
    from pxr import Usd, UsdPhysics
    from urdf_usd_converter import Converter

    with tempfile.TemporaryDirectory(prefix="urdfcli-isaac-") as folder:
        stage = Usd.Stage.Open(Converter(layer_structure=False, scene=False).convert(path, folder).path)
        bodies, joints = [], []
        for prim in stage.Traverse():
            name = prim.GetDisplayName() or prim.GetName()  # a name USD cannot hold is kept as the display name
            if prim.HasAPI(UsdPhysics.RigidBodyAPI):
                bodies.append({"name": name, "prim": prim.GetName(), "mass": _authored(UsdPhysics.MassAPI(prim).GetMassAttr()),
                               "inertia": _authored(UsdPhysics.MassAPI(prim).GetDiagonalInertiaAttr())})
            elif prim.IsA(UsdPhysics.Joint):
                joints.append({"name": name, "prim": prim.GetName(), "type": prim.GetTypeName(), **_usd_limits(prim)})
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


def said(outcome: Outcome, path: str) -> list[Said]:
    found = [] if outcome.accepted else [refusal(outcome.error, path)]
    return found + [m for m in lines_of(outcome.printed, "warning", path) if "warn" in m.text.lower()]


LOADER = Loader("isaac", python_package("urdf_usd_converter", "urdf-usd-converter"), said, built=built)
