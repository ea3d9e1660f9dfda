"""Held-out frames through the face: how well the articulatory parameters reproduce unseen motion (§3.1.2).

:func:`reconstruct_held_out` fits the parameters :func:`~engine.mocap.apply.apply_articulation`
added to frames the PCA did not analyse, deforms the model with the fitted
values and measures the error at the landmark vertices, in mm of the
recording. :func:`register_recording` first moves another recording rigidly
into the analysed recording's coordinates. Lengths are mm.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from engine.mocap.errors import MocapError
from engine.mocap.marker_alignment import similarity_fit
from engine.mocap.pca import Articulation

if TYPE_CHECKING:
    from engine.mocap.apply import AppliedArticulation
    from engine.model.model import Model

@dataclass
class HeldOutError:
    """Reconstruction error at the markers, mm of the recording (model mm ÷ the alignment scale)."""

    markers: list[str]
    rms_mm: float
    """Over all markers and frames."""
    max_mm: float
    per_marker_rms_mm: np.ndarray
    per_frame_rms_mm: np.ndarray
    n_frames: int
    rest_rms_mm: float
    """The same error with every new parameter at 0 (the model at rest): the baseline."""
    pca_rms_mm: float
    """The PCA model's own least-squares error at the markers, without the face."""
    values: np.ndarray
    """(F, C) fitted parameter values on the face."""

    def report(self) -> str:
        worst = int(np.argmax(self.per_marker_rms_mm))
        return (f"held-out reconstruction through the face: {self.n_frames} frames, {len(self.markers)} markers: "
                f"RMS {self.rms_mm:.3f} mm, max {self.max_mm:.3f} mm (worst marker {self.markers[worst]}: "
                f"{self.per_marker_rms_mm[worst]:.3f} mm RMS); PCA alone {self.pca_rms_mm:.3f} mm; "
                f"face at rest {self.rest_rms_mm:.3f} mm\n")


def reconstruct_held_out(model: Model, applied: AppliedArticulation, art: Articulation, markers: Sequence[str],
                         positions: npt.ArrayLike, register: bool = False) -> HeldOutError:
    """Fit the new parameters to held-out frames, deform the model, measure at the landmarks.

    ``markers`` names the columns of ``positions`` ((F, M, 3), mm, head
    motion removed, NaN where missing; the frames should not be among those
    the PCA analysed). Each frame is taken into model space with the
    alignment, the parameters :attr:`AppliedArticulation.names` are fitted
    by least squares to the markers present, the model is deformed with
    those values and the landmark vertices are compared with the markers.

    Frames from the recording the PCA analysed share its coordinates. A
    *different* recording has had its head motion removed relative to its
    own reference frame: pass ``register=True`` to first move it rigidly into
    the analysed recording's coordinates (:func:`register_recording`).
    """
    markers = [str(m) for m in markers]
    absent = [m for m in applied.markers if m not in markers]
    if absent:
        raise MocapError(f"the held-out data lack markers {', '.join(absent)}")
    x = np.asarray(positions, dtype=float)
    if x.ndim != 3 or x.shape[1:] != (len(markers), 3):
        raise MocapError(f"marker positions have shape {x.shape}, expected (frames, {len(markers)}, 3)")
    if register:
        rotation, translation = register_recording(art, markers, x)
        x = x @ rotation.T + translation
    x = x[:, [markers.index(m) for m in applied.markers]]
    fit = fit_frames(model, applied, applied.to_model(x))
    errors, rest_err, fitted = fit.errors, fit.rest_errors, fit.values
    errors /= applied.scale
    rest_err /= applied.scale
    frames = np.isfinite(errors).any(axis=1)
    if not frames.any():
        raise MocapError("no held-out frame has any of the markers")
    cols = [art.markers.index(m) for m in applied.markers]
    pca_fit = art.reconstruct(art.values(x, applied.markers))[:, cols]
    pca_err = np.linalg.norm(pca_fit - x, axis=2)
    return HeldOutError(
        markers=list(applied.markers), rms_mm=float(np.sqrt(np.nanmean(errors ** 2))),
        max_mm=float(np.nanmax(errors)),
        per_marker_rms_mm=np.sqrt(np.nanmean(np.where(np.isfinite(errors), errors ** 2, np.nan), axis=0)),
        per_frame_rms_mm=np.sqrt(np.nanmean(errors[frames] ** 2, axis=1)), n_frames=int(frames.sum()),
        rest_rms_mm=float(np.sqrt(np.nanmean(rest_err ** 2))), pca_rms_mm=float(np.sqrt(np.nanmean(pca_err ** 2))),
        values=fitted)


