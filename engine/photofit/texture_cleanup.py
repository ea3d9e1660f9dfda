"""The photograph's expression and light taken out of the texture: open mouth, mouth interior, shadows.

A smiling portrait shows teeth between parted lips. The head is fitted in
the photograph's expression (:mod:`engine.photofit.expression_fit`) and the
texture read through it posed, so its lips take the lips' pixels; what is
left is what lies *between* the lips in the photograph:

* :func:`mouth_opening`: the pixels inside the inner lip line (teeth, tongue,
  the dark inside) are not read into the skin (a lip texel the fit puts a
  little over the teeth takes the lips' colour from the fill instead), so the
  closed lips of the neutral face are lip-coloured;
* :func:`mouth_bag`: the skin inside the mouth (palate, cheeks' lining)
  keeps the head's own colours, painted by depth behind the lips
  (``engine/data/default-head/mouth_interior.py``), instead of the photograph's teeth;
* :func:`even_shadows`: the photograph's light is not the renderer's. Under
  the nose and along the creases from the nose to the mouth corners a
  portrait's key light leaves shadows (deepened by a smile), which the
  renderer's own shading then doubles. There the texture's brightness is
  lifted towards the smoothed brightness around it.

>>> import numpy as np
>>> lips = {"2.5": (10.0, 20.0), "2.2": (20.0, 16.0), "2.4": (30.0, 20.0), "2.3": (20.0, 24.0)}
>>> mask = mouth_opening((40, 40), lips, 1.0)
>>> bool(mask[20, 20]), bool(mask[20, 5]), bool(mask[10, 20])
(True, False, False)
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from scipy.ndimage import distance_transform_edt, gaussian_filter

from engine.model import Model

INNER_LIPS = ("2.5", "2.2", "2.4", "2.3")        # right corner, upper middle, left corner, lower middle
OPENING_MARGIN = 0.8                              # mm around the inner lip line also left out
SHADOW_KEEP = 0.35                                # the share of a shadow's darkening kept
SHADOW_RADIUS = 10.0                              # mm: the smoothing the darkening is measured against
#: (from, to, the "to" point moved by (x, y, z) mm, how far along): the creases from the nose's wings round the
#: mouth corners (a smile's nasolabial folds, passing 8 … 12 mm beside the corners), the corners' own creases, and
#: the upper lip under the nose (the philtrum, in the nose's shadow).
SHADOW_SEGMENTS = (("9.4", "8.4", (-10.0, -8.0, 0.0), 1.0), ("9.5", "8.3", (10.0, -8.0, 0.0), 1.0),
                   ("8.4", "8.4", (-7.0, -2.0, 0.0), 1.0), ("8.3", "8.3", (7.0, -2.0, 0.0), 1.0),
                   ("9.15", "8.1", (0.0, 0.0, 0.0), 0.75))
SHADOW_WIDTH = 4.5                                # mm either side of each segment


def mouth_opening(shape: tuple[int, ...], points: Mapping[str, tuple[float, float]], px_per_mm: float) -> np.ndarray:
    """(H, W) bool: the pixels between the inner lips of a front photograph (the lens through the inner lip
    corners 2.5, 2.4 and middles 2.2, 2.3), grown by :data:`OPENING_MARGIN`; all False without those points."""
    height, width = shape[0], shape[1]
    mask = np.zeros((height, width), dtype=bool)
    if not all(k in points for k in INNER_LIPS):
        return mask
    (rx, ry), (_, uy), (lx, ly), (_, dy) = (np.asarray(points[k], dtype=float) for k in INNER_LIPS)
    if lx - rx < 1.0:
        return mask
    margin = OPENING_MARGIN * px_per_mm
    x0, x1 = int(max(np.floor(rx - margin), 0)), int(min(np.ceil(lx + margin) + 1, width))
    y0 = int(max(np.floor(min(uy, ry, ly) - margin), 0))
    y1 = int(min(np.ceil(max(dy, ry, ly) + margin) + 1, height))
    if x1 <= x0 or y1 <= y0:
        return mask
    ys, xs = np.mgrid[y0:y1, x0:x1] + 0.5
    t = np.clip((xs - rx) / (lx - rx), 0.0, 1.0)             # 0 at the right corner, 1 at the left
    corner_line = ry + t * (ly - ry)
    middle = 4 * t * (1 - t)                                 # a parabola through the corners, 1 at the middle
    upper = corner_line + middle * (uy - (ry + ly) / 2)
    lower = corner_line + middle * (dy - (ry + ly) / 2)
    inside = (xs >= rx) & (xs <= lx) & (ys >= upper) & (ys <= lower)
    mask[y0:y1, x0:x1] = inside
    if margin > 0 and mask.any():
        mask |= distance_transform_edt(~mask) <= margin
    return mask


_BAGS: dict[tuple[int, int], np.ndarray] = {}


def mouth_bag(model: Model) -> np.ndarray:
    """(N,) bool: the skin vertices inside the mouth (:func:`engine.identity.mouth_bag.oral_cavity`) of ``model``,
    the default head (a fitted head shares its mesh; found on the default head's own lips, whose closed rim
    cuts the bag off cleanly: on a head fitted to an open mouth the cut once took most of the face)."""
    from engine.identity.mouth_bag import oral_cavity

    out = np.zeros(model.n_vertices, dtype=bool)
    if "skin" not in model.parts or "2.2" not in model.landmarks:
        return out
    key = (id(model), model.revision)
    if key not in _BAGS:
        _BAGS.clear()
        is_skin = model.vertex_part == model.parts.index("skin")
        bag, _ = oral_cavity(model.vertices, model.polygons(), is_skin, model.landmarks["2.2"])
        _BAGS[key] = bag
    out[_BAGS[key]] = True
    return out


def shadow_vertices(model: Model, vertices: np.ndarray, where: Mapping[str, int]) -> np.ndarray:
    """(N,) weights 0 … 1: how much each vertex lies where a portrait's light leaves shadows (under the nose,
    the creases from the nose to the mouth corners), 1 on :data:`SHADOW_SEGMENTS`, 0 beyond
    :data:`SHADOW_WIDTH`."""
    out = np.zeros(len(vertices))
    for a, b, offset, reach in SHADOW_SEGMENTS:
        if a not in where or b not in where:
            continue
        p, q = vertices[where[a]], vertices[where[b]] + np.asarray(offset)
        if a == b:
            p = p + 0.25 * np.asarray(offset)            # a corner's crease starts just beside the lips
        t = np.clip((vertices - p) @ (q - p) / max(float((q - p) @ (q - p)), 1e-9), 0.0, reach)
        distance = np.linalg.norm(vertices - (p + t[:, None] * (q - p)), axis=1)
        out = np.maximum(out, np.clip(1.5 - distance / SHADOW_WIDTH, 0.0, 1.0))
    return out


def even_shadows(atlas: np.ndarray, region: np.ndarray, covered: np.ndarray, texels_per_mm: float) -> None:
    """Lift the darkening of the ``region`` (H, W) weights in the (H, W, 3) ``atlas`` (in place): there each
    texel's brightness is drawn towards the brightness of its surroundings (smoothed over
    :data:`SHADOW_RADIUS`, ``covered`` texels only), keeping :data:`SHADOW_KEEP` of its darkening."""
    if not region.any():
        return
    luminance = atlas @ np.array([0.299, 0.587, 0.114])
    sigma = SHADOW_RADIUS * texels_per_mm
    weight = gaussian_filter(covered.astype(float), sigma)
    smooth = gaussian_filter(np.where(covered, luminance, 0.0), sigma) / np.maximum(weight, 1e-6)
    darker = np.clip(smooth - luminance, 0.0, None)            # only shadows are lifted, not highlights
    target = luminance + (1 - SHADOW_KEEP) * darker * region
    gain = np.where(luminance > 1.0, target / np.maximum(luminance, 1.0), 1.0)
    gain = np.where(covered, gain, 1.0)
    atlas *= gain[..., None]
    np.clip(atlas, 0, 255, out=atlas)
