"""The shape fit: cameras and identity parameters by regularised least squares, then a residual warp.

The landmark positions of an identity are close to linear in its parameters
near the default head, so they are sampled once per parameter
(:func:`landmark_basis`, one :func:`identity_vertices` each) and the
optimiser works on that linear model; the cameras are fitted exactly (the
rotation is non-linear). The model is then made again about the estimate and
the fit repeated (:data:`REFINEMENTS` times, :func:`linearise_at`): over the
whole range the landmarks are not linear, and the first estimate left 5 … 6 px
of landmark error that the identity could explain. A prior keeps each parameter
near its default, in units of :data:`PRIOR_SPREAD` (:data:`PRIOR_SPREADS` for
some). What the identity space cannot explain is taken up by a smooth warp
(Gaussian radial basis functions of the landmarks' 3-D residuals), eyes,
teeth and tongue moving rigidly with it. The sampling and the optimiser ask
``should_stop`` as they go (:mod:`engine.photofit.stopping`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from engine.identity import Identity, identity_parameter, identity_vertices
from engine.model import Model
from engine.photofit.camera import WeakPerspective, initial_vector
from engine.photofit.outline import LANDMARK_CLEARANCE, SkinColour, face_skin, outline_moves, outline_vertices
from engine.photofit.silhouette import foreground, profile_moves, profile_vertices
from engine.photofit.stopping import ShouldStop, stop_if_asked
from engine.photofit.texture import all_triangles, vertex_normals

#: The identity parameters fitted, and the step used to sample each one's effect.
FITTED_PARAMETERS = ("sex", "age", "weight", "head-scale-horiz-decr-incr", "head-scale-vert-decr-incr",
                     "nose-scale-horiz-decr-incr", "nose-scale-vert-decr-incr", "nose-trans-down-up",
                     "nose-scale-depth-decr-incr", "mouth-scale-horiz-decr-incr", "mouth-trans-down-up",
                     "eye-trans-down-up", "eye-trans-in-out", "eye-scale-decr-incr", "chin-height-decr-incr",
                     "chin-width-decr-incr", "chin-prominent-decr-incr")
#: Narrower ranges than the identity space's: the landmark model is linear about the default head (25 years),
#: which a child's or baby's proportions are too far from; a photograph of a child is not fitted well.
FIT_RANGES = {"age": (18.0, 90.0)}
#: How far (as a fraction of each parameter's range) the prior lets a parameter move at one unit of cost.
PRIOR_SPREAD = 0.35
#: Tighter for the head's overall height and width: they move the skull, which the landmarks hardly see, so a
#: loose prior let them take up landmark noise and the cameras' weak-perspective error (measured on four
#: synthetic heads, docs/photofit.md: the skull 2 … 4 mm nearer the truth, the face no worse).
PRIOR_SPREADS = {"head-scale-horiz-decr-incr": 0.1, "head-scale-vert-decr-incr": 0.1}
REFINEMENTS = 2                       # times the landmark model is made again about the estimate and refitted
REFINE_STEP = 0.05                    # of a parameter's range: the finite difference step about the estimate
PIXEL_NOISE = 2.0                     # px: the landmark placement error the reprojection residual is scaled by
WARP_RADIUS = 22.0                    # mm: the Gaussian warp's width
WARP_SMOOTHING = 0.3                  # ridge on the warp's weights: close landmarks must not fold it
RIGID_PARTS = ("eye_left", "eye_right", "teeth_upper", "teeth_lower", "tongue")


@dataclass
class ShapeFit:
    identity: Identity
    cameras: dict[str, WeakPerspective]
    vertices: np.ndarray              # identity vertices + residual warp, (N, 3) mm
    warp: np.ndarray                  # the warp alone, (N, 3) mm
    error_before_warp: float          # RMS landmark reprojection error, px
    error: float                      # after the warp, px


def landmark_basis(base: Model, ids: list[str],
                   should_stop: ShouldStop = None) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Default values (P,), steps (P,), landmark rest positions (L, 3) and their change per unit (P, L, 3)."""
    index = np.array([base.landmarks[k] for k in ids])
    defaults, steps, basis = [], [], []
    rest = base.vertices[index]
    for name in FITTED_PARAMETERS:
        stop_if_asked(should_stop)
        p = identity_parameter(name)
        step = 0.5 * (p.maximum - p.minimum) * 0.5
        value = p.default + step if p.default + step <= p.maximum else p.default - step
        moved = identity_vertices(Identity({name: value}), base)[index]
        defaults.append(p.default)
        steps.append(value - p.default)
        basis.append((moved - rest) / (value - p.default))
    return np.array(defaults), np.array(steps), rest, np.array(basis)


