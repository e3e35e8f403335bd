"""urdfcli against check_urdf and xacro, side by side, on generated models.

Run with ``make bench`` (or ``python benchmarks/run.py`` in the venv that has
urdfcli). It writes its models under ``benchmarks/generated/``:

- chains and trees (three children per link) of 1k, 10k and 100k links, each
  link with an inertial, a visual and a collision, each joint revolute;
- ``mixed/``: ~70 models of 4-200 KB made from the fixtures (xacro ones
  expanded with ``urdfcli expand``), scaled by replicating their links and
  joints under new names.

Every measurement is a separate process; wall time and peak memory (maximum
resident set size, from ``wait4``) are medians of several runs. It prints a
Markdown table with ratios and whether each target is met. Targets are
reported, never asserted.
"""

from __future__ import annotations

import compileall
import copy
import math
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

from lxml import etree

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures"
GENERATED = ROOT / "benchmarks" / "generated"
BIN = Path(sys.executable).parent
SIZES = (1_000, 10_000, 100_000)
RUNS = {1_000: 5, 10_000: 3, 100_000: 2}  # fewer repetitions where one run takes seconds
SMALL = FIXTURES / "seed000" / "my_robot.urdf"
MIXED_SIZES_KB = (5, 40, 100, 200)


# -- running and measuring -----------------------------------------------------
@dataclass
class Measure:
    seconds: float
    mib: float
    status: int

    def __str__(self) -> str:
        return f"{_seconds(self.seconds)}, {self.mib:.0f} MiB"


def _seconds(value: float) -> str:
    return f"{value * 1000:.0f} ms" if value < 1 else f"{value:.2f} s"


def measure(command: list[str], runs: int) -> Measure:
    """Median wall time and median peak RSS of ``runs`` runs, output discarded."""
    print("  " + " ".join(Path(part).name if os.sep in part else part for part in command[:3]) + (" ..." if len(command) > 3 else ""), flush=True)
    times, peaks, status = [], [], 0
    for _ in range(runs):
        start = time.perf_counter()
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, wait_status, usage = os.wait4(process.pid, 0)
        times.append(time.perf_counter() - start)
        peaks.append(usage.ru_maxrss / 1024)  # KiB on Linux
        process.returncode = status = os.waitstatus_to_exitcode(wait_status)
    return Measure(statistics.median(times), statistics.median(peaks), status)


def tool(name: str) -> str | None:
    """A program from this venv first, else from PATH."""
    local = BIN / name
    return str(local) if local.exists() else shutil.which(name)


def urdfcli(*args: str) -> list[str]:
    script = tool("urdfcli")
    return [script, *args] if script else [sys.executable, "-m", "urdfcli", *args]


# -- generated models ------------------------------------------------------------
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


