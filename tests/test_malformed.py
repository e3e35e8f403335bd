"""Malformed, huge and unreadable input: a short message naming the file, the documented exit code.

Exit codes: 0 no errors, 1 the input has errors (malformed XML included),
2 the command could not run (missing or unreadable file, bad option,
internal error). Never a traceback, never a partial output file.
"""

from __future__ import annotations

import errno
import json
import os
import random
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
from conftest import run_cli

ONE_LINK = '<robot name="r"><link name="a"/></robot>'


def write(folder: Path, name: str, data: str | bytes) -> Path:
    path = folder / name
    path.write_bytes(data.encode() if isinstance(data, str) else data)
    return path


MODEL_COMMANDS = ["check", "lint", "tree", "inertia", ("graph", "--format", "dot")]


def run(cli, command, path: Path):
    args = list(command) if isinstance(command, tuple) else [command]
    return cli(*args, str(path))


def no_traceback(result) -> None:
    assert "Traceback" not in result.stdout + result.stderr


MALFORMED = {
    "empty": (b"", 1, "the document is empty"),
    "only-white-space": (b"  \n\t\n", 1, "the document is empty"),
    "binary-garbage": (random.Random(6).randbytes(4096), 1, "X001 error"),
    "truncated-in-a-tag": (b'<robot name="r"><link name="a"/><lin', 1, "X001 error"),
    "truncated-in-an-attribute": (b'<robot name="r', 1, "X001 error"),
    "truncated-before-the-end-tag": (b'<robot name="r">\n<link name="a"/>\n', 3, "X001 error"),
    "unknown-encoding": (b'<?xml version="1.0" encoding="bogus-8"?>' + ONE_LINK.encode(), 1, "unknown encoding 'bogus-8' in the XML declaration"),
    "not-in-the-declared-encoding": (b'<?xml version="1.0" encoding="windows_1252"?>\n<robot name="r\x81"/>', 2, "byte 0x81 is not windows_1252"),
    "declared-utf16-is-utf8": (b'<?xml version="1.0" encoding="UTF-16"?>' + ONE_LINK.encode(), 1, "X001 error"),
    "declared-utf8-is-latin1": ('<robot name="r\xe9"><link name="a"/></robot>'.encode("latin-1"), 1, "X001 error"),
    "nul-in-attribute": (b'<robot name="r"><link name="a\x00b"/></robot>', 1, "X001 error"),
    "nul-after-root": (ONE_LINK.encode() + b"\x00\x00", 1, "X001 error"),
    "nul-only": (b"\x00" * 64, 1, "X001 error"),
    # xacro markup without the xacro namespace: libxml2 says which prefix, the message says the declaration
    "undeclared-xacro-prefix": (b'<robot name="r">\n  <xacro:property name="l" value="1"/>\n  <link name="a"/>\n</robot>', 2,
                                "<xacro:property> uses the prefix 'xacro', declared nowhere: declare xmlns:xacro=\"http://www.ros.org/wiki/xacro\""),
    # a merge git could not finish, committed as it was: the first marker's line, and what it is
    "merge-conflict": (b'<robot name="r">\n  <link name="a"/>\n<<<<<<< HEAD\n  <link name="b"/>\n=======\n  <link name="c"/>\n>>>>>>> arm\n</robot>\n',
                       3, "an unresolved merge conflict: git's conflict markers"),
    "nesting-deeper-than-libxml2-allows": (b'<robot name="r">' + b"<a>" * 300 + b"</a>" * 300 + b"</robot>", 1, "X001 error"),
}


@pytest.mark.parametrize("data, line, message", MALFORMED.values(), ids=MALFORMED.keys())
def test_malformed_xml_is_one_error_with_file_and_line(cli, tmp_path, data, line, message):
    path = write(tmp_path, "bad.urdf", data)
    result = cli("check", str(path))
    assert result.exit_code == 1
    first = result.stderr.splitlines()[0]
    assert first.startswith(f"{path}:{line}:")
    assert "X001 error" in first and message in first
    assert len(first) < 300
    no_traceback(result)


@pytest.mark.parametrize("command", MODEL_COMMANDS)
@pytest.mark.parametrize("name", ["empty", "binary-garbage", "truncated-in-a-tag", "nul-in-attribute", "declared-utf8-is-latin1"])
def test_malformed_xml_in_every_subcommand(cli, tmp_path, command, name):
    data, line, _ = MALFORMED[name]
    path = write(tmp_path, "bad.urdf", data)
    result = run(cli, command, path)
    assert result.exit_code == 1
    assert f"{path}:{line}:" in result.stderr + result.stdout
    no_traceback(result)


