"""Structural rules: emitted while a description is read and its tree built.

Everything check_urdf rejects is here (``urdfdom=True``), plus the defects
that make a description unusable which check_urdf does not see.
"""

from ..diagnostics import Severity
from .base import PLACED, SAFE, UNSAFE, declare, explain

ERROR, WARNING = Severity.ERROR, Severity.WARNING

U = dict(urdfdom=True)
REJECTED = "check_urdf rejects the file, and so does every tool built on urdfdom (robot_state_publisher, RViz, MoveIt, Gazebo's URDF import)."
DROPPED = (
    "check_urdf logs an error, drops the element that holds it (the link's visual, collision or inertial) and goes on: "
    "it exits 0 and prints the tree, and robot_state_publisher, RViz and MoveIt load the robot without that element."
)
BY_PLACE = (
    "Where it is decides what check_urdf does: in a joint (an origin, a limit), a link name or the robot, it rejects "
    "the file; in a link's visual, collision or inertial, it logs an error, drops that element and goes on (exit 0, the "
    "tree printed), and every tool built on urdfdom loads the robot without it."
)
LIBRARY = (
    " A xacro *library* (a file that writes no link, joint or macro call outside its macro definitions, such as"
    " a file of macros) is never judged as a robot: `check` and `lint` check it through the models that include it."
)

# Input
X001 = declare("X001", "xml-syntax-error", ERROR, "The file is not well-formed XML.", explain(
    "Reports where the XML parser stopped: an unclosed tag, a stray `&`, a missing quote.",
    f"Nothing can read a file that is not XML. {REJECTED}",
    '<robot name="r">\n  <link name="base">\n</robot>',
    '<robot name="r">\n  <link name="base"/>\n</robot>'), **U)
X002 = declare("X002", "xml-entity-declaration", ERROR, "The document declares XML entities, which urdfcli never expands.", explain(
    "Refuses a document whose DTD declares entities.",
    "Entities can read local files or expand to gigabytes (\"billion laughs\"); URDF never needs them. Use xacro properties instead.",
    '<!DOCTYPE robot [<!ENTITY base "base_link">]>\n<robot name="r">\n  <link name="&base;"/>\n</robot>',
    '<robot name="r">\n  <link name="base_link"/>\n</robot>'))
X003 = declare("X003", "xacro-error", ERROR, "xacro could not expand the file.", explain(
    "Reports a xacro expansion error (unknown macro, undefined property or argument, bad expression, an include that "
    "cannot be read) at the element being expanded.",
    "Without an expansion there is no URDF: `xacro` fails the same way at launch time, given the same packages. (An include "
    "of `$(find pkg)/...` that only the package's install folder holds, not its sources, is found once the workspace is "
    "built: the hint says so.)",
    '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="${base_name}"/>\n</robot>',
    '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:property name="base_name" value="base_link"/>\n  <link name="${base_name}"/>\n</robot>'))
X004 = declare("X004", "package-not-found", ERROR, "A `$(find pkg)` names a package that cannot be found.", explain(
    "Reports a `$(find NAME)` whose package is found neither through `-P/--package-path`, `ROS_PACKAGE_PATH`, `AMENT_PREFIX_PATH`, nor next to the input file.",
    "The include or file it builds cannot be read, so the expansion fails.",
    '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:include filename="$(find no_such_package)/urdf/arm.xacro"/>\n  <link name="base_link"/>\n</robot>',
    '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:include filename="$(find my_robot)/urdf/arm.xacro"/>\n  <link name="base_link"/>\n</robot>'))
X005 = declare("X005", "xacro-warning", WARNING, "xacro warned while expanding the file.", explain(
    "Passes on a warning xacro printed while expanding (a redefined global symbol, ignored children of an include, unknown attributes), "
    "and, as an error, what the model itself reports with `xacro.error()` (a wrong argument: xacro prints it and writes the URDF anyway).",
    "xacro expanded the file, but probably not as meant: a redefined `pi` changes every angle that uses it.",
    '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:property name="pi" value="3"/>\n  <link name="base_link"/>\n</robot>',
    '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:property name="half_turn" value="${pi}"/>\n  <link name="base_link"/>\n</robot>'),
    fix=SAFE, fix_doc="Rewrites the forms xacro deprecated and still reads: `load_yaml()`, `abs_filename()`, `dotify()` as "
    "`xacro.load_yaml()`..., `range()` and `sorted()` as `python.range()`..., a macro named `xacro:NAME` as `NAME` "
    "(safe: xacro reads both the same). Its other warnings have no fix."
    " A call written under an `xacro:unless` (or `xacro:if`) whose twin on the same condition writes the new form is kept: it is there for an xacro without it, and the hint names the condition to set.")

