"""Fitting one new leaf parameter to an example pose (§2.2.2): the entry points and their input checks.

:func:`fit_parameter` fits a parameter of a model to a pose, :func:`fit_pose`
does the same on plain arrays. The solvers are :mod:`engine.fitting.solvers`,
the mesh's edges and the region :mod:`engine.fitting.mesh_regions`; the
method and the measured residuals are in ``docs/fitting.md``. Lengths are mm.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, TypedDict

import numpy as np
import numpy.typing as npt

from engine.fitting.errors import FittingError
from engine.fitting.mesh_regions import edge_incidence, mesh_edges, region_indices, resolve_region, vertices_near
from engine.fitting.result import FitResult
from engine.fitting.solvers import fit_motion, initial_direction, initial_rotation, rotation_motion
from engine.model.model import InfluenceRegion
from engine.model.parameters import ROTATION, TRANSLATION, Parameter

if TYPE_CHECKING:
    from engine.model.model import Model

FIT_KINDS = ("rotation", "translation", "field")
DEFAULT_SMOOTHNESS = 0.01
DEFAULT_CORE = 0.9
FADE_RINGS = 3            # with smoothness, weights may fade out this many edges beyond the moving vertices
MOVING_MM = 1e-9          # a vertex moved by less than this does not move (as in reference-poses.h5)


class _SharedFields(TypedDict):
    """The new parameter's fields that do not depend on the kind of fit."""

    parent: str | None
    minimum: float
    maximum: float
    default: float
    description: str


def fit_parameter(model: Model, displacements: npt.ArrayLike, kind: str = "rotation", *, name: str = "fitted",
                  parent: str | None = None, region: str | Sequence[str] | npt.ArrayLike | None = None,
                  smoothness: float = DEFAULT_SMOOTHNESS, **options: Any) -> FitResult:
    """Fit one new leaf parameter of ``model`` to a pose; the model is not changed.

    ``displacements``: (N, 3) mm per vertex of the rest mesh (see
    :func:`reference_pose`). ``kind``: ``"rotation"``, ``"translation"`` or
    ``"field"``. ``region``: where the parameter may act — vertex indices, a
    boolean mask, a part name or a list of part names; the whole mesh when
    omitted. ``smoothness``: weight of the edge term (no unit, see the module
    docstring). Other keywords go to :func:`fit_pose`. Call
    :meth:`FitResult.apply` to add the result to the model.
    """
    if parent is not None:
        model.parameters[parent]        # ParameterError with a suggestion when unknown
    allowed = resolve_region(model, region)
    return fit_pose(model.vertices, displacements, kind, edges=mesh_edges(model.faces), region=allowed,
                    smoothness=smoothness, name=name, parent=parent, **options)


