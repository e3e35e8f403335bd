"""Each kind of false alarm the physics rules used to raise on published robots draws
nothing here, next to a small model with the real defect, which still draws its warning."""

from __future__ import annotations

import re

import pytest
from conftest import lint_file, run_cli

from urdfcli.diagnostics import Severity
from urdfcli.project.config import Config


def lint(tmp_path, body: str, name: str = "robot.urdf"):
    path = tmp_path / name
    path.write_text(f'<robot name="r">\n{body}\n</robot>\n')
    return lint_file(str(path), Config.everything()).diagnostics


def found(tmp_path, body: str, *codes: str) -> list[tuple[str, str, str]]:
    """(code, severity, message) of the diagnostics with these codes."""
    return [(d.code, d.severity.value, d.message) for d in lint(tmp_path, body) if d.code in codes]


def inertial(mass, ixx, iyy, izz, ixy=0, ixz=0, iyz=0, xyz="0 0 0") -> str:
    return (f'<inertial><origin xyz="{xyz}"/><mass value="{mass}"/>'
            f'<inertia ixx="{ixx}" ixy="{ixy}" ixz="{ixz}" iyy="{iyy}" iyz="{iyz}" izz="{izz}"/></inertial>')


def box(size: str, xyz: str = "0 0 0") -> str:
    return f'<collision><origin xyz="{xyz}"/><geometry><box size="{size}"/></geometry></collision>'


def sphere(radius) -> str:
    return f'<collision><geometry><sphere radius="{radius}"/></geometry></collision>'


BASE = '<link name="base">' + box("0.4 0.4 0.1") + inertial(10, 0.14, 0.14, 0.27) + "</link>"


def arm(name: str, inside: str, joint: str = "revolute", parent: str = "base", extra: str = "") -> str:
    limit = '<limit lower="-1" upper="1" effort="10" velocity="1"/>' if joint in ("revolute", "prismatic") else ""
    return (f'<link name="{name}">{inside}</link>'
            f'<joint name="{name}_joint" type="{joint}"><parent link="{parent}"/><child link="{name}"/>'
            f'<axis xyz="0 0 1"/>{limit}{extra}</joint>')


# -- A.1: inertia against geometry -------------------------------------------------------
# a 0.46 m link of 5 kg: uniform, a box 0.1 x 0.1 x 0.46 gives ixx = iyy = 0.092, izz = 0.0083
LINK = box("0.1 0.1 0.46", "0 0 0.23")


def test_a_cad_tensor_within_a_few_times_of_the_uniform_body_draws_nothing(tmp_path):
    # motors at the ends: twice the uniform moments, still inside what 5 kg in that box can reach
    cad = BASE + arm("link1", LINK + inertial(5, 0.18, 0.17, 0.005, ixz=0.004, xyz="0 0 0.23"))
    assert found(tmp_path, cad, "I009", "I010") == []


# a wrist of 1.4 kg whose collision is a cylinder turned to lie along y around the joint;
# the CAD tensor turns least about z (the next motor's axis)
WRIST = '<collision><origin rpy="1.57 0 0"/><geometry><cylinder radius="0.045" length="0.10"/></geometry></collision>'
WRIST_TENSOR = dict(ixx=0.00175, iyy=0.00157, izz=0.00122, ixy=-4.6e-06, ixz=-1.8e-06, iyz=0.000153)


def test_a_cad_tensor_centred_outside_its_turned_collision_shape_is_not_called_unrotated(tmp_path):
    # the centre of mass (the next motor, 0.107 m away) lies outside the cylinder: the tensor was not computed for it
    cad = BASE + arm("wrist", WRIST + inertial(1.4, xyz="0 -0.107 0.019", **WRIST_TENSOR))
    assert found(tmp_path, cad, "I009", "I010") == []


def test_the_same_tensor_centred_in_its_turned_collision_shape_is_called_unrotated(tmp_path):
    computed = BASE + arm("wrist", WRIST + inertial(1.4, **WRIST_TENSOR))
    (code, severity, message), = found(tmp_path, computed, "I009", "I010")
    assert code == "I010" and severity == "warning" and "'wrist'" in message and "rpy 1.57 0 0" in message


def test_a_moment_no_mass_inside_the_geometry_can_reach_is_flagged(tmp_path):
    # Panda link1's mistake: ixx = 0.703 on a 0.46 m link of 5 kg (at most 5 (0.23² + 0.05²) = 0.277)
    impossible = BASE + arm("link1", LINK + inertial(5, 0.70337, 0.70661, 0.009, xyz="0 0 0.23"))
    (code, severity, message), = found(tmp_path, impossible, "I009")
    assert severity == "warning" and "'link1'" in message and "iyy=0.707" in message and "2.6 times the most 5 kg can reach" in message


def test_the_reach_is_measured_from_the_declared_centre_of_mass(tmp_path):
    # the same tensor is possible about the box's centre, not about a centre near its end:
    # there the mass spreads at most (0.43)(0.03) along z
    tensor = inertial(5, 0.2, 0.2, 0.01, xyz="0 0 0.23")
    assert found(tmp_path, BASE + arm("link1", LINK + tensor), "I009") == []
    off_centre = inertial(5, 0.2, 0.2, 0.01, xyz="0 0 0.43")
    assert [c for c, _, _ in found(tmp_path, BASE + arm("link1", LINK + off_centre), "I009")] == ["I009"]