def linearise_at(base: Model, ids: list[str], values: np.ndarray,
                 should_stop: ShouldStop = None) -> tuple[np.ndarray, np.ndarray]:
    """Landmark positions (L, 3) of the identity with ``values`` (P,) and their change per unit (P, L, 3) there:
    the landmark model again about the current estimate (the landmarks are not linear over the whole range)."""
    index = np.array([base.landmarks[k] for k in ids])
    current = {n: float(v) for n, v in zip(FITTED_PARAMETERS, values, strict=True)}
    rest = identity_vertices(Identity(current), base)[index]
    basis = []
    for name, value in current.items():
        stop_if_asked(should_stop)
        p = identity_parameter(name)
        step = REFINE_STEP * (p.maximum - p.minimum)
        moved_value = value + step if value + step <= p.maximum else value - step
        moved = identity_vertices(Identity({**current, name: moved_value}), base)[index]
        basis.append((moved - rest) / (moved_value - value))
    return rest, np.array(basis)


def fit_shape(base: Model, points: Mapping[str, Mapping[str, tuple[float, float]]],
              side_photo: np.ndarray | None = None, should_stop: ShouldStop = None,
              front_photo: np.ndarray | None = None) -> ShapeFit:
    """Fit ``base`` (the default head) to the landmarks of each view (view → id → pixel).

    With ``side_photo`` on a plain background, the warp also puts the face's midline profile on the
    photograph's silhouette (:mod:`engine.photofit.silhouette`), and with ``front_photo`` too (the colour
    of the skin comes from its face) the rest of the head's outline where the side photograph shows skin
    there (:mod:`engine.photofit.outline`).
    """
    ids = sorted({k for view in points.values() for k in view})
    defaults, _, rest, basis = landmark_basis(base, ids, should_stop)
    spans = np.array([identity_parameter(n).maximum - identity_parameter(n).minimum for n in FITTED_PARAMETERS])
    lows = np.array([FIT_RANGES.get(n, (identity_parameter(n).minimum,))[0] for n in FITTED_PARAMETERS])
    highs = np.array([FIT_RANGES.get(n, (0.0, identity_parameter(n).maximum))[1] for n in FITTED_PARAMETERS])
    views = [v for v in ("front", "side") if points.get(v)]
    chosen = {v: (np.array([ids.index(k) for k in points[v]]), np.array(list(points[v].values()), dtype=float))
              for v in views}
    P = len(FITTED_PARAMETERS)
    spreads = np.array([PRIOR_SPREADS.get(n, PRIOR_SPREAD) for n in FITTED_PARAMETERS])

    centre = defaults

    def landmarks(values: np.ndarray) -> np.ndarray:
        return np.asarray(rest + np.einsum("p,pld->ld", values - centre, basis))

    def residuals(x: np.ndarray) -> np.ndarray:
        stop_if_asked(should_stop)               # each evaluation of the optimiser
        values = x[:P]
        shape = landmarks(values)
        out = [(values - defaults) / (spreads * spans)]
        for k, v in enumerate(views):
            camera = WeakPerspective.from_vector(v, x[P + 6 * k:P + 6 * k + 6])
            where, pixels = chosen[v]
            out.append(((camera.project(shape[where]) - pixels) / PIXEL_NOISE).ravel())
        return np.concatenate(out)

    start = [defaults] + [initial_vector(v, rest[chosen[v][0]], chosen[v][1]) for v in views]
    x0 = np.concatenate(start)
    inf = np.full(6 * len(views), np.inf)
    # cameras alone first (the identity at its default), then everything together
    fixed = least_squares(lambda c: residuals(np.concatenate([defaults, c])), x0[P:], method="lm")
    x0 = np.concatenate([defaults, fixed.x])
    solved = least_squares(residuals, x0, bounds=(np.concatenate([lows, -inf]), np.concatenate([highs, inf])),
                           x_scale=np.concatenate([spans * 0.1, np.ones(6 * len(views))]))
    for _ in range(REFINEMENTS):             # again about the estimate, where the linear model is accurate
        centre = np.clip(solved.x[:P], lows, highs)
        rest, basis = linearise_at(base, ids, centre, should_stop)
        solved = least_squares(residuals, np.concatenate([centre, solved.x[P:]]),
                               bounds=(np.concatenate([lows, -inf]), np.concatenate([highs, inf])),
                               x_scale=np.concatenate([spans * 0.1, np.ones(6 * len(views))]))
    values = np.clip(solved.x[:P], lows, highs)
    cameras = {v: WeakPerspective.from_vector(v, solved.x[P + 6 * k:P + 6 * k + 6]) for k, v in enumerate(views)}
    identity = Identity({n: float(val) for n, val, d in zip(FITTED_PARAMETERS, values, defaults, strict=True)
                         if abs(val - d) > 1e-6})
    vertices = identity_vertices(identity, base)
    index = np.array([base.landmarks[k] for k in ids])
    before = _rms_error(vertices[index], cameras, chosen)
    moves = _landmark_moves(vertices[index], cameras, chosen, len(ids))
    stop_if_asked(should_stop)
    warp = residual_warp(base, vertices, vertices[index], moves)
    stop_if_asked(should_stop)
    if side_photo is not None and "side" in cameras:
        skin = face_skin(front_photo, points["front"]) if front_photo is not None and "front" in points else None
        warp = _with_profile(base, vertices, warp, vertices[index], moves, side_photo, cameras["side"], should_stop,
                             skin)
    after = _rms_error(vertices[index] + warp[index], cameras, chosen)
    return ShapeFit(identity, cameras, vertices + warp, warp, before, after)


