"""PyBullet's own load (``check --target pybullet --load``, the differential test): ``loadURDF``
in DIRECT mode (with ``URDF_USE_INERTIA_FROM_FILE``, ``useFixedBase=True`` for the variants),
finding ``package://NAME/`` in the packages urdfcli resolved; the links and joints it made."""

from __future__ import annotations

import re

from ...project.loading import Loader, Outcome, Packages, Said, package_folders, python_package, quoted


def built(path: str, variants: frozenset[str], packages: Packages) -> dict:
    """Each link's mass and principal moments (``getDynamicsInfo``), each joint's kind and
    limits. PyBullet drops ``package://`` and looks the rest up under its search path, which
    holds one entry per package here."""
    import pybullet

    client = pybullet.connect(pybullet.DIRECT)
    try:
        with package_folders(packages) as folder:
            pybullet.setAdditionalSearchPath(folder, physicsClientId=client)
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
    finally:
        pybullet.disconnect(physicsClientId=client)


PREFIX = re.compile(r"b3(Warning|Error)\[[^\]]*\]:\s*")


def said(outcome: Outcome, path: str) -> list[Said]:
    """PyBullet's messages follow their ``b3Warning[FILE,LINE]:`` or ``b3Error[...]:`` prefix (its
    own source file, not the model's); "Cannot load URDF file." alone says nothing of why."""
    found = []
    pieces = PREFIX.split(outcome.printed)
    for kind, text in zip(pieces[1::2], pieces[2::2]):
        text = " ".join(text.split())
        if text:
            found.append(Said("error" if kind == "Error" else "warning", text, None, quoted(text)))
    if not outcome.accepted and not any(s.severity == "error" for s in found):
        found.append(Said("error", outcome.error.strip() or "Cannot load URDF file."))
    return found


LOADER = Loader("pybullet", python_package("pybullet", "pybullet"), said, built=built)
