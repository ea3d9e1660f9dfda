"""The head's whole outline in the side photograph, where the photograph shows skin there.

The midline profile (:mod:`engine.photofit.silhouette`) puts the face on
the side photograph's silhouette; this module does the same for the rest of
the head's outline in that view: the top and back of the skull, the nape,
the under-chin line. The outline of the fitted head is found by drawing it
with the side camera (:func:`outline_vertices`: skin vertices whose normal is
nearly perpendicular to the view and that lie on the drawn head's edge, one
per :data:`OUTLINE_SPACING` mm). Each is moved along its 2-D outline normal
to the nearest edge of the photograph's foreground along that line, within
:data:`FARTHEST_OUTLINE_MOVE` mm (:func:`outline_moves`; in millimetres, not pixels, so the rule is the
same at any photograph size).

Hair: a photograph's top and back outline is usually hair, not the scalp,
and the bald head must not be fitted to it. An outline point is trusted
only where the photograph just inside the edge is skin-coloured, judged by a
colour model of the face between the landmarks of the front photograph
(:class:`SkinColour`: mean and covariance of log luminance and chromaticity). A bald
head is fitted all round; under hair, only the face's profile, the
under-chin line and the neck are.

>>> import numpy as np
>>> face = np.zeros((40, 40, 3), dtype=np.uint8)
>>> face[:] = (200, 150, 125)
>>> face[::2, ::3] = (190, 140, 118)                       # a little texture
>>> skin = SkinColour.of_pixels(face.reshape(-1, 3))
>>> skin.is_skin(np.array([[198, 148, 124], [60, 42, 30], [230, 228, 232]])).tolist()
[True, False, False]
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from scipy.ndimage import binary_fill_holes, distance_transform_edt
from scipy.spatial import cKDTree

from engine.model import Model
from engine.photofit.camera import WeakPerspective
from engine.photofit.raster import rasterize
from engine.photofit.stopping import ShouldStop
from engine.photofit.texture import skin_triangles

OUTLINE_SPACING = 5.0               # mm between the outline points used
LANDMARK_CLEARANCE = 12.0           # mm from a landmark or profile point within which no outline point is used
RIM_NORMAL = 0.35                   # |n · v| below which a vertex may lie on the outline
RIM_PIXELS = 1.5                    # px of the drawn head (longer side DRAWING_SIDE) from its edge
DRAWING_SIDE = 600                  # px: the longer side of the drawing the outline is found in
BOUNDARY_CLEARANCE = 25.0           # mm from the mesh's open edge (the neck's cut) where no outline point is used
FARTHEST_OUTLINE_MOVE = 15.0        # mm: an edge farther than this along the outline's normal is not trusted
EDGE_RUN = 2.0                      # px of foreground before and background after an edge that make it an edge
INSIDE_SAMPLES = (3.0, 5.0, 7.0, 9.0)   # px inside the edge where the photograph's colour is tested for skin
SKIN_DISTANCE = 3.5                 # Mahalanobis distance from the face's colours still counted as skin
#: Least spread of each feature: log luminance (shading: at 3.5 of it a skin down to 42 % of the face's
#: luminance still counts) and chromaticity (a flat-coloured face must not make skin a single point; at 0.03
#: the lit brown hair on top of the synthetic head counted as skin, at 0.02 it does not).
COLOUR_FLOOR = (0.25, 0.02, 0.02)
FACE_POINTS = ("3.5", "3.6", "8.3", "8.4")


def skin_features(rgb: np.ndarray) -> np.ndarray:
    """(N, 3) log luminance and chromaticity (BT.601 Cb and Cr over luminance) of (N, 3) RGB colours.

    Over luminance, the chroma of one skin under brighter or dimmer light stays put; the log of the
    luminance lets shading scale it. Dark hair is told from shaded skin by luminance (and, usually, chroma).
    """
    r, g, b = (np.asarray(rgb, dtype=float)[:, k] for k in range(3))
    y = 0.299 * r + 0.587 * g + 0.114 * b
    return np.stack([np.log(y + 1.0), 0.564 * (b - y) / (y + 1.0), 0.713 * (r - y) / (y + 1.0)], axis=1)


@dataclass
class SkinColour:
    """A Gaussian model of the face's colour in :func:`skin_features`."""

    mean: np.ndarray
    inverse: np.ndarray

    @classmethod
    def of_pixels(cls, rgb: np.ndarray) -> SkinColour:
        values = skin_features(rgb)
        covariance = np.cov(values.T) + np.diag(np.square(COLOUR_FLOOR))
        return cls(values.mean(axis=0), np.linalg.inv(covariance))

    def is_skin(self, rgb: np.ndarray) -> np.ndarray:
        d = skin_features(rgb) - self.mean
        return np.asarray(np.einsum("ni,ij,nj->n", d, self.inverse, d) < SKIN_DISTANCE ** 2)


def face_skin(photo: np.ndarray, points: Mapping[str, tuple[float, float]]) -> SkinColour | None:
    """The skin model of the front photograph's face below the pupils and above the mouth corners, between
    the pupils (cheeks, nose, upper lip), or None without those four landmarks."""
    if not all(k in points for k in FACE_POINTS):
        return None
    (lx, ly), (rx, ry), (_, mouth_left), (_, mouth_right) = (points[k] for k in FACE_POINTS)
    apart = abs(lx - rx)
    top = max(ly, ry) + 0.25 * apart
    bottom = min(mouth_left, mouth_right) - 0.1 * apart
    left, right = min(lx, rx), max(lx, rx)
    rows = slice(max(int(top), 0), max(int(bottom), 0))
    columns = slice(max(int(left), 0), max(int(right), 0))
    pixels = photo[rows, columns].reshape(-1, 3)
    if len(pixels) < 20:
        return None
    return SkinColour.of_pixels(pixels)