def generate(kind: str, links: int) -> Path:
    """A chain (each link under the previous) or a tree (three children per link)."""
    path = GENERATED / f"{kind}_{links}.urdf"
    with path.open("w", encoding="utf-8") as out:
        out.write(f'<?xml version="1.0"?>\n<robot name="{kind}_{links}">\n')
        out.write('  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>\n')
        for i in range(links):
            out.write(LINK.format(i=i))
        for i in range(1, links):
            out.write(JOINT.format(i=i, parent=i - 1 if kind == "chain" else (i - 1) // 3))
        out.write("</robot>\n")
    return path


def fixture_bases() -> dict[str, bytes]:
    """Every fixture that is (or expands to) a whole URDF, by name."""
    bases = {}
    for path in sorted(FIXTURES.rglob("*.urdf")):
        bases[_base_name(path)] = path.read_bytes()
    for path in sorted(FIXTURES.rglob("*.urdf.xacro")):
        result = subprocess.run(urdfcli("expand", str(path)), capture_output=True)
        if result.returncode == 0 and b"<link" in result.stdout:
            bases[_base_name(path)] = result.stdout
    return bases


def _base_name(path: Path) -> str:
    relative = path.relative_to(FIXTURES)
    return relative.parts[0] + "_" + relative.name.replace(".urdf", "").replace(".xacro", "_xacro")


def replicate(data: bytes, copies: int) -> bytes:
    """The model with its links, joints, gazebo and transmission elements repeated
    ``copies`` times under new names, each copy fixed to the original root."""
    root = etree.fromstring(data, etree.XMLParser(remove_blank_text=True, resolve_entities=False, no_network=True))
    originals = [e for e in root if e.tag in ("link", "joint", "gazebo", "transmission")]
    children = {c.get("link") for c in root.iterfind("joint/child")}
    first_root = next((e.get("name") for e in root.iterfind("link") if e.get("name") not in children), None)
    for n in range(1, copies):
        suffix = f"_copy{n}"
        for element in originals:
            clone = copy.deepcopy(element)
            for node in clone.iter(etree.Element):
                for attribute in ("name", "reference", "link", "joint"):
                    value = node.get(attribute)
                    renamed = attribute != "name" or node is clone or node.tag in ("joint", "actuator")
                    if value is not None and renamed:
                        node.set(attribute, value + suffix)
            root.append(clone)
        if first_root is not None:
            joint = etree.SubElement(root, "joint", name=f"fix{suffix}", type="fixed")
            etree.SubElement(joint, "parent", link=first_root)
            etree.SubElement(joint, "child", link=first_root + suffix)
    return etree.tostring(root, xml_declaration=True, encoding="utf-8", pretty_print=True)


def generate_mixed() -> list[Path]:
    folder = GENERATED / "mixed"
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    written = []
    for name, data in fixture_bases().items():
        done = set()
        size = len(replicate(data, 1))
        for kilobytes in MIXED_SIZES_KB:
            copies = max(1, math.ceil(kilobytes * 1024 / size))
            if copies in done:
                continue
            done.add(copies)
            path = folder / f"{name}_x{copies}.urdf"
            path.write_bytes(replicate(data, copies))
            written.append(path)
    return written


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


def ratio_text(value: float | None) -> str:
    return "" if value is None else f"{value:.2f}"


def print_table(rows: list[Row]) -> None:
    header = ("case", "urdfcli", "compared with", "time ratio", "memory ratio", "target", "met")
    cells = [header] + [
        (r.case, r.ours, r.other, ratio_text(r.time_ratio), ratio_text(r.memory_ratio), r.target, r.met) for r in rows
    ]
    widths = [max(len(row[i]) for row in cells) for i in range(len(header))]
    for index, row in enumerate(cells):
        print("| " + " | ".join(cell.ljust(width) for cell, width in zip(row, widths)) + " |")
        if index == 0:
            print("|" + "|".join("-" * (width + 2) for width in widths) + "|")


def verdict(ok: bool) -> str:
    return "yes" if ok else "**no**"


def failed(measured: Measure, allowed: tuple[int, ...]) -> str:
    return "" if measured.status in allowed else f" (exit {measured.status})"


# -- the measurements ----------------------------------------------------------
def compare_check(rows: list[Row], kind: str, links: int, path: Path, check_urdf: str | None) -> Measure:
    runs = RUNS[links]
    case = f"check, {kind} of {links:,} links"
    if kind == "chain" and links >= 100_000:
        # Both tools print the tree indented by depth: ~20 GB of spaces on a 100k chain.
        ours = measure(urdfcli("check", "--format", "concise", str(path)), runs)
        rows.append(Row(case + " (--format concise)", str(ours) + failed(ours, (0,)), "check_urdf: not run (its tree output would be ~20 GB)"))
        return ours
    ours = measure(urdfcli("check", str(path)), runs)
    if check_urdf is None:
        rows.append(Row(case, str(ours) + failed(ours, (0,)), "check_urdf: not installed"))
        return ours
    theirs = measure([check_urdf, str(path)], runs)
    row = Row(case, str(ours) + failed(ours, (0,)), f"check_urdf: {theirs}{failed(theirs, (0,))}", ours.seconds / theirs.seconds, ours.mib / theirs.mib)
    if kind == "tree" and links == 100_000:
        row.target = "time ≤ 0.5, memory ≤ 0.5"
        row.met = f"time {verdict(row.time_ratio <= 0.5)}, memory {verdict(row.memory_ratio <= 0.5)}"
    rows.append(row)
    return ours


def scaling(rows: list[Row], command: str, trees: dict[int, Path], known: dict[int, Measure] | None = None) -> None:
    case = f"{command}: 100k / 10k tree"
    measured = known or {links: measure(urdfcli(command, str(trees[links])), RUNS[links]) for links in (10_000, 100_000)}
    big, small = measured[100_000], measured[10_000]
    time_ratio, memory_ratio = big.seconds / small.seconds, big.mib / small.mib
    rows.append(
        Row(case, f"100k: {big}{failed(big, (0, 1))}", f"10k: {small}{failed(small, (0, 1))}", time_ratio, memory_ratio, "< 12 (time and memory)",
            verdict(time_ratio < 12 and memory_ratio < 12))
    )


def import_costs() -> str:
    """Where the start-up of ``urdfcli check SMALL`` goes, from ``python -X importtime``."""
    result = subprocess.run([sys.executable, "-X", "importtime", "-m", "urdfcli", "check", str(SMALL)], capture_output=True, text=True)
    cumulative: dict[str, int] = {}
    for line in result.stderr.splitlines():
        match = re.match(r"import time:\s+\d+ \|\s+(\d+) \|(\s*)(\S+)", line)
        if match:
            name = match.group(3)
            cumulative[name] = max(cumulative.get(name, 0), int(match.group(1)))
    shown = [f"{name} {cumulative[name] / 1000:.0f} ms" for name in ("urdfcli.cli", "typer", "pydantic", "rich.console", "networkx", "xacro", "lxml.etree") if name in cumulative]
    absent = [name for name in ("pydantic", "networkx", "xacro") if name not in cumulative]
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
    sources (an editable install under PYTHONDONTWRITEBYTECODE=1 would, every time)."""
    import urdfcli

    compileall.compile_dir(str(Path(urdfcli.__file__).parent), quiet=1)


def main() -> int:
    started = time.perf_counter()
    check_urdf = shutil.which("check_urdf")
    xacro = tool("xacro")
    GENERATED.mkdir(parents=True, exist_ok=True)
    print(f"machine: {machine()}", flush=True)
    compile_urdfcli()
    print("generating models in benchmarks/generated ...", flush=True)
    trees = {links: generate("tree", links) for links in SIZES}
    chains = {links: generate("chain", links) for links in SIZES}
    mixed = generate_mixed()
    sizes = sorted(p.stat().st_size for p in mixed)
    print(f"{len(mixed)} mixed models, {sizes[0] / 1024:.0f}-{sizes[-1] / 1024:.0f} KB", flush=True)

    rows: list[Row] = []
    print("measuring ...", flush=True)
    check_trees = {}
    for links in SIZES:
        check_trees[links] = compare_check(rows, "tree", links, trees[links], check_urdf)
    for links in SIZES:
        compare_check(rows, "chain", links, chains[links], check_urdf)

    files = [str(p) for p in mixed]
    ours = measure(urdfcli("check", *files), 5)
    case = f"{len(files)} mixed models: one `urdfcli check` vs a shell loop"
    if check_urdf:
        loop = ["bash", "-c", 'for f in "$@"; do "$0" "$f"; done', check_urdf, *files]
        theirs = measure(loop, 5)
        rows.append(Row(case, str(ours), f"check_urdf loop: {theirs}", ours.seconds / theirs.seconds, ours.mib / theirs.mib, "time < 1", verdict(ours.seconds < theirs.seconds)))
    else:
        rows.append(Row(case, str(ours), "check_urdf: not installed"))

    largest = max(FIXTURES.rglob("*.urdf.xacro"), key=lambda p: p.stat().st_size)
    ours = measure(urdfcli("expand", str(largest)), 7)
    case = f"expand {largest.relative_to(FIXTURES)}"
    if xacro:
        theirs = measure([xacro, str(largest)], 7)
        rows.append(Row(case, str(ours) + failed(ours, (0,)), f"xacro: {theirs}{failed(theirs, (0,))}", ours.seconds / theirs.seconds, ours.mib / theirs.mib, "time ≤ 1.10", verdict(ours.seconds <= 1.10 * theirs.seconds)))
    else:
        rows.append(Row(case, str(ours), "xacro: not installed"))

    ours = measure(urdfcli("check", str(SMALL)), 11)
    floor = measure([sys.executable, "-c", "import lxml.etree"], 11)
    reference = f"python -c 'import lxml.etree': {floor}"
    if check_urdf:
        reference += f" (check_urdf: {measure([check_urdf, str(SMALL)], 11)})"
    rows.append(Row(f"check, one small file ({SMALL.name})", str(ours) + failed(ours, (0,)), reference, ours.seconds / floor.seconds, ours.mib / floor.mib, "time ≤ 6", verdict(ours.seconds <= 6 * floor.seconds)))

    scaling(rows, "check", trees, {links: check_trees[links] for links in (10_000, 100_000)})
    scaling(rows, "tree", trees)
    scaling(rows, "lint", trees)

    print()
    print(f"Measured on {machine()}; medians of {RUNS[1_000]} runs (1k), {RUNS[10_000]} (10k) and {RUNS[100_000]} (100k), 5 to 11 for the rest.")
    print("Ratios are urdfcli / the other; memory is peak resident set size.")
    print()
    print_table(rows)
    print()
    print(import_costs())
    print(f"\nbenchmark run time: {time.perf_counter() - started:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
