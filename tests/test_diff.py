"""`urdfcli diff`: two robots compared by meaning. Every kind of change with its text and
JSON, renames against removals and additions, the poses at zero joint positions, git
revisions whose includes changed, cosmetic differences that are no change, and the formats."""

from __future__ import annotations

import json
import subprocess

import pytest
from conftest import FIXTURES, example_robot_data, run_cli

from urdfcli import api
from urdfcli.report.diff import describe

ARM = """<?xml version="1.0"?>
<robot name="arm">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
  <link name="base_link">
    <inertial>
      <origin xyz="0 0 0.05" rpy="0 0 0"/>
      <mass value="4"/>
      <inertia ixx="0.02" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.03"/>
    </inertial>
    <visual>
      <geometry><cylinder radius="0.1" length="0.1"/></geometry>
      <material name="grey"/>
    </visual>
    <collision><geometry><cylinder radius="0.1" length="0.1"/></geometry></collision>
  </link>
  <link name="upper_arm">
    <inertial>
      <origin xyz="0 0 0.2" rpy="0 0 0"/>
      <mass value="2"/>
      <inertia ixx="0.03" ixy="0" ixz="0" iyy="0.03" iyz="0" izz="0.002"/>
    </inertial>
    <visual>
      <origin xyz="0 0 0.2" rpy="0 0 0"/>
      <geometry><box size="0.05 0.05 0.4"/></geometry>
      <material name="blue"><color rgba="0 0 1 1"/></material>
    </visual>
    <collision>
      <origin xyz="0 0 0.2" rpy="0 0 0"/>
      <geometry><box size="0.05 0.05 0.4"/></geometry>
    </collision>
  </link>
  <link name="forearm">
    <inertial>
      <origin xyz="0 0 0.15" rpy="0 0 0"/>
      <mass value="1"/>
      <inertia ixx="0.008" ixy="0" ixz="0" iyy="0.008" iyz="0" izz="0.001"/>
    </inertial>
    <visual><geometry><mesh filename="package://arm/meshes/forearm.stl" scale="0.001 0.001 0.001"/></geometry></visual>
    <collision><geometry><mesh filename="package://arm/meshes/forearm.stl" scale="0.001 0.001 0.001"/></geometry></collision>
  </link>
  <link name="camera_link">
    <inertial>
      <mass value="0.1"/>
      <inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.0001"/>
    </inertial>
    <visual><geometry><box size="0.02 0.08 0.02"/></geometry></visual>
  </link>
  <link name="tool0"/>
  <joint name="shoulder" type="revolute">
    <parent link="base_link"/>
    <child link="upper_arm"/>
    <origin xyz="0 0 0.1" rpy="0 0 0"/>
    <axis xyz="0 1 0"/>
    <limit lower="-1.57" upper="1.57" effort="50" velocity="2"/>
    <dynamics damping="0.5" friction="0.1"/>
    <safety_controller soft_lower_limit="-1.5" soft_upper_limit="1.5" k_position="10" k_velocity="5"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="upper_arm"/>
    <child link="forearm"/>
    <origin xyz="0 0 0.4" rpy="0 0 0"/>
    <axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="30" velocity="3"/>
  </joint>
  <joint name="elbow_mirror" type="revolute">
    <parent link="upper_arm"/>
    <child link="camera_link"/>
    <origin xyz="0.05 0 0.3" rpy="0 0 0"/>
    <axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="30" velocity="3"/>
    <mimic joint="elbow" multiplier="1" offset="0"/>
  </joint>
  <joint name="tool_joint" type="fixed">
    <parent link="forearm"/>
    <child link="tool0"/>
    <origin xyz="0 0 0.3" rpy="0 0 0"/>
  </joint>
  <transmission name="elbow_transmission">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="elbow"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="elbow_motor"><mechanicalReduction>50</mechanicalReduction></actuator>
  </transmission>
  <ros2_control name="arm_system" type="system">
    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
    <joint name="shoulder">
      <command_interface name="position"><param name="min">-1.57</param><param name="max">1.57</param></command_interface>
      <state_interface name="position"/>
    </joint>
  </ros2_control>
  <gazebo reference="forearm">
    <material>Gazebo/Grey</material>
    <mu1>0.2</mu1>
  </gazebo>
</robot>
"""


def write(folder, name: str, text: str):
    path = folder / name
    path.write_text(text)
    return str(path)


def changes_of(tmp_path, new: str, old: str = ARM, tolerance: float | None = None):
    difference = api.diff(write(tmp_path, "old.urdf", old), write(tmp_path, "new.urdf", new), tolerance=tolerance)
    return difference.comparison.changes


def only(changes, field="pose"):
    """The changes other than the poses they move (asserted apart)."""
    return [c for c in changes if c.field != field]


def one(tmp_path, old_text: str, new_text: str):
    """The single change (poses apart) that replacing old_text by new_text in ARM makes."""
    assert old_text in ARM, old_text
    changes = only(changes_of(tmp_path, ARM.replace(old_text, new_text, 1)))
    assert len(changes) == 1, changes
    return changes[0]


