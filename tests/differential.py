"""Running the real tools (check_urdf, xacro) on the same inputs as urdfcli."""

from __future__ import annotations

import json
import os
import random
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from conftest import FIXTURES, ROOT, require_tool
from lxml import etree

SUPPORT = ROOT / "tests" / "support"
PACKAGES = {"urdf01_rviz": str(FIXTURES / "urdf01_rviz"), "urdf02_gazebo": str(FIXTURES / "urdf02_gazebo")}


@dataclass
class ToolRun:
    returncode: int | None  # None: did not finish in time
    stdout: str
    stderr: str

    @property
    def rejects(self) -> bool:
        """check_urdf's verdict: an exit status other than 0, or any 'Error:' line it logged."""
        return self.returncode != 0 or any(line.startswith("Error:") for line in self.stderr.splitlines())


def check_urdf(path: Path, timeout: float = 10) -> ToolRun:
    tool = require_tool("check_urdf")
    try:
        done = subprocess.run([tool, str(path)], capture_output=True, text=True, timeout=timeout, errors="replace")
    except subprocess.TimeoutExpired:
        return ToolRun(None, "", "")
    return ToolRun(done.returncode, done.stdout, done.stderr)


def real_xacro(path: Path, *args: str, cwd: Path | None = None, packages: dict[str, str] = PACKAGES) -> subprocess.CompletedProcess:
    """The xacro CLI from PyPI, with $(find) answered from ``packages`` (name -> folder)."""
    tool = require_tool("xacro")
    env = {**os.environ, "PYTHONPATH": str(SUPPORT), "URDFCLI_TEST_PACKAGES": json.dumps(packages)}
    return subprocess.run([tool, str(path), *args], capture_output=True, text=True, env=env, cwd=cwd, timeout=60)


def expanded_fixture(path: Path, out_dir: Path) -> Path:
    """A fixture as plain URDF: xacro files expanded by the real xacro tool."""
    if not path.name.endswith(".xacro"):
        return path
    done = real_xacro(path)
    assert done.returncode == 0, done.stderr
    out = out_dir / (path.name.removesuffix(".xacro"))
    out.write_text(done.stdout)
    return out


def canonical(xml_text: str) -> list:
    """A comparable form of an XML document: elements, attributes, text; no comments or layout."""
    root = etree.fromstring(xml_text.encode(), etree.XMLParser(remove_comments=True, remove_blank_text=True))
    out = []
    for element in root.iter(etree.Element):
        out.append((element.tag, sorted(element.attrib.items()), (element.text or "").strip(), len(element)))
    return out


# -- mutation ------------------------------------------------------------------------
NUMBER_CORRUPTIONS = ["x", "", "nan", "inf", "1e999", "1 ", "0x10", "1,5", "+1", ".5", "-0", "1e-400", "--1"]
VECTOR_CORRUPTIONS = ["1 2", "1 2 3 4", "", "1\t2\t3", "1 x 3", "  1  2  3 ", "nan 0 0"]
NUMERIC_ATTRIBUTES = {"value", "ixx", "ixy", "ixz", "iyy", "iyz", "izz", "radius", "length", "effort", "velocity", "lower", "upper", "damping", "friction", "multiplier", "offset", "k_velocity"}
VECTOR_ATTRIBUTES = {"xyz", "rpy", "size", "scale", "rgba"}


def mutate(text: str, rng: random.Random) -> tuple[str, str]:
    """One random defect in a URDF document; returns (new text, what was done)."""
    root = etree.fromstring(text.encode())
    elements = list(root.iter(etree.Element))
    kind = rng.choice(["drop-attribute", "corrupt-number", "corrupt-vector", "duplicate-name", "break-reference", "drop-element", "rename-tag", "change-type", "swap-parent", "duplicate-element"])
    what = kind
    if kind == "drop-attribute":
        candidates = [e for e in elements if e.attrib]
        element = rng.choice(candidates)
        attribute = rng.choice(sorted(element.attrib))
        del element.attrib[attribute]
        what = f"drop {element.tag}@{attribute}"
    elif kind in ("corrupt-number", "corrupt-vector"):
        names = NUMERIC_ATTRIBUTES if kind == "corrupt-number" else VECTOR_ATTRIBUTES
        candidates = [(e, a) for e in elements for a in e.attrib if a in names]
        if candidates:
            element, attribute = rng.choice(candidates)
            value = rng.choice(NUMBER_CORRUPTIONS if kind == "corrupt-number" else VECTOR_CORRUPTIONS)
            element.set(attribute, value)
            what = f"{element.tag}@{attribute}={value!r}"
    elif kind == "duplicate-name":
        groups: dict[str, list] = {}
        for e in root:
            if e.tag in ("link", "joint", "material") and e.get("name"):
                groups.setdefault(e.tag, []).append(e)
        groups = {tag: group for tag, group in groups.items() if len(group) >= 2}
        if groups:
            a, b = rng.sample(groups[rng.choice(sorted(groups))], 2)
            b.set("name", a.get("name"))
            what = f"duplicate {b.tag} name {a.get('name')!r}"
    elif kind == "break-reference":
        refs = [e for e in elements if e.tag in ("parent", "child") and e.get("link")]
        if refs:
            element = rng.choice(refs)
            element.set("link", element.get("link") + "_typo")
            what = f"{element.tag} link typo"
    elif kind == "drop-element":
        candidates = [e for e in elements if e.getparent() is not None]
        element = rng.choice(candidates)
        element.getparent().remove(element)
        what = f"drop <{element.tag}>"
    elif kind == "rename-tag":
        element = rng.choice([e for e in elements if e.getparent() is not None])
        element.tag = rng.choice(["metrial", "box", "cone", "origin", "limit", "robot"])
        what = f"rename to <{element.tag}>"
    elif kind == "change-type":
        joints = [e for e in elements if e.tag == "joint"]
        if joints:
            joint = rng.choice(joints)
            joint.set("type", rng.choice(["revolute", "prismatic", "continuous", "fixed", "floating", "planar", "ball", ""]))
            what = f"joint type {joint.get('type')!r}"
    elif kind == "swap-parent":
        joints = [e for e in elements if e.tag == "joint" and e.find("parent") is not None and e.find("child") is not None]
        if joints:
            joint = rng.choice(joints)
            parent, child = joint.find("parent"), joint.find("child")
            p, c = parent.get("link"), child.get("link")
            if p is not None and c is not None:
                parent.set("link", c)
                child.set("link", p)
            what = "swap parent and child"
    elif kind == "duplicate-element":
        element = rng.choice([e for e in elements if e.getparent() is not None])
        element.getparent().append(etree.fromstring(etree.tostring(element)))
        what = f"duplicate <{element.tag}>"
    return etree.tostring(root, encoding="unicode"), what


def urdfcli_json(path: Path) -> dict:
    done = subprocess.run([sys.executable, "-m", "urdfcli", "check", "--format", "json", str(path)], capture_output=True, text=True, timeout=60)
    assert "Traceback" not in done.stderr, done.stderr
    return json.loads(done.stdout)