def test_proxy_shapes_and_links_of_a_few_grams_draw_nothing(tmp_path):
    # tiago's fingers: a millimetre sphere standing in, a tensor "to stabilize simulation"
    proxy = BASE + arm("finger", sphere(0.001) + inertial(0.05, 0.001, 0.001, 0.001))
    assert found(tmp_path, proxy, "I009", "I008") == []
    # 5 g with a tensor far beyond its 2 cm box: lost in a heavier body it is fixed to...
    light = BASE + arm("tip", box("0.02 0.02 0.02") + inertial(0.005, 1e-6, 1e-6, 1e-6), joint="fixed")
    assert found(tmp_path, light, "I009", "I008") == []
    # ...but a moving body is judged whatever its mass (issue: Kinova's 10 g finger links)
    moving = BASE + arm("tip", box("0.02 0.02 0.02") + inertial(0.005, 0.001, 0.001, 0.001))
    assert [c for c, _, _ in found(tmp_path, moving, "I009")] == ["I009"]
    # the same 50 g with that tensor on geometry that draws the finger is impossible
    real = BASE + arm("finger", box("0.02 0.02 0.08") + inertial(0.05, 0.001, 0.001, 0.001))
    assert [c for c, _, _ in found(tmp_path, real, "I009")] == ["I009"]


def test_an_orders_of_magnitude_placeholder_on_a_substantial_mass_is_flagged(tmp_path):
    # Baxter's gripper base: 0.3 kg with a 2e-8 tensor
    cylinder = '<collision><geometry><cylinder radius="0.04" length="0.05"/></geometry></collision>'
    placeholder = BASE + arm("gripper_base", cylinder + inertial(0.3, 2e-8, 3e-8, 2e-8), joint="fixed")
    (code, severity, message), = found(tmp_path, placeholder, "I009")
    assert severity == "warning" and "times below" in message and "a placeholder" in message
    # five times below the uniform body: mass near the axis, plausible
    plausible = BASE + arm("gripper_base", cylinder + inertial(0.3, 3e-5, 3e-5, 5e-5), joint="fixed")
    assert found(tmp_path, plausible, "I009") == []


def test_swapped_axes_are_flagged_and_rounding_is_not(tmp_path):
    camera = box("0.02 0.05 0.05")  # uniform: ixx = 4.17e-5, iyy = izz = 2.42e-5 for 0.1 kg
    swapped = BASE + arm("camera", camera + inertial(0.1, 2.42e-5, 2.42e-5, 4.17e-5), joint="fixed")
    (code, _, message), = found(tmp_path, swapped, "I009")
    assert "principal moments match its collision box, but on axes 90° away" in message
    rounded = BASE + arm("camera", camera + inertial(0.1, 4.2e-5, 2.4e-5, 2.4e-5), joint="fixed")
    assert found(tmp_path, rounded, "I009") == []
    # the same swap on a 10 g sensor frame (talos rgbd_link) moves nothing anyone feels: info
    light = BASE + arm("camera", camera + inertial(0.01, 2.42e-6, 2.42e-6, 4.17e-6), joint="fixed")
    assert [(c, s) for c, s, _ in found(tmp_path, light, "I009")] == [("I009", "info")]
    # nearly round (no moment 15 % apart from the others): no axis to get wrong. The box
    # gives ixx=2.62e-5 iyy=3.16e-5 izz=3.62e-5; ixx and izz exchanged are 28 % off
    roundish = BASE + arm("waist", box("0.05 0.043 0.036") + inertial(0.1, 3.62e-5, 3.16e-5, 2.62e-5), joint="fixed")
    assert found(tmp_path, roundish, "I009") == []


def test_suggest_does_not_call_a_uniform_body_a_correction(tmp_path):
    from conftest import run_cli

    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r">' + BASE + arm("link1", LINK + inertial(5, 0.70337, 0.70661, 0.009, xyz="0 0 0.23")) + "</robot>")
    out = run_cli("inertia", "--suggest", str(path)).stdout.decode()
    assert "<!-- link 'link1': a uniform body filling its collision box" in out and "corrected" not in out


# -- A.2: near-zero numbers --------------------------------------------------------------
def test_rounding_noise_is_zero_and_makes_a_point_mass_not_an_invalid_tensor(tmp_path):
    # iCub's head: 1.3 kg, one product of inertia of 2.4e-35 and the rest 0
    noise = BASE + arm("head", box("0.2 0.2 0.2") + inertial(1.33687, 0, 0, 0, ixz=2.40741e-35))
    assert [(c, s) for c, s, _ in found(tmp_path, noise, "I004", "I005", "I006")] == [("I004", "warning")]
    # a real product of inertia making it invalid is still I005
    invalid = BASE + arm("head", box("0.2 0.2 0.2") + inertial(1.3, 0.001, 0.001, 0.001, ixz=0.005))
    assert [c for c, _, _ in found(tmp_path, invalid, "I004", "I005", "I006")] == ["I005"]


