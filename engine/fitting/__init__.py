"""Fitting a parameter to an example pose (§2.2.2).

The paper set its parameters up by hand and proposed configuring them from
example poses "modeled by an artist, ... or a result of animating other
computer model", which it left under development. Given a pose — one
displacement per vertex of the rest mesh, mm — :func:`fit_parameter` finds one
new leaf parameter and its influence region that reproduce the pose at value 1
(Eq. 1 with ``v = 1``, every other parameter at rest):

* ``"rotation"``: an axis through a pivot and an angle θ, with per-vertex
  weights: ``d_i = w_i · (P_i · T(θ) − P_i)``;
* ``"translation"``: one direction ``v`` (mm), ``d_i = w_i · v``;
* ``"field"``: a field translation (blendshape), ``d_i = D_i`` — exact inside
  the region, nothing to fit.

Weights lie in [0, 1], are 0 outside the region, and minimise

    Σ_i |D_i − d_i|²  +  μ · Σ_(a, b) ∈ edges (w_a − w_b)²,     μ = smoothness · s²

where ``s`` is the largest displacement of the pose in the region (so
``smoothness`` has no unit; 0 means per-vertex weights). The method, the
choice of gauge (the largest weight is 1) and measured residuals on the
default head's reference poses are in ``docs/fitting.md``.

>>> import engine
>>> from engine.fitting import fit_parameter, reference_pose
>>> head = engine.load_model()
>>> pose = reference_pose("arkit/jawOpen")                     # (N, 3) mm
>>> fit = fit_parameter(head, pose, kind="rotation", name="jaw_drop", parent="head_tilt")
>>> round(fit.parameter.degrees_per_unit, 1), round(fit.residual_max_mm, 1)     # degrees, mm
(20.8, 4.4)
>>> fit.apply(head)                       # adds the parameter and its region
>>> P = head.deform(jaw_drop=1.0)         # ≈ rest + the pose
"""

from engine.fitting.errors import FittingError
from engine.fitting.mesh_regions import mesh_edges
from engine.fitting.parameter_fit import (
    DEFAULT_CORE,
    DEFAULT_SMOOTHNESS,
    FADE_RINGS,
    FIT_KINDS,
    MOVING_MM,
    fit_parameter,
    fit_pose,
)
from engine.fitting.reference_poses import reference_pose, reference_pose_names
from engine.fitting.result import FitResult

__all__ = [
    "DEFAULT_CORE",
    "DEFAULT_SMOOTHNESS",
    "FADE_RINGS",
    "FIT_KINDS",
    "MOVING_MM",
    "FitResult",
    "FittingError",
    "fit_parameter",
    "fit_pose",
    "mesh_edges",
    "reference_pose",
    "reference_pose_names",
]
