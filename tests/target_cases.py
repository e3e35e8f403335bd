"""Small models, one per consumer behaviour: a baseline arm with one change each.

The baseline: ``base_link`` (1 kg, a 10 cm box) -> revolute ``j1`` -> ``link1``
(the same) -> fixed ``tool_joint`` -> ``tool0`` (1 g frame with a small tensor).
Each case changes one thing; tests/test_targets.py loads every case into the
real consumers and compares their verdicts with urdfcli's.
"""

from __future__ import annotations

import struct
from pathlib import Path

BOX = '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>'
UNIT = 'ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"'
ZERO = 'ixx="0" iyy="0" izz="0" ixy="0" ixz="0" iyz="0"'
LIMIT = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
AXIS = '<axis xyz="0 0 1"/>'


def link(name: str, mass: str = "1", inertia: str = UNIT, extra: str = BOX, inertial: bool = True) -> str:
    found = f'<inertial><mass value="{mass}"/><inertia {inertia}/></inertial>' if inertial else ""
    return f'<link name="{name}">{found}{extra}</link>'


def joint(name: str, parent: str, child: str, kind: str = "revolute", limit: str = LIMIT, axis: str = AXIS, extra: str = "") -> str:
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
            f'<origin xyz="0 0 0.2"/>{axis}{limit}{extra}</joint>')


def robot(*parts: str) -> str:
    return '<robot name="r">' + "\n".join(parts) + "</robot>\n"


TOOL = link("tool0", "0.001", 'ixx="1e-6" iyy="1e-6" izz="1e-6" ixy="0" ixz="0" iyz="0"', extra="")
TOOL_JOINT = joint("tool_joint", "link1", "tool0", "fixed", limit="", axis="")


def arm(link1: str | None = None, j1: str | None = None, *more: str, base: str | None = None) -> str:
    return robot(base or link("base_link"), link1 or link("link1"), j1 or joint("j1", "base_link", "link1"), TOOL, TOOL_JOINT, *more)


def mesh(name: str) -> str:
    return f'<collision><geometry><mesh filename="{name}"/></geometry></collision>'


CASES = {
    "baseline": arm(),
    "zero-mass": arm(link("link1", "0", ZERO, extra="")),
    "no-inertial-no-geometry": arm(link("link1", inertial=False, extra="")),
    "no-inertial-box": arm(link("link1", inertial=False)),
    "zero-tensor": arm(link("link1", inertia=ZERO)),
    "mass-zero-with-tensor": arm(link("link1", "0")),
    "negative-mass": arm(link("link1", "-1")),
    "triangle": arm(link("link1", inertia='ixx="0.001" iyy="0.001" izz="0.01" ixy="0" ixz="0" iyz="0"')),
    "not-positive-definite": arm(link("link1", inertia='ixx="0.01" iyy="0.01" izz="0.01" ixy="0.02" ixz="0" iyz="0"')),
    "massless-middle": robot(link("base_link"), link("link1", inertial=False, extra=""), joint("j1", "base_link", "link1"),
                             link("link2"), joint("j2", "link1", "link2")),
    "massless-with-fixed-mass": robot(link("base_link"), link("link1", "0", ZERO, extra=""), joint("j1", "base_link", "link1"),
                                      link("link2"), joint("j2", "link1", "link2", "fixed", limit="", axis="")),
    "lower-above-upper": arm(j1=joint("j1", "base_link", "link1", limit='<limit lower="1" upper="-1" effort="1" velocity="1"/>')),
    "lower-equals-upper": arm(j1=joint("j1", "base_link", "link1", limit='<limit lower="0.5" upper="0.5" effort="1" velocity="1"/>')),
    "revolute-no-limit": arm(j1=joint("j1", "base_link", "link1", limit="")),
    "prismatic-no-limit": arm(j1=joint("j1", "base_link", "link1", "prismatic", limit="")),
    "continuous-with-limits": arm(j1=joint("j1", "base_link", "link1", "continuous")),
    "continuous-effort-only": arm(j1=joint("j1", "base_link", "link1", "continuous", limit='<limit effort="1" velocity="1"/>')),
    "mimic": arm(None, None, link("link2"), joint("j2", "link1", "link2", extra='<mimic joint="j1"/>')),
    "floating": arm(j1=joint("j1", "base_link", "link1", "floating", limit="", axis="")),
    "no-collision": arm(link("link1", extra="")),
    "cylinder": arm(link("link1", extra='<collision><geometry><cylinder radius="0.05" length="0.2"/></geometry></collision>')),
    "stl-collision": arm(link("link1", extra=mesh("part.stl"))),
    "ascii-stl-collision": arm(link("link1", extra=mesh("part_ascii.stl"))),
    "obj-collision": arm(link("link1", extra=mesh("part.obj"))),
    "dae-collision": arm(link("link1", extra=mesh("part.dae"))),
    "obj-flat-object-first": arm(link("link1", extra=mesh("parts.obj"))),
    "material-two-colours": arm(None, None, '<material name="paint"><color rgba="1 0 0 1"/></material>',
                                base=link("base_link", extra=BOX + '<visual><geometry><box size="0.1 0.1 0.1"/></geometry>'
                                          '<material name="paint"><color rgba="0 1 0 1"/></material></visual>')),
    "zero-size-box": arm(link("link1", extra='<visual><geometry><box size="0.1 0 0.1"/></geometry></visual>' + BOX)),
    "root-zero-moment": arm(base=link("base_link", inertia='ixx="0.01" iyy="0.01" izz="0" ixy="0" ixz="0" iyz="0"')),
    "world-root": robot('<link name="world"/>', link("base_link"), joint("mount", "world", "base_link", "fixed", limit="", axis=""),
                        link("link1"), joint("j1", "base_link", "link1"), TOOL, TOOL_JOINT),
    "balanced-triangle": arm(link("link1", inertia='ixx="0.001" iyy="0.001" izz="0.01" ixy="0" ixz="0" iyz="0"'), None,
                             '<mujoco><compiler balanceinertia="true"/></mujoco>'),
}

