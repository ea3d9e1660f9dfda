"""Dense weights for painting, and the whole-region operations on them.

Painting works on one dense float64 array per parameter (one weight per
vertex, 0 outside the region); :class:`DenseRegion` converts to and from the
model's sparse :class:`~engine.model.InfluenceRegion` and carries a field
translation's displacements along. Every operation here is pure: it takes
arrays and returns new ones (wrap the difference in
:meth:`Change.between <engine.painting.change.Change.between>` for undo).

>>> from engine import load_model
>>> from engine.painting import PaintContext, DenseRegion, grow_weights
>>> head = load_model(); ctx = PaintContext(head)
>>> dense = DenseRegion.from_model(head, "jaw_open")
>>> w = grow_weights(ctx, dense.weights, rings=2)
>>> int((w > 0).sum()) > int((dense.weights > 0).sum())
True
>>> region = dense.with_weights(w).to_region()        # back to sparse, for Model.set_region
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from engine.errors import UserError
from engine.model.model import InfluenceRegion, Model
from engine.painting.mirror import mirrored_vectors

if TYPE_CHECKING:
    from engine.painting.topology import PaintContext

LEFT_TO_RIGHT = "left_to_right"
RIGHT_TO_LEFT = "right_to_left"


@dataclass
class DenseRegion:
    """One parameter's influence region as dense arrays.

    Attributes
    ----------
    weights : (N,) float64
        Weight per vertex in [0, 1]; 0 outside the region.
    displacements : (N, 3) float64 or None
        A field translation's displacement per vertex (mm for value 1); kept
        for vertices painted down to 0, so painting them back restores their
        motion. Vertices that never had one get (0, 0, 0).
    listed_zero : (K,) int
        Vertices the sparse region listed with weight exactly 0; they stay
        listed while their weight is 0, so sparse → dense → sparse is exact.
    """

    weights: np.ndarray
    displacements: np.ndarray | None = None
    listed_zero: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

    @classmethod
    def from_region(cls, region: InfluenceRegion, n_vertices: int) -> DenseRegion:
        w = np.zeros(n_vertices)
        w[region.indices] = region.weights
        d = None
        if region.displacements is not None:
            d = np.zeros((n_vertices, 3))
            d[region.indices] = region.displacements
        return cls(w, d, region.indices[region.weights == 0].copy())

    @classmethod
    def from_model(cls, model: Model, name: str) -> DenseRegion:
        """The region of parameter ``name``; a field translation gets a displacement array even when empty."""
        model.parameters[name]
        dense = cls.from_region(model.regions[name], model.n_vertices)
        if model.parameters[name].field and dense.displacements is None:
            dense.displacements = np.zeros((model.n_vertices, 3))
        return dense

    def with_weights(self, weights: np.ndarray) -> DenseRegion:
        """The same region with other weights (displacements shared, not copied)."""
        return DenseRegion(_checked(weights, len(self.weights)), self.displacements, self.listed_zero)

    def to_region(self) -> InfluenceRegion:
        """Sparse region: vertices with weight > 0 (plus those originally listed at 0 that still are)."""
        w = self.weights
        keep = w > 0
        if len(self.listed_zero):
            keep[self.listed_zero[w[self.listed_zero] == 0]] = True
        idx = np.flatnonzero(keep)
        d = None if self.displacements is None else self.displacements[idx].copy()
        return InfluenceRegion(idx, w[idx].copy(), d)

    def copy(self) -> DenseRegion:
        return DenseRegion(self.weights.copy(), None if self.displacements is None else self.displacements.copy(),
                           self.listed_zero.copy())


def _checked(weights: npt.ArrayLike, n: int) -> np.ndarray:
    w = np.asarray(weights, dtype=float)
    if w.shape != (n,):
        raise UserError(f"expected {n} weights (one per vertex), got an array of shape {w.shape}")
    return w


def _mask(ctx: PaintContext, mask: npt.ArrayLike | None, part: str | None) -> np.ndarray:
    m = ctx.part_mask(part)
    if mask is not None:
        m = m & np.asarray(mask, dtype=bool)
    return m


def clip01(w: np.ndarray) -> np.ndarray:
    """Clip into [0, 1] in place and turn −0.0 into +0.0 (so 'unchanged' can be tested bit-wise)."""
    np.clip(w, 0.0, 1.0, out=w)
    w += 0.0
    return w


# -- simple operations -------------------------------------------------------------
def invert_weights(ctx: PaintContext, weights: npt.ArrayLike, *, part: str | None = None,
                   mask: npt.ArrayLike | None = None) -> np.ndarray:
    """``1 − w`` on the vertices of ``part`` (all by default) and ``mask``; others unchanged."""
    w = _checked(weights, ctx.n_vertices).copy()
    m = _mask(ctx, mask, part)
    w[m] = 1.0 - w[m]
    return clip01(w)


def clear_weights(ctx: PaintContext, weights: npt.ArrayLike, *, part: str | None = None,
                  mask: npt.ArrayLike | None = None) -> np.ndarray:
    """Weights set to 0 on ``part`` (all by default) and ``mask``."""
    w = _checked(weights, ctx.n_vertices).copy()
    w[_mask(ctx, mask, part)] = 0.0
    return w


def smooth_weights(ctx: PaintContext, weights: npt.ArrayLike, iterations: int = 1, factor: float = 0.5, *,
                   part: str | None = None, mask: npt.ArrayLike | None = None) -> np.ndarray:
    """Blur towards the neighbours' mean: ``w ← w + factor · (mean(neighbours) − w)``, ``iterations`` times.

    Only vertices of ``part``/``mask`` change (their neighbours outside are
    read, not written).
    """
    if not 0 <= factor <= 1:
        raise UserError(f"smoothing factor must be in [0, 1], not {factor:g}")
    w = _checked(weights, ctx.n_vertices).copy()
    m = _mask(ctx, mask, part)
    rows = np.flatnonzero(m)
    sub = ctx.neighbour_mean[rows]
    for _ in range(int(iterations)):
        w[rows] += factor * (sub @ w - w[rows])
    return clip01(w)


# -- mirror ----------------------------------------------------------------------------
def mirror_targets(ctx: PaintContext, direction: str = LEFT_TO_RIGHT) -> tuple[np.ndarray, np.ndarray]:
    """(target, source) vertex pairs for copying one side onto the other.

    ``left_to_right`` copies the subject's left (+X) onto the right (−X).
    Vertices on the plane and unmatched vertices are left out.
    """
    if direction not in (LEFT_TO_RIGHT, RIGHT_TO_LEFT):
        raise UserError(f"mirror direction must be '{LEFT_TO_RIGHT}' or '{RIGHT_TO_LEFT}', not '{direction}'")
    mm = ctx.mirror
    x = ctx.vertices[:, 0] - mm.center
    src_side = x > 0 if direction == LEFT_TO_RIGHT else x < 0
    target = np.flatnonzero(~src_side & (mm.map >= 0))
    source = mm.map[target]
    ok = (source != target) & src_side[source]
    return target[ok], source[ok]


def mirror_weights(ctx: PaintContext, weights: npt.ArrayLike, direction: str = LEFT_TO_RIGHT) -> np.ndarray:
    """Weights with one side copied onto the other through the mirror map (see :func:`mirror_targets`)."""
    w = _checked(weights, ctx.n_vertices).copy()
    target, source = mirror_targets(ctx, direction)
    w[target] = w[source]
    return w


def mirror_region(ctx: PaintContext, dense: DenseRegion, direction: str = LEFT_TO_RIGHT) -> DenseRegion:
    """A dense region mirrored side to side; a field's displacements are reflected too (x negated)."""
    out = dense.copy()
    target, source = mirror_targets(ctx, direction)
    out.weights[target] = dense.weights[source]
    if out.displacements is not None and dense.displacements is not None:
        out.displacements[target] = mirrored_vectors(dense.displacements[source])
    return out


