"""The result of a fit: the new parameter, its influence region, and how well they reproduce the pose (§2.2.2).

Residuals are per-vertex distances in mm.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from engine.fitting.errors import FittingError
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import ROTATION, Parameter


@dataclass
class FitResult:
    """A fitted parameter, its region, and how well they reproduce the pose.

    ``target`` is the pose and ``fitted`` the parameter's displacement at
    value 1 (both (N, 3), mm); ``allowed`` the vertices the fit could use
    (the region asked for). Residuals are per-vertex distances
    ``|target − fitted|`` in mm, over ``allowed`` (``residual_*``) and over
    the whole mesh (``mesh_residual_*``, which also counts the pose's motion
    outside the region). ``iterations`` counts the rounds of the smoothness
    alternation, ``seconds`` the fit's wall-clock time.
    """

    parameter: Parameter
    region: InfluenceRegion
    target: np.ndarray
    fitted: np.ndarray
    allowed: np.ndarray
    iterations: int
    seconds: float

    @property
    def weights(self) -> np.ndarray:
        """Dense per-vertex weights, (N,)."""
        return self.region.dense(len(self.target))

    @property
    def residual(self) -> np.ndarray:
        """``target − fitted``, (N, 3) mm."""
        return self.target - self.fitted

    @property
    def residual_rms_mm(self) -> float:
        return _rms(self.residual[self.allowed])

    @property
    def residual_max_mm(self) -> float:
        return float(np.linalg.norm(self.residual[self.allowed], axis=1).max())

    @property
    def mesh_residual_rms_mm(self) -> float:
        return _rms(self.residual)

    @property
    def mesh_residual_max_mm(self) -> float:
        return float(np.linalg.norm(self.residual, axis=1).max())

    @property
    def pose_rms_mm(self) -> float:
        """RMS displacement of the pose itself over the region (the scale of the residual)."""
        return _rms(self.target[self.allowed])

    @property
    def explained(self) -> float:
        """Share of the pose's squared displacement (whole mesh) that the parameter reproduces."""
        return 1.0 - float(np.sum(self.residual ** 2) / np.sum(self.target ** 2))

    def apply(self, model: Model) -> None:
        """Add the parameter and its region to ``model`` (a new leaf; the model announces the edit).

        Refuses a parent that is itself a leaf with an influence region: a
        child would turn it into a rigid group-1 parameter with normalised
        weights (§2.2) and change how it moves.
        """
        if model.n_vertices != len(self.target):
            raise FittingError(f"the fit is for {len(self.target)} vertices, the model has {model.n_vertices}")
        parent = self.parameter.parent
        if parent is not None and model.parameters.is_leaf(parent) and len(model.regions[parent].indices):
            raise FittingError(
                f"parent '{parent}' is a leaf with an influence region: a child would make it a rigid "
                "group-1 parameter with normalised weights and change how it moves; choose a rigid parent")
        model.add_parameter(self.parameter.copy(), self.region.copy())

    def summary(self) -> str:
        """One line: the transform, the region's size and the residuals."""
        p = self.parameter
        if p.kind == ROTATION:
            what = (f"rotation {p.degrees_per_unit:.2f}° about ({_fmt(p.axis, 3)}) "
                    f"through ({_fmt(p.pivot, 1)}) mm")
        elif p.field:
            what = "field translation"
        else:
            what = f"translation ({_fmt(p.direction, 2)}) mm"
        return (f"{p.name}: {what}, {len(self.region.indices)} vertices; residual RMS "
                f"{self.residual_rms_mm:.3f} mm, max {self.residual_max_mm:.3f} mm "
                f"(whole mesh {self.mesh_residual_rms_mm:.3f} / {self.mesh_residual_max_mm:.3f} mm); "
                f"{self.explained:.1%} of the pose")


def _rms(a: np.ndarray) -> float:
    return float(np.sqrt(np.mean(np.sum(a ** 2, axis=1)))) if len(a) else 0.0


def _fmt(v: np.ndarray, digits: int) -> str:
    return ", ".join(f"{x:.{digits}f}" for x in v)
