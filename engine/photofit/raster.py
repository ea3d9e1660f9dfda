"""Triangles drawn into a pixel grid with numpy: which triangle covers each pixel, where inside it, how near.

>>> import numpy as np
>>> hit, bary, _ = rasterize(np.array([[[0, 0], [4, 0], [0, 4.0]]]), 4, 4)
>>> hit.tolist()[3], bool(np.allclose(bary[0, 0], [0.75, 0.125, 0.125]))
([0, -1, -1, -1], True)
"""

from __future__ import annotations

import numpy as np

from engine.photofit.stopping import ShouldStop, stop_if_asked

#: Triangles drawn between two questions to ``should_stop`` (a few milliseconds of drawing).
TRIANGLES_PER_STOP_CHECK = 128
#: Pixels of bounding boxes drawn at once at most (unless one triangle's box is larger): bounds the memory.
PIXELS_PER_BATCH = 1 << 21


def rasterize(triangles: np.ndarray, width: int, height: int, depth: np.ndarray | None = None,
              should_stop: ShouldStop = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cover a ``height`` × ``width`` grid with (T, 3, 2) triangles (x, y in pixels; pixel centres at +0.5).

    Returns the triangle index of every pixel (−1 where none), the barycentric
    weights there (H, W, 3) and the depth (H, W; −inf where none). With
    ``depth`` (T, 3) the nearest (largest) wins, the first drawn of equals; without, the last drawn.
    Triangles of like size are drawn together, :data:`TRIANGLES_PER_STOP_CHECK` at a time (fewer where
    their boxes would pass :data:`PIXELS_PER_BATCH`), each batch on the grid of its largest bounding box;
    ``should_stop`` is asked before each batch
    (:mod:`engine.photofit.stopping`).
    """
    hit = np.full((height, width), -1, dtype=np.int64)
    bary = np.zeros((height, width, 3))
    zbuf = np.full((height, width), -np.inf)
    tri = np.asarray(triangles, dtype=float)
    if not len(tri):
        return hit, bary, zbuf
    lo = np.clip(np.floor(tri.min(axis=1) - 0.5).astype(int), 0, [width, height])
    hi = np.clip(np.ceil(tri.max(axis=1) - 0.5).astype(int) + 1, 0, [width, height])
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1])
    drawn = np.flatnonzero((np.abs(area) > 1e-12) & np.all(hi > lo, axis=1))
    extent = hi[drawn] - lo[drawn]
    drawn = drawn[np.lexsort((extent[:, 0], extent[:, 1]))]          # like sizes together: little padding
    found: list[tuple[np.ndarray, ...]] = []
    start = 0
    while start < len(drawn):
        stop_if_asked(should_stop)
        count = TRIANGLES_PER_STOP_CHECK
        while True:                                     # large triangles: fewer at a time, memory bounded
            t = drawn[start:start + count]
            span = (hi[t] - lo[t]).max(axis=0)
            if count == 1 or len(t) * int(span[0]) * int(span[1]) <= PIXELS_PER_BATCH:
                break
            count //= 2
        start += len(t)
        xs = (lo[t, 0][:, None, None] + np.arange(span[0])[None, None, :]) + 0.5          # (n, 1, w)
        ys = (lo[t, 1][:, None, None] + np.arange(span[1])[None, :, None]) + 0.5          # (n, h, 1)
        at, bt, ct = a[t][:, None, None, :], b[t][:, None, None, :], c[t][:, None, None, :]
        w1 = ((xs - at[..., 0]) * (ct[..., 1] - at[..., 1]) - (ct[..., 0] - at[..., 0]) * (ys - at[..., 1])) \
            / area[t][:, None, None]
        w2 = ((bt[..., 0] - at[..., 0]) * (ys - at[..., 1]) - (xs - at[..., 0]) * (bt[..., 1] - at[..., 1])) \
            / area[t][:, None, None]
        w0 = 1.0 - w1 - w2
        right, bottom = hi[t, 0][:, None, None], hi[t, 1][:, None, None]       # each triangle's own box
        inside = (w0 >= -1e-9) & (w1 >= -1e-9) & (w2 >= -1e-9) & (xs < right) & (ys < bottom)
        k, rows, cols = np.nonzero(inside)
        found.append((t[k], rows + lo[t[k], 1], cols + lo[t[k], 0], w0[inside], w1[inside], w2[inside]))
    if not found:
        return hit, bary, zbuf
    which, rows, cols, w0, w1, w2 = (np.concatenate(parts) for parts in zip(*found, strict=True))
    weights = np.stack([w0, w1, w2], axis=1)
    pixel = rows * width + cols
    if depth is not None:
        z = np.einsum("nk,nk->n", weights, np.asarray(depth, dtype=float)[which])
        order = np.lexsort((which, -z, pixel))          # per pixel: the nearest, then the first drawn
    else:
        order = np.lexsort((-which, pixel))              # per pixel: the last drawn
    first = order[np.r_[True, pixel[order][1:] != pixel[order][:-1]]]
    hit[rows[first], cols[first]] = which[first]
    bary[rows[first], cols[first]] = weights[first]
    if depth is not None:
        zbuf[rows[first], cols[first]] = z[first]
    return hit, bary, zbuf


def sample_bilinear(image: np.ndarray, xy: np.ndarray) -> np.ndarray:
    """(N, C) colours of ``image`` (H, W, C) at (N, 2) pixel positions (x, y; centres at +0.5), clamped."""
    height, width = image.shape[:2]
    x = np.clip(xy[:, 0] - 0.5, 0, width - 1)
    y = np.clip(xy[:, 1] - 0.5, 0, height - 1)
    x0 = np.minimum(x.astype(int), max(width - 2, 0))
    y0 = np.minimum(y.astype(int), max(height - 2, 0))
    x1, y1 = np.minimum(x0 + 1, width - 1), np.minimum(y0 + 1, height - 1)
    fx, fy = (x - x0)[:, None], (y - y0)[:, None]
    def at(rows: np.ndarray, cols: np.ndarray) -> np.ndarray:     # only the pixels sampled become floats
        return np.asarray(image[rows, cols], dtype=float)

    top = at(y0, x0) * (1 - fx) + at(y0, x1) * fx
    bottom = at(y1, x0) * (1 - fx) + at(y1, x1) * fx
    return np.asarray(top * (1 - fy) + bottom * fy)
