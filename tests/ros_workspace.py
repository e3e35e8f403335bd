"""A description repository laid out as real ones are (ur_description, franka_description):
packages whose package.xml name differs from their folder, top-level models that include
macro libraries from another package through $(find ...), and a model that only expands
with an argument (like ur.urdf.xacro's ur_type)."""

from __future__ import annotations

from pathlib import Path

XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def package_xml(name: str, depends: tuple[str, ...] = ()) -> str:
    return (
        '<?xml version="1.0"?>\n<package format="3">\n'
        f"  <name>{name}</name>\n  <version>0.1.0</version>\n  <description>{name}</description>\n"
        '  <maintainer email="dev@example.invalid">dev</maintainer>\n  <license>BSD</license>\n'
        "  <buildtool_depend>ament_cmake</buildtool_depend>\n"
        + "".join(f"  <depend>{depend}</depend>\n" for depend in depends)
        + "</package>\n"
    )


# Inertia macros: a library that includes nothing and only defines macros.
INERTIA = f"""<?xml version="1.0"?>
<robot {XACRO}>
  <xacro:macro name="cylinder_inertial" params="mass radius length">
    <inertial>
      <mass value="${{mass}}"/>
      <inertia ixx="${{mass * (3 * radius * radius + length * length) / 12}}" ixy="0" ixz="0"
               iyy="${{mass * (3 * radius * radius + length * length) / 12}}" iyz="0"
               izz="${{mass * radius * radius / 2}}"/>
    </inertial>
  </xacro:macro>
  <xacro:macro name="box_inertial" params="mass x y z">
    <inertial>
      <mass value="${{mass}}"/>
      <inertia ixx="${{mass * (y * y + z * z) / 12}}" ixy="0" ixz="0" iyy="${{mass * (x * x + z * z) / 12}}" iyz="0" izz="${{mass * (x * x + y * y) / 12}}"/>
    </inertial>
  </xacro:macro>
</robot>
"""

# The wheel macro: a library of the common package, including the inertia macros beside it.
WHEEL = f"""<?xml version="1.0"?>
<robot {XACRO}>
  <xacro:include filename="$(find acme_common)/urdf/inertia.xacro"/>
  <xacro:property name="wheel_length" value="0.04"/>
  <xacro:macro name="wheel" params="prefix parent radius *origin">
    <link name="${{prefix}}_wheel_link">
      <visual>
        <geometry><cylinder radius="${{radius}}" length="${{wheel_length}}"/></geometry>
      </visual>
      <collision>
        <geometry><cylinder radius="${{radius}}" length="${{wheel_length}}"/></geometry>
      </collision>
      <xacro:cylinder_inertial mass="0.5" radius="${{radius}}" length="${{wheel_length}}"/>
    </link>
    <joint name="${{prefix}}_wheel_joint" type="continuous">
      <parent link="${{parent}}"/>
      <child link="${{prefix}}_wheel_link"/>
      <xacro:insert_block name="origin"/>
      <axis xyz="0 0 1"/>
    </joint>
  </xacro:macro>
</robot>
"""

# A library nothing includes (yet).
SENSOR = f"""<?xml version="1.0"?>
<robot {XACRO}>
  <xacro:property name="sensor_size" value="0.05"/>
  <xacro:macro name="sensor" params="parent">
    <link name="sensor_link">
      <visual><geometry><box size="${{sensor_size}} ${{sensor_size}} ${{sensor_size}}"/></geometry></visual>
    </link>
    <joint name="sensor_joint" type="fixed"><parent link="${{parent}}"/><child link="sensor_link"/></joint>
  </xacro:macro>
</robot>
"""