@pytest.mark.parametrize(
    "data",
    [
        b"\xef\xbb\xbf" + b'<?xml version="1.0" encoding="UTF-8"?>\n<robot name="r\xc3\xb4bot"><link name="a"/></robot>',
        '<?xml version="1.0" encoding="ISO-8859-1"?>\n<robot name="r\xf4bot"><link name="a"/></robot>'.encode("latin-1"),
        '<?xml version="1.0" encoding="UTF-16"?>\n<robot name="r\xf4bot"><link name="a"/></robot>'.encode("utf-16"),
    ],
    ids=["utf8-bom", "latin1-declared", "utf16-with-bom"],
)
def test_byte_order_marks_and_declared_encodings_are_accepted(cli, tmp_path, data):
    path = write(tmp_path, "ok.urdf", data)
    result = cli("check", "--format", "json", str(path))
    assert result.exit_code == 0
    assert json.loads(result.stdout)["files"][0]["robot"] == "r\xf4bot"


ENCODINGS = ["latin-1", "latin1", "ISO-8859-1", "iso-8859-15", "cp1252", "windows-1252", "windows_1252", "mac-roman", "utf-16", "koi8-r"]


@pytest.mark.parametrize("encoding", ENCODINGS)
def test_every_encoding_python_reads_is_read(tmp_path, encoding):
    name = "\u0440\u043e\u0431\u043e\u0442" if encoding == "koi8-r" else "r\xf4bot"
    text = f'<?xml version="1.0" encoding="{encoding}"?>\n<robot name="{name}"><link name="a"/></robot>\n'
    path = write(tmp_path, "ok.urdf", text.encode(encoding))
    result = run_cli("check", "--format", "json", str(path))
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["files"][0]["robot"] == name


@pytest.mark.parametrize("encoding", ["latin-1", "ISO-8859-1", "cp1252"])
def test_declared_encodings_are_read_as_check_urdf_reads_them(tmp_path, encoding):
    """check_urdf reads these files (names in ASCII, the comment not): same verdict, same output."""
    from differential import check_urdf

    text = (f'<?xml version="1.0" encoding="{encoding}"?>\n<!-- Gr\xfc\xdfe, \xe9t\xe9 -->\n'
            '<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>\n')
    path = write(tmp_path, "ok.urdf", text.encode(encoding))
    real = check_urdf(path)
    assert not real.rejects
    mine = run_cli("check", "--format", "check_urdf", str(path))
    assert mine.returncode == 0 and mine.stdout.decode() == real.stdout


def numbers_robot(mass: str, xyz: str) -> str:
    return (
        '<robot name="r"><link name="a"/><link name="b"><inertial>'
        f'<mass value="{mass}"/><inertia ixx="1" ixy="-0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>'
        f'<joint name="j" type="revolute"><parent link="a"/><child link="b"/><origin xyz="{xyz}"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>'
    )


@pytest.mark.parametrize(
    "mass, xyz, code, message",
    [
        ("1e999", "0 0 0", "V002", "mass value: '1e999' overflows a double"),
        ("-1e999", "0 0 0", "V002", "'-1e999' overflows a double"),
        ("nan", "0 0 0", "V002", "'nan' is not a finite number"),
        ("1", "inf 0 0", "V002", "'inf' is not a finite number"),
        ("1", "0 NaN 0", "V002", "'NaN' is not a finite number"),
        ("0x10", "0 0 0", "V001", "'0x10' is not a number"),
        ("1", "1e-400 0 0", None, None),  # underflows to 0: a valid double
        ("-0", "-0 -0 -0", None, None),
    ],
)
def test_absurd_numbers(cli, tmp_path, mass, xyz, code, message):
    path = write(tmp_path, "numbers.urdf", numbers_robot(mass, xyz))
    result = cli("check", str(path))
    no_traceback(result)
    if code is None:
        assert result.exit_code == 0
        assert " error" not in result.stderr.replace("0 errors", "")
        return
    assert result.exit_code == 1
    assert f"{path}:1:" in result.stderr
    assert f"{code} error" in result.stderr and message in result.stderr


