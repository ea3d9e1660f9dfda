"""The animated object (§2.2): rest mesh, parts, parameter tree, influence regions, landmarks.

* :class:`Model`, :class:`InfluenceRegion` — the mesh and its parameters' regions (``model.py``).
* :class:`Parameter`, :class:`ParameterTree` — rotations and translations in a tree (``parameters.py``).
* :mod:`~engine.model.edits` — tree edits (add, remove, rename, move, replace, restore), each
  returning the :class:`TreeState` that undoes it.
* :class:`WeightChange`, :func:`apply_weight_change` — weights of some vertices of one region changed,
  applied with its exact inverse returned (``weight_changes.py``).
* polygons as a flat cell array (``cells.py``), MPEG-4 feature points (``landmarks.py``),
  subdivision of a whole model (``subdivide.py``).

>>> from engine.model import Model, Parameter, ParameterTree
"""

from engine.model.edits import TreeState, restore_tree
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import KINDS, ROTATION, TRANSLATION, Parameter, ParameterTree
from engine.model.weight_changes import WeightChange, apply_weight_change

__all__ = ["KINDS", "ROTATION", "TRANSLATION", "InfluenceRegion", "Model", "Parameter", "ParameterTree",
           "TreeState", "WeightChange", "apply_weight_change", "restore_tree"]
