"""urdfcli against check_urdf and xacro, side by side, on the work they both do.

Run with ``make bench`` (or ``python benchmarks/run.py`` in the venv that has
urdfcli; ``--quick`` runs fewer repetitions and leaves out the 100k-link tree;
``--baseline REV`` measures urdfcli at git revision REV beside it, in the same run,
each of its commands in turn with the others: "before" next to "now").
It measures every target of "What must hold" in one run:

1. ``check`` (and ``lint``) on the 69 URDFs of the installed
   ``example-robot-data`` package in one call, against a ``check_urdf`` shell loop;
   ``check --target mujoco`` on them against plain ``check`` (within 1.2x), and
   ``lint --fix`` on a copy of them (nothing safe to fix) against plain ``lint`` (within 1.1x);
   ``check --target all`` (every consumer's prediction and the compatibility table)
   against plain ``check`` (within 1.5x);
2. ``check``, ``tree`` and ``expand`` on one small file, against
   ``python -c 'import lxml.etree'``, the floor of any Python tool;
3. the bundled xacro fixtures that the ``xacro`` tool expands on its own (no
   ``$(find)``), ``check`` against ``xacro X | check_urdf`` and ``expand`` against
   ``xacro``; the same on a generated model of 1,500 macro calls;
4. ``check`` on a generated tree of 100,000 links (each with an inertial, a
   visual and a collision) against ``check_urdf``, time and peak memory; and
   ``check``, ``tree`` and ``lint`` on it against the 10,000-link tree;
5. ``urdfcli lsp``: the time from an edit (a ``didChange`` sent) to the edited
   file's diagnostics of that version published, over a series of edits made as
   keystrokes are, one at a time: in a 51-link xacro model; in a macro library
   that nine models include, with one of them open too (and the time until
   that model's list arrives); in PR2's URDF; in a
   URDF of 3,000 links, copies of one link, and in the same tree with no two
   links alike (``--editor`` measures these alone);
6. ``lint`` on the 69 URDFs with their meshes (``-P example-robot-data=...``, every
   mesh read) against loading each model once with ``yourdfpy.URDF.load(...,
   load_meshes=True)`` in one process, what a Python user would write;
7. ``diff`` of two versions of a 100-link model against one ``check`` of it, and
   ``lint`` of a repository with no generated URDF (the 69 URDFs, their xacro
   headers taken out) against the same ``lint`` with the drift rule X110 off.

Models are written under ``benchmarks/generated/``. Every measurement is a
separate process with its output discarded; the two commands of a comparison
run in turn, and a ratio is the median of urdfcli's runs over the median of the
other's (wall time; memory is peak resident set size, from ``wait4``, which
includes a command's children, as does the processor time shown beside each
time: user and system, which the machine's load changes less than the wall
time). Targets are reported, never asserted.
"""

from __future__ import annotations

import argparse
import compileall
import importlib.metadata
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures"
GENERATED = ROOT / "benchmarks" / "generated"
BIN = Path(sys.executable).parent
SMALL = FIXTURES / "seed000" / "my_robot.urdf"
MACRO_CALLS = 1_500


def _arguments():
    parser = argparse.ArgumentParser(
        prog="benchmarks/run.py",
        description="urdfcli against check_urdf, xacro and yourdfpy, side by side, as ratios (the cases: this file's docstring).",
    )
    parser.add_argument("--quick", action="store_true", help="fewer repetitions, and no 100,000-link tree")
    parser.add_argument("--editor", action="store_true", help="the editor server's figures alone")
    parser.add_argument("--baseline", metavar="REV", help="also urdfcli at git revision REV, in the same run, in turn with now")
    return parser.parse_args() if __name__ == "__main__" else parser.parse_args([])


ARGUMENTS = _arguments()
QUICK = ARGUMENTS.quick
EDITOR_ONLY = ARGUMENTS.editor
# the same urdfcli commands at BASELINE_REV (its src/ on PYTHONPATH, with this venv's
# packages), measured in the same run, in turn with the others: "before" beside "now"
BASELINE_REV = ARGUMENTS.baseline
BASELINE = GENERATED / "baseline"


# -- running and measuring -----------------------------------------------------
@dataclass
class Measure:
    seconds: float
    mib: float
    status: int
    cpu: float = 0.0  # processor time (user and system, its children included): the load changes it less than the wall time
    before: Measure | None = None  # the same command at the baseline revision, when one is given

    def __str__(self) -> str:
        return f"{_seconds(self.seconds)} (processor {_seconds(self.cpu)}), {self.mib:.0f} MiB"


class Command(list):
    """An urdfcli command line; ``twin`` is the same command at the baseline revision."""

    twin: list[str] | None = None