# One plain error each (a rule that is no consumer's): which consumers load the model anyway.
VISUAL_BOX = '<visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual>'
PLAIN_ERRORS = {
    "visual-mesh-missing": arm(link("link1", extra=BOX + '<visual><geometry><mesh filename="missing.stl"/></geometry></visual>')),
    "collision-mesh-missing": arm(link("link1", extra=mesh("missing.stl"))),
    "visual-mesh-unreadable": arm(link("link1", extra=BOX + '<visual><geometry><mesh filename="empty.stl"/></geometry></visual>')),
    "ros2-control-unknown-joint": arm(None, None, '<ros2_control name="arm" type="system"><hardware><plugin>mock_components/GenericSystem</plugin>'
                                      '</hardware><joint name="j9"><command_interface name="position"/></joint></ros2_control>'),
    "geometry-empty": arm(link("link1", extra=BOX + "<visual><geometry/></visual>")),
    "geometry-unknown-shape": arm(link("link1", extra=BOX + "<visual><geometry><cube/></geometry></visual>")),
    "joint-type-missing": arm(j1=joint("j1", "base_link", "link1").replace(' type="revolute"', "")),
    "joint-type-unknown": arm(j1=joint("j1", "base_link", "link1", "hinge")),
    "joint-child-missing": arm(j1=joint("j1", "base_link", "link1").replace('<child link="link1"/>', "")),
    "joint-link-not-found": arm(j1=joint("j1", "base", "link1")),
    "dynamics-empty": arm(j1=joint("j1", "base_link", "link1", extra="<dynamics/>")),
    "dynamics-negative": arm(j1=joint("j1", "base_link", "link1", extra='<dynamics damping="-0.5" friction="0.1"/>')),
    "zero-axis": arm(j1=joint("j1", "base_link", "link1", axis='<axis xyz="0 0 0"/>')),
    "mimic-unknown-joint": arm(None, None, link("link2"), joint("j2", "link1", "link2", extra='<mimic joint="j7"/>')),
    "mimic-itself": arm(None, None, link("link2"), joint("j2", "link1", "link2", extra='<mimic joint="j2"/>')),
    "material-without-colour": arm(None, None, '<material name="grey"/>',
                                   base=link("base_link", extra=BOX + '<visual><geometry><box size="0.1 0.1 0.1"/></geometry><material name="grey"/></visual>')),
    "link-name-missing": arm(None, None, '<link/>'),
    "joint-name-missing": arm(j1=joint("j1", "base_link", "link1").replace(' name="j1"', "")),
    "material-name-missing": arm(None, None, '<material><color rgba="1 0 0 1"/></material>'),
    "duplicate-link": arm(None, None, link("tool0", extra="")),
    "duplicate-joint": arm(None, None, link("link2"), joint("j1", "link1", "link2")),
    "duplicate-material": arm(None, None, '<material name="paint"><color rgba="1 0 0 1"/></material>', '<material name="paint"><color rgba="1 0 0 1"/></material>'),
    "robot-name-missing": arm().replace('<robot name="r">', "<robot>"),
    "robot-version": arm().replace('<robot name="r">', '<robot name="r" version="2.0">'),
    "robot-without-links": '<robot name="r"><material name="grey"><color rgba="0.5 0.5 0.5 1"/></material></robot>\n',
    "two-roots": arm(None, None, link("loose")),
    "no-root": robot(link("base_link"), link("link1"), joint("j1", "base_link", "link1"), joint("j0", "link1", "base_link")),
    "two-parents": arm(None, None, link("link2"), joint("j2", "base_link", "link2"), joint("j3", "link1", "link2")),
    "loop": arm(None, None, link("link2"), joint("j2", "link1", "link2"), link("link3"), joint("j3", "link2", "link3"), joint("j4", "link3", "link2")),
    "number-malformed": arm(link("link1", "2kg")),
    "number-not-finite": arm(link("link1", "nan")),
    "vector-length": arm(link("link1", extra='<collision><geometry><box size="0.1 0.1"/></geometry></collision>')),
    "attribute-missing": arm(link("link1", extra=BOX + '<visual><geometry><sphere/></geometry></visual>')),
    "element-missing": arm(link("link1", extra=BOX + "<visual></visual>")),
    "dimension-negative": arm(link("link1", extra=BOX + '<visual><geometry><cylinder radius="-0.05" length="0.2"/></geometry></visual>')),
    "rgba-out-of-range": arm(None, None, '<material name="orange"><color rgba="255 128 0 255"/></material>'),
    "xml-syntax": arm().replace("</robot>", "</robt>"),
    "entity-declaration": '<!DOCTYPE robot [<!ENTITY base "base_link">]>\n' + arm().replace('"base_link"', '"&base;"'),
}
CASES.update(PLAIN_ERRORS)

