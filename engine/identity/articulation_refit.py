"""The articulatory fields (§3.1.2) fitted again on a new face, by the default head's own procedure.

The default head's derivation makes ``lower_lip_raise`` by lifting the lower
lip section by section until it just meets the upper lip, and keeps
``mouth_widen``, ``lip_protrude`` and ``upper_lip_raise`` from pushing the
lower lip into the upper lip, alone or with the lips closed
(:mod:`engine.identity.lip_contact`). A carried-over field does neither on
lips of another shape; :func:`refit_articulation` runs the same fits on the
new face, starting from the carried-over fields (the closure's region and the
artist's shapes are the default head's, read back from its fields).
"""

from __future__ import annotations

import numpy as np

from engine.identity.lip_contact import (
    LipContact,
    LipContactError,
    fit_closure,
    follow_upper_lip,
    keep_lips_apart,
    vertex_adjacency,
)
from engine.model import InfluenceRegion, Model

CLEARANCE = 0.15        # mm left between the lips where they meet, as on the default head
CLOSURE = "lower_lip_raise"
KEPT_APART = ("mouth_widen", "lip_protrude", "upper_lip_raise")
SECTIONS = 31           # sagittal sections checked across the mouth (the derivation checks 61)


def jaw_share(model: Model) -> np.ndarray:
    """Each vertex's share of the jaw among the rigid group-1 weights (0 upper face … 1 lower jaw)."""
    n = model.n_vertices
    jaw = model.regions["jaw_open"].dense(n)
    total = sum((model.regions[name].dense(n) for name in ("jaw_open", "head_tilt", "neck_lean")
                 if name in model.regions), np.zeros(n))
    return np.divide(jaw, total, out=np.zeros(n), where=total > 0)


def refit_articulation(base: Model, head: Model) -> bool:
    """Fit ``head``'s closure and keep its lip fields apart (in place); False if its lips cross at rest."""
    names = [CLOSURE, *KEPT_APART]
    if not all(name in head.regions and head.regions[name].displacements is not None for name in names):
        return False
    n = head.n_vertices
    is_skin = head.vertex_part == head.parts.index("skin")
    lm = head.landmarks
    share, triangles = jaw_share(head), head.triangles()
    contact = LipContact(head.vertices, triangles, is_skin, share, lm)
    touch = contact.first_touch(head.vertices, CLEARANCE)
    if touch is not None:       # lips that meet nearer the middle than the default head's: check inside that
        half = contact.half_width(head.vertices)
        span = (touch - 1.0) / half
        if span < 0.3:
            return False
        contact = LipContact(head.vertices, triangles, is_skin, share, lm, span=span, touching_from=touch)
    base_forward = float(base.vertices[lm["2.2"], 2] - base.vertices[lm["2.3"], 2])
    if abs(base_forward) < 1e-6:
        return False
    region = np.clip(_dense_field(base, CLOSURE)[:, 2] / base_forward, 0.0, 1.0)   # z = region · forward
    forward = float(head.vertices[lm["2.2"], 2] - head.vertices[lm["2.3"], 2])
    try:
        closure, _ = fit_closure(contact, region, forward, CLEARANCE, nodes=13, iterations=3, steps=12)
        adjacency = vertex_adjacency(head.polygons(), n)
        lower_side = is_skin & ~contact.upper_vertex
        companions = [np.zeros_like(closure), closure]
        fields = {CLOSURE: closure}
        for name in KEPT_APART:
            F = _dense_field(head, name)
            if name == "lip_protrude":
                F = follow_upper_lip(contact, F, head.vertices + closure)
            fields[name], _ = keep_lips_apart(contact, F, CLEARANCE, companions, adjacency, lower_side,
                                              sections=SECTIONS)
    except LipContactError:
        return False
    for name, field in fields.items():
        rounded = np.round(field, 4)
        moved = np.flatnonzero(np.abs(rounded).max(axis=1) > 0)
        head.regions[name] = InfluenceRegion(moved, np.ones(len(moved)), rounded[moved])
    head.changed()
    return True


def _dense_field(model: Model, name: str) -> np.ndarray:
    region = model.regions[name]
    F = np.zeros((model.n_vertices, 3))
    if region.displacements is not None:
        F[region.indices] = region.weights[:, None] * region.displacements
    return F
