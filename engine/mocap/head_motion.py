"""Removing head motion: per-frame rigid alignment of the head-fixed markers (§3.1.1).

Every frame is moved by the rotation and translation (no scaling) that best
maps its reference markers onto the same markers in a reference frame, in
the least-squares sense (Kabsch's SVD solution, with the reflection
excluded). Transforms follow :mod:`engine.deform.transforms`: 4×4 matrices for row
vectors, ``[p, 1] · A = [p', 1]``. A frame uses whichever reference markers
it has (at least three, not on one line); a frame with fewer gets a NaN
alignment and all its markers count as missing.

>>> import numpy as np
>>> from engine.deform.transforms import rotation_about_axis, translation, apply
>>> ref = np.array([[0., 0, 0], [50, 0, 0], [0, 60, 0], [0, 0, 40]])
>>> T = rotation_about_axis([1, 2, 3], [10, 0, 0], 25) @ translation([5, -3, 8])
>>> A = kabsch(apply(T, ref)[None], ref, np.ones((1, 4), bool))[0]
>>> np.allclose(apply(A, apply(T, ref)), ref)
True
"""

from __future__ import annotations

from types import ModuleType
from typing import Any

import numpy as np

from engine.mocap.errors import MocapError

_rigid_fit: ModuleType | None
try:  # the compiled batched Kabsch (engine/mocap/_rigid_fit.c); numpy's batched SVD otherwise
    from engine.mocap import _rigid_fit
except ImportError:  # pragma: no cover - exercised where the extension is not built
    _rigid_fit = None

MIN_REFERENCE = 3
_COLLINEAR = 1e-9  # second singular value of the cross-covariance relative to the first


def kabsch(points: np.ndarray, target: np.ndarray, present: np.ndarray) -> np.ndarray:
    """Per-frame rigid transforms taking ``points`` onto ``target``.

    ``points`` (F, K, 3) are the reference markers in each frame, ``target``
    (K, 3) or (F, K, 3) where they should go, ``present`` (F, K) which are
    usable in each frame. Returns (F, 4, 4) row-vector transforms; NaN where
    a frame has fewer than three usable markers or they lie on a line. Units
    are whatever the points are in (mm).
    """
    points = np.asarray(points, dtype=float)
    n_frames = points.shape[0]
    target = np.broadcast_to(np.asarray(target, dtype=float), points.shape)
    w = (np.asarray(present, bool) & np.isfinite(points).all(axis=2) & np.isfinite(target).all(axis=2))
    count = w.sum(axis=1)
    safe = np.maximum(count, 1)[:, None]
    unusable = ~w
    p = points.copy()
    p[unusable] = 0.0
    q = np.array(target)
    q[unusable] = 0.0
    p_mean = p.sum(axis=1) / safe
    q_mean = q.sum(axis=1) / safe
    # Σ_k (p_k − p̄)ᵀ(q_k − q̄) = Σ_k (p_k − p̄)ᵀ q_k, as Σ_k (p_k − p̄) = 0 over the usable markers
    pc = p - p_mean[:, None]
    pc[unusable] = 0.0
    H = np.ascontiguousarray(pc.transpose(0, 2, 1) @ q)
    R, S = _rotations(H)  # row-vector rotation: p @ R
    t = q_mean - np.einsum("fi,fij->fj", p_mean, R)
    A = np.zeros((n_frames, 4, 4))
    A[:, :3, :3] = R
    A[:, 3, :3] = t
    A[:, 3, 3] = 1.0
    # points on a line leave the rotation about that line undetermined: H then has rank one
    bad = (count < MIN_REFERENCE) | (S[:, 1] <= _COLLINEAR * np.maximum(S[:, 0], 1e-300))
    A[bad] = np.nan
    return A