# What the consumers do on real robots, one case each: (case, profile, a piece of the consumer's own
# message (None: it says nothing), the rule of that profile that says it).
ZERO_TENSOR = ZERO
TINY = 'ixx="1e-16" iyy="1e-16" izz="1e-16" ixy="0" ixz="0" iyz="0"'
FIXED = {"kind": "fixed", "limit": "", "axis": ""}


def transmission(name: str, joint_name: str, actuator: str) -> str:
    return (f'<transmission name="{name}"><type>transmission_interface/SimpleTransmission</type><joint name="{joint_name}">'
            '<hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>'
            f'<actuator name="{actuator}"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>')


def visual_mesh(filename: str) -> str:
    return BOX + f'<visual><geometry><mesh filename="{filename}"/></geometry></visual>'


FACT_CASES = {
    # a ROS-Industrial support package: shapes, no <inertial> anywhere
    "all-massless": robot(link("base_link", inertial=False), link("link1", inertial=False), joint("j1", "base_link", "link1"),
                          link("tool0", inertial=False, extra=""), joint("tool_joint", "link1", "tool0", **FIXED)),
    "root-mass-zero": arm(base=link("base_link", "0", ZERO_TENSOR)),
    "zero-mass-frames-chained": arm(None, None, link("frame_a", "0", ZERO_TENSOR, extra=""), joint("a_joint", "link1", "frame_a", **FIXED),
                                    link("frame_b", "0", ZERO_TENSOR, extra=""), joint("b_joint", "frame_a", "frame_b", **FIXED)),
    "micro-mass": robot(link("base_link"), link("link1", "1e-6", 'ixx="1e-9" iyy="1e-9" izz="1e-9" ixy="0" ixz="0" iyz="0"'),
                        joint("j1", "base_link", "link1"), link("link2"), joint("j2", "link1", "link2")),
    "massless-flange": arm(None, None, link("flange", inertial=False, extra=""), joint("flange_joint", "link1", "flange", **FIXED),
                           link("finger"), joint("finger_joint", "flange", "finger")),
    "link-joint-one-name": arm(None, None, link("gripper"), joint("gripper", "link1", "gripper")),
    "mimic-walked-first": arm(None, None, link("left"), joint("b_finger", "link1", "left"), link("right"),
                              joint("a_finger", "link1", "right", extra='<mimic joint="b_finger"/>')),
    "visual-mesh-format": arm(link("link1", extra=visual_mesh("part.mesh"))),
    "visual-mesh-unknown-package": arm(link("link1", extra=visual_mesh("package://no_such_package/part.stl"))),
    "cylinder-offset": arm(link("link1", "2", extra='<collision><origin xyz="0.05 0 0"/><geometry><cylinder radius="0.04" length="0.3"/></geometry></collision>')),
    "boxes-offset": arm(link("link1", extra=BOX + '<collision><origin xyz="0 0 0.2" rpy="0 0 0.5"/><geometry><box size="0.1 0.2 0.05"/></geometry></collision>')),
    "sphere-offset": arm(link("link1", extra='<collision><origin xyz="0.05 0 0"/><geometry><sphere radius="0.1"/></geometry></collision>')),
    "obj-offset": arm(link("link1", extra='<collision><origin xyz="0.05 0 0"/><geometry><mesh filename="part.obj"/></geometry></collision>')),
    "tiny-inertia": arm(None, None, link("pad", "1e-3", TINY, extra=""), joint("pad_joint", "link1", "pad", **FIXED)),
    "zero-length-cylinder": arm(link("link1", extra='<collision><geometry><cylinder radius="0.05" length="0"/></geometry></collision>')),
    "material-nowhere": arm(base=link("base_link", extra=BOX + '<visual><geometry><box size="0.1 0.1 0.1"/></geometry><material name="steel"/></visual>')),
    "texture-unknown-package": arm(base=link("base_link", extra=BOX + '<visual><geometry><box size="0.1 0.1 0.1"/></geometry>'
                                             '<material name="decal"><texture filename="package://no_such_package/decal.png"/></material></visual>')),
    "shared-actuator": arm(None, None, link("link2"), joint("j2", "link1", "link2"), transmission("t1", "j1", "motor"), transmission("t2", "j2", "motor")),
    "repeated-transmission": arm(None, None, transmission("j1_transmission", "j1", "j1_motor"), transmission("j1_transmission", "j1", "j1_motor")),
    "fixed-mimic": arm(None, None, link("link2"), joint("j2", "link1", "link2", extra='<mimic joint="j1"/>', **FIXED)),
    "limit-without-bounds": arm(j1=joint("j1", "base_link", "link1", limit='<limit effort="1" velocity="1"/>')),
    "joint-friction": arm(j1=joint("j1", "base_link", "link1", extra='<dynamics damping="0.1" friction="0.5"/>')),
    "zero-effort-transmission": arm(None, joint("j1", "base_link", "link1", limit='<limit lower="-1" upper="1" effort="0" velocity="1"/>'),
                                    transmission("t1", "j1", "m1")),
    "names-with-spaces": robot(link("base_link"), link("upper arm"), joint("shoulder pitch", "base_link", "upper arm")),
    "massless-moving-no-shapes": arm(link("link1", inertial=False, extra="")),
}
CASES.update(FACT_CASES)
FACTS = [
    ("all-massless", "gazebo", "A model must have at least one link", "C507"),
    ("root-mass-zero", "gazebo", "A model must have at least one link", "C507"),
    ("zero-mass-frames-chained", "gazebo", "Pose values must be finite", "C508"),
    ("micro-mass", "gazebo", "link[link1] has no inertia, not modeled in sdf", "C501"),
    ("massless-flange", "gazebo", "link[flange] has no inertia, not modeled in sdf", "C501"),
    ("link-joint-one-name", "gazebo", "has a name collision", "C509"),
    ("mimic-walked-first", "pinocchio:mimic", "The parent joint of the mimic joint is not in the kinematic tree", "C303"),
    ("visual-mesh-format", "pybullet", "invalid mesh filename extension", "C408"),
    ("visual-mesh-unknown-package", "pybullet", "cannot find 'no_such_package/part.stl' in any directory in urdf path", "C408"),
    ("cylinder-offset", "pybullet", None, "C402"),
    ("tiny-inertia", "mujoco", "inertia must have positive eigenvalues", "C103"),
    ("zero-length-cylinder", "mujoco", "must be positive in geom", "C111"),
    ("collision-mesh-missing", "mujoco", "Error opening file 'missing.stl'", "C110"),
    ("obj-flat-object-first", "mujoco", "mesh volume is too small", "C112"),
    ("material-nowhere", "drake", "Material 'steel' not previously defined, but has no color or texture", "C207"),
    ("texture-unknown-package", "drake", "refers to unknown package 'no_such_package'", "C208"),
    ("shared-actuator", "drake", "already contains a joint actuator named 'motor'", "C209"),
    ("repeated-transmission", "drake", "already contains a joint actuator named 'j1_motor'", "C209"),
    ("fixed-mimic", "drake", "Joint 'j2' which has 0 DOF cannot mimic joint 'j1'", "C210"),
    ("limit-without-bounds", "drake", None, "C211"),
    ("joint-friction", "drake", "does not currently support non-zero joint friction", "C212"),
    ("zero-effort-transmission", "drake", "has a zero effort limit", "C213"),
    ("names-with-spaces", "isaac", None, "C703"),
    ("negative-mass", "isaac", None, "C704"),
    ("floating", "isaac", None, "C705"),
    ("massless-moving-no-shapes", "isaac", None, "C702"),
]

