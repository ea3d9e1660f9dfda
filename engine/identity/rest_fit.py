"""Two corrections of a new face's rest shape, so its rig works as on the default head.

MakeHuman's shape targets were made on a face whose lips meet; the default
head's lips rest slightly apart and its rig was fitted so, and its eyelids
clear its eyeballs by a fitted margin. A new identity can bring the lower lip
up against (or through) the upper lip, or grow the eyeball into the lids.

* :func:`keep_rest_lip_gap` moves the lower lip (the closure field's own
  region, so the corners follow as when the lips close) so that the inner lip
  midpoints 2.2/2.3 keep the default head's offset;
* :func:`keep_eyelid_clearance` shrinks each eyeball about its centre until
  the lid skin in front of it is as far from it as on the default head.
"""

from __future__ import annotations

import numpy as np

from engine.identity.carry_over import Similarity
from engine.model import Model

FRONT_MM = 3.0       # lid vertices more than this far in front of the eye's centre
NEAR_MM = 4.0        # … and at most this far outside the eyeball at rest


def keep_rest_lip_gap(base: Model, D: np.ndarray, name: str = "lower_lip_raise") -> np.ndarray:
    """``D`` with the lower lip moved so the rest offset 2.3 − 2.2 equals the default head's."""
    if name not in base.regions or base.regions[name].displacements is None:
        return D
    lm = base.landmarks
    region = base.regions[name]
    idx = region.indices
    field = np.asarray(region.displacements)
    at_mid = np.flatnonzero(idx == lm["2.3"])
    if not len(at_mid):
        return D
    weight = np.clip(np.linalg.norm(field, axis=1) / np.linalg.norm(field[at_mid[0]]), 0.0, 1.0)
    moved = base.vertices + D
    want = base.vertices[lm["2.3"]] - base.vertices[lm["2.2"]]
    have = moved[lm["2.3"]] - moved[lm["2.2"]]
    D = D.copy()
    D[idx] += weight[:, None] * (want - have)[None]
    return D


def keep_eyelid_clearance(base: Model, D: np.ndarray, eyes: dict[str, Similarity]) -> dict[str, Similarity]:
    """The eyes' motions, each eyeball made smaller where needed so the lids clear it as on the default head."""
    out = dict(eyes)
    moved = base.vertices + D
    lid_parts = [base.parts.index(p) for p in base.parts if p == "skin" or p.startswith("eyelashes")]
    lids = np.flatnonzero(np.isin(base.vertex_part, lid_parts))
    for part, move in eyes.items():
        if part not in base.parts:
            continue
        eye = base.part_vertices(part)
        centre = base.vertices[eye].mean(axis=0)
        radius = np.linalg.norm(base.vertices[eye] - centre, axis=1).max()
        clear0 = np.linalg.norm(base.vertices[lids] - centre, axis=1) - radius
        front = lids[(base.vertices[lids, 2] > centre[2] + FRONT_MM) & (clear0 > 0) & (clear0 < NEAR_MM)]
        if not len(front):
            continue
        before = np.linalg.norm(base.vertices[front] - centre, axis=1) - radius
        new_centre = move.point(centre)
        after = np.linalg.norm(moved[front] - new_centre, axis=1) - move.scale * radius
        short = float(np.max(before - after))
        if short > 0:
            scale = move.scale * (1.0 - short / (move.scale * radius))
            out[part] = Similarity(scale, move.rotation, move.centre, move.new_centre)
    return out


def refit_eyelid_angles(base: Model, head: Model) -> None:
    """Scale each eyelid's closing angle so that at value 1 the upper lid reaches the lower lid, as on ``base``.

    The angle needed is the angle, about the lid's axis, between the upper
    and lower lid midpoints (3.1/3.3 left, 3.2/3.4 right) seen from its pivot.
    """
    for side, (upper, lower) in (("left", ("3.1", "3.3")), ("right", ("3.2", "3.4"))):
        name = f"eyelid_{side}_close"
        if name not in head.regions or not {upper, lower} <= set(head.landmarks):
            continue
        before = _opening(base, name, upper, lower)
        after = _opening(head, name, upper, lower)
        if before > 1e-6 and after > 1e-6:
            p = head.parameters[name]
            p.degrees_per_unit = p.degrees_per_unit * after / before
    head.changed()


def _opening(model: Model, name: str, upper: str, lower: str) -> float:
    """The angle (degrees) about ``name``'s axis from the upper to the lower lid midpoint."""
    p = model.parameters[name]
    a = model.vertices[model.landmarks[upper]] - p.pivot
    b = model.vertices[model.landmarks[lower]] - p.pivot
    a = a - np.dot(a, p.axis) * p.axis
    b = b - np.dot(b, p.axis) * p.axis
    return float(np.degrees(np.arctan2(np.dot(np.cross(a, b), p.axis), np.dot(a, b))))


def keep_fields_off_the_eyes(head: Model) -> None:
    """Where a displacement field would carry lid skin in front of an eyeball into it, stop it at the surface."""
    for side in ("left", "right"):
        part = f"eye_{side}"
        if part not in head.parts:
            continue
        eye = head.part_vertices(part)
        centre = head.vertices[eye].mean(axis=0)
        radius = np.linalg.norm(head.vertices[eye] - centre, axis=1).max()
        for p in head.parameters:
            region = head.regions[p.name]
            if not p.field or region.displacements is None or not len(region.indices):
                continue
            P = head.vertices[region.indices]
            rest = np.linalg.norm(P - centre, axis=1)
            front = (P[:, 2] > centre[2] + FRONT_MM) & (rest > radius)
            if not front.any():
                continue
            D = np.array(region.displacements, dtype=float)
            for value in (p.maximum, p.minimum):
                Q = P + value * D
                dist = np.linalg.norm(Q - centre, axis=1)
                inside = front & (dist < radius) & (value != 0)
                if inside.any():
                    target = centre + (Q[inside] - centre) * (radius / dist[inside])[:, None]
                    D[inside] = (target - P[inside]) / value
            region.displacements = D
    head.changed()
