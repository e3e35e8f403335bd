"""The "did you mean" search gives difflib's answer, with less of its work, and never a name
that is the misspelt one with a whole prefix or suffix cut off, with other numbers, or with
whole parts unlike its own; the name with one added first."""

from __future__ import annotations

import difflib

import pytest

from hypothesis import given, settings
from hypothesis import strategies as st

from urdfcli.read.names import cut_from, numbered_apart, parts_apart, typo_of
from urdfcli.rules.suggestions import close_matches

NAMES = st.text(alphabet="abcde_12", max_size=8)  # few letters: many ties and near misses


@settings(max_examples=2000, deadline=None)
@given(NAMES, st.lists(NAMES, max_size=30), st.integers(1, 4), st.sampled_from([0.0, 0.3, 0.6, 0.8]))
def test_the_same_names_as_difflib(word, candidates, n, cutoff):
    if any(cut_from(candidate, word) for candidate in candidates):
        return  # (the word with a prefix or suffix added comes first: below)
    kept = [c for c in candidates if not cut_from(word, c) and not numbered_apart(word, c) and not parts_apart(word, c)]
    assert close_matches(word, candidates, n, cutoff) == difflib.get_close_matches(word, kept, n, cutoff)


def test_a_forgotten_prefix_is_offered_before_a_closer_spelling():
    """ROS-Industrial's ma1440_d500: a transmission names 'joint_1', the positioner's joint is
    'd500_joint_1' (a ${prefix} forgotten); difflib ranks the arm's 'joint_u' first, whose
    actuator it is not. Of several, the one adding least comes first."""
    joints = ["joint_s", "joint_l", "joint_u", "joint_r", "d500_joint_1", "d500_joint_2"]
    assert difflib.get_close_matches("joint_1", joints, n=1) == ["joint_u"]
    assert close_matches("joint_1", joints) == ["d500_joint_1"]
    assert close_matches("base", ["base_footprint", "base_link", "bse"]) == ["base_link"]


@pytest.mark.parametrize("suggest", [close_matches, lambda word, names: [typo_of(word, names)]])
def test_another_number_of_a_series_is_not_offered(suggest):
    """lbr_fri_ros2_stack's SRDF after lbr_link_7 was renamed lbr_link_flange: each pair naming
    lbr_link_7 said "did you mean 'lbr_link_6'?", which would disable another pair's checks."""
    links = [f"lbr_link_{i}" for i in range(7)] + ["lbr_link_flange", "lbr_link_ee"]
    assert suggest("lbr_link_7", links) in ([], [None])
    assert suggest("A8", ["A1", "A2", "A7"]) in ([], [None])
    assert suggest("link7", ["link", "link6"]) in ([], [None])
    # a typo beside the number is still one
    assert suggest("lbr_lnk_6", links) == ["lbr_link_6"]
    assert suggest("joint1", ["joint_1", "joint_2"]) == ["joint_1"]


def test_a_misspelt_link_among_many():
    links = [f"{side}_{part}_link" for side in ("left", "right") for part in ("shoulder", "elbow", "wrist", "finger", "thumb", "palm")]
    assert close_matches("left_elbw_link", links) == ["left_elbow_link"]
    assert close_matches("left_elbw_link", links, n=3) == ["left_elbow_link"]  # (difflib adds right_elbow_link, left_palm_link)


@pytest.mark.parametrize("suggest", [close_matches, lambda word, names: [typo_of(word, names)]])
def test_a_name_cut_short_is_not_offered_and_a_typo_is(suggest):
    """Doosan's SRDF names 'robotiq_85_base_link', which its URDF lacks: 'base_link' is the
    robot's base, not the fix (difflib ranks it first). Real typos keep their hint."""
    links = ["base_link", "link9", "tool0", "shoulder_link", "wrist_1_link"]
    assert difflib.get_close_matches("robotiq_85_base_link", links) == ["base_link"]
    for cut_short in ("robotiq_85_base_link", "base_link_2", "wrist_1_link_inertia"):
        assert suggest(cut_short, links) in ([], [None]), cut_short
    typos = {"link_9": "link9", "tool_0": "tool0", "shoulder_lnk": "shoulder_link", "wrist_1_lnk": "wrist_1_link"}

    for typo, meant in typos.items():
        assert suggest(typo, links) == [meant], typo


def test_a_prefix_written_twice_is_offered_the_name_once():
    """A macro that adds its prefix to a name already prefixed (PR2's gazebo reference
    'double_stereo_double_stereo_link'): the name with the prefix once is what was meant,
    though it is the word with a part cut off."""
    links = ["double_stereo_link", "double_stereo_frame_joint", "base_link"]
    assert close_matches("double_stereo_double_stereo_link", links) == ["double_stereo_link"]
    assert close_matches("base_link_link", links) == ["base_link"]


def test_a_name_sharing_a_prefix_but_not_the_part_that_differs_is_not_offered():
    """franka's SRDF names 'panda_hand' when the URDF has no hand: difflib offered 'panda_link8'
    (the shared 'panda_' carries the score), and 'right_hand' for 'left_hand'. A typo in the part
    that differs is still offered, and so is a name with a part left out (a prefix written twice)."""
    names = ["panda_link0", "panda_link5", "panda_link8", "panda_joint1", "panda_joint7", "right_hand", "sensor_mount_link", "right_elbow_link"]
    assert difflib.get_close_matches("panda_hand", names, n=1) == ["panda_link8"]
    for other in ("panda_hand", "left_hand", "left_elbw_link"):
        assert close_matches(other, names) == [], other
    assert close_matches("panda_jiont1", names) == ["panda_joint1"]
    assert close_matches("rigth_hand", names) == ["right_hand"]
    assert close_matches("sensor_mount_sensor_link", names) == ["sensor_mount_link"]
    # alike only in the suffix every name ends in: go2's stale 'stick_link', Limo's 'caster_wheel_link'
    assert close_matches("stick_link", ["imu_link", "base_link"]) == [] and close_matches("imu_lnk", ["imu_link"]) == ["imu_link"]
    assert close_matches("caster_wheel_link", ["laser_link", "base_link"]) == []
