"""KDL's own tree (``check --target kdl --load``, the differential test): kdl_parser's
``treeFromUrdfModel`` over urdfdom, as robot_state_publisher builds it, through kdl_tree.cpp
(beside this module), compiled once against the system's kdl_parser into the system's
temporary folder."""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import tempfile
from collections.abc import Sequence
from pathlib import Path

from ...model import massprops
from ...project.loading import Loader, Outcome, Packages, Said, lines_of, without_colours

SOURCE = Path(__file__).with_name("kdl_tree.cpp")
HEADER = Path("/usr/include/kdl_parser/kdl_parser.hpp")
LIBRARIES = ["-lkdl_parser", "-lorocos-kdl", "-lurdfdom_model"]
TIMEOUT = 60.0


def missing() -> str | None:
    if shutil.which("g++") is None or not HEADER.exists():
        return "kdl_parser is not installed (its headers and a C++ compiler; Debian 12: apt install libkdl-parser-dev g++)"
    return None


def program() -> tuple[str | None, str]:
    """kdl_tree.cpp compiled (once per version of it), or None and why not."""
    source = SOURCE.read_bytes()
    folder = Path(tempfile.gettempdir()) / f"urdfcli-kdl-{os.getuid()}-{hashlib.sha256(source).hexdigest()[:12]}"
    built = folder / "kdl_tree"
    if built.exists():
        return str(built), ""
    folder.mkdir(mode=0o700, exist_ok=True)
    partial = folder / f"kdl_tree.{os.getpid()}"
    done = subprocess.run([shutil.which("g++") or "g++", "-std=c++17", str(SOURCE), "-o", str(partial), *LIBRARIES],
                          capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        return None, f"kdl_tree.cpp does not compile against kdl_parser: {done.stderr.strip()[:300]}"
    os.replace(partial, built)  # whole or not at all, whoever compiles it at the same time
    return str(built), ""


def load(paths: Sequence[str], variants: frozenset[str], packages: Packages) -> list[Outcome]:
    compiled, why = program()
    if compiled is None:
        return [Outcome(False, why)] * len(paths)
    return [_tree(compiled, path) for path in paths]


def _tree(compiled: str, path: str) -> Outcome:
    """The KDL tree kdl_parser builds: its segments (each link but the root) with their joint's
    kind and their mass and principal moments; ``printed`` holds kdl_parser's and urdfdom's messages."""
    done = subprocess.run([compiled, path], capture_output=True, text=True, timeout=TIMEOUT, errors="replace")
    said = without_colours(done.stderr)
    if done.returncode != 0 or not done.stdout.startswith("{"):
        return Outcome(False, f"kdl_tree exited with status {done.returncode}", said)
    answer = json.loads(done.stdout)
    if not answer["accepted"]:
        return Outcome(False, answer["error"], said)
    for segment in answer["segments"]:
        segment["inertia"] = _about_centre_of_mass(segment)
    return Outcome(True, "", said, {"root": answer["root"], "bodies": answer["segments"]})


def _about_centre_of_mass(segment: dict) -> list[float]:
    """KDL keeps a segment's tensor about its origin; the principal moments about its centre
    of mass (parallel axis theorem) are what a link's <inertia> declares."""
    about = tuple(tuple(segment["inertia"][3 * i: 3 * i + 3]) for i in range(3))
    return sorted(massprops.principal_moments(massprops.parallel_axis(about, -segment["mass"], tuple(segment["cog"]))))


def said(outcome: Outcome, path: str) -> list[Said]:
    """urdfdom's ``Error:`` lines and kdl_parser's warnings, as printed."""
    found = []
    for message in lines_of(outcome.printed, "warning", path):
        if message.text.startswith("Error"):
            found.append(message._replace(severity="error"))
        elif "warn" in message.text.lower() or "kdl" in message.text.lower():
            found.append(message)
    if not outcome.accepted and not any(s.severity == "error" for s in found):
        found.append(Said("error", outcome.error.strip()))
    return found


LOADER = Loader("kdl", missing, said, load=load)
