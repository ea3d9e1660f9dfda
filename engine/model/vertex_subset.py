"""A model cut down to a few of its vertices, which deforms exactly like the whole model there (§2.2).

Every influence region is cut to the chosen vertices and the parameter tree is
kept whole, so deforming the copy gives the full model's positions at those
vertices in microseconds instead of milliseconds: what the landmarks table, the
motion-capture markers and the lip checks need, without moving the whole mesh.

>>> import numpy as np
>>> from engine import load_model
>>> head = load_model()
>>> lips = model_at_landmarks(head, ["8.1", "8.2"])
>>> moved = head.deform({"jaw_open": 0.5})[[head.landmarks["8.1"], head.landmarks["8.2"]]]
>>> bool(np.allclose(lips.deform({"jaw_open": 0.5}), moved, rtol=0, atol=1e-9))
True
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

import numpy as np
import numpy.typing as npt

from engine.errors import UserError
from engine.model.model import InfluenceRegion, Model

__all__ = ["model_at_landmarks", "model_at_vertices"]


def model_at_landmarks(model: Model, keys: Iterable[str]) -> Model:
    """A copy of ``model`` reduced to the vertices of the landmarks ``keys`` (in that order).

    It deforms exactly like the full model at those vertices, in microseconds
    instead of milliseconds: every influence region is cut down to them and
    the parameter tree is kept whole. Its landmarks are ``keys`` → 0, 1, ….
    """
    keys = [str(k) for k in keys]
    missing = [k for k in keys if k not in model.landmarks]
    if missing:
        raise UserError(f"the model has no landmark {', '.join(missing)}")
    vertices = np.array([model.landmarks[k] for k in keys], dtype=np.int64)
    return model_at_vertices(model, vertices, landmarks={k: i for i, k in enumerate(keys)})


def model_at_vertices(model: Model, vertices: npt.ArrayLike, landmarks: Mapping[str, int] | None = None) -> Model:
    """A copy of ``model`` reduced to the given vertex indices (no faces); see :func:`model_at_landmarks`.

    A vertex listed twice appears twice, with the same weights.
    """
    vertices = np.asarray(vertices, dtype=np.int64).reshape(-1)
    regions = {}
    for name, region in model.regions.items():
        pos = np.searchsorted(region.indices, vertices)        # region indices are sorted
        inside = pos < len(region.indices)
        inside[inside] = region.indices[pos[inside]] == vertices[inside]
        new_index, old = np.flatnonzero(inside), pos[inside]
        displacements = None if region.displacements is None else region.displacements[old].reshape(-1, 3)
        regions[name] = InfluenceRegion(new_index, region.weights[old] if len(old) else np.zeros(0), displacements)
    return Model(model.vertices[vertices], np.zeros(0, dtype=np.int64), list(model.parts),
                 model.vertex_part[vertices], model.parameters.copy(), regions, landmarks or {},
                 name=f"{model.name} (markers)")