# -- every kind of change ---------------------------------------------------------------
@pytest.mark.parametrize(
    ("old_text", "new_text", "kind", "element", "field", "old", "new", "said"),
    [
        ('<robot name="arm">', '<robot name="arm2">', "changed", "robot", "name", "arm", "arm2", "name: arm -> arm2"),
        ('<joint name="elbow" type="revolute">', '<joint name="elbow" type="continuous">', "changed", "joint[@name='elbow']", "type", "revolute", "continuous",
         "type: revolute -> continuous"),
        ('<origin xyz="0 0 0.4" rpy="0 0 0"/>', '<origin xyz="0 0 0.45" rpy="0 0 0"/>', "changed", "joint[@name='elbow']", "origin xyz", [0, 0, 0.4], [0, 0, 0.45],
         "origin xyz: 0 0 0.4 -> 0 0 0.45 (moved 50 mm)"),
        ('<origin xyz="0 0 0.4" rpy="0 0 0"/>', '<origin xyz="0 0 0.4" rpy="0 0 1.5707963"/>', "changed", "joint[@name='elbow']", "origin rpy", [0, 0, 0],
         [0, 0, 1.5707963], "origin rpy: 0 0 0 -> 0 0 1.5707963 (turned 90°)"),
        ('<axis xyz="0 1 0"/>\n    <limit lower="-2"', '<axis xyz="1 0 0"/>\n    <limit lower="-2"', "changed", "joint[@name='elbow']", "axis", [0, 1, 0], [1, 0, 0],
         "axis: 0 1 0 -> 1 0 0"),
        ('<limit lower="-1.57" upper="1.57"', '<limit lower="-1.57" upper="1.6"', "changed", "joint[@name='shoulder']", "limit upper", 1.57, 1.6,
         "limit upper: 1.57 -> 1.6 (+1.91 %)"),
        ('effort="50"', 'effort="60"', "changed", "joint[@name='shoulder']", "limit effort", 50, 60, "limit effort: 50 -> 60 (+20.00 %)"),
        ('velocity="2"/>', 'velocity="2.5"/>', "changed", "joint[@name='shoulder']", "limit velocity", 2, 2.5, "limit velocity: 2 -> 2.5 (+25.00 %)"),
        ('damping="0.5"', 'damping="0.7"', "changed", "joint[@name='shoulder']", "dynamics damping", 0.5, 0.7, "dynamics damping: 0.5 -> 0.7 (+40.00 %)"),
        ('k_velocity="5"', 'k_velocity="6"', "changed", "joint[@name='shoulder']", "safety_controller k_velocity", 5, 6,
         "safety_controller k_velocity: 5 -> 6 (+20.00 %)"),
        ('multiplier="1" offset="0"', 'multiplier="-1" offset="0"', "changed", "joint[@name='elbow_mirror']", "mimic multiplier", 1, -1,
         "mimic multiplier: 1 -> -1 (-200.00 %)"),
        ('    <dynamics damping="0.5" friction="0.1"/>\n', "", "removed", "joint[@name='shoulder']", "dynamics", [0.5, 0.1], None,
         "dynamics removed (was damping 0.5, friction 0.1)"),
        ('<mimic joint="elbow" multiplier="1" offset="0"/>\n', "", "removed", "joint[@name='elbow_mirror']", "mimic", "elbow", None, "mimic removed (was elbow)"),
        ('<mass value="2"/>', '<mass value="2.4"/>', "changed", "link[@name='upper_arm']", "inertial mass", 2, 2.4, "inertial mass: 2 -> 2.4 (+20.00 %)"),
        ('<origin xyz="0 0 0.2" rpy="0 0 0"/>\n      <mass', '<origin xyz="0 0 0.21" rpy="0 0 0"/>\n      <mass', "changed", "link[@name='upper_arm']",
         "inertial origin xyz", [0, 0, 0.2], [0, 0, 0.21], "inertial origin xyz: 0 0 0.2 -> 0 0 0.21 (moved 10 mm)"),
        ('ixx="0.03"', 'ixx="0.033"', "changed", "link[@name='upper_arm']", "inertial inertia ixx", 0.03, 0.033, "inertial inertia ixx: 0.03 -> 0.033 (+10.00 %)"),
        ('<box size="0.05 0.05 0.4"/></geometry>\n      <material', '<box size="0.05 0.05 0.45"/></geometry>\n      <material', "changed", "link[@name='upper_arm']",
         "visual geometry box size", [0.05, 0.05, 0.4], [0.05, 0.05, 0.45], "visual geometry box size: 0.05 0.05 0.4 -> 0.05 0.05 0.45"),
        ('<visual>\n      <geometry><cylinder radius="0.1" length="0.1"/>', '<visual>\n      <geometry><sphere radius="0.1"/>', "changed", "link[@name='base_link']",
         "visual geometry", "cylinder radius 0.1 length 0.1", "sphere radius 0.1", "visual geometry: cylinder radius 0.1 length 0.1 -> sphere radius 0.1"),
        ('<visual><geometry><mesh filename="package://arm/meshes/forearm.stl"', '<visual><geometry><mesh filename="package://arm/meshes/forearm_v2.stl"', "changed",
         "link[@name='forearm']", "visual geometry mesh filename", "package://arm/meshes/forearm.stl", "package://arm/meshes/forearm_v2.stl",
         "visual geometry mesh filename: package://arm/meshes/forearm.stl -> package://arm/meshes/forearm_v2.stl"),
        ('forearm.stl" scale="0.001 0.001 0.001"/></geometry></visual>', 'forearm.stl" scale="1 1 1"/></geometry></visual>', "changed", "link[@name='forearm']",
         "visual geometry mesh scale", [0.001, 0.001, 0.001], [1, 1, 1], "visual geometry mesh scale: 0.001 0.001 0.001 -> 1 1 1"),
        ('<material name="grey"/>', '<material name="blue"/>', "changed", "link[@name='base_link']", "visual material", "grey", "blue", "visual material: grey -> blue"),
        # name="" (as xacro macros write it) is no name: the material is the visual's own colour
        ('<box size="0.02 0.08 0.02"/></geometry></visual>', '<box size="0.02 0.08 0.02"/></geometry><material name=""><color rgba="0.2 0.2 0.2 1"/></material></visual>',
         "changed", "link[@name='camera_link']", "visual material colour", None, [0.2, 0.2, 0.2, 1], "visual material colour: (none) -> 0.2 0.2 0.2 1"),
        ('<material name="grey"/>', '<material name=""><color rgba="0.5 0.5 0.5 1"/></material>', "changed", "link[@name='base_link']", "visual material",
         "grey", "rgba 0.5 0.5 0.5 1", "visual material: grey -> rgba 0.5 0.5 0.5 1"),
        ('<color rgba="0 0 1 1"/>', '<color rgba="0 0 0.8 1"/>', "changed", "material[@name='blue']", "color rgba", [0, 0, 1, 1], [0, 0, 0.8, 1],
         "color rgba: 0 0 1 1 -> 0 0 0.8 1"),  # defined in a visual, and shared by name as any material
        ('<color rgba="0.5 0.5 0.5 1"/>', '<color rgba="0.6 0.6 0.6 1"/>', "changed", "material[@name='grey']", "color rgba", [0.5, 0.5, 0.5, 1], [0.6, 0.6, 0.6, 1],
         "color rgba: 0.5 0.5 0.5 1 -> 0.6 0.6 0.6 1"),
        ("<mechanicalReduction>50</mechanicalReduction>", "<mechanicalReduction>100</mechanicalReduction>", "changed", "transmission[@name='elbow_transmission']",
         "actuator[@name='elbow_motor']/mechanicalReduction", "50", "100", "actuator[@name='elbow_motor']/mechanicalReduction: 50 -> 100"),
        ('<param name="max">1.57</param>', '<param name="max">1.5</param>', "changed", "ros2_control[@name='arm_system']",
         "joint[@name='shoulder']/command_interface[@name='position']/param[@name='max']", "1.57", "1.5",
         "joint[@name='shoulder']/command_interface[@name='position']/param[@name='max']: 1.57 -> 1.5"),
        ("<mu1>0.2</mu1>", "<mu1>0.5</mu1>", "changed", "gazebo[@reference='forearm']", "mu1", "0.2", "0.5", "mu1: 0.2 -> 0.5"),
        ("    <mu1>0.2</mu1>\n", "", "removed", "gazebo[@reference='forearm']", "mu1", "0.2", None, "mu1 removed (was 0.2)"),
        ('<state_interface name="position"/>', '<state_interface name="position"/><state_interface name="velocity"/>', "added", "ros2_control[@name='arm_system']",
         "joint[@name='shoulder']/state_interface[@name='velocity']", None, None, "joint[@name='shoulder']/state_interface[@name='velocity'] added"),
        ('<collision><geometry><cylinder radius="0.1" length="0.1"/></geometry></collision>\n', "", "removed", "link[@name='base_link']", "collision",
         "cylinder radius 0.1 length 0.1", None, "collision removed (was cylinder radius 0.1 length 0.1)"),
        ("  </link>\n  <link name=\"upper_arm\">", "  <visual><geometry><sphere radius=\"0.05\"/></geometry></visual>\n  </link>\n  <link name=\"upper_arm\">", "added",
         "link[@name='base_link']", "visual[2]", None, "sphere radius 0.05", "visual[2] added: sphere radius 0.05"),
    ],
    ids=lambda v: v if isinstance(v, str) and len(v) < 40 else None,
)
def test_each_kind_of_change_with_its_text_and_json(tmp_path, old_text, new_text, kind, element, field, old, new, said):
    change = one(tmp_path, old_text, new_text)
    assert (change.kind, change.element, change.field) == (kind, element, field)
    assert change.old == old and change.new == new
    assert describe(change) == said
    # in the JSON, with where the new robot writes it (the old one for a removal)
    path = tmp_path / ("old.urdf" if kind == "removed" else "new.urdf")
    done = run_cli("diff", str(tmp_path / "old.urdf"), str(tmp_path / "new.urdf"), "--format", "json")
    assert done.returncode == 1
    document = json.loads(done.stdout)
    (entry,) = [c for c in document["changes"] if c["field"] != "pose"]
    assert {k: entry[k] for k in ("kind", "element", "field", "old", "new", "path")} == {
        "kind": kind, "element": element, "field": field, "old": old, "new": new, "path": str(path)}
    written = path.read_text().splitlines()[entry["line"] - 1]
    edited = (old_text if kind == "removed" else new_text) or old_text
    assert any(line.strip() and line.strip() in written or written.strip() in line for line in edited.splitlines()), (written, edited)


