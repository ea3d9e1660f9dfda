"""Where a head's landmarks start on a photograph before the user drags them: a sensible first guess.

:func:`initial_points` centres the head in the photograph and scales it to
fill :data:`FILL` of it (a cropped portrait), seen from the front or from the
subject's left, and projects the landmarks through that weak-perspective
camera. Once some points are placed, :func:`place_from` fits the camera
(scale and shift; the view's rotation) to them and puts the others where the
head says they are, so after dragging the pupils, nose, mouth and chin the
rest are close too.

>>> import numpy as np
>>> from engine.formats.model_files import load_model
>>> head = load_model()
>>> front = initial_points(head, "front", 900, 1200)
>>> x, y = front["9.3"]                                  # the nose tip: near the middle, above the centre
>>> bool(350 < x < 550 and 300 < y < 700)
True
>>> front["3.5"][0] > front["3.6"][0]                    # the subject's left pupil on the viewer's right
True
>>> moved = {k: (x + 40.0, y) for k, (x, y) in front.items() if k in ("3.5", "3.6", "2.1")}
>>> round(place_from(head, "front", moved)["9.3"][0] - x)
40
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from engine.model import Model
from engine.photofit.camera import WeakPerspective, initial_vector, view_rotation
from engine.photofit.face_points import point_index, point_vertices

#: How much of the photograph's width or height (whichever binds) the head fills at first.
FILL = 0.8
#: mm: a side photograph (taken from the subject's left, +X) shows landmarks at least this far left of the
#: middle; ones farther right are behind the face.
SIDE_MIDLINE_SLACK = 3.0

Pixels = dict[str, tuple[float, float]]


def visible_landmarks(model: Model, view: str) -> list[str]:
    """The landmark ids a ``view`` photograph shows: all from the front; the left and the middle from the side."""
    where = point_vertices(model)
    ids = sorted(where, key=_id_order)
    if view == "side":
        ids = [k for k in ids if model.vertices[where[k], 0] > -SIDE_MIDLINE_SLACK and not k.startswith("ibug.")]
    return ids


def initial_camera(model: Model, view: str, width: int, height: int) -> WeakPerspective:
    """The camera that shows ``model`` from ``view`` centred in a ``width`` × ``height`` photograph."""
    unit = WeakPerspective(1.0, view_rotation(view), np.zeros(2))
    flat = unit.project(model.vertices)
    low, high = flat.min(axis=0), flat.max(axis=0)
    extent = np.maximum(high - low, 1e-9)
    scale = FILL * float(min(width / extent[0], height / extent[1]))
    shift = np.array([width / 2.0, height / 2.0]) - scale * (low + high) / 2
    return WeakPerspective(scale, unit.rotation, shift)


def initial_points(model: Model, view: str, width: int, height: int) -> Pixels:
    """Pixels of ``model``'s landmarks a ``view`` photograph shows, by :func:`initial_camera`."""
    return _project(model, initial_camera(model, view, width, height), visible_landmarks(model, view))


def place_from(model: Model, view: str, placed: Mapping[str, tuple[float, float]]) -> Pixels:
    """Every landmark the view shows, by the camera (scale, shift) that best fits the ``placed`` ones.

    Needs two placed points or more (fewer: :class:`ValueError`); the placed ones are kept as they are.
    """
    known = point_vertices(model)
    ids = [k for k in placed if k in known]
    if len(ids) < 2:
        raise ValueError("place at least two landmarks first")
    points = model.vertices[point_index(model, ids)]
    pixels = np.array([placed[k] for k in ids], dtype=float)
    camera = WeakPerspective.from_vector(view, initial_vector(view, points, pixels))
    out = _project(model, camera, visible_landmarks(model, view))
    out.update({k: (float(x), float(y)) for k, (x, y) in placed.items() if k in out})
    return out


def _project(model: Model, camera: WeakPerspective, ids: list[str]) -> Pixels:
    pixels = camera.project(model.vertices[point_index(model, ids)])
    return {k: (float(x), float(y)) for k, (x, y) in zip(ids, pixels, strict=True)}


def _id_order(key: str) -> tuple[int, ...]:
    """MPEG-4 ids in their groups' order, then the iBUG points in theirs."""
    if key.startswith("ibug."):
        return (1 << 30, int(key.split(".")[1]))
    try:
        return tuple(int(p) for p in key.split("."))
    except ValueError:
        return (1 << 31,)
