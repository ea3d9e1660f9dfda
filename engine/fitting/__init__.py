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
(22.8, 4.3)
>>> fit.apply(head)                       # adds the parameter and its region
>>> P = head.deform(jaw_drop=1.0)         # ≈ rest + the pose
"""

from __future__ import annotations

import difflib
import time
from dataclasses import dataclass

import numpy as np
from scipy import sparse
from scipy.optimize import least_squares
from scipy.sparse.linalg import spsolve

from engine.errors import UserError
from engine.model.model import InfluenceRegion
from engine.model.parameters import ROTATION, TRANSLATION, Parameter

FIT_KINDS = ("rotation", "translation", "field")
DEFAULT_SMOOTHNESS = 0.01
DEFAULT_CORE = 0.9
FADE_RINGS = 3            # with smoothness, weights may fade out this many edges beyond the moving vertices
MOVING_MM = 1e-9          # a vertex moved by less than this does not move (as in reference-poses.h5)


class FittingError(UserError):
    """A pose, region or option that cannot be fitted."""


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

    def apply(self, model) -> None:
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


# -- public entry points ---------------------------------------------------------

def fit_parameter(model, displacements, kind: str = "rotation", *, name: str = "fitted",
                  parent: str | None = None, region=None, smoothness: float = DEFAULT_SMOOTHNESS,
                  **options) -> FitResult:
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
    allowed = _resolve_region(model, region)
    return fit_pose(model.vertices, displacements, kind, edges=mesh_edges(model.faces), region=allowed,
                    smoothness=smoothness, name=name, parent=parent, **options)


def fit_pose(vertices, displacements, kind: str = "rotation", *, edges=None, region=None,
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
    allowed = _region_indices(region, len(P))
    moving = np.linalg.norm(D[allowed], axis=1) > MOVING_MM
    if not moving.any():
        raise FittingError(f"the pose moves none of the {len(allowed)} vertices of the region")
    if kind == "rotation" and moving.sum() < 3:
        raise FittingError("a rotation needs at least 3 moving vertices in the region")
    common = dict(parent=parent, minimum=value_range[0], maximum=value_range[1], default=0.0,
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
    work = _near(allowed[moving], allowed, edges, len(P), FADE_RINGS if smoothness > 0 else 0)
    Pr, Dr = P[work], D[work]
    B = _incidence(edges, work, len(P))
    size = np.linalg.norm(Dr, axis=1)
    mu = smoothness * float(size.max()) ** 2
    pin = size >= core * size.max()
    if kind == "rotation":
        x0, motion, unpack = _rotation_motion(Pr, *_initial_rotation(Pr, Dr))
        x, w, rounds = _fit_motion(motion, x0, Dr, B, mu, pin, max_iterations)
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
        x, w, rounds = _fit_motion(lambda v, rows=slice(None): np.broadcast_to(v, Dr[rows].shape),
                                   _initial_direction(Dr), Dr, B, mu, pin, max_iterations)
        parameter = Parameter(name, TRANSLATION, direction=x, **common)
    w = np.where(w >= min_weight, np.clip(w, 0.0, 1.0), 0.0)
    keep = w > 0
    idx = work[keep]
    T = parameter.transform(1.0)         # the engine's own matrix, so the residual is the model's
    fitted = np.zeros_like(P)
    fitted[idx] = w[keep, None] * (P[idx] @ T[:3, :3] + T[3, :3] - P[idx])
    return FitResult(parameter, InfluenceRegion(idx, w[keep]), D, fitted, allowed, rounds,
                     time.perf_counter() - started)


# -- the solvers (on the region's vertices only) ----------------------------------
#
# The gauge. Scaling the weights down while turning further (or moving the
# pivot far away) changes a rotation's fit little, and left free the search
# drifts to large angles with small weights: a jaw that turns 31° at weight
# 0.7 instead of 22° at weight 1, which shrinks the rigid teeth. So the
# vertices that move at least ``core`` times as far as the farthest-moving one
# are held at weight 1: the motion is that of the part that moves fully.

def _fit_motion(motion, x0, D, B, mu, pin, max_iterations):
    """Fit the parameters ``x`` of ``motion(x)`` (n, 3: each vertex's displacement at weight 1) and the weights.

    First the motion alone, each vertex taking its best weight in closed
    form (variable projection, no smoothness); then, when ``mu > 0``,
    alternate smooth weights and motion. Every step is an exact least-squares
    solve for its own unknowns, so the objective never rises. Returns ``x``,
    the weights and the number of alternation rounds.
    """
    lm = dict(method="lm", xtol=1e-10, ftol=1e-10, gtol=1e-10, max_nfev=1000)

    def residual(x):
        R = motion(x)
        return (D - _best_weights(R, D, pin)[:, None] * R).ravel()

    x = least_squares(residual, x0, **lm).x
    if mu == 0 or B.shape[0] == 0:
        return x, _best_weights(motion(x), D, pin), 0
    cost_before, it = np.inf, 0
    for it in range(1, max_iterations + 1):
        w = _weight_step(motion(x), D, B, mu, pin)
        use = np.flatnonzero(w > 0)
        if 3 * len(use) < len(x):               # too few weighted vertices to move the transform
            break
        x = least_squares(lambda x: (D[use] - w[use, None] * motion(x, use)).ravel(), x, **lm).x
        cost = _cost(D, w[:, None] * motion(x), w, B, mu)
        if cost_before - cost <= 1e-4 * cost:       # the rounds gain < 1 % in all (docs/fitting.md)
            break
        cost_before = cost
    return x, _weight_step(motion(x), D, B, mu, pin), it


def _initial_rotation(P, D):
    """Kabsch on the vertices moving at least half the most, taken as rigid with weight 1."""
    mag = np.linalg.norm(D, axis=1)
    strong = np.flatnonzero(mag >= 0.5 * mag.max())
    if len(strong) < 3:
        strong = np.argsort(mag)[-3:]
    a, b = P[strong], P[strong] + D[strong]
    ca, cb = a.mean(axis=0), b.mean(axis=0)
    U, _, Vt = np.linalg.svd((a - ca).T @ (b - cb))
    d = np.sign(np.linalg.det(Vt.T @ U.T)) or 1.0
    R = Vt.T @ np.diag([1.0, 1.0, d]) @ U.T                 # b − cb ≈ R (a − ca), column convention
    omega = _rotation_vector(R)
    if np.linalg.norm(omega) < 1e-4:
        # (almost) a pure translation: a rotation of large radius about an axis across the motion
        move = (b - a).mean(axis=0)
        axis = np.cross(move, np.eye(3)[np.argmin(np.abs(move))])
        axis /= np.linalg.norm(axis)
        radius = 1000.0 * max(1.0, float(np.ptp(P, axis=0).max()))
        pivot = ca + radius * np.cross(axis, move / np.linalg.norm(move))     # so ca starts off along move
        return axis * (np.linalg.norm(move) / radius), pivot
    A = R.T                                                  # row convention: b ≈ a · A + t
    pivot = np.linalg.lstsq((np.eye(3) - A).T, cb - ca @ A, rcond=1e-8)[0]   # pivot·(I − A) = t, bar the slide
    return omega, pivot


def _initial_direction(D):
    """The direction u maximising Σ max(0, D_i · u)², scaled to the largest projection.

    The top principal axis of the vertices moving along it, by a fixed-point
    iteration that never lowers the sum; without a core and smoothness this
    is already the least-squares translation (vertices moving against it get
    weight 0, the one moving most along it weight 1).
    """
    u = np.linalg.svd(D, full_matrices=False)[2][0]
    u = -u if (D @ u).sum() < 0 else u
    for _ in range(100):
        along = D[D @ u > 0]
        new = np.linalg.svd(along, full_matrices=False)[2][0]
        new = -new if (along @ new).sum() < 0 else new
        if np.allclose(new, u, rtol=0, atol=1e-15):
            break
        u = new
    return u * (D @ u).max()


def _rotation_motion(P, omega, pivot):
    """Five unknowns around a rotation: ``ω`` (radians) and the pivot's shift across the axis.

    Sliding the pivot along the axis changes nothing, so it moves only in the
    plane across the starting axis, in units of the region's size (so the
    unknowns have comparable scales). Returns ``x0``, ``motion(x)`` and
    ``unpack(x) → (ω, pivot)``.
    """
    u = omega / np.linalg.norm(omega)
    e1 = np.cross(u, np.eye(3)[np.argmin(np.abs(u))])
    e1 /= np.linalg.norm(e1)
    size = float(np.sqrt(((P - P.mean(axis=0)) ** 2).sum(axis=1).mean())) or 1.0
    across = np.stack([e1, np.cross(u, e1)]) * size

    def unpack(x):
        return x[:3], pivot + x[3:] @ across

    def motion(x, rows=slice(None)):
        return _chords(P[rows], *unpack(x))

    return np.concatenate([omega, [0.0, 0.0]]), motion, unpack


def _best_weights(R, D, pin):
    """Each vertex's best weight in [0, 1] for the motion ``R`` (closed form), 1 where ``pin``."""
    h = np.einsum("ij,ij->i", R, R)
    g = np.einsum("ij,ij->i", R, D)
    w = np.clip(np.divide(g, h, out=np.zeros_like(g), where=h > 0), 0.0, 1.0)
    w[pin] = 1.0
    return w