# -- A.3: bodies, not links --------------------------------------------------------------
def test_a_collision_on_a_fixed_child_covers_the_moving_body(tmp_path):
    visual = '<visual><geometry><box size="0.1 0.1 0.3"/></geometry></visual>'
    torso = BASE + arm("torso", visual + inertial(5, 0.04, 0.04, 0.01), extra="")
    shape = arm("torso_collision", box("0.1 0.1 0.3"), joint="fixed", parent="torso")
    assert found(tmp_path, torso + shape, "D003") == []  # romeo's torso
    (code, severity, message), = found(tmp_path, torso, "D003")
    assert severity == "warning" and "'torso'" in message


def test_a_model_without_any_collision_gets_one_note(tmp_path):
    visual = '<visual><geometry><box size="0.1 0.1 0.3"/></geometry></visual>'
    display = f'<link name="base">{visual}</link>' + arm("a", visual) + arm("b", visual, parent="a")
    assert [(c, s) for c, s, _ in found(tmp_path, display, "D003")] == [("D003", "info")]


def test_a_massless_link_between_joints_of_a_massive_link_is_clean(tmp_path):
    # human.urdf's hips: three revolute joints through two massless *_virtual links
    hip = BASE + arm("hip_virtual", "") + arm("hip_virtual_2", "", parent="hip_virtual")
    hip += arm("upper_leg", box("0.1 0.1 0.4", "0 0 -0.2") + inertial(9, 0.13, 0.13, 0.015, xyz="0 0 -0.2"), parent="hip_virtual_2")
    assert found(tmp_path, hip, "I002") == []


def test_a_massless_moving_branch_is_one_warning_naming_its_links(tmp_path):
    # romeo's fingers: three massless phalanges driven by one joint and its mimics
    finger = BASE + arm("finger1", "") + arm("finger2", "", parent="finger1") + arm("finger3", "", parent="finger2")
    (code, severity, message), = found(tmp_path, finger, "I002")
    assert severity == "warning" and "'finger1', 'finger2', 'finger3'" in message and "joint 'finger1_joint'" in message


def test_a_light_frame_on_a_fixed_joint_is_not_a_point_mass(tmp_path):
    frame = BASE + arm("imu", inertial(0.005, 0, 0, 0), joint="fixed")
    assert found(tmp_path, frame, "I004") == []
    wrist = arm("wrist", box("0.05 0.05 0.05") + inertial(0.2, 0.0001, 0.0001, 0.0001))
    sensor = BASE + wrist + arm("ft_sensor", inertial(0.1, 0, 0, 0), joint="fixed", parent="wrist")  # tiago's wrist_ft_link
    assert [c for c, _, _ in found(tmp_path, sensor, "I004", "I009")] == ["I004"]  # one cause, one diagnostic


def test_a_point_mass_fixed_to_a_much_heavier_body_is_lost_in_it(tmp_path):
    """Stretch's 75 g laser on its 15 kg base, TALOS's 100 g force sensors on its wrists,
    ROS-Industrial's 0.4 kg link_t on a 4.8 kg flange: lumped into the body, the mass
    counts where it is; the missing turning of a small part is lost in the body's. Unless
    its shapes say it would turn the body materially (a long bar)."""
    laser = BASE + arm("laser", sphere(0.03) + inertial(0.075, 0, 0, 0), joint="fixed")
    assert found(tmp_path, laser, "I004") == []
    bar = BASE + arm("bar", box("2 0.02 0.02") + inertial(0.9, 0, 0, 0), joint="fixed")
    assert [c for c, _, _ in found(tmp_path, bar, "I004")] == ["I004"]  # 0.3 kg·m² about z, beside the base's 0.27
    heavy = BASE + arm("motor", inertial(3, 0, 0, 0), joint="fixed")  # a quarter of the body's mass
    assert [c for c, _, _ in found(tmp_path, heavy, "I004")] == ["I004"]


def test_an_invalid_tensor_on_a_dummy_link_of_a_heavier_body_is_a_warning_naming_mujoco(tmp_path):
    # ANYmal's root: 1e-6 kg with every element 1e-6, fixed to the real base; TIAGo's 1 mg
    # antennas: a negative principal moment. Lumped into the base they change nothing, but
    # MuJoCo refuses the model (tested against MuJoCo in tests/test_targets.py's cases).
    dummy = '<link name="root">' + inertial(1e-6, 1e-6, 1e-6, 1e-6, 1e-6, 1e-6, 1e-6) + "</link>"
    dummy += arm("base", box("0.4 0.4 0.1") + inertial(10, 0.14, 0.14, 0.27), joint="fixed", parent="root")
    [(code, severity, message)] = [(d.code, d.severity.value, d.message) for d in lint(tmp_path, dummy) if d.code in ("I005", "I006", "I011")]
    assert (code, severity) == ("I006", "warning") and "MuJoCo refuses the model" in message
    antenna = '<link name="base">' + box("0.4 0.4 0.1") + inertial(10, 0.14, 0.14, 0.27) + "</link>"
    antenna += arm("antenna", '<inertial><mass value="0.000001"/><inertia ixx="2.371e-08" ixy="6.119e-08" ixz="1.179e-08" '
                   'iyy="2.833e-08" iyz="7.74e-09" izz="3.849e-08"/></inertial>', joint="fixed", parent="base")
    [(code, severity, message)] = [(d.code, d.severity.value, d.message) for d in lint(tmp_path, antenna) if d.code in ("I005", "I006")]
    assert (code, severity) == ("I005", "warning") and "Drake replaces the tensor" in message


