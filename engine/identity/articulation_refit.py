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
from scipy import sparse

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
PLAIN_CLOSURE = dict(nodes=13, iterations=3, steps=12, local_rounds=0)
# Where the plain fit leaves the lips apart along the middle of the mouth (lips that already meet near the
# middle at rest, as a wide mouth's do, leave the lift little room between the nodes), a closer fit (more
# rounds; sections between the nodes lowered locally instead of the whole closure) is kept if the lips
# cross nowhere across the mouth with it, alone or with another lip field.
CLOSER_CLOSURE = dict(nodes=13, iterations=5, steps=12, local_rounds=3)
MIDDLE_GAP = 0.5        # mm: the largest lip gap along the middle half of the mouth the plain fit may leave


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
    whole_mouth = LipContact(head.vertices, triangles, is_skin, share, lm)      # the checks' span, not the fit's
    adjacency = vertex_adjacency(head.polygons(), n)
    try:
        fields = _fit_fields(head, contact, region, forward, adjacency, PLAIN_CLOSURE)
        if _middle_gap(whole_mouth, head.vertices + fields[CLOSURE]) > MIDDLE_GAP:
            closer = _fit_fields(head, contact, region, forward, adjacency, CLOSER_CLOSURE)
            closed = head.vertices + closer[CLOSURE]
            if all(whole_mouth.clear(closed + (F if name != CLOSURE else 0.0), 0.0, SECTIONS)
                   for name, F in closer.items()):
                fields = closer
    except LipContactError:
        return False
    for name, field in fields.items():
        rounded = np.round(field, 4)
        moved = np.flatnonzero(np.abs(rounded).max(axis=1) > 0)
        head.regions[name] = InfluenceRegion(moved, np.ones(len(moved)), rounded[moved])
    head.changed()
    return True


def _fit_fields(head: Model, contact: LipContact, region: np.ndarray, forward: float,
                adjacency: sparse.csr_matrix, settings: dict[str, int]) -> dict[str, np.ndarray]:
    """The closure fitted with ``settings``, and the other lip fields kept off the lips it closes."""
    closure, _ = fit_closure(contact, region, forward, CLEARANCE, **settings)
    lower_side = (head.vertex_part == head.parts.index("skin")) & ~contact.upper_vertex
    companions = [np.zeros_like(closure), closure]
    fields = {CLOSURE: closure}
    for name in KEPT_APART:
        F = _dense_field(head, name)
        if name == "lip_protrude":
            F = follow_upper_lip(contact, F, head.vertices + closure)
        fields[name], _ = keep_lips_apart(contact, F, CLEARANCE, companions, adjacency, lower_side,
                                          sections=SECTIONS)
    return fields


def _middle_gap(contact: LipContact, P: np.ndarray, sections: int = SECTIONS) -> float:
    """The largest distance between the lips of ``P`` in sections across the middle half of the mouth."""
    half = contact.half_width(P)
    gaps = [contact.distance(*contact.section(P, x)) for x in np.linspace(-0.5, 0.5, sections) * half + 1e-4]
    return max((g for g in gaps if np.isfinite(g)), default=0.0)


def _dense_field(model: Model, name: str) -> np.ndarray:
    region = model.regions[name]
    F = np.zeros((model.n_vertices, 3))
    if region.displacements is not None:
        F[region.indices] = region.weights[:, None] * region.displacements
    return F
