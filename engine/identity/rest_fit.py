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

import itertools
from collections.abc import Iterator

import numpy as np

from engine.identity.carry_over import Similarity
from engine.identity.lip_contact import LipContact
from engine.model import InfluenceRegion, Model

FRONT_MM = 3.0       # lid vertices more than this far in front of the eye's centre
NEAR_MM = 4.0        # … and at most this far outside the eyeball at rest


def keep_rest_lip_gap(base: Model, D: np.ndarray) -> np.ndarray:
    """``D`` with the lower lip near the mouth line moving as the upper lip above it does.

    The lips keep the default head's rest opening along the whole mouth (the
    lower lip takes the motion of its nearest upper-lip vertices at the mouth
    line, fading to its own motion 4.5 mm below it), so the articulatory
    fields, fitted to that opening, close and open the new mouth as they do
    the default head's.
    """
    from engine.identity.lip_contact import follow_upper_lip

    if not {"2.2", "2.3", "8.3", "8.4"} <= set(base.landmarks) or "jaw_open" not in base.regions:
        return D
    lm = base.landmarks
    contact = _lip_contact(base)
    D = D + mirror_symmetric(base.vertices, follow_upper_lip(contact, D, base.vertices) - D)
    # and exactly the default head's offset between the inner lip midpoints, the lower lip's whole
    # closing region carrying the correction (it is a fraction of a millimetre)
    region = base.regions.get("lower_lip_raise")
    if region is not None and region.displacements is not None:
        at_mid = np.flatnonzero(region.indices == lm["2.3"])
        if len(at_mid):
            size = np.linalg.norm(region.displacements, axis=1)
            weight = np.clip(size / size[at_mid[0]], 0.0, 1.0)
            want = base.vertices[lm["2.3"]] - base.vertices[lm["2.2"]]
            have = (base.vertices + D)[lm["2.3"]] - (base.vertices + D)[lm["2.2"]]
            D = D.copy()
            D[region.indices] += weight[:, None] * (want - have)[None]
    return D


def keep_mouth_bag_inside(base: Model, D: np.ndarray, neighbours: int = 8, behind_mm: float = 3.0) -> np.ndarray:
    """``D`` with the skin inside the mouth moving as the face skin nearest it does.

    MakeHuman's targets move the mouth's inner lining on their own; on a thin
    face the cheeks come in further than the lining, and a smile pulls the
    corners back through it (seen as red spots at the corners). Moved with the
    skin around it, the lining keeps the default head's distance behind it.
    The lips' own inner faces (within ``behind_mm`` of the rim) keep their motion.
    """
    from scipy.spatial import cKDTree

    if "skin" not in base.parts or "2.2" not in base.landmarks:
        return D
    bag, depth = _mouth_bag(base)
    is_skin = base.vertex_part == base.parts.index("skin")
    outside = np.flatnonzero(is_skin & ~np.isin(np.arange(base.n_vertices), bag))
    bag = bag[depth > behind_mm]
    if not len(bag):
        return D
    dist, near = cKDTree(base.vertices[outside]).query(base.vertices[bag], k=neighbours)
    w = 1.0 / np.maximum(dist, 1e-6) ** 2
    D = D.copy()
    D[bag] = np.einsum("mk,mkd->md", w / w.sum(axis=1, keepdims=True), D[outside[near]])
    return D


# Fields that pull the lips' corners or the cheeks off the lining (a smile, a sneer). The lip-contact
# fields (the articulation's, AU17/23/24) shape the lips' inner faces themselves and are left alone.
LINED_FIELDS = ("AU9_left_nose", "AU9_right_nose", "AU12_left", "AU12_right")


def line_fields_with_the_skin(base: Model, head: Model, neighbours: int = 8, behind_mm: float = 1.0,
                              names: tuple[str, ...] = LINED_FIELDS) -> None:
    """``head``'s blendshape fields with the mouth's lining moving as the face skin nearest it does (in place).

    A carried-over field moves the lining as it moved the default head's,
    but an identity's lining sits elsewhere behind its corners; a smile
    (AU12) then pulled the corners away from the lining and it showed through
    as red spots (seen on fuller lips). Only the lips' red edge within
    ``behind_mm`` of the rim keeps its own motion. Only the fields in
    ``names`` change, and only the displacements of the lining vertices
    already in their regions (regions and weights stay the default head's).
    """
    from scipy.spatial import cKDTree

    if "skin" not in base.parts or "2.2" not in base.landmarks:
        return
    bag, depth = _mouth_bag(base)
    is_skin = head.vertex_part == head.parts.index("skin")
    outside = np.flatnonzero(is_skin & ~np.isin(np.arange(head.n_vertices), bag))
    lining = bag[depth > behind_mm]
    if not len(lining):
        return
    dist, near = cKDTree(head.vertices[outside]).query(head.vertices[lining], k=neighbours)
    w = 1.0 / np.maximum(dist, 1e-6) ** 2
    w /= w.sum(axis=1, keepdims=True)
    row_of = np.full(head.n_vertices, -1)
    row_of[lining] = np.arange(len(lining))
    for p in head.parameters:
        region = head.regions[p.name]
        if p.name not in names or not p.field or region.displacements is None:
            continue
        F = np.zeros((head.n_vertices, 3))
        F[region.indices] = region.weights[:, None] * region.displacements
        followed = np.einsum("mk,mkd->md", w, F[outside[near]])
        # the region's vertices and weights stay (an unedited rig stays the default head's): only the
        # displacements of the lining it already moves change
        at = np.flatnonzero(np.isin(region.indices, lining) & (region.weights > 0))
        displacements = region.displacements.copy()
        displacements[at] = followed[row_of[region.indices[at]]] / region.weights[at, None]
        head.regions[p.name] = InfluenceRegion(region.indices.copy(), region.weights.copy(), displacements)
    head.changed()


