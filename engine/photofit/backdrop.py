"""Where a photograph shows the person and not the backdrop: a weight per pixel for the texture.

A texel whose point on the fitted head projects onto the backdrop (the
fitted scalp a little outside the true one, an ear's rim) must not take the
backdrop's colour. On a plain backdrop (:func:`engine.photofit.silhouette.foreground`,
sampled at both side edges) the person is the foreground with its holes filled
(a highlight on the skin as pale as the backdrop is still the person) and
whatever lies well inside the fitted head's outline (a whole face as pale
as the backdrop, as in many studio portraits); the
weight is 0 within :data:`EDGE_MARGIN` px of the backdrop, where the lens and
anti-aliasing blend the two, and rises to 1 over :data:`FEATHER` px, so the
photograph fades out towards its outline instead of stopping at an edge. A
busy backdrop gives None: every pixel is used, as before.

>>> import numpy as np
>>> photo = np.full((40, 60, 3), 230, dtype=np.uint8)
>>> photo[5:35, 15:45] = (170, 120, 100)
>>> photo[20, 30] = 230                                  # a highlight as pale as the backdrop
>>> weight = subject_weight(photo)
>>> float(weight[20, 5]), float(weight[20, 15]), float(weight[20, 30])
(0.0, 0.0, 1.0)
"""

from __future__ import annotations

import numpy as np
from scipy.ndimage import binary_fill_holes, distance_transform_edt

from engine.photofit.silhouette import foreground

EDGE_MARGIN = 1.5                  # px from the backdrop where a pixel is not used at all
FEATHER = 4.0                      # px over which the weight then rises to 1


def subject_weight(photo: np.ndarray, inside: np.ndarray | None = None) -> np.ndarray | None:
    """(H, W) weights in 0 … 1 of the photograph's pixels for the texture, or None on a busy backdrop.

    ``inside`` (H, W) bool marks pixels that are the person whatever their colour: the fitted head's
    outline in the photograph, shrunk well inside its rim (:meth:`engine.photofit.texture.DepthBuffer.well_inside`).
    A face as pale as the backdrop, whose skin meets the backdrop along the jaw or the neck, is no hole in
    the foreground; without it such a face would count as backdrop and take no colour from the photograph.
    """
    mask = foreground(photo, both_sides=True)
    if mask is None:
        return None
    person = binary_fill_holes(mask if inside is None else mask | inside)
    distance = distance_transform_edt(person)
    return np.asarray(np.clip((distance - EDGE_MARGIN) / FEATHER, 0.0, 1.0))