X006 = declare("X006", "library-unchecked", WARNING, "A xacro library that no model including it could check, for want of xacro arguments.", explain(
    "Flags a xacro library (macros and properties only), or a fragment (a file its models include that cannot be "
    "read on its own), given to urdfcli when no model of its repository that "
    "includes it could check it: each fails to expand for want of a xacro argument, or does not read the file "
    "with the arguments it is checked with (an include under `xacro:if`, such as a gripper included only with "
    "`hand:=true`). The library could then be checked on its own only: its xacro syntax, not the links and joints "
    "its macros make; the fragment not at all. A library that no model includes is not flagged.",
    "A mistake in a macro (a joint naming a link that does not exist) shows only when a model calls it. Without "
    "the arguments the models need, a pre-commit hook passes a broken library.",
    '# pyproject.toml, for a model urdf/robot.urdf.xacro that reads $(arg name) and has no default\n[tool.urdfcli]',
    '# pyproject.toml\n[tool.urdfcli]\nmodels = { "urdf/robot.urdf.xacro" = [["name:=robot"]] }'))
X007 = declare("X007", "xml-comment-hyphens", WARNING, "A comment holds `--`, which XML forbids.", explain(
    "Flags a comment of a URDF or SRDF that holds `--` or ends in `--->`, such as `<!-- ... --!>`. urdfcli reads "
    "it as urdfdom does: the comment runs on to the next `-->`, and all before that is commented out.",
    "urdfdom, MoveIt and the simulators read the file, but xacro, urdf_parser_py and any XML parser refuse it "
    "as not well-formed; and a mistyped end (`--!>`) comments out everything up to the next comment's end.",
    '<robot name="r">\n  <!-- the base --!>\n  <link name="base_link"/>\n  <!-- base_link is commented out up to here -->\n</robot>',
    '<robot name="r">\n  <!-- the base -->\n  <link name="base_link"/>\n</robot>'))

# Robot
R001 = declare("R001", "robot-element-missing", ERROR, "The root element is not `<robot>`.", explain(
    "Flags a document whose root element is not `<robot>`.",
    f"A URDF is a `<robot>`. {REJECTED}",
    '<model name="r">\n  <link name="base_link"/>\n</model>',
    '<robot name="r">\n  <link name="base_link"/>\n</robot>'), **U)
R002 = declare("R002", "robot-name-missing", ERROR, "`<robot>` has no `name` attribute.", explain(
    "Flags a `<robot>` without `name`." + LIBRARY,
    f"The name identifies the model (and names the graph urdf_to_graphviz draws). {REJECTED}",
    '<robot>\n  <link name="base_link"/>\n</robot>',
    '<robot name="r">\n  <link name="base_link"/>\n</robot>'), **U)
R003 = declare("R003", "robot-version-unsupported", ERROR, "`<robot version>` is not `1.0`.", explain(
    "Flags a `version` attribute other than `1.0`, or one that is not of the form `x.y`.",
    f"urdfdom only reads version 1.0. {REJECTED}",
    '<robot name="r" version="2.0">\n  <link name="base_link"/>\n</robot>',
    '<robot name="r" version="1.0">\n  <link name="base_link"/>\n</robot>'), **U)
R004 = declare("R004", "robot-without-links", ERROR, "The robot has no `<link>`.", explain(
    "Flags a robot that defines no link at all." + LIBRARY,
    f"A robot needs at least a root link. {REJECTED}",
    '<robot name="r">\n  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>\n</robot>',
    '<robot name="r">\n  <link name="base_link"/>\n</robot>'), **U)

# Names
N001 = declare("N001", "link-name-missing", ERROR, "A `<link>` has no `name`.", explain(
    "Flags a `<link>` without `name`.",
    f"Joints refer to links by name. {REJECTED}",
    '<link/>', '<link name="base_link"/>'), **U)
