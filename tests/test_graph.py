"""urdfcli graph: the real urdf_to_graphviz's DOT with --compat, and rendered PDF, SVG and PNG."""

from __future__ import annotations

import html
import random
import shutil
import subprocess
from pathlib import Path

import pytest
from conftest import FIXTURES, all_fixture_models, has_errors, require_tool, run_cli
from lxml import etree
from test_tree import IDS, MODELS, plain_urdf

CAR = FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"
CRANE = FIXTURES / "seed001" / "broken_inertia_crane.urdf"


def real_urdf_to_graphviz(urdf: Path, folder: Path) -> subprocess.CompletedProcess:
    folder.mkdir(exist_ok=True)
    return subprocess.run([require_tool("urdf_to_graphviz"), str(urdf), "real"], capture_output=True, text=True, cwd=folder)


@pytest.mark.parametrize("path", all_fixture_models(), ids=lambda p: p.relative_to(FIXTURES).as_posix())
def test_compat_is_urdf_to_graphviz(path, tmp_path):
    require_tool("dot")
    if path.name.endswith(".xacro"):
        expanded = run_cli("expand", str(path), "-o", str(tmp_path / "expanded.urdf"))
        if expanded.returncode != 0:  # urdf_to_graphviz cannot read what xacro cannot expand
            mine = run_cli("graph", "--compat", str(path), "mine", cwd=tmp_path)
            assert mine.returncode == 1 and not (tmp_path / "mine.gv").exists()
            return
    real = real_urdf_to_graphviz(plain_urdf(path, tmp_path), tmp_path / "real")
    assert real.returncode == 0, real.stderr
    mine = run_cli("graph", "--compat", str(path), "mine", cwd=tmp_path)
    assert mine.returncode == (1 if has_errors(path) else 0), mine.stderr  # errors urdfdom does not check: still drawn
    assert mine.stdout.decode() == "Created file mine.gv\nCreated file mine.pdf\n"
    real_lines = (tmp_path / "real" / "real.gv").read_text().splitlines()
    mine_lines = (tmp_path / "mine.gv").read_text().splitlines()
    assert sorted(mine_lines) == sorted(real_lines)
    assert mine_lines == real_lines  # the same order too
    assert pdf_pages(tmp_path / "mine.pdf") >= 1


NUMBERS = ["1e-7", "123456789", "-0", "0.30000000000000004", "1e300", "-1e-300", "999999.5", "0.000123456789", "1234567", "-2.5e-5"]
ANGLES = [
    "0 0 0",
    "-0 -0 -0",
    "1.5707963267948966 0 0",
    "0 1.5707963267948966 0",
    "0 -1.5707963267948966 0",
    "0 1.5663 0",  # just inside getRPY's gimbal threshold
    "0 1.5664 0",  # just outside it
    "3.141592653589793 3.141592653589793 3.141592653589793",
    "0 0 -3.141592653589793",
    "10 20 30",
    "1e-7 1e-7 1e-7",
]


def crafted_robot() -> str:
    """Origins with numbers that C++ streams print in every notation, and angles near gimbal lock."""
    rng = random.Random(7)
    angles = ANGLES + [" ".join(repr(rng.uniform(-7, 7)) for _ in range(3)) for _ in range(100)]
    parts = ['<robot name="crafted">', '<link name="root"/>']
    for i, rpy in enumerate(angles):
        xyz = " ".join(NUMBERS[(i * k + k) % len(NUMBERS)] for k in (1, 3, 7))
        parts.append(
            f'<link name="l{i}"/><joint name="j{i:03d}" type="fixed"><parent link="root"/><child link="l{i}"/>'
            f'<origin xyz="{xyz}" rpy="{rpy}"/></joint>'
        )
    return "\n".join(parts + ["</robot>"])


def test_compat_numbers_are_cpp_stream_numbers(tmp_path):
    path = tmp_path / "crafted.urdf"
    path.write_text(crafted_robot())
    real = real_urdf_to_graphviz(path, tmp_path / "real")
    assert real.returncode == 0, real.stderr
    real_text = (tmp_path / "real" / "real.gv").read_text()
    for line in (
        '"root" -> "j000" [label="xyz: 1.23457e+08 0.3 0.000123457 \\nrpy: 0 -0 0"]',
        '"root" -> "j001" [label="xyz: -0 1e+06 1e+300 \\nrpy: -0 -0 -0"]',
        '"root" -> "j005" [label="xyz: 1e+06 1.23457e+06 -0 \\nrpy: 0 1.5663 0"]',
        '"root" -> "j006" [label="xyz: 0.000123457 1.23457e+08 -2.5e-05 \\nrpy: 0 1.5708 -0"]',
        '"root" -> "j009" [label="xyz: 1e-07 1e-07 1e-07 \\nrpy: -2.56637 1.15044 -1.41593"]',
    ):
        assert line in real_text.splitlines()
    mine = run_cli("graph", "--compat", "--format", "dot", str(path))
    assert mine.returncode == 0, mine.stderr
    assert mine.stdout.decode() == real_text


