"""What the pre-commit hook costs on a description repository when one xacro library changes.

Run with ``python benchmarks/hook.py`` in the venv that has urdfcli. It writes a
repository under ``benchmarks/generated/hook_repo``: two packages, 30 top-level
models, each including a shared wheel macro and one of ten part libraries
through ``$(find ...)``. A commit that changes ``gripper.xacro`` (included by
two of the models) runs ``urdfcli check LIBRARY``; the target is that this
stays under one second plus the cost of checking the two affected models
directly, i.e. finding them among the 30 costs less than a second. Reported,
never asserted.
"""

from __future__ import annotations

import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
REPO = ROOT / "benchmarks" / "generated" / "hook_repo"
MODELS = 30
XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def package_xml(name: str) -> str:
    return f'<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n  <version>0.1.0</version>\n</package>\n'


def part(name: str) -> str:
    return f"""<robot {XACRO}>
  <xacro:macro name="{name}" params="parent">
    <link name="{name}_link">
      <inertial><mass value="0.2"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
      <visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual>
      <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
    </link>
    <joint name="{name}_joint" type="fixed"><parent link="${{parent}}"/><child link="{name}_link"/></joint>
  </xacro:macro>
</robot>
"""


def model(index: int, parts: list[str]) -> str:
    includes = "".join(f'  <xacro:include filename="$(find acme_common)/urdf/{p}.xacro"/>\n' for p in parts)
    calls = "".join(f'  <xacro:{p} parent="base_link"/>\n' for p in parts)
    return f"""<robot name="robot_{index}" {XACRO}>
{includes}  <link name="base_footprint"/>
  <joint name="base_joint" type="fixed"><parent link="base_footprint"/><child link="base_link"/></joint>
  <link name="base_link">
    <inertial><mass value="5"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <visual><geometry><box size="0.4 0.4 0.4"/></geometry></visual>
    <collision><geometry><box size="0.4 0.4 0.4"/></geometry></collision>
  </link>
{calls}</robot>
"""


def generate() -> tuple[Path, list[Path]]:
    """The repository; the changed library and the models that include it."""
    shutil.rmtree(REPO, ignore_errors=True)
    (REPO / ".git").mkdir(parents=True)
    common, robots = REPO / "common", REPO / "robots"
    (common / "urdf").mkdir(parents=True)
    (robots / "urdf").mkdir(parents=True)
    (common / "package.xml").write_text(package_xml("acme_common"))
    (robots / "package.xml").write_text(package_xml("acme_robots"))
    names = ["wheel", "gripper", *(f"part_{i}" for i in range(10))]
    for name in names:
        (common / "urdf" / f"{name}.xacro").write_text(part(name))
    affected = []
    for index in range(MODELS):
        parts = ["wheel", f"part_{index % 10}"] + (["gripper"] if index in (3, 17) else [])
        path = robots / "urdf" / f"robot_{index:02d}.urdf.xacro"
        path.write_text(model(index, parts))
        if "gripper" in parts:
            affected.append(path)
    return common / "urdf" / "gripper.xacro", affected


def median_seconds(command: list[str], runs: int = 7) -> float:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        done = subprocess.run(command, cwd=REPO, capture_output=True)
        times.append(time.perf_counter() - start)
        if done.returncode != 0:
            sys.exit(f"{' '.join(command)} failed:\n{done.stdout.decode()}{done.stderr.decode()}")
    return statistics.median(times)


def main() -> int:
    library, affected = generate()
    urdfcli = [sys.executable, "-m", "urdfcli", "check", "--format", "concise"]
    hook = median_seconds([*urdfcli, str(library.relative_to(REPO))])
    direct = median_seconds([*urdfcli, *(str(p.relative_to(REPO)) for p in affected)])
    shared = median_seconds([*urdfcli, "common/urdf/wheel.xacro"], 3)
    every = median_seconds([*urdfcli, *(str(p.relative_to(REPO)) for p in sorted((REPO / "robots/urdf").glob("*.xacro")))], 3)
    print(f"{MODELS} models; gripper.xacro is included by {len(affected)}, wheel.xacro by all")
    print(f"check gripper.xacro (the hook):            {hook * 1000:.0f} ms")
    print(f"check the {len(affected)} affected models directly:    {direct * 1000:.0f} ms")
    print(f"finding them among {MODELS} models costs:        {(hook - direct) * 1000:.0f} ms (target < 1000 ms: {'met' if hook - direct < 1 else 'NOT met'})")
    print(f"check wheel.xacro (through all {MODELS}):       {shared * 1000:.0f} ms; the {MODELS} models directly: {every * 1000:.0f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