_BAGS: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}


def _mouth_bag(model: Model) -> tuple[np.ndarray, np.ndarray]:
    from engine.identity.mouth_bag import oral_cavity

    key = (id(model), model.revision)
    if key not in _BAGS:
        is_skin = model.vertex_part == model.parts.index("skin")
        _BAGS.clear()
        _BAGS[key] = oral_cavity(model.vertices, model.polygons(), is_skin, model.landmarks["2.2"])
    return _BAGS[key]


def eyeballs(model: Model) -> Iterator[tuple[str, np.ndarray, np.ndarray]]:
    """(side, the eyeball's vertices, its centre) for each eyeball the model has."""
    for side in ("left", "right"):
        if f"eye_{side}" in model.parts:
            yield side, model.part_vertices(f"eye_{side}"), eye_centre(model, side)


def eye_centre(model: Model, side: str) -> np.ndarray:
    """The centre of an eyeball: its gaze pivot where the model has one, else its vertices' mean."""
    name = f"eye_{side}_turn"
    if name in model.regions:
        return np.asarray(model.parameters[name].pivot, dtype=float)
    return np.asarray(model.vertices[model.part_vertices(f"eye_{side}")].mean(axis=0))


_CONTACTS: dict[tuple[int, int], object] = {}


def _lip_contact(model: Model) -> LipContact:
    """The lip contact of ``model``'s rest mesh (remembered for the last model and revision asked)."""
    from engine.identity.articulation_refit import jaw_share
    from engine.identity.lip_contact import LipContact

    key = (id(model), model.revision)
    found = _CONTACTS.get(key)
    if not isinstance(found, LipContact) or found.rest is not model.vertices:
        is_skin = model.vertex_part == model.parts.index("skin")
        found = LipContact(model.vertices, model.triangles(), is_skin, jaw_share(model), model.landmarks)
        _CONTACTS.clear()
        _CONTACTS[key] = found
    return found


def mirror_symmetric(rest: np.ndarray, change: np.ndarray) -> np.ndarray:
    """``change`` made left–right symmetric where the rest mesh is (x ↦ −x), so the midline stays on it."""
    from scipy.spatial import cKDTree

    mirrored = rest * np.array([-1.0, 1.0, 1.0])
    dist, partner = cKDTree(rest).query(mirrored)
    paired = dist < 1e-6
    flip = np.array([-1.0, 1.0, 1.0])
    out = change.copy()
    out[paired] = (change[paired] + change[partner[paired]] * flip) / 2
    return out


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
        centre = eye_centre(base, part.removeprefix("eye_"))
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
    for _side, eye, centre in eyeballs(head):
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


REACH_MM = 8.0             # lid skin further than this from the eyeball cannot be brought into it
LID_ALLOWANCE_MM = 0.03     # how far a lid pose may enter the eyeball (the default head's blink: 0.04 mm)


def keep_lids_off_the_eyes(head: Model, largest_combination: int = 3, rounds: int = 6) -> None:
    """Shrink an eyeball (about its centre) until no lid pose carries the lid skin in front of it inside it.

    The poses are the leaves that move that skin, at their maximum, alone and
    in combinations of up to ``largest_combination`` (a blink with a lid
    tightener, a cheek raiser with a smile); leaves superpose in the rest
    frame (§2.2, invariant 4), so a combination's motion is the sum of its
    members'. Skin that a smaller eyeball leaves outside is checked again.
    On the default head these poses enter at most 0.04 mm.
    """
    for side, eye, centre in eyeballs(head):
        lid_parts = [head.parts.index(p) for p in ("skin", f"eyelashes_{side}") if p in head.parts]
        lids = np.flatnonzero(np.isin(head.vertex_part, lid_parts))
        lids = lids[head.vertices[lids, 2] > centre[2] + FRONT_MM]
        for _ in range(rounds):
            radius = float(np.linalg.norm(head.vertices[eye] - centre, axis=1).max())
            clearance = np.linalg.norm(head.vertices[lids] - centre, axis=1) - radius
            near = lids[(clearance > 0) & (clearance < REACH_MM)]
            moving = [p.name for p in head.parameters if head.parameters.group(p.name) == 2
                      and p.maximum > 0 and np.isin(head.regions[p.name].indices, near).any()]
            if not moving:
                break
            single = np.array([head.deform({a: head.parameters[a].maximum})[near] - head.vertices[near]
                               for a in moving])
            worst = 0.0
            for size in range(1, min(largest_combination, len(moving)) + 1):
                for combination in itertools.combinations(range(len(moving)), size):
                    posed = head.vertices[near] + single[list(combination)].sum(axis=0)
                    worst = max(worst, radius - float(np.linalg.norm(posed - centre, axis=1).min()))
            if worst <= LID_ALLOWANCE_MM:
                break
            scale = (radius - (worst - LID_ALLOWANCE_MM) - 0.01) / radius
            head.vertices[eye] = centre + (head.vertices[eye] - centre) * scale
            head.changed()
