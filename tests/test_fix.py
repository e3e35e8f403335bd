"""`lint --fix`, `--diff`, `--unsafe-fixes` and `--add-noqa`: the fixes urdfcli writes into
xacro, URDF and package.xml files.

Each case is a small package written as people write them; after `--fix` the finding is
gone, no other finding appears, every byte outside the edits is kept (the files are
compared whole), xacro's own expansion (the `xacro` program from PyPI) differs only at
the fixed elements, and a second `--fix` changes nothing. Values that come from an
expression, or from a property or parameter that cannot be edited alike everywhere, are
left alone, and the diagnostic says why. Every fixable rule's documented Example is
fixed too, and `lint --fix --diff` on the published models applies with `patch` and
leaves models check_urdf loads as before.
"""

from __future__ import annotations

import difflib
import json
import os
import re
import shutil
import subprocess
from collections import Counter
from pathlib import Path

import pytest
from conftest import example_robot_data, require_tool, run_cli
from models import CRATE
from differential import canonical
from support.meshes import box, example_package, write

from urdfcli.rules import REGISTRY, example_code

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


# -- helpers ---------------------------------------------------------------------------------
def put(root: Path, files: dict[str, str | bytes]) -> None:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(text if isinstance(text, bytes) else text.encode())


def snapshot(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def found_in(report: str) -> Counter:
    """What a JSON report holds, as (code, message) pairs: lines move when a fix adds one,
    so the FILE:LINE a message names is FILE:N."""
    return Counter((d["code"], re.sub(r"(\.\w+):\d+", r"\1:N", d["message"])) for f in json.loads(report)["files"] for d in f["diagnostics"])


def findings(cli, model: str, *options: str) -> Counter:
    return found_in(cli("lint", "--isolated", "--format", "json", *options, model).stdout)


def diagnostics(cli, model: str, *options: str) -> list[dict]:
    done = cli("lint", "--isolated", "--format", "json", *options, model)
    return [d for f in json.loads(done.stdout)["files"] for d in f["diagnostics"]]


def expansion(model: Path) -> list | None:
    """xacro's own output for a xacro model, canonical (None for a plain URDF)."""
    if not model.name.endswith(".xacro"):
        text = model.read_bytes().decode("latin-1" if b"ISO-8859-1" in model.read_bytes()[:60] else "utf-8")
    else:
        tool = require_tool("xacro")
        done = subprocess.run([tool, str(model)], capture_output=True, text=True, timeout=60, cwd=model.parent)
        assert done.returncode == 0, done.stderr
        text = done.stdout
    return [(tag, tuple(attributes), text, children) for tag, attributes, text, children in canonical(text)]


def changed_elements(before: list, after: list) -> list[str]:
    """The tags of the elements that differ between two canonical expansions."""
    found = []
    for op, a, b, c, d in difflib.SequenceMatcher(None, before, after, autojunk=False).get_opcodes():
        if op != "equal":
            found += [entry[0] for entry in before[a:b]] + [entry[0] for entry in after[c:d]]
    return sorted(set(found))


def fixed(cli, root: Path, model: str, code: str, *options: str, elements: tuple[str, ...]) -> dict[str, bytes]:
    """Fix ``model`` (in ``root``) and check what must hold of every fix: the finding of
    ``code`` gone, no new finding, the expansion changed only in ``elements``' tags (their
    counts may change only by an added child), a second --fix changing nothing. The files after."""
    before_files = snapshot(root)
    before = findings(cli, model, *options)
    assert any(c == code for c, _ in before), before
    expanded = expansion(root / model)
    done = cli("lint", "--isolated", "--fix", *options, model)
    assert "fixed, " in done.stdout, done.stdout
    after = findings(cli, model, *options)
    assert not any(c == code for c, _ in after), done.stdout
    assert not after - before, f"new findings: {after - before}"
    assert changed_elements(expanded, expansion(root / model)) == sorted(elements)
    files = snapshot(root)
    assert files != before_files
    again = cli("lint", "--isolated", "--fix", *options, model)
    assert re.search(r"^0 fixed, ", again.stdout, re.M) and snapshot(root) == files  # nothing left to fix: nothing changes
    return files


@pytest.fixture
def here(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    return tmp_path


# -- rpy and limits in degrees, lower above upper -----------------------------------------------
ARM = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base_link"/>
  <link name="arm_link"/>
  <!-- the arm turned a quarter turn -->
  <joint name="arm_joint" type="revolute">
    <parent link="base_link"/>
    <child link="arm_link"/>
    <origin xyz="0 0 0.1" rpy='0 0 90'/>
    <limit lower="1.57" upper="-1.57" effort="10" velocity="1"/>
  </joint>
</robot>
"""


def test_rpy_in_degrees_written_in_radians_only_where_it_was(cli, here):
    put(here, {"arm.urdf": ARM})
    files = fixed(cli, here, "arm.urdf", "V009", "--unsafe-fixes", elements=("origin", "limit"))
    assert files["arm.urdf"].decode() == ARM.replace("rpy='0 0 90'", "rpy='0 0 1.570796'").replace(
        'lower="1.57" upper="-1.57"', 'lower="-1.57" upper="1.57"')


def test_safe_fixes_only_without_unsafe_fixes(cli, here):
    put(here, {"arm.urdf": ARM})
    done = cli("lint", "--isolated", "--fix", "arm.urdf")
    assert (here / "arm.urdf").read_text() == ARM  # degrees and swapped limits change the robot: unsafe
    assert re.search(r"^0 fixed, ", done.stdout, re.M)
    assert "2 fixes available with --fix --unsafe-fixes" in done.stdout
    assert "fix (unsafe): write rpy=\"0 0 1.570796\" (radians)" in done.stdout


def test_limits_in_degrees(cli, here):
    text = ARM.replace('lower="1.57" upper="-1.57"', 'lower="-170" upper="170"').replace("'0 0 90'", "'0 0 0'")
    put(here, {"arm.urdf": text})
    files = fixed(cli, here, "arm.urdf", "J016", "--unsafe-fixes", elements=("limit",))
    assert files["arm.urdf"].decode() == text.replace('lower="-170" upper="170"', 'lower="-2.96706" upper="2.96706"')


# -- xacro: where the value was written ------------------------------------------------------------
MACROS = f"""<?xml version="1.0"?>
<robot name="rover" {XACRO_NS}>
  <xacro:property name="mount_yaw" value="90"/>
  <xacro:macro name="wheel" params="side roll">
    <link name="${{side}}_wheel"/>
    <joint name="${{side}}_wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="${{side}}_wheel"/>
      <origin xyz="0 0.2 0" rpy="${{roll}} 0 0"/>
    </joint>
  </xacro:macro>
  <link name="base_link"/>
  <link name="mast"/>
  <joint name="mast_joint" type="fixed">
    <parent link="base_link"/>
    <child link="mast"/>
    <origin rpy="0 0 ${{mount_yaw}}"/>
  </joint>
  <xacro:wheel side="left" roll="180"/>
  <xacro:wheel side="right" roll="-180"/>
</robot>
"""


def test_a_property_defined_once_and_each_macro_call_are_edited(cli, here):
    put(here, {"rover.urdf.xacro": MACROS})
    files = fixed(cli, here, "rover.urdf.xacro", "V009", "--unsafe-fixes", elements=("origin",))
    assert files["rover.urdf.xacro"].decode() == (
        MACROS.replace('value="90"', 'value="1.570796"').replace('roll="180"', 'roll="3.141593"').replace('roll="-180"', 'roll="-3.141593"')
    )


def test_a_value_computed_by_an_expression_is_left_alone_and_says_where(cli, here):
    text = MACROS.replace('rpy="0 0 ${mount_yaw}"', 'rpy="0 0 ${mount_yaw * 2}"').replace('roll="-180"', 'roll="${-90 * 2}"')
    put(here, {"rover.urdf.xacro": text})
    found = {d["line"]: d["fix"] for d in diagnostics(cli, "rover.urdf.xacro", "--select", "V009")}
    line = text[: text.index("${mount_yaw * 2}")].count("\n") + 1
    assert found[line]["available"] is False
    assert found[line]["reason"] == f"the value is computed by ${{mount_yaw * 2}} at rover.urdf.xacro:{line}"
    # the right wheel's roll is computed at its call; the left one's is a literal there
    done = cli("lint", "--isolated", "--fix", "--unsafe-fixes", "rover.urdf.xacro")
    assert "no fix: the value is computed by ${-90 * 2} at rover.urdf.xacro:20" in done.stdout
    assert (here / "rover.urdf.xacro").read_text() == text.replace('roll="180"', 'roll="3.141593"')


def test_a_property_read_negated_for_the_other_bound_is_edited_once(cli, here):
    """``lower="${-limit}" upper="${limit}"`` in a macro called twice: the property
    defined once is the one literal; written in radians, both bounds of both joints are."""
    text = f"""<?xml version="1.0"?>
<robot name="arm" {XACRO_NS}>
  <xacro:property name="elbow_limit" value="150"/>  <!-- the elbow's reach -->
  <xacro:macro name="segment" params="name parent">
    <link name="${{name}}"/>
    <joint name="${{name}}_joint" type="revolute">
      <parent link="${{parent}}"/>
      <child link="${{name}}"/>
      <limit lower="${{-elbow_limit}}" upper="${{elbow_limit}}" effort="50" velocity="2"/>
    </joint>
  </xacro:macro>
  <link name="base_link"/>
  <xacro:segment name="upper_arm" parent="base_link"/>
  <xacro:segment name="forearm" parent="upper_arm"/>
</robot>
"""
    put(here, {"arm.urdf.xacro": text})
    files = fixed(cli, here, "arm.urdf.xacro", "J016", "--unsafe-fixes", elements=("limit",))
    assert files["arm.urdf.xacro"].decode() == text.replace('value="150"', 'value="2.617994"')


def test_a_property_read_where_its_value_means_something_else_is_left_alone(cli, here):
    text = MACROS.replace('<link name="mast"/>', '<link name="mast"/>\n  <xacro:if value="${mount_yaw > 45}"><link name="flag"/></xacro:if>')
    put(here, {"rover.urdf.xacro": text})
    (mast,) = [d for d in diagnostics(cli, "rover.urdf.xacro", "--select", "V009") if "0 0 90" in d["message"]]
    line = text[: text.index("<xacro:if")].count("\n") + 1
    assert mast["fix"]["reason"] == f"the value is property 'mount_yaw', also read at rover.urdf.xacro:{line}, where it does not go into the model as such"


def test_a_property_defined_twice_is_left_alone(cli, here):
    text = MACROS.replace('<link name="mast"/>', '<link name="mast"/>\n  <xacro:property name="mount_yaw" value="90"/>')
    put(here, {"rover.urdf.xacro": text})
    (mast,) = [d for d in diagnostics(cli, "rover.urdf.xacro", "--select", "V009") if "0 0 90" in d["message"]]
    assert mast["fix"]["reason"] == "the value is property 'mount_yaw', defined 2 times (rover.urdf.xacro:3, rover.urdf.xacro:14)"


def test_a_literal_in_a_macro_body_is_edited_when_every_call_needs_it(cli, here):
    text = MACROS.replace('<origin xyz="0 0.2 0" rpy="${roll} 0 0"/>', '<origin xyz="0 0.2 0" rpy="${roll} 0 0"/>\n      <limit lower="1" upper="-1" effort="1" velocity="1"/>')
    text = text.replace('type="continuous"', 'type="revolute"')
    put(here, {"rover.urdf.xacro": text})
    files = fixed(cli, here, "rover.urdf.xacro", "J010", "--unsafe-fixes", "--select", "J010", elements=("limit",))
    assert files["rover.urdf.xacro"].decode() == text.replace('lower="1" upper="-1"', 'lower="-1" upper="1"')


# -- inertia: the tensor from the geometry ----------------------------------------------------------


def test_the_inertia_and_centre_of_mass_from_the_collision_geometry(cli, here):
    put(here, {"crate.urdf": CRATE})
    suggested = run_cli("inertia", "--suggest", "crate.urdf", cwd=here).stdout.decode()
    assert 'ixx="0.0216667"' in suggested and '<origin xyz="0 0 0.1"' in suggested
    files = fixed(cli, here, "crate.urdf", "I007", "--unsafe-fixes", elements=("inertia", "inertial", "origin"))
    assert files["crate.urdf"].decode() == CRATE.replace(
        '    <inertial>\n', '    <inertial>\n      <origin xyz="0 0 0.1" rpy="0 0 0"/>\n'
    ).replace('ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"', 'ixx="0.0216667" ixy="0" ixz="0" iyy="0.0333333" iyz="0" izz="0.0416667"')


@pytest.mark.parametrize(("code", "tensor"), [
    ("I004", 'ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"'),
    ("I005", 'ixx="0.02" ixy="0" ixz="0" iyy="0.03" iyz="0" izz="-0.04"'),
    ("I006", 'ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.04"'),
])
def test_a_wrong_tensor_is_written_from_the_geometry(cli, here, code, tensor):
    text = CRATE.replace('ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"', tensor).replace("<inertial>", '<inertial>\n      <origin xyz="0 0 0.1"/>')
    put(here, {"crate.urdf": text})
    files = fixed(cli, here, "crate.urdf", code, "--unsafe-fixes", elements=("inertia",))
    assert files["crate.urdf"].decode() == text.replace(tensor, 'ixx="0.0216667" ixy="0" ixz="0" iyy="0.0333333" iyz="0" izz="0.0416667"')


PARTS = f"""<?xml version="1.0"?>
<robot {XACRO_NS}>
  <xacro:macro name="box_inertia" params="m x y z">
    <inertial>
      <mass value="${{m}}"/>
      <inertia ixx="${{m*(y*y+z*z)/12}}" ixy="0" ixz="0" iyy="${{m*(x*x+z*z)/12}}" iyz="0" izz="${{m*(x*x+y*y)/12}}"/>
    </inertial>
  </xacro:macro>
  <xacro:macro name="fixed_inertia">
    <inertial>
      <mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>
    </inertial>
  </xacro:macro>
</robot>
"""
BODY = f"""<?xml version="1.0"?>
<robot name="bot" {XACRO_NS}>
  <xacro:include filename="parts.xacro"/>
  <link name="base_link"/>
  <link name="top">
    <xacro:box_inertia m="2" x="0.1" y="0.3" z="0.4"/>
    <collision><geometry><box size="0.4 0.3 0.1"/></geometry></collision>
  </link>
  <joint name="top_joint" type="continuous"><parent link="base_link"/><child link="top"/><axis xyz="0 0 1"/></joint>
  <link name="a"><xacro:fixed_inertia/><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <link name="b"><xacro:fixed_inertia/><collision><geometry><box size="0.3 0.2 0.1"/></geometry></collision></link>
  <joint name="a_joint" type="continuous"><parent link="base_link"/><child link="a"/><axis xyz="0 0 1"/></joint>
  <joint name="b_joint" type="continuous"><parent link="base_link"/><child link="b"/><axis xyz="0 0 1"/></joint>
</robot>
"""


def test_a_tensor_computed_by_a_macro_or_shared_by_calls_is_left_alone(cli, here):
    put(here, {"parts.xacro": PARTS, "bot.urdf.xacro": BODY})
    found = {(d["code"], d["message"].split("'")[1]): d["fix"] for d in diagnostics(cli, "bot.urdf.xacro") if d["code"].startswith("I")}
    top = found[("I009", "top")]
    assert top["reason"] == "the value is computed by ${m*(y*y+z*z)/12} at parts.xacro:6"
    # the same literal tensor for two links of other sizes: one edit cannot fit both
    shared = [fix for (code, link), fix in found.items() if link in ("a", "b")]
    assert shared and all(f["reason"] and "would also change" in f["reason"] for f in shared), found
    before = snapshot(here)
    cli("lint", "--isolated", "--fix", "--unsafe-fixes", "bot.urdf.xacro")
    assert snapshot(here) == before


def test_a_number_xacro_writes_its_own_way_is_edited_at_the_call(cli, here):
    """myCobot's arm passes izz="0.000096" to its link_inertial macro, and xacro writes the
    ${izz} it reads as 9.6e-05: the literal at the call is still the value to edit."""
    text = f"""<?xml version="1.0"?>
<robot name="r" {XACRO_NS}>
  <xacro:macro name="link_inertial" params="mass ixx iyy izz">
    <inertial>
      <mass value="${{mass}}"/>
      <inertia ixx="${{ixx}}" ixy="0" ixz="0" iyy="${{iyy}}" iyz="0" izz="${{izz}}"/>
    </inertial>
  </xacro:macro>
  <link name="base"/>
  <link name="arm">
    <collision><geometry><box size="0.1 0.1 1.0"/></geometry></collision>
    <xacro:link_inertial mass="2" ixx="0.000096" iyy="1e-4" izz=" 0.000096 "/>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""
    put(here, {"robot.urdf.xacro": text})
    files = fixed(cli, here, "robot.urdf.xacro", "I009", "--unsafe-fixes", elements=("inertia",))
    assert files["robot.urdf.xacro"].decode() == text.replace(
        'ixx="0.000096" iyy="1e-4" izz=" 0.000096 "', 'ixx="0.168333" iyy="0.168333" izz=" 0.00333333 "')


SEGMENT = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="seg" params="name parent size">
    <joint name="${name}_joint" type="revolute"><parent link="${parent}"/><child link="${name}"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
    <link name="${name}">
      <collision><geometry><box size="${size} ${size} ${size}"/></geometry></collision>
      <inertial>
        <mass value="1"/>
        <inertia ixx="0.00166667" ixy="0" ixz="0" iyy="0.00166667" iyz="0" izz="0.00166667"/>
      </inertial>
    </link>
  </xacro:macro>
</robot>
"""


def segment_models(here) -> None:
    """Two models of one package calling seg: a with a 0.1 m box (the tensor fits), b with a 1 m box."""
    model = '<?xml version="1.0"?>\n<robot name="{n}" xmlns:xacro="http://www.ros.org/wiki/xacro">\n' \
            '  <xacro:include filename="$(find pkg)/urdf/seg.xacro"/>\n  <link name="base_link"/>\n' \
            '  <xacro:seg name="s1" parent="base_link" size="{size}"/>\n</robot>\n'
    put(here, {"pkg/package.xml": '<package format="3"><name>pkg</name></package>\n', "pkg/urdf/seg.xacro": SEGMENT,
               "pkg/urdf/a.urdf.xacro": model.format(n="a", size="0.1"), "pkg/urdf/b.urdf.xacro": model.format(n="b", size="1.0")})
    (here / ".git").mkdir()


def test_fixes_that_undo_each_other_stop_and_are_not_counted(cli, here):
    """b's fix of seg.xacro's tensor makes it wrong for a, and a's fix undoes it, round after
    round: the fixing stops where it started, says 0 fixed, and writes nothing (it said 10 fixed)."""
    segment_models(here)
    before = snapshot(here)
    done = cli("lint", "--isolated", "--fix", "--unsafe-fixes", "pkg")
    assert re.search(r"^0 fixed, ", done.stdout, re.M) and snapshot(here) == before, done.stdout


def test_an_unsafe_fix_in_a_macro_another_model_expands_is_not_applied(cli, here):
    """b's fix of the tensor in seg.xacro's body would give model a, whose 0.1 m box it fits,
    a tensor a hundred times too large: fixing b alone leaves seg.xacro as it is, says why in
    one line and counts no fix (it wrote the tensor and said 1 fixed)."""
    segment_models(here)
    before, a_found = snapshot(here), findings(cli, "pkg/urdf/a.urdf.xacro")
    done = run_cli("lint", "--isolated", "--fix", "--unsafe-fixes", "pkg/urdf/b.urdf.xacro", cwd=here)
    assert snapshot(here) == before
    assert done.stderr.decode() == ("urdfcli: pkg/urdf/seg.xacro:9: I009 not fixed: macro 'seg', whose body it edits, "
                                    "is also expanded by pkg/urdf/a.urdf.xacro, which is not among the models fixed\n")
    assert re.search(r"^0 fixed, 1 remaining", done.stdout.decode(), re.M) and done.returncode == 1
    assert findings(cli, "pkg/urdf/a.urdf.xacro") == a_found


@pytest.mark.parametrize("given", [("pkg/urdf/a.urdf.xacro", "pkg/urdf/b.urdf.xacro"), ("pkg/urdf/seg.xacro",), ("-j", "2", "pkg/urdf/seg.xacro")])
def test_a_fix_in_a_macro_body_is_applied_when_every_model_expanding_it_is_fixed(cli, here, given):
    """Both models with a 1 m box: the one tensor fits both, and is written when both are fixed,
    given by name or through the library they are checked through (in other processes too)."""
    segment_models(here)
    put(here, {"pkg/urdf/a.urdf.xacro": (here / "pkg/urdf/a.urdf.xacro").read_text().replace('size="0.1"', 'size="1.0"')})
    done = run_cli("lint", "--isolated", "--fix", "--unsafe-fixes", "--select", "I009", *given, cwd=here)
    assert (done.returncode, done.stderr.decode()) == (0, ""), done.stdout.decode()
    assert re.search(r"^1 fixed, 0 remaining", done.stdout.decode(), re.M) and 'ixx="0.166667"' in (here / "pkg/urdf/seg.xacro").read_text()


@pytest.mark.parametrize("given", ['size="$(arg size)"', 'size="${size}"'])
def test_an_inertial_worked_out_from_a_xacro_argument_is_not_written_as_literals(cli, here, given):
    """xArm's other_geometry: the box's size comes from an argument (through the macro's call, or
    a property). A tensor worked out for this argument set, written as literals in the macro
    body, would be wrong with any other: no fix, saying where the argument comes in."""
    segment_models(here)
    model = here / "pkg/urdf/a.urdf.xacro"
    property_ = '  <xacro:property name="size" value="$(arg size)"/>\n' if "${" in given else ""
    model.write_text(model.read_text().replace('size="0.1"', given).replace(
        "  <xacro:include", f'  <xacro:arg name="size" default="1.0"/>\n{property_}  <xacro:include'))
    [found] = [d for d in diagnostics(cli, "pkg/urdf/a.urdf.xacro") if d["code"] == "I009"]
    assert found["fix"]["reason"] == ('the new values would be worked out from size="${size} ${size} ${size}" at pkg/urdf/seg.xacro:6, '
                                      "which $(arg size) gives: they would fit this argument set only"), found["fix"]
    before = snapshot(here)
    cli("lint", "--isolated", "--fix", "--unsafe-fixes", "--select", "I009", "pkg/urdf/a.urdf.xacro")
    assert snapshot(here) == before


# -- meshes and packages ---------------------------------------------------------------------------
PACKAGE = """<?xml version="1.0"?>
<package format="3">
  <name>my_robot</name>
  <version>0.1.0</version>
  <description>A robot</description>
  <maintainer email="me@example.com">me</maintainer>
  <license>BSD</license>

  <buildtool_depend>ament_cmake</buildtool_depend>
  <exec_depend>robot_state_publisher</exec_depend>  <!-- publishes the TF tree -->
\t<exec_depend>xacro</exec_depend>

  <export>
    <build_type>ament_cmake</build_type>
  </export>
</package>
"""
MESHES = """<package format="3"><name>robot_meshes</name><version>1.0.0</version><description>meshes</description>
<maintainer email="me@example.com">me</maintainer><license>BSD</license></package>
"""
MODEL = f"""<?xml version="1.0"?>
<robot name="r" {XACRO_NS}>
  <xacro:property name="meshes" value="robot_meshes"/>
  <link name="base_link">
    <visual><geometry><mesh filename="package://${{meshes}}/meshes/arm.STL"/></geometry></visual>
    <collision><geometry><mesh filename="package://robot_meshes/meshes/arm.stl"/></geometry></collision>
  </link>
</robot>
"""


@pytest.fixture
def workspace(here):
    put(here, {"src/my_robot/package.xml": PACKAGE, "src/my_robot/urdf/robot.urdf.xacro": MODEL, "src/robot_meshes/package.xml": MESHES})
    write(here / "src/robot_meshes/meshes/arm.stl", box())
    (here / ".git").mkdir()
    return here


def test_a_dependency_is_declared_after_the_last_of_its_kind_in_its_indentation(cli, workspace):
    model = "src/my_robot/urdf/robot.urdf.xacro"
    files = fixed(cli, workspace, model, "P001", "--select", "P001", elements=())
    assert files["src/my_robot/package.xml"].decode() == PACKAGE.replace(
        "\t<exec_depend>xacro</exec_depend>\n", "\t<exec_depend>xacro</exec_depend>\n\t<exec_depend>robot_meshes</exec_depend>\n"
    )
    assert files[model].decode() == MODEL


@pytest.mark.parametrize(("manifest", "declared"), [
    ('<package format="2">\n  <name>my_robot</name>\n  <export/>\n</package>\n', '<package format="2">\n  <name>my_robot</name>\n  <exec_depend>robot_meshes</exec_depend>\n  <export/>\n</package>\n'),
    ('<package>\n  <name>my_robot</name>\n  <build_depend>catkin</build_depend>\n</package>\n', '<package>\n  <name>my_robot</name>\n  <build_depend>catkin</build_depend>\n  <run_depend>robot_meshes</run_depend>\n</package>\n'),
], ids=["before-export", "format-1"])
def test_a_dependency_in_a_manifest_without_one_of_its_kind(cli, workspace, manifest, declared):
    put(workspace, {"src/my_robot/package.xml": manifest})
    report = json.loads(cli("lint", "--isolated", "--format", "json", "--select", "P001", "src/my_robot/urdf/robot.urdf.xacro").stdout)
    [diagnostic] = report["files"][0]["diagnostics"]
    added = next(line.strip() for line in declared.split("\n") if "robot_meshes" in line)
    assert diagnostic["hint"].startswith(f"add {added} to src/my_robot/package.xml")  # the line the fix adds (format 1: no <exec_depend>)
    cli("lint", "--isolated", "--fix", "--select", "P001", "src/my_robot/urdf/robot.urdf.xacro")
    assert (workspace / "src/my_robot/package.xml").read_text() == declared


def test_description_packages_using_each_other_get_run_dependencies_only(cli, here):
    """Baxter's model includes its grippers' xacro from rethink_ee_description, whose
    fingers load meshes from baxter_description. Both are read where the model is
    expanded and loaded, not to build: a <build_depend> each way (what the fix wrote)
    is a cycle in catkin's build order, and catkin stops."""
    manifest = '<?xml version="1.0"?>\n<package>\n  <name>{}</name>\n  <buildtool_depend>catkin</buildtool_depend>\n</package>\n'
    put(here, {
        "robot_description/package.xml": manifest.format("robot_description"),
        "robot_description/urdf/robot.urdf.xacro": f"""<?xml version="1.0"?>
<robot name="r" {XACRO_NS}>
  <xacro:include filename="$(find gripper_description)/urdf/gripper.xacro"/>
  <link name="base_link"/>
  <xacro:gripper parent="base_link"/>
</robot>
""",
        "gripper_description/package.xml": manifest.format("gripper_description"),
        "gripper_description/urdf/gripper.xacro": f"""<?xml version="1.0"?>
<robot {XACRO_NS}>
  <xacro:macro name="gripper" params="parent">
    <link name="finger"><visual><geometry><mesh filename="package://robot_description/meshes/finger.stl"/></geometry></visual></link>
    <joint name="finger_joint" type="fixed"><parent link="${{parent}}"/><child link="finger"/></joint>
  </xacro:macro>
</robot>
""",
    })
    write(here / "robot_description/meshes/finger.stl", box())
    (here / ".git").mkdir()
    model = "robot_description/urdf/robot.urdf.xacro"
    assert [c for c, _ in findings(cli, model, "--select", "P001")] == ["P001", "P001"]
    cli("lint", "--isolated", "--fix", "--select", "P001", model)  # (xacro's $(find) needs ROS: no expansion compared)
    assert findings(cli, model, "--select", "P001") == Counter()
    files = snapshot(here)
    added = "  <buildtool_depend>catkin</buildtool_depend>\n  <run_depend>{}</run_depend>\n"
    assert files["robot_description/package.xml"].decode() == manifest.format("robot_description").replace(
        "  <buildtool_depend>catkin</buildtool_depend>\n", added.format("gripper_description"))
    assert files["gripper_description/package.xml"].decode() == manifest.format("gripper_description").replace(
        "  <buildtool_depend>catkin</buildtool_depend>\n", added.format("robot_description"))


def test_a_mesh_name_fixed_in_the_literal_part_of_a_computed_uri(cli, workspace):
    model = "src/my_robot/urdf/robot.urdf.xacro"
    files = fixed(cli, workspace, model, "D004", "--select", "D004", elements=("mesh",))
    assert files[model].decode() == MODEL.replace("/meshes/arm.STL", "/meshes/arm.stl")


def test_absolute_and_file_uris_become_package_uris(cli, workspace):
    mesh = workspace / "src/robot_meshes/meshes/arm.stl"
    text = MODEL.replace("package://${meshes}/meshes/arm.STL", f"file://{mesh}").replace("package://robot_meshes/meshes/arm.stl", str(mesh))
    put(workspace, {"src/my_robot/urdf/robot.urdf.xacro": text})
    model = "src/my_robot/urdf/robot.urdf.xacro"
    files = fixed(cli, workspace, model, "F002", "--select", "F002", elements=("mesh",))
    assert files[model].decode() == MODEL.replace("package://${meshes}/meshes/arm.STL", "package://robot_meshes/meshes/arm.stl")


def test_a_relative_mesh_path_is_left_to_its_author(cli, workspace):
    text = MODEL.replace("package://${meshes}/meshes/arm.STL", "../../robot_meshes/meshes/arm.stl")
    put(workspace, {"src/my_robot/urdf/robot.urdf.xacro": text})
    (flagged,) = diagnostics(cli, "src/my_robot/urdf/robot.urdf.xacro", "--select", "F002")
    assert flagged["fix"]["reason"].startswith("a relative path is what MuJoCo, PyBullet and Drake read")


def test_a_millimetre_mesh_is_scaled(cli, here):
    example_package(here / "my_robot")
    put(here, {"my_robot/package.xml": '<package format="2"><name>my_robot</name></package>\n', "my_robot/urdf/arm.urdf": """<robot name="arm">
  <link name="arm">
    <inertial>
      <mass value="5"/>
      <inertia ixx="0.0708" ixy="0" ixz="0" iyy="0.0708" iyz="0" izz="0.0083"/>
    </inertial>
    <visual><geometry><mesh filename="package://my_robot/meshes/arm_mm.stl"/></geometry></visual>
  </link>
</robot>
"""})
    files = fixed(cli, here, "my_robot/urdf/arm.urdf", "F003", "--unsafe-fixes", "--select", "F003", elements=("mesh",))
    assert 'filename="package://my_robot/meshes/arm_mm.stl" scale="0.001 0.001 0.001"/>' in files["my_robot/urdf/arm.urdf"].decode()


# -- xacro's deprecated forms and unprefixed tags -------------------------------------------------
def test_deprecated_forms_xacro_still_reads_are_rewritten(cli, here):
    text = f"""<?xml version="1.0"?>
<robot name="r" {XACRO_NS}>
  <xacro:macro name="xacro:part" params="n">
    <link name="part_${{n}}"/>
  </xacro:macro>
  <xacro:property name="sizes" value="${{list(range(2))}}"/>
  <link name="base_link"/>
  <xacro:part n="${{sizes[1]}}"/>
  <joint name="j" type="fixed"><parent link="base_link"/><child link="part_1"/></joint>
</robot>
"""
    put(here, {"r.urdf.xacro": text})
    files = fixed(cli, here, "r.urdf.xacro", "X005", elements=())
    assert files["r.urdf.xacro"].decode() == text.replace('name="xacro:part"', 'name="part"').replace("list(range(2))", "list(python.range(2))")


def test_an_unprefixed_include_is_prefixed_and_read(cli, here):
    text = '<?xml version="1.0"?>\n<robot name="r">\n  <include filename="arm.xacro"/>\n  <link name="base_link"/>\n</robot>\n'
    arm = f'<robot {XACRO_NS}>\n  <link name="arm"/>\n</robot>\n'
    put(here, {"r.urdf.xacro": text, "arm.xacro": arm})
    before = expansion(here / "r.urdf.xacro")
    done = cli("lint", "--isolated", "--fix", "--unsafe-fixes", "--select", "X107", "r.urdf.xacro")
    assert re.search(r"^1 fixed, 0 remaining", done.stdout, re.M)
    assert (here / "r.urdf.xacro").read_text() == text.replace("<include", "<xacro:include").replace('<robot name="r">', f'<robot name="r" {XACRO_NS}>')
    after = expansion(here / "r.urdf.xacro")
    # xacro now reads the include: the element it copied is gone, the arm it includes is there
    assert [e[0] for e in before] == ["robot", "include", "link"] and [e[0] for e in after] == ["robot", "link", "link"]


# -- a generated URDF that drifted from its xacro ---------------------------------------------------
def test_a_drifted_generated_urdf_is_regenerated_under_its_own_header(cli, here):
    source = f'<robot name="kr" {XACRO_NS}>\n  <link name="link_6"/>\n  <link name="flange"/>\n' \
             '  <joint name="flange_joint" type="fixed"><parent link="link_6"/><child link="flange"/></joint>\n</robot>\n'
    header = '<?xml version="1.0" ?>\r\n<!-- | This document was autogenerated by xacro from /home/ci/ws/src/kr/urdf/kr.xacro | -->\r\n'
    urdf = header + '<robot name="kr">\r\n  <link name="link_6"/>\r\n</robot>\r\n'
    put(here, {"urdf/kr.xacro": source, "urdf/kr.urdf": urdf})
    done = cli("lint", "--isolated", "--fix", "--unsafe-fixes", "--select", "X110", "urdf/kr.urdf")
    assert re.search(r"^1 fixed, 0 remaining", done.stdout, re.M), done.stdout
    written = (here / "urdf/kr.urdf").read_bytes().decode()
    assert written.startswith(header + '<robot name="kr">\r\n')  # the header and the line ends kept
    assert '<link name="flange"/>' in written and expansion(here / "urdf/kr.urdf") == expansion(here / "urdf/kr.xacro")
    again = cli("lint", "--isolated", "--fix", "--unsafe-fixes", "--select", "X110", "urdf/kr.urdf")
    assert re.search(r"^0 fixed, 0 remaining", again.stdout, re.M) and (here / "urdf/kr.urdf").read_bytes().decode() == written


# -- what is kept, byte for byte -----------------------------------------------------------------------
def test_every_byte_outside_the_edits_is_kept(cli, here):
    text = ("<?xml version='1.0' encoding='ISO-8859-1'?>\r\n<!-- Bras articul\xe9 -->\r\n<robot name='arm'>\r\n"
            "\t<link name='base_link'/>\r\n\t<link name='arm_link'/>\r\n"
            "\t<joint name='arm_joint' type='revolute'>  <!-- l'\xe9paule -->\r\n"
            "\t\t<parent link='base_link'/>\r\n\t\t<child link='arm_link'/>\r\n"
            "\t\t<origin rpy='0  0\t90' xyz=\"0 0 0.1\"/>\r\n"
            "\t\t<limit upper='-1.57' effort='10' lower='1.57' velocity='1'/>\r\n\t</joint>\r\n</robot>")
    data = text.encode("latin-1")
    put(here, {"arm.urdf": data})
    cli("lint", "--isolated", "--fix", "--unsafe-fixes", "arm.urdf")
    expected = data.replace(b"rpy='0  0\t90'", b"rpy='0  0\t1.570796'").replace(b"upper='-1.57'", b"upper='1.57'").replace(b"lower='1.57'", b"lower='-1.57'")
    assert (here / "arm.urdf").read_bytes() == expected


def test_diff_writes_nothing_and_applies_with_patch(cli, here):
    put(here, {"rover.urdf.xacro": MACROS, "arm.urdf": ARM.replace("\n", "\r\n")})
    before = snapshot(here)
    done = run_cli("lint", "--isolated", "--diff", "--unsafe-fixes", "rover.urdf.xacro", "arm.urdf", cwd=here)
    assert done.returncode == 1 and snapshot(here) == before
    assert done.stderr.decode().endswith("would apply 5 fixes in 2 files\n")
    patched = here / "patched"
    shutil.copytree(here, patched, ignore=shutil.ignore_patterns("patched"))
    applied = subprocess.run([require_tool("patch"), "-p1", "--binary"], input=done.stdout, cwd=patched, capture_output=True)
    assert applied.returncode == 0, applied.stdout
    run_cli("lint", "--isolated", "--fix", "--unsafe-fixes", "rover.urdf.xacro", "arm.urdf", cwd=here)
    assert snapshot(patched) == {k: v for k, v in snapshot(here).items() if not k.startswith("patched/")}
    nothing = run_cli("lint", "--isolated", "--diff", "--unsafe-fixes", "rover.urdf.xacro", "arm.urdf", cwd=here)
    assert (nothing.returncode, nothing.stdout) == (0, b"")


LATIN_1_ARM = (  # a fixed line that holds a character of the declared encoding
    "<?xml version='1.0' encoding='ISO-8859-1'?>\n<robot name='arm'>\n  <link name='base_link'/>\n  <link name='arm_link'/>\n"
    "  <joint name='arm_joint' type='revolute'><parent link='base_link'/><child link='arm_link'/>\n"
    "    <limit lower='1.57' upper='-1.57' effort='10' velocity='1'/> <!-- \xe9paule -->\n  </joint>\n</robot>\n"
).encode("latin-1")


def test_the_diff_of_a_file_in_another_encoding_applies_with_patch(here):
    put(here, {"arm.urdf": LATIN_1_ARM})
    done = run_cli("lint", "--isolated", "--diff", "--unsafe-fixes", "arm.urdf", cwd=here)
    assert done.returncode == 1 and b"-    <limit lower='1.57' upper='-1.57' effort='10' velocity='1'/> <!-- \xe9paule -->\n" in done.stdout
    applied = subprocess.run([require_tool("patch"), "-p1"], input=done.stdout, cwd=here, capture_output=True)
    assert applied.returncode == 0, applied.stdout
    assert (here / "arm.urdf").read_bytes() == LATIN_1_ARM.replace(b"lower='1.57' upper='-1.57'", b"lower='-1.57' upper='1.57'")


def test_the_diff_names_a_file_given_by_its_absolute_path_as_patch_finds_it(here):
    put(here, {"urdf/arm.urdf": ARM})
    done = run_cli("lint", "--isolated", "--diff", "--unsafe-fixes", str(here / "urdf" / "arm.urdf"), cwd=here)
    assert done.stdout.startswith(b"--- a/urdf/arm.urdf\n+++ b/urdf/arm.urdf\n"), done.stdout[:200]
    applied = subprocess.run([require_tool("patch"), "-p1"], input=done.stdout, cwd=here, capture_output=True)
    assert applied.returncode == 0, applied.stdout


def test_the_diff_of_files_above_the_working_folder_applies_as_standard_error_says(here):
    """`--diff ../other/urdf/arm.urdf` named it a/../other/urdf/arm.urdf, which patch (and git
    apply) refuse: the paths of the whole diff are relative to the nearest folder above that
    holds every file, and the command printed applies it from the working folder, as --fix
    would have written them."""
    put(here, {"other/urdf/arm.urdf": ARM, "work/arm.urdf": ARM, "fixed/other/urdf/arm.urdf": ARM, "fixed/work/arm.urdf": ARM})
    work = here / "work"
    done = run_cli("lint", "--isolated", "--diff", "--unsafe-fixes", "arm.urdf", "../other/urdf/arm.urdf", cwd=work)
    names = re.findall(rb"^(?:---|\+\+\+) (\S+)", done.stdout, re.M)
    assert names == [b"a/work/arm.urdf", b"b/work/arm.urdf", b"a/other/urdf/arm.urdf", b"b/other/urdf/arm.urdf"], done.stdout
    said = done.stderr.decode()
    assert said.endswith("the paths are relative to ..: apply the diff with `patch -p1 -d ..`\n"), said
    command = re.search(r"`patch (.*)`", said).group(1).split()
    applied = subprocess.run([require_tool("patch"), *command], input=done.stdout, cwd=work, capture_output=True)
    assert applied.returncode == 0, applied.stdout
    run_cli("lint", "--isolated", "--fix", "--unsafe-fixes", "work/arm.urdf", "other/urdf/arm.urdf", cwd=here / "fixed")
    for name in ("work/arm.urdf", "other/urdf/arm.urdf"):
        assert (here / name).read_bytes() == (here / "fixed" / name).read_bytes() != ARM.encode()
    # every file below the working folder: named from it, and no line about where to apply it
    put(here, {"below/urdf/arm.urdf": ARM})
    below = run_cli("lint", "--isolated", "--diff", "--unsafe-fixes", "urdf/arm.urdf", cwd=here / "below")
    assert below.stdout.startswith(b"--- a/urdf/arm.urdf\n") and b"relative to" not in below.stderr


def test_a_fixed_file_reached_through_a_symbolic_link_is_written_where_it_is(cli, here):
    put(here, {"description/urdf/arm.urdf": ARM})
    (here / "arm.urdf").symlink_to(here / "description" / "urdf" / "arm.urdf")
    cli("lint", "--isolated", "--fix", "--unsafe-fixes", "arm.urdf")
    assert (here / "arm.urdf").is_symlink()  # the link kept, the file it names fixed
    assert (here / "description/urdf/arm.urdf").read_text() != ARM and "rpy='0 0 1.570796'" in (here / "arm.urdf").read_text()


def test_add_noqa_silences_what_remains(cli, here):
    put(here, {"arm.urdf": ARM})
    done = cli("lint", "--isolated", "--add-noqa", "arm.urdf")
    assert done.exit_code == 0 and "noqa comment" in done.stdout
    written = (here / "arm.urdf").read_text()
    assert "  <!-- urdfcli: noqa: " in written and "V009" in written and "J010" in written
    assert cli("lint", "--isolated", "arm.urdf").exit_code == 0
    assert cli("lint", "--isolated", "--add-noqa", "arm.urdf").stdout.count("noqa comment") == 0
    assert (here / "arm.urdf").read_text() == written


def test_add_noqa_exits_as_lint_does_for_what_no_comment_silences(cli, here):
    """A file that is not XML (X001) is reported whatever the comments say: after --add-noqa
    silenced arm.urdf, the run exits 1 as the lint after it does, and says what remains
    (it exited 0)."""
    put(here, {"arm.urdf": ARM, "broken.urdf": '<robot name="r">\n  <link name="a">\n</robot>\n'})
    done = cli("lint", "--isolated", "--add-noqa", "arm.urdf", "broken.urdf")
    assert re.search(r"^\d+ noqa comments written, 1 remaining$", done.stdout, re.M), done.stdout
    after = cli("lint", "--isolated", "--format", "concise", "arm.urdf", "broken.urdf")
    assert [line.split()[1] for line in after.stdout.splitlines() if line.startswith(("arm", "broken"))] == ["X001"], after.stdout
    assert done.exit_code == after.exit_code == 1
    assert cli("lint", "--isolated", "--add-noqa", "--exit-zero", "broken.urdf").exit_code == 0


def test_add_noqa_writes_no_comment_for_a_model_xacro_cannot_expand(cli, here):
    """X003 (and X004) stop the expansion: no model is checked, whatever a comment says. The
    comment --add-noqa wrote silenced nothing and the run exited 0; the editor offered it too."""
    put(here, {"r.urdf.xacro": f'<robot name="r" {XACRO_NS}>\n  <link name="${{nope}}"/>\n</robot>\n'})
    done = cli("lint", "--isolated", "--add-noqa", "r.urdf.xacro")
    assert "noqa" not in (here / "r.urdf.xacro").read_text()
    assert re.search(r"^0 noqa comments written, 1 remaining$", done.stdout, re.M), done.stdout
    assert done.exit_code == 1


def test_add_noqa_silences_a_finding_on_the_whole_file_with_a_noqa_file_comment(cli, here):
    """A drifted generated URDF (X110, at its XML declaration) and a library no model
    could check (X006, no line): a noqa-file comment, after the declaration."""
    declaration = '<?xml version="1.0" ?>\n'
    header = '<!-- | This document was autogenerated by xacro from kr.xacro | -->\n'
    drifted = '<robot name="kr">\n  <link name="link_6"/>\n</robot>\n'
    library = f'<robot {XACRO_NS}>\n  <xacro:macro name="tool" params="parent">\n    <link name="${{parent}}_tool"/>\n  </xacro:macro>\n</robot>\n'
    put(here, {".git/HEAD": "", "urdf/kr.xacro": f'<robot name="kr" {XACRO_NS}>\n  <link name="link_6"/>\n  <link name="flange"/>\n'
               '  <joint name="j" type="fixed"><parent link="link_6"/><child link="flange"/></joint>\n</robot>\n',
               "urdf/kr.urdf": declaration + header + drifted,
               "urdf/tool.xacro": library,
               "urdf/arm.urdf.xacro": f'<robot name="arm" {XACRO_NS}>\n  <xacro:include filename="tool.xacro"/>\n'
               '  <link name="base_link"/>\n  <xacro:tool parent="$(arg base)"/>\n</robot>\n'})
    before = run_cli("lint", "--format", "concise", "--select", "X110,X006", "urdf/kr.urdf", "urdf/tool.xacro", cwd=here)
    assert before.returncode == 1 and "X110 warning" in before.stdout.decode() and "X006 warning" in before.stdout.decode()
    done = run_cli("lint", "--add-noqa", "--select", "X110,X006", "urdf/kr.urdf", "urdf/tool.xacro", cwd=here)
    assert "2 noqa comments written" in done.stdout.decode(), done.stdout.decode()
    assert (here / "urdf/kr.urdf").read_text() == declaration.rstrip("\n") + "\n<!-- urdfcli: noqa-file: X110 -->\n" + header + drifted
    assert (here / "urdf/tool.xacro").read_text() == "<!-- urdfcli: noqa-file: X006 -->\n" + library
    after = run_cli("lint", "--select", "X110,X006", "urdf/kr.urdf", "urdf/tool.xacro", cwd=here)
    assert after.returncode == 0, after.stdout.decode()


def test_configuration_turns_fixing_on(cli, here):
    put(here, {"arm.urdf": ARM, "pyproject.toml": "[tool.urdfcli]\nfix = true\nunsafe-fixes = true\n"})
    done = cli("lint", "arm.urdf")
    assert re.search(r"^2 fixed, 0 remaining", done.stdout, re.M) and "1.570796" in (here / "arm.urdf").read_text()
    put(here, {"arm.urdf": ARM, "pyproject.toml": "[tool.urdfcli]\nfix = 1\n"})
    assert "fix: expected true or false" in run_cli("lint", "arm.urdf", cwd=here).stderr.decode()


def test_check_fixes_what_check_finds(cli, here):
    put(here, {"arm.urdf": ARM})
    done = run_cli("check", "--isolated", "--fix", "--unsafe-fixes", "arm.urdf", cwd=here)
    assert done.returncode == 0 and "2 fixed, 0 remaining" in done.stdout.decode()
    assert "rpy='0 0 1.570796'" in (here / "arm.urdf").read_text()


def test_standard_input_is_never_written_back(here):
    done = run_cli("lint", "--fix", "-", input=ARM, cwd=here)
    assert done.returncode == 2 and "cannot write standard input back" in done.stderr.decode()
    diff = run_cli("lint", "--diff", "--unsafe-fixes", "-", input=ARM, cwd=here)
    assert diff.returncode == 1 and b"+    <origin xyz=\"0 0 0.1\" rpy='0 0 1.570796'/>" in diff.stdout


# -- every fixable rule: its documented Example fixed ------------------------------------------------
# P001 needs a package.xml beside its files, X005's Example is a warning without a fix, X110's a
# generated URDF beside its xacro source, F002's a relative path (left to its author): they are
# fixed above. The Examples of I004, I005 and I006 have no geometry to take a tensor from:
# "I004", "I005" and "I006" are fixed below.
FIXABLE = sorted(code for code, rule in REGISTRY.items() if rule.fixable is not None)
WITHOUT_EXAMPLE_FIX = {"P001", "X005", "X110", "F002", "I004", "I005", "I006"}


def test_every_fixable_rule_whose_example_is_not_fixed_has_a_case_of_its_own():
    text = Path(__file__).read_text()
    assert len(FIXABLE) >= 15
    assert all(text.count(f'"{code}"') >= 2 for code in WITHOUT_EXAMPLE_FIX)  # the set above, and its case


@pytest.mark.parametrize("code", sorted(set(FIXABLE) - WITHOUT_EXAMPLE_FIX))
def test_the_documented_example_of_a_fixable_rule_is_fixed(cli, here, code):
    root = here / "my_robot"
    example_package(root)
    snippet = example_code(REGISTRY[code].sections()["Example"])
    if not snippet.lstrip().startswith("<robot"):
        snippet = f'<robot name="example">\n{snippet}\n</robot>\n'
    name = "example.urdf.xacro" if "xacro:" in snippet else "example.urdf"
    put(root, {"package.xml": '<package format="2"><name>my_robot</name></package>\n', f"urdf/{name}": snippet,
               "urdf/arm.xacro": f'<robot {XACRO_NS}/>\n'})
    model = f"my_robot/urdf/{name}"
    before = findings(cli, model, "--select", "ALL")
    assert any(c == code for c, _ in before)
    cli("lint", "--isolated", "--select", "ALL", "--fix", "--unsafe-fixes", model)
    after = findings(cli, model, "--select", "ALL")
    assert not any(c == code for c, _ in after), after
    assert not after - before


# -- the published models ---------------------------------------------------------------------------------
def test_the_published_models_fixed_by_patch_load_as_before(tmp_path):
    """`lint --fix --diff --unsafe-fixes` on the 69 published models: the diff applies with
    patch, check_urdf prints the same tree of every model before and after, every fix's
    finding is gone and none appears."""
    check_urdf, patch = require_tool("check_urdf"), require_tool("patch")
    package = tmp_path / "example-robot-data"
    shutil.copytree(example_robot_data(), package, ignore=shutil.ignore_patterns("*.py", "__pycache__"))
    robots = package / "robots"
    models = sorted(p.relative_to(robots).as_posix() for p in robots.rglob("*.urdf"))
    assert len(models) == 69
    env = {key: value for key, value in os.environ.items() if key not in ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH")}
    common = ("--isolated", "-P", f"example-robot-data={package}", "--jobs", "2")

    def lint(*options):
        return run_cli("lint", *common, *options, *models, cwd=robots, env=env)

    before = found_in(lint("--format", "json").stdout)
    done = lint("--diff", "--unsafe-fixes")
    assert done.returncode == 1, done.stderr.decode()
    assert done.stdout.count(b"\n+++ b/") + done.stdout.startswith(b"+++ b/") >= 30  # the tensors CAD exports got wrong, mostly
    trees = {m: subprocess.run([check_urdf, m], cwd=robots, capture_output=True).stdout for m in models}
    applied = subprocess.run([patch, "-p1", "--binary"], input=done.stdout, cwd=robots, capture_output=True)
    assert applied.returncode == 0, applied.stdout.decode()
    assert {m: subprocess.run([check_urdf, m], cwd=robots, capture_output=True).stdout for m in models} == trees
    report = lint("--format", "json").stdout
    after = found_in(report)
    assert not after - before, f"new findings: {after - before}"
    assert sum(after.values()) < sum(before.values())
    # nothing left that a second --fix would change
    assert not [d for f in json.loads(report)["files"] for d in f["diagnostics"] if d["fix"] and d["fix"]["available"]]


@pytest.mark.parametrize("command", [("lint", "--fix"), ("lint", "--diff"), ("check", "--fix"), ("check", "--diff")])
def test_fixing_a_file_that_is_not_there_says_so_in_one_line(tmp_path, command):
    """Nothing was read, so nothing was fixed: the one line that says why, exit 2, and no
    '0 fixed, 0 remaining' or 'nothing to fix' after it; with a file that is there, they stay."""
    done = run_cli(*command, "missing.urdf", cwd=tmp_path)
    assert (done.returncode, done.stdout.decode(), done.stderr.decode()) == (2, "", "urdfcli: missing.urdf: no such file\n")
    (tmp_path / "r.urdf").write_text('<robot name="r"><link name="a"/></robot>\n')
    done = run_cli(*command, "r.urdf", "missing.urdf", cwd=tmp_path)
    said = done.stdout.decode() + done.stderr.decode()
    assert done.returncode == 2 and ("nothing to fix" if "--diff" in command else "0 fixed, 0 remaining") in said


def test_a_package_outside_the_repository_is_never_written(here):
    """A model of this repository calling a macro of a package found with -P (an installed
    or vendored share): its tensor fix is in that package, which is not written."""
    segment_models(here / "vendor")  # seg.xacro's package, found with -P; not this repository
    repo = here / "repo"
    (repo / ".git").mkdir(parents=True)
    put(repo, {"robot/package.xml": '<package format="3"><name>robot</name></package>\n',
               "robot/urdf/r.urdf.xacro": '<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                          '  <xacro:include filename="$(find pkg)/urdf/seg.xacro"/>\n  <link name="base_link"/>\n'
                                          '  <xacro:seg name="s1" parent="base_link" size="1.0"/>\n</robot>\n'})
    before = snapshot(here)
    done = run_cli("lint", "--isolated", "-P", f"pkg={here / 'vendor' / 'pkg'}", "--fix", "--unsafe-fixes", "--select", "I009", "robot/urdf/r.urdf.xacro", cwd=repo)
    assert snapshot(here) == before
    assert done.stderr.decode() == (f"urdfcli: {here / 'vendor' / 'pkg' / 'urdf' / 'seg.xacro'}: not written: it is outside the repository "
                                    "or workspace of what was checked (a package found with -P, or installed)\n")
    assert re.search(r"^0 fixed, 1 remaining", done.stdout.decode(), re.M) and done.returncode == 1


def test_add_noqa_silences_what_a_macro_made_at_the_call_not_in_the_shared_body(cli, here):
    """b's seg call makes a tensor 100 times too small: the comment goes on b's call, not into
    seg.xacro's body, where it would silence model a and any model to come."""
    segment_models(here)
    seg = (here / "pkg/urdf/seg.xacro").read_text()
    done = cli("lint", "--isolated", "--add-noqa", "--select", "I009", "pkg/urdf/b.urdf.xacro")
    assert "1 noqa comment" in done.stdout, done.stdout
    assert (here / "pkg/urdf/seg.xacro").read_text() == seg
    assert '<xacro:seg name="s1" parent="base_link" size="1.0"/>' in (here / "pkg/urdf/b.urdf.xacro").read_text()
    assert "urdfcli: noqa: I009" in (here / "pkg/urdf/b.urdf.xacro").read_text()
    assert cli("lint", "--isolated", "--select", "I009", "pkg/urdf/b.urdf.xacro").exit_code == 0
    # model a, made wrong the same way, is still told
    (here / "pkg/urdf/a.urdf.xacro").write_text((here / "pkg/urdf/a.urdf.xacro").read_text().replace('size="0.1"', 'size="1.0"'))
    assert "I009 warning" in cli("lint", "--isolated", "--select", "I009", "pkg/urdf/a.urdf.xacro").stdout


def test_a_swapped_pair_written_as_a_property_and_its_negation_is_fixed_at_the_property(cli, here):
    """lower="${swing}" upper="${-swing}" with swing 1.2: one edit, swing = -1.2, fixes both
    bounds (it was refused as changing 'another value', the other bound of the same fix); a
    sibling model of the folder defining its own 'swing' does not stop it."""
    model = ('<?xml version="1.0"?>\n<robot name="{n}" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
             '  <xacro:property name="swing" value="{v}"/>\n  <link name="base_link"/><link name="l1"/>\n'
             '  <joint name="j3" type="revolute"><parent link="base_link"/><child link="l1"/><axis xyz="0 0 1"/>'
             '<limit lower="${{swing}}" upper="${{-swing}}" effort="10" velocity="1"/></joint>\n</robot>\n')
    put(here, {"p.urdf.xacro": model.format(n="p", v="-0.5"), "p2.urdf.xacro": model.format(n="p2", v="1.2")})
    files = fixed(cli, here, "p2.urdf.xacro", "J010", "--unsafe-fixes", "--select", "J010", elements=("limit",))
    assert files["p2.urdf.xacro"].decode() == model.format(n="p2", v="-1.2")
    assert files["p.urdf.xacro"].decode() == model.format(n="p", v="-0.5")