@pytest.mark.parametrize("command", MODEL_COMMANDS)
def test_absurd_numbers_in_every_subcommand(cli, tmp_path, command):
    for mass, xyz in (("1e999", "nan 0 0"), ("-0", "-0 1e-400 0"), ("1e308", "1e308 1e308 1e308")):
        path = write(tmp_path, "numbers.urdf", numbers_robot(mass, xyz))
        result = run(cli, command, path)
        assert result.exit_code in (0, 1)
        no_traceback(result)


def test_megabyte_long_attributes(cli, tmp_path):
    name = "a" * 3_000_000
    long_name = write(tmp_path, "long_name.urdf", f'<robot name="r"><link name="{name}"/></robot>')
    started = time.monotonic()
    result = cli("check", str(long_name))
    assert time.monotonic() - started < 10
    assert result.exit_code == 0
    no_traceback(result)

    size = " ".join(["1"] * 1_000_000)
    long_vector = write(tmp_path, "long_vector.urdf", f'<robot name="r"><link name="a"><visual><geometry><box size="{size}"/></geometry></visual></link></robot>')
    result = cli("check", str(long_vector))
    assert result.exit_code == 1
    line = next(line for line in result.stderr.splitlines() if "V003" in line)
    assert line.startswith(f"{long_vector}:1:")
    assert "has 1000000 components, 3 expected" in line and "(1999999 characters)" in line
    assert len(line) < 400
    assert len(result.stderr) < 5000


def wide_model(links: int) -> str:
    joints = (
        f'<link name="l{i}"/><joint name="j{i}" type="fixed"><parent link="l0"/><child link="l{i}"/></joint>' for i in range(1, links)
    )
    return '<robot name="wide"><link name="l0"/>' + "".join(joints) + "</robot>"


def chain_model(links: int) -> str:
    joints = (
        f'<link name="l{i}"/><joint name="j{i}" type="continuous"><parent link="l{i - 1}"/><child link="l{i}"/>'
        '<axis xyz="0 0 1"/></joint>'
        for i in range(1, links)
    )
    return '<robot name="chain"><link name="l0"/>' + "".join(joints) + "</robot>"


@pytest.fixture(scope="module")
def huge(tmp_path_factory) -> dict[str, Path]:
    folder = tmp_path_factory.mktemp("huge")
    return {"wide": write(folder, "wide.urdf", wide_model(100_000)), "chain": write(folder, "chain.urdf", chain_model(20_000))}


@pytest.mark.parametrize(
    "model, children, last",
    [("wide", 99_999, "    child(99999):  l99999"), ("chain", 1, " " * 4 * 19_999 + "child(1):  l19999")],
    ids=["100000-links", "20000-deep-chain"],
)
def test_huge_models_are_checked_without_recursion(cli, huge, model, children, last):
    started = time.monotonic()
    result = cli("check", "--format", "check_urdf", str(huge[model]))
    assert time.monotonic() - started < 60
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    assert lines[2] == f"root Link: l0 has {children} child(ren)"
    assert len(lines) == {"wide": 3 + 99_999, "chain": 3 + 19_999}[model]
    assert lines[-1] == last


@pytest.mark.parametrize("model, depth", [("wide", 1), ("chain", 19_999)])
def test_tree_prints_huge_models(cli, huge, model, depth):
    started = time.monotonic()
    result = cli("tree", "--format", "json", str(huge[model]))
    assert time.monotonic() - started < 60
    assert result.exit_code == 0
    assert "l19999" in result.stdout
    no_traceback(result)


@pytest.mark.parametrize("command", [c for c in MODEL_COMMANDS if c not in ("check", "tree")])
def test_other_subcommands_survive_a_deep_chain(cli, huge, command):
    started = time.monotonic()
    result = run(cli, command, huge["chain"])
    assert time.monotonic() - started < 120
    assert result.exit_code in (0, 1)
    no_traceback(result)


# -- files that cannot be read: exit 2, one line ---------------------------------------
def cli_lines(result) -> list[str]:
    return [line for line in result.stderr.splitlines() if line.startswith("urdfcli:")]


def test_missing_file(cli, tmp_path):
    missing = tmp_path / "missing.urdf"
    result = cli("check", str(missing))
    assert result.exit_code == 2
    assert cli_lines(result) == [f"urdfcli: {missing}: no such file"]
    no_traceback(result)


def test_directory_given_as_a_file(cli, tmp_path):
    result = cli("check", str(tmp_path))
    assert result.exit_code == 2
    assert cli_lines(result) == [f"urdfcli: {tmp_path}: no robot model in this folder (*.urdf, *.urdf.xacro, *.srdf, or a *.xacro file that makes a robot)"]


