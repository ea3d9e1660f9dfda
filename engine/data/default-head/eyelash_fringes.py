"""Eyelashes as thin dark fringes on the lid margins, moving with the lids.

A stage of ``derive_default_head.py``. MakeHuman's lash cards are long flat
strips made for a transparent texture; drawn opaque and merely shortened
towards the eyeball, the lower ones stuck out of the skin below the lid as
black shards and the upper one floated above the lid, where it crossed the
iris when the lid tightener (AU7) lifted the lid under it. Here each card
is laid onto its lid instead:

* the lid margin is the skin's edge loop through the upper lid's margin
  above the pupil (landmark 3.1 / 3.2), where the lid meets the eyeball;
  its two arcs between the eye corners are the upper and lower lid
  (:func:`lid_margins`), and the lashes grow from the lid's front edge
  before them (:func:`front_margin`);
* every lash vertex gets a *root* on its lid's margin, at its own angle
  about the eyeball centre (two neighbouring margin vertices and a blend,
  :func:`lash_roots`), and sits on the line from that root outwards, as far
  along it as it was along its card (:func:`lay_lashes`): the upper lashes
  :data:`UPPER_LENGTH_MM` long, the lower :data:`LOWER_LENGTH_MM`;
* the lashes move exactly as their roots do: in the artist's poses (their
  displacement is their root's) and in the rig, where each lash vertex takes
  its root's weight in every rotation and translation
  (:func:`attach_lashes`), so a blink, AU5, AU6 or AU7 carries them with the
  lid margin and they never leave it (a displacement field is the artist's
  pose at every vertex, so its lashes already follow their roots).

Lengths are mm.

>>> import numpy as np
>>> angle_about(np.array([[1.0, 1.0, 5.0]]), np.zeros(3)).round(3).tolist()
[0.785]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from mouth_interior import edge_loop

UPPER_LENGTH_MM = 1.9
LOWER_LENGTH_MM = 1.3
ROOT_OUT_MM = 0.5          # the root sits this far out of the lid margin (radially), on its skin
CURL = 0.6                  # how much the lashes turn up (upper) or down (lower) besides pointing out
FORWARD = 0.5               # and how much forward (+Z), clear of the lid's skin above (below) them
CARD_SPAN_DEGREES = 6.0     # a lash vertex's "along the card" is judged among card vertices this close in angle


@dataclass
class LashRoots:
    """Where each lash vertex hangs on its lid margin: between margin vertices ``a`` and ``b``, at ``t``."""

    lashes: np.ndarray
    a: np.ndarray
    b: np.ndarray
    t: np.ndarray

    def blend(self, values: np.ndarray) -> np.ndarray:
        """A per-vertex quantity (weights, displacements) at the roots."""
        t = self.t.reshape((-1,) + (1,) * (values.ndim - 1))
        return (1 - t) * values[self.a] + t * values[self.b]


def angle_about(points: np.ndarray, centre: np.ndarray) -> np.ndarray:
    """Angle (radians) of points about a centre in the frontal (x, y) plane."""
    return np.arctan2(points[:, 1] - centre[1], points[:, 0] - centre[0])


def lid_margins(vertices, polygons, is_skin, upper_margin: int, centre) -> tuple[np.ndarray, np.ndarray]:
    """(upper arc, lower arc) of the lid margin around one eye, each ordered by angle about the centre."""
    skin_polygons = [p for p in polygons if is_skin[p].all()]
    beside = sorted({int(p[(list(p).index(upper_margin) + k) % len(p)])
                     for p in skin_polygons if upper_margin in p for k in (-1, 1)})
    # the margin runs sideways from 3.1: of its neighbours, the one at nearly the same height
    first = min(beside, key=lambda v: abs(vertices[v, 1] - vertices[upper_margin, 1])
                - abs(vertices[v, 0] - vertices[upper_margin, 0]))
    loop = np.array(edge_loop(skin_polygons, upper_margin, first))
    x = vertices[loop, 0]
    i, j = sorted((int(np.argmin(x)), int(np.argmax(x))))
    arcs = [loop[i:j + 1], np.concatenate([loop[j:], loop[:i + 1]])]
    upper = max(arcs, key=lambda arc: vertices[arc, 1].mean())
    lower = min(arcs, key=lambda arc: vertices[arc, 1].mean())
    order = lambda arc: arc[np.argsort(np.unwrap(angle_about(vertices[arc], centre)))]  # noqa: E731
    return order(upper), order(lower)


def front_margin(vertices, polygons, is_skin, arc, up: float, reach: float = 2.5, rings: int = 4) -> np.ndarray:
    """For each vertex of a lid's margin loop (where the lid meets the eyeball), the vertex on the front
    edge of the lid in front of it: of the skin within ``rings`` edges of the loop, ``reach`` mm of it
    in the frontal plane and on the lid's side (``up`` +1 upper, −1 lower), the most forward one."""
    n = len(vertices)
    neighbours = [set() for _ in range(n)]
    for p in polygons:
        if is_skin[p].all():
            for i in range(len(p)):
                a, b = int(p[i]), int(p[(i + 1) % len(p)])
                neighbours[a].add(b)
                neighbours[b].add(a)
    zone = {int(v) for v in arc}
    ring = set(zone)
    for _ in range(rings):
        ring = {u for v in ring for u in neighbours[v]} - zone
        zone |= ring
    lid = np.array(sorted(zone))
    front = []
    for v in arc:
        near = lid[(np.linalg.norm(vertices[lid, :2] - vertices[v, :2], axis=1) < reach)
                   & (up * (vertices[lid, 1] - vertices[v, 1]) > -0.3)]
        front.append(near[np.argmax(vertices[near, 2])])
    return np.array(front)


