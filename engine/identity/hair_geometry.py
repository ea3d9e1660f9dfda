"""Hair made from the skin: shells over a region, strands as thin ribbons draped over it, brows, a curtain, a bun.

Everything is grown on the default head's rest shape and returned as
:class:`HairPiece` s — vertices written as skin anchors (:mod:`engine.identity.hair_surface`),
triangles, and a colour shade per vertex (1 the hair's own colour, less
darker). Pieces are opaque geometry: a *shell* (the region's skin triangles
lifted a few mm, thinning to nothing at the region's edge) gives the hair
its body, and *ribbons* (strands 0.3–1.2 mm wide lying along a combing
direction, a little above the shell) give it its grain. Random choices
come from one seeded generator, so the same choice grows the same hair.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from engine.identity.hair_regions import HairRegions
from engine.identity.hair_surface import Anchors, SkinSurface, frames

Field = Callable[[np.ndarray, np.ndarray], np.ndarray]    # (points, normals) → unit directions


@dataclass
class HairPiece:
    """Hair vertices as ``anchors``, (T, 3) ``triangles`` into them, per-vertex ``shade`` and ``strand`` number."""

    anchors: Anchors
    triangles: np.ndarray
    shade: np.ndarray
    strand: np.ndarray

    @staticmethod
    def join(pieces: list[HairPiece]) -> HairPiece:
        tris, start, strands, first = [], 0, [], 0
        for piece in pieces:
            tris.append(piece.triangles + start)
            strands.append(piece.strand + first)
            start += len(piece.anchors)
            first += int(piece.strand.max()) + 1 if len(piece.strand) else 0
        return HairPiece(Anchors.concatenate([p.anchors for p in pieces]),
                         np.concatenate(tris) if tris else np.zeros((0, 3), np.int64),
                         np.concatenate([p.shade for p in pieces]) if pieces else np.zeros(0),
                         np.concatenate(strands) if strands else np.zeros(0, np.int64))


def shell(vertices: np.ndarray, regions: HairRegions, strength: np.ndarray, thickness: float,
          surface: SkinSurface, least: float = 0.25, shade: float = 0.7) -> HairPiece:
    """The skin triangles where ``strength`` (per skin vertex) is above zero, lifted by up to ``thickness`` mm."""
    dense = np.zeros(len(vertices))
    dense[regions.skin] = strength
    tri = regions.triangles[(dense[regions.triangles] > 0.02).all(axis=1)]
    used, inverse = np.unique(tri, return_inverse=True)
    owner = np.zeros(len(vertices), np.int64)
    owner[tri.ravel()] = np.repeat(np.arange(len(tri)), 3)          # one triangle each used vertex is in
    corners = tri[owner[used]]
    bary = (corners == used[:, None]).astype(float)
    lift = (least + (thickness - least) * dense[used])[:, None] * surface.vertex_normals[used]
    offset = np.einsum("mid,md->mi", frames(vertices, corners), lift)
    return HairPiece(Anchors(corners, bary, offset), inverse.reshape(-1, 3),
                     np.full(len(used), shade), np.zeros(len(used), np.int64))


def sample_roots(vertices: np.ndarray, regions: HairRegions, strength: np.ndarray, count: int,
                 rng: np.random.Generator) -> np.ndarray:
    """``count`` points on the skin, denser where ``strength`` (per skin vertex) is higher."""
    dense = np.zeros(len(vertices))
    dense[regions.skin] = strength
    tri = regions.triangles
    a, b, c = (vertices[tri[:, k]] for k in range(3))
    weight = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1) * dense[tri].mean(axis=1) ** 2
    if weight.sum() <= 0:
        return np.zeros((0, 3))
    pick = rng.choice(len(tri), size=count, p=weight / weight.sum())
    u, v = rng.random(count), rng.random(count)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    return a[pick] + u[:, None] * (b[pick] - a[pick]) + v[:, None] * (c[pick] - a[pick])


def ribbons(surface: SkinSurface, roots: np.ndarray, field: Field, length: np.ndarray, width: np.ndarray,
            height: np.ndarray, segments: int, shade: np.ndarray, lift_tip: float = 0.0,
            keep: Callable[[np.ndarray], np.ndarray] | None = None) -> HairPiece:
    """Strands from ``roots`` combed along ``field``, each ``length`` mm in ``segments`` steps, draped
    ``height`` mm over the skin (``+ lift_tip`` at the tip), ``width`` mm wide tapering to a third at the tip.

    ``keep(points)`` may stop a strand where it leaves its region (the rest of it is folded onto its last point).
    """
    m = len(roots)
    centre = np.zeros((segments + 1, m, 3))
    normal = np.zeros((segments + 1, m, 3))
    centre[0], anchors = surface.drape(roots, height)
    normal[0] = surface.normals_at(anchors)
    alive = np.ones(m, bool)
    for k in range(1, segments + 1):
        step = field(centre[k - 1], normal[k - 1]) * (length / segments)[:, None]
        lift = height + lift_tip * k / segments
        moved, anchors = surface.drape(centre[k - 1] + step, lift)
        if keep is not None:
            alive &= keep(moved)
        centre[k] = np.where(alive[:, None], moved, centre[k - 1])
        normal[k] = surface.normals_at(anchors)
    tangent = np.gradient(centre, axis=0)
    side = np.cross(normal, tangent)
    side /= np.maximum(np.linalg.norm(side, axis=2, keepdims=True), 1e-9)
    taper = np.linspace(1.0, 0.35, segments + 1)[:, None, None] * width[None, :, None] / 2
    left, right = centre + taper * side, centre - taper * side
    points = np.stack([left, right], axis=2).transpose(1, 0, 2, 3).reshape(-1, 3)   # strand, step, side
    base = (np.arange(m) * 2 * (segments + 1))[:, None] + 2 * np.arange(segments)[None, :]
    L0, R0, L1, R1 = base, base + 1, base + 2, base + 3
    triangles = np.concatenate([np.stack([L0, R0, L1], -1).reshape(-1, 3), np.stack([R0, R1, L1], -1).reshape(-1, 3)])
    along = np.repeat(np.linspace(0.8, 1.08, segments + 1), 2)
    shades = (shade[:, None] * along[None, :]).ravel()
    return HairPiece(surface.closest(points), triangles, shades, np.repeat(np.arange(m), 2 * (segments + 1)))


def tangent(direction: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """``direction`` with its part along ``normals`` taken off, unit length."""
    t = direction - (direction * normals).sum(axis=1, keepdims=True) * normals
    return t / np.maximum(np.linalg.norm(t, axis=1, keepdims=True), 1e-9)


def brow_hairs(surface: SkinSurface, ends: tuple[np.ndarray, np.ndarray, np.ndarray], count: int,
               widths: tuple[float, float, float], rng: np.random.Generator) -> HairPiece:
    """One brow: ``count`` short hairs rooted in the band inner → top → outer (half-widths ``widths`` mm),
    the inner ones standing up, the rest lying outwards along the brow, those above and below leaning in."""
    inner, top, outer = ends
    t = rng.random(count) ** 0.85                              # more hairs towards the head of the brow
    first = t < 0.5
    s = np.where(first, t / 0.5, (t - 0.5) / 0.5)[:, None]
    line = np.where(first[:, None], inner + s * (top - inner), top + s * (outer - top))
    along = np.where(first[:, None], top - inner, outer - top)
    along /= np.linalg.norm(along, axis=1, keepdims=True)
    half = np.interp(t, [0.0, 0.5, 1.0], widths)
    across = rng.uniform(-1, 1, count) * half
    _, anchor = surface.drape(line, 0.0)
    n = surface.normals_at(anchor)
    up = tangent(np.tile([0.0, 1.0, 0.0], (count, 1)), n)
    along = tangent(along, n)
    roots = line + across[:, None] * up
    # at the head the hairs stand up (and a little outwards); then they lie along the brow, those in the
    # upper half leaning down towards its middle line and those in the lower half up
    stand = np.clip(1.0 - t / 0.22, 0.0, 1.0)[:, None]
    lean = -0.35 * (across / np.maximum(half, 1e-6))[:, None]
    direction = stand * (up + 0.4 * along) + (1 - stand) * (along + lean * up)
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    fixed = direction.copy()

    def comb(points: np.ndarray, normals: np.ndarray) -> np.ndarray:
        return tangent(fixed, normals)

    length = np.interp(t, [0.0, 0.2, 0.7, 1.0], [4.5, 7.0, 7.5, 5.0]) * rng.uniform(0.8, 1.15, count)
    width = rng.uniform(0.28, 0.42, count)
    shade = rng.uniform(0.8, 1.15, count)
    return ribbons(surface, roots, comb, length, width, np.full(count, 0.12), 3, shade, lift_tip=0.45)


def curtain(vertices: np.ndarray, skin: np.ndarray, scalp_surface: SkinSurface, top_y: float, bottom_y: float,
            front_azimuth: float, columns: int, rows: int, gap: float, rng: np.random.Generator) -> HairPiece:
    """Long hair falling from the skull's widest part: a sheet around the sides and back from ``top_y`` down to
    ``bottom_y`` (mm), ``gap`` mm clear of the skin below it, in ``columns`` strands' width of streaks;
    its vertices are held by the scalp (they move with the head)."""
    from engine.identity.hair_regions import AXIS_Z

    P = vertices[skin]
    angle = np.radians(np.concatenate([np.linspace(front_azimuth, 180.0, columns // 2),
                                       np.linspace(-180.0, -front_azimuth, columns // 2)]))
    ys = np.linspace(top_y, bottom_y, rows)
    skin_angle = np.arctan2(P[:, 0], P[:, 2] - AXIS_Z)
    skin_radius = np.hypot(P[:, 0], P[:, 2] - AXIS_Z)
    radius = np.zeros((rows, len(angle)))
    for j, a in enumerate(angle):
        near = np.abs(np.angle(np.exp(1j * (skin_angle - a)))) < np.radians(9.0)
        for i, y in enumerate(ys):
            above = near & (P[:, 1] > y - 6.0) & (P[:, 1] < top_y + 25.0)
            radius[i, j] = skin_radius[above].max() if above.any() else radius[i - 1, j]
    radius = np.maximum.accumulate(radius, axis=0) + gap       # falls straight down from the widest part
    radius *= 1.0 + 0.04 * np.linspace(0.0, 1.0, rows)[:, None]   # and spreads a little
    jitter = rng.normal(0.0, 0.9, len(angle))
    radius = radius + jitter[None, :] * np.linspace(0.3, 1.0, rows)[:, None]
    bottom = ys[None, :].T + rng.uniform(-6.0, 6.0, len(angle))[None, :] * np.linspace(0, 1, rows)[:, None]
    points = np.stack([radius * np.sin(angle)[None, :], np.broadcast_to(bottom, radius.shape),
                       AXIS_Z + radius * np.cos(angle)[None, :]], axis=-1).reshape(-1, 3)
    cols = len(angle)
    idx = np.arange(rows * cols).reshape(rows, cols)
    a, b, c, d = idx[:-1, :-1], idx[:-1, 1:], idx[1:, :-1], idx[1:, 1:]
    # outward normals: columns run from the right side round the back to the left, rows downwards
    triangles = np.concatenate([np.stack([a, c, b], -1).reshape(-1, 3), np.stack([b, c, d], -1).reshape(-1, 3)])
    streak = rng.uniform(0.72, 1.12, cols)
    shade = (streak[None, :] * np.linspace(0.95, 1.05, rows)[:, None]).ravel()
    return HairPiece(scalp_surface.closest(points), triangles, shade, np.tile(np.arange(cols), rows))


def bun(centre: np.ndarray, radius: float, scalp_surface: SkinSurface, rng: np.random.Generator) -> HairPiece:
    """Tied hair's knot: a flattened ball of ``radius`` mm at ``centre`` (behind the head), held by the scalp."""
    lat, lon = np.linspace(0, np.pi, 14), np.linspace(0, 2 * np.pi, 33)[:-1]
    la, lo = np.meshgrid(lat, lon, indexing="ij")
    unit = np.stack([np.sin(la) * np.cos(lo), np.cos(la), np.sin(la) * np.sin(lo)], -1).reshape(-1, 3)
    points = centre + unit * np.array([1.0, 0.85, 0.75]) * radius * (1 + rng.normal(0, 0.03, (len(unit), 1)))
    rows, cols = len(lat), len(lon)
    idx = np.arange(rows * cols).reshape(rows, cols)
    a, b = idx[:-1], np.roll(idx[:-1], -1, axis=1)
    c, d = idx[1:], np.roll(idx[1:], -1, axis=1)
    triangles = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([b, d, c], -1).reshape(-1, 3)])
    shade = np.tile(rng.uniform(0.75, 1.1, cols), rows)
    return HairPiece(scalp_surface.closest(points), triangles, shade, np.tile(np.arange(cols), rows))