@pytest.mark.parametrize("command", ["tree", "inertia", "expand"])
def test_missing_file_and_directory_in_other_subcommands(cli, tmp_path, command):
    for path, message in ((tmp_path / "missing.urdf", "no such file"), (tmp_path, "is a directory, not a file")):
        result = cli(command, str(path))
        assert result.exit_code == 2
        assert cli_lines(result) == [f"urdfcli: {path}: {message}"]


def test_unreadable_file(tmp_path):
    """chmod 000. Root reads it anyway, so as root the run drops the capabilities that allow it."""
    folder = tmp_path / "shared"
    folder.mkdir()
    path = write(folder, "secret.urdf", ONE_LINK)
    path.chmod(0)
    command = [sys.executable, "-m", "urdfcli", "check", str(path)]
    if os.geteuid() == 0:
        setpriv = shutil.which("setpriv")
        if setpriv is None:
            pytest.skip("running as root, and setpriv (util-linux) is missing to drop the read-any-file capability")
        dropped = "-dac_override,-dac_read_search"
        command = [setpriv, f"--inh-caps={dropped}", f"--bounding-set={dropped}", *command]
    result = subprocess.run(command, capture_output=True, text=True, timeout=60, env={**os.environ, "NO_COLOR": "1"})
    assert result.returncode == 2
    assert [line for line in result.stderr.splitlines() if line.startswith("urdfcli:")] == [f"urdfcli: {path}: permission denied"]
    assert "Traceback" not in result.stderr


@pytest.mark.parametrize("command", ["check", "expand", "tree", "graph", "inertia", "lint"])
def test_unknown_option_is_one_line_exit_2(tmp_path, command):
    path = write(tmp_path, "ok.urdf", ONE_LINK)
    result = run_cli(command, "--no-such-option", str(path))
    assert result.returncode == 2
    assert result.stderr.decode() == f"urdfcli: No such option: --no-such-option (see 'urdfcli {command} -h')\n"
    assert result.stdout == b""


def test_unknown_subcommand_and_missing_argument_are_one_line_exit_2():
    result = run_cli("no-such-command")
    assert result.returncode == 2
    assert result.stderr.decode() == "urdfcli: No such command 'no-such-command'. (see 'urdfcli -h')\n"
    result = run_cli("check")
    assert result.returncode == 2
    assert len(result.stderr.decode().splitlines()) == 1 and "Missing argument" in result.stderr.decode()


def run_main(monkeypatch, capsys, *args: str) -> tuple[int, str]:
    from urdfcli.cli import main

    code = main(list(args))
    return code, capsys.readouterr().err


def test_an_internal_error_is_one_line_asking_for_a_bug_report(monkeypatch, capsys, tmp_path):
    import urdfcli.model.load

    def broken(*args, **kwargs):
        raise ZeroDivisionError("division by zero\nwith a second line")

    monkeypatch.setattr(urdfcli.model.load, "read", broken)
    monkeypatch.delenv("URDFCLI_DEBUG", raising=False)
    path = write(tmp_path, "ok.urdf", ONE_LINK)
    code, err = run_main(monkeypatch, capsys, "check", str(path))
    assert code == 2
    assert err.count("\n") == 1
    assert err.startswith("urdfcli: internal error (ZeroDivisionError: division by zero with a second line) on check ")
    assert str(path) in err and "please report this bug" in err and "URDFCLI_DEBUG=1" in err
    assert "Traceback" not in err


def test_urdfcli_debug_shows_the_traceback(monkeypatch, tmp_path):
    """With URDFCLI_DEBUG=1, the real process prints the traceback of an internal error."""
    path = write(tmp_path, "ok.urdf", ONE_LINK)
    program = (
        "import sys, urdfcli.model.load\n"
        "def broken(*a, **k): raise ZeroDivisionError('boom')\n"
        "urdfcli.model.load.read = broken\n"
        "from urdfcli.cli import main\n"
        f"sys.exit(main(['check', {str(path)!r}]))\n"
    )
    for debug, traceback in (("1", True), ("", False)):
        result = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, timeout=60, env={**os.environ, "URDFCLI_DEBUG": debug})
        assert ("Traceback" in result.stderr) is traceback
        assert "ZeroDivisionError" in result.stderr
        assert result.returncode == (1 if traceback else 2)


