"""The weak-perspective camera of one photograph: scale, rotation, 2-D translation.

A point ``X`` (mm, head frame: +X the subject's left, +Y up, +Z forward)
lands at ``scale · (R X)[:2]`` flipped to image rows (y down) plus ``shift``
pixels. A portrait is taken from about a metre or more, where the head's
depth is a few percent of the distance, so perspective is nearly an overall
scale; the small remainder is taken up by the residual warp.

>>> import numpy as np
>>> camera = WeakPerspective(2.0, view_rotation("front"), np.array([320.0, 240.0]))
>>> camera.project(np.array([[10.0, 5.0, 99.0]])).tolist()
[[340.0, 230.0]]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial.transform import Rotation

#: Rows: the camera's right, up and towards-camera directions in head coordinates.
VIEW_AXES = {
    "front": ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)),
    "side": ((0.0, 0.0, -1.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0)),   # seen from the subject's left
}


def view_rotation(view: str) -> np.ndarray:
    return np.array(VIEW_AXES[view], dtype=float)


@dataclass
class WeakPerspective:
    """``scale`` px/mm, ``rotation`` (3, 3) head → camera (rows right, up, towards camera), ``shift`` (2,) px."""

    scale: float
    rotation: np.ndarray
    shift: np.ndarray

    def project(self, points: np.ndarray) -> np.ndarray:
        """(N, 2) pixel positions (x right, y down) of (N, 3) points."""
        camera = points @ self.rotation.T
        return self.scale * np.stack([camera[:, 0], -camera[:, 1]], axis=1) + self.shift

    def depth(self, points: np.ndarray) -> np.ndarray:
        """(N,) how far towards the camera each point is, mm (larger is nearer)."""
        return np.asarray(points @ self.rotation[2], dtype=float)

    def toward_camera(self) -> np.ndarray:
        return np.asarray(self.rotation[2], dtype=float)

    @classmethod
    def from_vector(cls, view: str, vector: np.ndarray) -> WeakPerspective:
        """From ``[log scale, rotation vector (3), shift (2)]``, the rotation relative to the view's."""
        turn = Rotation.from_rotvec(vector[1:4]).as_matrix()
        return cls(float(np.exp(vector[0])), turn @ view_rotation(view), np.asarray(vector[4:6], dtype=float))


def initial_vector(view: str, points: np.ndarray, pixels: np.ndarray) -> np.ndarray:
    """A start for :meth:`WeakPerspective.from_vector`: the view's rotation, scale and shift by the spread."""
    R = view_rotation(view)
    camera = points @ R.T
    flat = np.stack([camera[:, 0], -camera[:, 1]], axis=1)
    spread_model = np.sqrt(((flat - flat.mean(0)) ** 2).sum(1).mean())
    spread_photo = np.sqrt(((pixels - pixels.mean(0)) ** 2).sum(1).mean())
    scale = spread_photo / max(spread_model, 1e-9)
    shift = pixels.mean(0) - scale * flat.mean(0)
    return np.concatenate([[np.log(max(scale, 1e-9))], np.zeros(3), shift])