def _with_profile(base: Model, vertices: np.ndarray, warp: np.ndarray, centres: np.ndarray, moves: np.ndarray,
                  photo: np.ndarray, camera: WeakPerspective, should_stop: ShouldStop = None,
                  skin: SkinColour | None = None) -> np.ndarray:
    """The warp again, with the moves of the midline profile and (with ``skin``) of the rest of the outline onto
    the side photograph's silhouette added."""
    mask = foreground(photo)
    stop_if_asked(should_stop)
    if mask is None:
        return warp
    profile = profile_vertices(base, vertices + warp)
    near_landmark = np.linalg.norm(vertices[profile][:, None] - centres[None], axis=2).min(axis=1) < 4.0
    profile = profile[~near_landmark]
    trusted, extra = profile_moves(mask, camera, (vertices + warp)[profile])
    targets, target_moves = [centres], [moves]
    if trusted.sum() >= 3:
        targets.append(vertices[profile[trusted]])
        target_moves.append(warp[profile[trusted]] + extra[trusted])
    if len(targets) > 1:
        stop_if_asked(should_stop)
        warp = residual_warp(base, vertices, np.concatenate(targets), np.concatenate(target_moves))
    if skin is None:
        return warp
    # the outline second, on the warped head, with the landmarks and the profile held where they now are
    taken = np.concatenate(targets)
    outline, outline_extra = _outline_targets(base, vertices, warp, taken, photo, mask, camera, skin, should_stop)
    if not len(outline):
        return warp
    held = np.concatenate([_nearest(vertices, taken), outline])
    stop_if_asked(should_stop)
    return warp + residual_warp(base, vertices + warp, (vertices + warp)[held],
                                np.concatenate([np.zeros((len(held) - len(outline), 3)), outline_extra]))


