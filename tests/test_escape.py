"""No control or direction-changing character from an input reaches the terminal.

Names, messages and source excerpts carry C0 and C1 controls, DEL, ESC/OSC
sequences and bidirectional overrides; every text output shows them as
visible escapes, and leaves printable text in any script alone.
"""

from __future__ import annotations

import re
import unicodedata

import pytest
from conftest import run_cli
from differential import check_urdf

from urdfcli.report.escape import escape

C1_CSI, DEL, RLO, LRI, RLM = "\x9b", "\x7f", "\u202e", "\u2066", "\u200f"
NAMES = (
    '<robot name="evil&#x202e;bot">'
    '<link name="base&#x9b;31m"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>'
    '<link name="arm&#x202e;txt.exe&#x7f;&#10;x"/>'
    '<joint name="j&#x2066;oint&#x200f;&#9;1" type="revolute"><parent link="base&#x9b;31m"/><child link="arm&#x202e;txt.exe&#x7f;&#10;x"/>'
    '<limit effort="1" velocity="1" lower="-1" upper="1"/></joint>'
    "</robot>"
)
MISSING = '<robot name="r"><link name="a"/><joint name="j" type="fixed"><parent link="a"/><child link="b&#x9b;2J&#x202e;"/></joint></robot>'
ESC_OSC = b"\x1b[31mRED\x1b]0;pwned\x07 not xml\n"


def unsafe(text: str) -> list[str]:
    """Characters a terminal would act on or that reorder text; the line breaks are the output's own."""
    return sorted({c for c in text if c != "\n" and (unicodedata.category(c) in ("Cc", "Cf") or not c.isprintable())})


@pytest.fixture
def inputs(tmp_path):
    (tmp_path / "names.urdf").write_text(NAMES, encoding="utf-8")
    (tmp_path / "missing.urdf").write_text(MISSING, encoding="utf-8")
    (tmp_path / "esc.urdf").write_bytes(ESC_OSC)
    (tmp_path / "binary.urdf").write_bytes(bytes(range(256)) * 4)
    return tmp_path


RUNS = [
    ("check", "names.urdf"),
    ("check", "missing.urdf"),
    ("check", "esc.urdf"),
    ("check", "binary.urdf"),
    ("check", "--format", "concise", "missing.urdf"),
    ("check", "--format", "check_urdf", "names.urdf"),
    ("check", "--format", "check_urdf", "missing.urdf"),
    ("check", "--format", "github", "missing.urdf"),
    ("check", "--color", "always", "missing.urdf"),
    ("check", "--format", "json", "missing.urdf"),
    ("lint", "--format", "sarif", "names.urdf"),
    ("lint", "names.urdf"),
    ("lint", "esc.urdf"),
    ("lint", "--format", "concise", "missing.urdf"),
    ("tree", "names.urdf"),
    ("tree", "--ascii", "names.urdf"),
    ("tree", "--color", "always", "names.urdf"),
    ("graph", "--format", "dot", "names.urdf"),
    ("graph", "--format", "dot", "--compat", "names.urdf"),
    ("graph", "--format", "dot", "--collapse-fixed", "--inertial", "names.urdf"),
    ("inertia", "names.urdf"),
    ("expand", "esc.urdf"),
]


@pytest.mark.parametrize("args", RUNS, ids=" ".join)
def test_no_control_character_reaches_the_output(inputs, args):
    done = run_cli(*args[:-1], str(inputs / args[-1]))
    for stream in (done.stdout, done.stderr):
        text = stream.decode("utf-8")
        if "--color" in args:  # our own styles are the only escape sequences
            text = re.sub(r"\x1b\[[0-9;]*m", "", text)
        assert unsafe(text) == [], text


def test_the_escapes_show_what_was_there(inputs):
    names = run_cli("tree", str(inputs / "names.urdf")).stdout.decode()
    assert "base\\x9b31m" in names and "arm\\u202etxt.exe\\x7f\\nx" in names and "j\\u2066oint\\u200f\\t1" in names
    dot = run_cli("graph", "--format", "dot", str(inputs / "names.urdf")).stdout.decode()
    assert 'label="base\\\\x9b31m' in dot and "evil\\\\u202ebot" in dot
    compat = run_cli("graph", "--format", "dot", "--compat", str(inputs / "names.urdf")).stdout.decode()
    assert '"base\\x9b31m" [label="base\\x9b31m"];' in compat
    missing = run_cli("check", str(inputs / "missing.urdf")).stderr.decode()
    assert "'b\\x9b2J\\u202e'" in missing
    esc = run_cli("check", str(inputs / "esc.urdf")).stderr.decode()
    assert "\\x1b[31mRED\\x1b]0;pwned\\x07 not xml" in esc
    lint = run_cli("lint", str(inputs / "names.urdf")).stdout.decode()  # lint reports on standard output
    assert "arm\\u202etxt.exe\\x7f\\nx" in lint  # I002 names the massless moving link


def test_graph_names_its_files_after_the_robot_without_control_characters(inputs):
    done = run_cli("graph", "-f", "dot", str(inputs / "names.urdf"), cwd=inputs)  # the model draws
    assert done.returncode == 0
    written = run_cli("graph", str(inputs / "names.urdf"), cwd=inputs)
    assert written.returncode in (0, 2)  # 2: dot refused the picture; the .gv is written either way
    assert (inputs / "evil\\u202ebot.gv").exists()


def test_json_keeps_the_data_and_escapes_it_as_json(inputs):
    import json

    done = run_cli("check", "--format", "json", str(inputs / "names.urdf"))
    assert "\\u202e" in done.stdout.decode()
    assert json.loads(done.stdout)["files"][0]["robot"] == "evil\u202ebot"


def test_the_caret_stays_under_the_column_after_escapes(inputs):
    path = inputs / "caret.urdf"
    path.write_text('<robot name="r"><link name="\u202e\u202e"/><link name="a"/></robot>\n', encoding="utf-8")
    lines = run_cli("check", str(path)).stderr.decode().splitlines()
    assert lines[0].startswith(f"{path}:1:34: T001 error")  # two links without a parent: at the second one
    source = next(i for i, line in enumerate(lines) if line.lstrip().startswith("1 |"))
    assert lines[source][lines[source + 1].index("^") :].startswith('<link name="a"/>')


def test_printable_text_in_any_script_is_left_alone():
    assert escape("bras_é 関節 ülink ω") == "bras_é 関節 ülink ω"
    assert escape("a\x1bb\x85c\u202ed\u2069e\nf\x00") == "a\\x1bb\\x85c\\u202ed\\u2069e\\nf\\x00"


def test_check_urdf_format_is_still_check_urdfs_output_for_non_ascii_names(tmp_path):
    path = tmp_path / "unicode.urdf"
    path.write_text('<robot name="роботы"><link name="基座"/><link name="bras_é"/>'
                    '<joint name="j" type="fixed"><parent link="基座"/><child link="bras_é"/></joint></robot>', encoding="utf-8")
    real = check_urdf(path)
    assert real.returncode == 0
    assert run_cli("check", "--format", "check_urdf", str(path)).stdout.decode() == real.stdout
