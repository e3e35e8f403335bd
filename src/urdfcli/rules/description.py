"""Description rules: the model loads, but something in it is misspelt, missing or points nowhere."""

from __future__ import annotations

import difflib
import re

from lxml import etree

from ..document import tag_name
from . import WARNING, check

# What the URDF format allows: element -> (attributes, child elements). Elements
# whose contents belong to another format (gazebo, transmission, ros2_control)
# are not looked into; <geometry> shapes are G002's business.
ORIGIN = ({"xyz", "rpy"}, set())
SCHEMA: dict[str, tuple[set[str], set[str]]] = {
    "robot": ({"name", "version"}, {"link", "joint", "material", "transmission", "gazebo", "ros2_control"}),
    "link": ({"name", "type"}, {"inertial", "visual", "collision"}),
    "inertial": (set(), {"origin", "mass", "inertia"}),
    "origin": ORIGIN,
    "mass": ({"value"}, set()),
    "inertia": ({"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}, set()),
    "visual": ({"name"}, {"origin", "geometry", "material"}),
    "collision": ({"name"}, {"origin", "geometry"}),
    "geometry": (set(), None),  # shapes: checked by G001/G002
    "box": ({"size"}, set()),
    "cylinder": ({"radius", "length"}, set()),
    "sphere": ({"radius"}, set()),
    "mesh": ({"filename", "scale"}, set()),
    "material": ({"name"}, {"color", "texture"}),
    "color": ({"rgba"}, set()),
    "texture": ({"filename"}, set()),
    "joint": ({"name", "type"}, {"origin", "parent", "child", "axis", "calibration", "dynamics", "limit", "mimic", "safety_controller"}),
    "parent": ({"link"}, set()),
    "child": ({"link"}, set()),
    "axis": ({"xyz"}, set()),
    "calibration": ({"rising", "falling", "reference_position"}, set()),
    "dynamics": ({"damping", "friction"}, set()),
    "limit": ({"lower", "upper", "effort", "velocity"}, set()),
    "mimic": ({"joint", "multiplier", "offset"}, set()),
    "safety_controller": ({"soft_lower_limit", "soft_upper_limit", "k_position", "k_velocity"}, set()),
}
OPAQUE = {"gazebo", "transmission", "ros2_control"}

# Gazebo plugin parameters that name a joint or a link (ROS 1 and ROS 2 spellings).
PLUGIN_JOINT_TAGS = {
    "jointName", "joint_name", "leftJoint", "rightJoint", "left_joint", "right_joint",
    "leftFrontJoint", "rightFrontJoint", "leftRearJoint", "rightRearJoint",
    "left_front_joint", "right_front_joint", "left_rear_joint", "right_rear_joint",
}
PLUGIN_LINK_TAGS = {"bodyName", "body_name", "robotBaseFrame", "robot_base_frame", "frameName", "frame_name"}
WORLD_FRAMES = {"world", "map", "odom", ""}


def _suggestion(word: str, known) -> str | None:
    close = difflib.get_close_matches(word, sorted(known), n=1, cutoff=0.6)
    return close[0] if close else None


def _schema_elements(loaded) -> list:
    """(element, its schema) for every URDF element outside other formats' blocks (D001 and D002 share it)."""
    return loaded.remembered("schema-elements", lambda: list(_walk_schema(loaded.robot.element)))


def _walk_schema(root):
    stack = [root]
    while stack:
        element = stack.pop()
        tag = tag_name(element)
        schema = SCHEMA.get(tag)
        if schema is None or (tag in OPAQUE and element is not root):
            continue
        yield element, schema
        if schema[1] is not None:
            stack.extend(reversed([c for c in element if isinstance(c.tag, str) and tag_name(c) in schema[1]]))


def _is_foreign(name: str) -> bool:
    """Namespaced names (``xacro:``, ``{uri}``) belong to other formats."""
    return ":" in name or name.startswith("{")


@check("D001", "unknown-element", WARNING, "An element the URDF format does not have where it is written.", in_check=False)
def unknown_element(loaded):
    """## What it does
    Flags a child element that URDF does not define inside its parent, such as a
    misspelt `<metrial>` in a `<visual>`, and suggests the closest known element.

    ## Why is this bad?
    urdfdom and every other consumer skip elements they do not know, silently:
    the misspelt material, limit or origin is simply not there.

    ## Example
    ```xml
    <link name="base">
      <visual>
        <geometry><box size="1 1 1"/></geometry>
        <metrial name="grey"/>
      </visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="base">
      <visual>
        <geometry><box size="1 1 1"/></geometry>
        <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
      </visual>
    </link>
    ```
    """
    for element, (_, children) in _schema_elements(loaded):
        if children is None:
            continue
        for child in element:
            if not isinstance(child.tag, str) or _is_foreign(tag_name(child)) or tag_name(child) in children:
                continue
            tag, parent = tag_name(child), tag_name(element)
            close = _suggestion(tag, children)
            hint = f"did you mean <{close}>?" if close else f"<{parent}> may hold {', '.join(f'<{c}>' for c in sorted(children))}"
            yield loaded.diagnostic("D001", f"<{tag}> is not a URDF element inside <{parent}>; it is ignored", child, hint)


@check("D002", "unknown-attribute", WARNING, "An attribute the URDF format does not define on its element.", in_check=False)
def unknown_attribute(loaded):
    """## What it does
    Flags an attribute that URDF does not define on its element, such as
    `<color rgb="...">` for `rgba`, and suggests the closest known attribute.

    ## Why is this bad?
    The attribute is ignored: the colour, limit or axis it meant to set keeps
    its default, and nothing tells the author.

    ## Example
    ```xml
    <material name="orange">
      <color rgb="1 0.5 0 1"/>
    </material>
    ```

    ## Use instead
    ```xml
    <material name="orange">
      <color rgba="1 0.5 0 1"/>
    </material>
    ```
    """
    for element, (attributes, _) in _schema_elements(loaded):
        for name in element.attrib:
            if name in attributes or _is_foreign(name):
                continue
            tag = tag_name(element)
            close = _suggestion(name, attributes)
            hint = f"did you mean '{close}'?" if close else (f"<{tag}> takes {', '.join(sorted(attributes))}" if attributes else f"<{tag}> takes no attributes")
            yield loaded.diagnostic("D002", f"<{tag}> has no attribute '{name}'; it is ignored", element, hint)


@check("D003", "visual-without-collision", WARNING, "A link with inertia and a visual, but no collision.", in_check=False)
def visual_without_collision(loaded):
    """## What it does
    Flags a link that has an `<inertial>` and a `<visual>` but no `<collision>`.

    ## Why is this bad?
    A simulated body with mass but no collision shape falls through the floor
    and passes through other bodies; the visual makes it look solid.

    ## Example
    ```xml
    <link name="body">
      <inertial><mass value="1"/><inertia ixx="0.17" ixy="0" ixz="0" iyy="0.17" iyz="0" izz="0.17"/></inertial>
      <visual><geometry><box size="1 1 1"/></geometry></visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="body">
      <inertial><mass value="1"/><inertia ixx="0.17" ixy="0" ixz="0" iyy="0.17" iyz="0" izz="0.17"/></inertial>
      <visual><geometry><box size="1 1 1"/></geometry></visual>
      <collision><geometry><box size="1 1 1"/></geometry></collision>
    </link>
    ```
    """
    for link in loaded.robot.links.values():
        if link.inertial is not None and link.visuals and not link.collisions:
            yield loaded.diagnostic("D003", f"link '{link.name}' has inertia and a visual but no collision", link.element, "add a <collision> (often the visual's geometry, or a simpler one)")


def _resources(loaded):
    """(element, kind, uri) for every mesh and texture file the model names."""
    for element in loaded.robot.element.iter("mesh", "texture"):
        uri = element.get("filename")
        if uri:
            yield element, tag_name(element), uri


def _package_of(uri: str) -> str | None:
    match = re.match(r"package://([^/]*)", uri)
    return match.group(1) if match else None


@check("D004", "resource-not-found", WARNING, "A mesh or texture file that does not exist.", in_check=False)
def file_not_found(loaded):
    """## What it does
    Resolves each `<mesh filename>` and `<texture filename>` (`package://`,
    `file://`, absolute or relative paths; never a network address) and flags
    a file that does not exist. Relative paths are taken from the input's folder.

    ## Why is this bad?
    RViz, Gazebo and MoveIt show nothing, or refuse to load the robot, when a
    mesh is missing; collision checking silently loses the shape.

    ## Example
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm.STL"/></geometry></visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></visual>
    </link>
    ```
    """
    if loaded.resolver is None:
        return
    base = loaded.document.file.parent if loaded.document.file else None
    for element, kind, uri in _resources(loaded):
        package = _package_of(uri)
        if package is not None and loaded.resolver.find(package) is None:
            continue  # D005
        path = loaded.resolver.resolve_uri(uri, base)
        if path is not None and not path.exists():
            looked = f" (looked for {path})" if str(path) != uri else ""
            yield loaded.diagnostic("D004", f"{kind} '{uri}' not found{looked}", element, "file names are case-sensitive" if path.parent.is_dir() else None)


@check("D005", "package-uri-not-found", WARNING, "A `package://` URI names a package that cannot be found.", in_check=False)
def package_not_found(loaded):
    """## What it does
    Flags a `package://NAME/...` mesh or texture whose package cannot be found
    with `-P/--package-path`, `ROS_PACKAGE_PATH`, `AMENT_PREFIX_PATH`, or next
    to the input file (its own package and its siblings).

    ## Why is this bad?
    Consumers resolve `package://` through the ROS package index: a misspelt
    or missing package leaves the robot without its meshes.

    ## Example
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robto/meshes/arm.stl"/></geometry></visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></visual>
    </link>
    ```
    """
    if loaded.resolver is None:
        return
    for element, kind, uri in _resources(loaded):
        package = _package_of(uri)
        if package is not None and loaded.resolver.find(package) is None:
            yield loaded.diagnostic("D005", f"{kind} '{uri}': package '{package}' not found {loaded.resolver.where()}", element, "name the package's folder with -P NAME=DIR, or fix its name")


def _known_names(loaded) -> set[str]:
    return set(loaded.robot.links) | set(loaded.robot.joints)


@check("D006", "gazebo-reference-not-found", WARNING, "A `<gazebo reference>` naming no link or joint.", in_check=False)
def gazebo_reference(loaded):
    """## What it does
    Flags a `<gazebo reference="...">` block whose reference is neither a link
    nor a joint of the robot.

    ## Why is this bad?
    Gazebo applies the block (sensors, materials, friction) to nothing, without
    a word: the camera or the wheel friction is simply missing in simulation.

    ## Example
    ```xml
    <link name="camera_link"/>
    <gazebo reference="camera">
      <material>Gazebo/Black</material>
    </gazebo>
    ```

    ## Use instead
    ```xml
    <link name="camera_link"/>
    <gazebo reference="camera_link">
      <material>Gazebo/Black</material>
    </gazebo>
    ```
    """
    known = _known_names(loaded)
    for element in loaded.robot.element.iterfind("gazebo"):
        reference = element.get("reference")
        if reference is not None and reference not in known:
            close = _suggestion(reference, known)
            yield loaded.diagnostic("D006", f"<gazebo reference='{reference}'> names no link or joint", element, f"did you mean '{close}'?" if close else None)


@check("D007", "transmission-joint-not-found", WARNING, "A transmission naming a joint that does not exist.", in_check=False)
def transmission_joint(loaded):
    """## What it does
    Flags a `<transmission>` whose `<joint name>` is not a joint of the robot.

    ## Why is this bad?
    ros_control and gazebo_ros_control fail to load the controller for a
    transmission whose joint does not exist, and the robot does not move.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="wheel_link"/>
    <joint name="wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="wheel_link"/>
    </joint>
    <transmission name="wheel_trans">
      <type>transmission_interface/SimpleTransmission</type>
      <joint name="wheel_jiont">
        <hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface>
      </joint>
    </transmission>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="wheel_link"/>
    <joint name="wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="wheel_link"/>
    </joint>
    <transmission name="wheel_trans">
      <type>transmission_interface/SimpleTransmission</type>
      <joint name="wheel_joint">
        <hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface>
      </joint>
    </transmission>
    ```
    """
    joints = set(loaded.robot.joints)
    for transmission in loaded.robot.element.iterfind("transmission"):
        for joint in transmission.iterfind("joint"):
            name = joint.get("name")
            if name is not None and name not in joints:
                close = _suggestion(name, joints)
                yield loaded.diagnostic("D007", f"transmission '{transmission.get('name', '')}' names joint '{name}', which does not exist", joint, f"did you mean '{close}'?" if close else None)


def _plugin_references(loaded, tags: set[str]):
    """(element, name) for each plugin parameter among ``tags``; lists split on commas."""
    for plugin in loaded.robot.element.iter("plugin"):
        for element in plugin.iter(etree.Element):
            if element.tag in tags and element.text:
                for name in re.split(r"[,\s]+", element.text.strip()):
                    yield element, name.lstrip("/")


@check("D008", "plugin-joint-not-found", WARNING, "A Gazebo plugin parameter naming a joint that does not exist.", in_check=False)
def plugin_joint(loaded):
    """## What it does
    Flags a Gazebo plugin parameter that names a joint (`leftJoint`,
    `right_joint`, `jointName`, `joint_name`...) when no joint has that name.

    ## Why is this bad?
    The plugin (a differential drive, a joint state publisher) fails to start
    or drives nothing, and only Gazebo's log says why.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="left_wheel_link"/>
    <joint name="left_wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="left_wheel_link"/>
    </joint>
    <gazebo>
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <left_joint>left_wheel</left_joint>
      </plugin>
    </gazebo>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="left_wheel_link"/>
    <joint name="left_wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="left_wheel_link"/>
    </joint>
    <gazebo>
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <left_joint>left_wheel_joint</left_joint>
      </plugin>
    </gazebo>
    ```
    """
    joints = set(loaded.robot.joints)
    for element, name in _plugin_references(loaded, PLUGIN_JOINT_TAGS):
        if name and name not in joints:
            close = _suggestion(name, joints)
            yield loaded.diagnostic("D008", f"plugin parameter <{element.tag}> names joint '{name}', which does not exist", element, f"did you mean '{close}'?" if close else None)


@check("D009", "plugin-link-not-found", WARNING, "A Gazebo plugin parameter naming a link that does not exist.", in_check=False)
def plugin_link(loaded):
    """## What it does
    Flags a Gazebo plugin parameter that names a link (`robotBaseFrame`,
    `robot_base_frame`, `bodyName`, `frame_name`...) when no link has that
    name. `world`, `map` and `odom` are frames outside the robot and pass.

    ## Why is this bad?
    The plugin publishes or applies forces in a frame that does not exist:
    TF lookups fail and sensors report in the wrong frame.

    ## Example
    ```xml
    <link name="base_link"/>
    <gazebo>
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <robot_base_frame>base</robot_base_frame>
      </plugin>
    </gazebo>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <gazebo>
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <robot_base_frame>base_link</robot_base_frame>
      </plugin>
    </gazebo>
    ```
    """
    links = set(loaded.robot.links)
    for element, name in _plugin_references(loaded, PLUGIN_LINK_TAGS):
        if name not in links and name not in WORLD_FRAMES:
            close = _suggestion(name, links)
            yield loaded.diagnostic("D009", f"plugin parameter <{element.tag}> names link '{name}', which does not exist", element, f"did you mean '{close}'?" if close else None)