def _nearest(vertices: np.ndarray, points: np.ndarray) -> np.ndarray:
    """(P,) the index of the vertex nearest each of (P, 3) points."""
    return np.asarray(np.linalg.norm(points[:, None] - vertices[None], axis=2).argmin(axis=1))


def _outline_targets(base: Model, vertices: np.ndarray, warp: np.ndarray, taken: np.ndarray, photo: np.ndarray,
                     mask: np.ndarray,
                     camera: WeakPerspective, skin: SkinColour,
                     should_stop: ShouldStop = None) -> tuple[np.ndarray, np.ndarray]:
    """Outline vertices (not within LANDMARK_CLEARANCE of a landmark or profile point, ``taken``, unwarped: the
    face is theirs, and the slits of the lips and eyes are no outline) with a trusted skin edge, and their 3-D
    moves onto it."""
    shape = vertices + warp
    triangles = all_triangles(base)
    outline, directions = outline_vertices(base, shape, vertex_normals(shape, triangles), triangles, camera,
                                           should_stop)
    stop_if_asked(should_stop)
    if len(outline) and len(taken):
        apart = np.linalg.norm(vertices[outline][:, None] - taken[None], axis=2).min(axis=1) >= LANDMARK_CLEARANCE
        outline, directions = outline[apart], directions[apart]
    trusted, moves = outline_moves(photo, mask, camera, shape[outline], directions, skin)
    return outline[trusted], moves[trusted]


def _rms_error(shape: np.ndarray, cameras: Mapping[str, WeakPerspective],
               chosen: Mapping[str, tuple[np.ndarray, np.ndarray]]) -> float:
    errors = [np.linalg.norm(cameras[v].project(shape[w]) - px, axis=1) for v, (w, px) in chosen.items()]
    return float(np.sqrt(np.mean(np.concatenate(errors) ** 2)))


def _landmark_moves(shape: np.ndarray, cameras: Mapping[str, WeakPerspective],
                    chosen: Mapping[str, tuple[np.ndarray, np.ndarray]], count: int) -> np.ndarray:
    """(L, 3) the smallest 3-D move of each landmark that puts it on its pixel in every view that shows it."""
    normal = np.zeros((count, 3, 3))
    right = np.zeros((count, 3))
    for v, (where, pixels) in chosen.items():
        camera = cameras[v]
        J = camera.scale * np.stack([camera.rotation[0], -camera.rotation[1]])      # (2, 3) px per mm
        r = pixels - camera.project(shape[where])
        normal[where] += J.T @ J
        right[where] += r @ J
    normal += 1e-6 * np.eye(3) * max(float(np.abs(normal).max()), 1.0)
    return np.asarray(np.linalg.solve(normal, right[..., None])[..., 0])


def residual_warp(base: Model, vertices: np.ndarray, centres: np.ndarray, moves: np.ndarray) -> np.ndarray:
    """(N, 3) a smooth displacement that moves each centre by its move; rigid parts translate as a whole."""
    gaussian = np.exp(-(np.linalg.norm(centres[:, None] - centres[None], axis=2) / WARP_RADIUS) ** 2)
    weights = np.linalg.solve(gaussian + WARP_SMOOTHING * np.eye(len(centres)), moves)
    field = np.exp(-(np.linalg.norm(vertices[:, None] - centres[None], axis=2) / WARP_RADIUS) ** 2) @ weights
    for part in RIGID_PARTS:
        if part in base.parts:
            inside = base.vertex_part == base.parts.index(part)
            if inside.any():
                field[inside] = field[inside].mean(axis=0)
    return np.asarray(field)
