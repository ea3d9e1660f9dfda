"""The furrows, wrinkles and bulges that FACS names as an action unit's appearance changes, as geometry.

A stage of ``derive_default_head.py`` (through ``action_units.py``): each
function here returns an (N, 3) displacement field in mm, for both sides of
the face, that is added to the AU's pose before it is split into its left
and right parameters. FACS (Ekman, Friesen & Hager 2002) codes an AU by its
appearance — AU1 + 2 crease the forehead, AU4 furrows the skin between the
brows, AU6 bags the lower lid and draws crow's feet, AU9 wrinkles the root
of the nose, AU12 deepens the nasolabial furrow, AU17 wrinkles the chin
boss — so the AU parameter carries them: a script that raises ``AU4_left``
gets its furrow with it, at the AU's intensity.

A *crease* is a path along the mesh's own edges (the shortest path on the
skin through waypoints placed from the MPEG-4 landmarks), pushed into the
skin along its normal, deepest on the path and gone within about one ring
of neighbours; a *bulge* is a smooth push out of the skin. With skin edges
of 3–8 mm (docs/default-head.md) a crease is one line of vertices: the
geometry can hold two or three forehead lines, one glabellar furrow a side,
two lines across the root of the nose, three crow's feet, the nasolabial
furrow and the mentolabial sulcus, not fine wrinkles. Depths are at FACS
intensity E (the AU at value 1) and scale with it.

The lashes hang on the lids: where a field moves lid skin (AU6 bags and lifts
the lower lid), each lash vertex moves as the skin vertex nearest it at rest
(:meth:`Skin.carry_lashes`, which ``action_units.appearance`` applies), so
that the lower lashes stay on the lifted lid.

Waypoints are given for the subject's left side (+X) and mirrored.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
from scipy import sparse
from scipy.sparse.csgraph import dijkstra
from scipy.spatial import cKDTree

CREASE_RING_MM = 0.55   # a crease's width: its depth falls to exp(-1) this far, as a share of the local edge
FRONT = 0.0             # waypoints snap to skin whose normal faces forward at least this much (z component)


@dataclass
class Skin:
    """The rest skin as the crease functions see it: positions, unit normals, its edge graph."""

    vertices: np.ndarray
    normals: np.ndarray
    skin: np.ndarray            # indices of the skin vertices
    graph: sparse.csr_matrix    # skin edges, weighted by their length (mm)
    edge_mm: np.ndarray         # each vertex's mean edge length
    landmarks: dict[str, np.ndarray]
    eyes: dict[str, tuple[np.ndarray, float]]   # side -> the eyeball's centre and radius
    lashes: np.ndarray          # the lash vertices …
    lash_skin: np.ndarray       # … and the skin vertex nearest each at rest (on its lid)

    @classmethod
    def of(cls, model) -> Skin:
        V = model.vertices
        n = len(V)
        is_skin = model.vertex_part == model.parts.index("skin")
        tri = model.triangles()
        tri = tri[is_skin[tri].all(axis=1)]
        cross = np.cross(V[tri[:, 1]] - V[tri[:, 0]], V[tri[:, 2]] - V[tri[:, 0]])
        normals = np.zeros((n, 3))
        for k in range(3):
            np.add.at(normals, tri[:, k], cross)
        length = np.linalg.norm(normals, axis=1, keepdims=True)
        normals = np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)
        edges = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
        edges = np.unique(np.sort(edges, axis=1), axis=0)
        # quads are split into triangles: drop the diagonals, so that paths follow the mesh's rows
        polys = [p for p in model.polygons() if is_skin[p].all()]
        sides = {tuple(sorted((int(p[i]), int(p[(i + 1) % len(p)])))) for p in polys for i in range(len(p))}
        keep = np.array([tuple(e) in sides for e in edges.tolist()])
        edges = edges[keep]
        w = np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1)
        graph = sparse.coo_matrix((np.r_[w, w], (np.r_[edges[:, 0], edges[:, 1]], np.r_[edges[:, 1], edges[:, 0]])),
                                  shape=(n, n)).tocsr()
        count = np.bincount(edges.ravel(), minlength=n)
        total = np.bincount(edges[:, 0], weights=w, minlength=n) + np.bincount(edges[:, 1], weights=w, minlength=n)
        edge_mm = np.divide(total, count, out=np.full(n, np.nan), where=count > 0)
        eyes = {}
        for side in ("left", "right"):
            centre = np.asarray(model.parameters[f"eye_{side}_turn"].pivot, dtype=float)
            eyes[side] = centre, float(np.linalg.norm(V[model.part_vertices(f"eye_{side}")] - centre, axis=1).max())
        lashes = np.flatnonzero(np.isin(model.vertex_part, [model.parts.index(p) for p in model.parts
                                                            if p.startswith("eyelashes")]))
        S = np.flatnonzero(is_skin)
        lash_skin = S[cKDTree(V[S]).query(V[lashes])[1]] if len(lashes) else lashes
        return cls(V, normals, S, graph, edge_mm, model.landmark_positions(), eyes, lashes, lash_skin)

    def carry_lashes(self, D: np.ndarray) -> np.ndarray:
        """``D`` with every lash vertex moved as the skin vertex nearest it at rest: a furrow or bulge on a
        lid carries the lashes on it (the artist's poses move them with the lid margin already)."""
        D = D.copy()
        D[self.lashes] = D[self.lash_skin]
        return D

    def lm(self, key: str) -> np.ndarray:
        return self.landmarks[key]

    def nearest(self, xy) -> int:
        """The forward-facing skin vertex nearest (x, y) in the front view, frontmost where several are close."""
        front = self.skin[self.normals[self.skin, 2] > FRONT]
        d = np.linalg.norm(self.vertices[front, :2] - np.asarray(xy, dtype=float), axis=1)
        near = d < d.min() + 1.0
        return int(front[near][np.argmax(self.vertices[front[near], 2])])

    def path(self, waypoints) -> np.ndarray:
        """Skin vertices along the shortest edge path through the (x, y) waypoints, in order."""
        stops = [self.nearest(p) for p in waypoints]
        out = [stops[0]]
        for a, b in itertools.pairwise(stops):
            _, pred = dijkstra(self.graph, indices=a, return_predecessors=True)
            leg, k = [], b
            while k != a and k >= 0:
                leg.append(k)
                k = pred[k]
            out += leg[::-1]
        return np.array(out)


def _smoothstep(t):
    t = np.clip(t, 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def _along(points: np.ndarray, path_points: np.ndarray):
    """Distance of each point to the polyline, and where along it (0 … 1 of its length) the nearest point is."""
    a, b = path_points[:-1], path_points[1:]
    ab = b - a
    seg = np.linalg.norm(ab, axis=1)
    cum = np.r_[0.0, np.cumsum(seg)]
    t = np.clip(np.einsum("mkd,kd->mk", points[:, None] - a[None], ab) / np.maximum(seg ** 2, 1e-12), 0, 1)
    closest = a[None] + t[..., None] * ab[None]
    d = np.linalg.norm(points[:, None] - closest, axis=2)
    k = np.argmin(d, axis=1)
    rows = np.arange(len(points))
    s = (cum[k] + t[rows, k] * seg[k]) / max(cum[-1], 1e-12)
    return d[rows, k], s


def crease(skin: Skin, waypoints, depth: float, weight=None, ends: float = 0.15) -> np.ndarray:
    """A furrow ``depth`` mm deep along the skin's edge path through ``waypoints`` ((x, y) mm, front view).

    ``weight(P)``: the depth's share at the rest positions ``P`` (default 1), on top of which the
    furrow fades in and out over ``ends`` of its length.
    """
    path = skin.path(waypoints)
    P = skin.vertices[path]
    out = np.zeros_like(skin.vertices)
    near = skin.skin[np.linalg.norm(skin.vertices[skin.skin, None] - P[None], axis=2).min(axis=1) < 12.0]
    d, s = _along(skin.vertices[near], P)
    width = CREASE_RING_MM * np.nan_to_num(skin.edge_mm[near], nan=5.0)
    share = _smoothstep(s / ends) * _smoothstep((1 - s) / ends) if ends > 0 else np.ones_like(s)
    if weight is not None:
        share = share * weight(skin.vertices[near])
    profile = np.exp(-(d / width) ** 2)
    out[near] = -(depth * share * profile)[:, None] * skin.normals[near]
    return out


def bulge(skin: Skin, centre, height: float, radius: float, direction=None) -> np.ndarray:
    """The skin pushed out by ``height`` mm about ``centre`` ((x, y) in the front view, snapped to the skin),
    fading smoothly to nothing at ``radius`` mm; along the skin's normals, or along ``direction``."""
    centre = skin.vertices[skin.nearest(centre)]
    S = skin.skin
    d = np.linalg.norm(skin.vertices[S] - centre, axis=1)
    share = 1 - _smoothstep(d / radius)
    out = np.zeros_like(skin.vertices)
    motion = skin.normals[S] if direction is None else np.broadcast_to(np.asarray(direction, float), (len(S), 3))
    out[S] = (height * share)[:, None] * motion
    return out


def both_sides(one_side) -> np.ndarray:
    """``one_side(m)`` for m = +1 (the subject's left) and −1 (the right, mirrored), added."""
    return one_side(1.0) + one_side(-1.0)


def _brow_height(skin: Skin, x: float) -> float:
    """The rest brow line's height at |x| (through 4.1, 4.3, 4.5)."""
    xs = [skin.lm(k)[0] for k in ("4.1", "4.3", "4.5")]
    ys = [skin.lm(k)[1] for k in ("4.1", "4.3", "4.5")]
    return float(np.interp(abs(x), xs, ys))


def _across(half_width: float, step: float = 10.0) -> np.ndarray:
    return np.linspace(-half_width, half_width, round(2 * half_width / step) + 1)


# -- the AUs' appearance changes (both sides; value 1 = FACS intensity E) -------------------------------

FOREHEAD_LINES_MM = (11.0, 20.0, 30.0)   # the frontalis lines above the brow's top (4.3)


def forehead_lines(skin: Skin, medial: bool, depth: float = 1.5) -> np.ndarray:
    """AU1 (``medial``: the middle of the forehead) or AU2 (its sides): horizontal lines above the brows.

    FACS: AU1 wrinkles the centre of the forehead, AU2 its lateral parts, and 1 + 2 draw lines across
    it. The lines follow the brow's arch, flattened; AU1's fade out over |x| = 18 … 38 mm, AU2's fade
    in over 14 … 34 mm and out beyond the brow's tail, so that together they run across."""
    top = skin.lm("4.3")[1]
    tail = skin.lm("4.5")[0]
    out = np.zeros_like(skin.vertices)
    for k, rise in enumerate(FOREHEAD_LINES_MM):
        pts = [(x, top + rise + 0.35 * (_brow_height(skin, x) - top)) for x in _across(tail)]

        def weight(P):
            x = np.abs(P[:, 0])
            if medial:
                return 1 - _smoothstep((x - 18.0) / 20.0)
            return _smoothstep((x - 14.0) / 20.0) * (1 - _smoothstep((x - tail + 6.0) / 8.0))
        out += crease(skin, pts, depth * (1.0 - 0.15 * k), weight, ends=0.0)
    return out


def glabella(skin: Skin, depth: float = 1.8) -> np.ndarray:
    """AU4: a vertical furrow between the brows on each side, medial to the inner brow, and the brow's
    inner end bunched (the corrugator's bulge above it)."""
    b, inner = skin.lm("4.1"), skin.lm("3.11")

    def one(m):
        x = 0.45 * b[0]
        pts = [(m * x, b[1] + 6.0), (m * x, b[1] - 2.0), (m * (x - 1.0), inner[1] + 7.0)]
        return (crease(skin, pts, depth, ends=0.25)
                + bulge(skin, (m * (b[0] + 2.0), b[1] + 3.0), 0.8, 9.0))
    return both_sides(one)


def nose_root(skin: Skin, depth: float = 1.2) -> np.ndarray:
    """AU9: two lines across the root of the nose, where its skin is pulled up and bunched."""
    inner = skin.lm("3.11")
    out = np.zeros_like(skin.vertices)
    for k, drop in enumerate((0.0, 6.0)):
        y = inner[1] - drop
        pts = [(-9.0, y - 3.0), (-4.0, y), (0.0, y + 1.0), (4.0, y), (9.0, y - 3.0)]
        out += crease(skin, pts, depth * (1 - 0.2 * k), ends=0.2)
    return out


def nasolabial(skin: Skin, depth: float = 2.0, cheek: float = 1.5, upper_only: bool = False) -> np.ndarray:
    """The nasolabial furrow from beside the nose wing to beyond the lip corner, and the cheek bulging
    above and beside it (AU12 along its whole length; AU10 and AU9 deepen its upper part)."""
    wing, corner = skin.lm("9.5"), skin.lm("8.3")

    def one(m):
        pts = [(m * (wing[0] + 3.5), wing[1] + 4.0), (m * (wing[0] + 8.0), wing[1] - 7.0),
               (m * (corner[0] + 8.0), corner[1] + 2.0), (m * (corner[0] + 9.0), corner[1] - 9.0)]
        at_corner = corner * np.array([m, 1.0, 1.0])

        def weight(P):
            # clear of the lip corner, where the mouth's lining lies a few mm behind the skin
            near = _smoothstep((np.linalg.norm(P - at_corner, axis=1) - 5.0) / 4.0)
            if upper_only:
                return near * (1 - _smoothstep((wing[1] - 10.0 - P[:, 1]) / 10.0))
            return near
        out = crease(skin, pts, depth, weight, ends=0.1)
        if cheek:
            apex = ((wing[0] + corner[0]) / 2 + 12.0, (wing[1] + corner[1]) / 2 + 4.0)
            out += bulge(skin, (m * apex[0], apex[1]), cheek, 14.0)
        return out
    return both_sides(one)


def lower_lid_bag(skin: Skin, bag: float = 1.2, furrow: float = 1.0, feet: float = 0.5) -> np.ndarray:
    """AU6: the skin below the lower lid bagged (a bulge under the lid, the infraorbital furrow below it)
    and crow's feet fanning out from the outer eye corner."""
    lid, outer, inner = skin.lm("3.3"), skin.lm("3.7"), skin.lm("3.11")

    def one(m):
        x0, x1 = inner[0] + 4.0, outer[0] - 3.0
        out = crease(skin, [(m * x0, lid[1] - 9.0), (m * lid[0], lid[1] - 10.5), (m * x1, lid[1] - 7.5)], furrow)
        for x in np.linspace(x0 + 3.0, x1 - 2.0, 4):
            out += bulge(skin, (m * x, lid[1] - 4.5), bag / 2.0, 6.0)
        for angle in (32.0, 2.0, -30.0):         # clear of the lid's own corner, whose small faces would tear
            a = np.radians(angle)
            start = outer[:2] + np.array([5.0, 0.0])
            pts = [(m * (start[0] + r * np.cos(a)), start[1] + r * np.sin(a)) for r in (4.0, 8.0, 13.0)]
            out += crease(skin, pts, feet, ends=0.35)
        return out
    return both_sides(one)


def lower_lid_lift(skin: Skin, lift: float = 1.3, reach: float = 9.0) -> np.ndarray:
    """AU6: the lower lid pushed up over the eyeball by the raised cheek, ``lift`` mm at its margin (3.3),
    fading out ``reach`` mm below it; the skin turns up about the eyeball's centre, so it slides over it."""
    out = np.zeros_like(skin.vertices)
    for side, lid in (("left", "3.3"), ("right", "3.4")):
        centre, radius = skin.eyes[side]
        margin = skin.lm(lid)
        P = skin.vertices[skin.skin]
        below = margin[1] - P[:, 1]
        near = (np.abs(P[:, 0] - centre[0]) < radius * 1.15) & (P[:, 2] > centre[2]) & (below > -1.0) \
            & (below < reach)
        share = (1 - _smoothstep((below - 1.0) / (reach - 1.0))) * (1 - _smoothstep(
            (np.abs(P[:, 0] - centre[0]) - 0.6 * radius) / (0.55 * radius)))
        share = np.where(near, share, 0.0)
        a = P - centre
        up = np.cross(np.array([-1.0, 0.0, 0.0]), a)        # the motion of turning up about the x axis
        up /= np.maximum(np.linalg.norm(up, axis=1, keepdims=True), 1e-9)
        out[skin.skin] += (lift * share)[:, None] * up
    return out


def chin_boss(skin: Skin, lift: float = 3.0, sulcus: float = 1.2) -> np.ndarray:
    """AU17: the chin boss pushed up and forward (its soft tissue bunched) and the mentolabial sulcus
    under the lower lip deepened into a furrow curving up at its ends."""
    chin, lip = skin.lm("2.10"), skin.lm("2.3")
    y = chin[1] + 0.37 * (lip[1] - chin[1])
    out = bulge(skin, (0.0, chin[1] + 2.0), 1.0, 14.0)
    out += bulge(skin, (0.0, chin[1] + 2.0), lift, 16.0, direction=(0.0, 1.0, 0.25))
    pts = [(-15.0, y + 3.0), (-8.0, y), (0.0, y - 1.0), (8.0, y), (15.0, y + 3.0)]
    return out + crease(skin, pts, sulcus, ends=0.2)


def corner_pouch(skin: Skin, height: float = 0.8) -> np.ndarray:
    """AU15: the skin below and beside the pulled-down lip corners pouched."""
    corner = skin.lm("8.3")
    return both_sides(lambda m: bulge(skin, (m * (corner[0] + 3.0), corner[1] - 9.0), height, 8.0))
