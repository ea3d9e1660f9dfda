"""The web player's camera: ``render --view``'s framing (:func:`engine.outputs.camera.camera_pose`) in a
form the player can redo for any canvas size, so a page of any shape shows the head as ``render`` would
at that size.

``camera_pose`` stands the camera on the view's axis at the distance where every framed point fits, with
a margin, both across (which depends on the picture's aspect) and up (which does not). Up, one number
does: the distance the height needs. Across, the distance is ``max_i(b_i + a_i / tan_x)`` over the points
(``a`` a point's distance from the axis sideways, ``b`` its depth in front of the focal plane, ``tan_x``
the half-width of the view, which grows with the aspect): the upper envelope of lines in ``1 / tan_x``,
so only the points on the convex hull of the ``(a, b)`` pairs that reach it for some aspect are kept —
a few dozen of the head's vertices. The player takes the larger of the two distances, as
``camera_pose`` does.

>>> from engine import load_model
>>> framing = web_framing(load_model())
>>> sorted(framing)
['behind', 'distance_up', 'in_front', 'sides', 'tan_half_height']
>>> 2 <= len(framing["sides"]) < 100
True
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from engine.outputs.camera import MARGIN, VIEW_ANGLE, VIEWS, framed_points

if TYPE_CHECKING:
    from engine.model import Model

__all__ = ["framed_distance", "near_far", "web_framing"]


def web_framing(model: Model, view: str = "front") -> dict[str, Any]:
    """What the player needs to frame the rest pose as ``render --view VIEW`` at any size (metres)."""
    points = framed_points(model)
    back = np.asarray(VIEWS[view], dtype=float)
    back /= np.linalg.norm(back)
    up = np.array([0.0, 1.0, 0.0])
    right = np.cross(up, back)
    right /= np.linalg.norm(right)
    u, v, w = points @ right, points @ up, points @ back
    cu, cv, cw = (u.min() + u.max()) / 2, (v.min() + v.max()) / 2, (w.min() + w.max()) / 2
    tan_y = float(np.tan(np.radians(VIEW_ANGLE) / 2) * (1 - 2 * MARGIN))
    distance_up = float(np.max((w - cw) + np.abs(v - cv) / tan_y))
    sides = _envelope(np.abs(u - cu), w - cw)
    return {"tan_half_height": tan_y, "distance_up": distance_up / 1000.0,
            "sides": [[round(float(a) / 1000.0, 9), round(float(b) / 1000.0, 9)] for a, b in sides],
            "in_front": float(w.max() - cw) / 1000.0, "behind": float(cw - w.min()) / 1000.0}


def framed_distance(framing: dict[str, Any], width: float, height: float) -> float:
    """The camera's distance from its focal point (metres) for a ``width`` × ``height`` picture: what the
    player computes, and what :func:`engine.outputs.camera.camera_pose` gives at that size."""
    tan_x = framing["tan_half_height"] * width / height
    across = max(b + a / tan_x for a, b in framing["sides"])
    return max(framing["distance_up"], across, 0.001)


def near_far(framing: dict[str, Any], distance: float) -> tuple[float, float]:
    """The clipping range (metres) at ``distance``, as ``camera_pose`` sets it (10 mm either side)."""
    near = max(distance - framing["in_front"] - 0.010, distance * 0.01)
    return near, distance + framing["behind"] + 0.010


def _envelope(a: np.ndarray, b: np.ndarray) -> list[tuple[float, float]]:
    """The pairs ``(a_i, b_i)`` on which ``max_i(b_i + a_i·s)`` is reached for some ``s`` > 0, in order of
    growing ``s``: from the point farthest in front (the widest of those) to the widest point."""
    first = int(np.lexsort((-a, -b))[0])            # largest b; of those, the largest a
    kept = [first]
    current = first
    while True:
        wider = a > a[current] + 1e-9
        if not wider.any():
            break
        # where each wider point overtakes the current one; the first to do so is the next on the envelope
        overtakes = np.full(a.shape, np.inf)
        overtakes[wider] = (b[current] - b[wider]) / (a[wider] - a[current])
        overtakes = np.maximum(overtakes, 0.0)
        soonest = overtakes.min()
        ties = np.flatnonzero(overtakes <= soonest + 1e-12)
        current = int(ties[np.argmax(a[ties])])
        kept.append(current)
    return [(float(a[i]), float(b[i])) for i in kept]
