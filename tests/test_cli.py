"""The command line on first contact: help, usage, metavars and colour."""

from __future__ import annotations

import os
import re
import subprocess
import sys

import pytest
from conftest import run_cli
from test_terminal import on_terminal

COMMANDS = ("expand", "check", "tree", "graph", "inertia", "lint", "rules", "rule")
BROKEN = '<robot name="r"><link name="a"/><link name="a"/></robot>'


def test_bare_urdfcli_prints_the_help_and_exits_2_without_an_error_line():
    done = run_cli()
    assert done.returncode == 2
    assert b"Usage: urdfcli" in done.stdout and b"Commands" in done.stdout
    assert done.stderr == b""


def test_expand_usage_says_one_file():
    usage = next(line for line in run_cli("expand", "--help").stdout.decode().splitlines() if "Usage:" in line)
    assert "FILE [NAME:=VALUE]..." in usage and "FILE..." not in usage


@pytest.mark.parametrize("command", COMMANDS)
def test_options_read_as_words_and_every_command_has_color(command):
    text = run_cli(command, "--help", env={"COLUMNS": "200"}).stdout.decode()
    options = [line for line in text.splitlines() if re.match(r"\W*--", line)]
    assert any(re.search(r"--color\s+WHEN\s", line) for line in options)
    for line in options:
        assert not re.search(r"<(str|int|float|path|int range|float range)>", line), line
    for line in (o for o in options if "--format" in o):
        assert re.search(r"--format\s+-f\s+(FORMAT|dot)\s", line), line


ALL_COMMANDS = (*COMMANDS, "diff", "drift", "lsp")


@pytest.mark.parametrize("command", ALL_COMMANDS)
def test_every_option_help_shows_whole(command):
    """The help screen shows each option's help text as written: rich reads `[word]` as
    markup and drops it (`in [tool.urdfcli]` once showed as `in )`)."""
    import typer.main

    from urdfcli.cli import build_app

    text = " ".join(re.sub(r"[│╭╰─╮╯]", " ", run_cli(command, "--help", env={"COLUMNS": "400"}).stdout.decode()).split())
    click_command = typer.main.get_command(build_app((command,))).commands[command]
    for parameter in click_command.params:
        help_text = getattr(parameter, "help", None)
        if help_text and not getattr(parameter, "hidden", False):
            assert " ".join(help_text.split()) in text, (parameter.name, help_text)


def test_lint_help_paragraphs_wrap_as_one():
    """The docstring's own line breaks do not show: no short line inside a paragraph."""
    text = run_cli("lint", "--help", env={"COLUMNS": "80"}).stdout.decode()
    prose = text.split("Arguments")[0]
    paragraphs = [[line.strip() for line in block.splitlines() if line.strip()] for block in re.split(r"\n\s*\n", prose)]
    paragraph = next(p for p in paragraphs if p and p[0].startswith("Configuration comes from"))
    assert " ".join(paragraph).endswith("Exit 0 when nothing remains, 1 when a warning or error remains, 2 when it cannot run.")
    assert all(len(line) > 60 for line in paragraph[:-1]), paragraph


def on_a_terminal(*args: str, env: dict) -> bytes:
    """What urdfcli writes to a terminal (both streams)."""
    return on_terminal(*args, env=env)[0]


def test_no_color_removes_bold_and_dim_too_and_color_option_decides(tmp_path):
    path = tmp_path / "broken.urdf"
    path.write_text(BROKEN)
    assert b"\x1b[1m" in on_a_terminal("check", str(path), env={})  # bold summary on a terminal
    assert b"\x1b[" not in on_a_terminal("check", str(path), env={"NO_COLOR": "1"})
    assert b"\x1b[" not in on_a_terminal("check", "--color", "never", str(path), env={})
    assert b"\x1b[" not in on_a_terminal("check", "--help", env={"NO_COLOR": "1"})
    piped = run_cli("check", "--color", "always", str(path))
    assert b"\x1b[1m" in piped.stderr
    assert b"\x1b[" not in run_cli("check", str(path)).stderr
    bad = run_cli("tree", "--color", "sometimes", str(path))
    assert bad.returncode == 2 and b"sometimes" in bad.stderr


# -- the end of a run: no finalization, nothing lost ------------------------------------------
WIDE = '<robot name="wide"><link name="l0"/>' + "".join(
    f'<link name="l{i}"/><joint name="j{i}" type="fixed"><parent link="l0"/><child link="l{i}"/></joint>' for i in range(1, 5000)
) + "</robot>"
IN_PROCESS = "import sys; from urdfcli.cli import main\nsys.exit(main(sys.argv[1:]))\n"
BUFFERED = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"} | {"NO_COLOR": "1", "COLUMNS": "200"}


def test_the_program_prints_all_a_run_that_ends_as_python_does_prints(tmp_path):
    """The program's buffered output, larger than a pipe holds, and its exit code are
    those of main() ending the usual way."""
    path = tmp_path / "wide.urdf"
    path.write_text(WIDE)
    for args in (["tree", str(path)], ["check", str(path)], ["check", "--format", "json", str(path), str(tmp_path / "missing.urdf")]):
        ours, usual = (subprocess.run([sys.executable, *how, *args], capture_output=True, env=BUFFERED) for how in (["-m", "urdfcli"], ["-c", IN_PROCESS]))
        assert len(ours.stdout) > 65_536 or args[1] == "--format"
        assert (ours.returncode, ours.stdout, ours.stderr) == (usual.returncode, usual.stdout, usual.stderr)


def test_a_reader_that_stops_early_ends_the_run_with_exit_1_and_no_message(tmp_path):
    path = tmp_path / "wide.urdf"
    path.write_text(WIDE)
    program = subprocess.Popen([sys.executable, "-m", "urdfcli", "tree", str(path)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=BUFFERED)
    assert program.stdout.readline().startswith(b"l0")
    program.stdout.close()
    assert program.wait(timeout=60) == 1
    assert program.stderr.read() == b""
