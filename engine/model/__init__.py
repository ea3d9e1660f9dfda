"""The animated object (§2.2): rest mesh, parts, parameter tree, influence regions, landmarks.

* :class:`Model`, :class:`InfluenceRegion` — the mesh and its parameters' regions (``model.py``).
* :class:`Parameter`, :class:`ParameterTree` — rotations and translations in a tree (``parameters.py``).
* polygons as a flat cell array (``cells.py``), MPEG-4 feature points (``landmarks.py``),
  subdivision of a whole model (``subdivide.py``).

>>> from engine.model import Model, Parameter, ParameterTree
"""

from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import KINDS, ROTATION, TRANSLATION, Parameter, ParameterTree

__all__ = ["KINDS", "ROTATION", "TRANSLATION", "InfluenceRegion", "Model", "Parameter", "ParameterTree"]
