"""Type stub of the compiled deformation kernel ``engine.deform._kernel`` (source: ``_kernel.c``)."""

import numpy as np

ABI: int
SOURCE_SHA256: str

class Plan:
    """The static structure of one deformer; :meth:`deform` runs one frame."""

    def __init__(self, kind: np.ndarray, parent: np.ndarray, topo: np.ndarray, axis: np.ndarray,
                 pivot: np.ndarray, scale: np.ndarray, direction: np.ndarray, rest: np.ndarray,
                 order: np.ndarray, segments: np.ndarray, entries: np.ndarray, data: np.ndarray) -> None: ...
    @property
    def n_vertices(self) -> int: ...
    @property
    def n_segments(self) -> int:
        """Number of segments (runs of vertices moving alike)."""
    def deform(self, values: np.ndarray, out: np.ndarray, /) -> None:
        """Write the deformed (N, 3) positions for ``values`` (tree order) into ``out``."""
