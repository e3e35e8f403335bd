"""The consumers that are programs, not Python packages: Gazebo's URDF conversion
(sdformat's ``ign sdf``, or ``gz sdf`` from sdformat 13 on) and robot_state_publisher's
KDL tree (kdl_parser, through tests/support/kdl_tree.cpp compiled here).

Each gives a :class:`urdfcli.project.consumers.ConsumerLoad` like the Python consumers:
whether it accepted the model, its error, what it printed and what it built.
Both come from Debian packages that ``make test`` installs (Makefile ``system-test``);
a missing one skips locally and fails in CI (``conftest.require_tool``).
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from conftest import IN_CI, ROOT, require_tool
from lxml import etree

from urdfcli.model import massprops
from urdfcli.project.consumers import ConsumerLoad

KDL_SOURCE = ROOT / "tests" / "support" / "kdl_tree.cpp"
KDL_LIBRARIES = ["-lkdl_parser", "-lorocos-kdl", "-lurdfdom_model"]
TIMEOUT = 60
TENSOR = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")


def sdformat() -> list[str]:
    """The command that runs sdformat's tool: ``gz sdf`` where installed, else ``ign sdf``."""
    tool = shutil.which("gz") or require_tool("ign")
    done = subprocess.run([tool, "sdf", "--help"], capture_output=True, text=True, timeout=TIMEOUT)
    if done.returncode != 0 or "--print" not in done.stdout:
        unavailable(f"{tool} has no sdf command (Debian: libsdformat-dev): {done.stdout.strip()[:200]}")
    return [tool, "sdf"]


def unavailable(message: str) -> None:
    """Skip locally, fail in CI: a consumer that cannot run here."""
    if IN_CI:
        pytest.fail(message)
    pytest.skip(message)


def gazebo(command: list[str], path: str) -> ConsumerLoad:
    """What Gazebo makes of a URDF file: sdformat's SDF (``sdf -p``), and whether
    ``sdf -k`` (the checks Gazebo runs when it loads a model) finds it valid."""
    checked = subprocess.run([*command, "-k", path], capture_output=True, text=True, timeout=TIMEOUT, errors="replace")
    converted = subprocess.run([*command, "-p", path], capture_output=True, text=True, timeout=TIMEOUT, errors="replace")
    said = _without_noise(checked.stderr + converted.stderr)
    if checked.returncode != 0 or converted.returncode != 0:
        errors = [line for line in said.splitlines() if "Error" in line]
        return ConsumerLoad(False, "\n".join(errors) or f"sdf -k exited with status {checked.returncode}", said)
    return ConsumerLoad(True, "", said, sdf_model(converted.stdout))


def _without_noise(text: str) -> str:
    """sdformat's messages without colour codes and ignition-tools' note about its backtrace library."""
    text = re.sub(r"\x1b\[[0-9;]*m", "", text)
    return "\n".join(line for line in text.splitlines() if "libignition-tools-backward" not in line)


def sdf_model(text: str) -> dict:
    """The links (mass, principal moments) and joints (type, limits, mimic) of an SDF model."""
    model = etree.fromstring(text.encode()).find("model")
    links = []
    for link in model.iter("link"):
        inertial = link.find("inertial")
        mass = float(inertial.findtext("mass")) if inertial is not None else None
        tensor = inertial.find("inertia") if inertial is not None else None
        moments = _principal(massprops.matrix({key: float(tensor.findtext(key)) for key in TENSOR})) if tensor is not None else None
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


def _principal(tensor: massprops.Matrix) -> list[float]:
    return sorted(massprops.principal_moments(tensor))


def kdl_program(folder: Path) -> str:
    """tests/support/kdl_tree.cpp compiled against the system's kdl_parser into ``folder``."""
    compiler = require_tool("g++")
    program = folder / "kdl_tree"
    done = subprocess.run([compiler, "-std=c++17", str(KDL_SOURCE), "-o", str(program), *KDL_LIBRARIES],
                          capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        unavailable(f"kdl_tree.cpp does not compile (Debian: libkdl-parser-dev): {done.stderr.strip()[:300]}")
    return str(program)


def kdl(program: str, path: str) -> ConsumerLoad:
    """The KDL tree kdl_parser builds: its segments (each link but the root) with their joint's
    kind and their mass and principal moments; ``printed`` holds kdl_parser's warnings."""
    done = subprocess.run([program, path], capture_output=True, text=True, timeout=TIMEOUT, errors="replace")
    said = _without_noise(done.stderr)
    if done.returncode != 0 or not done.stdout.startswith("{"):
        return ConsumerLoad(False, f"kdl_tree exited with status {done.returncode}", said)
    answer = json.loads(done.stdout)
    if not answer["accepted"]:
        return ConsumerLoad(False, answer["error"], said)
    for segment in answer["segments"]:
        segment["inertia"] = _about_centre_of_mass(segment)
    return ConsumerLoad(True, "", said, {"root": answer["root"], "bodies": answer["segments"]})


def _about_centre_of_mass(segment: dict) -> list[float]:
    """KDL keeps a segment's tensor about its origin; the principal moments about its centre
    of mass (parallel axis theorem) are what a link's <inertia> declares."""
    about = tuple(tuple(segment["inertia"][3 * i: 3 * i + 3]) for i in range(3))
    return _principal(massprops.parallel_axis(about, -segment["mass"], tuple(segment["cog"])))
