"""Homogeneous 4×4 transforms in the paper's row-vector convention (§2.2, §2.2.1).

``rotation_about_axis`` is checked against an independent construction
(``scipy.spatial.transform.Rotation``, column-vector convention, transposed
into the row layout), and the layout, pivot, translation and composition order
against their definitions. Lengths are mm, angles degrees.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from engine.deform.transforms import IDENTITY, apply, is_identity, rotation_about_axis, translation
from engine.model.parameters import Parameter

RNG_SEEDS = range(20)


def independent_rotation(axis, pivot, degrees) -> np.ndarray:
    """Row-convention 4×4 from scipy: ``[p, 1] · T = (p − c) Rᵀ + c``."""
    axis = np.asarray(axis, float)
    R = Rotation.from_rotvec(np.deg2rad(degrees) * axis / np.linalg.norm(axis)).as_matrix()
    c = np.asarray(pivot, float)
    T = np.eye(4)
    T[:3, :3] = R.T
    T[3, :3] = c - c @ R.T
    return T


@pytest.mark.parametrize("seed", RNG_SEEDS)
def test_rotation_matches_scipy(seed):
    rng = np.random.default_rng(seed)
    axis, pivot = rng.normal(size=3) * rng.uniform(0.1, 10), rng.uniform(-100, 100, 3)
    degrees = rng.uniform(-360, 360)
    T = rotation_about_axis(axis, pivot, degrees)
    np.testing.assert_allclose(T, independent_rotation(axis, pivot, degrees), rtol=0, atol=1e-12)
    points = rng.uniform(-100, 100, (10, 3))
    R = Rotation.from_rotvec(np.deg2rad(degrees) * axis / np.linalg.norm(axis))
    np.testing.assert_allclose(apply(T, points), R.apply(points - pivot) + pivot, rtol=0, atol=1e-10)


@pytest.mark.parametrize("seed", RNG_SEEDS)
def test_rotation_is_proper_and_keeps_pivot_and_axis_fixed(seed):
    rng = np.random.default_rng(seed)
    axis, pivot = rng.normal(size=3), rng.uniform(-100, 100, 3)
    T = rotation_about_axis(axis, pivot, rng.uniform(-180, 180))
    A = T[:3, :3]
    np.testing.assert_allclose(A @ A.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(A) == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_array_equal(T[:, 3], [0, 0, 0, 1])
    u = axis / np.linalg.norm(axis)
    on_axis = pivot + np.outer([-30.0, 0.0, 12.5], u)
    np.testing.assert_allclose(apply(T, on_axis), on_axis, rtol=0, atol=1e-10)
    points = rng.uniform(-100, 100, (20, 3))
    moved = apply(T, points)
    np.testing.assert_allclose(np.linalg.norm(moved - pivot, axis=1), np.linalg.norm(points - pivot, axis=1),
                               rtol=0, atol=1e-10)


def test_rotation_follows_the_right_hand_rule():
    """Positive degrees turn counter-clockwise seen from the tip of the axis: x → y about +z."""
    np.testing.assert_allclose(apply(rotation_about_axis([0, 0, 1], [0, 0, 0], 90), [[1.0, 0, 0]]),
                               [[0, 1.0, 0]], atol=1e-15)
    np.testing.assert_allclose(apply(rotation_about_axis([1, 0, 0], [0, 0, 0], 90), [[0, 1.0, 0]]),
                               [[0, 0, 1.0]], atol=1e-15)
    np.testing.assert_allclose(apply(rotation_about_axis([0, 1, 0], [0, 0, 0], 90), [[0, 0, 1.0]]),
                               [[1.0, 0, 0]], atol=1e-15)
    # the module's own doctest: about +z through (1, 0, 0)
    np.testing.assert_allclose(apply(rotation_about_axis([0, 0, 1], [1, 0, 0], 90), [[2.0, 0, 0]]),
                               [[1.0, 1.0, 0]], atol=1e-15)


def test_rotation_angle_zero_and_full_turn():
    np.testing.assert_allclose(rotation_about_axis([1, 2, 3], [4, 5, 6], 0), np.eye(4), atol=1e-15)
    np.testing.assert_allclose(rotation_about_axis([1, 2, 3], [4, 5, 6], 360), np.eye(4), atol=1e-12)
    np.testing.assert_allclose(rotation_about_axis([1, 2, 3], [4, 5, 6], -30),
                               np.linalg.inv(rotation_about_axis([1, 2, 3], [4, 5, 6], 30)), atol=1e-12)


def test_matrix_layout_is_row_vector():
    """Linear part transposed in the upper-left block, translation in the last row (§2.2:
    ``P * T`` with ``P = [x, y, z, 1]``)."""
    T = translation([1.0, -2.0, 3.5])
    np.testing.assert_array_equal(T[3], [1.0, -2.0, 3.5, 1.0])
    np.testing.assert_array_equal(T[:3, :3], np.eye(3))
    np.testing.assert_array_equal(T[:3, 3], [0, 0, 0])
    p = np.array([10.0, 20.0, 30.0])
    np.testing.assert_array_equal(np.append(p, 1.0) @ T, [11.0, 18.0, 33.5, 1.0])
    np.testing.assert_array_equal(apply(T, [p]), [[11.0, 18.0, 33.5]])
    R = rotation_about_axis([0, 0, 1], [0, 0, 0], 90)
    np.testing.assert_allclose(np.array([1.0, 0, 0, 1]) @ R, [0, 1.0, 0, 1], atol=1e-15)
    np.testing.assert_allclose(R[:3, :3], Rotation.from_euler("z", 90, degrees=True).as_matrix().T, atol=1e-15)


def test_translation_moves_every_point_by_the_displacement():
    rng = np.random.default_rng(3)
    d = rng.uniform(-10, 10, 3)
    points = rng.uniform(-100, 100, (7, 3))
    np.testing.assert_allclose(apply(translation(d), points), points + d, rtol=0, atol=1e-12)


def test_composition_applies_left_factor_first():
    """``T_c · T_p`` applies ``T_c`` first, then ``T_p`` — the order of the paper's
    propagation ``T'_c = T_c · T_p`` (§2.2)."""
    rng = np.random.default_rng(4)
    A = rotation_about_axis([0, 0, 1], [5, 0, 0], 90)
    B = translation([0, 0, 10]) @ rotation_about_axis([1, 0, 0], [0, 3, 0], 45)
    points = rng.uniform(-50, 50, (5, 3))
    np.testing.assert_allclose(apply(A @ B, points), apply(B, apply(A, points)), rtol=0, atol=1e-12)
    assert not np.allclose(apply(A @ B, points), apply(B @ A, points))
    # a concrete case: turn x → y about the origin, then shift +x
    T = rotation_about_axis([0, 0, 1], [0, 0, 0], 90) @ translation([1, 0, 0])
    np.testing.assert_allclose(apply(T, [[1.0, 0, 0]]), [[1.0, 1.0, 0]], atol=1e-15)