# -- A.4: one cause, one diagnostic ------------------------------------------------------
def test_identity_on_many_links_is_one_diagnostic_naming_them(tmp_path):
    # simple_humanoid: the identity on every link drew I007 and I008 on each
    body = '<link name="base">' + box("0.3 0.3 0.3") + inertial(27, 1, 1, 1) + "</link>"
    body += arm("a", box("0.1 0.1 0.3") + inertial(2, 1, 1, 1)) + arm("b", box("0.1 0.1 0.3") + inertial(1, 1, 1, 1), parent="a")
    diagnostics = found(tmp_path, body, "I007", "I008", "I009")
    assert [(c, m) for c, _, m in diagnostics] == [("I007", "inertia of 3 links is the identity, a placeholder: 'base', 'a' and 'b'")]


def test_a_tensor_shared_by_links_of_different_size_is_one_diagnostic(tmp_path):
    # PR2's casters: one tensor on the 3.5 kg caster body and its 0.44 kg wheels
    tensor = inertial(3.5, 0.0124, 0.0152, 0.0118)
    wheel = inertial(0.44, 0.0124, 0.0152, 0.0118)
    casters = BASE + arm("caster", box("0.1 0.1 0.1") + tensor) + arm("wheel_l", box("0.08 0.02 0.08") + wheel, parent="caster")
    casters += arm("wheel_r", box("0.08 0.02 0.08") + wheel, parent="caster")
    diagnostics = found(tmp_path, casters, "I008", "I009")
    assert [c for c, _, _ in diagnostics] == ["I008"]
    # the tensor fits the caster: the diagnostic is about the wheels
    assert "links 'wheel_l' and 'wheel_r' (0.44 kg) have the inertia tensor" in diagnostics[0][2] and "of 1 other link (3.5 kg)" in diagnostics[0][2]
    assert "caster" not in diagnostics[0][2]  # identical parts may share a tensor: only those it does not fit are named


def test_identical_links_sharing_a_tensor_and_light_dummies_are_not_placeholders(tmp_path):
    wheel = box("0.08 0.02 0.08") + inertial(0.44, 0.000250, 0.000469, 0.000250)
    twins = BASE + arm("wheel_l", wheel) + arm("wheel_r", wheel)
    assert found(tmp_path, twins, "I008") == []
    frames = BASE + arm("tool", inertial(0.001, 1e-5, 1e-5, 1e-5), joint="fixed") + arm("camera", inertial(0.01, 1e-5, 1e-5, 1e-5), joint="fixed")
    assert found(tmp_path, frames, "I008") == []


def test_an_invalid_tensor_shared_by_links_is_not_also_a_placeholder(tmp_path):
    # PR2's sensor_mount_link and double_stereo_link: one tensor breaking the triangle inequality
    invalid = inertial(0.05, 0.001, 0.001, 0.01)
    mounts = BASE + arm("mount", box("0.05 0.05 0.05") + invalid, joint="fixed")
    mounts += arm("stereo", box("0.05 0.05 0.05") + inertial(0.1, 0.001, 0.001, 0.01), joint="fixed")
    diagnostics = found(tmp_path, mounts, "I006", "I008", "I009")
    assert [(c, m.split("'")[1]) for c, _, m in diagnostics] == [("I006", "mount"), ("I006", "stereo")]


# -- A.5: root inertia ---------------------------------------------------------------------
def test_root_inertia_is_a_note_and_a_dummy_root_is_silent(tmp_path):
    assert [(c, s) for c, s, _ in found(tmp_path, BASE, "I011")] == [("I011", "info")]
    dummy = '<link name="base">' + box("0.4 0.4 0.1") + inertial(1e-6, 1e-9, 1e-9, 1e-9) + "</link>"
    assert found(tmp_path, dummy, "I011") == []


def test_a_massless_foot_frame_with_a_tiny_tensor_draws_nothing(tmp_path):
    # Bolt's FL_FOOT: mass 0 with 5e-7 kg m2, fixed to a lower leg of 0.2 kg
    leg = BASE + arm("leg", box("0.03 0.03 0.2") + inertial(0.2, 0.0007, 0.0007, 0.00003))
    foot = arm("foot", inertial(0, 5e-7, 5e-7, 5e-7), joint="fixed", parent="leg")
    assert found(tmp_path, leg + foot, "I003") == []
    # the same tensor on a link that moves on its own, or a real tensor without mass: flagged
    moving = arm("foot", inertial(0, 5e-7, 5e-7, 5e-7), parent="leg")
    assert [c for c, _, _ in found(tmp_path, leg + moving, "I003")] == ["I003"]
    heavy = arm("foot", inertial(0, 0.1, 0.1, 0.1), joint="fixed", parent="leg")
    assert [c for c, _, _ in found(tmp_path, leg + heavy, "I003")] == ["I003"]


