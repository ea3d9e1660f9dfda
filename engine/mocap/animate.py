"""A capture session drives the face: every frame's markers → articulatory parameter values (issue 22 §1).

§3.1.2 derives articulatory parameters from motion capture; here the recording
then *plays* through them. For each frame of a session (head motion removed),
the markers present are taken into model space by the alignment
:func:`~engine.mocap.apply.apply_articulation` found, and the values of the
component parameters are fitted to them by least squares (missing markers
simply leave their rows out; a frame with none takes the values interpolated
from its neighbours). Optionally the session's own rigid head motion, relative
to its first aligned frame, turns the head through ``head_turn``, ``head_nod``
and ``head_tilt`` (:mod:`engine.model.head_rotation`). Values are kept within
each parameter's range, and how often that bit is counted.

The report gives, per marker, the RMS distance between the recording and the
animated face's landmark over the take, in mm of the recording (the face's
error ÷ the alignment's scale), beside the same with the face at rest.

>>> from engine import load_model
>>> from engine.mocap.session import load_session
>>> from engine.mocap.articulation_file import load_articulation_file
>>> take = animate_session(load_session("take.h5"), load_articulation_file("art.h5"), load_model())  # doctest: +SKIP
>>> print(take.report())                                                                            # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from engine.mocap.apply import AppliedArticulation, apply_articulation, component_names
from engine.mocap.errors import MocapError
from engine.mocap.held_out import FrameFit, fit_frames
from engine.mocap.pca import Articulation
from engine.mocap.session import Session
from engine.model.head_rotation import head_rotation_values
from engine.model.model import Model
from engine.outputs.animation_file import write_animation


@dataclass
class SessionAnimation:
    """A session played through a model: tracks of every parameter, and how close the face came."""

    model: Model
    """The model animated: the one given, with the component parameters added if it lacked them."""
    applied: AppliedArticulation
    times_ms: np.ndarray
    """(F,) the session's frame times."""
    values: np.ndarray
    """(F, P) every parameter of :attr:`model`, in tree order (:attr:`names`)."""
    names: list[str]
    markers: list[str]
    """The markers compared (the applied ones), in :attr:`per_marker_rms_mm`'s order."""
    per_marker_rms_mm: np.ndarray
    """Per marker: RMS over the take of recording ↔ animated landmark, mm of the recording."""
    per_marker_rest_rms_mm: np.ndarray
    """The same with the face at rest: what the animation is measured against."""
    frames_without_markers: int
    clamped: dict[str, int] = field(default_factory=dict)
    """Parameter → frames whose fitted value was outside its range (kept at the bound)."""
    head_motion: bool = False

    @property
    def rms_mm(self) -> float:
        return float(np.sqrt(np.mean(self.per_marker_rms_mm ** 2)))

    def report(self) -> str:
        lines = [f"{len(self.times_ms)} frames, {len(self.applied.names)} articulatory parameters "
                 f"({', '.join(self.applied.names)})" + (", head motion" if self.head_motion else ""),
                 f"recording ↔ animated face, RMS over the take: {self.rms_mm:.2f} mm "
                 f"(face at rest: {float(np.sqrt(np.mean(self.per_marker_rest_rms_mm ** 2))):.2f} mm)",
                 "per marker (mm RMS, animated / at rest):"]
        lines += [f"  {m:>6s}  {a:6.2f}  {r:6.2f}" for m, a, r in
                  zip(self.markers, self.per_marker_rms_mm, self.per_marker_rest_rms_mm, strict=True)]
        if self.frames_without_markers:
            lines.append(f"{self.frames_without_markers} frame(s) had none of the markers: values interpolated")
        lines += [f"kept {name} within its range in {n} frame(s)" for name, n in self.clamped.items()]
        return "\n".join(lines) + "\n"


def animate_session(session: Session, art: Articulation, model: Model, *, head_motion: bool = False,
                    prefix: str | None = None) -> SessionAnimation:
    """Play ``session`` through ``model`` with the components of ``art`` (see the module text).

    When ``model`` already has the component parameters (a model saved by
    ``mocap apply`` with the same names), they are used as they are; the
    alignment is found again from the landmarks. Otherwise they are added to
    a copy of ``model``.
    """
    names = component_names(art, None, prefix)
    present = [n for n in names if n in model.parameters]
    if present and len(present) < len(names):
        raise MocapError(f"the model has some of the component parameters ({', '.join(present)}) but not all "
                         f"of {', '.join(names)}")
    animated = model.copy()
    if present:
        bare = model.copy()
        for name in names:
            bare.remove_parameter(name)
        applied = apply_articulation(bare, art, prefix=prefix)
    else:
        applied = apply_articulation(animated, art, prefix=prefix)
    fit, fitted, empty = session_component_values(animated, applied, session)

    tree = animated.parameters
    all_names = list(tree.names)
    values = np.tile([tree[n].default for n in all_names], (len(fitted), 1)).astype(float)
    for k, name in enumerate(applied.names):
        values[:, all_names.index(name)] = fitted[:, k]
    if head_motion:
        rotations = _head_rotations(session, applied.rotation)
        rotation_names, angles = head_rotation_values(animated, rotations)
        for k, name in enumerate(rotation_names):
            values[:, all_names.index(name)] = angles[:, k]
    clamped = _clamp(values, all_names, animated)

    errors = fit.errors / applied.scale
    rest = fit.rest_errors / applied.scale
    if not np.isfinite(errors).any():
        raise MocapError("no frame of the session has any of the analysed markers")
    return SessionAnimation(
        model=animated, applied=applied, times_ms=session.times_ms, values=values, names=all_names,
        markers=list(applied.markers), per_marker_rms_mm=_rms(errors), per_marker_rest_rms_mm=_rms(rest),
        frames_without_markers=empty, clamped=clamped, head_motion=head_motion)


