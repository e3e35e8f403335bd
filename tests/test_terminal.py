"""What a person sees: each command run on a real pseudo-terminal, as from a shell.

On a terminal rich draws colours and the progress bar, a path the tests that
redirect everything never take: the diagnostics must be printed, the exit code
right, and the cursor shown again however the run ends.
"""

from __future__ import annotations

import os
import pty
import re
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from conftest import FIXTURES, example_robot_data

HIDE_CURSOR, SHOW_CURSOR = b"\x1b[?25l", b"\x1b[?25h"
ANSI = re.compile(rb"\x1b\[[0-9;?]*[A-Za-z]")


def on_terminal(
    *args: str, cwd: Path | None = None, interrupt_after: float | None = None, env: dict | None = None, program: Path | None = None
) -> tuple[bytes, int]:
    """Everything urdfcli (or ``program``) writes to a terminal (both streams), and
    its exit code; with ``interrupt_after``, Ctrl-C is pressed after that many seconds."""
    leader, follower = pty.openpty()
    environment = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "FORCE_COLOR", "CI", "GITHUB_ACTIONS", "URDFCLI_DEBUG")}
    process = subprocess.Popen(
        [sys.executable, *([str(program)] if program else ["-m", "urdfcli"]), *args], stdin=follower, stdout=follower, stderr=follower,
        cwd=cwd, env={**environment, "TERM": "xterm-256color", "COLUMNS": "200", **(env or {})}, start_new_session=True,
    )
    os.close(follower)
    out = b""
    started = time.monotonic()
    interrupted = False
    while True:
        if interrupt_after is not None and not interrupted and time.monotonic() - started > interrupt_after:
            os.killpg(process.pid, signal.SIGINT)  # as the terminal does for Ctrl-C
            interrupted = True
        ready, _, _ = select.select([leader], [], [], 0.1)
        if not ready:
            if process.poll() is not None:
                break
            continue
        try:
            chunk = os.read(leader, 65536)
        except OSError:
            break
        if not chunk:
            break
        out += chunk
    code = process.wait(timeout=120)
    os.close(leader)
    return out, code


def text(out: bytes) -> str:
    return ANSI.sub(b"", out).replace(b"\r", b"").decode()


def cursor_restored(out: bytes) -> bool:
    """Whether a cursor hidden during the run is shown again after."""
    hidden = out.rfind(HIDE_CURSOR)
    return hidden < 0 or out.rfind(SHOW_CURSOR) > hidden


BROKEN = FIXTURES / "seed001" / "broken_inertia_crane.urdf"