# -- C.8, C.9: limits that stop a joint ---------------------------------------------------
def limited(joint_type: str, limit: str, mimic: str = "") -> str:
    return ('<link name="base"/><link name="wheel"/>'
            f'<joint name="wheel_joint" type="{joint_type}"><parent link="base"/><child link="wheel"/>'
            f'<axis xyz="0 1 0"/>{limit}{mimic}</joint>')


@pytest.mark.parametrize("joint_type, limit, flagged", [
    ("revolute", '<limit effort="10" velocity="5"/>', True),  # centauro's j_wheel_1: range [0, 0]
    ("prismatic", '<limit effort="10" velocity="5"/>', True),
    ("revolute", '<limit upper="1.5" effort="10" velocity="5"/>', False),  # [0, 1.5] is a range
    ("continuous", '<limit effort="10" velocity="5"/>', False),
])
def test_a_revolute_joint_without_a_range(tmp_path, joint_type, limit, flagged):
    diagnostics = found(tmp_path, limited(joint_type, limit), "J013")
    assert [(c, s) for c, s, _ in diagnostics] == ([("J013", "warning")] if flagged else [])


TRANSMISSION = ('<transmission name="t"><type>transmission_interface/SimpleTransmission</type><joint name="wheel_joint">'
                '<hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint></transmission>')


def test_zero_effort_or_velocity_on_a_driven_joint(tmp_path):
    zero = limited("revolute", '<limit lower="0" upper="1" effort="0" velocity="0"/>')
    (code, severity, message), = found(tmp_path, zero + TRANSMISSION, "J014")
    assert severity == "warning" and "effort=0 and velocity=0" in message and "commands it no torque or force and no speed" in message
    # romeo's LHand: nothing drives it, so it is taken as passive, a note
    (code, severity, message), = found(tmp_path, zero, "J014")
    assert severity == "info" and "taken as passive" in message
    assert [c for c, _, _ in found(tmp_path, limited("continuous", '<limit effort="10" velocity="-1"/>'), "J014")] == ["J014"]
    # a mimic joint follows another and is not driven
    mimic = limited("revolute", '<limit lower="0" upper="1" effort="0" velocity="0"/>', '<mimic joint="drive"/>')
    mimic += '<link name="hub"/><joint name="drive" type="continuous"><parent link="base"/><child link="hub"/></joint>'
    assert found(tmp_path, mimic, "J014") == []
    assert found(tmp_path, limited("revolute", '<limit lower="0" upper="1" effort="5" velocity="2"/>'), "J014") == []


def test_zero_effort_on_every_driven_joint_of_an_arm_is_one_warning(tmp_path):
    # a ROS-Industrial arm writes effort="0" on every joint; its MoveIt config drives them all through ros2_control
    arm = '<link name="l0"/>' + "".join(
        f'<link name="l{i}"/><joint name="joint_{i}" type="revolute"><parent link="l{i - 1}"/><child link="l{i}"/>'
        f'<axis xyz="0 0 1"/><limit effort="0" lower="-3" upper="3" velocity="3.67"/></joint>' for i in range(1, 4))
    arm += ('<ros2_control name="fake" type="system"><hardware><plugin>mock_components/GenericSystem</plugin></hardware>'
            + "".join(f'<joint name="joint_{i}"><command_interface name="position"/></joint>' for i in range(1, 4))
            + "</ros2_control>")
    (code, severity, message), = found(tmp_path, arm, "J014")
    assert severity == "warning" and message.startswith("3 joints ('joint_1', 'joint_2', 'joint_3') have effort=0")
    assert "MoveIt" not in message  # MoveIt reads no effort limit
    (code, severity, message), = found(tmp_path, arm.replace('velocity="3.67"', 'velocity="0"', 1).replace('effort="0"', 'effort="5"', 1), "J014")[:1]
    assert message.startswith("joint 'joint_1' has velocity=0") and "MoveIt" in message


@pytest.mark.parametrize("limit, flagged", [
    ('<limit lower="-1" upper="1" effort="10" velocity="5"/>', True),  # meant to be revolute
    ('<limit lower="-6.2832" upper="6.2832" effort="10" velocity="5"/>', False),  # kinova: a leftover
    ('<limit lower="-3.14159" upper="3.14159" effort="10" velocity="5"/>', False),  # a full turn
    ('<limit upper="1" effort="10" velocity="5"/>', False),  # one bound: meaning unclear
])
def test_a_continuous_joint_with_a_range_narrower_than_a_turn(tmp_path, limit, flagged):
    diagnostics = found(tmp_path, limited("continuous", limit), "J012")
    assert [(c, s) for c, s, _ in diagnostics] == ([("J012", "warning")] if flagged else [])