def test_a_joint_element_added_or_removed_whole_names_the_values_it_writes(tmp_path):
    """Fetch's arm joints lost <dynamics damping="1"/> in its xacro: each value is named, and
    the friction it does not write is left out, not shown as a bare "(none)"."""
    damped = ARM.replace(' friction="0.1"', "")
    plain = damped.replace('    <dynamics damping="0.5"/>\n', "")
    [removed] = only(changes_of(tmp_path, plain, damped))
    [added] = only(changes_of(tmp_path, damped, plain))
    assert (removed.old, added.new) == ([0.5, None], [0.5, None])
    assert (describe(removed), describe(added)) == ("dynamics removed (was damping 0.5)", "dynamics added: damping 0.5")


def test_links_and_joints_added_and_removed(tmp_path):
    new = ARM.replace('  <link name="tool0"/>\n', '  <link name="tool0"/>\n  <link name="flange"/>\n').replace(
        '  <transmission name="elbow_transmission">',
        '  <joint name="flange_joint" type="fixed">\n    <parent link="tool0"/>\n    <child link="flange"/>\n  </joint>\n  <transmission name="elbow_transmission">',
    ).replace('<gazebo reference="forearm">\n    <material>Gazebo/Grey</material>\n    <mu1>0.2</mu1>\n  </gazebo>\n', "")
    changes = changes_of(tmp_path, new)
    assert [(c.kind, c.element, c.field) for c in changes] == [
        ("added", "link[@name='flange']", None),
        ("added", "joint[@name='flange_joint']", None),
        ("removed", "gazebo[@reference='forearm']", None),
    ]
    assert changes[0].location.file.endswith("new.urdf") and changes[0].location.line == new.splitlines().index('  <link name="flange"/>') + 1
    assert changes[2].location.file.endswith("old.urdf")  # a removal: where the old robot wrote it
    assert changes[2].anchor.file.endswith("new.urdf")  # and the new robot's closest place (its robot element) for annotations


def test_totals_follow(tmp_path):
    new = ARM.replace('<mass value="2"/>', '<mass value="2.5"/>').replace('<joint name="elbow" type="revolute">', '<joint name="elbow" type="fixed">')
    difference = api.diff(write(tmp_path, "old.urdf", ARM), write(tmp_path, "new.urdf", new))
    old, new_totals = difference.comparison.old, difference.comparison.new
    assert (old.links, old.joints, old.dof, old.mass) == (5, 4, 2, 7.1)  # the mimic joint follows: 2 DOF
    assert (new_totals.dof, new_totals.mass) == (1, 7.6)
    done = run_cli("diff", str(tmp_path / "old.urdf"), str(tmp_path / "new.urdf"))
    assert done.stdout.decode().splitlines()[-1] == "3 changed; mass 7.1 kg -> 7.6 kg (+7.04 %); 2 DOF -> 1"
    # a total of CAD masses (Franka's 4.970684 kg and the like) is a sum nobody wrote: 6 digits, or as many as tell them apart
    cad = ARM.replace('<mass value="2"/>', '<mass value="4.970684"/>')
    write(tmp_path, "cad.urdf", cad)
    write(tmp_path, "cad_new.urdf", cad.replace('<mass value="4.970684"/>', '<mass value="4.970784"/>', 1))
    assert api.diff(str(tmp_path / "cad.urdf"), str(tmp_path / "cad_new.urdf")).comparison.old.mass == pytest.approx(10.070684)
    done = run_cli("diff", str(tmp_path / "old.urdf"), str(tmp_path / "cad.urdf"))
    assert done.stdout.decode().splitlines()[-1] == "1 changed; mass 7.1 kg -> 10.0707 kg (+41.84 %)"
    done = run_cli("diff", str(tmp_path / "cad.urdf"), str(tmp_path / "cad_new.urdf"))
    assert done.stdout.decode().splitlines()[-1].startswith("1 changed; mass 10.0707 kg -> 10.0708 kg (+0.000")


# -- renames ---------------------------------------------------------------------------
def test_renamed_link_and_its_joint_are_renames_and_names_elsewhere_follow(tmp_path):
    new = ARM.replace('"forearm"', '"lower_arm"').replace('"elbow"', '"elbow_joint"').replace('reference="forearm"', 'reference="lower_arm"')
    changes = changes_of(tmp_path, new)
    assert [(c.kind, c.element, c.old, c.new) for c in changes] == [
        ("renamed", "link[@name='lower_arm']", "forearm", "lower_arm"),
        ("renamed", "joint[@name='elbow_joint']", "elbow", "elbow_joint"),
    ]  # the joints naming it, the mimic, the transmission and the gazebo block follow the new names: no other change
    assert describe(changes[0]) == "renamed from 'forearm'"


