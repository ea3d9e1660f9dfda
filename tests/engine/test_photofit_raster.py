"""The rasteriser (engine/photofit/raster.py) draws batches of triangles at once: it must give, pixel for
pixel, what drawing them one at a time in order gives (the nearest wins with depths, the first of equals;
the last drawn without)."""

from __future__ import annotations

import numpy as np
import pytest

from engine.photofit.raster import rasterize


def one_at_a_time(tri, width, height, depth=None):
    """The rule written plainly: each triangle in turn, over its own bounding box."""
    hit = np.full((height, width), -1, dtype=np.int64)
    bary = np.zeros((height, width, 3))
    zbuf = np.full((height, width), -np.inf)
    for t, ((ax, ay), (bx, by), (cx, cy)) in enumerate(tri):
        area = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
        if abs(area) <= 1e-12:
            continue
        for row in range(height):
            for col in range(width):
                x, y = col + 0.5, row + 0.5
                if not (np.floor(min(ax, bx, cx) - 0.5) <= col < np.ceil(max(ax, bx, cx) - 0.5) + 1
                        and np.floor(min(ay, by, cy) - 0.5) <= row < np.ceil(max(ay, by, cy) - 0.5) + 1):
                    continue
                w1 = ((x - ax) * (cy - ay) - (cx - ax) * (y - ay)) / area
                w2 = ((bx - ax) * (y - ay) - (x - ax) * (by - ay)) / area
                w0 = 1.0 - w1 - w2
                if min(w0, w1, w2) < -1e-9:
                    continue
                if depth is not None:
                    z = w0 * depth[t][0] + w1 * depth[t][1] + w2 * depth[t][2]
                    if not z > zbuf[row, col]:
                        continue
                    zbuf[row, col] = z
                hit[row, col] = t
                bary[row, col] = (w0, w1, w2)
    return hit, bary, zbuf


@pytest.mark.parametrize("with_depth", [False, True])
@pytest.mark.parametrize("seed", range(4))
def test_batches_draw_what_one_at_a_time_draws(seed, with_depth):
    rng = np.random.default_rng(seed)
    width, height = 23, 17
    corners = rng.uniform(-4, 27, size=(60, 1, 2)) + rng.normal(scale=rng.uniform(0.5, 9, size=(60, 1, 1)),
                                                               size=(60, 3, 2))
    corners[5] = corners[4]                                     # the same triangle twice: equal depths
    corners[7, 2] = corners[7, 1]                               # a degenerate one
    depth = rng.uniform(0, 10, size=(60, 3)) if with_depth else None
    if with_depth:
        depth[5] = depth[4]
    got = rasterize(corners, width, height, depth)
    want = one_at_a_time(corners, width, height, depth)
    assert np.array_equal(got[0], want[0])
    np.testing.assert_allclose(got[1], want[1], rtol=0, atol=1e-12)
    np.testing.assert_allclose(got[2], want[2], rtol=0, atol=1e-12)
    assert (got[0] >= 0).sum() > 50


def test_large_triangles_drawn_a_few_at_a_time_draw_the_same(monkeypatch):
    from engine.photofit import raster

    rng = np.random.default_rng(9)
    corners = rng.uniform(-10, 50, size=(40, 3, 2))               # boxes of up to 40 × 40 px
    depth = rng.uniform(0, 10, size=(40, 3))
    monkeypatch.setattr(raster, "PIXELS_PER_BATCH", 900)          # a batch of 128 would pass it: halved down
    got = rasterize(corners, 40, 40, depth)
    want = one_at_a_time(corners, 40, 40, depth)
    assert np.array_equal(got[0], want[0])
    np.testing.assert_allclose(got[2], want[2], rtol=0, atol=1e-12)


def test_no_triangles_draw_nothing():
    hit, bary, zbuf = rasterize(np.zeros((0, 3, 2)), 5, 4)
    assert (hit == -1).all() and not bary.any() and np.isneginf(zbuf).all()
