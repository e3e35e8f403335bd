"""Every warning and error `urdfcli lint` reports on the 69 published models of
example-robot-data, against a reviewed snapshot: tests/snapshots/example-robot-data.txt.

Any change to what the rules say on real robots shows up in review as a diff of
that file. After reviewing the change, write the new snapshot with

    URDFCLI_UPDATE_SNAPSHOTS=1 pytest tests/test_corpus.py

The models come from the installed `example-robot-data` distribution (a test
dependency), found through its metadata. Their meshes are named
`package://example-robot-data/...`, the folder the distribution installs (and
registers in its ament index), while its package.xml says
`example_robot_descriptions`: the run names that folder with `-P`, as a ROS or
Pinocchio user's package path does, so the meshes resolve. Lines are
`MODEL:LINE: CODE severity: message` with paths relative to the robots folder
and in a stable order, so that the snapshot is the same on every machine.
"""

from __future__ import annotations

import difflib
import json
import os
from pathlib import Path

import pytest
from conftest import ROOT, example_robot_data, run_cli

SNAPSHOT = ROOT / "tests" / "snapshots" / "example-robot-data.txt"
UPDATE = os.environ.get("URDFCLI_UPDATE_SNAPSHOTS", "") not in ("", "0")
HEADER = """\
# Every warning and error of `urdfcli lint` (default rules) on example-robot-data 6.0.0.
# Reviewed: a diff here is a change in what urdfcli says about published robots.
# Regenerate after review: URDFCLI_UPDATE_SNAPSHOTS=1 pytest tests/test_corpus.py
"""
SHOWN = ("error", "warning")


def lint_lines(package: Path, config: Path) -> list[str]:
    robots = package / "robots"
    models = sorted(p.relative_to(robots).as_posix() for p in robots.rglob("*.urdf"))
    env = {key: value for key, value in os.environ.items() if key not in ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH")}
    done = run_cli(
        "lint", "--config", str(config), "--format", "json", "--jobs", "2",
        "-P", f"example-robot-data={package}", *models, cwd=robots, env=env,
    )
    assert done.returncode in (0, 1), done.stderr.decode()
    report = json.loads(done.stdout)
    assert len(report["files"]) == len(models) == 69
    lines = []
    for file in report["files"]:
        for d in file["diagnostics"]:
            if d["severity"] in SHOWN:
                lines.append((file["path"], d.get("line") or 0, d.get("column") or 0, d["code"], f"{d['path']}:{d.get('line') or 0}: {d['code']} {d['severity']}: {d['message']}"))
    lines.sort()
    # the package folder appears in a few messages (where packages were looked for)
    return [line[-1].replace(str(package), "example-robot-data") for line in lines]


def test_corpus_matches_the_reviewed_snapshot(tmp_path):
    package = example_robot_data()
    config = tmp_path / "urdfcli.toml"
    config.write_text("")  # default rules, whatever configuration surrounds the installed package
    text = HEADER + "".join(line + "\n" for line in lint_lines(package, config))
    if UPDATE:
        SNAPSHOT.parent.mkdir(parents=True, exist_ok=True)
        SNAPSHOT.write_text(text, encoding="utf-8")
        return
    reviewed = SNAPSHOT.read_text(encoding="utf-8") if SNAPSHOT.exists() else ""
    if text != reviewed:
        diff = list(difflib.unified_diff(reviewed.splitlines(), text.splitlines(), "reviewed snapshot", "urdfcli now", lineterm="", n=0))
        shown = diff[:200] + ([f"... and {len(diff) - 200} more diff lines"] if len(diff) > 200 else [])
        pytest.fail(
            "urdfcli's findings on example-robot-data changed; review them, then run\n"
            "URDFCLI_UPDATE_SNAPSHOTS=1 pytest tests/test_corpus.py\n\n" + "\n".join(shown),
            pytrace=False,
        )