@dataclass
class FrameFit:
    """Per-frame least-squares values of the applied parameters, and the misfit at the landmarks (model mm)."""

    values: np.ndarray
    """(F, C) values of :attr:`AppliedArticulation.names`; NaN in frames with no marker present."""
    errors: np.ndarray
    """(F, m) distance between the deformed landmark and its marker; NaN where the marker is missing."""
    rest_errors: np.ndarray
    """(F, m) the same distance with the model at rest."""


def fit_frames(model: Model, applied: AppliedArticulation, target: np.ndarray) -> FrameFit:
    """Fit the applied parameters frame by frame to ``target`` ((F, m, 3) model mm, the columns of
    :attr:`AppliedArticulation.markers`, NaN where missing), from the markers each frame has."""
    from engine.model.vertex_subset import model_at_landmarks

    sub = model_at_landmarks(model, applied.markers)                        # exact at these vertices, fast
    rest = sub.vertices
    basis = np.stack([sub.deform({n: 1.0}) - rest for n in applied.names])  # (C, m, 3): linear leaves
    deformer = sub.deformer()
    order = {n: i for i, n in enumerate(sub.parameters.names)}
    base = sub.values_array()
    errors = np.full(target.shape[:2], np.nan)
    rest_err = np.full(target.shape[:2], np.nan)
    fitted = np.full((len(target), len(applied.names)), np.nan)
    A = basis.reshape(len(applied.names), -1).T
    for f in range(len(target)):
        ok = np.isfinite(target[f]).all(axis=1)
        if not ok.any():
            continue
        rows = np.repeat(ok, 3)
        v = np.linalg.lstsq(A[rows], (target[f] - rest).reshape(-1)[rows], rcond=None)[0]
        fitted[f] = v
        values = base.copy()
        for name, value in zip(applied.names, v, strict=True):
            values[order[name]] = value
        moved = deformer.deform(values)
        errors[f, ok] = np.linalg.norm(moved[ok] - target[f, ok], axis=1)
        rest_err[f, ok] = np.linalg.norm(rest[ok] - target[f, ok], axis=1)
    return FrameFit(fitted, errors, rest_err)


def register_recording(art: Articulation, markers: Sequence[str], positions: npt.ArrayLike,
                       iterations: int = 30) -> tuple[np.ndarray, np.ndarray]:
    """The rigid motion (R, t) that takes another recording into the coordinates ``art`` was computed in.

    Minimises ``Σ_f |R x_f + t − (mean + Σ_k v_fk C_k)|²`` over one rotation
    and translation for the whole recording and free component values per
    frame (alternating Procrustes and least squares), on the frames where
    every analysed marker is present. ``positions`` (F, M, 3) mm, columns
    named by ``markers``. Returns ``R`` (3, 3) and ``t`` (3,): ``x ↦ x Rᵀ + t``.
    """
    x = art._take(positions, markers)
    complete = np.isfinite(x).all(axis=(1, 2))
    if not complete.any():
        raise MocapError("no frame has every analysed marker: cannot register the recording")
    x = x[complete]
    flat = x.reshape(-1, 3)
    _, rotation, translation = similarity_fit(x.mean(axis=0), art.mean, scale=False)
    for _ in range(iterations):
        moved = x @ rotation.T + translation
        target = art.reconstruct(art.values(moved))
        _, new_rotation, new_translation = similarity_fit(flat, target.reshape(-1, 3), scale=False)
        step = np.abs(new_rotation - rotation).max() + np.abs(new_translation - translation).max()
        rotation, translation = new_rotation, new_translation
        if step < 1e-10:
            break
    return rotation, translation