def test_severities_are_as_documented():
    from urdfcli.rules import rule

    assert rule("I011").severity is Severity.INFO
    for code in ("I002", "I004", "I008", "I009", "J013", "J014", "D003"):
        assert rule(code).severity is Severity.WARNING


def test_axes_swapped_on_a_long_link_are_found_though_its_moments_are_not_the_geometrys(tmp_path):
    """A hand 0.2 m long along y whose declared tensor turns hardest about y: its moments
    are CAD-like (within a few times of the box's), so they match the geometry on no axis,
    and yet the long axis says the axes are swapped. The same hand turned right draws nothing."""
    swapped = BASE + arm("hand", box("0.1 0.2 0.05") + inertial(0.2, 0.0002, 0.0005, 0.0004))
    [(code, severity, message)] = found(tmp_path, swapped, "I009")
    assert (code, severity) == ("I009", "warning")
    assert "long along y, so its moment about y is its smallest, but the declared tensor turns hardest about y" in message
    right = BASE + arm("hand", box("0.1 0.2 0.05") + inertial(0.2, 0.0005, 0.0002, 0.0004))
    assert found(tmp_path, right, "I009") == []


STANDOFF = """<?xml version="1.0"?>
<robot name="tower" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base"/>
  <xacro:macro name="standoff" params="name x">
    <joint name="${name}_joint" type="fixed"><parent link="base"/><child link="${name}"/><origin xyz="${x} 0 0"/></joint>
    <link name="${name}">
      <collision><geometry><cylinder radius="0.004" length="0.2"/></geometry></collision>
      <inertial>
        <mass value="0.1"/>
        <inertia ixx="0.0000008" ixy="0" ixz="0" iyy="0.000334" iyz="0" izz="0.000334"/>
      </inertial>
    </link>
  </xacro:macro>
  <xacro:standoff name="s1" x="0.1"/>
  <xacro:standoff name="s2" x="0.2"/>
  <xacro:standoff name="s3" x="0.3"/>
  <xacro:standoff name="s4" x="0.4"/>
</robot>
"""


def test_axes_swapped_in_a_macro_body_are_one_diagnostic_naming_every_link_its_calls_made(tmp_path):
    """TurtleBot 4's tower standoffs: one tensor with swapped axes written once in a macro
    called four times drew four I009 at one line, alike but for the link's name. It is one,
    naming the links, whose fix writes the tensor once and leaves no I009."""
    path = tmp_path / "tower.urdf.xacro"
    path.write_text(STANDOFF)
    [found] = [d for d in lint_file(str(path), Config.everything()).diagnostics if d.code == "I009"]
    assert found.message.startswith("inertia of links 's1', 's2', 's3' and 1 more: izz=0.000334 (link axes) is 104.4 times the most")
    assert found.subjects == ("s1", "s2", "s3", "s4") and (found.path, found.line) == (str(path), 10)
    edits = found.fix.edits
    assert edits and len({(e.start, e.end) for e in edits}) == len(edits), edits  # each literal of the body once
    done = run_cli("lint", "--isolated", "--select", "I009", "--fix", "--unsafe-fixes", str(path))
    assert re.search(r"^1 fixed, 0 remaining", done.stdout.decode(), re.M), done.stdout.decode()
    assert [d.code for d in lint_file(str(path), Config.everything()).diagnostics if d.code == "I009"] == []


def test_any_rule_a_macro_multiplies_says_it_once_in_a_sentence_that_stays_right(tmp_path):
    """I003 (mass 0, a tensor) in the same macro: 'link 'a' has ...' cannot become 'links ... has',
    so the other links are named beside the first."""
    path = tmp_path / "tower.urdf.xacro"
    path.write_text(STANDOFF.replace('<mass value="0.1"/>', '<mass value="0"/>').replace('  <xacro:standoff name="s3" x="0.3"/>\n  <xacro:standoff name="s4" x="0.4"/>\n', ""))
    [found] = [d for d in lint_file(str(path), Config.everything()).diagnostics if d.code == "I003"]
    assert (found.message, found.subjects) == ("link 's1' (and 's2' alike) has mass 0 but a non-zero inertia tensor", ("s1", "s2"))


ARM = """<robot name="arms" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="world"/>
  <xacro:macro name="arm" params="prefix">
    <link name="${prefix}upper"/>
    <joint name="${prefix}shoulder" type="revolute">
      <parent link="world"/><child link="${prefix}upper"/>
      <limit lower="-1" upper="1" effort="ten" velocity="1"/>
    </joint>
    <joint name="${prefix}elbow" type="revolute"><parent link="${prefix}upper"/><child link="${prefix}fore"/></joint>
    <link name="${prefix}fore"/>
  </xacro:macro>
  <xacro:arm prefix="left_"/>
  <xacro:arm prefix="right_"/>
</robot>
"""