def test_renamed_link_whose_name_the_tree_alone_gives(tmp_path):
    """A link renamed and its mass changed: the same place, the same joint and shape: renamed, mass changed."""
    new = ARM.replace('"camera_link"', '"camera_body"').replace('<mass value="0.1"/>', '<mass value="0.12"/>')
    changes = changes_of(tmp_path, new)
    assert [(c.kind, c.element, c.field) for c in changes] == [
        ("renamed", "link[@name='camera_body']", "name"),
        ("changed", "link[@name='camera_body']", "inertial mass"),
    ]


def test_another_link_in_the_place_of_a_removed_one_is_a_removal_and_an_addition(tmp_path):
    """The camera replaced by a lidar: another name, mass, inertia, shape and joint origin at the same place."""
    lidar = """  <link name="lidar_link">
    <inertial>
      <mass value="0.8"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.0015"/>
    </inertial>
    <visual><geometry><cylinder radius="0.04" length="0.06"/></geometry></visual>
  </link>"""
    start, end = ARM.index('  <link name="camera_link">'), ARM.index('  <link name="tool0"/>')
    new = ARM[:start] + lidar + "\n" + ARM[end:]
    new = new.replace('<child link="camera_link"/>\n    <origin xyz="0.05 0 0.3" rpy="0 0 0"/>', '<child link="lidar_link"/>\n    <origin xyz="0 0 0.42" rpy="0 0 0"/>')
    changes = changes_of(tmp_path, new)
    assert [(c.kind, c.element, c.field) for c in changes] == [
        ("added", "link[@name='lidar_link']", None),
        ("removed", "link[@name='camera_link']", None),
        ("changed", "joint[@name='elbow_mirror']", "child"),
        ("changed", "joint[@name='elbow_mirror']", "origin xyz"),
    ]


# -- poses at zero joint positions -----------------------------------------------------
def test_a_moved_origin_displaces_every_link_below_it(tmp_path):
    new = ARM.replace('<origin xyz="0 0 0.1" rpy="0 0 0"/>\n    <axis xyz="0 1 0"/>\n    <limit lower="-1.57"',
                      '<origin xyz="0 0 0.13" rpy="0 0 0"/>\n    <axis xyz="0 1 0"/>\n    <limit lower="-1.57"')
    changes = changes_of(tmp_path, new)
    moved = {c.element: c.moved for c in changes if c.field == "pose"}
    assert set(moved) == {f"link[@name='{n}']" for n in ("upper_arm", "forearm", "camera_link", "tool0")}  # not base_link
    assert all(mm == pytest.approx(30.0) and degrees == pytest.approx(0.0, abs=1e-9) for mm, degrees in moved.values())
    pose = next(c for c in changes if c.element == "link[@name='tool0']" and c.field == "pose")
    assert pose.old["xyz"] == pytest.approx([0, 0, 0.8]) and pose.new["xyz"] == pytest.approx([0, 0, 0.83])
    done = run_cli("diff", str(tmp_path / "old.urdf"), str(tmp_path / "new.urdf"))
    lines = done.stdout.decode().splitlines()
    at = lines.index("at zero joint positions:")
    assert lines[at + 1].startswith("~ link 'upper_arm' moved 30 mm, turned 0°  ")
    assert lines[-1] == "1 changed; 4 links moved at zero joint positions"


def test_a_move_of_a_metre_or_more_reads_in_whole_millimetres(tmp_path):
    new = ARM.replace('<origin xyz="0 0 0.1" rpy="0 0 0"/>\n    <axis xyz="0 1 0"/>\n    <limit lower="-1.57"',
                      '<origin xyz="0 0 1.35" rpy="0 0 0"/>\n    <axis xyz="0 1 0"/>\n    <limit lower="-1.57"')
    changes_of(tmp_path, new)
    done = run_cli("diff", str(tmp_path / "old.urdf"), str(tmp_path / "new.urdf"))
    text = done.stdout.decode()
    assert "origin xyz: 0 0 0.1 -> 0 0 1.35 (moved 1250 mm)" in text
    assert "~ link 'upper_arm' moved 1250 mm, turned 0°  " in text
    assert "e+0" not in text


def test_a_turned_origin_moves_and_turns_the_links_below(tmp_path):
    new = ARM.replace('<origin xyz="0 0 0.4" rpy="0 0 0"/>', '<origin xyz="0 0 0.4" rpy="0 0.5235988 0"/>')  # elbow turned 30°
    changes = changes_of(tmp_path, new)
    tool = next(c for c in changes if c.element == "link[@name='tool0']" and c.field == "pose")
    millimetres, degrees = tool.moved
    assert degrees == pytest.approx(30.0, abs=1e-4)
    assert millimetres == pytest.approx(2 * 300 * __import__("math").sin(__import__("math").radians(15)), rel=1e-5)  # the 0.3 m chord of 30°


def test_a_link_that_only_moved_under_a_turned_joint_turned_0_degrees(tmp_path):
    """xArm's link_tcp, 172 mm above the gripper's base and 126 mm above the vacuum gripper's,
    under joints turned by 1.5708: the same rotation, which read 'turned 2.09e-06°' when its
    angle came from an arc cosine of a trace a rounding below 3."""
    old = ARM.replace('<origin xyz="0 0 0.1" rpy="0 0 0"/>', '<origin xyz="0 0 0.1" rpy="1.5708 0.2 0"/>')
    new = old.replace('<origin xyz="0 0 0.4" rpy="0 0 0"/>', '<origin xyz="0 0 0.43" rpy="0 0 0"/>')
    changes = changes_of(tmp_path, new, old)
    moved = {c.element: c.moved for c in changes if c.field == "pose"}
    assert moved and all(mm == pytest.approx(30.0) and degrees == 0.0 for mm, degrees in moved.values())
    text = run_cli("diff", str(tmp_path / "old.urdf"), str(tmp_path / "new.urdf")).stdout.decode()
    assert "~ link 'forearm' moved 30 mm, turned 0°  " in text and "e-0" not in text


# -- cosmetic differences are no change ------------------------------------------------
def test_cosmetic_differences_are_no_change(tmp_path):
    cosmetic = (
        ARM.replace('<origin xyz="0 0 0.4" rpy="0 0 0"/>', '<origin rpy="0.0 0.0 0.0"   xyz="0.0 0 4e-1" />')  # attribute order, number formats
        .replace('<mass value="2"/>', '<!-- measured -->\n      <mass value="2.000"/>')  # comments
        .replace("  <link", "\t<link")  # whitespace
        .replace('<limit lower="-1.57" upper="1.57"', '<limit upper="1.5700000000001" lower="-1.57"')  # within the tolerance
        .replace('<origin xyz="0 0 0.3" rpy="0 0 0"/>', '<origin xyz="0 0 0.3" rpy="6.283185307179586 0 0"/>')  # the same rotation
    )
    old, new = write(tmp_path, "old.urdf", ARM), write(tmp_path, "new.urdf", cosmetic)
    assert api.diff(old, new).comparison.changes == ()
    done = run_cli("diff", old, new)
    assert done.returncode == 0
    assert done.stdout.decode().splitlines()[-1] == "same robot: no change"


