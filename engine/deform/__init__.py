"""The deformation engine of §2.2: parameter values → vertex positions.

* :class:`Deformer` — the fast path (a compiled kernel, ``_kernel.c``, with a numpy fallback)
  built once per model revision; :func:`deform_reference` — the equations written out plainly.
* 4×4 homogeneous transforms in the paper's row-vector convention (``transforms.py``).

``docs/deformation.md`` derives the formulation and its invariants.

>>> from engine.deform import Deformer, deform_reference
"""

from engine.deform.deformer import Deformer, deform_reference

__all__ = ["Deformer", "deform_reference"]