N002 = declare("N002", "joint-name-missing", ERROR, "A `<joint>` has no `name`.", explain(
    "Flags a `<joint>` without `name`.",
    f"Controllers, transmissions and joint states refer to joints by name. {REJECTED}",
    '<link name="a"/>\n<link name="b"/>\n<joint type="fixed">\n  <parent link="a"/>\n  <child link="b"/>\n</joint>',
    '<link name="a"/>\n<link name="b"/>\n<joint name="a_to_b" type="fixed">\n  <parent link="a"/>\n  <child link="b"/>\n</joint>'), **U)
N003 = declare("N003", "material-name-missing", ERROR, "A `<material>` has no `name`.", explain(
    "Flags a `<material>`, top-level or inside a visual, without `name`.",
    "Materials are shared by name: one without a name gives no colour. check_urdf logs an error and goes on (it exits 0 and prints the tree): "
    "a top-level one is kept with no name, a visual's own drops the visual.",
    '<material>\n  <color rgba="1 0 0 1"/>\n</material>\n<link name="base_link"/>',
    '<material name="red">\n  <color rgba="1 0 0 1"/>\n</material>\n<link name="base_link"/>'), **U)
N004 = declare("N004", "duplicate-link", ERROR, "Two links have the same name.", explain(
    "Flags a link whose name an earlier link already has.",
    f"Names identify links; which of the two a joint means is undefined. {REJECTED}",
    '<link name="base_link"/>\n<link name="base_link"/>',
    '<link name="base_link"/>\n<link name="base_footprint"/>\n<joint name="footprint_joint" type="fixed">\n  <parent link="base_footprint"/>\n  <child link="base_link"/>\n</joint>'), **U)
N005 = declare("N005", "duplicate-joint", ERROR, "Two joints have the same name.", explain(
    "Flags a joint whose name an earlier joint already has.",
    f"Joint states, controllers and transmissions refer to joints by name. {REJECTED}",
    '<link name="a"/>\n<link name="b"/>\n<link name="c"/>\n<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>\n<joint name="j" type="fixed"><parent link="a"/><child link="c"/></joint>',
    '<link name="a"/>\n<link name="b"/>\n<link name="c"/>\n<joint name="a_to_b" type="fixed"><parent link="a"/><child link="b"/></joint>\n<joint name="a_to_c" type="fixed"><parent link="a"/><child link="c"/></joint>'), **U)
N006 = declare("N006", "duplicate-material", ERROR, "Two top-level materials have the same name.", explain(
    "Flags a top-level `<material>` whose name an earlier top-level material already has.",
    f"Visuals refer to materials by name. {REJECTED}",
    '<material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>\n<material name="grey"><color rgba="0.6 0.6 0.6 1"/></material>\n<link name="base_link"/>',
    '<material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>\n<material name="light_grey"><color rgba="0.6 0.6 0.6 1"/></material>\n<link name="base_link"/>'), **U)

# Values
V001 = declare("V001", "number-malformed", ERROR, "A number that urdfdom cannot read.", explain(
    "Flags a numeric attribute that is not a number as urdfdom reads numbers (a unit, a comma as decimal point, an unexpanded `${...}`).",
    f"{BY_PLACE}",
    '<link name="base_link">\n  <inertial><mass value="2kg"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>\n</link>',
    '<link name="base_link">\n  <inertial><mass value="2"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>\n</link>'), **U)
V002 = declare("V002", "number-not-finite", ERROR, "A number that is NaN, infinite or overflows.", explain(
    "Flags `nan`, `inf` and numbers too large for a double.",
    "Kinematics and dynamics solvers propagate NaN and infinity into every pose and torque they compute.",
    '<link name="base_link">\n  <inertial><mass value="nan"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>\n</link>',
    '<link name="base_link">\n  <inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>\n</link>'), **U)
V003 = declare("V003", "vector-length", ERROR, "A vector (`xyz`, `rpy`, `size`, `scale`) without three components.", explain(
    "Flags an `xyz`, `rpy`, box `size` or mesh `scale` that does not have exactly three space-separated numbers.",
    f"{BY_PLACE}",
    '<link name="base_link">\n  <visual><geometry><box size="1 1"/></geometry></visual>\n</link>',
    '<link name="base_link">\n  <visual><geometry><box size="1 1 0.5"/></geometry></visual>\n</link>'), **U)