ROVER = f"""<?xml version="1.0"?>
<robot {XACRO} name="rover">
  <xacro:include filename="$(find acme_common)/urdf/wheel.xacro"/>
  <link name="base_footprint"/>
  <joint name="base_joint" type="fixed">
    <parent link="base_footprint"/>
    <child link="base_link"/>
  </joint>
  <link name="base_link">
    <visual><geometry><box size="0.4 0.3 0.1"/></geometry></visual>
    <collision><geometry><box size="0.4 0.3 0.1"/></geometry></collision>
    <xacro:box_inertial mass="5" x="0.4" y="0.3" z="0.1"/>
  </link>
  <xacro:wheel prefix="left" parent="base_link" radius="0.1">
    <origin xyz="0 0.17 0" rpy="-1.5708 0 0"/>
  </xacro:wheel>
  <xacro:wheel prefix="right" parent="base_link" radius="0.1">
    <origin xyz="0 -0.17 0" rpy="-1.5708 0 0"/>
  </xacro:wheel>
</robot>
"""

# Like ur.urdf.xacro: the arm's type is an argument with no default (declared nowhere).
ARM = f"""<?xml version="1.0"?>
<robot {XACRO} name="arm">
  <xacro:include filename="$(find acme_common)/urdf/wheel.xacro"/>
  <xacro:property name="reach" value="${{dict(small=0.3, large=0.6)['$(arg arm_type)']}}"/>
  <link name="world"/>
  <joint name="world_joint" type="fixed">
    <parent link="world"/>
    <child link="base_link"/>
  </joint>
  <link name="base_link">
    <visual><geometry><box size="0.2 0.2 ${{reach}}"/></geometry></visual>
    <collision><geometry><box size="0.2 0.2 ${{reach}}"/></geometry></collision>
    <xacro:box_inertial mass="2" x="0.2" y="0.2" z="${{reach}}"/>
  </link>
  <xacro:wheel prefix="turntable" parent="base_link" radius="0.08">
    <origin xyz="0 0 0.1" rpy="0 0 0"/>
  </xacro:wheel>
</robot>
"""

CONFIG = """[tool.urdfcli]
models = { "description/urdf/arm.urdf.xacro" = [["arm_type:=small"], ["arm_type:=large"]] }
"""


def make_repository(root: Path, config: bool = True) -> Path:
    """Write the repository's files under ``root`` (no git); returns root."""
    files = {
        "common/package.xml": package_xml("acme_common"),
        "common/urdf/inertia.xacro": INERTIA,
        "common/urdf/wheel.xacro": WHEEL,
        "common/urdf/sensor.xacro": SENSOR,
        "description/package.xml": package_xml("acme_rover_description", depends=("acme_common",)),
        "description/urdf/rover.urdf.xacro": ROVER,
        "description/urdf/arm.urdf.xacro": ARM,
        "description/README.md": "# acme rover\n",
    }
    if config:
        files["pyproject.toml"] = CONFIG
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def make_colcon_workspace(root: Path) -> tuple[Path, Path]:
    """A colcon workspace ``root/ws/src`` of two repositories: repo_b's package
    acme_wheels holds the wheel and inertia libraries, repo_a's acme_robot (declaring
    no dependency) is empty. Returns (repo_a, repo_b)."""
    src = root / "ws" / "src"
    repo_a, repo_b = src / "repo_a", src / "repo_b"
    for repo in (repo_a, repo_b):
        (repo / ".git").mkdir(parents=True)
    files = {
        repo_b / "wheels" / "package.xml": package_xml("acme_wheels"),
        repo_b / "wheels" / "urdf" / "wheel.xacro": WHEEL.replace("$(find acme_common)/urdf/inertia.xacro", "inertia.xacro"),
        repo_b / "wheels" / "urdf" / "inertia.xacro": INERTIA,
        repo_a / "robot" / "package.xml": package_xml("acme_robot"),
    }
    for path, text in files.items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return repo_a, repo_b


def edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, f"{old!r} not in {path}"
    path.write_text(text.replace(old, new, 1))


def line_of(path: Path, needle: str) -> int:
    return next(i for i, line in enumerate(path.read_text().splitlines(), 1) if needle in line)
