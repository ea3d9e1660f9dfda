"""Brush strokes: one mouse drag, from a Python prompt or from the workbench, as one undo step.

* :class:`Stroke` gathers the dabs of one drag on a dense weight array into
  one :class:`~engine.painting.change.Change`.
* :class:`PaintStroke` is the paint tool's stroke on one parameter of a
  model: dabs spaced :data:`SPACING` × radius apart along the drag, or the
  gradient tool's ramp redrawn as the mouse moves; :meth:`PaintStroke.finish`
  gives the model-level :class:`~engine.model.weight_changes.WeightChange`.
  The workbench's paint tool drives exactly this object with the points
  under the mouse, so a stroke scripted with the same points, brush and view
  gives the same weights, bit for bit.
* :func:`rest_point` maps a pick on the drawn (possibly posed) mesh back to
  the rest mesh, where painting happens.

All points are rest-mesh millimetres.

>>> from engine import load_model
>>> from engine.model.weight_changes import apply_weight_change
>>> from engine.painting import Brush, PaintContext, PaintStroke
>>> head = load_model(); ctx = PaintContext(head)
>>> stroke = PaintStroke(head, "brow_raise", Brush("add", radius=12, strength=0.3), ctx,
...                      view_direction=(0, 0, -1))
>>> for x in (-20.0, 0.0, 20.0):                       # the mouse moves across the brow
...     _ = stroke.to((x, 160.0, 125.0))
>>> len(stroke.points)                                 # a dab every 3 mm (0.25 × 12 mm)
14
>>> change = stroke.finish()                           # nothing written into the model yet
>>> undo = apply_weight_change(head, "brow_raise", change)   # one undo step
>>> _ = apply_weight_change(head, "brow_raise", undo)        # undone, bit for bit
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from engine.errors import UserError
from engine.model.model import Model
from engine.model.weight_changes import WeightChange
from engine.painting.brush import Brush, compute_dab, compute_gradient
from engine.painting.change import Change, weight_change_from_dense
from engine.painting.topology import PaintContext, _point
from engine.painting.weights import DenseRegion

SPACING = 0.25
"""Dabs along a stroke are this fraction of the brush radius apart."""


class Stroke:
    """One mouse drag: dabs applied to ``weights`` in place, gathered into one :class:`Change`.

    ``weights`` is the dense float array being painted (length N); the
    stroke keeps a copy of it as it was when the stroke began, so
    :meth:`finish` returns exactly the vertices whose bits differ with their
    original and final values (one undo step).

    >>> w = np.zeros(5)
    >>> stroke = Stroke(w)
    >>> _ = stroke.apply(Change.between(w, np.array([0.0, 0.5, 0.5, 0.0, 0.0])))
    >>> _ = stroke.apply(Change.between(w, np.array([0.0, 0.5, 1.0, 0.25, 0.0])))
    >>> step = stroke.finish()
    >>> step.indices, step.before, step.after
    (array([1, 2, 3]), array([0., 0., 0.]), array([0.5 , 1.  , 0.25]))
    >>> step.undo(w); w
    array([0., 0., 0., 0., 0.])
    >>> step.redo(w); w
    array([0.  , 0.5 , 1.  , 0.25, 0.  ])
    """

    def __init__(self, weights: np.ndarray):
        if not isinstance(weights, np.ndarray) or weights.ndim != 1 or weights.dtype != np.float64:
            raise UserError("a stroke paints a 1-D float64 weight array (one weight per vertex)")
        self.weights = weights
        self._start = weights.copy()
        self._touched = np.zeros(len(weights), dtype=bool)
        self.dabs = 0

    def apply(self, change: Change) -> Change:
        """Write one change into the weights and remember what it touched; returns it."""
        change.redo(self.weights)
        self._touched[change.indices] = True
        self.dabs += 1
        return change

    def dab(self, ctx: PaintContext, brush: Brush, point: npt.ArrayLike,
            view_direction: npt.ArrayLike | None = None, *, camera_position: npt.ArrayLike | None = None,
            pressure: float = 1.0) -> Change:
        """Compute a brush dab (:func:`~engine.painting.brush.compute_dab`) on the current weights and apply it."""
        return self.apply(compute_dab(ctx, self.weights, brush, point, view_direction,
                                      camera_position=camera_position, pressure=pressure))

    def finish(self) -> Change:
        """The whole stroke as one change (vertices back at their original value are left out)."""
        idx = np.flatnonzero(self._touched)
        differ = self._start[idx].view(np.uint64) != self.weights[idx].view(np.uint64)
        idx = idx[differ]
        return Change(idx, self._start[idx].copy(), self.weights[idx].copy())


def rest_point(model: Model, vertex_indices: npt.ArrayLike, barycentric_weights: npt.ArrayLike) -> np.ndarray:
    """The rest-mesh point (3,) mm of a pick on the drawn mesh, posed or not.

    ``vertex_indices`` are the hit polygon's model vertices and
    ``barycentric_weights`` the hit point's interpolation weights on them
    (summing to 1): the same weights on the rest positions give the same
    point of the surface at rest.

    >>> model = Model([[0, 0, 0], [10, 0, 0], [0, 10, 0]], [3, 0, 1, 2])
    >>> rest_point(model, [0, 1, 2], [0.5, 0.25, 0.25])
    array([2.5, 2.5, 0. ])
    """
    vertices = np.asarray(vertex_indices, dtype=np.int64).reshape(-1)
    weights = np.asarray(barycentric_weights, dtype=float).reshape(-1)
    if len(vertices) == 0 or vertices.shape != weights.shape:
        raise UserError(f"a pick needs one interpolation weight per polygon vertex "
                        f"({len(vertices)} vertices, {len(weights)} weights)")
    if vertices.min() < 0 or vertices.max() >= model.n_vertices:
        raise UserError(f"a picked vertex is outside 0..{model.n_vertices - 1}")
    return weights @ model.vertices[vertices]


class PaintStroke:
    """One stroke of the paint tool on parameter ``name`` of ``model``: dabs along a drag, or a gradient.

    Parameters
    ----------
    model : Model
        Read, never written: :meth:`finish` returns the change to apply.
    name : str
        The parameter whose weights are painted.
    brush : Brush
        Used for every dab; assign :attr:`brush` to change it mid-stroke.
    context : PaintContext, optional
        The mesh's topology (built here if not given; build it once per mesh).
    dense : DenseRegion, optional
        The parameter's dense weights to paint into, in place (a tool shares
        them with its colours and :class:`~engine.painting.LivePreview`);
        read from the model if not given.
    view_direction, camera_position : (3,) mm, optional
        The view, for ``front_faces_only``: the direction the camera looks, or
        the camera's position (perspective). A call to :meth:`to` or
        :meth:`gradient_to` may give its own.
    spacing : float
        Dabs along the drag are ``spacing × brush.radius`` apart.

    Attributes
    ----------
    points : list of (3,) arrays
        The centre of every dab so far, in order (rest mm).
    """

    def __init__(self, model: Model, name: str, brush: Brush, context: PaintContext | None = None, *,
                 dense: DenseRegion | None = None, view_direction: npt.ArrayLike | None = None,
                 camera_position: npt.ArrayLike | None = None, spacing: float = SPACING):
        model.parameters[name]                 # unknown names raise with a suggestion
        if not (np.isfinite(spacing) and spacing > 0):
            raise UserError(f"dab spacing must be a positive fraction of the radius, not {spacing!r}")
        self.model, self.name, self.brush, self.spacing = model, name, brush, float(spacing)
        self.context = context if context is not None else PaintContext(model)
        if self.context.n_vertices != model.n_vertices:
            raise UserError(f"the paint context is of a mesh of {self.context.n_vertices} vertices, "
                            f"the model has {model.n_vertices}: build one for this model")
        self.dense = dense if dense is not None else DenseRegion.from_model(model, name)
        if self.dense.weights.shape != (model.n_vertices,):
            raise UserError(f"the painted weights have shape {self.dense.weights.shape}, "
                            f"expected ({model.n_vertices},)")
        self.view_direction, self.camera_position = view_direction, camera_position
        self.points: list[np.ndarray] = []
        self._stroke = Stroke(self.dense.weights)
        self._gradient: tuple[np.ndarray, Change] | None = None    # start, the ramp drawn last

    @property
    def weights(self) -> np.ndarray:
        """The dense weights being painted (N,), as they are now."""
        return self.dense.weights

    def _view(self, view_direction: npt.ArrayLike | None,
              camera_position: npt.ArrayLike | None) -> tuple[npt.ArrayLike | None, npt.ArrayLike | None]:
        if view_direction is None and camera_position is None:
            return self.view_direction, self.camera_position
        return view_direction, camera_position

    def dab(self, point: npt.ArrayLike, *, view_direction: npt.ArrayLike | None = None,
            camera_position: npt.ArrayLike | None = None) -> Change:
        """One dab of the brush at ``point`` (mm); returns what it changed in the dense weights."""
        if self._gradient is not None:
            raise UserError("this stroke draws a gradient; dabs need a stroke of their own")
        p = _point(point)
        view, eye = self._view(view_direction, camera_position)
        change = self._stroke.dab(self.context, self.brush, p, view, camera_position=eye)
        self.points.append(p)
        return change

    def to(self, point: npt.ArrayLike, *, view_direction: npt.ArrayLike | None = None,
           camera_position: npt.ArrayLike | None = None) -> Change:
        """Dabs from the last one towards ``point`` (mm), ``spacing × radius`` apart; the first dab at ``point``.

        What a mouse move with the button down does. Returns what these dabs
        changed in the dense weights (for recolouring).
        """
        p = _point(point)
        if not self.points:
            return self.dab(p, view_direction=view_direction, camera_position=camera_position)
        step = self.spacing * self.brush.radius
        start = self.points[-1]
        gap = p - start
        distance = float(np.linalg.norm(gap))
        change = Change.empty()
        for k in range(1, int(distance // step) + 1):
            change = change.followed_by(self.dab(start + gap * (k * step / distance),
                                                 view_direction=view_direction, camera_position=camera_position))
        return change

    def gradient_to(self, point: npt.ArrayLike, *, view_direction: npt.ArrayLike | None = None,
                    camera_position: npt.ArrayLike | None = None) -> Change:
        """The gradient tool: the first call sets the start (where the weight is ``brush.value``); each later
        call draws the ramp again from the start to ``point`` (where it is 0), replacing the previous one.

        The ramp uses the brush's strength, part, front-faces-only, connected
        and mirror settings (:func:`~engine.painting.brush.compute_gradient`).
        Returns what the call changed in the dense weights.
        """
        if self.points:
            raise UserError("this stroke paints dabs; a gradient is a stroke of its own")
        end = _point(point)
        if self._gradient is None:
            self._gradient = (end, Change.empty())
            return Change.empty()
        start, previous = self._gradient
        previous.undo(self.dense.weights)
        axis = end - start
        if float(axis @ axis) == 0:
            change = Change.empty()                # start and end the same point: no ramp yet
        else:
            b = self.brush
            view, eye = self._view(view_direction, camera_position)
            change = compute_gradient(self.context, self.dense.weights, start, end, start_value=b.value,
                                      end_value=0.0, strength=b.strength, part=b.part,
                                      front_faces_only=b.front_faces_only, view_direction=view,
                                      camera_position=eye, connected=b.connected, mirror=b.mirror)
        self._stroke.apply(change)
        self._gradient = (start, change)
        return previous.inverse().followed_by(change)

    def finish(self) -> WeightChange:
        """The whole stroke as one change of the model's region (not applied: see
        :func:`~engine.model.weight_changes.apply_weight_change`); empty if nothing changed."""
        return weight_change_from_dense(self.model, self.name, self._stroke.finish())

    def cancel(self) -> Change:
        """Put the dense weights back as they were when the stroke began; returns what that changed."""
        back = self._stroke.finish().inverse()
        back.redo(self.dense.weights)
        self._stroke = Stroke(self.dense.weights)
        self.points, self._gradient = [], None
        return back