V004 = declare("V004", "attribute-missing", ERROR, "A required attribute is missing.", explain(
    "Flags a required attribute that is absent: a sphere's `radius`, a mesh's `filename`, a limit's `effort` or `velocity`, an inertia component.",
    f"{BY_PLACE}",
    '<link name="base_link">\n  <visual><geometry><sphere/></geometry></visual>\n</link>',
    '<link name="base_link">\n  <visual><geometry><sphere radius="0.1"/></geometry></visual>\n</link>'), **U)
V005 = declare("V005", "element-missing", ERROR, "A required child element is missing.", explain(
    "Flags a required child element that is absent: `<geometry>` in a visual or collision, `<mass>` or `<inertia>` in an inertial.",
    f"{DROPPED}",
    '<link name="base_link">\n  <visual><origin xyz="0 0 0"/></visual>\n</link>',
    '<link name="base_link">\n  <visual><origin xyz="0 0 0"/><geometry><box size="1 1 1"/></geometry></visual>\n</link>'), **U)
V006 = declare("V006", "dimension-negative", ERROR, "A box size, radius or length that is negative.", explain(
    "Flags a box size component, sphere or cylinder radius, or cylinder length below zero. A zero one is V008.",
    "A negative size describes no shape: urdfdom accepts it, but collision checkers and physics engines reject it or "
    "compute a negative volume. It is an error because no reading of it is right.",
    '<link name="base_link">\n  <collision><geometry><cylinder radius="-0.1" length="0.2"/></geometry></collision>\n</link>',
    '<link name="base_link">\n  <collision><geometry><cylinder radius="0.1" length="0.2"/></geometry></collision>\n</link>'))
V007 = declare("V007", "rgba-out-of-range", ERROR, "An rgba component outside [0, 1].", explain(
    "Flags an rgba component below 0 or above 1 (often a 0-255 colour).",
    "Colours are fractions. check_urdf logs an error and drops the colour (a visual's material, the visual) and goes on: it exits 0 and prints the tree.",
    '<material name="orange"><color rgba="255 128 0 255"/></material>\n<link name="base_link"/>',
    '<material name="orange"><color rgba="1 0.5 0 1"/></material>\n<link name="base_link"/>'), **U)
V008 = declare("V008", "dimension-zero", WARNING, "A box size, radius or length that is zero.", explain(
    "Flags a box size component, sphere or cylinder radius, or cylinder length that is exactly zero "
    "(often a placeholder shape). A negative one is V006.",
    "A shape without volume loads in urdfdom, ROS and MoveIt, so it is a warning, not an error; but physics "
    "engines (Gazebo, MuJoCo, Drake) reject or mishandle a zero-sized collision shape, and it draws nothing.",
    '<link name="base_link">\n  <collision><geometry><box size="0 0 0"/></geometry></collision>\n</link>',
    '<link name="base_link">\n  <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>\n</link>'))

V009 = declare("V009", "rpy-in-degrees", WARNING, "An `<origin rpy>` angle written in degrees.", explain(
    "Flags an `<origin rpy>` with an angle beyond a full turn (2π): `rpy=\"0 0 90\"`, `\"3.14159 0 180\"`. "
    "Angles within a turn are left alone, whatever they are: 5 could be degrees or radians, and only the author knows.",
    "URDF angles are radians: 90 radians is 5157 degrees, and the part is turned by 1.6 rad (and 180 by 4.2 rad) "
    "instead of a quarter or a half turn. Every consumer reads it so, without a word.",
    '<link name="base_link"/>\n<link name="camera_link"/>\n<joint name="camera_joint" type="fixed">\n  <parent link="base_link"/>\n  <child link="camera_link"/>\n  <origin xyz="0.1 0 0.2" rpy="0 0 90"/>\n</joint>',
    '<link name="base_link"/>\n<link name="camera_link"/>\n<joint name="camera_joint" type="fixed">\n  <parent link="base_link"/>\n  <child link="camera_link"/>\n  <origin xyz="0.1 0 0.2" rpy="0 0 1.5708"/>\n</joint>'),
    fix=UNSAFE, fix_doc="Writes each angle beyond a turn in radians, where it was written (unsafe: the pose changes)." f" {PLACED}")