def _seconds(value: float) -> str:
    return f"{value * 1000:.0f} ms" if value < 1 else f"{value:.2f} s"


def _once(command: list[str]) -> tuple[float, float, int, float]:
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, wait_status, usage = os.wait4(process.pid, 0)
    seconds = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(wait_status)
    return seconds, usage.ru_maxrss / 1024, process.returncode, usage.ru_utime + usage.ru_stime  # ru_maxrss: KiB on Linux


def measure(*commands: list[str], runs: int) -> list[Measure]:
    """Median wall time, processor time and peak RSS of each command, the commands run in turn ``runs``
    times; an urdfcli command's twin at the baseline revision runs in turn with them, and
    its figures are the ``before`` of the command's."""
    twins = [getattr(command, "twin", None) for command in commands]
    run = [*commands, *(twin for twin in twins if twin is not None)]
    for command in commands:
        print("  " + " ".join(Path(p).name if os.sep in p else p for p in command[:4]) + (" ..." if len(command) > 4 else ""), flush=True)
    samples: list[list[tuple[float, float, int, float]]] = [[] for _ in run]
    for _ in range(runs):
        for index, command in enumerate(run):
            samples[index].append(_once(command))
    found = [
        Measure(
            statistics.median(s for s, _, _, _ in runs_of), statistics.median(m for _, m, _, _ in runs_of), max(c for _, _, c, _ in runs_of),
            statistics.median(p for _, _, _, p in runs_of),
        )
        for runs_of in samples
    ]
    ours, befores = found[: len(commands)], iter(found[len(commands):])
    for measured, twin in zip(ours, twins):
        if twin is not None:
            measured.before = next(befores)
    return ours


def tool(name: str) -> str | None:
    """A program from this venv first, else from PATH."""
    local = BIN / name
    return str(local) if local.exists() else shutil.which(name)


def urdfcli(*args: str, twin: bool = True) -> Command:
    """urdfcli as installed here (and, with --baseline, its twin at that revision: both
    run as ``python -m urdfcli`` then, the sources named by PYTHONPATH; none for a
    command the baseline does not have)."""
    if BASELINE_REV is None:
        script = tool("urdfcli")
        return Command([script, *args] if script else [sys.executable, "-m", "urdfcli", *args])
    command = Command(["env", f"PYTHONPATH={ROOT / 'src'}", sys.executable, "-m", "urdfcli", *args])
    command.twin = ["env", f"PYTHONPATH={BASELINE / 'src'}", sys.executable, "-m", "urdfcli", *args] if twin else None
    return command


def shell(script: str, *args: str) -> list[str]:
    """``bash -c script`` with ``args`` as $0, $1, ...: a loop or a pipe of programs."""
    return ["bash", "-c", script, *args]


# -- inputs ----------------------------------------------------------------------
LINK = """  <link name="link_{i}">
    <inertial>
      <origin xyz="0 0 0.05" rpy="0 0 0"/>
      <mass value="1.0"/>
      <inertia ixx="0.0104" ixy="0" ixz="0" iyy="0.0104" iyz="0" izz="0.0008"/>
    </inertial>
    <visual>
      <origin xyz="0 0 0.05" rpy="0 0 0"/>
      <geometry><box size="0.1 0.1 0.35"/></geometry>
      <material name="grey"/>
    </visual>
    <collision>
      <origin xyz="0 0 0.05" rpy="0 0 0"/>
      <geometry><box size="0.1 0.1 0.35"/></geometry>
    </collision>
  </link>
"""
JOINT = """  <joint name="joint_{i}" type="revolute">
    <parent link="link_{parent}"/>
    <child link="link_{i}"/>
    <origin xyz="0 0 0.1" rpy="0 0 0"/>
    <axis xyz="0 0 1"/>
    <limit lower="-1.57" upper="1.57" effort="10" velocity="1"/>
  </joint>
"""


