"""The mass-property maths against the closed forms of solid bodies and against numpy/trimesh."""

from __future__ import annotations

import math

import numpy
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from urdfcli.model import massprops as mp

finite = st.floats(min_value=-10, max_value=10, allow_nan=False, allow_infinity=False)
positive = st.floats(min_value=0.01, max_value=10, allow_nan=False, allow_infinity=False)
angles = st.floats(min_value=-math.pi, max_value=math.pi, allow_nan=False)


def close(a, b, rel=1e-9, abs_=1e-12):
    assert numpy.allclose(numpy.array(a, dtype=float), numpy.array(b, dtype=float), rtol=rel, atol=abs_), (a, b)


def test_box_cylinder_sphere_match_the_spec_formulas():
    m, x, y, z = 2.0, 0.5, 0.3, 0.1
    close(mp.box(m, (x, y, z)), mp.diagonal(m * (y * y + z * z) / 12, m * (x * x + z * z) / 12, m * (x * x + y * y) / 12))
    close(mp.box(2.0, (0.5, 0.3, 0.1)), mp.diagonal(0.0166667, 0.0433333, 0.0566667), rel=1e-5)  # fixtures/README numbers
    r, h = 0.05, 0.02
    close(mp.cylinder(0.5, r, h), mp.diagonal(0.5 * (3 * r * r + h * h) / 12, 0.5 * (3 * r * r + h * h) / 12, 0.5 * r * r / 2))
    close(mp.sphere(0.5, 0.03875), mp.diagonal(0.0003003125, 0.0003003125, 0.0003003125))


def test_volumes():
    assert mp.box_volume((1, 2, 3)) == 6
    assert mp.cylinder_volume(1, 2) == pytest.approx(2 * math.pi)
    assert mp.sphere_volume(3) == pytest.approx(36 * math.pi)


@settings(max_examples=200, deadline=None)
@given(st.lists(finite, min_size=6, max_size=6))
def test_principal_moments_are_numpys_eigenvalues(values):
    tensor = mp.matrix(dict(zip(mp.KEYS, values)))
    expected = numpy.linalg.eigvalsh(numpy.array(tensor))
    close(mp.principal_moments(tensor), expected, rel=1e-6, abs_=1e-7 * max(1.0, mp.scale_of(tensor)))


@settings(max_examples=300, deadline=None)
@given(st.lists(finite, min_size=6, max_size=6))
def test_positive_semidefinite_agrees_with_numpy(values):
    tensor = mp.matrix(dict(zip(mp.KEYS, values)))
    smallest = numpy.linalg.eigvalsh(numpy.array(tensor))[0]
    scale = max(mp.scale_of(tensor), 1e-300)
    if abs(smallest) > 1e-6 * scale:  # clear cases only: the boundary is rounding
        assert mp.is_positive_semidefinite(tensor) == (smallest > 0)


def test_a_rank_one_tensor_is_positive_semidefinite():
    assert mp.is_positive_semidefinite(mp.matrix(dict.fromkeys(mp.KEYS, 7.953125)))


@settings(max_examples=100, deadline=None)
@given(angles, angles, angles)
def test_rotation_is_urdfs_fixed_axis_rpy(roll, pitch, yaw):
    import trimesh.transformations as tf

    close(mp.rotation((roll, pitch, yaw)), tf.euler_matrix(roll, pitch, yaw, "sxyz")[:3, :3], abs_=1e-12)


def test_rotating_a_box_a_quarter_turn_about_z_swaps_ixx_and_iyy():
    rotated = mp.tidy(mp.rotate(mp.box(1.0, (0.4, 0.2, 0.1)), mp.rotation((0, 0, math.pi / 2))))
    close(rotated, mp.box(1.0, (0.2, 0.4, 0.1)))


def test_a_cylinder_stood_up_about_x_has_its_axis_moment_on_y():
    """The wheel case: rpy 1.5708 0 0 turns the cylinder's z axis onto the link's y."""
    rotated = mp.tidy(mp.rotate(mp.cylinder(0.5, 0.05, 0.02), mp.rotation((1.5708, 0, 0))))
    side, axis = 0.5 * (3 * 0.0025 + 0.0004) / 12, 0.5 * 0.0025 / 2
    close(rotated, mp.diagonal(side, axis, side), rel=1e-6)


@settings(max_examples=100, deadline=None)
@given(positive, positive, positive, angles, angles, angles)
def test_rotation_keeps_principal_moments(x, y, z, roll, pitch, yaw):
    tensor = mp.box(1.0, (x, y, z))
    rotated = mp.rotate(tensor, mp.rotation((roll, pitch, yaw)))
    close(mp.principal_moments(rotated), mp.principal_moments(tensor), rel=1e-6, abs_=1e-9)
    assert mp.moments_difference(rotated, tensor) < 1e-6


def test_parallel_axis_adds_m_r2_minus_r_rt():
    offset = (1.0, 2.0, 3.0)
    moved = mp.parallel_axis(mp.ZERO, 2.0, offset)
    r = numpy.array(offset)
    close(moved, 2.0 * (r @ r * numpy.eye(3) - numpy.outer(r, r)))