def _rotations(H: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Kabsch rotations R = U diag(1, 1, d) Vᵀ (d = sign det UVᵀ) and singular values of (F, 3, 3) H.

    The compiled ``engine.mocap._rigid_fit`` (one-sided Jacobi SVD) when it is built,
    numpy's batched SVD otherwise; both agree to rounding.
    """
    if _rigid_fit is not None:
        R = np.empty_like(H)
        S = np.empty(H.shape[:2])
        _rigid_fit.rotations(H, R, S)
        return R, S
    U, S, Vt = np.linalg.svd(H)
    d = np.sign(np.linalg.det(U @ Vt))
    d[d == 0] = 1.0
    U[:, :, 2] *= d[:, None]
    return U @ Vt, S


def apply_alignment(positions: np.ndarray, alignment: np.ndarray) -> np.ndarray:
    """Move (F, M, 3) positions by per-frame (F, 4, 4) row-vector transforms."""
    positions = np.ascontiguousarray(positions, dtype=float)
    alignment = np.ascontiguousarray(alignment, dtype=float)
    if _rigid_fit is not None and positions.ndim == 3 and alignment.shape == (len(positions), 4, 4):
        out = np.empty_like(positions)
        _rigid_fit.move(positions, alignment, out)
        return out
    return positions @ alignment[:, :3, :3] + alignment[:, None, 3, :3]


def remove_head_motion(positions: np.ndarray, missing: np.ndarray, reference: list[int],
                       reference_frame: str | int = "first", filled: np.ndarray | None = None,
                       ) -> tuple[np.ndarray, np.ndarray, dict[str, Any]]:
    """Align every frame's reference markers to a reference frame; returns ``(aligned, alignment, info)``.

    ``positions`` (F, M, 3) mm with NaN where ``missing`` (F, M); ``reference``
    the column indices of the head-fixed markers. ``filled`` (F, M) marks
    gap-filled samples: a frame aligns on its measured reference markers when
    it has three, and takes filled ones only when it must (a spline estimate
    would otherwise tilt an exact alignment). ``reference_frame`` is
    ``"first"`` (the first frame with every reference marker present), a frame
    index, or ``"mean"`` (the mean reference shape after aligning to the
    first, then every frame aligned to that mean: two rounds of generalised
    Procrustes). ``info`` holds the frame used, the number of unaligned
    frames and the per-frame RMS residual of the reference markers (mm).
    """
    positions = np.asarray(positions, dtype=float)
    n_frames = positions.shape[0]
    reference = list(reference)
    if len(reference) < MIN_REFERENCE:
        raise MocapError(f"removing head motion needs at least {MIN_REFERENCE} head-fixed reference markers, "
                         f"not {len(reference)}")
    ref_points = positions[:, reference]
    present = ~np.asarray(missing, bool)[:, reference]
    if filled is not None:
        measured = present & ~np.asarray(filled, bool)[:, reference]
        enough = measured.sum(axis=1) >= MIN_REFERENCE
        present = np.where(enough[:, None], measured, present)
    complete = np.flatnonzero(present.all(axis=1))
    if isinstance(reference_frame, (int, np.integer)) and not isinstance(reference_frame, bool):
        frame = int(reference_frame)
        if not 0 <= frame < n_frames:
            raise MocapError(f"reference frame {frame} is outside the recording (0 … {n_frames - 1})")
        if not present[frame].all():
            raise MocapError(f"frame {frame} lacks reference markers; pick a frame where all are present")
    elif reference_frame in ("first", "mean"):
        if len(complete) == 0:
            raise MocapError("no frame has all the reference markers: choose others (--reference) or "
                             "a larger --max-gap")
        frame = int(complete[0])
    else:
        raise MocapError(f"unknown reference frame '{reference_frame}' (use first, mean or a frame number)")
    target = ref_points[frame]
    alignment = kabsch(ref_points, target, present)
    if reference_frame == "mean":
        for _ in range(2):
            moved = apply_alignment(ref_points, alignment)
            ok = present & np.all(np.isfinite(moved), axis=2)
            counts = ok.sum(axis=0)
            if np.any(counts == 0):
                break
            target = np.where(ok[..., None], moved, 0.0).sum(axis=0) / counts[:, None]
            alignment = kabsch(ref_points, target, present)
    aligned = apply_alignment(positions, alignment)
    moved = apply_alignment(ref_points, alignment)
    sq = np.where(present[..., None], (moved - target[None]) ** 2, 0.0).sum(axis=(1, 2))
    n = np.maximum(present.sum(axis=1), 1)
    residual = np.sqrt(sq / n)
    unaligned = ~np.isfinite(alignment[:, 0, 0])
    residual[unaligned] = np.nan
    info = {"reference_frame": "mean" if reference_frame == "mean" else frame,
            "unaligned_frames": int(unaligned.sum()), "residual_rms_mm": residual}
    return aligned, alignment, info
