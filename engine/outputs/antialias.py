"""FXAA on a picture already drawn: edges smoothed on the CPU, after the frame is read back.

On a machine without a GPU (Mesa's llvmpipe) VTK's own FXAA pass costs as much as drawing the
frame again at 1280 × 720, and 8× multisampling three times as much (docs/looks.md). Most of a
frame has no edge: this port of the FXAA 3.11 "quality" algorithm (Timothy Lottes, NVIDIA, 2011)
first finds, with a few whole-picture numpy operations, the pixels whose neighbourhood has a
contrast worth smoothing (a few per cent of a face picture), and does the rest of the work for
those alone:

* the edge's orientation from the second differences of the 3 × 3 neighbourhood's luma, and the
  side of it the pixel looks across to;
* a search along the edge, both ways, for where it ends (steps of 1, 1, 2, 2, 2, 2, 4 and 8
  pixels), so that a stair-stepped edge gets a blend that ramps along each step;
* the sub-pixel blend of a pixel much brighter or darker than its neighbours' mean (a thin
  line, an eyelash);
* the pixel mixed with the one across the edge by the larger of the two.

The result is the same for the same picture on any machine (numpy in float32, no threads).

>>> import numpy as np
>>> picture = np.zeros((8, 8, 3), dtype=np.uint8)
>>> picture[np.tril_indices(8)] = 255                  # a hard diagonal edge
>>> smoothed = fxaa(picture)
>>> smoothed.shape, smoothed.dtype, bool(((smoothed > 0) & (smoothed < 255)).any())
((8, 8, 3), dtype('uint8'), True)
>>> bool((fxaa(np.full((4, 4, 3), 90, dtype=np.uint8)) == 90).all())      # nothing to smooth
True
"""

from __future__ import annotations

import numpy as np

__all__ = ["EDGE_THRESHOLD", "EDGE_THRESHOLD_MIN", "SEARCH_STEPS", "SUBPIXEL", "fxaa", "settings"]

EDGE_THRESHOLD = 0.125           # a local contrast below this share of the brightest neighbour is no edge …
                                 # (1/8: computed as a shift)
EDGE_THRESHOLD_MIN = 0.0312      # … nor one below this (dark areas)
SUBPIXEL = 0.75                  # how much a thin feature is blended with its surroundings (0 … 1)
SEARCH_STEPS = (1, 1, 2, 2, 2, 2, 4, 8)


def settings() -> dict[str, object]:
    """The settings this FXAA runs with (a stimulus set's provenance records them)."""
    return {"method": "fxaa-3.11-quality (numpy, on the read-back frame)", "edge_threshold": EDGE_THRESHOLD,
            "edge_threshold_min": EDGE_THRESHOLD_MIN, "subpixel": SUBPIXEL, "search_steps": list(SEARCH_STEPS)}


def fxaa(image: np.ndarray) -> np.ndarray:
    """``image`` ((H, W, 3) uint8 RGB) with its edges smoothed, as a new array."""
    height, width = image.shape[:2]
    out = np.array(image, dtype=np.uint8, copy=True)
    if height < 3 or width < 3:
        return out
    green = np.ascontiguousarray(image[..., 1])               # luma: the green channel (FXAA's cheap variant)
    edge = np.pad(green, 1, mode="edge")
    centre = edge[1:-1, 1:-1]
    brightest = np.maximum(np.maximum(edge[:-2, 1:-1], edge[2:, 1:-1]), np.maximum(edge[1:-1, :-2], edge[1:-1, 2:]))
    darkest = np.minimum(np.minimum(edge[:-2, 1:-1], edge[2:, 1:-1]), np.minimum(edge[1:-1, :-2], edge[1:-1, 2:]))
    np.maximum(brightest, centre, out=brightest)
    np.minimum(darkest, centre, out=darkest)
    contrast = brightest - darkest                            # uint8: brightest >= darkest
    floor = np.maximum(brightest >> 3, np.uint8(round(EDGE_THRESHOLD_MIN * 255)))   # EDGE_THRESHOLD = 1/8
    where = np.flatnonzero(contrast >= floor)
    if len(where) == 0:
        return out
    ys, xs = np.divmod(where, width)
    pad = edge.astype(np.float32) / np.float32(255)
    py, px = ys + 1, xs + 1                                   # in the padded picture
    m = pad[py, px]
    n, s, w, e = pad[py - 1, px], pad[py + 1, px], pad[py, px - 1], pad[py, px + 1]
    nw, ne, sw, se = pad[py - 1, px - 1], pad[py - 1, px + 1], pad[py + 1, px - 1], pad[py + 1, px + 1]
    span = contrast[ys, xs].astype(np.float32) / np.float32(255)
    horizontal = (np.abs(nw + sw - 2 * w) + 2 * np.abs(n + s - 2 * m) + np.abs(ne + se - 2 * e)
                  >= np.abs(nw + ne - 2 * n) + 2 * np.abs(w + e - 2 * m) + np.abs(sw + se - 2 * s))
    # the two neighbours across the edge (above/below a horizontal edge, left/right of a vertical one)
    before = np.where(horizontal, n, w)
    after = np.where(horizontal, s, e)
    towards_before = np.abs(before - m) >= np.abs(after - m)
    across = np.where(towards_before, -1, 1)                  # step across the edge, on the crossing axis
    neighbour = np.where(towards_before, before, after)
    gradient = np.maximum(np.abs(before - m), np.abs(after - m))
    # sub-pixel: how far the pixel stands out from its neighbours' weighted mean
    mean = (2 * (n + s + w + e) + nw + ne + sw + se) / np.float32(12)
    sub = np.clip(np.abs(mean - m) / span, 0.0, 1.0)
    sub = ((-2.0 * sub + 3.0) * sub * sub) ** 2 * SUBPIXEL
    # the search along the edge's middle line, between the pixel and the one across
    edge_mean = (m + neighbour) / 2
    threshold = gradient / 4
    dy_along, dx_along = np.where(horizontal, 0, 1), np.where(horizontal, 1, 0)
    dy_across, dx_across = np.where(horizontal, across, 0), np.where(horizontal, 0, across)
    lower = (m - edge_mean) < 0
    found = []
    for direction in (-1, 1):
        distance = np.zeros(len(ys), dtype=np.int64)
        end = np.zeros(len(ys), dtype=np.float32)
        done = np.zeros(len(ys), dtype=bool)
        for step in SEARCH_STEPS:
            going = ~done
            distance[going] += step
            y = np.clip(py + direction * distance * dy_along, 0, height + 1)
            x = np.clip(px + direction * distance * dx_along, 0, width + 1)
            value = (pad[y, x] + pad[np.clip(y + dy_across, 0, height + 1), np.clip(x + dx_across, 0, width + 1)]) / 2
            end = np.where(going, value - edge_mean, end)
            done |= np.abs(end) >= threshold
        found.append((distance, end))
    (distance_n, end_n), (distance_p, end_p) = found
    nearer_n = distance_n < distance_p
    nearest = np.minimum(distance_n, distance_p).astype(np.float32)
    good = np.where(nearer_n, (end_n < 0) != lower, (end_p < 0) != lower)
    offset = np.where(good, 0.5 - nearest / (distance_n + distance_p), 0.0)
    blend = np.maximum(offset, sub).astype(np.float32)[:, None]
    mixed = image[ys, xs].astype(np.float32) * (1 - blend) + \
        image[np.clip(ys + dy_across, 0, height - 1), np.clip(xs + dx_across, 0, width - 1)].astype(np.float32) * blend
    out[ys, xs] = np.clip(np.rint(mixed), 0, 255).astype(np.uint8)
    return out
