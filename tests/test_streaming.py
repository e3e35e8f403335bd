"""A small document is parsed whole, a large one streamed: both read the same model
and report the same problems, where they are."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import all_fixture_models, example_robot_data, load
from test_malformed import MALFORMED

from urdfcli.options import RuleSet
from urdfcli.read import xml


def readings(path: Path, monkeypatch) -> list:
    """What a load reports on ``path``, and the links and joints it read: read whole,
    and streamed."""
    found = []
    for whole_up_to in (xml.WHOLE_UP_TO, 0):
        monkeypatch.setattr(xml, "WHOLE_UP_TO", whole_up_to)
        result = load(str(path), RuleSet.LINT)
        robot = result.robot
        model = (robot.links, robot.joints, robot.materials, robot.resources, list(result.loaded.document.tops)) if robot else None
        found.append(([(d.code, d.line, d.location.column, d.message, d.element) for d in result.diagnostics], model))
    return found


@pytest.mark.parametrize("name", sorted(MALFORMED))
def test_malformed_documents_read_alike(tmp_path, monkeypatch, name):
    path = tmp_path / "robot.urdf"
    path.write_bytes(MALFORMED[name][0])
    whole, streamed = readings(path, monkeypatch)
    assert whole == streamed


def test_fixture_models_read_alike(monkeypatch):
    """Plain and xacro (their expansion is read): every fixture model."""
    for path in all_fixture_models():
        whole, streamed = readings(path, monkeypatch)
        assert whole == streamed, path.name


def test_published_models_read_alike(monkeypatch):
    paths = sorted((example_robot_data() / "robots").rglob("*.urdf"))
    assert len(paths) > 60
    assert all(path.stat().st_size <= xml.WHOLE_UP_TO for path in paths)  # read whole by default
    for path in paths:
        whole, streamed = readings(path, monkeypatch)
        assert whole == streamed, path.name


def test_a_kept_block_holds_only_itself(tmp_path, monkeypatch):
    """The blocks the model keeps (<gazebo>...) are out of the document's tree: with
    many files checked at once, each keeps its block, not its whole document."""
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r"><link name="a"/><gazebo reference="a"><mu1>1</mu1></gazebo><link name="b"/></robot>')
    for whole_up_to in (xml.WHOLE_UP_TO, 0):
        monkeypatch.setattr(xml, "WHOLE_UP_TO", whole_up_to)
        (block,) = load(str(path), RuleSet.TREE).robot.extensions
        assert block.tag == "gazebo"
        assert block.getparent() is None