def test_tolerance_decides_what_is_the_same(tmp_path):
    nearly = ARM.replace('<mass value="2"/>', '<mass value="2.0001"/>')
    assert [c.field for c in only(changes_of(tmp_path, nearly))] == ["inertial mass"]
    assert only(changes_of(tmp_path, nearly, tolerance=1e-3)) == []
    done = run_cli("diff", str(tmp_path / "old.urdf"), str(tmp_path / "new.urdf"), "--tolerance", "1e-3")
    assert done.returncode == 0
    done = run_cli("diff", str(tmp_path / "old.urdf"), str(tmp_path / "new.urdf"), "--tolerance", "2")
    assert done.returncode == 2 and "--tolerance" in done.stderr.decode()


@pytest.mark.parametrize("name", ["ur5_robot.urdf", "talos_full_v2.urdf", "solo12.urdf", "panda.urdf"])
def test_a_published_model_against_itself_is_the_same(name):
    found = sorted(example_robot_data().rglob(name))
    assert found, name
    done = run_cli("diff", str(found[0]), str(found[0]))
    assert done.returncode == 0, done.stdout.decode()


def test_a_xacro_model_against_its_own_expansion_is_the_same(tmp_path):
    model = FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"
    expanded = run_cli("expand", str(model))
    assert expanded.returncode == 0
    done = run_cli("diff", str(model), "-", input=expanded.stdout)
    assert done.returncode == 0, done.stdout.decode()
    done = run_cli("diff", str(model), str(model), "-f", "json")
    assert done.returncode == 0 and json.loads(done.stdout)["summary"]["same"] is True


# -- xacro: locations through includes and macro calls; git revisions -----------------
ARM_MACRO = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="reach" value="0.4"/>
  <xacro:macro name="segment" params="name parent length">
    <link name="${name}">
      <inertial>
        <mass value="1"/>
        <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.001"/>
      </inertial>
    </link>
    <joint name="${name}_joint" type="revolute">
      <parent link="${parent}"/>
      <child link="${name}"/>
      <origin xyz="0 0 ${length}" rpy="0 0 0"/>
      <axis xyz="0 1 0"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
    </joint>
  </xacro:macro>
</robot>
"""
ARM_MODEL = """<?xml version="1.0"?>
<robot name="xarm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="macros/segment.xacro"/>
  <link name="base_link"/>
  <xacro:segment name="upper" parent="base_link" length="0.1"/>
  <xacro:segment name="lower" parent="upper" length="${reach}"/>
</robot>
"""


def git(*args, cwd):
    subprocess.run(["git", "-c", "user.name=t", "-c", "user.email=t@urdfcli.invalid", "-c", "commit.gpgsign=false", *args], cwd=cwd, check=True, capture_output=True)


@pytest.fixture
def repository(tmp_path):
    """A git repository whose included macro file changed between two commits (and again in the working tree)."""
    repo = tmp_path / "repo"
    (repo / "urdf" / "macros").mkdir(parents=True)
    (repo / "urdf" / "arm.urdf.xacro").write_text(ARM_MODEL)
    (repo / "urdf" / "macros" / "segment.xacro").write_text(ARM_MACRO)
    git("init", "-q", cwd=repo)
    git("add", "-A", cwd=repo)
    git("commit", "-q", "-m", "first", cwd=repo)
    second = ARM_MACRO.replace('value="0.4"', 'value="0.45"').replace('<mass value="1"/>', '<mass value="1.2"/>')
    (repo / "urdf" / "macros" / "segment.xacro").write_text(second)
    git("commit", "-q", "-am", "longer, heavier", cwd=repo)
    (repo / "urdf" / "macros" / "segment.xacro").write_text(second.replace('upper="1"', 'upper="1.2"'))  # not committed
    return repo


def test_revisions_read_their_includes_as_they_were(repository):
    done = run_cli("diff", "HEAD~1:urdf/arm.urdf.xacro", "HEAD:urdf/arm.urdf.xacro", "--format", "json", cwd=repository)
    assert done.returncode == 1, done.stderr.decode()
    document = json.loads(done.stdout)
    found = {(c["element"], c["field"]): c for c in document["changes"]}
    assert set(found) == {
        ("link[@name='upper']", "inertial mass"), ("link[@name='lower']", "inertial mass"),
        ("joint[@name='lower_joint']", "origin xyz"), ("link[@name='lower']", "pose"),
    }
    assert document["notes"] == []  # every file of the model is the revision's own
    mass = found[("link[@name='lower']", "inertial mass")]
    assert (mass["old"], mass["new"], mass["relative"]) == (1.0, 1.2, pytest.approx(0.2))
    # located in the macro file as it was at HEAD, with the call that made the link
    assert (mass["path"], mass["line"]) == ("HEAD:urdf/macros/segment.xacro", 7)
    assert mass["trace"] == [{"path": "HEAD:urdf/arm.urdf.xacro", "line": 6, "column": 3, "macro": "segment"}]
    assert found[("link[@name='lower']", "pose")]["moved_mm"] == pytest.approx(50.0)
    # HEAD against the working tree: only the uncommitted limit, in the working tree's file
    done = run_cli("diff", "HEAD:urdf/arm.urdf.xacro", "urdf/arm.urdf.xacro", "-f", "json", cwd=repository)
    changes = json.loads(done.stdout)["changes"]
    assert {(c["element"], c["field"], c["path"], c["line"]) for c in changes} == {
        ("joint[@name='upper_joint']", "limit upper", "urdf/macros/segment.xacro", 16),
        ("joint[@name='lower_joint']", "limit upper", "urdf/macros/segment.xacro", 16),
    }
    # ./PATH is relative to the current folder, as git show reads it; the working tree is untouched
    done = run_cli("diff", "HEAD~1:./arm.urdf.xacro", "HEAD:./arm.urdf.xacro", cwd=repository / "urdf")
    assert done.returncode == 1 and "HEAD:urdf/macros/segment.xacro:7" in done.stdout.decode()
    assert 'upper="1.2"' in (repository / "urdf" / "macros" / "segment.xacro").read_text()
    # github annotations name the file by its path in the repository
    done = run_cli("diff", "HEAD~1:urdf/arm.urdf.xacro", "HEAD:urdf/arm.urdf.xacro", "-f", "github", cwd=repository)
    assert "::notice file=urdf/macros/segment.xacro,line=7,col=" in done.stdout.decode()


def workspace_robot(tmp_path, model: str):
    """A colcon workspace of two repositories (ros_workspace.make_colcon_workspace): repo_a,
    a git repository, holds acme_robot's robot.urdf.xacro, which puts a wheel of repo_b's
    acme_wheels on its base; committed twice, the second time with a larger wheel."""
    from ros_workspace import XACRO, make_colcon_workspace

    repo_a, repo_b = make_colcon_workspace(tmp_path)
    (repo_a / ".git").rmdir()
    robot = repo_a / "robot" / "urdf" / "robot.urdf.xacro"
    robot.parent.mkdir()
    robot.write_text(model.replace("XACRO", XACRO))
    git("init", "-q", cwd=repo_a)
    git("add", "-A", cwd=repo_a)
    git("commit", "-q", "-m", "first", cwd=repo_a)
    robot.write_text(robot.read_text().replace('radius="0.1"', 'radius="0.12"'))
    git("commit", "-q", "-am", "larger wheel", cwd=repo_a)
    return repo_a, repo_b


WHEELED = """<?xml version="1.0"?>
<robot XACRO name="robot">
  <xacro:include filename="$(find acme_wheels)/urdf/wheel.xacro"/>
  <link name="base_link"/>
  <xacro:wheel prefix="left" parent="base_link" radius="0.1"><origin xyz="0 0.17 0" rpy="-1.5708 0 0"/></xacro:wheel>