def test_two_half_boxes_compose_into_the_whole_box():
    half = mp.box(1.0, (0.5, 1.0, 2.0))
    mass, com, tensor = mp.combine([(1.0, (-0.25, 0.0, 0.0), half), (1.0, (0.25, 0.0, 0.0), half)])
    assert mass == 2.0
    close(com, (0, 0, 0))
    close(tensor, mp.box(2.0, (1.0, 1.0, 2.0)))


def test_combine_rotated_and_offset_parts_against_numpy():
    """Eight randomly placed and turned boxes, composed by hand with numpy."""
    rng = numpy.random.default_rng(7)
    parts, reference = [], []
    for _ in range(8):
        mass, size, rpy, centre = rng.uniform(0.1, 3), rng.uniform(0.05, 1, 3), rng.uniform(-3, 3, 3), rng.uniform(-1, 1, 3)
        rotation = numpy.array(mp.rotation(tuple(rpy)))
        tensor = rotation @ numpy.array(mp.box(mass, tuple(size))) @ rotation.T
        parts.append((mass, tuple(centre), tuple(map(tuple, tensor))))
        reference.append((mass, centre, tensor))
    total = sum(m for m, _, _ in reference)
    com = sum(m * c for m, c, _ in reference) / total
    expected = sum(t + m * ((c - com) @ (c - com) * numpy.eye(3) - numpy.outer(c - com, c - com)) for m, c, t in reference)
    mass, centre, tensor = mp.combine(parts)
    assert mass == pytest.approx(total)
    close(centre, com)
    close(tensor, expected)


def test_combine_of_nothing_is_zero():
    assert mp.combine([]) == (0.0, (0.0, 0.0, 0.0), mp.ZERO)


def test_compose_and_place_follow_a_chain_of_origins():
    shoulder = mp.transform((0, 0, 1), (0, 0, math.pi / 2))
    elbow = mp.transform((1, 0, 0), (0, 0, 0))
    pose = mp.compose(shoulder, elbow)
    close(pose[1], (0, 1, 1), abs_=1e-12)
    close(mp.place(pose, (1, 0, 0)), (0, 2, 1), abs_=1e-12)


def test_validity_tests():
    invalid = mp.matrix({"ixx": 1, "ixy": 0, "ixz": 0, "iyy": 0, "iyz": 1, "izz": 1})  # seed 002's helloworld
    assert not mp.is_positive_semidefinite(invalid)
    close(mp.principal_moments(invalid), ((1 - math.sqrt(5)) / 2, 1, (1 + math.sqrt(5)) / 2))
    assert mp.triangle_violation(mp.diagonal(0.00026, 0.00026, 0.00063))  # seed 000's wheel
    assert mp.triangle_violation(mp.diagonal(0.001, 0.001, 0.01))  # PR2 sensor_mount_link
    assert mp.triangle_violation(mp.box(1.0, (0.3, 0.2, 0.1))) is None
    assert mp.is_identity(mp.diagonal(1, 1, 1)) and not mp.is_identity(mp.diagonal(1, 1, 1.5))
    assert mp.is_zero(mp.ZERO)


def test_relative_difference_catches_swapped_axes_and_passes_rounding():
    true = mp.box(0.01, (0.02, 0.05, 0.05))
    swapped = mp.diagonal(true[2][2], true[1][1], true[0][0])
    rounded = mp.diagonal(*(float(f"{true[i][i]:.2g}") for i in range(3)))
    assert mp.relative_difference(swapped, true) > 0.4
    assert mp.relative_difference(rounded, true) < 0.05
    assert mp.moments_difference(swapped, true) == pytest.approx(0.0)


def test_tidy_removes_rounding_noise_only():
    noisy = mp.rotate(mp.cylinder(0.5, 0.05, 0.02), mp.rotation((1.5708, 0, 0)))
    assert noisy[1][2] != 0 and mp.tidy(noisy)[1][2] == 0
    assert mp.tidy(mp.diagonal(1.0, 1e-3, 1e-4)) == mp.diagonal(1.0, 1e-3, 1e-4)


@settings(max_examples=300, deadline=None)
@given(
    st.tuples(angles, angles, angles),
    st.tuples(*[st.floats(1e-6, 1e3) for _ in range(3)]),
)
def test_principal_axes_are_numpys_where_a_moment_stands_apart(rpy, moments):
    """The closed-form axis of a simple principal moment is numpy's eigenvector, up to sign."""
    tensor = mp.rotate(mp.diagonal(*moments), mp.rotation(rpy))
    values, vectors = numpy.linalg.eigh(numpy.array(tensor))
    largest = max(abs(v) for v in values)
    for i in range(3):
        if all(abs(values[i] - values[j]) >= 0.15 * largest for j in range(3) if j != i):
            axis = mp.principal_axis(tensor, mp.principal_moments(tensor)[i])
            assert axis is not None
            assert abs(abs(float(numpy.dot(axis, vectors[:, i]))) - 1.0) < 1e-6