def test_what_the_reader_finds_in_a_macro_body_is_said_once_for_its_calls(tmp_path):
    """A joint without <limit> and a limit that is no number, written once in a macro called
    for each arm: one diagnostic each, naming both joints (as the rules' findings are), not
    one per call at the same line."""
    path = tmp_path / "arms.urdf.xacro"
    path.write_text(ARM)
    found = {d.code: d for d in lint_file(str(path), Config.everything()).diagnostics if d.code in ("J003", "V001")}
    assert [d.code for d in lint_file(str(path), Config.everything()).diagnostics].count("J003") == 1
    assert found["J003"].message == "revolute joint 'left_elbow' (and 'right_elbow' alike) has no <limit>"
    assert found["J003"].subjects == ("left_elbow", "right_elbow") and found["J003"].line == 9
    assert found["V001"].subjects == ("left_shoulder", "right_shoulder"), found["V001"]


UNPREFIXED_LIMIT = """<robot name="hand" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="palm"/>
  <xacro:macro name="actuator" params="name *limit">
    <joint name="${name}_joint" type="revolute">
      <parent link="palm"/><child link="${name}_link"/>
      <insert_block name="limit"/>
    </joint>
    <link name="${name}_link"/>
  </xacro:macro>
  <xacro:actuator name="thumb"><limit lower="-1" upper="1" effort="2" velocity="3"/></xacro:actuator>
</robot>
"""


def test_a_limit_lost_to_an_insert_block_without_prefix_is_traced_to_it(tmp_path):
    """The call gives a <limit>, but the body's <insert_block> lacks xacro: and is copied as it
    is: 'add <limit>' would send the reader to a limit already written."""
    path = tmp_path / "hand.urdf.xacro"
    path.write_text(UNPREFIXED_LIMIT)
    [found] = [d for d in lint_file(str(path), Config.everything()).diagnostics if d.code == "J003"]
    assert found.message == "revolute joint 'thumb_joint' has no <limit>"
    assert "<insert_block name=\"limit\"/>" in found.hint and "xacro:insert_block" in found.hint, found.hint



def test_an_inertia_lost_to_a_macro_called_without_prefix_is_traced_to_the_call(tmp_path):
    """Robotnik's pallet truck writes <cylinder_inertia m="..."/> in its wheels' <inertial>:
    without xacro: the call is copied as written and the <inertial> has no <inertia> (V005,
    urdfdom refuses it). The hint names the call; a misspelt child is offered its right name,
    and a plain URDF is not told about xacro."""
    head = '<robot name="truck" xmlns:xacro="http://www.ros.org/wiki/xacro">'
    macro = '<xacro:macro name="cylinder_inertia" params="m"><inertia ixx="${m}" ixy="0" ixz="0" iyy="${m}" iyz="0" izz="${m}"/></xacro:macro>'
    path = tmp_path / "truck.urdf.xacro"
    path.write_text(f'{head}\n{macro}\n<link name="wheel"><inertial><mass value="1"/><cylinder_inertia m="1"/></inertial></link>\n</robot>\n')
    [found] = [d for d in lint_file(str(path), Config()).diagnostics if d.code == "V005"]
    assert found.message == "<inertial> has no <inertia>" and found.line == 3
    assert found.hint == ("it holds <cylinder_inertia>, which URDF does not read: a xacro macro called without the xacro: prefix is "
                          "copied as written; write <xacro:cylinder_inertia .../>")
    path.write_text(f'{head}\n{macro}\n<link name="wheel"><inertial><mass value="1"/><xacro:cylinder_inertia m="1"/></inertial></link>\n</robot>\n')
    assert [d for d in lint_file(str(path), Config()).diagnostics if d.code == "V005"] == []
    plain = tmp_path / "truck.urdf"
    for child, hint in (('<intertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>', "did you mean <inertia>? it holds <intertia>"),
                        ('<cylinder_inertia m="1"/>', None)):
        plain.write_text(f'<robot name="truck"><link name="wheel"><inertial><mass value="1"/>{child}</inertial></link></robot>\n')
        [found] = [d for d in lint_file(str(plain), Config()).diagnostics if d.code == "V005"]
        assert found.hint == hint

# -- A.3: the centre of mass against the geometry -----------------------------------------
# Doosan m1013's link 3: a forearm 0.4 m long whose centre of mass is written in the base frame
FOREARM = box("0.08 0.08 0.4", "0 0 0.2")
FOREARM_TENSOR = dict(ixx=0.05, iyy=0.05, izz=0.004)


def forearm(centre: str, inside: str = FOREARM) -> str:
    return BASE + arm("forearm", inside + inertial(3.8, **FOREARM_TENSOR, xyz=centre), extra='<origin xyz="0 0 0.95"/>')


def test_a_centre_of_mass_written_in_the_base_frame_is_flagged(tmp_path):
    (code, severity, message), = found(tmp_path, forearm("0 0 1.15"), "I013")
    assert severity == "warning" and "'forearm' (0 0 1.15) lies 0.75 m outside the box (-0.04 -0.04 0) to (0.04 0.04 0.4)" in message
    # the root frame puts it 0.2 m up the forearm: said, as the likely mistake
    assert message.endswith("read in the frame of the root link 'base', it lies inside")
    # a centre wrong in any other way is flagged too, without that reading
    (_, _, message), = found(tmp_path, forearm("0 0 -0.5"), "I013")
    assert "lies 0.5 m outside" in message and "root link" not in message


