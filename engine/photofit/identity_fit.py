"""Who the photograph shows, and how they look in it: identity, expression and cameras fitted to the landmarks.

The landmarks of an identity are close to linear in its parameters near the
default head, so each parameter's effect on them is sampled
(:class:`IdentityBasis`, one :func:`identity_vertices` each) and the optimiser
(``scipy.optimize.least_squares``) works on that model, with the photograph's
expression (:mod:`engine.photofit.expression_fit`) and a weak-perspective
camera per photograph. Face modifiers are MakeHuman targets, linear on each
side of 0, so each side is sampled once, when the fit first goes there; the
macro parameters (sex, age, ancestry) are not linear and are sampled again
about the estimate (:data:`REFINEMENTS` times), with the expression.

The priors keep a face a face (``docs/photofit.md``): each parameter is
pulled to its default, one unit of cost at :data:`PRIOR_SPREAD` of its range
(:data:`PRIOR_SPREADS` for some); **age** to :data:`AGE_CENTRE` years within
18 … 90; **eye size** by a tight prior (landmarks of a smiling or narrowed eye
drove it to its bound: staring eyes); **sex** to whichever of
:data:`SEX_MODES` (a woman's, a man's) fits the landmarks better, both tried,
so it is not left between the two.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares, lsq_linear

from engine.identity import Identity, identity_parameter, identity_vertices
from engine.model import Model
from engine.photofit.camera import WeakPerspective, initial_vector
from engine.photofit.expression_fit import ExpressionBasis
from engine.photofit.face_points import point_index
from engine.photofit.side_table import first_macro_effect, shipped_sides, side_effect
from engine.photofit.stopping import ShouldStop, stop_if_asked

#: The identity parameters fitted (the macros first).
MACROS = ("sex", "age", "african", "asian", "caucasian")
MODIFIERS = ("head-scale-horiz-decr-incr", "head-scale-vert-decr-incr", "head-fat-decr-incr", "head-oval",
             "head-square", "head-triangular", "head-invertedtriangular", "chin-bones-decr-incr",
             "chin-height-decr-incr", "chin-width-decr-incr", "chin-prominent-decr-incr", "cheek-volume-decr-incr",
             "cheek-bones-decr-incr", "eye-trans-down-up", "eye-trans-in-out", "eye-scale-decr-incr",
             "eye-height2-decr-incr", "eyebrows-trans-down-up", "nose-scale-horiz-decr-incr",
             "nose-scale-vert-decr-incr", "nose-trans-down-up", "nose-scale-depth-decr-incr",
             "nose-nostrils-width-decr-incr", "nose-flaring-decr-incr", "mouth-scale-horiz-decr-incr",
             "mouth-trans-down-up", "mouth-lowerlip-height-decr-incr", "mouth-upperlip-height-decr-incr")
FITTED_PARAMETERS = MACROS + MODIFIERS
#: Narrower ranges than the identity space's: the landmark model is made about an adult, which a child's or a
#: baby's proportions are too far from; a photograph of a child is not fitted well.
FIT_RANGES = {"age": (18.0, 90.0), "african": (0.02, 1.0), "asian": (0.02, 1.0), "caucasian": (0.02, 1.0)}
PRIOR_SPREAD = 0.35
PRIOR_SPREADS = {"head-scale-horiz-decr-incr": 0.05, "head-scale-vert-decr-incr": 0.05, "eye-scale-decr-incr": 0.12,
                 "eye-height2-decr-incr": 0.25, "age": 0.12, "sex": 0.15, "african": 0.3, "asian": 0.3,
                 "caucasian": 0.3}
#: Seen only in the face's outline: fitted where the jaw line's points are given (found by dlib), else held at
#: their defaults (with the MPEG-4 points alone they took up landmark noise and moved the skull, which no
#: landmark sees: 1 mm further from a synthetic truth's).
OUTLINE_PARAMETERS = ("head-fat-decr-incr", "head-oval", "head-square", "head-triangular", "head-invertedtriangular",
                      "chin-bones-decr-incr", "cheek-volume-decr-incr", "cheek-bones-decr-incr")
OUTLINE_POINTS = 8                    # jaw-line points at least, for them to be fitted
#: Landmarks tell age poorly: on real portraits a prior of 25 % about 40 years left most people at 18 … 29 (a man
#: of 75 at 21); this one keeps adults adult unless the landmarks insist.
AGE_CENTRE = 45.0
SEX_MODES = (0.15, 0.85)
REFINEMENTS = 2
GAUSS_NEWTON_STEPS = 60               # at most, each solve
STEP_TOLERANCE = 1e-4                 # a step this small (in units of each column's norm) ends a solve
REFINE_STEP = 0.05                    # of a macro's range: the finite difference about the estimate
PIXEL_NOISE = 2.0                     # px: the landmark placement error the reprojection residual is scaled by
#: Landmarks trusted less than the rest: the jaw line is an outline (dlib slides its points along it).
POINT_WEIGHTS = {f"ibug.{n}": 0.5 for n in (*range(8), *range(9, 17))}


@dataclass
class ParameterFit:
    identity: Identity
    expression: dict[str, float]
    cameras: dict[str, WeakPerspective]
    landmarks: np.ndarray             # (L, 3) the identity's landmarks at rest by the fitted model, mm
    offsets: np.ndarray               # (L, 3) how far the expression moves them, mm
    ids: list[str]
    cost: float


class IdentityBasis:
    """The landmarks (``ids``) of the identity with parameter values (P,), by a model linear about a centre."""

    def __init__(self, base: Model, ids: Sequence[str], should_stop: ShouldStop = None):
        self.base, self.index, self.should_stop = base, point_index(base, ids), should_stop
        self.params = [identity_parameter(n) for n in FITTED_PARAMETERS]
        self.defaults = np.array([p.default for p in self.params])
        self.spans = np.array([p.maximum - p.minimum for p in self.params])
        self.macro = np.array([n in MACROS for n in FITTED_PARAMETERS])
        self.sides: dict[tuple[int, int], np.ndarray] = {}        # (parameter, ±1) → (L, 3) per unit
        self.centre = self.defaults.copy()
        self.at_centre = base.vertices[self.index]
        # the effects about the default identity do not depend on the photograph: shipped where they can be
        self.table = shipped_sides(base, MODIFIERS, MACROS)
        self.rows = self.table.rows(self.index) if self.table is not None else None
        self.macro_columns = self._first_macro_columns()
        for k in np.flatnonzero(~self.macro):
            self.side(int(k), 1)
        self._refresh()

    def vertices(self, values: np.ndarray) -> np.ndarray:
        return identity_vertices(Identity(self.as_dict(values)), self.base)

    def as_dict(self, values: np.ndarray) -> dict[str, float]:
        return {p.name: float(v) for p, v, d in zip(self.params, values, self.defaults, strict=True)
                if abs(v - d) > 1e-6}

    def side(self, k: int, sign: int) -> np.ndarray:
        """(L, 3) modifier ``k``'s effect per unit on the side ``sign`` of 0 (MakeHuman's target there)."""
        if (k, sign) not in self.sides:
            stop_if_asked(self.should_stop)
            name = self.params[k].name
            self.sides[(k, sign)] = (self.table.side(name, sign, self.rows) if self.table and self.rows is not None
                                     else side_effect(self.base, self.index, name, sign))
        return self.sides[(k, sign)]

    def _first_macro_columns(self) -> dict[int, np.ndarray]:
        """The macros' effects about the default identity (:func:`first_macro_effect`)."""
        out = {}
        for k in np.flatnonzero(self.macro):
            stop_if_asked(self.should_stop)
            name = self.params[k].name
            out[int(k)] = (self.table.macro(name, self.rows) if self.table and self.rows is not None
                           else first_macro_effect(self.base, self.index, name))
        return out

    def _macro_columns(self, values: np.ndarray) -> dict[int, np.ndarray]:
        current = self.as_dict(values)
        out = {}
        for k in np.flatnonzero(self.macro):
            stop_if_asked(self.should_stop)
            p = self.params[k]
            step = REFINE_STEP * (p.maximum - p.minimum)
            moved_value = values[k] + step if values[k] + step <= p.maximum else values[k] - step
            moved = identity_vertices(Identity({**current, p.name: float(moved_value)}), self.base)[self.index]
            out[int(k)] = (moved - self.at_centre) / (moved_value - values[k])
        return out

    def linearise(self, values: np.ndarray) -> None:
        """The model again about ``values``: the landmarks there, the macros' effects there, and each modifier's
        side it has moved to sampled."""
        for k in np.flatnonzero(~self.macro):
            if values[k] < -0.02:
                self.side(int(k), -1)
        stop_if_asked(self.should_stop)
        self.centre = np.asarray(values, dtype=float).copy()
        self.at_centre = self.vertices(self.centre)[self.index]
        self.macro_columns = self._macro_columns(self.centre)
        self._refresh()

    def positions(self, values: np.ndarray) -> np.ndarray:
        """(L, 3) the landmarks of the identity ``values``, mm."""
        values = np.asarray(values, dtype=float)
        out = self.at_centre + np.einsum("k,kld->ld", values[self._macros] - self.centre[self._macros],
                                         self._macro_stack)
        modifiers = self._modifiers
        return out + np.einsum("m,mld->ld", values[modifiers], self._sided(values)) - self._modifier_centre

    def columns(self, values: np.ndarray) -> np.ndarray:
        """(P, L, 3) each parameter's effect per unit at ``values`` (the derivative of :meth:`positions`)."""
        out = np.empty((len(self.params), len(self.index), 3))
        out[self._macros] = self._macro_stack
        out[self._modifiers] = self._sided(values)
        return out

    def _sided(self, values: np.ndarray) -> np.ndarray:
        """(M, L, 3) each modifier's effect per unit on the side of 0 its value is on (the other side mirrored
        until it is sampled)."""
        negative = np.asarray(values)[self._modifiers] < 0
        return np.where(negative[:, None, None], self._negative, self._positive)

    def _refresh(self) -> None:
        """The stacked arrays :meth:`positions` uses, after sampling or linearising."""
        self._macros = np.flatnonzero(self.macro)
        self._modifiers = np.flatnonzero(~self.macro)
        self._macro_stack = np.array([self.macro_columns[int(k)] for k in self._macros])
        self._positive = np.array([self.sides[(int(k), 1)] for k in self._modifiers])
        self._negative = np.array([self.sides.get((int(k), -1), self.sides[(int(k), 1)]) for k in self._modifiers])
        self._modifier_centre = np.einsum("m,mld->ld", self.centre[self._modifiers], self._sided(self.centre))


