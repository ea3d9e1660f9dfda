"""FXAA on the read-back frame (issue 36): smoother edges than none, close to supersampling, and cheap
because only edge pixels are touched (counted, not timed)."""

from __future__ import annotations

import numpy as np

from engine.outputs.antialias import fxaa

SLOPE, OFFSET, SIZE, SUB = 0.27, 11.3, (64, 96), 8


def _edge(samples: int) -> np.ndarray:
    """A dark shape under a bright sky whose edge is the line y = SLOPE·x + OFFSET, drawn with
    samples × samples samples a pixel (box-averaged), as RGB uint8."""
    height, width = SIZE
    offsets = (np.arange(samples) + 0.5) / samples
    ys = (np.arange(height)[:, None] + offsets[None, :]).reshape(-1)
    xs = (np.arange(width)[:, None] + offsets[None, :]).reshape(-1)
    inside = (ys[:, None] > SLOPE * xs[None, :] + OFFSET).astype(np.float64)
    grey = inside.reshape(height, samples, width, samples).mean(axis=(1, 3))
    value = np.rint(230 - 200 * grey).astype(np.uint8)
    return np.repeat(value[:, :, None], 3, axis=2)


def _error(image: np.ndarray, reference: np.ndarray) -> float:
    return float(np.abs(image.astype(int) - reference.astype(int)).mean())


def _largest_step_along_edge(image: np.ndarray) -> int:
    """Edge-step statistic: the largest jump between horizontally adjacent pixels on the edge rows
    (a stair-stepped edge jumps by the whole contrast, a smooth one by a fraction of it)."""
    grey = image[..., 1].astype(int)
    return int(np.abs(np.diff(grey, axis=1)).max())


def test_fxaa_smooths_a_stair_stepped_edge_towards_supersampling() -> None:
    aliased, supersampled = _edge(1), _edge(SUB)
    smoothed = fxaa(aliased)
    assert _error(smoothed, supersampled) < 0.7 * _error(aliased, supersampled)
    assert _largest_step_along_edge(smoothed) < 0.75 * _largest_step_along_edge(aliased)
    assert _largest_step_along_edge(aliased) == 200


def test_fxaa_touches_only_the_pixels_near_an_edge() -> None:
    aliased = _edge(1)
    changed = np.any(fxaa(aliased) != aliased, axis=2)
    rows, cols = np.nonzero(changed)
    assert changed.sum() > 0
    assert np.all(np.abs(rows - (SLOPE * cols + OFFSET)) < 3)        # within a few pixels of the line
    assert changed.mean() < 0.1


def test_fxaa_leaves_a_flat_picture_alone_and_keeps_shape_and_type() -> None:
    flat = np.full((9, 7, 3), 77, dtype=np.uint8)
    out = fxaa(flat)
    assert out.shape == flat.shape and out.dtype == np.uint8 and (out == 77).all()
    assert out is not flat


def test_fxaa_in_place_gives_the_same_picture_and_leaves_a_copy_alone() -> None:
    aliased = _edge(1)
    copied = fxaa(aliased)
    assert not np.array_equal(copied, aliased)               # the original is untouched …
    assert np.array_equal(aliased, _edge(1))
    frame = aliased.copy()
    smoothed = fxaa(frame, copy=False)                       # … a fresh frame is smoothed where it is
    assert smoothed is frame and np.array_equal(smoothed, copied)
    flipped = aliased[::-1]                                  # not contiguous: copied even when asked not to
    assert fxaa(flipped, copy=False) is not flipped and np.array_equal(flipped, aliased[::-1])