def fit_pose(vertices: npt.ArrayLike, displacements: npt.ArrayLike, kind: str = "rotation", *,
             edges: npt.ArrayLike | None = None, region: npt.ArrayLike | None = None,
             smoothness: float = DEFAULT_SMOOTHNESS, core: float = DEFAULT_CORE, name: str = "fitted",
             parent: str | None = None, value_range: tuple[float, float] = (0.0, 1.0),
             min_weight: float = 1e-4, max_iterations: int = 50, description: str = "") -> FitResult:
    """:func:`fit_parameter` on plain arrays: rest ``vertices`` and ``displacements`` (N, 3, mm).

    ``edges``: (E, 2) vertex pairs for the smoothness term (none: no term).
    ``region``: vertex indices or an (N,) boolean mask. ``core``: vertices
    moving at least this fraction of the region's largest displacement keep
    weight 1 (the gauge, ``docs/fitting.md``; 1.0 holds only the farthest-moving one).
    Weights below ``min_weight`` are dropped from the region.
    ``value_range``: the new parameter's (min, max). ``max_iterations``:
    rounds of the smoothness alternation.
    """
    started = time.perf_counter()
    P = _points(vertices, "rest vertices")
    D = _points(displacements, "pose displacements")
    if D.shape != P.shape:
        raise FittingError(f"the pose has {len(D)} displacement vectors, the mesh {len(P)} vertices")
    if kind not in FIT_KINDS:
        raise FittingError(f"unknown fit kind '{kind}' (use {', '.join(FIT_KINDS)})")
    if not (_is_number(smoothness) and smoothness >= 0):
        raise FittingError(f"smoothness must be a number ≥ 0, not {smoothness!r}")
    if not (_is_number(core) and 0 < core <= 1):
        raise FittingError(f"core must be a number in (0, 1], not {core!r}")
    allowed = region_indices(region, len(P))
    moving = np.linalg.norm(D[allowed], axis=1) > MOVING_MM
    if not moving.any():
        raise FittingError(f"the pose moves none of the {len(allowed)} vertices of the region")
    if kind == "rotation" and moving.sum() < 3:
        raise FittingError("a rotation needs at least 3 moving vertices in the region")
    common: _SharedFields = dict(parent=parent, minimum=value_range[0], maximum=value_range[1], default=0.0,
                                 description=description)

    if kind == "field":          # a blendshape: the pose itself, exact inside the region
        idx = allowed[moving]
        fitted = np.zeros_like(P)
        fitted[idx] = D[idx]
        return FitResult(Parameter(name, TRANSLATION, field=True, **common),
                         InfluenceRegion(idx, np.ones(len(idx)), D[idx]), D, fitted, allowed, 0,
                         time.perf_counter() - started)

    # Still vertices take weight 0 (nothing to fit) except where smoothness fades the weights out:
    # only a few rings around the motion, beyond which the weights fall below min_weight.
    work = vertices_near(allowed[moving], allowed, edges, len(P), FADE_RINGS if smoothness > 0 else 0)
    Pr, Dr = P[work], D[work]
    B = edge_incidence(edges, work, len(P))
    size = np.linalg.norm(Dr, axis=1)
    mu = smoothness * float(size.max()) ** 2
    pin = size >= core * size.max()
    if kind == "rotation":
        x0, motion, unpack = rotation_motion(Pr, *initial_rotation(Pr, Dr))
        x, w, rounds = fit_motion(motion, x0, Dr, B, mu, pin, max_iterations)
        omega, pivot = unpack(x)
        angle = float(np.linalg.norm(omega))
        if angle < 1e-12:
            raise FittingError("the fitted rotation does not turn: the pose moves the region like a translation")
        axis = omega / angle
        centroid = (w @ Pr) / w.sum()
        pivot = pivot + ((centroid - pivot) @ axis) * axis      # the axis point nearest the moving part
        parameter = Parameter(name, ROTATION, axis=axis, pivot=pivot, degrees_per_unit=float(np.degrees(angle)),
                              **common)
    else:
        x, w, rounds = fit_motion(lambda v, rows=slice(None): np.broadcast_to(v, Dr[rows].shape),
                                   initial_direction(Dr), Dr, B, mu, pin, max_iterations)
        parameter = Parameter(name, TRANSLATION, direction=x, **common)
    w = np.where(w >= min_weight, np.clip(w, 0.0, 1.0), 0.0)
    keep = w > 0
    idx = work[keep]
    T = parameter.transform(1.0)         # the engine's own matrix, so the residual is the model's
    fitted = np.zeros_like(P)
    fitted[idx] = w[keep, None] * (P[idx] @ T[:3, :3] + T[3, :3] - P[idx])
    return FitResult(parameter, InfluenceRegion(idx, w[keep]), D, fitted, allowed, rounds,
                     time.perf_counter() - started)


def _points(values: npt.ArrayLike, what: str) -> np.ndarray:
    try:
        a = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise FittingError(f"{what} must be an (N, 3) array of numbers") from None
    if a.ndim != 2 or a.shape[1] != 3:
        raise FittingError(f"{what} must be an (N, 3) array, not shape {a.shape}")
    bad = ~np.isfinite(a).all(axis=1)
    if bad.any():
        raise FittingError(f"{what}: {int(bad.sum())} vertices have non-finite coordinates "
                           f"(first: vertex {int(np.flatnonzero(bad)[0])})")
    return a


def _is_number(value: object) -> bool:
    return isinstance(value, (int, float, np.number)) and bool(np.isfinite(value))