def test_the_root_a_centre_is_read_in_is_named_when_the_model_has_two_roots(tmp_path):
    # a second, unconnected root: the model has no single root, the forearm's is still 'base'
    (_, _, message), = found(tmp_path, forearm("0 0 1.15") + '<link name="stray"/>', "I013")
    assert message.endswith("read in the frame of the root link 'base', it lies inside"), message


def test_a_centre_inside_or_just_outside_the_shapes_is_not_flagged(tmp_path):
    assert found(tmp_path, forearm("0 0 0.18"), "I013") == []
    # 9 cm past the end of a 0.4 m box: within a quarter of its longest side (a mount left undrawn)
    assert found(tmp_path, forearm("0 0 0.49"), "I013") == []
    # and 11 cm is not
    assert [c for c, _, _ in found(tmp_path, forearm("0 0 0.51"), "I013")] == ["I013"]
    # a small part: 4 cm out of a 6 cm box is within the 5 cm any part's undrawn pieces can shift it
    small = BASE + arm("camera", box("0.06 0.04 0.04") + inertial(0.3, 1e-4, 1e-4, 1e-4, xyz="-0.07 0 0"))
    assert found(tmp_path, small, "I013") == []


def test_frames_stand_ins_and_placeholders_draw_no_centre_warning(tmp_path):
    # a link without shapes, a frame: nothing to hold its centre
    assert found(tmp_path, forearm("0 0 1.15", inside=""), "I013") == []
    # a mass denser than steel in its box: the shapes draw a part only (a motor drawn as a disc)
    disc = '<collision><geometry><cylinder radius="0.038" length="0.013"/></geometry></collision>'
    assert found(tmp_path, BASE + arm("hip", disc + inertial(0.754, 5e-4, 3e-4, 5e-4, xyz="0 -0.078 0")), "I013") == []
    # a stand-in collision far smaller than the visual: the union of both holds the centre
    visual = '<visual><origin xyz="0 0 0.2"/><geometry><box size="0.08 0.08 0.4"/></geometry></visual>'
    assert found(tmp_path, forearm("0 0 0.3", inside=visual + sphere(0.002)), "I013") == []


def test_the_reach_of_a_tensor_about_a_misplaced_centre_is_not_judged(tmp_path):
    # moments no mass in the box could reach about the declared centre: the centre is the mistake, said once
    huge = BASE + arm("forearm", FOREARM + inertial(3.8, 20, 20, 20, xyz="0 0 1.15"), extra='<origin xyz="0 0 0.95"/>')
    assert [c for c, _, _ in found(tmp_path, huge, "I009", "I013")] == ["I013"]
    # about a centre inside the shapes, the same moments are impossible
    inside = BASE + arm("forearm", FOREARM + inertial(3.8, 20, 20, 20, xyz="0 0 0.2"), extra='<origin xyz="0 0 0.95"/>')
    assert [c for c, _, _ in found(tmp_path, inside, "I009", "I013")] == ["I009"]


def test_a_mesh_holds_the_centre_of_mass_where_its_vertices_are(tmp_path):
    from support.meshes import box as box_mesh, write

    mesh = box_mesh((0.08, 0.08, 0.4))
    mesh.apply_translation((0, 0, 0.2))
    write(tmp_path / "meshes" / "forearm.stl", mesh)
    shapes = '<collision><geometry><mesh filename="meshes/forearm.stl"/></geometry></collision>'
    assert found(tmp_path, forearm("0 0 0.18", inside=shapes), "I013") == []
    (_, _, message), = found(tmp_path, forearm("0 0 1.15", inside=shapes), "I013")
    assert "lies 0.75 m outside the box (-0.04 -0.04 0) to (0.04 0.04 0.4)" in message
    # a mesh that cannot be read: its size is unknown, nothing is said
    missing = '<collision><geometry><mesh filename="meshes/missing.stl"/></geometry></collision>'
    assert found(tmp_path, forearm("0 0 1.15", inside=missing), "I013") == []


def test_an_invisible_visual_of_a_virtual_wheel_needs_no_collision(tmp_path):
    # ros2_control_demos' carlikebot: a virtual wheel between the real ones, drawn in a
    # material of alpha 0, stands for them in the bicycle model
    invisible = '<material name="invisible"><color rgba="0 0 0 0"/></material>'
    wheel = '<visual><geometry><cylinder radius="0.05" length="0.01"/></geometry><material name="invisible"/></visual>'
    virtual = BASE + arm("virtual_wheel", wheel + inertial(0.1, 1e-4, 1e-4, 1e-4))
    assert found(tmp_path, invisible + virtual, "D003") == []
    inline = wheel.replace('<material name="invisible"/>', '<material name="clear">' + '<color rgba="0 0 0 0"/></material>')
    assert found(tmp_path, BASE + arm("virtual_wheel", inline + inertial(0.1, 1e-4, 1e-4, 1e-4)), "D003") == []
    (code, severity, message), = found(tmp_path, invisible.replace('0 0 0 0', '0 0 0 1') + virtual, "D003")
    assert severity == "warning" and "'virtual_wheel'" in message