def test_check_on_a_terminal_prints_the_tree_and_every_diagnostic():
    out, code = on_terminal("check", str(FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"))
    shown = text(out)
    assert code == 0
    assert "root Link: base_footprint has 1 child(ren)" in shown
    assert "M003 warning: material 'black'" in shown and "1 file checked: 0 errors, 1 warning" in shown
    assert b"\x1b[" in out  # styled: it is a terminal
    assert cursor_restored(out)


def test_lint_of_published_models_with_their_meshes_shows_progress_then_every_diagnostic():
    """A run of several seconds: rich draws its progress bar on the terminal, removes
    it, shows the cursor again, and the whole report follows."""
    data = example_robot_data()
    robots = data / "robots"
    models = [
        robots / "anymal_b_simple_description/robots/anymal.urdf", robots / "ur_description/urdf/ur5_robot.urdf",
        robots / "panda_description/urdf/panda.urdf", robots / "b1_description/urdf/b1.urdf",
        robots / "go1_description/urdf/go1.urdf", robots / "z1_description/urdf/z1.urdf",
    ]
    out, code = on_terminal("lint", "-P", f"example-robot-data={data}", *map(str, models))
    shown = text(out)
    assert code == 1  # the published models have warnings
    assert b"linting" in out and HIDE_CURSOR in out  # the progress bar was drawn
    drawn = text(out)
    assert re.search(r"linting.* [0-5]/6 .*robots/\w+_description/", drawn)  # files done out of all, and the file being read
    assert b"38;2;249;38;114" not in out and b"\x1b[31m" not in out  # not rich's red-pink bar: the terminal's own colour
    assert cursor_restored(out)
    assert "6 files checked:" in shown
    assert "I009 warning: inertia of link 'wrist_1_link'" in shown  # ur5: a diagnostic, printed after the bar
    assert "internal error" not in shown and "Traceback" not in shown


def test_the_concise_summary_is_a_line_of_its_own_on_a_terminal():
    """The concise format writes its diagnostics on standard output and the summary on
    standard error: on one terminal, after the progress bar, the summary starts a line."""
    data = example_robot_data()
    robots = data / "robots"
    models = [robots / "ur_description/urdf/ur5_robot.urdf", robots / "panda_description/urdf/panda.urdf", robots / "z1_description/urdf/z1.urdf"]
    out, code = on_terminal("lint", "--format", "concise", "-P", f"example-robot-data={data}", *map(str, models))
    lines = text(out[max(0, out.rfind(SHOW_CURSOR)):]).splitlines()
    assert code == 1
    summary = [line for line in lines if "files checked:" in line]
    assert len(summary) == 1 and re.fullmatch(r"3 files checked: \d+ errors?, \d+ warnings?(, \d+ info)?", summary[0]), summary
    assert all(re.match(r"\S+\.urdf:\d+:\d+: [A-Z]\d{3} ", line) for line in lines[: lines.index(summary[0])])


def test_a_workspace_lint_on_a_terminal_fits_its_width(tmp_path):
    """The test workspace on a terminal 100 columns wide: messages, notes and hints wrapped
    at that width alike (only a word longer than the room left would go past it; none
    here is), every finding once, and nothing left of the progress bar."""
    from ros_workspace import make_ros_workspace

    src = make_ros_workspace(tmp_path)
    out, code = on_terminal("lint", "src", cwd=src.parent, env={"COLUMNS": "100"})
    shown = text(out)
    assert code == 1 and "Traceback" not in shown
    report = text(out[max(0, out.rfind(SHOW_CURSOR)):]).lstrip("\n")  # after the progress bar, if one was drawn (it hides the cursor)
    for line in report.splitlines():
        assert len(line) <= 100, line
    firsts = [line.split(" ")[0] for line in report.splitlines() if re.match(r"src/\S+:\d+:\d+: [A-Z]\d{3} ", line)]
    assert len(firsts) == len(set(firsts))  # nothing twice
    assert "\n13 files checked: 2 errors, 7 warnings, 5 info\n" in report  # one K009: franka's passive joint in its group
    assert cursor_restored(out)


def test_a_long_source_line_is_cut_to_the_terminal_around_its_caret(tmp_path):
    """A source line wider than the terminal (the published models' one-line <inertia>, an
    SRDF's <end_effector>) is cut to fit it, the part around the caret shown, the caret
    under the attribute it names."""
    comment = "<!-- " + "a comment as long as a CAD exporter writes, " * 4 + "-->"
    (tmp_path / "long.urdf").write_text(
        f'<robot name="r">\n  <link name="a">{comment}<visual><geometry><box size="1 1 -1"/></geometry></visual></link>\n</robot>\n'
    )
    out, code = on_terminal("lint", "long.urdf", cwd=tmp_path, env={"COLUMNS": "80"})
    lines = text(out).splitlines()
    assert code == 1
    assert all(len(line) <= 80 + len(line.split(": ")[0]) for line in lines)  # beside the position a diagnostic begins with
    assert all(len(line) <= 80 for line in lines if " | " in line)
    excerpt = next(i for i, line in enumerate(lines) if line.startswith("     2 | "))
    assert lines[excerpt].startswith("     2 | ...")  # the start cut off, the caret's part shown
    caret = lines[excerpt + 1].index("^")
    assert lines[excerpt][caret:].startswith('size="1 1 -1"') or lines[excerpt][caret:].startswith("<box")


def test_a_source_line_is_never_wrapped_and_the_caret_stays_under_its_column(tmp_path):
    """xArm's <xacro:arg default="$(find xarm_controller)/config/..."> on an 80-column
    terminal: the excerpt went past the width by the path it held, was wrapped like a
    hint, and its caret landed two lines below its text. It is cut to the width now, the
    caret on the next line, under its text."""
    comment = "<!-- exported from /home/engineer/cad/exports/robot_arm/assembly/version_2/parts/link_a.step -->"
    (tmp_path / "long.urdf").write_text(
        f'<robot name="r">\n  <link name="a"><visual><geometry><box size="1 1 -1"/></geometry></visual>{comment}</link>\n</robot>\n'
    )
    out, code = on_terminal("lint", "long.urdf", cwd=tmp_path, env={"COLUMNS": "80"})
    lines = text(out).splitlines()
    assert code == 1
    assert all(len(line) <= 80 for line in lines), lines
    excerpt = next(i for i, line in enumerate(lines) if line.startswith("     2 | "))
    assert len(lines[excerpt]) == 80 and lines[excerpt].endswith("...")  # cut, not wrapped
    assert lines[excerpt + 1].startswith("       | ")
    assert lines[excerpt][lines[excerpt + 1].index("^"):].startswith('size="1 1 -1"')


def test_the_command_line_sets_its_ctrl_c_handler_before_it_imports_anything():
    """A Ctrl-C while Python imports a module no handler covers ends in a traceback: the entry point
    covers the import of urdfcli.cli, and main sets its own handler before importing more."""
    program = (
        "import sys\n"
        "import urdfcli.cli as cli\n"
        "from urdfcli.cli.interrupt import CtrlC\n"
        "before, install = set(sys.modules), CtrlC.install\n"
        "CtrlC.install = classmethod(lambda cls: (print(sorted(set(sys.modules) - before)), install())[1])\n"
        "cli.main(['--version'])\n"
    )
    done = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0 and done.stdout.splitlines()[0] == "[]", done.stdout + done.stderr


def test_an_error_that_follows_a_swallowed_ctrl_c_ends_as_interrupted(monkeypatch, capsys):
    """Ctrl-C reaches lint's -j workers too: when the main process's KeyboardInterrupt was
    swallowed by a library (trimesh importing scipy) and the pool then breaks for the
    workers Ctrl-C ended, the run is interrupted (130), not an internal error (2)."""
    from urdfcli import cli

    def command(**_):
        try:
            os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C, as the terminal sends it
            time.sleep(1)
        except BaseException:  # noqa: BLE001 - as the library does
            pass
        raise RuntimeError("A process in the process pool was terminated abruptly")

    monkeypatch.setattr(cli, "program_for", lambda argv: command)
    assert cli.main(["lint", "robot.urdf"]) == 130
    assert capsys.readouterr().err == "urdfcli: interrupted\n"


@pytest.mark.parametrize("after", [0.2, 1.0, 2.0])  # while Python starts; while trimesh imports scipy (it swallows the exception); later
def test_lint_interrupted_restores_the_terminal(after):
    data = example_robot_data()
    models = sorted((data / "robots").rglob("*.urdf"))[:30]
    out, code = on_terminal("lint", "-P", f"example-robot-data={data}", *map(str, models), interrupt_after=after)
    # 130, or ended by the signal itself: CPython does that at exit when the interrupt reached code
    # it ran for a library (scipy's modules, while trimesh imports them); a shell shows 130 for both
    assert code in (130, -signal.SIGINT), text(out)[-1000:]
    assert "urdfcli: interrupted" in text(out)
    assert cursor_restored(out)
    assert "Traceback" not in text(out)


def test_tree_on_a_terminal():
    out, code = on_terminal("tree", str(FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"))
    shown = text(out)
    assert code == 0
    assert "└── base_link  ← link2footprint (fixed)" in shown
    assert "9 links, 8 joints (4 fixed, 4 continuous), 4 DOF, depth 3, 6 leaf links" in shown
    assert cursor_restored(out)


def test_inertia_on_a_terminal_prints_its_table_and_problems():
    out, code = on_terminal("inertia", str(BROKEN))
    shown = text(out)
    assert code == 1
    assert "robot 'crane'" in shown or "robot '" in shown
    assert re.search(r"I00\d warning", shown)
    assert re.search(r"1 file audited: \d+ problems", shown)
    assert cursor_restored(out)


def test_graph_on_a_terminal_says_which_files_it_wrote(tmp_path):
    out, code = on_terminal("graph", str(FIXTURES / "seed000" / "my_robot.urdf"), "-o", "tree.svg", cwd=tmp_path)
    assert code == 0, text(out)
    assert "Created file tree.svg" in text(out)
    assert (tmp_path / "tree.svg").read_bytes().lstrip().startswith((b"<?xml", b"<svg"))
    assert cursor_restored(out)


def test_an_internal_error_on_a_terminal_is_one_line(tmp_path):
    """The report of an internal error reaches the terminal, and the terminal is left as it was."""
    program = tmp_path / "broken_run.py"
    program.write_text(
        "import sys, urdfcli.model.load\n"
        "def broken(*a, **k): raise ZeroDivisionError('boom')\n"
        "urdfcli.model.load.read = broken\n"
        "from urdfcli.cli import main\n"
        "sys.exit(main(sys.argv[1:]))\n"
    )
    out, code = on_terminal("check", str(BROKEN), program=program)
    assert code == 2
    lines = [line for line in text(out).splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("urdfcli: internal error (ZeroDivisionError: boom)")
    assert cursor_restored(out)


@pytest.mark.parametrize("command", ["check", "lint"])
def test_a_report_redirected_to_a_file_holds_the_diagnostics(tmp_path, command):
    """`lint robot.urdf > report.txt` keeps the report (check keeps check_urdf's layout:
    its tree in the file, the diagnostics on the terminal)."""
    report = tmp_path / "report.txt"
    with report.open("wb") as stream:
        done = subprocess.run([sys.executable, "-m", "urdfcli", command, str(BROKEN)], stdout=stream, stderr=subprocess.PIPE)
    assert done.returncode == 1  # warnings fail lint; the crane's meshes, of another machine, fail check too
    written = report.read_text()
    if command == "lint":
        assert "I00" in written and "file checked:" in written
    else:
        assert written.startswith("robot name is: ") and "I00" in done.stderr.decode()
