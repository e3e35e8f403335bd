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


def install_package(workspace: Path, package: Path, name: str, folders: dict[str, str], symlink: bool = True) -> Path:
    """What ``colcon build`` installs of the ament_cmake package ``package`` into
    ``workspace/install/NAME`` (one prefix per package, colcon's default): each of
    ``folders``, a folder of its sources -> a folder of ``share/NAME`` (CMake's
    ``install(DIRECTORY description/urdf DESTINATION share/${PROJECT_NAME})``), each file
    linked to its source (``--symlink-install``) or copied; its package.xml; its name in
    the ament index. Returns the share folder."""
    import shutil

    prefix = workspace / "install" / name
    share = prefix / "share" / name
    files = [(package / "package.xml", share / "package.xml")]
    for source, destination in folders.items():
        files += [(file, share / destination / file.relative_to(package / source)) for file in sorted((package / source).rglob("*")) if file.is_file()]
    for file, installed in files:
        installed.parent.mkdir(parents=True, exist_ok=True)
        if symlink:
            installed.symlink_to(file)
        else:
            shutil.copyfile(file, installed)
    registered = prefix / "share" / "ament_index" / "resource_index" / "packages" / name
    registered.parent.mkdir(parents=True, exist_ok=True)
    registered.write_text("")
    return share


def edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, f"{old!r} not in {path}"
    path.write_text(text.replace(old, new, 1))


def line_of(path: Path, needle: str) -> int:
    return next(i for i, line in enumerate(path.read_text().splitlines(), 1) if needle in line)


# A colcon workspace as real ones are: a src/ of several repositories cloned side by side
# (as `vcs import` lays them out), description packages with macro libraries and fragments
# (Baxter's end effectors, TALOS's `${side}_arm.transmissions.urdf.xacro` included from a
# macro, an include computed from an argument with a default), MoveIt config packages
# beside them (SRDF macros in `.xacro` and `.srdf.xacro` files, a generated `.srdf`),
# generated URDFs committed beside their xacro, and a package used through package:// that
# the package.xml does not declare. The files are in tests/ros_ws/src; meshes and the
# generated files are made here.

ROS_WS = Path(__file__).parent / "ros_ws"

# name -> (package, file) of the generated URDF/SRDF -> its xacro source, as `xacro SRC -o OUT` leaves them
GENERATED = {
    "franka_ros/franka_description/robots/panda/panda.urdf": "franka_ros/franka_description/robots/panda/panda.urdf.xacro",
    "pr2_common/pr2_description/robots/pr2.urdf": "pr2_common/pr2_description/robots/pr2.urdf.xacro",
    "panda_moveit_config/config/panda.srdf": "panda_moveit_config/config/panda_arm_hand.srdf.xacro",
}

# mesh file -> the box it holds: size (x, y, z) and centre, metres
MESHES = {
    "franka_ros/franka_description/meshes/visual/hand.stl": ((0.06, 0.2, 0.08), (0, 0, 0.04)),
    "husky/husky_description/meshes/base_link.stl": ((0.99, 0.67, 0.25), (0, 0, 0.12)),
    "husky/husky_description/meshes/bumper.stl": ((0.05, 0.6, 0.08), (0, 0, 0)),
    "clearpath_common/clearpath_platform_description/meshes/top_plate.stl": ((0.8, 0.6, 0.006), (0, 0, 0.003)),
    "pr2_common/pr2_description/meshes/base_v0/base.stl": ((0.65, 0.65, 0.28), (0, 0, 0.14)),
    "pr2_common/pr2_description/meshes/base_v0/caster.stl": ((0.19, 0.16, 0.1), (0, 0, 0.05)),
    "pr2_common/pr2_description/meshes/base_v0/pr2_wheel.stl": ((0.15, 0.034, 0.15), (0, 0, 0)),
}


def box_stl(size: tuple[float, float, float], centre: tuple[float, float, float]) -> bytes:
    """A binary STL of a closed box (12 triangles, outward normals)."""
    import struct

    half = [s / 2 for s in size]
    corner = [[centre[i] + (half[i] if (k >> i) & 1 else -half[i]) for i in range(3)] for k in range(8)]
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    triangles = [(a, b, c) for a, b, c, d in faces for a, b, c in ((a, b, c), (a, c, d))]
    data = bytearray(b"box".ljust(80, b"\0") + struct.pack("<I", len(triangles)))
    for triangle in triangles:
        data += struct.pack("<3f", 0, 0, 0)
        for index in triangle:
            data += struct.pack("<3f", *corner[index])
        data += b"\0\0"
    return bytes(data)


def make_ros_workspace(root: Path) -> Path:
    """Write the workspace under ``root/ws`` (each repository with a ``.git`` folder);
    returns the workspace's ``src`` folder. The generated URDFs and SRDF are expanded
    from their xacro as the xacro tool writes them (its banner naming the source)."""
    import shutil

    from urdfcli import Session, api

    src = root / "ws" / "src"
    shutil.copytree(ROS_WS / "src", src)
    for repo in src.iterdir():
        (repo / ".git").mkdir()
    for name, (size, centre) in MESHES.items():
        (src / name).parent.mkdir(parents=True, exist_ok=True)
        (src / name).write_bytes(box_stl(size, centre))
    with Session() as session:
        for name, source in GENERATED.items():
            text, _, diagnostics = api.expand(str(src / source), session)
            assert text is not None, f"{source}: {diagnostics}"
            (src / name).write_text(text)
    return src


def moveit_repository(root):
    """A repository as vendors write it: a description package whose model calls an arm
    macro from a library, and a MoveIt config package beside it whose SRDF names the arm's
    links and joints."""
    (root / ".git").mkdir(parents=True)
    description, config = root / "cell_description", root / "cell_moveit_config"
    (description / "urdf").mkdir(parents=True)
    (config / "config").mkdir(parents=True)
    for package, depends in ((description, ""), (config, "<exec_depend>cell_description</exec_depend>")):
        (package / "package.xml").write_text(f'<package format="3"><name>{package.name}</name>{depends}</package>\n')
    (description / "urdf" / "arm.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:macro name="arm" params="prefix">\n'
        '    <link name="${prefix}base"/>\n    <link name="${prefix}tip"/>\n'
        '    <joint name="${prefix}elbow" type="revolute"><parent link="${prefix}base"/><child link="${prefix}tip"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n'
        '  </xacro:macro>\n</robot>\n'
    )
    (description / "urdf" / "cell.urdf.xacro").write_text(
        '<robot name="cell" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:include filename="$(find cell_description)/urdf/arm.xacro"/>\n  <xacro:arm prefix="arm_"/>\n</robot>\n'
    )
    (config / "config" / "cell.srdf").write_text(
        '<robot name="cell">\n  <group name="arm"><chain base_link="arm_base" tip_link="arm_tip"/></group>\n'
        '  <group_state name="home" group="arm"><joint name="arm_elbow" value="0"/></group_state>\n</robot>\n'
    )
    (root / "other_moveit_config" / "config").mkdir(parents=True)
    (root / "other_moveit_config" / "config" / "other.srdf").write_text('<robot name="other">\n  <group name="g"><link name="x"/></group>\n</robot>\n')

