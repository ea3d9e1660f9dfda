"""The default head's reference poses: the artist's poses shipped in ``reference-poses.h5`` (§2.2.2).

Each is a dense (N, 3) displacement of the default head's rest vertices, mm.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from engine.fitting.errors import FittingError, suggest_name


def reference_pose_names(path: str | Path | None = None) -> list[str]:
    """Names of the reference poses, ``"<group>/<pose>"`` (``arkit/jawOpen``, ``expression_units/...``)."""
    import h5py

    from engine.paths import reference_poses_path

    with h5py.File(path or reference_poses_path(), "r") as f:
        return [f"{g}/{n}" for g in ("arkit", "expression_units") if g in f for n in f[g]]


def reference_pose(name: str, path: str | Path | None = None) -> np.ndarray:
    """One reference pose of the default head as dense (N, 3) displacements, mm.

    ``name`` is ``"arkit/jawOpen"`` or, when unambiguous, just ``"jawOpen"``.
    ``path`` defaults to ``engine/data/default-head/reference-poses.h5``.
    """
    import h5py

    from engine.paths import reference_poses_path

    names = reference_pose_names(path)
    matches = [n for n in names if n == name or n.split("/", 1)[1] == name]
    if len(matches) != 1:
        why = "is ambiguous" if matches else "is not a reference pose"
        raise FittingError(f"'{name}' {why}{suggest_name(name, names) if not matches else ''}")
    with h5py.File(path or reference_poses_path(), "r") as f:
        D = np.zeros((len(f["source_vertex"]), 3))
        g = f[matches[0]]
        D[g["indices"][()]] = g["displacements"][()]
    return D

