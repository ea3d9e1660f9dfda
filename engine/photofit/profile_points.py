"""A side photograph's landmarks estimated from its silhouette (dlib's models find no profile)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from engine.model import Model
from engine.photofit.errors import PhotoFitError


def profile_points(base: Model, photo: np.ndarray, path: str | Path | None = None) -> dict[str, tuple[float, float]]:
    """The side photograph's landmarks, px (not yet made: refused)."""
    raise PhotoFitError("a side photograph's points are not found by themselves (dlib's models find frontal faces "
                        "only): place them in the workbench's photo wizard, or give --landmarks POINTS.json with a "
                        "'side' view", file=path)
