"""Every rule's documented Example is flagged with its code; its Use instead is not.

The examples in the documentation are the test table: each is written into a
small ROS package (``my_robot``, with ``urdf/arm.xacro`` and real meshes: ``meshes/arm.stl``,
a 0.1 x 0.1 x 0.4 m box, and its variants from tests/support/meshes.py) and linted with
every rule selected.
"""

from __future__ import annotations

import re

import pytest
from conftest import lint_file
from support.meshes import example_package

from urdfcli.model.srdf import SRDF_TAGS
from urdfcli.targets import profile
from urdfcli.project.config import Config
from urdfcli.rules import REGISTRY, example_code
from urdfcli.rules import srdf as srdf_rules

ROBOT_CHILDREN = {"link", "joint", "material", "gazebo", "transmission"}
# X006 is about a library and the models of its repository that include it: its Example and
# Use instead are a pyproject.toml, tested in tests/test_workspace.py. P001 is about a package.xml
# and the files of its package: tested in tests/test_xacro_sources.py. X110 compares a URDF with the xacro file
# beside it that generated it: tested in tests/test_drift.py.
NEEDS_A_REPOSITORY = {"X006", "P001", "X110"}
# C001-C004 report what a consumer said on a real load (check --target NAME --load): tests/test_targets.py.
NEEDS_A_LOAD = {"C001", "C002", "C003", "C004"}
RULES = sorted((r for r in REGISTRY.values() if r.code not in NEEDS_A_REPOSITORY | NEEDS_A_LOAD), key=lambda r: r.code)


def first_tag(snippet: str) -> str:
    without_comments = re.sub(r"<!--.*?-->", "", snippet, flags=re.DOTALL)
    match = re.search(r"<([A-Za-z_][\w:.-]*)", without_comments)
    return match.group(1) if match else ""


def materialise(snippet: str, package) -> str:
    """The snippet as a file in the package; fragments are wrapped in a <robot>. An SRDF
    (MoveIt's) is written to config/example.srdf, beside the URDF of its robot."""
    if any(f"<{tag}" in snippet for tag in SRDF_TAGS):
        (package / "urdf" / "example.urdf").write_text(srdf_rules.URDF + "\n", encoding="utf-8")
        path = package / "config" / "example.srdf"
        path.parent.mkdir(exist_ok=True)
        path.write_text(snippet, encoding="utf-8")
        return str(path)
    if first_tag(snippet) in ROBOT_CHILDREN:
        snippet = f'<robot name="example">\n{snippet}\n</robot>\n'
    name = "example.urdf.xacro" if "xacro:" in snippet else "example.urdf"
    path = package / "urdf" / name
    path.write_text(snippet, encoding="utf-8")
    return str(path)


@pytest.fixture
def package(tmp_path):
    root = tmp_path / "my_robot"
    (root / "meshes").mkdir(parents=True)
    (root / "urdf").mkdir()
    (root / "package.xml").write_text('<package format="2"><name>my_robot</name></package>\n')
    example_package(root)
    (root / "urdf" / "arm.xacro").write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro"/>\n')
    return root


def codes(path: str, target: str | None = None) -> list[str]:
    """What every rule finds; a target rule's examples are linted for its target (--target)."""
    config = Config.everything()
    if target is not None:
        config = config._replace(targets=(profile(target),))
    return [d.code for d in lint_file(path, config).diagnostics]


@pytest.mark.parametrize("rule", RULES, ids=lambda r: r.code)
def test_example_is_flagged_and_use_instead_is_clean(rule, package, monkeypatch):
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    sections = rule.sections()
    bad, good = example_code(sections.get("Example", "")), example_code(sections.get("Use instead", ""))
    assert bad and good, f"{rule.code} needs an xml code block in Example and in Use instead"
    assert rule.code in codes(materialise(bad, package), rule.target), f"{rule.code}'s Example is not flagged"
    assert rule.code not in codes(materialise(good, package), rule.target), f"{rule.code}'s Use instead is flagged"
