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


def fxaa(image: np.ndarray, copy: bool = True) -> np.ndarray:
    """``image`` ((H, W, 3) uint8 RGB) with its edges smoothed, as a new array (``copy=False``: smoothed
    where it is, when it is a writable C-contiguous uint8 array, and returned)."""
    height, width = image.shape[:2]
    if copy or image.dtype != np.uint8 or not image.flags.c_contiguous or not image.flags.writeable:
        out = np.array(image, dtype=np.uint8, copy=True)
    else:
        out = image
    if height < 3 or width < 3:
        return out
    edge = _padded_luma(out)
    centre = edge[1:-1, 1:-1]
    n_, s_, w_, e_ = edge[:-2, 1:-1], edge[2:, 1:-1], edge[1:-1, :-2], edge[1:-1, 2:]
    brightest = np.maximum(n_, s_)
    np.maximum(brightest, w_, out=brightest)
    np.maximum(brightest, e_, out=brightest)
    np.maximum(brightest, centre, out=brightest)
    contrast = np.minimum(n_, s_)
    np.minimum(contrast, w_, out=contrast)
    np.minimum(contrast, e_, out=contrast)
    np.minimum(contrast, centre, out=contrast)
    np.subtract(brightest, contrast, out=contrast)            # uint8: brightest >= darkest
    np.right_shift(brightest, 3, out=brightest)               # EDGE_THRESHOLD = 1/8 …
    np.maximum(brightest, np.uint8(round(EDGE_THRESHOLD_MIN * 255)), out=brightest)     # … and the floor
    where = np.flatnonzero(contrast >= brightest)
    if len(where) == 0:
        return out
    ys, xs = np.divmod(where, width)
    stride = width + 2                                        # of the padded picture, flattened
    flat = edge.reshape(-1)
    here = (ys + 1) * stride + (xs + 1)                       # each edge pixel in the padded picture

    def luma(index: np.ndarray) -> np.ndarray:
        return _UNIT[flat[index]]

    m = luma(here)
    n, s, w, e = luma(here - stride), luma(here + stride), luma(here - 1), luma(here + 1)
    nw, ne, sw, se = luma(here - stride - 1), luma(here - stride + 1), luma(here + stride - 1), luma(here + stride + 1)
    span = _UNIT[contrast.reshape(-1)[where]]
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
    dy_across, dx_across = np.where(horizontal, across, 0), np.where(horizontal, 0, across)
    lower = (m - edge_mean) < 0
    # a point on the search line: ``start + position × along`` (the pixel's own row or column) and
    # ``start_across + position × along`` (the one across), ``position`` kept inside the padded picture
    position = np.where(horizontal, xs + 1, ys + 1)
    limit = np.where(horizontal, width + 1, height + 1)
    along = np.where(horizontal, 1, stride)
    start = np.where(horizontal, (ys + 1) * stride, xs + 1)
    start_across = np.where(horizontal, (ys + 1 + dy_across) * stride, xs + 1 + dx_across)
    found = []
    for direction in (-1, 1):
        distance = np.zeros(len(ys), dtype=np.int64)
        end = np.zeros(len(ys), dtype=np.float32)
        going = np.arange(len(ys))                            # the pixels whose search goes on
        for step in SEARCH_STEPS:
            distance[going] += step
            at = np.minimum(np.maximum(position[going] + direction * distance[going], 0), limit[going])
            at *= along[going]
            value = (luma(start[going] + at) + luma(start_across[going] + at)) / 2 - edge_mean[going]
            end[going] = value
            going = going[np.abs(value) < threshold[going]]
            if len(going) == 0:
                break
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


_UNIT = np.arange(256, dtype=np.float32) / np.float32(255)      # a uint8 level as 0 … 1


def _padded_luma(image: np.ndarray) -> np.ndarray:
    """The green channel (FXAA's cheap luma) with its edge pixels repeated one pixel further round."""
    height, width = image.shape[:2]
    edge = np.empty((height + 2, width + 2), dtype=np.uint8)
    edge[1:-1, 1:-1] = image[..., 1]
    edge[0, 1:-1], edge[-1, 1:-1] = image[0, :, 1], image[-1, :, 1]
    edge[:, 0], edge[:, -1] = edge[:, 1], edge[:, -2]
    return edge