def test_cpp_number_examples():
    from urdfcli.report.drawing import cpp_number

    assert [cpp_number(v) for v in (1e-7, 123456789.0, -0.0, 0.1 + 0.2, 100000.0, 1000000.0, 0.0001, 0.00001)] == [
        "1e-07", "1.23457e+08", "-0", "0.3", "100000", "1e+06", "0.0001", "1e-05",
    ]


def pdf_pages(path: Path) -> int:
    info = subprocess.run([require_tool("pdfinfo"), str(path)], capture_output=True, text=True, check=True).stdout
    return int(next(line.split()[1] for line in info.splitlines() if line.startswith("Pages:")))


def test_default_writes_robot_name_gv_and_pdf(tmp_path):
    require_tool("dot")
    result = run_cli("graph", str(CAR), cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.decode() == "Created file mycar.gv\nCreated file mycar.pdf\n"
    assert pdf_pages(tmp_path / "mycar.pdf") >= 1
    subprocess.run([require_tool("pdftoppm"), "-png", "-r", "50", "-f", "1", "-l", "1", "-singlefile", "mycar.pdf", "page"], cwd=tmp_path, check=True)
    png = (tmp_path / "page.png").read_bytes()
    assert png.startswith(b"\x89PNG") and len(png) > 1000
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mycar.gv", "mycar.pdf", "page.png"]  # no temporary files left


def svg_texts(svg: bytes) -> str:
    root = etree.fromstring(svg)
    return "\n".join(html.unescape(t) for t in root.itertext())


@pytest.mark.parametrize("path", MODELS, ids=IDS)
def test_svg_shows_every_link(path, tmp_path):
    require_tool("dot")
    out = tmp_path / "graph.svg"
    result = run_cli("graph", str(path), "-o", str(out), "--limits", "--inertial")
    assert result.returncode == (1 if has_errors(path) else 0), result.stderr
    text = svg_texts(out.read_bytes())
    root = etree.parse(str(plain_urdf(path, tmp_path))).getroot()
    for link in root.iterfind("link"):
        assert link.get("name") in text
    for joint in root.iterfind("joint"):
        assert joint.get("name") in text and joint.get("type") in text


ODD_NAMES = """<?xml version="1.0" encoding="utf-8"?>
<robot name="odd &quot;robot&quot; \\ 1">
  <link name="base link"/>
  <link name="quo&quot;ted"/>
  <link name="back\\slash\\"/>
  <link name="ünïcødé_腕"/>
  <link name="brace{}[];-&gt;"/>
  <joint name="j &quot;1&quot;" type="revolute"><parent link="base link"/><child link="quo&quot;ted"/><limit lower="-1.5" upper="1.5" effort="10" velocity="2"/></joint>
  <joint name="j\\2" type="prismatic"><parent link="base link"/><child link="back\\slash\\"/><limit upper="0.5" effort="10" velocity="2"/></joint>
  <joint name="関節" type="planar"><parent link="quo&quot;ted"/><child link="ünïcødé_腕"/><origin rpy="0 0 1.5708"/></joint>
  <joint name="float" type="floating"><parent link="base link"/><child link="brace{}[];-&gt;"/></joint>
</robot>
"""


def test_names_with_quotes_backslashes_spaces_and_unicode_render(tmp_path):
    require_tool("dot")
    path = tmp_path / "odd.urdf"
    path.write_text(ODD_NAMES, encoding="utf-8")
    out = tmp_path / "odd.svg"
    result = run_cli("graph", str(path), "-o", str(out), "--limits")
    assert result.returncode == 0, result.stderr
    text = svg_texts(out.read_bytes())
    for name in ('odd "robot" \\ 1', "base link", 'quo"ted', "back\\slash\\", "ünïcødé_腕", "brace{}[];->", 'j "1"', "j\\2", "関節"):
        assert name in text.splitlines(), name
    assert "effort 10 N·m" in text and "0…0.5 m" in text


def test_default_style_colours_types_and_shows_origins():
    result = run_cli("graph", "--format", "dot", str(CRANE))
    assert result.returncode == 0, result.stderr
    dot = result.stdout.decode()
    assert '"joint:joint_pivot" [label="joint_pivot\\nrevolute\\naxis 0 0 1", color="#1f77b4", fontcolor="#1f77b4"];' in dot
    assert '"joint:joint_car" [label="joint_car\\nprismatic\\naxis -1 0 0", color="#ff7f0e"' in dot
    assert '"link:shoulder_link_right" -> "joint:joint_car" [color="#ff7f0e", label="xyz: 10 0 -0.5\\nrpy: 0 0 3.14159"];' in dot
    legend = next(line for line in dot.splitlines() if line.startswith('"legend"'))
    assert [t for t in ("fixed", "revolute", "continuous", "prismatic") if f">{t}</font>" in legend] == ["fixed", "revolute", "prismatic"]
    assert "rankdir=TB" in dot and "mass" not in dot and "effort" not in dot


def test_limits_inertial_rankdir_options():
    dot = run_cli("graph", "-f", "dot", "--limits", "--inertial", "--rankdir", "LR", str(CRANE)).stdout.decode()
    assert "rankdir=LR" in dot
    assert '"link:base_link" [label="base_link\\nmass 900000 kg"];' in dot
    assert "-3.14…3.14 rad (-179.9…179.9°)\\neffort 1000 N·m\\nvelocity 2 rad/s" in dot


def test_numbers_read_as_written_or_to_6_digits_as_the_tree_shows_them(tmp_path):
    """Kinova's j2s6s200: joint 5 sits at z -0.10375, which 4 digits drew as -0.1037, half a
    millimetre off. Numbers are drawn as the tree shows them: as written up to 7 significant
    digits, else to 6 (what xacro computed)."""
    model = tmp_path / "arm.urdf"
    model.write_text(
        '<robot name="arm"><link name="base"><inertial><mass value="0.46784"/>'
        '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link><link name="tip"/>'
        '<joint name="j5" type="revolute"><parent link="base"/><child link="tip"/>'
        '<origin xyz="0 0.0016 -0.10375" rpy="-1.5707963267948966 0 3.141592653589793"/><axis xyz="0 0 1"/>'
        '<limit lower="0.5235987755982988" upper="5.759586531581287" effort="6.8" velocity="0.9843656"/></joint></robot>')
    done = run_cli("graph", str(model), "--limits", "--inertial", "-o", "arm.gv", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    dot = (tmp_path / "arm.gv").read_text()
    assert '[color="#1f77b4", label="xyz: 0 0.0016 -0.10375\\nrpy: -1.5708 0 3.14159"];' in dot
    assert '"link:base" [label="base\\nmass 0.46784 kg"];' in dot
    assert "0.523599…5.75959 rad (30…330°)\\neffort 6.8 N·m\\nvelocity 0.9843656 rad/s" in dot


def test_collapse_fixed_merges_fixed_chains():
    dot = run_cli("graph", "-f", "dot", "--collapse-fixed", "--inertial", str(CAR)).stdout.decode()
    link_nodes = [line for line in dot.splitlines() if line.startswith('"link:') and "->" not in line]
    assert len(link_nodes) == 5  # base_footprint with its fixed children, and four wheels
    assert link_nodes[0].startswith('"link:base_footprint" [label="base_footprint\\nno inertial\\n+ base_link\\n+ camera\\n+ support\\n+ laser')
    assert "fixed" not in dot.split('"legend"')[0]


def test_output_extension_chooses_the_format(tmp_path):
    require_tool("dot")
    for name, magic in (("g.pdf", b"%PDF"), ("g.svg", b"<?xml"), ("g.png", b"\x89PNG"), ("g.gv", b"digraph"), ("g.dot", b"digraph")):
        result = run_cli("graph", str(CRANE), "-o", str(tmp_path / name))
        assert result.returncode == 0, result.stderr
        assert (tmp_path / name).read_bytes().startswith(magic), name
    assert sorted(p.name for p in tmp_path.iterdir()) == ["g.dot", "g.gv", "g.pdf", "g.png", "g.svg"]
    bad = run_cli("graph", str(CRANE), "-o", str(tmp_path / "g.jpeg"))
    assert bad.returncode == 2 and b"unknown extension" in bad.stderr


def without_dot(tmp_path: Path) -> dict:
    """An environment whose PATH has no `dot` (an empty folder)."""
    empty = tmp_path / "empty-bin"
    empty.mkdir(exist_ok=True)
    return {"PATH": str(empty)}


def test_missing_dot_is_exit_2_and_keeps_the_dot_file(tmp_path):
    folder = tmp_path / "out"
    folder.mkdir()
    result = run_cli("graph", str(CAR), cwd=folder, env=without_dot(tmp_path))
    assert result.returncode == 2
    assert result.stdout.decode() == "Created file mycar.gv\n"
    stderr = result.stderr.decode()
    assert stderr.count("\n") == 1 and "'dot' was not found" in stderr and "apt-get install graphviz" in stderr
    assert (folder / "mycar.gv").read_text().startswith('digraph "mycar" {')
    assert sorted(p.name for p in folder.iterdir()) == ["mycar.gv"]
    single = run_cli("graph", str(CAR), "-o", "car.svg", cwd=folder, env=without_dot(tmp_path))
    assert single.returncode == 2 and "the graph is in car.gv" in single.stderr.decode()
    assert sorted(p.name for p in folder.iterdir()) == ["car.gv", "mycar.gv"]
    dot_only = run_cli("graph", str(CAR), "-o", "car.dot", cwd=folder, env=without_dot(tmp_path))
    assert dot_only.returncode == 0  # DOT needs no Graphviz


def generated_robot(n: int, seed: int = 3) -> str:
    rng = random.Random(seed)
    types = ["fixed", "revolute", "continuous", "prismatic"]
    parts = ['<robot name="generated">', '<link name="link0"/>']
    for i in range(1, n):
        kind = types[i % 4]
        limit = '<limit lower="-1" upper="1" effort="1" velocity="1"/>' if kind in ("revolute", "prismatic") else ""
        parts.append(
            f'<link name="link{i}"/><joint name="joint{i}" type="{kind}"><parent link="link{rng.randrange(max(0, i - 5), i)}"/>'
            f'<child link="link{i}"/><origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>{limit}</joint>'
        )
    return "\n".join(parts + ["</robot>"])


def test_a_1000_link_model_renders(tmp_path):
    require_tool("dot")
    path = tmp_path / "big.urdf"
    path.write_text(generated_robot(1000))
    result = run_cli("graph", str(path), "big", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert pdf_pages(tmp_path / "big.pdf") >= 1
    assert (tmp_path / "big.gv").read_text().count('[label="link') == 1000


def test_rendering_has_a_time_limit(tmp_path):
    require_tool("dot")
    path = tmp_path / "huge.urdf"
    path.write_text(generated_robot(4000))
    result = run_cli("graph", str(path), "-o", "huge.pdf", "--timeout", "1", cwd=tmp_path)
    assert result.returncode == 2
    assert "dot took longer than 1 s" in result.stderr.decode()
    assert (tmp_path / "huge.gv").exists() and not (tmp_path / "huge.pdf").exists()


def test_never_overwrites_the_input(tmp_path):
    path = tmp_path / "model.gv"
    shutil.copy(CRANE, path)
    before = path.read_bytes()
    result = run_cli("graph", str(path), "-o", str(path))
    assert result.returncode == 2 and b"refusing to overwrite the input file" in result.stderr
    assert path.read_bytes() == before
    named = run_cli("graph", str(path), "model", cwd=tmp_path)  # OUT.gv would be the input
    assert named.returncode == 2 and path.read_bytes() == before


def test_a_model_with_errors_writes_nothing(tmp_path):
    path = tmp_path / "bad.urdf"
    path.write_text('<robot name="bad"><link name="a"/><joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>')
    result = run_cli("graph", str(path), cwd=tmp_path)
    assert result.returncode == 1
    assert "J005 error" in result.stderr.decode()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.urdf"]


LIMIT = '<limit effort="1" velocity="1" lower="-1" upper="1"/>'
CHECK_ERRORS = (  # errors only check's rules find: a zero axis (J007), a mimic of a missing joint (J008)
    '<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
    f'<joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 0"/>{LIMIT}</joint>'
    f'<joint name="k" type="revolute"><parent link="a"/><child link="c"/>{LIMIT}<mimic joint="nope"/></joint></robot>'
)


def error_lines(stderr: bytes) -> list[str]:
    """The diagnostics and their details, without check's summary line."""
    return [line for line in stderr.decode().splitlines() if "file checked" not in line and "files checked" not in line]


@pytest.mark.parametrize("command", [("tree",), ("tree", "--format", "json"), ("graph", "--format", "dot"), ("graph",)])
def test_tree_and_graph_report_checks_errors_as_check_does(tmp_path, command):
    path = tmp_path / "r.urdf"
    path.write_text(CHECK_ERRORS)
    check = run_cli("check", str(path), cwd=tmp_path)
    assert check.returncode == 1 and "J007 error" in check.stderr.decode() and "J008 error" in check.stderr.decode()
    done = run_cli(*command, str(path), cwd=tmp_path)
    assert done.returncode == 1
    assert error_lines(done.stderr) == error_lines(check.stderr)
    if command[0] == "graph":  # urdfdom reads it, so urdf_to_graphviz draws it: so does graph
        drawn = done.stdout.decode().startswith('digraph "r"') if "dot" in command else (tmp_path / "r.pdf").exists()
        assert drawn


REJECTED = (  # urdfdom rejects a revolute joint without <limit>: urdf_to_graphviz draws nothing
    '<robot name="r"><link name="a"/><link name="b"/>'
    '<joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint></robot>'
)


def test_graph_of_a_model_urdfdom_rejects_is_drawn_only_with_force(tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(REJECTED)
    for compat in ([], ["--compat"]):
        refused = run_cli("graph", *compat, str(path), cwd=tmp_path)
        assert refused.returncode == 1 and "J003 error" in refused.stderr.decode()
        assert refused.stdout == b"" and sorted(p.name for p in tmp_path.iterdir()) == ["r.urdf"]


def test_graph_force_draws_a_model_with_errors_and_still_exits_1(tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(REJECTED)
    dot = run_cli("graph", "--force", "--format", "dot", str(path), cwd=tmp_path)
    assert dot.returncode == 1 and dot.stdout.decode().startswith('digraph "r"') and "J003 error" in dot.stderr.decode()
    files = run_cli("graph", "--force", str(path), "out", cwd=tmp_path)
    assert files.returncode == 1 and (tmp_path / "out.gv").exists()
    assert "--force" in run_cli("graph", "--help", env={"COLUMNS": "200"}).stdout.decode()


def test_format_dot_prints_and_writes_nothing(tmp_path):
    result = run_cli("graph", "--compat", "--format", "dot", str(CRANE), cwd=tmp_path)
    assert result.returncode == 0
    assert result.stdout.decode().startswith("digraph G {\nnode [shape=box];\n")
    assert list(tmp_path.iterdir()) == []
    clash = run_cli("graph", "--format", "dot", "-o", "x.pdf", str(CRANE), cwd=tmp_path)
    assert clash.returncode == 2


def test_readme_example_picture_is_committed():
    readme = (FIXTURES.parent / "README.md").read_text(encoding="utf-8")
    assert "(docs/images/crane_graph.png)" in readme
    png = (FIXTURES.parent / "docs" / "images" / "crane_graph.png").read_bytes()
    assert png.startswith(b"\x89PNG") and len(png) > 10000


def test_compat_draws_what_urdf_to_graphviz_draws_when_urdfdom_misses_the_errors(tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(CHECK_ERRORS)
    real = real_urdf_to_graphviz(path, tmp_path / "real")
    assert real.returncode == 0, real.stderr  # urdfdom checks neither a zero axis nor a mimic's joint
    mine = run_cli("graph", "--compat", "--format", "dot", str(path))
    assert mine.returncode == 1 and "J007 error" in mine.stderr.decode() and "J008 error" in mine.stderr.decode()
    assert mine.stdout.decode() == (tmp_path / "real" / "real.gv").read_text()
    rejected = tmp_path / "rejected.urdf"
    rejected.write_text(REJECTED)
    assert real_urdf_to_graphviz(rejected, tmp_path / "refused").returncode != 0


def test_a_mimic_joint_says_what_it_follows_as_the_tree_does(tmp_path):
    """ABB's irb6640: joint_cylinder follows joint_2; drawn as a plain revolute joint, it
    looked like a joint of its own to command."""
    path = tmp_path / "r.urdf"
    path.write_text(
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
        '<joint name="joint_2" type="revolute"><parent link="a"/><child link="b"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        '<joint name="joint_cylinder" type="revolute"><parent link="a"/><child link="c"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'
        '<mimic joint="joint_2" multiplier="-0.25" offset="0.1"/></joint></robot>'
    )
    dot = run_cli("graph", "-f", "dot", str(path)).stdout.decode()
    assert '[label="joint_cylinder\\nrevolute\\naxis 1 0 0\\nmimics joint_2 × -0.25 + 0.1"' in dot
    assert '[label="joint_2\\nrevolute\\naxis 1 0 0", ' in dot
    assert "mimics joint_2 × -0.25 + 0.1" in run_cli("tree", str(path)).stdout.decode()