def _weight_step(R, D, B, mu, pin):
    """Weights in [0, 1], 1 where ``pin``, minimising Σ |D_i − w_i R_i|² + μ |B w|² (a sparse box QP)."""
    h = np.einsum("ij,ij->i", R, R)
    g = np.einsum("ij,ij->i", R, D)
    ridge = 1e-12 * max(float(h.max()), mu)                # keeps still vertices determined (they go to 0)
    H = (sparse.diags(h + ridge) + mu * (B.T @ B)).tocsr()
    return _box_qp(H, g, pin)


def _box_qp(H, g, pin, max_iterations: int = 100):
    """argmin ½ wᵀHw − gᵀw over 0 ≤ w ≤ 1 with w = 1 where ``pin``: primal-dual active set.

    H = diagonal + μ·Laplacian is an M-matrix, for which the method ends in
    finitely many steps (Hintermüller, Ito & Kunisch 2003), each one sparse
    solve; typically 2–6 here.
    """
    c = H.diagonal()
    w = np.clip(g / c, 0.0, 1.0)
    w[pin] = 1.0
    lam = g - H @ w
    lower = upper = None
    for _ in range(max_iterations):
        # ties (a still vertex at 0 with nothing pulling it up) go to the bounds: smaller solves
        new_lower, new_upper = (lam + c * w < 0) & ~pin, (lam + c * (w - 1.0) > 0) | pin
        if lower is not None and np.array_equal(new_lower, lower) and np.array_equal(new_upper, upper):
            break
        lower, upper = new_lower, new_upper
        free = ~(lower | upper)
        w = upper.astype(float)
        if free.any():
            rhs = g[free] - H[free][:, upper] @ np.ones(int(upper.sum()))
            w[free] = spsolve(H[free][:, free].tocsc(), rhs) if free.sum() > 1 else rhs / c[free]
        lam = g - H @ w
        lam[free] = 0.0
    return np.clip(w, 0.0, 1.0)


