"""Where the camera of a rendered picture stands: the preset views and the framing of the model.

The head faces +Z with +Y up; :data:`VIEWS` gives, for each preset view, the
direction from the head towards the camera. :func:`camera_pose` places a
perspective camera that fits a set of points with a margin,
:func:`framed_points` chooses the points to fit (the head down to a little
below the chin) and :func:`place_camera` sets a pyvista camera. Lengths are
mm, angles degrees.

>>> import numpy as np
>>> cube = np.array([[x, y, z] for x in (-50, 50) for y in (-50, 50) for z in (-50, 50)], dtype=float)
>>> focal, position, up, near_far = camera_pose(cube, VIEWS["front"], 600, 800)
>>> focal.tolist(), bool(position[2] > 50), up.tolist()
([0.0, 0.0, 0.0], True, [0.0, 1.0, 0.0])
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

if TYPE_CHECKING:
    from engine.model import Model

VIEWS = {
    # direction from the head towards the camera; the head faces +Z, +Y up,
    # and the subject's left is +X
    "front": (0.0, 0.0, 1.0),
    "side": (1.0, 0.0, 0.0),
    "three-quarter": (np.sqrt(0.5), 0.0, np.sqrt(0.5)),
}
VIEW_ANGLE = 20.0                      # degrees, vertical; a portrait lens
MARGIN = 0.06                          # fraction of the picture kept free around the model
NECK_SHOWN = 0.10                      # neck shown below the chin, as a fraction of chin-to-crown height


def framed_points(model: Model) -> np.ndarray:
    """Rest-pose points the camera must show: the head down to a little below the chin.

    With a chin landmark (MPEG-4 2.1) the neck below it is left to be cropped, so
    the face fills more of the picture; without one the whole model is framed.
    """
    points = model.vertices
    chin = model.landmarks.get("2.1")
    if chin is None:
        return points
    chin_y = points[chin, 1]
    top = points[:, 1].max()
    if top <= chin_y:
        return points
    keep = points[:, 1] >= chin_y - NECK_SHOWN * (top - chin_y)
    return points[keep]


def place_camera(camera: Any, points: np.ndarray, toward_camera: ArrayLike, width: int, height: int) -> None:
    """Set a pyvista camera to :func:`camera_pose` (perspective, fits every point with a margin).

    ``points`` (N, 3) mm; ``toward_camera`` the direction from the model to
    the camera; ``width`` and ``height`` the picture's size in pixels.
    """
    focal, position, up, near_far = camera_pose(points, toward_camera, width, height)
    camera.focal_point = tuple(focal)
    camera.position = tuple(position)
    camera.up = tuple(up)
    camera.view_angle = VIEW_ANGLE
    camera.clipping_range = near_far


def camera_pose(points: np.ndarray, toward_camera: ArrayLike, width: int,
                height: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, tuple[float, float]]:
    """Focal point, position, view-up and clipping range (mm) of a perspective camera
    looking along ``-toward_camera`` that fits every point with a margin."""
    back = np.asarray(toward_camera, dtype=float)
    back /= np.linalg.norm(back)
    up = np.array([0.0, 1.0, 0.0])
    right = np.cross(up, back)
    right /= np.linalg.norm(right)
    u, v, w = points @ right, points @ up, points @ back
    cu, cv, cw = (u.min() + u.max()) / 2, (v.min() + v.max()) / 2, (w.min() + w.max()) / 2
    tan_y = np.tan(np.radians(VIEW_ANGLE) / 2) * (1 - 2 * MARGIN)
    tan_x = tan_y * width / height
    # distance from the focal plane such that every point projects inside the picture
    distance = max(np.max((w - cw) + np.abs(u - cu) / tan_x), np.max((w - cw) + np.abs(v - cv) / tan_y), 1.0)
    focal = cu * right + cv * up + cw * back
    near = max(distance - (w.max() - cw) - 10.0, distance * 0.01)
    return focal, focal + distance * back, up, (near, distance + (cw - w.min()) + 10.0)