def generate_tree(links: int, distinct: bool = False) -> Path:
    """A tree of ``links`` links, three children per link: copies of one link, or with
    ``distinct`` each link its own length and mass (and the tensor of its box)."""
    path = GENERATED / f"tree_{links}{'_distinct' if distinct else ''}.urdf"
    with path.open("w", encoding="utf-8") as out:
        out.write(f'<?xml version="1.0"?>\n<robot name="tree_{links}">\n')
        out.write('  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>\n')
        for i in range(links):
            out.write(_distinct_link(i) if distinct else LINK.format(i=i))
        for i in range(1, links):
            out.write(JOINT.format(i=i, parent=(i - 1) // 3))
        out.write("</robot>\n")
    return path


def _distinct_link(i: int) -> str:
    """LINK with its own length (0.2 m and 0.1 mm more for each link) and mass."""
    length, mass = 0.2 + i * 1e-4, 1.0 + i * 1e-3
    side, end = mass * (0.1**2 + length**2) / 12, mass * 2 * 0.1**2 / 12
    return (LINK.format(i=i).replace('<mass value="1.0"/>', f'<mass value="{mass:.4f}"/>')
            .replace('ixx="0.0104" ixy="0" ixz="0" iyy="0.0104" iyz="0" izz="0.0008"', f'ixx="{side:.6g}" ixy="0" ixz="0" iyy="{side:.6g}" iyz="0" izz="{end:.6g}"')
            .replace('size="0.1 0.1 0.35"', f'size="0.1 0.1 {length:.4f}"'))


MACRO = """<?xml version="1.0"?>
<robot name="macros" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="length" value="0.35"/>
  <xacro:property name="mass" value="1.0"/>
  <xacro:macro name="segment" params="name parent z:=0.1">
    <link name="${{name}}">
      <inertial>
        <origin xyz="0 0 ${{length / 2}}" rpy="0 0 0"/>
        <mass value="${{mass}}"/>
        <inertia ixx="${{mass * (3 * 0.05**2 + length**2) / 12}}" ixy="0" ixz="0"
                 iyy="${{mass * (3 * 0.05**2 + length**2) / 12}}" iyz="0" izz="${{mass * 0.05**2 / 2}}"/>
      </inertial>
      <visual>
        <origin xyz="0 0 ${{length / 2}}" rpy="0 0 0"/>
        <geometry><cylinder radius="0.05" length="${{length}}"/></geometry>
      </visual>
      <collision>
        <origin xyz="0 0 ${{length / 2}}" rpy="0 0 0"/>
        <geometry><cylinder radius="0.05" length="${{length}}"/></geometry>
      </collision>
    </link>
    <joint name="${{name}}_joint" type="revolute">
      <parent link="${{parent}}"/>
      <child link="${{name}}"/>
      <origin xyz="0 0 ${{z}}" rpy="0 0 0"/>
      <axis xyz="0 0 1"/>
      <limit lower="${{-pi / 2}}" upper="${{pi / 2}}" effort="10" velocity="1"/>
    </joint>
  </xacro:macro>
  <link name="base"/>
{calls}</robot>
"""


def generate_macro_model(calls: int) -> Path:
    """A xacro model of ``calls`` calls of one macro (a link and a joint each), in a tree."""
    path = GENERATED / f"macros_{calls}.urdf.xacro"
    lines = []
    for i in range(calls):
        parent = "base" if i == 0 else f"s{(i - 1) // 3}"
        lines.append(f'  <xacro:segment name="s{i}" parent="{parent}"/>\n')
    path.write_text(MACRO.format(calls="".join(lines)), encoding="utf-8")
    return path


def corpus_package() -> Path | None:
    """The installed example-robot-data folder (pip install -e '.[test]'): package.xml, robots/."""
    try:
        distribution = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        return None
    return Path(distribution.locate_file("cmeel.prefix/share/example-robot-data"))


def corpus() -> list[Path]:
    """The URDFs of the installed example-robot-data package."""
    package = corpus_package()
    return sorted((package / "robots").rglob("*.urdf")) if package is not None else []


def xacro_fixtures(xacro: str) -> list[Path]:
    """The bundled .urdf.xacro fixtures the xacro tool expands without help (no $(find))."""
    found = []
    for path in sorted(FIXTURES.rglob("*.urdf.xacro")):
        if subprocess.run([xacro, str(path)], capture_output=True).returncode == 0:
            found.append(path)
    return found


# -- the table -------------------------------------------------------------------
@dataclass
class Row:
    case: str
    ours: str
    other: str
    time_ratio: float | None = None
    memory_ratio: float | None = None
    target: str = ""
    met: str = ""
    before: str = ""  # the baseline revision's figures, when one is given


def verdict(ok: bool) -> str:
    return "yes" if ok else "**no**"


def failed(measured: Measure, allowed: tuple[int, ...] = (0, 1)) -> str:
    return "" if measured.status in allowed else f" (exit {measured.status})"


def compare(rows: list[Row], case: str, ours: Measure, other_name: str, theirs: Measure, limit: float | None, memory_limit: float | None = None) -> None:
    time_ratio, memory_ratio = ours.seconds / theirs.seconds, ours.mib / theirs.mib
    row = Row(case, f"{ours}{failed(ours)}", f"{other_name}: {theirs}{failed(theirs)}", time_ratio, memory_ratio)
    if ours.before is not None:
        before, other = ours.before, theirs.before or theirs  # another urdfcli command: its baseline twin
        row.before = f"{before}{failed(before)}, {before.seconds / other.seconds:.2f}" + (f" / {before.mib / other.mib:.2f}" if memory_limit is not None else "")
    if limit is not None:
        row.target = f"time ≤ {limit:g}" + (f", memory ≤ {memory_limit:g}" if memory_limit is not None else "")
        met = verdict(time_ratio <= limit)
        if memory_limit is not None:
            met = f"time {met}, memory {verdict(memory_ratio <= memory_limit)}"
        row.met = met
    rows.append(row)


def print_table(rows: list[Row]) -> None:
    header = ("case", "urdfcli", "compared with", "time ratio", "memory ratio", "target", "met") + (("before (" + BASELINE_REV + "), ratio",) if BASELINE_REV else ())
    cells = [header] + [
        (r.case, r.ours, r.other.replace("|", "\\|"), "" if r.time_ratio is None else f"{r.time_ratio:.2f}", "" if r.memory_ratio is None else f"{r.memory_ratio:.2f}", r.target, r.met)
        + ((r.before,) if BASELINE_REV else ())
        for r in rows
    ]
    widths = [max(len(row[i]) for row in cells) for i in range(len(header))]
    for index, row in enumerate(cells):
        print("| " + " | ".join(cell.ljust(width) for cell, width in zip(row, widths)) + " |")
        if index == 0:
            print("|" + "|".join("-" * (width + 2) for width in widths) + "|")


# -- the cases ---------------------------------------------------------------------
def corpus_cases(rows: list[Row], check_urdf: str) -> None:
    files = [str(p) for p in corpus()]
    if not files:
        rows.append(Row("example-robot-data corpus", "not installed (pip install -e '.[test]')", ""))
        return
    loop = shell('for f in "$@"; do "$0" "$f"; done', check_urdf, *files)
    runs = 3 if QUICK else 7
    check, lint, theirs = measure(urdfcli("check", *files), urdfcli("lint", *files), loop, runs=runs)
    compare(rows, f"check, the {len(files)} example-robot-data URDFs in one call", check, "check_urdf loop", theirs, 1.2)
    compare(rows, f"lint, the same {len(files)} URDFs (meshes absent)", lint, "check_urdf loop", theirs, 2.0)
    targeted, every, plain = measure(urdfcli("check", "--target", "mujoco", *files), urdfcli("check", "--target", "all", *files), urdfcli("check", *files), runs=runs)
    compare(rows, f"check --target mujoco, the same {len(files)} URDFs", targeted, "plain check", plain, 1.2)
    compare(rows, f"check --target all, the same {len(files)} URDFs", every, "plain check", plain, 1.5)
    copies = corpus_copy()  # --fix writes where it fixes: a copy, though these have nothing safe to fix
    fixing, plain = measure(urdfcli("lint", "--fix", *copies, twin=False), urdfcli("lint", *copies, twin=False), runs=runs)
    compare(rows, f"lint --fix, the same {len(files)} URDFs (nothing to fix)", fixing, "plain lint", plain, 1.1)


def corpus_copy() -> list[str]:
    """The corpus copied under benchmarks/generated/, for the commands that may write."""
    package = corpus_package()
    target = GENERATED / "example-robot-data"
    shutil.rmtree(target, ignore_errors=True)
    shutil.copytree(package / "robots", target / "robots")
    shutil.copy2(package / "package.xml", target / "package.xml")
    return sorted(str(p) for p in (target / "robots").rglob("*.urdf"))


MESH_MEMORY_MIB = 500


def mesh_cases(rows: list[Row]) -> None:
    """lint reading every mesh of the corpus, against yourdfpy loading every model with its meshes."""
    files, package = [str(p) for p in corpus()], str(corpus_package())
    if not files:
        return
    runs = 1 if QUICK else 3
    ours, theirs = measure(urdfcli("lint", "--isolated", "-P", f"example-robot-data={package}", *files), [sys.executable, str(ROOT / "benchmarks" / "yourdfpy_load.py"), package, *files], runs=runs)
    compare(rows, f"lint, the {len(files)} URDFs with their meshes (-P)", ours, "yourdfpy.URDF.load(load_meshes=True), one process", theirs, 0.5)
    rows[-1].target += f", peak ≤ {MESH_MEMORY_MIB} MiB"
    rows[-1].met += f", peak {verdict(ours.mib <= MESH_MEMORY_MIB)}"


def small_file_cases(rows: list[Row]) -> None:
    runs = 5 if QUICK else 11
    floor_command = [sys.executable, "-c", "import lxml.etree"]
    for command in ("check", "tree", "expand"):
        ours, floor = measure(urdfcli(command, str(SMALL)), floor_command, runs=runs)
        compare(rows, f"{command}, one small file ({SMALL.name}, {SMALL.stat().st_size:,} bytes)", ours, "python -c 'import lxml.etree'", floor, 2.0)


def xacro_cases(rows: list[Row], check_urdf: str, xacro: str) -> None:
    pipe = 'set -o pipefail; "$0" "$1" | "$2" /dev/stdin'
    runs = 3 if QUICK else 7
    fixtures = xacro_fixtures(xacro)
    for path in fixtures:
        name = str(path.relative_to(FIXTURES))
        check, expand, piped, alone = measure(urdfcli("check", str(path)), urdfcli("expand", str(path)), shell(pipe, xacro, str(path), check_urdf), [xacro, str(path)], runs=runs)
        compare(rows, f"check {name}", check, "xacro | check_urdf", piped, 2.0)
        compare(rows, f"expand {name}", expand, "xacro", alone, 2.0)
    model = generate_macro_model(MACRO_CALLS)
    runs = 2 if QUICK else 3
    check, expand, piped, alone = measure(urdfcli("check", str(model)), urdfcli("expand", str(model)), shell(pipe, xacro, str(model), check_urdf), [xacro, str(model)], runs=runs)
    compare(rows, f"check, generated xacro model of {MACRO_CALLS:,} macro calls", check, "xacro | check_urdf", piped, 0.5)
    compare(rows, f"expand, the same {MACRO_CALLS:,} macro calls", expand, "xacro", alone, 0.5)


def large_cases(rows: list[Row], check_urdf: str) -> None:
    trees = {links: generate_tree(links) for links in (10_000, 100_000)}
    small, big = trees[10_000], trees[100_000]
    check_big, theirs = measure(urdfcli("check", str(big)), [check_urdf, str(big)], runs=3)
    size = big.stat().st_size / 1e6
    compare(rows, f"check, tree of 100,000 links ({size:.0f} MB)", check_big, "check_urdf", theirs, 1.0, 0.5)
    for command in ("check", "tree", "lint"):
        if command == "check":
            (at_10k,) = measure(urdfcli(command, str(small)), runs=5)
            at_100k = check_big
        else:
            at_10k, at_100k = measure(urdfcli(command, str(small)), urdfcli(command, str(big)), runs=2)
        time_ratio, memory_ratio = at_100k.seconds / at_10k.seconds, at_100k.mib / at_10k.mib
        rows.append(
            Row(f"{command}: tree of 100k links / of 10k", f"100k: {at_100k}{failed(at_100k)}", f"10k: {at_10k}{failed(at_10k)}", time_ratio, memory_ratio,
                "< 11 (time and memory)", verdict(time_ratio < 11 and memory_ratio < 11))
        )


def diff_cases(rows: list[Row]) -> None:
    """diff of two versions of a 100-link tree (an origin near the root moved, masses and a limit
    changed, a link renamed), against one check of it; lint with and without the drift rule."""
    old = generate_tree(100)
    new = GENERATED / "tree_100_changed.urdf"
    text = old.read_text(encoding="utf-8").replace('<mass value="1.0"/>', '<mass value="1.1"/>', 20)
    text = text.replace('<origin xyz="0 0 0.1" rpy="0 0 0"/>', '<origin xyz="0 0.02 0.1" rpy="0 0 0.1"/>', 1)
    text = text.replace('upper="1.57"', 'upper="1.6"', 5).replace('"link_99"', '"link_ninety_nine"')
    new.write_text(text, encoding="utf-8")
    runs = 5 if QUICK else 11
    diff, check = measure(urdfcli("diff", str(old), str(new), twin=False), urdfcli("check", str(old), twin=False), runs=runs)
    compare(rows, "diff, two versions of a 100-link tree", diff, "one check of it", check, 2.5)
    files = corpus()
    if not files:
        return
    plain, robots = GENERATED / "no_generated_urdf", corpus_package() / "robots"
    shutil.rmtree(plain, ignore_errors=True)
    for file in files:  # a repository of URDFs written by hand: no xacro header, no xacro beside them
        copy = plain / file.relative_to(robots)
        copy.parent.mkdir(parents=True, exist_ok=True)
        copy.write_text(re.sub(r"<!--.*?-->", "", file.read_text(encoding="utf-8"), flags=re.DOTALL), encoding="utf-8")
    runs = 3 if QUICK else 7
    on, off = measure(urdfcli("lint", "--isolated", str(plain), twin=False), urdfcli("lint", "--isolated", "--ignore", "X110", str(plain), twin=False), runs=runs)
    compare(rows, f"lint, a repository of {len(files)} URDFs none generated", on, "the same lint without X110 (drift)", off, 1.1)


EDITS = 10 if QUICK else 30
EDITOR_LINKS = 50
LIBRARY_MODELS = 9


@dataclass
class EditorCase:
    """Files opened in an editor (the last one is the one looked at), and one number typed
    over again and again in ``edited``: the value that follows ``after``."""

    name: str
    opened: list[Path]
    edited: Path
    after: str
    target: float  # seconds, the median asked for


def _cpu_seconds(pid: int) -> float:
    """The processor time of a process and of those under it still running (the server
    under its supervisor, its xacro worker)."""
    def own(process: int) -> float:
        fields = Path(f"/proc/{process}/stat").read_text().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime, stime

    return sum(own(process) for process in _tree(pid))


def _memory_mib(pid: int) -> float:
    """The memory of a process and of those under it: their proportional set sizes summed
    (a page they share counted once in all)."""
    def own(process: int) -> int:
        rollup = Path(f"/proc/{process}/smaps_rollup").read_text()
        return int(next(row.split()[1] for row in rollup.splitlines() if row.startswith("Pss:")))

    return sum(own(process) for process in _tree(pid)) / 1024


def _tree(pid: int) -> list[int]:
    """``pid`` and the processes under it."""
    parents = {int(p.name): _parent(p.name) for p in Path("/proc").iterdir() if p.name.isdigit()}
    tree = [pid]
    for member in tree:
        tree += [child for child, parent in parents.items() if parent == member]
    return tree


def _parent(process: str) -> int | None:
    try:
        return int(Path(f"/proc/{process}/stat").read_text().rsplit(")", 1)[1].split()[1])
    except (OSError, ValueError, IndexError):
        return None


async def _edit_latencies(case: EditorCase, edits: int, server: list[str]) -> tuple[list[float], float, float, list[float]]:
    """Seconds from each edit sent to the server until the edited file's diagnostics of
    that version arrive, the processor time the server and its xacro worker spent per
    edit, the memory of the server's processes at the end (MiB), and the seconds from each edit
    until the list of the other open file (the model a library is opened from) arrives."""
    import asyncio

    from lsprotocol import types
    from pygls.lsp.client import LanguageClient
    from pygls.uris import from_fs_path

    client = LanguageClient("bench", "1")
    arrived: dict[tuple[str, int], float] = {}
    every: list[tuple[str, float]] = []  # each list published: its file, when
    published = asyncio.Event()

    @client.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    def diagnostics(ls, params: types.PublishDiagnosticsParams) -> None:
        arrived.setdefault((params.uri, params.version or 0), time.perf_counter())
        every.append((params.uri, time.perf_counter()))
        published.set()

    async def wait_for(uri: str, version: int) -> float:
        while (uri, version) not in arrived:
            published.clear()
            await asyncio.wait_for(published.wait(), 120)
        return arrived[(uri, version)]

    async def published_after(uri: str, sent: float) -> float:
        while not any(file == uri and at > sent for file, at in every):
            published.clear()
            await asyncio.wait_for(published.wait(), 120)
        return next(at for file, at in every if file == uri and at > sent)

    root = case.opened[0].parent
    await client.start_io(*server, cwd=str(root))
    await client.initialize_async(types.InitializeParams(capabilities=types.ClientCapabilities(), process_id=os.getpid(), root_uri=from_fs_path(str(root))))
    client.initialized(types.InitializedParams())
    for path in case.opened:
        client.text_document_did_open(types.DidOpenTextDocumentParams(types.TextDocumentItem(from_fs_path(str(path)), "xml", 1, path.read_text())))
        await wait_for(from_fs_path(str(path)), 1)
    uri, text = from_fs_path(str(case.edited)), case.edited.read_text()
    start = text.index(case.after) + len(case.after)
    line, column = text.count("\n", 0, start), start - (text.rfind("\n", 0, start) + 1)
    length = text.index('"', start) - start
    latencies, others = [], []
    pid = client._server.pid
    cpu = _cpu_seconds(pid)
    for version in range(2, edits + 2):
        await asyncio.sleep(0.2)  # a pause between keystrokes: each edit is checked on its own
        typed = types.Range(types.Position(line, column), types.Position(line, column + length))
        new = f"{1 + version % 9}.{version % 10}"
        change = types.TextDocumentContentChangePartial(typed, new)
        length = len(new)
        sent = time.perf_counter()
        client.text_document_did_change(types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(version, uri), [change]))
        latencies.append(await wait_for(uri, version) - sent)
        for path in case.opened:  # and the other open files' checks, before the next keystroke
            if path != case.edited:
                others.append(await published_after(from_fs_path(str(path)), sent) - sent)
    cpu = (_cpu_seconds(pid) - cpu) / edits
    rss = _memory_mib(pid)
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return latencies, cpu, rss, others


LIBRARY = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="arm_mass" value="2.0"/>
  <xacro:property name="arm_length" value="0.4"/>
  <xacro:macro name="segment" params="name parent mass length">
    <link name="${name}">
      <inertial>
        <mass value="${mass}"/>
        <inertia ixx="${mass * length**2 / 12}" ixy="0" ixz="0" iyy="${mass * length**2 / 12}" iyz="0" izz="${mass * 0.05**2 / 2}"/>
      </inertial>
      <visual><geometry><cylinder radius="0.05" length="${length}"/></geometry></visual>
      <collision><geometry><cylinder radius="0.05" length="${length}"/></geometry></collision>
    </link>
    <joint name="${name}_joint" type="revolute">
      <parent link="${parent}"/><child link="${name}"/>
      <origin xyz="0 0 ${length}"/><axis xyz="0 0 1"/>
      <limit lower="-3" upper="3" effort="10" velocity="1"/>
    </joint>
  </xacro:macro>
  <xacro:macro name="arm" params="prefix parent">
    <xacro:segment name="${prefix}shoulder" parent="${parent}" mass="${arm_mass}" length="${arm_length}"/>
    <xacro:segment name="${prefix}upper_arm" parent="${prefix}shoulder" mass="${arm_mass}" length="${arm_length}"/>
    <xacro:segment name="${prefix}forearm" parent="${prefix}upper_arm" mass="${arm_mass / 2}" length="${arm_length}"/>
    <xacro:segment name="${prefix}wrist_1" parent="${prefix}forearm" mass="${arm_mass / 4}" length="0.1"/>
    <xacro:segment name="${prefix}wrist_2" parent="${prefix}wrist_1" mass="${arm_mass / 4}" length="0.1"/>
    <xacro:segment name="${prefix}wrist_3" parent="${prefix}wrist_2" mass="${arm_mass / 4}" length="0.1"/>
  </xacro:macro>
</robot>
"""


def generate_library_workspace(models: int) -> tuple[Path, list[Path]]:
    """A package whose macro library (an arm, as ur_macro.xacro is) ``models`` models include,
    each with two arms: the library and the models."""
    folder = GENERATED / f"library_{models}"
    (folder / "urdf").mkdir(parents=True, exist_ok=True)
    (folder / "package.xml").write_text('<?xml version="1.0"?>\n<package format="3"><name>arms</name><version>0.1.0</version>'
                                        '<description>arms</description><maintainer email="a@b.c">a</maintainer><license>BSD</license></package>\n')
    library = folder / "urdf" / "arm_macro.xacro"
    library.write_text(LIBRARY)
    paths = []
    for i in range(models):
        path = folder / "urdf" / f"robot_{i}.urdf.xacro"
        path.write_text(f'<?xml version="1.0"?>\n<robot name="robot_{i}" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                        '  <xacro:include filename="$(find arms)/urdf/arm_macro.xacro"/>\n  <link name="world"/>\n'
                        '  <xacro:arm prefix="left_" parent="world"/>\n  <xacro:arm prefix="right_" parent="world"/>\n</robot>\n')
        paths.append(path)
    return library, paths


def editor_cases(rows: list[Row]) -> None:
    import asyncio

    model = generate_macro_model(EDITOR_LINKS)
    library, models = generate_library_workspace(LIBRARY_MODELS)
    cases = [
        EditorCase(f"xacro model of {EDITOR_LINKS + 1} links", [model], model, '<xacro:property name="mass" value="', 0.100),
        EditorCase(f"macro library included by {LIBRARY_MODELS} models, one of them open", [models[0], library], library, '<xacro:property name="arm_mass" value="', 0.300),
        EditorCase("URDF of 3,000 links", [generate_tree(3_000)], GENERATED / "tree_3000.urdf", '<mass value="', 0.300),
        # the same tree with no two links alike: what no sharing of work between equal links helps
        EditorCase("URDF of 3,000 distinct links", [generate_tree(3_000, distinct=True)], GENERATED / "tree_3000_distinct.urdf", '<mass value="', 0.300),
    ]
    package = corpus_package()
    if package is not None:
        pr2 = package / "robots" / "pr2_description" / "urdf" / "pr2.urdf"
        cases.insert(2, EditorCase("PR2 (pr2.urdf, 82 links)", [pr2], pr2, '<mass value="', 0.200))
    for case in cases:
        server = urdfcli("lsp")
        try:
            latencies, cpu, rss, others = asyncio.run(_edit_latencies(case, EDITS, server))
            before = asyncio.run(_edit_latencies(case, EDITS, server.twin)) if server.twin is not None else None
        except ImportError:
            rows.append(Row("lsp: re-check after an edit", "pygls not installed (pip install -e '.[lsp]')", ""))
            return
        median, worst = statistics.median(latencies), max(latencies)
        ours = f"median {_seconds(median)}, slowest {_seconds(worst)} ({len(latencies)} edits); processor {_seconds(cpu)} an edit; server {rss:.0f} MiB"
        ours += f"; the open model's list {_seconds(statistics.median(others))}" if others else ""
        row = Row(f"lsp: edit to its diagnostics, {case.name}", ours, "", target=f"median ≤ {case.target * 1000:.0f} ms", met=verdict(median <= case.target))
        if before is not None:
            row.before = f"median {_seconds(statistics.median(before[0]))}; processor {_seconds(before[1])} an edit"
            row.before += f"; the open model's list {_seconds(statistics.median(before[3]))}" if before[3] else ""
        rows.append(row)


def import_costs() -> str:
    """Where the start-up of ``urdfcli check SMALL`` goes, from ``python -X importtime``."""
    result = subprocess.run([sys.executable, "-X", "importtime", "-m", "urdfcli", "check", str(SMALL)], capture_output=True, text=True)
    cumulative: dict[str, int] = {}
    for line in result.stderr.splitlines():
        match = re.match(r"import time:\s+\d+ \|\s+(\d+) \|(\s*)(\S+)", line)
        if match:
            name = match.group(3)
            cumulative[name] = max(cumulative.get(name, 0), int(match.group(1)))
    names = ("urdfcli.cli", "typer", "lxml.etree", "urdfcli.api", "urdfcli.rules", "rich.console", "pydantic", "networkx", "xacro", "urdfcli.model.inertia")
    shown = [f"{name} {cumulative[name] / 1000:.0f} ms" for name in names if name in cumulative]
    absent = [name for name in ("pydantic", "networkx", "xacro", "numpy", "trimesh", "yourdfpy") if name not in cumulative]
    text = "imports of `urdfcli check` on a small file (python -X importtime, cumulative): " + ", ".join(shown)
    return text + (f"; not imported: {', '.join(absent)}" if absent else "")


def machine() -> str:
    cpu = "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{os.cpu_count()} CPUs ({cpu}), Python {platform.python_version()}, {platform.system()} {platform.release()}"


def compile_urdfcli() -> None:
    """Byte-compile urdfcli as an installer would, so that no run measures compiling its
    sources (an editable install under PYTHONDONTWRITEBYTECODE=1 would, every time): the
    installed package, and this checkout's src/, which runs with --baseline (in a
    worktree other than the installed one, they differ)."""
    import urdfcli

    for folder in {Path(urdfcli.__file__).parent.resolve(), (ROOT / "src" / "urdfcli").resolve()}:
        compileall.compile_dir(str(folder), quiet=1, force=True)  # (its staleness test reads only the time, to the second)


def extract_baseline(revision: str) -> None:
    """The sources of urdfcli at ``revision``, under benchmarks/generated/baseline, byte-compiled."""
    shutil.rmtree(BASELINE, ignore_errors=True)
    BASELINE.mkdir(parents=True)
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", revision, "src"], capture_output=True, check=True).stdout
    subprocess.run(["tar", "-x", "-C", str(BASELINE)], input=archive, check=True)
    compileall.compile_dir(str(BASELINE / "src"), quiet=1, force=True)
    print(f"baseline: {revision} ({subprocess.run(['git', '-C', str(ROOT), 'log', '-1', '--format=%h %s', revision], capture_output=True, text=True).stdout.strip()[:80]})", flush=True)


def main() -> int:
    started = time.perf_counter()
    check_urdf, xacro = shutil.which("check_urdf"), tool("xacro")
    if check_urdf is None or xacro is None:
        print("benchmarks/run.py needs check_urdf (liburdfdom-tools) and xacro: run `make bench`", file=sys.stderr)
        return 2
    GENERATED.mkdir(parents=True, exist_ok=True)
    print(f"machine: {machine()}", flush=True)
    compile_urdfcli()
    if BASELINE_REV is not None:
        extract_baseline(BASELINE_REV)
    rows: list[Row] = []
    print("measuring ...", flush=True)
    if EDITOR_ONLY:
        editor_cases(rows)
        print_table(rows)
        return 0
    corpus_cases(rows, check_urdf)
    mesh_cases(rows)
    small_file_cases(rows)
    xacro_cases(rows, check_urdf, xacro)
    editor_cases(rows)
    diff_cases(rows)
    if not QUICK:
        large_cases(rows, check_urdf)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else None
    print()
    print(f"Measured on {machine()}; ratios are urdfcli / the other (medians of runs taken in turn); memory is peak resident set size.")
    print()
    print_table(rows)
    print()
    print(import_costs())
    print(f"\nbenchmark run time: {time.perf_counter() - started:.0f} s" + (f"; load average at the end: {load:.1f}" if load is not None else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