def _cost(D, fitted, w, B, mu):
    return float(np.sum((D - fitted) ** 2) + mu * np.sum((B @ w) ** 2))


def _chords(P, omega, pivot):
    """``P · T − P`` for the rotation by the vector ``ω`` (radians) about an axis through ``pivot``."""
    return (P - pivot) @ (_rotation_matrix(omega).T - np.eye(3))


def _rotation_matrix(omega):
    """Rodrigues: the rotation by |ω| radians about ω (column convention)."""
    theta = float(np.linalg.norm(omega))
    if theta == 0.0:
        return np.eye(3)
    x, y, z = np.asarray(omega) / theta
    K = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    return np.eye(3) + np.sin(theta) * K + (1.0 - np.cos(theta)) * (K @ K)


def _rotation_vector(R):
    """The rotation vector (axis × angle, radians) of a rotation matrix, also near 180°."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_matrix(R).as_rotvec()


# -- mesh, region, and input checks ----------------------------------------------

def mesh_edges(faces) -> np.ndarray:
    """The unique edges (E, 2), smaller index first, of a flat polygon cell array."""
    from engine.model.cells import cell_sizes, cell_starts

    cells = np.asarray(faces, dtype=np.int64).reshape(-1)
    sizes = cell_sizes(cells)
    starts = cell_starts(sizes)
    pairs = []
    for k in np.unique(sizes):
        poly = cells[starts[sizes == k][:, None] + np.arange(1, k + 1)]
        pairs.append(np.stack([poly, np.roll(poly, -1, axis=1)], axis=-1).reshape(-1, 2))
    if not pairs:
        return np.zeros((0, 2), dtype=np.int64)
    e = np.sort(np.concatenate(pairs), axis=1)
    return np.unique(e[e[:, 0] != e[:, 1]], axis=0)


def _near(seed, allowed, edges, n, rings):
    """``seed`` and the vertices of ``allowed`` within ``rings`` edges of it (walking inside ``allowed``)."""
    if rings == 0 or edges is None:
        return seed
    e = _checked_edges(edges, n)
    inside = np.zeros(n, dtype=bool)
    inside[allowed] = True
    e = e[inside[e].all(axis=1)]
    A = sparse.coo_matrix((np.ones(2 * len(e)), (e.ravel(), e[:, ::-1].ravel())), shape=(n, n)).tocsr()
    reached = np.zeros(n, dtype=bool)
    reached[seed] = True
    for _ in range(rings):
        reached |= (A @ reached.astype(float)) > 0
    return np.flatnonzero(reached)


def _checked_edges(edges, n):
    e = np.asarray(edges)
    if e.ndim != 2 or e.shape[1] != 2 or (len(e) and (not np.issubdtype(e.dtype, np.integer)
                                                      or e.min() < 0 or e.max() >= n)):
        raise FittingError(f"edges must be an (E, 2) array of vertex indices in 0..{n - 1}")
    return e.astype(np.int64)


def _incidence(edges, allowed, n):
    """Signed edge–vertex incidence matrix over the region's vertices (edges with both ends inside)."""
    if edges is None:
        return sparse.csr_matrix((0, len(allowed)))
    e = _checked_edges(edges, n)
    local = np.full(n, -1)
    local[allowed] = np.arange(len(allowed))
    e = local[e]
    e = e[(e >= 0).all(axis=1)]
    m = len(e)
    rows = np.repeat(np.arange(m), 2)
    vals = np.tile([1.0, -1.0], m)
    return sparse.csr_matrix((vals, (rows, e.ravel())), shape=(m, len(allowed)))


