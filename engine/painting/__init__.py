"""Weight painting: every operation of the workbench's weight-paint tool as an engine function.

The workbench (issue 7) only calls these and wraps each result in an undo
command. All coordinates are rest-mesh millimetres; weights are dense float64
arrays, one per parameter (:class:`DenseRegion` converts to and from the
model's sparse :class:`~engine.model.InfluenceRegion`).

* :class:`PaintContext` — topology, normals, KD-tree, parts, surface pieces and
  the X-mirror map of one mesh, built once (``docs/painting.md`` has the costs).
* :class:`Brush`, :func:`compute_dab`, :func:`brush_footprint` — add, subtract,
  set, smooth with radius, strength, falloff, front faces only, one part,
  mirror, surface-connected selection.
* :func:`compute_gradient`, :func:`sample_weight` — the gradient tool and the
  eyedropper.
* :class:`Change`, :class:`Stroke` — what changed (indices, before, after) and
  one drag as one exact undo step.
* whole-region operations: :func:`normalise_group1`, :func:`invert_weights`,
  :func:`clear_weights`, :func:`mirror_weights` / :func:`mirror_region`,
  :func:`smooth_weights`, :func:`grow_weights`, :func:`shrink_weights`.
* :func:`heat_colors` — weights to viewport colours.
* :class:`LivePreview` — the posed mesh following the weights dab by dab,
  without rebuilding the model's deformer.

A stroke at a Python prompt:

>>> from engine import load_model
>>> from engine.painting import PaintContext, DenseRegion, Brush, Stroke, heat_colors
>>> head = load_model()
>>> ctx = PaintContext(head)                                   # once per mesh
>>> dense = DenseRegion.from_model(head, "brow_raise")
>>> brush = Brush("add", radius=15, strength=0.3, falloff="smooth", part="skin", mirror=True)
>>> stroke = Stroke(dense.weights)                             # mouse pressed
>>> for x in (20.0, 25.0, 30.0):                               # mouse moves over the brow
...     change = stroke.dab(ctx, brush, (x, 160.0, 125.0), view_direction=(0, 0, -1))
>>> step = stroke.finish()                                     # mouse released: one undo step
>>> head.set_region("brow_raise", dense.to_region())
>>> colours = heat_colors(dense.weights)                       # (N, 3) uint8 for the viewport
>>> step.undo(dense.weights); head.set_region("brow_raise", dense.to_region())   # undo, exactly
"""

from engine.painting.brush import (FALLOFFS, MODES, Brush, brush_footprint, compute_dab, compute_gradient, paintable_mask,
                    sample_weight)
from engine.painting.changes import Change, Stroke
from engine.painting.heatmap import WEIGHT_RAMP, heat_colors
from engine.painting.mirror import MirrorMap, mirror_map, mirrored_points, mirrored_vectors
from engine.painting.preview import LivePreview
from engine.painting.topology import PaintContext, mirrored_part_name
from engine.painting.weights import (LEFT_TO_RIGHT, RIGHT_TO_LEFT, DenseRegion, clear_weights, grow_weights, group1_names,
                      invert_weights, mirror_region, mirror_targets, mirror_weights, normalise_group1,
                      normalise_stack, shrink_weights, smooth_weights)

__all__ = [
    "FALLOFFS", "LEFT_TO_RIGHT", "MODES", "RIGHT_TO_LEFT", "WEIGHT_RAMP", "Brush", "Change", "DenseRegion",
    "LivePreview", "MirrorMap", "PaintContext", "Stroke", "brush_footprint", "clear_weights", "compute_dab",
    "compute_gradient", "grow_weights", "group1_names", "heat_colors", "invert_weights", "mirror_map",
    "mirror_region", "mirror_targets", "mirror_weights", "mirrored_part_name", "mirrored_points",
    "mirrored_vectors", "normalise_group1", "normalise_stack", "paintable_mask", "sample_weight",
    "shrink_weights", "smooth_weights",
]
