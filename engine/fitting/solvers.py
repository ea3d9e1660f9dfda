"""The solvers of the fit (on the region's vertices only): the motion and the per-vertex weights (§2.2.2).

Weights lie in [0, 1] and minimise ``Σ_i |D_i − w_i R_i|² + μ Σ_edges (w_a − w_b)²``
for the motion ``R`` of the fitted transform; ``docs/fitting.md`` gives the
method. Lengths are mm, angles radians.

The gauge. Scaling the weights down while turning further (or moving the
pivot far away) changes a rotation's fit little, and left free the search
drifts to large angles with small weights: a jaw that turns 31° at weight
0.7 instead of 22° at weight 1, which shrinks the rigid teeth. So the
vertices that move at least ``core`` times as far as the farthest-moving one
are held at weight 1: the motion is that of the part that moves fully.

>>> import numpy as np
>>> np.round(_rotation_matrix([0.0, 0.0, np.pi / 2]), 6).tolist()
[[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

import numpy as np
import numpy.typing as npt
from scipy import sparse
from scipy.optimize import least_squares
from scipy.sparse.linalg import spsolve


class Motion(Protocol):
    """``motion(x, rows)``: the (n, 3) displacement at weight 1 of the vertices ``rows`` (default all), mm."""

    def __call__(self, x: np.ndarray, rows: slice | np.ndarray = ..., /) -> np.ndarray: ...


def fit_motion(motion: Motion, x0: np.ndarray, D: np.ndarray, B: sparse.csr_matrix, mu: float, pin: np.ndarray,
               max_iterations: int) -> tuple[np.ndarray, np.ndarray, int]:
    """Fit the parameters ``x`` of ``motion(x)`` (n, 3: each vertex's displacement at weight 1) and the weights.

    First the motion alone, each vertex taking its best weight in closed
    form (variable projection, no smoothness); then, when ``mu > 0``,
    alternate smooth weights and motion. Every step is an exact least-squares
    solve for its own unknowns, so the objective never rises. Returns ``x``,
    the weights and the number of alternation rounds.
    """
    lm = dict(method="lm", xtol=1e-10, ftol=1e-10, gtol=1e-10, max_nfev=1000)

    def residual(x: np.ndarray) -> np.ndarray:
        R = motion(x)
        return (D - _best_weights(R, D, pin)[:, None] * R).ravel()

    x = least_squares(residual, x0, **lm).x
    if mu == 0 or B.shape[0] == 0:
        return x, _best_weights(motion(x), D, pin), 0
    cost_before, rounds = np.inf, 0
    while rounds < max_iterations:
        rounds += 1
        w = _weight_step(motion(x), D, B, mu, pin)
        use = np.flatnonzero(w > 0)
        if 3 * len(use) < len(x):               # too few weighted vertices to move the transform
            break
        x = least_squares(lambda x, use=use, w=w: (D[use] - w[use, None] * motion(x, use)).ravel(), x, **lm).x
        cost = _cost(D, w[:, None] * motion(x), w, B, mu)
        if cost_before - cost <= 1e-4 * cost:       # the rounds gain < 1 % in all (docs/fitting.md)
            break
        cost_before = cost
    return x, _weight_step(motion(x), D, B, mu, pin), rounds


def initial_rotation(P: np.ndarray, D: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Kabsch on the vertices moving at least half the most, taken as rigid with weight 1."""
    mag = np.linalg.norm(D, axis=1)
    strong = np.flatnonzero(mag >= 0.5 * mag.max())
    if len(strong) < 3:
        strong = np.argsort(mag)[-3:]
    a, b = P[strong], P[strong] + D[strong]
    ca, cb = a.mean(axis=0), b.mean(axis=0)
    U, _, Vt = np.linalg.svd((a - ca).T @ (b - cb))
    d = np.sign(np.linalg.det(Vt.T @ U.T)) or 1.0
    R = Vt.T @ np.diag([1.0, 1.0, d]) @ U.T                 # b − cb ≈ R (a − ca), column convention
    omega = _rotation_vector(R)
    if np.linalg.norm(omega) < 1e-4:
        # (almost) a pure translation: a rotation of large radius about an axis across the motion
        move = (b - a).mean(axis=0)
        axis = np.cross(move, np.eye(3)[np.argmin(np.abs(move))])
        axis /= np.linalg.norm(axis)
        radius = 1000.0 * max(1.0, float(np.ptp(P, axis=0).max()))
        pivot = ca + radius * np.cross(axis, move / np.linalg.norm(move))     # so ca starts off along move
        return axis * (np.linalg.norm(move) / radius), pivot
    A = R.T                                                  # row convention: b ≈ a · A + t
    pivot = np.linalg.lstsq((np.eye(3) - A).T, cb - ca @ A, rcond=1e-8)[0]   # pivot·(I − A) = t, bar the slide
    return omega, pivot


def initial_direction(D: np.ndarray) -> np.ndarray:
    """The direction u maximising Σ max(0, D_i · u)², scaled to the largest projection.

    The top principal axis of the vertices moving along it, by a fixed-point
    iteration that never lowers the sum; without a core and smoothness this
    is already the least-squares translation (vertices moving against it get
    weight 0, the one moving most along it weight 1).
    """
    u = np.linalg.svd(D, full_matrices=False)[2][0]
    u = -u if (D @ u).sum() < 0 else u
    for _ in range(100):
        along = D[D @ u > 0]
        new = np.linalg.svd(along, full_matrices=False)[2][0]
        new = -new if (along @ new).sum() < 0 else new
        if np.allclose(new, u, rtol=0, atol=1e-15):
            break
        u = new
    return u * (D @ u).max()


def rotation_motion(P: np.ndarray, omega: np.ndarray, pivot: np.ndarray,
                    ) -> tuple[np.ndarray, Motion, Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]]:
    """Five unknowns around a rotation: ``ω`` (radians) and the pivot's shift across the axis.

    Sliding the pivot along the axis changes nothing, so it moves only in the
    plane across the starting axis, in units of the region's size (so the
    unknowns have comparable scales). Returns ``x0``, ``motion(x)`` and
    ``unpack(x) → (ω, pivot)``.
    """
    u = omega / np.linalg.norm(omega)
    e1 = np.cross(u, np.eye(3)[np.argmin(np.abs(u))])
    e1 /= np.linalg.norm(e1)
    size = float(np.sqrt(((P - P.mean(axis=0)) ** 2).sum(axis=1).mean())) or 1.0
    across = np.stack([e1, np.cross(u, e1)]) * size

    def unpack(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return x[:3], pivot + x[3:] @ across

    def motion(x: np.ndarray, rows: slice | np.ndarray = slice(None)) -> np.ndarray:
        return _chords(P[rows], *unpack(x))

    return np.concatenate([omega, [0.0, 0.0]]), motion, unpack


def _best_weights(R: np.ndarray, D: np.ndarray, pin: np.ndarray) -> np.ndarray:
    """Each vertex's best weight in [0, 1] for the motion ``R`` (closed form), 1 where ``pin``."""
    h = np.einsum("ij,ij->i", R, R)
    g = np.einsum("ij,ij->i", R, D)
    w = np.clip(np.divide(g, h, out=np.zeros_like(g), where=h > 0), 0.0, 1.0)
    w[pin] = 1.0
    return w


def _weight_step(R: np.ndarray, D: np.ndarray, B: sparse.csr_matrix, mu: float, pin: np.ndarray) -> np.ndarray:
    """Weights in [0, 1], 1 where ``pin``, minimising Σ |D_i − w_i R_i|² + μ |B w|² (a sparse box QP)."""
    h = np.einsum("ij,ij->i", R, R)
    g = np.einsum("ij,ij->i", R, D)
    ridge = 1e-12 * max(float(h.max()), mu)                # keeps still vertices determined (they go to 0)
    H = (sparse.diags(h + ridge) + mu * (B.T @ B)).tocsr()
    return _box_qp(H, g, pin)


def _box_qp(H: sparse.csr_matrix, g: np.ndarray, pin: np.ndarray, max_iterations: int = 100) -> np.ndarray:
    """argmin ½ wᵀHw − gᵀw over 0 ≤ w ≤ 1 with w = 1 where ``pin``: primal-dual active set.

    H = diagonal + μ·Laplacian is an M-matrix, for which the method ends in
    finitely many steps (Hintermüller, Ito & Kunisch 2003), each one sparse
    solve; typically 2–6 here.
    """
    c = H.diagonal()
    w = np.clip(g / c, 0.0, 1.0)
    w[pin] = 1.0
    lam = g - H @ w
    lower = upper = None
    for _ in range(max_iterations):
        # ties (a still vertex at 0 with nothing pulling it up) go to the bounds: smaller solves
        new_lower, new_upper = (lam + c * w < 0) & ~pin, (lam + c * (w - 1.0) > 0) | pin
        if (lower is not None and upper is not None
                and np.array_equal(new_lower, lower) and np.array_equal(new_upper, upper)):
            break
        lower, upper = new_lower, new_upper
        free = ~(lower | upper)
        w = upper.astype(float)
        if free.any():
            rhs = g[free] - H[free][:, upper] @ np.ones(int(upper.sum()))
            w[free] = spsolve(H[free][:, free].tocsc(), rhs) if free.sum() > 1 else rhs / c[free]
        lam = g - H @ w
        lam[free] = 0.0
    return np.clip(w, 0.0, 1.0)


def _cost(D: np.ndarray, fitted: np.ndarray, w: np.ndarray, B: sparse.csr_matrix, mu: float) -> float:
    return float(np.sum((D - fitted) ** 2) + mu * np.sum((B @ w) ** 2))


def _chords(P: np.ndarray, omega: np.ndarray, pivot: np.ndarray) -> np.ndarray:
    """``P · T − P`` for the rotation by the vector ``ω`` (radians) about an axis through ``pivot``."""
    return (P - pivot) @ (_rotation_matrix(omega).T - np.eye(3))


def _rotation_matrix(omega: npt.ArrayLike) -> np.ndarray:
    """Rodrigues: the rotation by |ω| radians about ω (column convention)."""
    theta = float(np.linalg.norm(omega))
    if theta == 0.0:
        return np.eye(3)
    x, y, z = np.asarray(omega) / theta
    K = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    return np.eye(3) + np.sin(theta) * K + (1.0 - np.cos(theta)) * (K @ K)


def _rotation_vector(R: np.ndarray) -> np.ndarray:
    """The rotation vector (axis × angle, radians) of a rotation matrix, also near 180°."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_matrix(R).as_rotvec()