def _region_indices(region, n) -> np.ndarray:
    if region is None:
        return np.arange(n)
    r = np.asarray(region)
    if r.dtype == bool:
        if r.shape != (n,):
            raise FittingError(f"a region mask needs one entry per vertex ({n}), not shape {r.shape}")
        r = np.flatnonzero(r)
    elif r.size and not np.issubdtype(r.dtype, np.integer):
        raise FittingError("a region is vertex indices, a boolean mask or part names")
    r = np.unique(r.astype(np.int64).reshape(-1))
    if len(r) == 0:
        raise FittingError("the region is empty")
    if r[0] < 0 or r[-1] >= n:
        raise FittingError(f"the region names a vertex outside 0..{n - 1}")
    return r


def _resolve_region(model, region):
    """Part name(s) to vertex indices; anything else is checked by :func:`_region_indices`."""
    if isinstance(region, str):
        region = [region]
    if isinstance(region, (list, tuple)) and region and all(isinstance(r, str) for r in region):
        for part in region:
            if part not in model.parts:
                raise FittingError(f"unknown part '{part}'{_suggest(part, model.parts)}")
        return np.concatenate([model.part_vertices(p) for p in region])
    return region


def _points(values, what) -> np.ndarray:
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


def _is_number(value) -> bool:
    return isinstance(value, (int, float, np.number)) and bool(np.isfinite(value))


def _rms(a) -> float:
    return float(np.sqrt(np.mean(np.sum(a ** 2, axis=1)))) if len(a) else 0.0


def _fmt(v, digits) -> str:
    return ", ".join(f"{x:.{digits}f}" for x in v)


def _suggest(name, known) -> str:
    close = difflib.get_close_matches(name, list(known), n=1)
    return f" (did you mean '{close[0]}'?)" if close else f" (known: {', '.join(known)})"


# -- the shipped reference poses ---------------------------------------------------

def reference_pose_names(path=None) -> list[str]:
    """Names of the reference poses, ``"<group>/<pose>"`` (``arkit/jawOpen``, ``expression_units/...``)."""
    import h5py

    from engine.paths import reference_poses_path

    with h5py.File(path or reference_poses_path(), "r") as f:
        return [f"{g}/{n}" for g in ("arkit", "expression_units") if g in f for n in f[g]]


def reference_pose(name: str, path=None) -> np.ndarray:
    """One reference pose of the default head as dense (N, 3) displacements, mm.

    ``name`` is ``"arkit/jawOpen"`` or, when unambiguous, just ``"jawOpen"``.
    ``path`` defaults to ``data/default-head/reference-poses.h5``.
    """
    import h5py

    from engine.paths import reference_poses_path

    names = reference_pose_names(path)
    matches = [n for n in names if n == name or n.split("/", 1)[1] == name]
    if len(matches) != 1:
        why = "is ambiguous" if matches else "is not a reference pose"
        raise FittingError(f"'{name}' {why}{_suggest(name, names) if not matches else ''}")
    with h5py.File(path or reference_poses_path(), "r") as f:
        D = np.zeros((len(f["source_vertex"]), 3))
        g = f[matches[0]]
        D[g["indices"][()]] = g["displacements"][()]
    return D