def session_component_values(model: Model, applied: AppliedArticulation, session: Session
                             ) -> tuple[FrameFit, np.ndarray, int]:
    """Every frame of ``session`` fitted with the applied components of ``model``.

    Returns the fit (values, NaN in frames with none of the markers, and the
    errors at the landmarks), the values (F, C) with such frames interpolated
    from their neighbours, and how many there were. The workbench's player
    plays a session through the face with these values.
    """
    absent = [m for m in applied.markers if m not in session.markers]
    if absent:
        raise MocapError(f"the session lacks the analysed markers {', '.join(absent)}")
    columns = [session.markers.index(m) for m in applied.markers]
    x = session.positions[:, columns].copy()
    x[session.missing[:, columns]] = np.nan
    fit = fit_frames(model, applied, applied.to_model(x))
    values, empty = _fill_empty_frames(fit.values)
    return fit, values, empty


def write_session_animation(animation: SessionAnimation, output: str | Path, *, audio: str | Path | None = None,
                            audio_offset_ms: float = 0.0, size: tuple[int, int] = (640, 480),
                            view: str = "front", progress: Callable[[int, int], None] | None = None) -> Path:
    """Write the animation as a tracks table (``.csv``) or a video (``.mp4``, with the take's ``audio``).

    ``audio_offset_ms``: when the WAV's first sample sounds relative to the
    session's first frame (positive: later — silence is put before it;
    negative: earlier — its first samples are dropped).
    """
    return write_animation(output, animation.model, animation.names, animation.times_ms, animation.values,
                           _frame_rate(animation.times_ms), audio=audio, audio_offset_ms=audio_offset_ms, size=size,
                           view=view, progress=progress)


def _head_rotations(session: Session, marker_to_model: np.ndarray) -> np.ndarray:
    """(F, 3, 3) the head's rotation at each frame relative to the first aligned one, in model axes."""
    M = session.alignment[:, :3, :3]                        # row vectors: positions = raw · M
    aligned = np.flatnonzero(np.isfinite(M).all(axis=(1, 2)))
    if not len(aligned):
        raise MocapError("the session has no head-aligned frame: its head motion is unknown")
    # raw = Mᵀ⁻¹ … per frame; the head at frame f, seen in the reference frame's axes, is turned by M_refᵀ M_f
    reference = M[aligned[0]]
    H = np.einsum("ji,fjk->fik", reference, M)
    H[~np.isfinite(H).all(axis=(1, 2))] = np.eye(3)
    u, _, vt = np.linalg.svd(H)                             # the nearest rotations (the fit's round-off)
    H = u @ vt
    R = marker_to_model
    return np.einsum("ij,fjk,lk->fil", R, H, R)


def _fill_empty_frames(values: np.ndarray) -> tuple[np.ndarray, int]:
    """Frames with no fit (NaN) take values interpolated from their neighbours (held at the ends)."""
    empty = ~np.isfinite(values).all(axis=1)
    if not empty.any() or empty.all():
        return values, int(empty.sum())
    frames = np.arange(len(values))
    out = values.copy()
    for k in range(values.shape[1]):
        out[empty, k] = np.interp(frames[empty], frames[~empty], values[~empty, k])
    return out, int(empty.sum())


def _clamp(values: np.ndarray, names: list[str], model: Model) -> dict[str, int]:
    clamped: dict[str, int] = {}
    for k, name in enumerate(names):
        p = model.parameters[name]
        outside = (values[:, k] < p.minimum) | (values[:, k] > p.maximum)
        if outside.any():
            clamped[name] = int(outside.sum())
            values[:, k] = np.clip(values[:, k], p.minimum, p.maximum)
    return clamped


def _rms(errors: np.ndarray) -> np.ndarray:
    """Per column: the RMS of its finite entries (NaN for a marker never seen)."""
    return np.array([float(np.sqrt(np.mean(c[np.isfinite(c)] ** 2))) if np.isfinite(c).any() else np.nan
                     for c in errors.T])


def _frame_rate(times_ms: np.ndarray) -> float:
    if len(times_ms) < 2:
        return 30.0
    return float(1000.0 / np.median(np.diff(times_ms)))
