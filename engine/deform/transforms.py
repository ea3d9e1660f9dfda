"""Homogeneous 4×4 transforms in the paper's row-vector convention (§2.2).

The paper writes a transformed point as ``P * T`` with ``P`` a row vector
``[x, y, z, 1]``; we keep that convention so the equations read the same in
code and paper. A matrix therefore holds its linear part *transposed* in the
upper-left 3×3 block and its translation in the last row::

    T = | A  0 |      [p, 1] · T = [p · A + b, 1]
        | b  1 |

and ``T_c · T_p`` applies ``T_c`` first, then ``T_p`` (the paper's
propagation ``T'_c = T_c · T_p``). Lengths are millimetres, angles degrees.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

IDENTITY = np.eye(4)
IDENTITY.setflags(write=False)


def rotation_about_axis(axis: npt.ArrayLike, pivot: npt.ArrayLike, degrees: float) -> np.ndarray:
    """Rotation by ``degrees`` about the line through ``pivot`` along ``axis``.

    Positive angles turn counter-clockwise when looking from the tip of
    ``axis`` towards the pivot (right-hand rule).

    >>> T = rotation_about_axis([0, 0, 1], [1, 0, 0], 90)
    >>> np.round(apply(T, [[2.0, 0.0, 0.0]]), 12)
    array([[1., 1., 0.]])
    """
    u = np.asarray(axis, dtype=float)
    u = u / np.linalg.norm(u)
    c = np.asarray(pivot, dtype=float)
    theta = np.deg2rad(degrees)
    cos, sin = np.cos(theta), np.sin(theta)
    x, y, z = u
    # Rodrigues' formula for column vectors, R p.
    R = np.array([
        [cos + x * x * (1 - cos), x * y * (1 - cos) - z * sin, x * z * (1 - cos) + y * sin],
        [y * x * (1 - cos) + z * sin, cos + y * y * (1 - cos), y * z * (1 - cos) - x * sin],
        [z * x * (1 - cos) - y * sin, z * y * (1 - cos) + x * sin, cos + z * z * (1 - cos)],
    ])
    T = np.eye(4)
    T[:3, :3] = R.T
    T[3, :3] = c - c @ R.T
    return T


def translation(displacement: npt.ArrayLike) -> np.ndarray:
    """Translation by ``displacement`` (mm) as a row-convention 4×4 matrix."""
    T = np.eye(4)
    T[3, :3] = np.asarray(displacement, dtype=float)
    return T


def apply(T: np.ndarray, points: npt.ArrayLike) -> np.ndarray:
    """Transform an (N, 3) array of points: ``[p, 1] · T`` for every row."""
    P = np.asarray(points, dtype=float)
    return P @ T[:3, :3] + T[3, :3]


def is_identity(T: np.ndarray) -> bool:
    """True when ``T`` is exactly the identity (no tolerance)."""
    # the diagonal test rejects almost every moving matrix before the full comparison (per-frame path)
    return T[0, 0] == 1.0 and T[1, 1] == 1.0 and T[2, 2] == 1.0 and bool(np.array_equal(T, IDENTITY))