</robot>
"""


def test_a_revision_reads_the_packages_of_sibling_repositories_as_they_are_now(tmp_path):
    """repo_a at HEAD~1 holds no acme_wheels: it is read from repo_b, where the workspace
    finds it now (as -P would), and the output says that its changes since are not seen."""
    repo_a, repo_b = workspace_robot(tmp_path, WHEELED)
    wheels = repo_b / "wheels"
    done = run_cli("diff", "HEAD~1:robot/urdf/robot.urdf.xacro", "robot/urdf/robot.urdf.xacro", cwd=repo_a)
    assert done.returncode == 1, done.stderr.decode()
    lines = done.stdout.decode().splitlines()
    note = f"repo_a at HEAD~1 has no package 'acme_wheels': read as it is now, in {wheels}"
    assert lines[2] == f"note: {note}"
    assert "    visual geometry cylinder radius: 0.1 -> 0.12 (+20.00 %)" in [line.split("  /")[0] for line in lines]
    document = json.loads(run_cli("diff", "HEAD~1:robot/urdf/robot.urdf.xacro", "HEAD:robot/urdf/robot.urdf.xacro", "-f", "json", cwd=repo_a).stdout)
    assert document["notes"] == [note, note.replace("HEAD~1", "HEAD")]
    assert {c["field"] for c in document["changes"]} >= {"visual geometry cylinder radius", "collision geometry cylinder radius"}
    markdown = run_cli("diff", "HEAD~1:robot/urdf/robot.urdf.xacro", "robot/urdf/robot.urdf.xacro", "-f", "markdown", cwd=repo_a).stdout.decode()
    assert f"- note: {note}" in markdown.splitlines()
    # -P repo_b reads it from there too: as it is now, said alike
    done = run_cli("diff", "HEAD~1:robot/urdf/robot.urdf.xacro", "robot/urdf/robot.urdf.xacro", "-P", str(repo_b), "-f", "json", cwd=repo_a)
    assert json.loads(done.stdout)["notes"] == [note]


def test_a_mesh_named_through_find_is_the_same_file_at_a_revision(tmp_path):
    """xacro's $(find acme_robot) names the mesh by an absolute path: in the revision's
    temporary copy at one side, in the working tree (or another copy) at the other. The
    same place in the repository is the same file; another one is named REV:PATH."""
    model = WHEELED.replace('<link name="base_link"/>', '<link name="base_link"><visual><geometry><mesh filename="$(find acme_robot)/meshes/base.stl"/></geometry></visual></link>')
    repo_a, _ = workspace_robot(tmp_path, model)
    for new in ("HEAD:robot/urdf/robot.urdf.xacro", "robot/urdf/robot.urdf.xacro"):
        document = json.loads(run_cli("diff", "HEAD~1:robot/urdf/robot.urdf.xacro", new, "-f", "json", cwd=repo_a).stdout)
        assert "visual geometry mesh filename" not in {c["field"] for c in document["changes"]}, document["changes"]
    robot = repo_a / "robot" / "urdf" / "robot.urdf.xacro"
    robot.write_text(robot.read_text().replace("meshes/base.stl", "meshes/body.stl"))
    document = json.loads(run_cli("diff", "HEAD~1:robot/urdf/robot.urdf.xacro", "robot/urdf/robot.urdf.xacro", "-f", "json", cwd=repo_a).stdout)
    (mesh,) = [c for c in document["changes"] if c["field"] == "visual geometry mesh filename"]
    assert (mesh["old"], mesh["new"]) == ("HEAD~1:robot/meshes/base.stl", str(repo_a / "robot" / "meshes" / "body.stl"))


def test_a_parameters_file_named_through_find_is_the_same_file_at_a_revision(tmp_path):
    """articubot_one's ros2_control.xacro gives gazebo_ros2_control
    $(find articubot_one)/config/my_controllers.yaml: an absolute path into the revision's
    temporary copy at one side, into the working tree at the other. Nothing else changed:
    the robots are the same."""
    plugin = ('<gazebo><plugin name="gazebo_ros2_control" filename="libgazebo_ros2_control.so">'
              '<parameters>$(find acme_robot)/config/controllers.yaml</parameters></plugin></gazebo>\n</robot>')
    repo_a, _ = workspace_robot(tmp_path, WHEELED.replace("</robot>", plugin))
    robot = repo_a / "robot" / "urdf" / "robot.urdf.xacro"
    robot.write_text(robot.read_text().replace('radius="0.12"', 'radius="0.1"'))  # back to the first commit's robot
    done = run_cli("diff", "HEAD~1:robot/urdf/robot.urdf.xacro", "robot/urdf/robot.urdf.xacro", "-f", "json", cwd=repo_a)
    assert done.returncode == 0, done.stdout.decode()
    assert json.loads(done.stdout)["changes"] == []
    robot.write_text(robot.read_text().replace("config/controllers.yaml", "config/other.yaml"))
    document = json.loads(run_cli("diff", "HEAD~1:robot/urdf/robot.urdf.xacro", "robot/urdf/robot.urdf.xacro", "-f", "json", cwd=repo_a).stdout)
    (parameters,) = document["changes"]
    assert (parameters["old"], parameters["new"]) == ("HEAD~1:robot/config/controllers.yaml", str(repo_a / "robot" / "config" / "other.yaml"))


def test_a_revision_named_from_a_folder_outside_the_repository_says_so(tmp_path):
    """From the root of a colcon workspace (no git repository), HEAD:src/bot/robot.urdf
    names the file of a repository below: said as such, not only 'no such file'."""
    repo = tmp_path / "ws" / "src" / "bot"
    repo.mkdir(parents=True)
    (repo / "robot.urdf").write_text('<robot name="r"><link name="base"/></robot>\n')
    git("init", "-q", cwd=repo)
    git("add", "-A", cwd=repo)
    git("commit", "-q", "-m", "first", cwd=repo)
    done = run_cli("diff", "HEAD:src/bot/robot.urdf", "src/bot/robot.urdf", cwd=tmp_path / "ws")
    assert done.returncode == 2
    assert done.stderr.decode() == (
        "urdfcli: HEAD:src/bot/robot.urdf: no such file; read as REV:PATH, no git repository holds the current folder: "
        "run urdfcli diff from the repository holding src/bot/robot.urdf\n"
    )


def test_revisions_that_cannot_be_read(repository):
    done = run_cli("diff", "HEAD~5:urdf/arm.urdf.xacro", "HEAD:urdf/arm.urdf.xacro", cwd=repository)
    assert done.returncode == 2
    assert done.stderr.decode() == "urdfcli: HEAD~5:urdf/arm.urdf.xacro: no such file\n"
    done = run_cli("diff", "HEAD:urdf/missing.urdf", "HEAD:urdf/arm.urdf.xacro", cwd=repository)
    assert done.returncode == 2
    assert "HEAD:urdf/missing.urdf: 'urdf/missing.urdf' does not exist at revision HEAD" in done.stderr.decode()


# -- formats and exit codes --------------------------------------------------------------
def test_text_groups_changes_by_element(tmp_path):
    new = ARM.replace('effort="50"', 'effort="60"').replace('damping="0.5"', 'damping="0.7"').replace('  <link name="tool0"/>\n', "").replace(
        '  <joint name="tool_joint" type="fixed">\n    <parent link="forearm"/>\n    <child link="tool0"/>\n    <origin xyz="0 0 0.3" rpy="0 0 0"/>\n  </joint>\n', "")
    old, new_path = write(tmp_path, "old.urdf", ARM), write(tmp_path, "new.urdf", new)
    done = run_cli("diff", old, new_path)
    assert done.returncode == 1
    lines = done.stdout.decode().splitlines()
    assert lines[0] == f"--- {old}  robot 'arm': 5 links, 4 joints, 2 DOF, 7.1 kg"
    assert lines[1] == f"+++ {new_path}  robot 'arm': 4 links, 3 joints, 2 DOF, 7.1 kg"
    assert lines[2:] == [
        f"- link 'tool0'  {old}:{line_of(ARM, '<link name=' + q('tool0'))}:3",
        "~ joint 'shoulder'",
        f"    limit effort: 50 -> 60 (+20.00 %)  {new_path}:{line_of(new, 'effort=' + q('60'))}:{column_of(new, 'effort=' + q('60'))}",
        f"    dynamics damping: 0.5 -> 0.7 (+40.00 %)  {new_path}:{line_of(new, 'damping=' + q('0.7'))}:{column_of(new, 'damping=' + q('0.7'))}",
        f"- joint 'tool_joint'  {old}:{line_of(ARM, '<joint name=' + q('tool_joint'))}:3",
        "2 removed, 2 changed",
    ]


COMPUTED = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base">
    <inertial><mass value="${MASS}"/><inertia ixx="${IXX}" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <visual><geometry><box size="${SIDE} 0.1 0.1"/></geometry></visual>
  </link>
  <link name="arm"/>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="arm"/>
    <origin xyz="0 0 ${SIDE}" rpy="0 0 ${pi/3}"/><axis xyz="0 0 1"/>
    <limit lower="${-radians(LIMIT)}" upper="${radians(LIMIT)}" effort="1" velocity="1"/>
  </joint>
  <gazebo reference="base"><mu1>${MASS}</mu1></gazebo>
</robot>
"""


