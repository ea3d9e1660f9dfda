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


def rasterize(triangles: np.ndarray, width: int, height: int, depth: np.ndarray | None = None,
              should_stop: ShouldStop = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cover a ``height`` × ``width`` grid with (T, 3, 2) triangles (x, y in pixels; pixel centres at +0.5).

    Returns the triangle index of every pixel (−1 where none), the barycentric
    weights there (H, W, 3) and the depth (H, W; −inf where none). With
    ``depth`` (T, 3) the nearest (largest) wins; without, the last drawn. ``should_stop`` is asked
    every :data:`TRIANGLES_PER_STOP_CHECK` triangles (:mod:`engine.photofit.stopping`).
    """
    hit = np.full((height, width), -1, dtype=np.int64)
    bary = np.zeros((height, width, 3))
    zbuf = np.full((height, width), -np.inf)
    tri = np.asarray(triangles, dtype=float)
    lo = np.clip(np.floor(tri.min(axis=1) - 0.5).astype(int), 0, [width, height])
    hi = np.clip(np.ceil(tri.max(axis=1) - 0.5).astype(int) + 1, 0, [width, height])
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1])
    for drawn, t in enumerate(np.flatnonzero((np.abs(area) > 1e-12) & np.all(hi > lo, axis=1))):
        if drawn % TRIANGLES_PER_STOP_CHECK == 0:
            stop_if_asked(should_stop)
        xs = np.arange(lo[t, 0], hi[t, 0]) + 0.5
        ys = np.arange(lo[t, 1], hi[t, 1]) + 0.5
        X, Y = np.meshgrid(xs, ys)
        w1 = ((X - a[t, 0]) * (c[t, 1] - a[t, 1]) - (c[t, 0] - a[t, 0]) * (Y - a[t, 1])) / area[t]
        w2 = ((b[t, 0] - a[t, 0]) * (Y - a[t, 1]) - (X - a[t, 0]) * (b[t, 1] - a[t, 1])) / area[t]
        w0 = 1.0 - w1 - w2
        inside = (w0 >= -1e-9) & (w1 >= -1e-9) & (w2 >= -1e-9)
        if not inside.any():
            continue
        rows, cols = np.nonzero(inside)
        rows_g, cols_g = rows + lo[t, 1], cols + lo[t, 0]
        weights = np.stack([w0[inside], w1[inside], w2[inside]], axis=1)
        if depth is not None:
            z = weights @ depth[t]
            nearer = z > zbuf[rows_g, cols_g]
            rows_g, cols_g, weights, z = rows_g[nearer], cols_g[nearer], weights[nearer], z[nearer]
            zbuf[rows_g, cols_g] = z
        hit[rows_g, cols_g] = t
        bary[rows_g, cols_g] = weights
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
