"""The face's profile in the side photograph: where the head meets a plain background.

Studio portraits have a plain background; its colour is sampled at the
photograph's left edge, row by row, and the head is what differs from it
(:func:`foreground`). Along each row, the face's profile is the first
foreground pixel from the side the face looks to. :func:`profile_moves`
gives, for the fitted head's midline profile vertices, how far each must
move (in 3-D) to lie on that edge. A busy background (an edge that is not
nearly one colour per row) gives no profile, and the fit uses landmarks alone.

>>> import numpy as np
>>> photo = np.full((20, 30, 3), 240, dtype=np.uint8)
>>> photo[5:15, 12:30] = (150, 110, 90)
>>> mask = foreground(photo)
>>> bool(mask[10, 12]), bool(mask[10, 11])
(True, False)
"""

from __future__ import annotations

import numpy as np

from engine.model import Model
from engine.photofit.camera import WeakPerspective

BORDER = 0.03                          # fraction of each side taken as the background sample
BUSY_BACKGROUND = 20.0                 # RGB spread of the border above which no silhouette is used
MIN_CONTRAST = 40.0                    # RGB distance from the background that counts as the head
MIDLINE = 1.5                          # mm: profile vertices lie this close to the midline (x = 0)
FARTHEST_MOVE = 12.0                   # px: an edge farther than this from the fitted profile is not trusted
PROFILE_SPACING = 4.0                  # mm between the profile points used


def foreground(photo: np.ndarray, both_sides: bool = False) -> np.ndarray | None:
    """(H, W) bool: pixels unlike the background, or None when the background is not plain.

    The background is sampled row by row at the photograph's left edge, in front of the face (a side
    photograph is taken from the subject's left, so the face looks left), which allows for the
    vertical gradient of studio backdrops. With ``both_sides`` (a front photograph, or the texture's
    test of any photograph) the right edge is sampled too, and a pixel is background if it is like
    either edge's colour in its row; the background must be plain at both.
    """
    width = photo.shape[1]
    bw = max(int(width * BORDER), 1)
    borders = [photo[:, :bw].astype(float)] + ([photo[:, width - bw:].astype(float)] if both_sides else [])
    colours, spreads = [], []
    for border in borders:                                                # (H, bw, 3) each
        colours.append(np.median(border, axis=1))                         # (H, 3) per row
        spreads.append(float(np.median(np.linalg.norm(border - colours[-1][:, None], axis=2))))
    if max(spreads) > BUSY_BACKGROUND:
        return None
    pixels = photo.astype(np.float32)
    square = np.full(photo.shape[:2], np.inf, dtype=np.float32)
    for colour in colours:
        square = np.minimum(square, np.square(pixels - colour[:, None].astype(np.float32)).sum(axis=2))
    return np.asarray(square > max(MIN_CONTRAST, 4 * max(spreads)) ** 2)


def profile_vertices(model: Model, vertices: np.ndarray) -> np.ndarray:
    """Indices of skin vertices on the face's midline from the chin to the brows' height, PROFILE_SPACING apart."""
    skin = model.vertex_part == model.parts.index("skin") if "skin" in model.parts else np.ones(len(vertices), bool)
    chin, brow = model.landmarks.get("2.1"), model.landmarks.get("4.1")
    if chin is None or brow is None:
        return np.zeros(0, dtype=np.int64)
    low, high = vertices[chin, 1], vertices[brow, 1] + 10.0
    candidates = np.flatnonzero(skin & (np.abs(vertices[:, 0]) < MIDLINE) & (vertices[:, 1] >= low)
                                & (vertices[:, 1] <= high))
    if not len(candidates):
        return candidates
    # keep, per height band, the most forward vertex: the profile itself, not the inside of the mouth
    bands = np.floor((vertices[candidates, 1] - low) / PROFILE_SPACING).astype(int)
    chosen = [candidates[bands == b][np.argmax(vertices[candidates[bands == b], 2])] for b in np.unique(bands)]
    return np.asarray(chosen, dtype=np.int64)


def profile_moves(mask: np.ndarray, camera: WeakPerspective, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For (N, 3) profile points: which have a trusted edge (N,) bool, and their 3-D moves (N, 3) mm."""
    height = mask.shape[0]
    pixels = camera.project(points)
    forward = camera.project(points + np.array([0.0, 0.0, 1.0]))            # the head faces +Z
    facing = np.sign(np.median(forward[:, 0] - pixels[:, 0])) or -1.0      # the image direction the face looks to
    ok = np.zeros(len(points), dtype=bool)
    moves = np.zeros((len(points), 3))
    right = camera.rotation[0]
    for k, (x, y) in enumerate(pixels):
        row = int(y)
        if not 0 <= row < height:
            continue
        columns = np.flatnonzero(mask[row])
        if not len(columns):
            continue
        edge = (columns.min() if facing < 0 else columns.max() + 1) + 0.0
        shift = edge - x
        if abs(shift) <= FARTHEST_MOVE:
            ok[k] = True
            moves[k] = shift / camera.scale * right
    return ok, moves
