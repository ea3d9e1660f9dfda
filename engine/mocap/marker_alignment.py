"""Markers onto the model: the similarity transform from marker coordinates to model coordinates (§3.1.2).

:func:`similarity_fit` is Umeyama's least-squares similarity (scale,
rotation, translation) between corresponding points; :func:`align_to_landmarks`
also finds the component values at which the markers look most like the
model at rest. Lengths are mm.
"""

from __future__ import annotations

import numpy as np

from engine.mocap.errors import MocapError


def align_to_landmarks(mean: np.ndarray, comps: np.ndarray, target: np.ndarray, rest_offset: bool,
                       ridge: float = 1e-6) -> tuple[float, np.ndarray, np.ndarray, np.ndarray, float]:
    """Similarity transform marker → model, and the component values of the model's rest pose.

    ``mean`` (K, 3) and ``comps`` (C, K, 3) are the PCA model at the K
    markers, ``target`` (K, 3) the model's rest landmarks, all mm. Returns
    ``(scale, rotation, translation, rest_values, rms_mm)``.

    Starts from the Procrustes fit of the mean shape, then (``rest_offset``)
    minimises ``Σ |s R (mean + Σ v_k C_k) + t − L|² + ridge · |B|² |v|²``
    over scale, rotation, translation and ``v`` jointly (Levenberg–Marquardt);
    the tiny ridge only matters where a component could imitate a similarity.
    """
    from scipy.optimize import least_squares
    from scipy.spatial.transform import Rotation

    c = comps.shape[0]
    scale, rotation, translation = similarity_fit(mean, target)
    values = np.zeros(c)
    if rest_offset:
        flat = comps.reshape(c, -1)
        weight = np.sqrt(ridge * np.sum(flat ** 2) / c)

        def residuals(p: np.ndarray) -> np.ndarray:
            rot = Rotation.from_rotvec(p[:3]).as_matrix()
            shape = mean + np.tensordot(p[7:], comps, axes=1)
            fit = np.exp(p[3]) * shape @ rot.T + p[4:7] - target
            return np.concatenate([fit.reshape(-1), weight * p[7:]])

        start = np.concatenate([Rotation.from_matrix(rotation).as_rotvec(), [np.log(scale)], translation, values])
        solution = least_squares(residuals, start, method="lm", xtol=1e-12, ftol=1e-12, gtol=1e-12)
        values = solution.x[7:]
        scale, rotation, translation = similarity_fit(mean + np.tensordot(values, comps, axes=1), target)
    shape = mean + np.tensordot(values, comps, axes=1)
    rms = float(np.sqrt(np.mean(np.sum((scale * shape @ rotation.T + translation - target) ** 2, axis=1))))
    return scale, rotation, translation, values, rms


def similarity_fit(source: np.ndarray, target: np.ndarray,
                   scale: bool = True) -> tuple[float, np.ndarray, np.ndarray]:
    """Scale s, rotation R, translation t minimising Σ |s R x + t − y|² (Umeyama 1991); s = 1 if not ``scale``.

    ``source`` and ``target`` are (K, 3) corresponding points (column-vector
    convention: y ≈ s R x + t). Used to place markers on the model's landmarks.

    >>> x = np.array([[0., 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    >>> s, R, t = similarity_fit(x, 2 * x + [5, 0, 0])
    >>> round(s, 9), np.allclose(R, np.eye(3)), t.round(9).tolist()
    (2.0, True, [5.0, 0.0, 0.0])
    """
    mx, my = source.mean(axis=0), target.mean(axis=0)
    x, y = source - mx, target - my
    u, d, vt = np.linalg.svd(y.T @ x / len(x))
    s = np.ones(3)
    if np.linalg.det(u) * np.linalg.det(vt) < 0:
        s[2] = -1.0
    rotation = u @ np.diag(s) @ vt
    var = np.sum(x ** 2) / len(x)
    if var <= 0:
        raise MocapError("the markers all sit at one point: cannot align them to the model")
    factor = float(np.sum(d * s) / var) if scale else 1.0
    return factor, rotation, my - factor * rotation @ mx
