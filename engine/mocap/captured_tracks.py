"""A session's markers → the trajectories of the model's own articulatory parameters (issue 22 §2, step 1).

To learn how phones move ``jaw_open``, ``mouth_widen``, ``lip_protrude``,
``upper_lip_raise`` and ``lower_lip_raise``, the recording is first read as
values of those parameters, frame by frame:

1. **Into the articulation's coordinates.** Each session has had its head
   motion removed relative to its own reference frame; it is moved rigidly
   into the coordinates of the articulation file (``--articulation``, from
   ``mocap pca`` on a take of the same speaker and marker set) with
   :func:`~engine.mocap.held_out.register_recording`.
2. **Onto the model.** The similarity transform that ``mocap apply`` uses
   (:func:`~engine.mocap.marker_alignment.align_to_landmarks`: the
   articulation's marker shape onto the model's rest landmarks, with the
   component values of the model's rest pose fitted alongside) takes the
   analysed markers that are model landmarks into model space.
3. **Per frame, the parameter values** that bring the model's landmark
   vertices nearest the markers present (missing markers leave their rows
   out): Gauss–Newton from the previous frame's values, the Jacobian taken
   numerically at the current values, so that ``jaw_open``, a rotation, is
   fitted on its arc rather than its tangent.

:class:`CapturedTake` keeps the markers in model space too, so that any
candidate tracks can be put through the model and measured against the
recording (:meth:`CapturedTake.marker_error_mm`), in mm of the recording.
Lengths are mm, times ms.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from engine.mocap.errors import MocapError
from engine.mocap.held_out import register_recording
from engine.mocap.marker_alignment import align_to_landmarks, similarity_fit
from engine.mocap.pca import Articulation
from engine.mocap.session import Session
from engine.model.model import Model

GAUSS_NEWTON_STEPS = 3
ALIGNMENT_ROUNDS = 4
_STEP = 1e-4


class MarkerModel:
    """The model reduced to the marker vertices, driven by a few of its parameters (values (F, P) → (F, m, 3))."""

    def __init__(self, model: Model, markers: Sequence[str], parameters: Sequence[str]) -> None:
        from engine.mocap.synthetic import marker_vertices
        from engine.model.vertex_subset import model_at_vertices

        places = marker_vertices(model, markers)
        self.markers = list(markers)
        self.sub = model_at_vertices(model, [places[m] for m in self.markers],
                                     landmarks={m: i for i, m in enumerate(self.markers)})
        self.parameters = list(parameters)
        self.rest = self.sub.vertices.copy()
        self._deformer = self.sub.deformer()
        self._base = self.sub.values_array()
        order = list(self.sub.parameters.names)
        self._columns = np.array([order.index(p) for p in self.parameters], dtype=np.int64)

    def deform(self, values: np.ndarray) -> np.ndarray:
        """(F, P) parameter values → (F, m, 3) marker vertex positions, model mm."""
        values = np.atleast_2d(values)
        out = np.empty((len(values), len(self.rest), 3))
        full = np.tile(self._base, (len(values), 1))
        full[:, self._columns] = values
        for f in range(len(values)):
            out[f] = self._deformer.deform(full[f])
        return out

    def jacobian(self, values: np.ndarray) -> np.ndarray:
        """(m·3, P) derivative of the marker positions at ``values`` (P,), central differences."""
        steps = np.eye(len(self.parameters)) * _STEP
        plus = self.deform(values + steps)
        minus = self.deform(values - steps)
        return ((plus - minus) / (2 * _STEP)).reshape(len(self.parameters), -1).T


@dataclass
class CapturedTake:
    """One session read as articulatory trajectories (model units), with its markers in model space."""

    source: str
    times_ms: np.ndarray
    """(F,) frame times, ms."""
    phones: list[tuple[float, float, str]]
    parameters: list[str]
    values: np.ndarray
    """(F, P) fitted parameter values; NaN in frames with no marker present."""
    markers: list[str]
    """The markers compared (articulation markers that are model landmarks)."""
    target: np.ndarray
    """(F, m, 3) the markers in model space, mm; NaN where missing."""
    scale: float
    """Model mm per recording mm (the alignment's scale)."""

    @property
    def n_frames(self) -> int:
        return len(self.times_ms)

    def marker_error_mm(self, marker_model: MarkerModel, tracks: np.ndarray, frames: np.ndarray) -> np.ndarray:
        """(f, m) distance between the model driven by ``tracks`` (F, P) and the recording at ``frames``
        (F bools), mm of the recording; NaN where a marker is missing."""
        moved = marker_model.deform(tracks[frames])
        return np.linalg.norm(moved - self.target[frames], axis=2) / self.scale


def capture_tracks(session: Session, art: Articulation, model: Model, parameters: Sequence[str],
                   source: str = "") -> tuple[CapturedTake, MarkerModel]:
    """Read ``session`` as trajectories of ``parameters`` of ``model`` (see the module text)."""
    lips = [m for m in art.markers if m in model.landmarks]
    absent = [m for m in lips if m not in session.markers]
    if absent:
        raise MocapError(f"the session lacks the articulation's markers {', '.join(absent)}", file=source or None)
    if len(lips) < 3:
        raise MocapError(f"only {len(lips)} of the articulation's markers are landmarks of the model: "
                         "the alignment needs 3", file=source or None)
    markers = lips + [m for m in session.markers if m not in lips and _placeable(model, m)]
    positions = session.positions.copy()
    positions[session.missing] = np.nan
    rotation, translation = register_recording(art, session.markers, positions)
    x = positions[:, [session.markers.index(m) for m in markers]] @ rotation.T + translation
    columns = [art.markers.index(m) for m in lips]
    rest = model.vertices[[model.landmarks[m] for m in lips]]
    scale, align, shift, _, _ = align_to_landmarks(art.mean[columns], art.components[:, columns], rest, True)
    marker_model = MarkerModel(model, markers, parameters)
    for _ in range(ALIGNMENT_ROUNDS):
        values = fit_values(marker_model, scale * x @ align.T + shift)
        scale, align, shift = _refit_alignment(marker_model, x, values)
    target = scale * x @ align.T + shift
    values = fit_values(marker_model, target)
    take = CapturedTake(source or session.source, session.times_ms, list(session.phones), list(parameters),
                        values, markers, target, float(scale))
    return take, marker_model


def _placeable(model: Model, marker: str) -> bool:
    from engine.errors import UserError
    from engine.mocap.synthetic import marker_vertices

    try:
        marker_vertices(model, [marker])
    except UserError:
        return False
    return True


def fit_values(marker_model: MarkerModel, target: np.ndarray, steps: int = GAUSS_NEWTON_STEPS) -> np.ndarray:
    """(F, P) parameter values bringing the marker vertices nearest ``target`` (F, m, 3), frame by frame."""
    n_params = len(marker_model.parameters)
    values = np.full((len(target), n_params), np.nan)
    current = np.zeros(n_params)
    for f in range(len(target)):
        present = np.isfinite(target[f]).all(axis=1)
        if present.sum() * 3 < n_params:
            continue
        rows = np.repeat(present, 3)
        goal = target[f].reshape(-1)[rows]
        for _ in range(steps):
            moved = marker_model.deform(current[None])[0].reshape(-1)[rows]
            jac = marker_model.jacobian(current)[rows]
            current = current + np.linalg.lstsq(jac, goal - moved, rcond=None)[0]
        values[f] = current
    return values


def _refit_alignment(marker_model: MarkerModel, x: np.ndarray,
                     values: np.ndarray) -> tuple[float, np.ndarray, np.ndarray]:
    """The similarity taking every present marker of every fitted frame onto the model posed at its values."""
    fitted = np.isfinite(values).all(axis=1)
    posed = marker_model.deform(values[fitted])
    source = x[fitted].reshape(-1, 3)
    present = np.isfinite(source).all(axis=1)
    return similarity_fit(source[present], posed.reshape(-1, 3)[present])
