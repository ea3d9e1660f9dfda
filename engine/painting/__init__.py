"""Weight painting: every operation of the workbench's weight-paint tool as an engine function.

The paper's configuration tool paints each parameter's influence region on
the static model (§2.2.2). The workbench only calls these functions and
wraps each result in an undo command. All coordinates are rest-mesh
millimetres; weights are painted as dense float64 arrays, one per parameter
(:class:`DenseRegion` converts to and from the model's sparse
:class:`~engine.model.InfluenceRegion`), and leave painting as one
:class:`~engine.model.WeightChange` (NaN: not in the region), applied with
:func:`~engine.model.apply_weight_change`, which returns its exact inverse.

* :class:`PaintContext` — topology, normals, KD-tree, parts, surface pieces and
  the X-mirror map of one mesh, built once (``docs/painting.md`` has the costs).
* :class:`Brush`, :func:`compute_dab`, :func:`brush_footprint` — add, subtract,
  set, smooth with radius, strength, falloff, front faces only, one part,
  mirror, surface-connected selection.
* :func:`compute_gradient`, :func:`sample_weight` — the gradient tool and the
  eyedropper.
* :class:`PaintStroke` — the paint tool's stroke on a model's parameter: dabs
  :data:`SPACING` × radius apart along a drag, the gradient redrawn as the
  mouse moves, the result as one :class:`~engine.model.WeightChange`;
  :func:`rest_point` maps a pick on the posed mesh to the rest mesh. The
  workbench's mouse drives exactly this object.
* :class:`Change`, :class:`Stroke` — what changed in dense weights (indices,
  before, after) and one drag gathered into one exact change;
  :func:`weight_change_from_dense` turns a dense change into the model's.
* whole-region operations: :func:`normalise_group1`, :func:`invert_weights`,
  :func:`clear_weights`, :func:`mirror_weights` / :func:`mirror_region`,
  :func:`smooth_weights`, :func:`grow_weights`, :func:`shrink_weights`.
* :func:`heat_colors` — weights to viewport colours.
* :class:`LivePreview` — the posed mesh following the weights dab by dab,
  without rebuilding the model's deformer.

A stroke at a Python prompt, as the workbench paints it:

>>> from engine import load_model
>>> from engine.model import apply_weight_change
>>> from engine.painting import PaintContext, Brush, PaintStroke, heat_colors
>>> head = load_model()
>>> ctx = PaintContext(head)                                   # once per mesh
>>> brush = Brush("add", radius=15, strength=0.3, falloff="smooth", part="skin", mirror=True)
>>> stroke = PaintStroke(head, "brow_raise", brush, ctx, view_direction=(0, 0, -1))   # mouse pressed
>>> for x in (20.0, 25.0, 30.0):                               # mouse moves over the brow
...     change = stroke.to((x, 160.0, 125.0))
...     colours = heat_colors(stroke.weights[change.indices])  # recolour only what changed
>>> step = stroke.finish()                                     # mouse released: one undo step
>>> undo = apply_weight_change(head, "brow_raise", step)       # written into the model
>>> redo = apply_weight_change(head, "brow_raise", undo)       # undo, exactly
"""

from engine.painting.brush import (
    FALLOFFS,
    MODES,
    Brush,
    brush_footprint,
    compute_dab,
    compute_gradient,
    paintable_mask,
    sample_weight,
)
from engine.painting.change import Change, weight_change_from_dense
from engine.painting.heatmap import WEIGHT_RAMP, heat_colors
from engine.painting.mirror import MirrorMap, mirror_map, mirrored_points, mirrored_vectors
from engine.painting.preview import LivePreview
from engine.painting.strokes import SPACING, PaintStroke, Stroke, rest_point
from engine.painting.topology import PaintContext, mirrored_part_name
from engine.painting.weights import (
    LEFT_TO_RIGHT,
    RIGHT_TO_LEFT,
    DenseRegion,
    clear_weights,
    group1_names,
    grow_weights,
    invert_weights,
    mirror_region,
    mirror_targets,
    mirror_weights,
    normalise_group1,
    normalise_stack,
    shrink_weights,
    smooth_weights,
)

__all__ = [
    "FALLOFFS", "LEFT_TO_RIGHT", "MODES", "RIGHT_TO_LEFT", "SPACING", "WEIGHT_RAMP", "Brush", "Change",
    "DenseRegion", "LivePreview", "MirrorMap", "PaintContext", "PaintStroke", "Stroke", "brush_footprint",
    "clear_weights", "compute_dab", "compute_gradient", "group1_names", "grow_weights", "heat_colors",
    "invert_weights", "mirror_map", "mirror_region", "mirror_targets", "mirror_weights", "mirrored_part_name",
    "mirrored_points", "mirrored_vectors", "normalise_group1", "normalise_stack", "paintable_mask", "rest_point",
    "sample_weight", "shrink_weights", "smooth_weights", "weight_change_from_dense",
]