# -- grow / shrink ---------------------------------------------------------------------
def _neighbour_stats(ctx: PaintContext, w: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For each vertex in ``rows``: the mean of its neighbours' non-zero weights, and their count."""
    counts = ctx.degree[rows]
    total = int(counts.sum())
    offsets = np.repeat(ctx.indptr[rows] - np.cumsum(counts) + counts, counts) + np.arange(total)
    owner = np.repeat(np.arange(len(rows)), counts)
    nw = w[ctx.indices[offsets]]
    on = nw > 0
    n_on = np.bincount(owner[on], minlength=len(rows))
    s = np.bincount(owner[on], weights=nw[on], minlength=len(rows))
    return np.divide(s, n_on, out=np.zeros(len(rows)), where=n_on > 0), n_on


def grow_weights(ctx: PaintContext, weights: npt.ArrayLike, rings: int = 1, *, distance: float | None = None,
                 value: float | None = None, part: str | None = None, mask: npt.ArrayLike | None = None) -> np.ndarray:
    """Extend the region (weight > 0) by ``rings`` rings of neighbours, or by geodesic ``distance`` mm.

    Existing weights are not changed. A new vertex takes ``value`` if given,
    else the mean of its region neighbours (ring by ring) or the weight of
    the nearest region vertex over the surface (by distance), so the edge
    of the region moves out with its weights. Only vertices of
    ``part``/``mask`` are added.
    """
    w = _checked(weights, ctx.n_vertices).copy()
    allowed = _mask(ctx, mask, part)
    if value is not None and not 0 <= value <= 1:
        raise UserError(f"grow value must be in [0, 1], not {value:g}")
    if distance is not None:
        inside = np.flatnonzero(w > 0)
        if len(inside) == 0 or distance <= 0:
            return w
        from scipy.sparse import csgraph  # imported when needed: 0.2 s at launch
        dist, _, source = csgraph.dijkstra(ctx.adjacency, directed=False, indices=inside, limit=float(distance),
                                           min_only=True, return_predecessors=True)
        new = np.flatnonzero((w == 0) & allowed & np.isfinite(dist) & (source >= 0))
        w[new] = value if value is not None else w[source[new]]
        return w
    for _ in range(int(rings)):
        outside = np.flatnonzero((w == 0) & allowed)
        mean, n_on = _neighbour_stats(ctx, w, outside)
        grow = n_on > 0
        if not grow.any():
            break
        w[outside[grow]] = value if value is not None else mean[grow]
    return w


def shrink_weights(ctx: PaintContext, weights: npt.ArrayLike, rings: int = 1, *, distance: float | None = None,
                   part: str | None = None, mask: npt.ArrayLike | None = None) -> np.ndarray:
    """Pull the region's edge in: zero the region vertices within ``rings`` rings (or ``distance`` mm over
    the surface) of a vertex outside it. Only vertices of ``part``/``mask`` change."""
    w = _checked(weights, ctx.n_vertices).copy()
    allowed = _mask(ctx, mask, part)
    outside = w == 0
    if distance is not None:
        src = np.flatnonzero(outside)
        if len(src) == 0 or distance <= 0:
            return w
        from scipy.sparse import csgraph  # imported when needed: 0.2 s at launch
        dist = csgraph.dijkstra(ctx.adjacency, directed=False, indices=src, limit=float(distance), min_only=True)
        w[(w > 0) & allowed & (dist <= distance)] = 0.0
        return w
    for _ in range(int(rings)):
        inside = np.flatnonzero((w > 0) & allowed)
        _, n_in = _neighbour_stats(ctx, (w == 0).astype(float), inside)   # neighbours outside the region
        edge = inside[n_in > 0]
        if len(edge) == 0:
            break
        w[edge] = 0.0
    return w


# -- normalisation of group 1 ------------------------------------------------------------
def group1_names(model: Model) -> list[str]:
    """The non-leaf (group-1, rigid) parameters, in tree order."""
    tree = model.parameters
    return [n for n in tree.names if tree.group(n) == 1]


def normalise_stack(W: np.ndarray, keep: int | None = None) -> np.ndarray:
    """Columns of a (K, N) weight stack scaled to sum to 1 wherever they sum to more than 0.

    With ``keep`` (a row), that row's weights stay as they are and the other
    rows share the rest (``1 − w_keep``) in their current proportions; where
    the others are all 0 the kept row becomes 1 (it is the vertex's only rigid
    influence).
    """
    W = np.array(W, dtype=float, copy=True)
    if W.ndim != 2:
        raise UserError("normalise a (parameters × vertices) weight stack")
    if keep is None:
        s = W.sum(axis=0)
        np.divide(W, s, out=W, where=s > 0)
        return np.clip(W, 0.0, 1.0, out=W)
    k = W[keep].copy()
    others = np.delete(np.arange(len(W)), keep)
    s = W[others].sum(axis=0)
    scale = np.divide(1.0 - k, s, out=np.zeros_like(s), where=s > 0)
    W[others] *= scale
    W[keep] = np.where((s == 0) & (k > 0), 1.0, k)
    return np.clip(W, 0.0, 1.0, out=W)


def normalise_group1(model: Model, keep: str | None = None,
                     weights: dict[str, npt.ArrayLike] | None = None) -> dict[str, InfluenceRegion]:
    """New regions for every group-1 parameter with weights summing to 1 per vertex (where any).

    The engine normalises group-1 weights itself when it deforms (§2.2);
    this makes the stored weights say what the engine does, so what the
    painter sees is what moves. ``keep`` names a group-1 parameter whose
    weights are held (the one being painted, like Blender's auto-normalise);
    ``weights`` optionally gives dense arrays to use instead of the model's
    regions for some parameters (e.g. the one being painted, not yet stored).
    Regions keep their listed vertices; only weights change.
    """
    names = group1_names(model)
    if keep is not None and keep not in names:
        raise UserError(f"'{keep}' is not a group-1 (non-leaf) parameter, so its weights are not normalised")
    n = model.n_vertices
    weights = dict(weights or {})
    W = np.zeros((len(names), n))
    for k, name in enumerate(names):
        W[k] = _checked(weights[name], n) if name in weights else model.regions[name].dense(n)
    W = normalise_stack(W, None if keep is None else names.index(keep))
    out = {}
    for k, name in enumerate(names):
        if name in weights:
            listed_zero = model.regions[name].indices[model.regions[name].weights == 0]
            out[name] = DenseRegion(W[k], None, listed_zero).to_region()
        else:
            r = model.regions[name]
            out[name] = InfluenceRegion(r.indices.copy(), W[k][r.indices], None)
    return out