TETRAHEDRON = ((0, 0, 0), (0.05, 0, 0), (0, 0.05, 0), (0, 0, 0.05))
FACES = ((0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3))


def write_meshes(folder: Path) -> None:
    """part.stl (binary), part_ascii.stl, part.obj, parts.obj (a flat object, then part.obj's), empty.stl (no bytes)
    and part.dae (a stand-in: only its extension is judged)."""
    triangles = b"".join(
        struct.pack("<12fH", 0, 0, 0, *TETRAHEDRON[a], *TETRAHEDRON[b], *TETRAHEDRON[c], 0) for a, b, c in FACES
    )
    (folder / "part.stl").write_bytes(b"\0" * 80 + struct.pack("<I", len(FACES)) + triangles)
    facets = "".join(
        "facet normal 0 0 0\nouter loop\n" + "".join("vertex {} {} {}\n".format(*TETRAHEDRON[i]) for i in face) + "endloop\nendfacet\n"
        for face in FACES
    )
    (folder / "part_ascii.stl").write_text(f"solid part\n{facets}endsolid part\n")
    vertices = "".join(f"v {x} {y} {z}\n" for x, y, z in TETRAHEDRON)
    (folder / "part.obj").write_text(vertices + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in FACES))
    plate = "o plate\nv 0 0 0\nv 0.05 0 0\nv 0.05 0.05 0\nv 0 0.05 0\nf 1 2 3\nf 1 3 4\n"  # flat, and first: all MuJoCo reads
    (folder / "parts.obj").write_text(plate + "o part\n" + vertices + "".join(f"f {a + 5} {b + 5} {c + 5}\n" for a, b, c in FACES))
    (folder / "empty.stl").write_bytes(b"")
    (folder / "part.dae").write_text('<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1"/>\n')


def write_cases(folder: Path) -> dict[str, Path]:
    write_meshes(folder)
    paths = {}
    for name, text in CASES.items():
        paths[name] = folder / f"{name}.urdf"
        paths[name].write_text(text)
    return paths
