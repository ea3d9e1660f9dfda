"""Weights as colours for the viewport: a blue → red ramp, zero weight shown in the base colour.

The ramp is Google's *Turbo* (Mikhailo, 2019; Apache-2.0), sampled at 17
points and interpolated into a 256-entry table: a rainbow whose lightness
rises and falls smoothly, without the bands and dark spots of *jet*. Weight
0 exactly (outside the region) keeps the mesh's own colour, so the region's
edge is visible.

>>> import numpy as np
>>> c = heat_colors(np.array([0.0, 0.001, 0.5, 1.0]), base=(200, 200, 200))
>>> c[0].tolist(), c.dtype
([200, 200, 200], dtype('uint8'))
>>> bool(c[1, 2] > c[1, 0]), bool(c[3, 0] > c[3, 2])     # low weights blue, high red
(True, True)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from engine.errors import UserError

# Turbo at t = 0, 1/16, …, 1 (sRGB, 0–255; the values of matplotlib's "turbo")
_TURBO_17 = np.array([
    [48, 18, 59], [64, 64, 162], [70, 107, 227], [66, 148, 255], [40, 188, 235], [24, 221, 194],
    [50, 242, 152], [109, 254, 98], [164, 252, 60], [205, 236, 52], [238, 207, 58], [253, 172, 52],
    [251, 126, 33], [235, 80, 14], [208, 47, 5], [169, 22, 1], [122, 4, 3]], dtype=float)

# both ends of turbo are nearly black; the ramp runs over turbo(0.08 … 0.9) so a small weight is a
# clear blue and weight 1 a clear red
_t = np.linspace(0.0, 1.0, 17)
_s = np.linspace(0.08, 0.9, 256)
WEIGHT_RAMP = np.stack([np.interp(_s, _t, _TURBO_17[:, c]) for c in range(3)], axis=1).round().astype(np.uint8)
"""(256, 3) uint8: the colour of weight ``k / 255``."""

DEFAULT_BASE = (205, 205, 205)


def heat_colors(weights: npt.ArrayLike, base: npt.ArrayLike = DEFAULT_BASE,
                out: np.ndarray | None = None) -> np.ndarray:
    """(N, 3) uint8 colours for N weights in [0, 1]; weight 0 takes ``base``.

    ``base`` is one colour (3,) or one per weight (N, 3) — e.g. the model's
    part colours, so the region shows on top of the ordinary look. Pass
    ``out`` (N, 3) uint8 to write into an existing buffer. For a dab, colour
    only the changed vertices::

        colors[change.indices] = heat_colors(change.after, base=base_colors[change.indices])
    """
    w = np.asarray(weights, dtype=float).reshape(-1)
    k = np.rint(np.clip(w, 0.0, 1.0) * 255.0).astype(np.intp)
    colors = np.take(WEIGHT_RAMP, k, axis=0, out=out)
    zero = w <= 0.0
    if zero.any():
        b = np.asarray(base, dtype=np.uint8)
        if b.shape == (3,):
            colors[zero] = b
        elif b.shape == (len(w), 3):
            colors[zero] = b[zero]
        else:
            raise UserError(f"base colour must be (3,) or ({len(w)}, 3), not {b.shape}")
    return colors
