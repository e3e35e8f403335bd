"""PyBullet's own load (``check --target pybullet --load``, the differential test): ``loadURDF``
in DIRECT mode (with ``URDF_USE_INERTIA_FROM_FILE``, ``useFixedBase=True`` for the variants),
finding ``package://NAME/`` in the packages urdfcli resolved; the links and joints it made."""

from __future__ import annotations

import os
import re

from ...project.loading import Loader, Outcome, Packages, Said, line_in, package_folders, python_package, quoted


def built(path: str, variants: frozenset[str], packages: Packages) -> dict:
    """Each link's mass and principal moments (``getDynamicsInfo``), each joint's kind and
    limits, how many constraints it made (none for a ``<mimic>``: it has none). PyBullet drops ``package://`` and looks the rest up from its working folder
    first (UrdfFindMeshFile.h): it works, while it loads, in a folder holding one entry per
    package (this runs in a child process of its own)."""
    import pybullet

    client = pybullet.connect(pybullet.DIRECT)
    here = os.getcwd()
    try:
        with package_folders(packages) as folder:
            os.chdir(folder)
            flags = pybullet.URDF_USE_INERTIA_FROM_FILE if "inertia-from-file" in variants else 0
            body = pybullet.loadURDF(os.path.abspath(path), flags=flags, useFixedBase="fixed-base" in variants, physicsClientId=client)
            os.chdir(here)
        base = pybullet.getDynamicsInfo(body, -1, physicsClientId=client)
        links = [{"name": pybullet.getBodyInfo(body, physicsClientId=client)[0].decode(), "mass": base[0], "inertia": list(base[2])}]
        joints = []
        for i in range(pybullet.getNumJoints(body, physicsClientId=client)):
            info = pybullet.getJointInfo(body, i, physicsClientId=client)
            dynamics = pybullet.getDynamicsInfo(body, i, physicsClientId=client)
            links.append({"name": info[12].decode(), "mass": dynamics[0], "inertia": list(dynamics[2])})
            joints.append({"name": info[1].decode(), "type": int(info[2]), "lower": info[8], "upper": info[9]})
        return {"links": links, "joints": joints, "constraints": pybullet.getNumConstraints(physicsClientId=client)}
    finally:
        os.chdir(here)
        pybullet.disconnect(physicsClientId=client)


PREFIX = re.compile(r"b3(Warning|Error)\[[^\]]*\]:\s*")


def said(outcome: Outcome, path: str) -> list[Said]:
    """PyBullet's messages follow their ``b3Warning[FILE,LINE]:`` or ``b3Error[...]:`` prefix (its
    own source file, not the model's), one message cut into several where it names a link
    ("... for Link:", "link1"). Its refusal says only "Cannot load URDF file.": its errors are
    joined into one, with the warning that came just before them (the reason, such as "cannot
    find 'x.stl' in any directory in urdf path"), at the line that warning names."""
    pieces = PREFIX.split(outcome.printed)
    messages: list[tuple[str, str]] = []
    for kind, text in zip(pieces[1::2], pieces[2::2]):
        text = " ".join(text.split())
        if not text:
            continue
        if messages and messages[-1][0] == kind and messages[-1][1].endswith(":"):
            messages[-1] = (kind, f"{messages[-1][1]} {text}")
        else:
            messages.append((kind, text))
    errors = [text for kind, text in messages if kind == "Error"]
    first_error = next((n for n, (kind, _) in enumerate(messages) if kind == "Error"), None)
    reason = messages[first_error - 1][1] if first_error and messages[first_error - 1][0] == "Warning" else None
    found = [Said("warning", text, line_in(text, path), quoted(text)) for kind, text in messages if kind == "Warning" and text != reason]
    if not outcome.accepted:
        text = "; ".join(errors) or outcome.error.strip() or "Cannot load URDF file."
        if reason is not None:
            text = f"{reason} ({text})"
        found.insert(0, Said("error", text, line_in(reason or "", path), quoted(text)))
    return found


LOADER = Loader("pybullet", python_package("pybullet", "pybullet"), said, built=built)