def outline_vertices(model: Model, vertices: np.ndarray, normals: np.ndarray, triangles: np.ndarray,
                     camera: WeakPerspective, should_stop: ShouldStop = None) -> tuple[np.ndarray, np.ndarray]:
    """Skin vertices on the head's outline seen by ``camera`` (OUTLINE_SPACING apart) and their (N, 2) outward
    2-D normals (unit, image x right, y down)."""
    skin = model.vertex_part == model.parts.index("skin") if "skin" in model.parts else np.ones(len(vertices), bool)
    pixels = camera.project(vertices)
    low, high = pixels.min(axis=0) - 4, pixels.max(axis=0) + 4
    factor = DRAWING_SIDE / float(max(high - low))
    size = np.ceil((high - low) * factor).astype(int) + 1
    hit, _, _ = rasterize((pixels[triangles] - low) * factor, int(size[0]), int(size[1]), should_stop=should_stop)
    inside = distance_transform_edt(binary_fill_holes(hit >= 0))
    where = np.clip(((pixels - low) * factor).astype(int), 0, size - 1)
    on_edge = inside[where[:, 1], where[:, 0]] <= RIM_PIXELS
    facing = np.abs(normals @ camera.toward_camera()) < RIM_NORMAL
    candidates = np.flatnonzero(skin & on_edge & facing & (_clearance(model, vertices) > BOUNDARY_CLEARANCE))
    chosen: list[int] = []
    for k in candidates:
        if not chosen or np.linalg.norm(vertices[chosen] - vertices[k], axis=1).min() >= OUTLINE_SPACING:
            chosen.append(int(k))
    index = np.asarray(chosen, dtype=np.int64)
    flat = np.stack([normals[index] @ camera.rotation[0], -(normals[index] @ camera.rotation[1])], axis=1)
    flat /= np.maximum(np.linalg.norm(flat, axis=1, keepdims=True), 1e-12)
    return index, flat


def outline_moves(photo: np.ndarray, mask: np.ndarray, camera: WeakPerspective, points: np.ndarray,
                  directions: np.ndarray, skin: SkinColour) -> tuple[np.ndarray, np.ndarray]:
    """For (N, 3) outline points and their (N, 2) outward directions: which have a trusted skin edge (N,) and
    their 3-D moves onto it (N, 3) mm. ``mask`` is the photograph's foreground."""
    person = binary_fill_holes(mask)
    height, width = person.shape
    farthest = FARTHEST_OUTLINE_MOVE * camera.scale
    steps = np.arange(-farthest - EDGE_RUN, farthest + EDGE_RUN + 0.25, 0.5)
    run = round(EDGE_RUN / 0.5)
    pixels = camera.project(points)
    ok = np.zeros(len(points), dtype=bool)
    moves = np.zeros((len(points), 3))
    inside_colours = []
    shifts = np.zeros(len(points))
    for k, (start, direction) in enumerate(zip(pixels, directions, strict=True)):
        line = start + steps[:, None] * direction
        cols, rows = line[:, 0].astype(int), line[:, 1].astype(int)
        within = (cols >= 0) & (cols < width) & (rows >= 0) & (rows < height)
        on = np.zeros(len(steps), dtype=bool)
        on[within] = person[rows[within], cols[within]]
        edges = [i for i in range(run, len(steps) - run)
                 if on[i - run + 1:i + 1].all() and not on[i + 1:i + 1 + run].any()]
        if not edges:
            inside_colours.append(np.zeros((len(INSIDE_SAMPLES), 3)))
            continue
        best = min(edges, key=lambda i: abs(steps[i] + 0.25))
        shift = steps[best] + 0.25
        if abs(shift) > farthest:
            inside_colours.append(np.zeros((len(INSIDE_SAMPLES), 3)))
            continue
        ok[k] = True
        shifts[k] = shift
        probe = start + (shift - np.array(INSIDE_SAMPLES))[:, None] * direction
        probe = np.clip(probe, 0, [width - 1, height - 1]).astype(int)
        inside_colours.append(photo[probe[:, 1], probe[:, 0]].astype(float))
    colours = np.median(np.asarray(inside_colours), axis=1) if len(points) else np.zeros((0, 3))
    ok &= skin.is_skin(colours) if len(points) else ok
    along = (directions[:, :1] * camera.rotation[0] - directions[:, 1:] * camera.rotation[1]) / camera.scale
    moves[ok] = shifts[ok, None] * along[ok]
    return ok, moves


def _clearance(model: Model, vertices: np.ndarray) -> np.ndarray:
    """(N,) mm from each vertex to the nearest vertex on an open edge of the skin (the neck's cut)."""
    tri_v, _, _ = skin_triangles(model)
    edges = np.sort(np.concatenate([tri_v[:, [0, 1]], tri_v[:, [1, 2]], tri_v[:, [2, 0]]]), axis=1)
    unique, counts = np.unique(edges, axis=0, return_counts=True)
    rim = np.unique(unique[counts == 1])
    if not len(rim):
        return np.full(len(vertices), np.inf)
    distance, _ = cKDTree(vertices[rim]).query(vertices)
    return np.asarray(distance)