# -- outputs: atomic, never over an input ---------------------------------------------------
XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
GOOD_XACRO = f'<robot {XACRO} name="r"><xacro:property name="n" value="a"/><link name="${{n}}"/></robot>'
BAD_XACRO = f'<robot {XACRO} name="r"><link name="${{undefined_name}}"/></robot>'


def leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


def test_expand_failure_leaves_no_file(cli, tmp_path):
    bad = write(tmp_path, "bad.urdf.xacro", BAD_XACRO)
    out = tmp_path / "out.urdf"
    result = cli("expand", str(bad), "-o", str(out))
    assert result.exit_code == 1
    assert not out.exists()
    assert leftovers(tmp_path) == []


def test_expand_failure_keeps_the_previous_good_output(cli, tmp_path):
    good = write(tmp_path, "good.urdf.xacro", GOOD_XACRO)
    out = tmp_path / "out.urdf"
    assert cli("expand", str(good), "-o", str(out)).exit_code == 0
    before = out.read_bytes()
    assert b'<link name="a"/>' in before
    good.write_text(BAD_XACRO)
    assert cli("expand", str(good), "-o", str(out)).exit_code == 1
    assert out.read_bytes() == before
    assert leftovers(tmp_path) == []


def test_expand_write_error_keeps_the_previous_output_and_no_temporary_file(cli, tmp_path, monkeypatch):
    good = write(tmp_path, "good.urdf.xacro", GOOD_XACRO)
    out = write(tmp_path, "out.urdf", "previous good output")

    def disk_full(*args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(os, "replace", disk_full)
    result = cli("expand", str(good), "-o", str(out))
    assert result.exit_code == 2
    assert cli_lines(result) == [f"urdfcli: {out}: cannot write: No space left on device"]
    assert out.read_text() == "previous good output"
    assert leftovers(tmp_path) == []


def test_output_equal_to_an_input_is_refused(cli, tmp_path):
    main = write(tmp_path, "robot.urdf.xacro", f'<robot {XACRO} name="r"><xacro:include filename="part.xacro"/></robot>')
    part = write(tmp_path, "part.xacro", f'<robot {XACRO}><link name="a"/></robot>')
    link = tmp_path / "alias.urdf.xacro"
    link.symlink_to(main)
    for out, victim in ((main, main), (link, main), (part, part), (Path(os.path.relpath(main)), main)):
        before = victim.read_bytes()
        result = cli("expand", str(main), "-o", str(out))
        assert result.exit_code == 2, out
        assert cli_lines(result) == [f"urdfcli: {out}: refusing to overwrite the input file"]
        assert victim.read_bytes() == before
    assert leftovers(tmp_path) == []


def test_graph_failure_leaves_no_file_and_keeps_the_previous_output(cli, tmp_path):
    good = write(tmp_path, "robot.urdf", '<robot name="r"><link name="a"/><link name="b"/>'
                 '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>')
    out = tmp_path / "graph.gv"
    assert cli("graph", str(good), "-o", str(out)).exit_code == 0
    before = out.read_bytes()
    assert b'"a"' in before
    good.write_text('<robot name="r"><link name="a"/><lin')
    result = cli("graph", str(good), "-o", str(out))
    assert result.exit_code == 1
    assert out.read_bytes() == before
    fresh = tmp_path / "fresh.gv"
    assert cli("graph", str(good), "-o", str(fresh)).exit_code == 1
    assert not fresh.exists()
    assert leftovers(tmp_path) == []


def test_graph_output_equal_to_the_input_is_refused(cli, tmp_path):
    path = write(tmp_path, "robot.gv", ONE_LINK)
    result = cli("graph", str(path), "-o", str(path))
    assert result.exit_code in (1, 2)
    assert path.read_text() == ONE_LINK


# -- many files: each gets its verdict, the exit code is the worst ----------------------------
def test_one_broken_file_does_not_stop_the_others(cli, tmp_path):
    first = write(tmp_path, "first.urdf", ONE_LINK)
    broken = write(tmp_path, "broken.urdf", b"\x00garbage")
    last = write(tmp_path, "last.urdf", ONE_LINK.replace('"r"', '"last"'))
    result = cli("check", "--format", "json", str(first), str(broken), str(last))
    assert result.exit_code == 1
    files = json.loads(result.stdout)["files"]
    assert [(f["path"], f["ok"]) for f in files] == [(str(first), True), (str(broken), False), (str(last), True)]
    assert files[2]["robot"] == "last"


def test_exit_code_is_the_worst_of_all_files(cli, tmp_path):
    good = write(tmp_path, "good.urdf", ONE_LINK)
    broken = write(tmp_path, "broken.urdf", "<robot")
    missing = tmp_path / "missing.urdf"
    assert cli("check", str(good), str(good)).exit_code == 0
    assert cli("check", str(good), str(broken)).exit_code == 1
    result = cli("check", str(missing), str(broken), str(good))
    assert result.exit_code == 2
    assert f"urdfcli: {missing}: no such file" in result.stderr
    assert f"{broken}:1:" in result.stderr
    assert "robot name is: r" in result.stdout


def test_lint_reports_every_file_and_the_worst_exit_code(cli, tmp_path):
    good = write(tmp_path, "good.urdf", ONE_LINK)
    broken = write(tmp_path, "broken.urdf", "<robot")
    missing = tmp_path / "missing.urdf"
    result = cli("lint", str(missing), str(broken), str(good))
    assert result.exit_code == 2
    assert f"{broken}:1:" in result.stderr + result.stdout
    no_traceback(result)


@pytest.mark.parametrize("where", ["main", "included"])
def test_a_name_lxml_accepts_but_xacro_refuses(cli, tmp_path, where):
    """U+FEFF is a name character for libxml2 (XML 1.0 5th edition) but not for xacro's expat."""
    odd = f'<robot {XACRO} name="r">\n<link\ufeffx name="a"/>\n</robot>'
    if where == "main":
        path = write(tmp_path, "odd.urdf.xacro", odd)
        located = f"{path}:2:"
    else:
        write(tmp_path, "odd.xacro", odd)
        path = write(tmp_path, "main.urdf.xacro", f'<robot {XACRO} name="r"><xacro:include filename="odd.xacro"/></robot>')
        located = "odd.xacro:2:"
    result = cli("check", str(path))
    assert result.exit_code == 1
    assert located in result.stderr
    assert "X001 error: xacro cannot read this document: not well-formed (invalid token)" in result.stderr
    no_traceback(result)


# `--` inside a comment: XML forbids it, urdfdom (tinyxml2) and MoveIt read the comment on to
# the next `-->`. A mistyped end (`--!>`) is found in published MoveIt configurations.
HYPHENATED = '<?xml version="1.0"?>\n<robot name="r">\n  <!-- <link name="old"/> --!>\n  <link name="a"/>\n  <!-- ends here -->\n  <link name="b"/>\n</robot>\n'


def test_a_comment_holding_double_hyphens_is_read_as_urdfdom_reads_it(cli, tmp_path):
    from differential import check_urdf

    path = write(tmp_path, "robot.urdf", HYPHENATED)
    real = check_urdf(path)
    assert not real.rejects and "root Link: b has 0 child(ren)" in real.stdout  # 'a' is inside the comment for urdfdom
    result = cli("check", str(path))
    no_traceback(result)
    assert result.exit_code == 0, result.stderr
    assert "root Link: b has 0 child(ren)" in result.stdout
    mine = run_cli("check", "--format", "check_urdf", str(path))
    assert mine.stdout.decode() == real.stdout
    assert "robot.urdf:3:3: X007 warning: comment holds '--'" in result.stderr
    big = HYPHENATED.replace('  <link name="b"/>\n', "".join(f'  <link name="l{i}"/>\n' for i in range(60000)) + '  <link name="b"/>\n')
    streamed = cli("lint", "--select", "X007", str(write(tmp_path, "big.urdf", big)))
    no_traceback(streamed)
    assert "big.urdf:3:3: X007 warning" in streamed.stdout and "X001" not in streamed.stdout


def test_an_srdf_comment_holding_double_hyphens_is_a_warning(cli, tmp_path):
    srdf = '<robot name="r">\n  <group name="arm"><link name="a"/></group>\n  <!-- <virtual_joint name="v"/> --!>\n  <!-- next -->\n</robot>\n'
    result = cli("check", str(write(tmp_path, "r.srdf", srdf)), "--urdf", str(write(tmp_path, "r.urdf", ONE_LINK)))
    no_traceback(result)
    assert result.exit_code == 0, result.stderr
    assert "r.srdf:3:3: X007 warning" in result.stderr


def test_a_xacro_comment_holding_double_hyphens_stays_an_error(cli, tmp_path):
    result = cli("check", str(write(tmp_path, "robot.urdf.xacro", HYPHENATED)))
    no_traceback(result)
    assert result.exit_code == 1  # xacro refuses the file
    assert "X001 error" in result.stderr and "X007" not in result.stderr