def lash_roots(vertices, lashes, arc, front, centre) -> LashRoots:
    """Each lash vertex's root on the lid's front edge (``front``, one per vertex of the margin ``arc``),
    at the lash's own angle about the eyeball centre along the arc (clamped to its ends)."""
    arc_angle = np.unwrap(angle_about(vertices[arc], centre))
    lash_angle = angle_about(vertices[lashes], centre)
    lash_angle = lash_angle + 2 * np.pi * np.round((arc_angle.mean() - lash_angle) / (2 * np.pi))
    k = np.clip(np.searchsorted(arc_angle, lash_angle) - 1, 0, len(arc) - 2)
    t = np.clip((lash_angle - arc_angle[k]) / (arc_angle[k + 1] - arc_angle[k]), 0.0, 1.0)
    return LashRoots(np.asarray(lashes), front[k], front[k + 1], t)


def lay_lashes(vertices, made, roots: LashRoots, centre, length: float, up: float) -> None:
    """Place the lash vertices on the lines out of their roots, in place.

    ``made`` are MakeHuman's card positions: a vertex's share of the way from
    the card's root edge to its tip (radially, among card vertices at about
    its angle) is its share of ``length``; ``up`` is +1 for upper lashes, −1
    for lower ones.
    """
    card = made[roots.lashes]
    radius = np.linalg.norm(card - centre, axis=1)
    angle = angle_about(card, centre)
    along = np.zeros(len(card))
    for k in range(len(card)):
        near = np.abs(np.angle(np.exp(1j * (angle - angle[k])))) < np.radians(CARD_SPAN_DEGREES)
        lo, hi = radius[near].min(), radius[near].max()
        along[k] = (radius[k] - lo) / (hi - lo) if hi > lo + 1e-6 else 0.0
    root = roots.blend(vertices)
    out = root - centre
    out /= np.linalg.norm(out, axis=1)[:, None]
    direction = out + CURL * up * np.array([0.0, 1.0, 0.0]) + FORWARD * np.array([0.0, 0.0, 1.0])
    direction /= np.linalg.norm(direction, axis=1)[:, None]
    vertices[roots.lashes] = root + ROOT_OUT_MM * out + (length * along)[:, None] * direction


def attach_lashes(model, all_roots: list[LashRoots]) -> None:
    """Give every lash vertex its root's weight in every rotation and translation, in place.

    Only the lash vertices' entries change. Displacement fields are left as
    they were made: a field is the artist's pose itself at every vertex, and
    the lashes' poses are already their roots' (``derive_default_head.py``).
    """
    from engine import InfluenceRegion

    n = model.n_vertices
    lashes = np.concatenate([roots.lashes for roots in all_roots])
    for p in model.parameters:
        region = model.regions[p.name]
        if region.displacements is not None:
            continue
        weights = region.dense(n)
        lash_weight = np.concatenate([roots.blend(weights) for roots in all_roots])
        keep = ~np.isin(region.indices, lashes)
        add = lash_weight > 1e-6
        model.set_region(p.name, InfluenceRegion(np.concatenate([region.indices[keep], lashes[add]]),
                                                 np.concatenate([region.weights[keep],
                                                                 np.round(lash_weight[add], 6)])))