def computed(**values: str) -> str:
    text = COMPUTED
    for name, value in values.items():
        text = text.replace(name, value)
    return text


def test_computed_numbers_read_short_in_text_and_whole_in_json(tmp_path):
    """What xacro computes (0.1+0.2 is 0.30000000000000004, radians(170) 2.9670597283903604)
    reads as 6 digits in every text format, shapes and gazebo values alike; JSON keeps each bit."""
    import math

    old = write(tmp_path, "old.urdf.xacro", computed(MASS="0.1+0.2", IXX="0.01", SIDE="0.1*3", LIMIT="170"))
    new = write(tmp_path, "new.urdf.xacro", computed(MASS="0.1+0.7", IXX="0.1/3", SIDE="0.1*7", LIMIT="160"))
    done = run_cli("diff", old, new)
    said = done.stdout.decode()
    assert done.returncode == 1 and done.stderr == b""
    assert "0000000" not in said and "9999999" not in said, said
    lines = [line.split("  /")[0].strip() for line in said.splitlines()]
    assert lines[0].endswith("robot 'r': 2 links, 1 joint, 1 DOF, 0.3 kg") and lines[1].endswith("0.8 kg")
    assert {
        "inertial mass: 0.3 -> 0.8 (+166.67 %)",
        "inertial inertia ixx: 0.01 -> 0.0333333 (+233.33 %)",
        "visual geometry box size: 0.3 0.1 0.1 -> 0.7 0.1 0.1",
        "origin xyz: 0 0 0.3 -> 0 0 0.7 (moved 400 mm)",
        "limit lower: -2.96706 -> -2.79253 (+5.88 %)",
        "limit upper: 2.96706 -> 2.79253 (-5.88 %)",
        "mu1: 0.3 -> 0.8",
    } <= set(lines)
    assert lines[-1].endswith("mass 0.3 kg -> 0.8 kg (+166.67 %); 1 link moved at zero joint positions")
    for output_format in ("markdown", "github"):
        shown = run_cli("diff", old, new, "--format", output_format).stdout.decode()
        assert "limit upper: 2.96706 -> 2.79253" in shown and "0000000" not in shown, shown
    document = json.loads(run_cli("diff", old, new, "--format", "json").stdout)
    values = {change["field"]: (change["old"], change["new"]) for change in document["changes"]}
    assert values["limit upper"] == (math.radians(170), math.radians(160))  # as xacro computes them (Python floats)
    assert values["inertial mass"] == (0.1 + 0.2, 0.1 + 0.7) and values["mu1"] == (repr(0.1 + 0.2), repr(0.1 + 0.7))
    # shape and shape kind changed: the numbers of its text read short too
    cylinder = write(tmp_path, "cylinder.urdf.xacro", computed(MASS="0.1+0.2", IXX="0.01", SIDE="0.1*3", LIMIT="170").replace(
        '<box size="${0.1*3} 0.1 0.1"/>', '<cylinder radius="${0.1*3}" length="${1/3}"/>'))
    assert "visual geometry: box 0.3 0.1 0.1 -> cylinder radius 0.3 length 0.333333  " in run_cli("diff", old, cylinder).stdout.decode()