def fit_parameters(base: Model, points: Mapping[str, Mapping[str, tuple[float, float]]],
                   should_stop: ShouldStop = None) -> ParameterFit:
    """Identity, expression and a camera per view that put ``base``'s points on the landmarks (view → id → px)."""
    ids = sorted({k for view in points.values() for k in view})
    identity = IdentityBasis(base, ids, should_stop)
    expression = ExpressionBasis(base, identity.index)
    P, E = len(FITTED_PARAMETERS), len(expression.names)
    lows = np.array([FIT_RANGES.get(p.name, (p.minimum, p.maximum))[0] for p in identity.params])
    highs = np.array([FIT_RANGES.get(p.name, (p.minimum, p.maximum))[1] for p in identity.params])
    spreads = np.array([PRIOR_SPREADS.get(p.name, PRIOR_SPREAD) for p in identity.params]) * identity.spans
    if sum(k in POINT_WEIGHTS for k in ids) < OUTLINE_POINTS:
        for k, p in enumerate(identity.params):
            if p.name in OUTLINE_PARAMETERS:
                spreads[k] *= 1e-4
    views = [v for v in ("front", "side") if points.get(v)]
    chosen = {v: (np.array([ids.index(k) for k in points[v]]), np.array(list(points[v].values()), dtype=float),
                  np.array([POINT_WEIGHTS.get(k, 1.0) for k in points[v]])) for v in views}
    centres = identity.defaults.copy()
    centres[[p.name for p in identity.params].index("age")] = AGE_CENTRE

    def residuals(x: np.ndarray) -> np.ndarray:
        stop_if_asked(should_stop)               # each evaluation of the optimiser
        values, moves = x[:P], x[P:P + E]
        shape = identity.positions(values) + expression.offsets(moves)
        out = [(values - centres) / spreads, expression.prior(moves)]
        for k, v in enumerate(views):
            camera = WeakPerspective.from_vector(v, x[P + E + 6 * k:P + E + 6 * k + 6])
            where, pixels, weights = chosen[v]
            out.append((weights[:, None] * (camera.project(shape[where]) - pixels) / PIXEL_NOISE).ravel())
        return np.concatenate(out)

    Q = P + E
    lo = np.concatenate([lows, expression.low])
    hi = np.concatenate([highs, expression.high])

    def jacobian(x: np.ndarray) -> np.ndarray:
        """Of :func:`residuals`: the identity and the expression exactly (the landmarks are linear in them, on
        each modifier's side of 0), each camera's six by central differences."""
        values, moves = x[:P], x[P:Q]
        shape = identity.positions(values) + expression.offsets(moves)
        by_parameter = np.concatenate([identity.columns(values), expression.basis])        # (Q, L, 3)
        cams = 6 * len(views)
        rows = [np.hstack([np.diag(1 / spreads), np.zeros((P, E + cams))]),
                np.hstack([np.zeros((E, P)), np.diag(expression.prior(np.ones(E))), np.zeros((E, cams))])]
        for k, v in enumerate(views):
            c = x[Q + 6 * k:Q + 6 * k + 6]
            camera = WeakPerspective.from_vector(v, c)
            where, _, weights = chosen[v]
            flat = camera.scale * np.stack([camera.rotation[0], -camera.rotation[1]])          # (2, 3) px per mm
            w = (weights / PIXEL_NOISE)[:, None]
            block = np.zeros((2 * len(where), Q + cams))
            block[:, :Q] = (np.einsum("ad,qnd->naq", flat, by_parameter[:, where]) * w[:, :, None]).reshape(-1, Q)
            for j in range(6):
                step = np.zeros(6)
                step[j] = 1e-6
                ahead = WeakPerspective.from_vector(v, c + step).project(shape[where])
                behind = WeakPerspective.from_vector(v, c - step).project(shape[where])
                block[:, Q + 6 * k + j] = ((ahead - behind) / 2e-6 * w).ravel()
            rows.append(block)
        return np.vstack(rows)

    def solve(x0: np.ndarray) -> tuple[np.ndarray, float]:
        """Damped Gauss-Newton steps, each a bounded linear least-squares problem (the bounds on the identity
        and the expression), until the step is small."""
        x = np.concatenate([np.clip(x0[:Q], lo, hi), x0[Q:]])
        r = residuals(x)
        cost, damping = 0.5 * float(r @ r), 1e-3
        free = np.full(len(x) - Q, np.inf)
        for _ in range(GAUSS_NEWTON_STEPS):
            stop_if_asked(should_stop)
            J = jacobian(x)
            scale = np.maximum(np.linalg.norm(J, axis=0), 1e-9)
            A = np.vstack([J / scale, np.sqrt(damping) * np.eye(len(x))])
            below = np.concatenate([np.minimum(lo - x[:Q], -1e-12), -free]) * scale
            above = np.concatenate([np.maximum(hi - x[:Q], 1e-12), free]) * scale
            scaled = lsq_linear(A, np.concatenate([-r, np.zeros(len(x))]), bounds=(below, above), method="bvls").x
            moved = x + scaled / scale
            moved[:Q] = np.clip(moved[:Q], lo, hi)
            r_moved = residuals(moved)
            cost_moved = 0.5 * float(r_moved @ r_moved)
            if cost_moved <= cost:
                x, r, cost, damping = moved, r_moved, cost_moved, max(damping / 10, 1e-9)
                if np.abs(scaled).max() < STEP_TOLERANCE:
                    break
            else:
                damping *= 10
        return x, cost

    rest = identity.positions(identity.defaults)
    start = np.concatenate([initial_vector(v, rest[chosen[v][0]], chosen[v][1]) for v in views])
    at_rest = np.concatenate([identity.defaults, np.zeros(E)])
    cameras = least_squares(lambda c: residuals(np.concatenate([at_rest, c])), start, method="lm").x

    best = None
    sex = [p.name for p in identity.params].index("sex")
    for mode in SEX_MODES:                   # a woman's or a man's face, whichever the landmarks prefer
        centres[sex] = mode
        x0 = np.concatenate([at_rest, cameras])
        x0[sex] = mode
        x, cost = solve(x0)
        if best is None or cost < best[2]:
            best = (mode, x, cost)
    assert best is not None
    centres[sex], x, cost = best
    for _ in range(REFINEMENTS):             # again about the estimate, where the linear model is accurate
        identity.linearise(x[:P])
        expression.linearise(x[P:Q])
        x, cost = solve(x)
    values, moves = x[:P], x[P:Q]
    cams = {v: WeakPerspective.from_vector(v, x[Q + 6 * k:Q + 6 * k + 6]) for k, v in enumerate(views)}
    return ParameterFit(Identity(identity.as_dict(values)), expression.as_dict(moves), cams,
                        identity.positions(values), expression.offsets(moves), ids, cost)