V010 = declare("V010", "dynamics-negative", ERROR, "A joint's damping or friction that is negative.", explain(
    "Flags a `<dynamics damping>` or `friction` below zero.",
    "Negative damping or friction feeds energy into the joint: Gazebo, MuJoCo and Drake accelerate it without end. "
    "urdfdom reads it without a word.",
    '<link name="base_link"/>\n<link name="arm_link"/>\n<joint name="arm_joint" type="continuous">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n  <dynamics damping="-0.5" friction="0.1"/>\n</joint>',
    '<link name="base_link"/>\n<link name="arm_link"/>\n<joint name="arm_joint" type="continuous">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n  <dynamics damping="0.5" friction="0.1"/>\n</joint>'))
# Geometry and materials
G001 = declare("G001", "geometry-empty", ERROR, "`<geometry>` holds no shape.", explain(
    "Flags a `<geometry>` with no shape element in it.",
    f"{DROPPED}",
    '<link name="base_link">\n  <visual><geometry/></visual>\n</link>',
    '<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry></visual>\n</link>'), **U)
G002 = declare("G002", "geometry-unknown-shape", ERROR, "`<geometry>` holds an unknown shape.", explain(
    "Flags a shape other than `box`, `cylinder`, `sphere` and `mesh` (`capsule` is not URDF).",
    f"{DROPPED}",
    '<link name="base_link">\n  <visual><geometry><cube size="1 1 1"/></geometry></visual>\n</link>',
    '<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry></visual>\n</link>'), **U)
G003 = declare("G003", "geometry-multiple-shapes", WARNING, "`<geometry>` holds more than one shape; only the first is used.", explain(
    "Flags a `<geometry>` with more than one shape.",
    "urdfdom reads only the first shape and drops the others without a word.",
    '<link name="base_link">\n  <visual><geometry><box size="1 1 1"/><sphere radius="0.5"/></geometry></visual>\n</link>',
    '<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry></visual>\n  <visual><geometry><sphere radius="0.5"/></geometry></visual>\n</link>'))
G004 = declare("G004", "element-repeated", WARNING, "A `<visual>`, `<collision>` or `<inertial>` holds two of one child; only the first is used.", explain(
    "Flags a second `<geometry>`, `<material>` or `<origin>` in one `<visual>` or `<collision>`, and a second `<origin>`, `<mass>` or `<inertia>` in one `<inertial>`.",
    "urdfdom, and every parser after it, reads the first and drops the rest without a word: the second colour or shape is never seen. "
    "A second shape belongs in a `<visual>` of its own.",
    '<link name="base_link">\n  <visual>\n    <geometry><box size="1 1 1"/></geometry>\n    <geometry><sphere radius="0.5"/></geometry>\n  </visual>\n</link>',
    '<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry></visual>\n  <visual><geometry><sphere radius="0.5"/></geometry></visual>\n</link>'))
M001 = declare("M001", "material-without-color", ERROR, "A top-level material with neither colour nor texture.", explain(
    "Flags a top-level `<material>` without `<color rgba>` or `<texture filename>`. A `<color rgba>` written but unreadable (a component out of range, V007; not a number, V001) is said by that rule alone.",
    "A material that defines nothing is a mistake, often `rgb=` written for `rgba=`. check_urdf logs that it has no colour and goes on (exit 0): the visuals that name it get none.",
    '<material name="grey"/>\n<link name="base_link"/>',
    '<material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>\n<link name="base_link"/>'), **U)
M002 = declare("M002", "material-undefined", WARNING, "A visual names a material defined nowhere.", explain(
    "Flags a visual's `<material name>` without colour or texture whose name no top-level material defines. A material with an empty name is left alone: urdfdom never looks it up; "
    "so is one whose colour is written but unreadable (V007, V001) or written on `<material>` (M005): that rule says so.",
    "check_urdf only warns, and RViz draws the visual in a default colour.",
    '<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry><material name="grey"/></visual>\n</link>',
    '<material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>\n<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry><material name="grey"/></visual>\n</link>'))
M003 = declare("M003", "material-redefined", WARNING, "One material name is given different colours.", explain(
    "Flags a material name given a colour different from the one it was given before (often in two xacro files). "
    "Components within a tenth of each other are the same colour (`0.752941176470588` and `0.75294`, "
    "an alpha of 0.9 and 1): a difference no viewer shows is left alone; "
    "a material with an empty name is never shared (urdfdom skips it), so it clashes with nothing.",
    "Consumers keep one colour per name: which one wins depends on the order the files were included.",
    '<link name="camera">\n  <visual><geometry><box size="1 1 1"/></geometry><material name="black"><color rgba="0 0 0 0.8"/></material></visual>\n</link>\n<link name="laser">\n  <visual><geometry><box size="1 1 1"/></geometry><material name="black"><color rgba="0 0 0 0.5"/></material></visual>\n</link>',
    '<link name="camera">\n  <visual><geometry><box size="1 1 1"/></geometry><material name="black"><color rgba="0 0 0 0.8"/></material></visual>\n</link>\n<link name="laser">\n  <visual><geometry><box size="1 1 1"/></geometry><material name="translucent_black"><color rgba="0 0 0 0.5"/></material></visual>\n</link>'))