def test_numbers_closer_than_six_digits_read_apart(tmp_path):
    """At a small tolerance, two computed numbers that 6 digits make alike get the digits that tell them apart."""
    old = write(tmp_path, "old.urdf.xacro", computed(MASS="0.1+0.2", IXX="0.01", SIDE="0.1*3", LIMIT="170"))
    new = write(tmp_path, "new.urdf.xacro", computed(MASS="0.1+0.2+1e-8", IXX="0.01", SIDE="0.1*3", LIMIT="170+1e-7"))
    lines = run_cli("diff", old, new, "--tolerance", "1e-12").stdout.decode().splitlines()
    assert lines[1].endswith(" 0.30000001 kg") and lines[0].endswith(" 0.3 kg")
    said = [line.split("  /")[0].strip() for line in lines]
    assert "inertial mass: 0.3 -> 0.30000001 (+0.00000333 %)" in said
    assert "limit upper: 2.967059728 -> 2.96705973 (+0.0000000588 %)" in said, said  # 2.96706 both at 6 digits
    assert "mu1: 0.3 -> 0.30000001" in said


def q(text: str) -> str:
    return f'"{text}"'


def line_of(text: str, needle: str) -> int:
    return next(number for number, line in enumerate(text.splitlines(), 1) if needle in line)


def column_of(text: str, needle: str) -> int:
    return text.splitlines()[line_of(text, needle) - 1].index(needle) + 1


def test_markdown_and_github(tmp_path):
    new = ARM.replace('effort="50"', 'effort="60"').replace('"camera_link"', '"camera|link"')
    old, new_path = write(tmp_path, "old.urdf", ARM), write(tmp_path, "new.urdf", new)
    markdown = run_cli("diff", old, new_path, "--format", "markdown").stdout.decode()
    assert "**1 renamed, 1 changed**" in markdown
    assert "| ~ | link 'camera\\|link' | renamed from 'camera_link' |" in markdown  # a pipe in a name stays in its cell
    assert f"| ~ | joint 'shoulder' | limit effort: 50 -> 60 (+20.00 %) | {new_path}:" in markdown
    github = run_cli("diff", old, new_path, "--format", "github").stdout.decode().splitlines()
    assert len(github) == 2
    assert github[1].startswith(f"::notice file={new_path},line=")
    assert github[1].endswith("::joint 'shoulder': limit effort: 50 -> 60 (+20.00 %25)")
    auto = run_cli("diff", old, new_path, env={"GITHUB_ACTIONS": "true"}).stdout.decode().splitlines()
    assert auto == github


def test_unreadable_inputs_exit_2(tmp_path):
    good = write(tmp_path, "good.urdf", ARM)
    broken = write(tmp_path, "broken.urdf", "<robot name='r'><link name='a'></robot>")
    done = run_cli("diff", good, broken)
    assert done.returncode == 2
    assert done.stderr.decode().startswith(f"urdfcli: {broken}: cannot be read as a robot: ")
    assert done.stdout == b""
    done = run_cli("diff", good, str(tmp_path / "missing.urdf"))
    assert (done.returncode, done.stderr.decode()) == (2, f"urdfcli: {tmp_path / 'missing.urdf'}: no such file\n")
    done = run_cli("diff", good)
    assert done.returncode == 2 and "diff compares two files, OLD and NEW; got 1" in done.stderr.decode()
    done = run_cli("diff", "-", "-", input=ARM)
    assert done.returncode == 2 and "only one of OLD and NEW can be standard input" in done.stderr.decode()


def reformatted(text: bytes) -> bytes:
    """A URDF written another way: attributes in reverse order, every number of an attribute
    written with another format (0.1 -> 0.10000, 1 -> 1.0e0), comments added, indented anew."""
    from lxml import etree

    root = etree.fromstring(text, etree.XMLParser(remove_blank_text=True, resolve_entities=False, no_network=True))

    def rewrite(value: str) -> str:
        pieces = value.split()
        try:
            numbers = [float(p) for p in pieces]
        except ValueError:
            return value
        return "  ".join(f"{n:.17e}" if i % 2 else f"{n:.17g}" + ("" if "." in f"{n:.17g}" or "e" in f"{n:.17g}" else ".0") for i, n in enumerate(numbers))

    for element in root.iter():
        if not isinstance(element.tag, str):
            continue
        items = list(element.attrib.items())
        element.attrib.clear()
        for name, value in reversed(items):
            element.set(name, rewrite(value) if name not in ("name", "filename", "link", "joint", "type", "reference") else value)
        if len(element):
            element.insert(0, etree.Comment(" reformatted "))
    etree.indent(root, space="\t")
    return etree.tostring(root, xml_declaration=True, encoding="utf-8")


def test_every_published_model_reformatted_is_the_same_robot(tmp_path):
    """The 69 published URDFs, each against a copy with its attributes reordered, its numbers
    written another way, comments added and indented anew: no change."""
    models = sorted(example_robot_data().rglob("*.urdf"))
    assert len(models) >= 60
    with api.Session() as session:
        for index, model in enumerate(models):
            copy = tmp_path / f"{index}_{model.name}"
            copy.write_bytes(reformatted(model.read_bytes()))
            changes = api.diff(model, copy, session=session).comparison.changes
            assert changes == (), (model, changes[:3])


def test_a_xacro_argument_needed_is_named(tmp_path):
    model = write(tmp_path, "needs.urdf.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="$(arg n)"/></robot>\n')
    done = run_cli("diff", model, model)
    assert (done.returncode, done.stderr.decode()) == (
        2, f"urdfcli: {model}: needs xacro argument 'n': give n:=VALUE after the two files, or in [tool.urdfcli.xacro-args]\n")
    assert run_cli("diff", model, model, "n:=base_link").returncode == 0


def test_the_configured_xacro_arguments_are_read(tmp_path):
    """Unitree's go1.urdf against the robot.xacro it was generated from, which needs argument DEBUG
    that urdfcli.toml gives: the command X110's hint gives said to give DEBUG:=VALUE after the two
    files (exit 2). Each is read with the arguments its configuration gives it, the command
    line's over them; --isolated reads none."""
    for folder in ("xacro", "urdf"):
        (tmp_path / folder).mkdir()
    source = write(tmp_path, "xacro/robot.xacro", '<robot name="go1" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="base"/>'
                   '<xacro:if value="$(arg DEBUG)"><link name="world"/><joint name="base_static_joint" type="fixed">'
                   '<parent link="world"/><child link="base"/></joint></xacro:if></robot>\n')
    (tmp_path / "urdfcli.toml").write_text('[xacro-args]\n"xacro/robot.xacro" = { DEBUG = "false" }\n')
    urdf = write(tmp_path, "urdf/go1.urdf", '<robot name="go1"><link name="base"/></robot>\n')
    done = run_cli("diff", urdf, source, cwd=tmp_path)
    assert (done.returncode, done.stderr.decode()) == (0, ""), done.stdout.decode()
    done = run_cli("diff", urdf, source, "DEBUG:=true", "--format", "json", cwd=tmp_path)
    assert done.returncode == 1 and {c["element"] for c in json.loads(done.stdout)["changes"]} >= {"link[@name='world']"}
    done = run_cli("diff", "--isolated", urdf, source, cwd=tmp_path)
    assert done.returncode == 2 and "needs xacro argument 'DEBUG'" in done.stderr.decode()
