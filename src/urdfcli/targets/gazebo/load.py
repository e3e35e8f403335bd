"""Gazebo's own conversion (``check --target gazebo --load``, the differential test): sdformat's
tool (``gz sdf``, or ``ign sdf`` for sdformat 12) converts the URDF (``-p``, the SDF it makes) and
runs the checks Gazebo runs when it loads a model (``-k``); its home is a temporary folder, so
that its log (``.sdformat/sdformat.log``, where sdformat 12 says what it drops) is read and removed."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from collections.abc import Sequence

from lxml import etree

from ...model import massprops
from ...project.loading import Loader, Outcome, Packages, Said, quoted, without_colours

TIMEOUT = 60.0  # seconds sdformat may take on one model
TENSOR = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")


def command() -> list[str] | None:
    """``gz sdf`` where installed, else ``ign sdf``; None when neither has the sdf command."""
    for tool in ("gz", "ign"):
        found = shutil.which(tool)
        if found is None:
            continue
        done = subprocess.run([found, "sdf", "--help"], capture_output=True, text=True, timeout=TIMEOUT, errors="replace")
        if done.returncode == 0 and "--print" in done.stdout:
            return [found, "sdf"]
    return None


def missing() -> str | None:
    if command() is None:
        return "sdformat's tool is not installed (`gz sdf` or `ign sdf`; Debian 12: apt install ignition-tools libsdformat-dev)"
    return None


def load(paths: Sequence[str], variants: frozenset[str], packages: Packages) -> list[Outcome]:
    tool = command()
    if tool is None:
        return [Outcome(False, missing() or "")] * len(paths)
    with tempfile.TemporaryDirectory(prefix="urdfcli-sdformat-") as home:
        return [_convert(tool, path, home) for path in paths]


def _convert(tool: list[str], path: str, home: str) -> Outcome:
    """What sdformat makes of one URDF file: its SDF (``-p``), and whether ``-k`` finds it valid."""
    environment = {**os.environ, "HOME": home}
    log = os.path.join(home, ".sdformat", "sdformat.log")
    if os.path.exists(log):
        os.unlink(log)

    def run(flag: str) -> subprocess.CompletedProcess:
        return subprocess.run([*tool, flag, path], capture_output=True, text=True, timeout=TIMEOUT, errors="replace", env=environment)

    checked, converted = run("-k"), run("-p")
    printed = _without_noise(checked.stderr + converted.stderr)
    dropped = _dropped(log)
    if checked.returncode != 0 or converted.returncode != 0 or "Error" in printed:
        errors = [line for line in printed.splitlines() if "Error" in line]
        return Outcome(False, "\n".join(errors) or f"sdf -k exited with status {checked.returncode}", printed)
    return Outcome(True, "", printed, {**sdf_model(converted.stdout), "dropped": dropped})


def _without_noise(text: str) -> str:
    """sdformat's messages without colour codes and ignition-tools' note about its backtrace library."""
    return "\n".join(line for line in without_colours(text).splitlines() if "libignition-tools-backward" not in line)


def _dropped(log: str) -> list[str]:
    """What sdformat 12 writes only to its log: the links it leaves out ("not modeled in sdf")."""
    try:
        with open(log, encoding="utf-8", errors="replace") as file:
            text = file.read()
    except OSError:
        return []
    return [line.split("]", 1)[-1].strip() for line in text.splitlines() if "not modeled in sdf" in line]


def sdf_model(text: str) -> dict:
    """The links (mass, principal moments) and joints (type, limits, mimic) of an SDF model."""
    model = etree.fromstring(text.encode(), etree.XMLParser(recover=True)).find("model")  # recover: sdformat writes `ignition::` attribute names
    links = []
    for link in model.iter("link"):
        inertial = link.find("inertial")
        mass = float(inertial.findtext("mass")) if inertial is not None else None
        tensor = inertial.find("inertia") if inertial is not None else None
        moments = sorted(massprops.principal_moments(massprops.matrix({key: float(tensor.findtext(key)) for key in TENSOR}))) if tensor is not None else None
        links.append({"name": link.get("name"), "mass": mass, "inertia": moments})
    joints = []
    for joint in model.iter("joint"):
        limit = joint.find("axis/limit")
        joints.append({
            "name": joint.get("name"),
            "type": joint.get("type"),
            "lower": float(limit.findtext("lower")) if limit is not None and limit.findtext("lower") else None,
            "upper": float(limit.findtext("upper")) if limit is not None and limit.findtext("upper") else None,
            "mimic": joint.find("axis/mimic") is not None,
        })
    return {"bodies": links, "joints": joints}


NAMED = re.compile(r"""(?:link|joint)\[@name=["']([^"']+)["']\]|\[([^\]\s]+)\]""")


def said(outcome: Outcome, path: str) -> list[Said]:
    """sdformat's ``Error`` lines (an ``Error Code N: [...]: Msg: ...`` message names the
    element as an SDF path), and the links its log says it leaves out."""
    found = []
    for line in outcome.printed.splitlines():
        line = line.strip()
        if "Error" in line or "Warning" in line:
            names = tuple(a or b for a, b in NAMED.findall(line)) or quoted(line)
            found.append(Said("error" if "Error" in line else "warning", line, None, names))
    for line in outcome.built.get("dropped", ()):
        found.append(Said("warning", line, None, quoted(line)))
    if not outcome.accepted and not found:
        found.append(Said("error", outcome.error.strip()))
    return found


LOADER = Loader("gazebo", missing, said, load=load)
