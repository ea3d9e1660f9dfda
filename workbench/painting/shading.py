"""The heat map paint mode draws: the weight's colour, made lighter or darker by the colour under it.

The flat heat map (:func:`engine.painting.heat_colors`) gives every vertex of
one weight the same colour, so while the painted parameter is held open
(Live preview) the lips, the teeth and the inside of the mouth of a jaw
region of weight 1 are all one red, and the shape the weights make is not
to be seen. Here each weight's colour keeps the lightness of the vertex's
own colour relative to the skin's: teeth lighter, the mouth's inside and
the lips darker, the skin exactly the ramp's colour (what the legend shows).
Weight 0 (outside the region) keeps the vertex's own colour, as before.

>>> import numpy as np
>>> skin, mouth = (224, 172, 148), (90, 40, 40)
>>> c = shaded_heat_colors(np.array([1.0, 1.0, 0.0]), np.array([skin, mouth, mouth], dtype=np.uint8))
>>> bool(c[1].sum() < c[0].sum()), c[2].tolist()      # the same weight, darker inside the mouth; 0: its own
(True, [90, 40, 40])
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from engine.painting import heat_colors

from ..viewport.colors import SKIN, hex_to_rgb

LUMA = np.array([0.299, 0.587, 0.114])
SKIN_LUMA = float(np.dot(hex_to_rgb(SKIN), LUMA))
DARKEST, LIGHTEST = 0.3, 1.25        # how far a vertex's own lightness may scale the ramp's colour
KEEP = 0.7                           # the share of the vertex's own lightness in the factor (the rest: 1)


def shaded_heat_colors(weights: npt.ArrayLike, base: npt.ArrayLike) -> np.ndarray:
    """(N, 3) uint8: ``heat_colors(weights, base)`` with each weighted vertex's colour scaled by its
    ``base`` colour's lightness relative to the skin's (``base``: (N, 3) uint8, the ordinary colours)."""
    base = np.asarray(base, dtype=np.uint8).reshape(-1, 3)
    colors = heat_colors(weights, base=base)
    inside = np.asarray(weights, dtype=float).reshape(-1) > 0.0
    if inside.any():
        lightness = base[inside].astype(float) @ LUMA / SKIN_LUMA
        factor = np.clip(1.0 - KEEP + KEEP * lightness, DARKEST, LIGHTEST)
        colors[inside] = np.clip(np.rint(colors[inside] * factor[:, None]), 0, 255).astype(np.uint8)
    return colors
