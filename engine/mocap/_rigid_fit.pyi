"""Type stub of the compiled batched Kabsch ``engine.mocap._rigid_fit`` (source: ``_rigid_fit.c``)."""

import numpy as np

SOURCE_SHA256: str

def rotations(H: np.ndarray, R: np.ndarray, S: np.ndarray, /) -> None:
    """Write the Kabsch rotations of the (F, 3, 3) float64 ``H`` into ``R`` and their singular values into ``S``."""

def move(P: np.ndarray, A: np.ndarray, out: np.ndarray, /) -> None:
    """Write ``P · A[:3, :3] + A[3, :3]`` per frame into ``out`` ((F, M, 3) and (F, 4, 4) float64)."""
