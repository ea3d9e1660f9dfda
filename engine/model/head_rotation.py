"""A rigid rotation of the whole head → the values of the model's head turn, nod and tilt.

The default head turns its head by three nested rotations (§2.2.1): ``head_turn``
(about +Y), its child ``head_nod`` (about +X) and the nod's child
``head_tilt`` (about +Z). A child turns first and its parent turns the result,
each about its own rest axis, so together they turn the head by
``R = R_turn · R_nod · R_tilt``: intrinsic angles about the three axes, in the
tree's order. :func:`head_rotation_values` splits any rotation that way (on the
model's own axes, whatever they are, as long as each is at right angles to the
next) and gives each parameter's value (angle ÷ its degrees per unit).

>>> import numpy as np, engine
>>> head = engine.load_model()
>>> turn = np.radians(10)                          # 10° about +Y
>>> rotation = np.array([[np.cos(turn), 0, np.sin(turn)], [0, 1, 0], [-np.sin(turn), 0, np.cos(turn)]])
>>> names, values = head_rotation_values(head, rotation[None])
>>> names, (np.round(values, 4) + 0.0).tolist()            # + 0.0: no -0.0
(['head_turn', 'head_nod', 'head_tilt'], [[0.1745, 0.0, 0.0]])
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

import numpy as np

from engine.errors import ParameterError

if TYPE_CHECKING:
    from engine.model.model import Model

HEAD_ROTATIONS = ("head_turn", "head_nod", "head_tilt")


def head_rotation_values(model: Model, rotations: np.ndarray,
                         names: tuple[str, ...] = HEAD_ROTATIONS) -> tuple[list[str], np.ndarray]:
    """(the parameter names, outermost first; their values (F, 3)) turning the head by each of ``rotations``.

    ``rotations``: (F, 3, 3) rotation matrices in the model's axes (column
    vectors, ``x ↦ R x``). ``names`` are three rotation parameters, each the
    parent (or an ancestor) of the next in some order; raises
    :class:`~engine.errors.ParameterError` when the model lacks one, one is
    not a rotation, they do not nest, or an axis is not at right angles to the
    next one's.
    """
    from scipy.spatial.transform import Rotation

    tree = model.parameters
    missing = [n for n in names if n not in tree.names]
    if missing:
        raise ParameterError(f"the model has no head rotation {', '.join(repr(n) for n in missing)}")
    not_rotations = [n for n in names if tree[n].kind != "rotation"]
    if not_rotations:
        raise ParameterError(f"{', '.join(repr(n) for n in not_rotations)} must be rotations to turn the head")
    order = sorted(names, key=lambda n: len(tree.ancestors(n)))
    for outer, inner in itertools.pairwise(order):
        if outer not in tree.ancestors(inner):
            raise ParameterError(f"'{inner}' must be a child of '{outer}' to split a head rotation into "
                                 f"{', '.join(order)}")
    axes = np.array([np.asarray(tree[n].axis, dtype=float) for n in order])
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    if abs(axes[0] @ axes[1]) > 1e-6 or abs(axes[1] @ axes[2]) > 1e-6:
        raise ParameterError(f"the axes of {', '.join(order)} are not each at right angles to the next")
    matrices = np.asarray(rotations, dtype=float).reshape(-1, 3, 3)
    angles = Rotation.from_matrix(matrices).as_davenport(axes, "intrinsic")     # (F, 3) radians
    per_unit = np.array([tree[n].degrees_per_unit for n in order])
    return list(order), np.degrees(np.atleast_2d(angles)) / per_unit