def test_apply_accepts_lists_and_keeps_shape():
    out = apply(np.eye(4), [[1, 2, 3], [4, 5, 6]])
    assert out.shape == (2, 3) and out.dtype == float
    assert apply(np.eye(4), np.zeros((0, 3))).shape == (0, 3)


def test_identity_is_exact_and_read_only():
    assert is_identity(np.eye(4))
    assert is_identity(rotation_about_axis([0, 1, 0], [1, 2, 3], 0))
    assert not is_identity(translation([0, 0, 1e-300]))
    assert not is_identity(rotation_about_axis([0, 1, 0], [0, 0, 0], 1e-9))
    with pytest.raises(ValueError, match="read-only"):
        IDENTITY[0, 0] = 2.0


@pytest.mark.parametrize("seed", range(5))
def test_parameter_transform_scales_value(seed):
    """A rotation turns ``value × degrees_per_unit`` degrees about its axis through its pivot;
    a translation moves ``value × direction`` mm; a field translation's matrix is the
    identity (its motion is per vertex); value 0 is the identity exactly."""
    rng = np.random.default_rng(seed)
    axis, pivot, dpu = rng.normal(size=3), rng.uniform(-50, 50, 3), rng.uniform(1, 60)
    rot = Parameter("r", "rotation", axis=axis, pivot=pivot, degrees_per_unit=dpu)
    v = rng.uniform(-2, 2)
    np.testing.assert_allclose(rot.transform(v), independent_rotation(axis, pivot, v * dpu), rtol=0, atol=1e-12)
    direction = rng.uniform(-10, 10, 3)
    tr = Parameter("t", "translation", direction=direction)
    np.testing.assert_allclose(tr.transform(v), translation(v * direction), rtol=0, atol=1e-15)
    field = Parameter("f", "translation", field=True)
    assert is_identity(field.transform(v))
    for p in (rot, tr, field):
        assert is_identity(p.transform(0.0))
