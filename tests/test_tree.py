"""urdfcli tree: every link and joint, check_urdf's order, the summary, and the JSON tree."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest
from conftest import FIXTURES, all_fixture_models, has_errors, require_tool, run_cli
from lxml import etree

BROKEN = {"seed000/broken_xacro_robot.urdf.xacro"}  # xacro cannot expand it
MODELS = [p for p in all_fixture_models() if p.relative_to(FIXTURES).as_posix() not in BROKEN]
IDS = [p.relative_to(FIXTURES).as_posix() for p in MODELS]
DOF = {"fixed": 0, "revolute": 1, "continuous": 1, "prismatic": 1, "planar": 3, "floating": 6}


def plain_urdf(path: Path, folder: Path) -> Path:
    """The fixture as plain URDF: xacro files expanded with `urdfcli expand`."""
    if not path.name.endswith(".xacro"):
        return path
    out = folder / (path.name.removesuffix(".xacro"))
    result = run_cli("expand", str(path), "-o", str(out))
    assert result.returncode == 0, result.stderr
    return out


def check_urdf_tree(path: Path) -> list[tuple[int, str]]:
    """(depth, link) in check_urdf's order, read from its output."""
    output = subprocess.run([require_tool("check_urdf"), str(path)], capture_output=True, text=True, check=True).stdout
    rows = [(0, re.search(r"root Link: (\S+)", output).group(1))]
    for line in output.splitlines():
        found = re.match(r"( +)child\(\d+\):  (.*)$", line)
        if found:
            rows.append((len(found.group(1)) // 4, found.group(2)))
    return rows


def xml_joints(path: Path) -> dict[str, etree._Element]:
    root = etree.parse(str(path)).getroot()
    return {j.get("name"): j for j in root.iterfind("joint")}


@pytest.mark.parametrize("path", MODELS, ids=IDS)
def test_links_in_check_urdf_order_with_every_joint(path, tmp_path, cli):
    urdf = plain_urdf(path, tmp_path)
    expected = check_urdf_tree(urdf)
    result = cli("tree", "--ascii", str(path))
    assert result.exit_code == (1 if has_errors(path) else 0), result.output  # the tree is shown all the same
    lines = result.stdout.splitlines()
    tree, summary = lines[:-1], lines[-1]
    assert len(tree) == len(expected)
    joints = xml_joints(urdf)
    for line, (depth, link) in zip(tree, expected):
        guide = re.match(r"(?:[|` ]   |[|`]-- )*", line).group(0)
        assert len(guide) // 4 == depth
        assert line[len(guide) :].startswith(link)
        if depth:
            name = line.split("  <- ")[1].split(" (")[0]
            assert joints[name].find("child").get("link") == link
            assert f"({joints[name].get('type')}" in line
    shown_joints = {line.split("  <- ")[1].split(" (")[0] for line in tree[1:]}
    assert shown_joints == set(joints)
    types = Counter(j.get("type") for j in joints.values())
    leaves = sum(1 for i, (d, _) in enumerate(expected) if i + 1 == len(expected) or expected[i + 1][0] <= d)
    assert f"{len(expected)} link" in summary
    assert f"{sum(types.values())} joint" in summary
    for joint_type, count in types.items():
        assert f"{count} {joint_type}" in summary
    free = [j.get("type") for j in joints.values() if j.find("mimic") is None]
    assert f"{sum(DOF[t] for t in free)} DOF" in summary
    assert f"depth {max(d for d, _ in expected)}" in summary
    assert f"{leaves} leaf link" in summary


@pytest.mark.parametrize("path", MODELS, ids=IDS)
def test_json_tree_matches_the_model(path, tmp_path, cli):
    urdf = plain_urdf(path, tmp_path)
    root = etree.parse(str(urdf)).getroot()
    joints = xml_joints(urdf)
    links = {link.get("name") for link in root.iterfind("link")}
    result = cli("tree", "--format", "json", str(path))
    assert result.exit_code == (1 if has_errors(path) else 0), result.output
    data = json.loads(result.stdout)
    assert data["robot"] == root.get("name")
    seen_links, seen_joints = [], []
    stack = [data["root"]]
    while stack:
        link = stack.pop()
        seen_links.append(link["name"])
        for child in link["children"]:
            joint, element = child["joint"], joints[child["joint"]["name"]]
            seen_joints.append(joint["name"])
            assert joint["parent"] == link["name"] == element.find("parent").get("link")
            assert joint["child"] == child["link"]["name"] == element.find("child").get("link")
            assert joint["type"] == element.get("type")
            origin = element.find("origin")
            xyz = [float(v) for v in origin.get("xyz", "0 0 0").split()] if origin is not None else [0.0] * 3
            assert joint["origin"]["xyz"] == xyz
            limit = element.find("limit")
            if limit is not None and limit.get("upper") is not None:
                assert joint["limit"]["upper"] == float(limit.get("upper"))
            stack.append(child["link"])
    assert sorted(seen_links) == sorted(links)
    assert sorted(seen_joints) == sorted(joints)
    assert data["summary"]["links"] == len(links)


CRANE = FIXTURES / "seed001" / "broken_inertia_crane.urdf"


def test_revolute_limits_in_radians_and_degrees(cli):
    result = cli("tree", str(CRANE))
    line = next(line for line in result.stdout.splitlines() if "joint_pivot" in line)
    assert "revolute, axis 0 0 1, -3.14…3.14 rad (-179.9…179.9°)" in line
    assert "10…100 m" in result.stdout  # prismatic joint_car


def test_max_depth_counts_what_it_hides(cli):
    result = cli("tree", "--max-depth", "1", "--ascii", str(CRANE))
    lines = result.stdout.splitlines()
    assert lines[0] == "base_link"
    assert lines[1].startswith("`-- shoulder_link_base  <- joint_pivot") and lines[1].endswith(".. 5 links below")
    assert lines[2].startswith("7 links, 6 joints")  # the summary still covers the whole tree
    data = json.loads(cli("tree", "--max-depth", "1", "-f", "json", str(CRANE)).stdout)
    assert data["root"]["children"][0]["link"] == {"name": "shoulder_link_base", "mass": 100.0, "hidden_links": 5, "children": []}


def test_from_link_shows_a_subtree(cli):
    result = cli("tree", "--from", "shoulder_link_right", "--no-joints", "--ascii", str(CRANE))
    assert result.stdout.splitlines() == [
        "shoulder_link_right",
        "|-- car_link",
        "|   `-- hook_link",
        "`-- shoulder_link_left",
        "4 links, 3 joints (1 fixed, 2 prismatic), 2 DOF, depth 2, 2 leaf links",
    ]


def test_unknown_from_link_is_exit_2_with_a_suggestion():
    result = run_cli("tree", "--from", "car_lnk", str(CRANE))
    assert result.returncode == 2
    assert result.stderr.decode().strip() == "urdfcli: no link named 'car_lnk' in robot 'crane_tower'; did you mean 'car_link' or 'base_link'?"


def test_ascii_output_is_ascii(cli):
    result = cli("tree", "--ascii", str(CRANE))
    assert result.stdout.isascii()
    assert "-3.14..3.14 rad (-179.9..179.9 deg)" in result.stdout


LOOPS = """<robot name="loops">
  <link name="a"/><link name="b"/><link name="c"/><link name="d"/>
  <joint name="ab" type="fixed"><parent link="a"/><child link="b"/></joint>
  <joint name="bc" type="revolute"><parent link="b"/><child link="c"/><limit effort="1" velocity="1"/></joint>
  <joint name="cb" type="fixed"><parent link="c"/><child link="b"/></joint>
  <joint name="ad" type="fixed"><parent link="a"/><child link="d"/></joint>
  <joint name="dc" type="fixed"><parent link="d"/><child link="c"/></joint>
</robot>"""


def test_loops_and_second_parents_end_and_fail(tmp_path):
    path = tmp_path / "loops.urdf"
    path.write_text(LOOPS)
    result = run_cli("tree", "--ascii", str(path))
    assert result.returncode == 1
    assert result.stdout.decode().splitlines() == [
        "a",
        "|-- b  <- ab (fixed)",
        "|   `-- c  <- bc (revolute, axis 1 0 0, 0..0 rad (0..0 deg))",
        "|       `-- b  <- cb (fixed)  (already shown above)",
        "`-- d  <- ad (fixed)",
        "    `-- c  <- dc (fixed)  (already shown above)",
        "4 links, 5 joints (4 fixed, 1 revolute), 1 DOF, depth 2, 0 leaf links",
    ]
    assert "T004 error" in result.stderr.decode() and "T003 error" in result.stderr.decode()


def test_a_link_with_two_parents_is_marked_where_it_comes_second(tmp_path):
    """'c' is reached by 'ac' (first by name) and, below 'b', by 'bc'. Shown depth
    first, 'b' comes before 'c' at the top level: 'c' under 'b' is shown first, so
    the mark belongs on the 'ac' row that follows it, not on the first."""
    path = tmp_path / "two_parents.urdf"
    path.write_text(
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"/><link name="d"/>'
        '<joint name="ab" type="fixed"><parent link="a"/><child link="b"/></joint>'
        '<joint name="ac" type="fixed"><parent link="a"/><child link="c"/></joint>'
        '<joint name="bc" type="fixed"><parent link="b"/><child link="c"/></joint>'
        '<joint name="cd" type="fixed"><parent link="c"/><child link="d"/></joint></robot>'
    )
    result = run_cli("tree", "--ascii", str(path))
    assert result.returncode == 1
    assert result.stdout.decode().splitlines()[:5] == [
        "a",
        "|-- b  <- ab (fixed)",
        "|   `-- c  <- bc (fixed)",
        "|       `-- d  <- cd (fixed)",
        "`-- c  <- ac (fixed)  (already shown above)",
    ]


def test_no_root_asks_for_from(tmp_path):
    path = tmp_path / "ring.urdf"
    path.write_text(
        '<robot name="ring"><link name="a"/><link name="b"/>'
        '<joint name="ab" type="fixed"><parent link="a"/><child link="b"/></joint>'
        '<joint name="ba" type="fixed"><parent link="b"/><child link="a"/></joint></robot>'
    )
    result = run_cli("tree", str(path))
    assert result.returncode == 1 and result.stdout == b""
    assert "choose one with --from LINK" in result.stderr.decode()
    assert run_cli("tree", "--from", "b", str(path)).stdout.decode().startswith("b\n└── a  ← ba (fixed)\n")


def test_bad_input_is_one_line_and_exit_2(tmp_path):
    result = run_cli("tree", str(tmp_path / "missing.urdf"))
    assert result.returncode == 2
    assert result.stderr.decode().count("\n") == 1 and "no such file" in result.stderr.decode()


def chain(n: int) -> str:
    links = "".join(f'<link name="l{i}"/>' for i in range(n))
    joints = "".join(
        f'<joint name="j{i}" type="continuous"><parent link="l{i - 1}"/><child link="l{i}"/></joint>' for i in range(1, n)
    )
    return f'<robot name="chain">{links}{joints}</robot>'


def test_a_deep_chain_serialises(tmp_path, cli):
    path = tmp_path / "chain.urdf"
    path.write_text(chain(3000))
    result = cli("tree", "-f", "json", str(path))
    assert result.exit_code == 0
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(50000)
    try:
        data = json.loads(result.stdout)
    finally:
        sys.setrecursionlimit(limit)
    assert data["summary"] == {"links": 3000, "joints": {"continuous": 2999}, "dof": 2999, "mimic_joints": 0, "depth": 2999, "leaf_links": 1}


def test_readme_shows_the_real_tree_of_the_bundled_example():
    readme = (FIXTURES.parent / "README.md").read_text(encoding="utf-8")
    command = "$ urdfcli tree fixtures/urdf02_gazebo/urdf/car.urdf.xacro\n"
    shown = readme.split(command, 1)[1].split("```", 1)[0]
    result = run_cli("tree", "fixtures/urdf02_gazebo/urdf/car.urdf.xacro", cwd=FIXTURES.parent)
    assert result.returncode == 0
    assert shown == result.stdout.decode()


def test_dof_leaves_out_mimic_joints_and_a_planar_joint_counts_three(tmp_path):
    links = "".join(f'<link name="{n}"/>' for n in "abcde")
    limit = '<limit effort="1" velocity="1" lower="-1" upper="1"/>'
    path = tmp_path / "gripper.urdf"
    path.write_text(
        f'<robot name="g">{links}'
        '<joint name="base" type="planar"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint>'
        f'<joint name="finger" type="prismatic"><parent link="b"/><child link="c"/>{limit}</joint>'
        f'<joint name="finger2" type="prismatic"><parent link="b"/><child link="d"/>{limit}<mimic joint="finger"/></joint>'
        f'<joint name="finger3" type="revolute"><parent link="b"/><child link="e"/>{limit}<mimic joint="finger" multiplier="2"/></joint>'
        "</robot>"
    )
    result = run_cli("tree", str(path))
    assert result.returncode == 0, result.stderr
    assert result.stdout.decode().splitlines()[-1].endswith("4 DOF (2 mimic joints follow others, not counted), depth 2, 3 leaf links")
    summary = json.loads(run_cli("tree", "--format", "json", str(path)).stdout)["summary"]
    assert (summary["dof"], summary["mimic_joints"]) == (4, 2)


def test_computed_limits_read_short_and_a_mimic_says_its_multiplier(tmp_path):
    """fanuc's lrmate200id: xacro writes ${radians(170)} as 2.9670597283903604, which the tree
    shows as 2.96706 (the degrees beside it exact); a value written short stays as written; the
    lever of a parallel linkage follows joint_3 with multiplier -1: shown, not just 'mimics'."""
    path = tmp_path / "arm.urdf"
    path.write_text(
        '<robot name="arm"><link name="base_link"/><link name="link_1"/><link name="lever"/>'
        '<joint name="joint_1" type="revolute"><parent link="base_link"/><child link="link_1"/><axis xyz="0 0 1"/>'
        '<limit lower="-2.9670597283903604" upper="1.57" effort="0" velocity="1"/></joint>'
        '<joint name="joint_lever" type="revolute"><parent link="base_link"/><child link="lever"/><axis xyz="0 1 0"/>'
        '<limit lower="-1" upper="1" effort="0" velocity="1"/><mimic joint="joint_1" multiplier="-1" offset="0.5"/></joint></robot>\n')
    out = run_cli("tree", str(path)).stdout.decode()
    assert "joint_1 (revolute, axis 0 0 1, -2.96706…1.57 rad (-170…89.95°))" in out
    assert "mimics joint_1 × -1 + 0.5)" in out
    assert "mimics joint_1 * -1 + 0.5)" in run_cli("tree", "--ascii", str(path)).stdout.decode()


def test_an_axis_written_with_negative_zeros_reads_without_them(tmp_path):
    """Denso's VS060 writes its axes as an exporter does: -0.000000 1.000000 -0.000000."""
    path = tmp_path / "arm.urdf"
    path.write_text(
        '<robot name="arm"><link name="base_link"/><link name="J1"/>'
        '<joint name="joint_1" type="revolute"><parent link="base_link"/><child link="J1"/><axis xyz="-0.000000 1.000000 -0.000000"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>\n')
    out = run_cli("tree", str(path)).stdout.decode()
    assert "joint_1 (revolute, axis 0 1 0, " in out, out
    dot = run_cli("graph", "--format", "dot", str(path)).stdout.decode()
    assert "axis 0 1 0" in dot and "-0" not in dot, dot


def test_an_origin_written_with_negative_zeros_is_drawn_without_them(tmp_path):
    """Techman's TM arms write their origins as their exporter does: rpy="0.000000 -0.000000 1.570796"."""
    path = tmp_path / "arm.urdf"
    path.write_text(
        '<robot name="arm"><link name="link_3"/><link name="link_4"/>'
        '<joint name="joint_4" type="revolute"><parent link="link_3"/><child link="link_4"/>'
        '<origin rpy="0.000000 -0.000000 1.570796" xyz="0.311500 -0.000000 -0.156300"/><axis xyz="0 0 1"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>\n')
    dot = run_cli("graph", "--format", "dot", str(path)).stdout.decode()
    assert "xyz: 0.3115 0 -0.1563\\nrpy: 0 0 1.570796" in dot, dot


def test_a_computed_small_limit_reads_short(tmp_path):
    """${1/30000} is 3.3333333333333335e-05 in xacro's output: its exponent does not keep all its digits."""
    path = tmp_path / "slide.urdf"
    path.write_text(
        '<robot name="slide"><link name="base_link"/><link name="carriage"/>'
        '<joint name="slide" type="prismatic"><parent link="base_link"/><child link="carriage"/><axis xyz="1 0 0"/>'
        f'<limit lower="0" upper="{1 / 30000!r}" effort="1" velocity="1"/></joint></robot>\n')
    out = run_cli("tree", str(path)).stdout.decode()
    assert "0…3.33333e-05 m" in out, out