M004 = declare("M004", "rgba-length", WARNING, "An rgba value without exactly four components.", explain(
    "Flags an `rgba` that does not have four numbers (red, green, blue, alpha).",
    "urdfdom reads what is there; a missing alpha leaves the colour transparent or undefined.",
    '<material name="red"><color rgba="1 0 0"/></material>\n<link name="base_link"/>',
    '<material name="red"><color rgba="1 0 0 1"/></material>\n<link name="base_link"/>'))
M005 = declare("M005", "material-rgba-attribute", WARNING, "An `rgba` written on `<material>` instead of in its `<color>`.", explain(
    "Flags a visual's `<material rgba=\"...\">` that has no `<color>` child. (On a top-level material the same mistake is M001, an error.)",
    "urdfdom, Gazebo, MuJoCo and every other parser read a material's colour from its `<color rgba>` child only: "
    "the attribute is ignored and the visual is drawn in a default colour.",
    '<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry><material name="grey" rgba="0.5 0.5 0.5 1"/></visual>\n</link>',
    '<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry><material name="grey"><color rgba="0.5 0.5 0.5 1"/></material></visual>\n</link>'))

# Joints
_LINKS = '<link name="base_link"/>\n<link name="arm_link"/>\n'
J001 = declare("J001", "joint-type-missing", ERROR, "A `<joint>` has no `type`.", explain(
    "Flags a `<joint>` without `type`.",
    f"Without a type nothing knows how the child moves. {REJECTED}",
    _LINKS + '<joint name="arm_joint">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n</joint>',
    _LINKS + '<joint name="arm_joint" type="fixed">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n</joint>'), **U)
J002 = declare("J002", "joint-type-unknown", ERROR, "A joint type other than the six URDF types.", explain(
    "Flags a joint type other than fixed, revolute, continuous, prismatic, floating and planar.",
    f"{REJECTED}",
    _LINKS + '<joint name="arm_joint" type="hinge">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n  <limit lower="0" upper="1" effort="10" velocity="1"/>\n</joint>',
    _LINKS + '<joint name="arm_joint" type="revolute">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n  <limit lower="0" upper="1" effort="10" velocity="1"/>\n</joint>'), **U)
J003 = declare("J003", "joint-limit-missing", ERROR, "A revolute or prismatic joint without `<limit>`.", explain(
    "Flags a revolute or prismatic joint without `<limit>`.",
    f"Their range, effort and velocity are required. {REJECTED}",
    _LINKS + '<joint name="arm_joint" type="revolute">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n</joint>',
    _LINKS + '<joint name="arm_joint" type="revolute">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n  <limit lower="-1.57" upper="1.57" effort="10" velocity="1"/>\n</joint>'), **U)
J004 = declare("J004", "joint-link-unspecified", ERROR, "A joint without `<parent link>` or `<child link>`.", explain(
    "Flags a joint that lacks `<parent link>` or `<child link>` (or gives an empty name).",
    f"A joint connects two links. {REJECTED}",
    _LINKS + '<joint name="arm_joint" type="fixed">\n  <parent link="base_link"/>\n</joint>',
    _LINKS + '<joint name="arm_joint" type="fixed">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n</joint>'), **U)
J006 = declare("J006", "joint-dynamics-empty", ERROR, "`<dynamics>` with neither damping nor friction.", explain(
    "Flags a `<dynamics>` that sets neither `damping` nor `friction`.",
    f"{REJECTED}",
    _LINKS + '<joint name="arm_joint" type="continuous">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n  <dynamics/>\n</joint>',
    _LINKS + '<joint name="arm_joint" type="continuous">\n  <parent link="base_link"/>\n  <child link="arm_link"/>\n  <dynamics damping="0.1"/>\n</joint>'), **U)
