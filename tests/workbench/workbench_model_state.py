"""Everything a model holds, as plain comparable data, for "undo restores it bit for bit" checks.

Arrays become (dtype, shape, bytes), so two states are equal only if every
bit of every array is. (The name is unique on purpose: test folders are on
``sys.path`` side by side.)
"""

from __future__ import annotations

import numpy as np

import engine


def _bits(array) -> tuple | None:
    if array is None:
        return None
    array = np.ascontiguousarray(array)
    return (array.dtype.str, array.shape, array.tobytes())


def model_state(model: engine.Model) -> dict:
    """The model's data: mesh, parts, the tree in order (every attribute), every region."""
    parameters = [
        (p.name, p.kind, p.parent, _bits(np.float64(p.minimum)), _bits(np.float64(p.maximum)),
         _bits(np.float64(p.default)), _bits(p.axis), _bits(p.pivot), _bits(np.float64(p.degrees_per_unit)),
         _bits(p.direction), p.field, p.description)
        for p in model.parameters]
    regions = {name: (_bits(r.indices), _bits(r.weights), _bits(r.displacements))
               for name, r in model.regions.items()}
    return {
        "vertices": _bits(model.vertices), "faces": _bits(model.faces), "parts": list(model.parts),
        "vertex_part": _bits(model.vertex_part), "vertex_colors": _bits(model.vertex_colors),
        "part_colors": dict(model.part_colors), "landmarks": dict(model.landmarks),
        "name": model.name, "description": model.description,
        "parameters": parameters, "regions": regions,
        "groups": {p.name: model.parameters.group(p.name) for p in model.parameters},
    }
