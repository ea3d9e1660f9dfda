"""The shape fit: identity, expression and cameras fitted to the landmarks, then a residual warp.

:func:`engine.photofit.identity_fit.fit_parameters` finds the identity (who
the person is), the photograph's expression (how they look in it) and a
weak-perspective camera per photograph by regularised least squares. What
the identity space cannot explain is taken up by a smooth warp (Gaussian
radial basis functions of the landmarks' 3-D residuals, measured on the
head posed in the photograph's expression and applied at rest), eyes, teeth
and tongue moving rigidly with it. The sampling and the optimiser ask
``should_stop`` as they go (:mod:`engine.photofit.stopping`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from engine.identity import Identity, identity_vertices
from engine.model import Model
from engine.photofit.camera import WeakPerspective
from engine.photofit.face_points import point_index
from engine.photofit.identity_fit import fit_parameters
from engine.photofit.outline import LANDMARK_CLEARANCE, SkinColour, face_skin, outline_moves, outline_vertices
from engine.photofit.silhouette import foreground, profile_moves, profile_vertices
from engine.photofit.stopping import ShouldStop, stop_if_asked
from engine.photofit.texture import all_triangles, vertex_normals

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
    expression: dict[str, float] = field(default_factory=dict)   # the photograph's: rig parameter → value


def fit_shape(base: Model, points: Mapping[str, Mapping[str, tuple[float, float]]],
              side_photo: np.ndarray | None = None, should_stop: ShouldStop = None,
              front_photo: np.ndarray | None = None) -> ShapeFit:
    """Fit ``base`` (the default head) to the landmarks of each view (view → id → pixel).

    With ``side_photo`` on a plain background, the warp also puts the face's midline profile on the
    photograph's silhouette (:mod:`engine.photofit.silhouette`), and with ``front_photo`` too (the colour
    of the skin comes from its face) the rest of the head's outline where the side photograph shows skin
    there (:mod:`engine.photofit.outline`).
    """
    fitted = fit_parameters(base, points, should_stop)
    ids, identity, cameras = fitted.ids, fitted.identity, fitted.cameras
    views = [v for v in ("front", "side") if points.get(v)]
    chosen = {v: (np.array([ids.index(k) for k in points[v]]), np.array(list(points[v].values()), dtype=float))
              for v in views}
    vertices = identity_vertices(identity, base)
    index = point_index(base, ids)
    offsets = fitted.offsets                # the photograph's expression: its landmarks are the posed head's
    before = _rms_error(vertices[index] + offsets, cameras, chosen)
    moves = _landmark_moves(vertices[index] + offsets, cameras, chosen, len(ids))
    stop_if_asked(should_stop)
    warp = residual_warp(base, vertices, vertices[index], moves)
    stop_if_asked(should_stop)
    if side_photo is not None and "side" in cameras:
        skin = face_skin(front_photo, points["front"]) if front_photo is not None and "front" in points else None
        warp = _with_profile(base, vertices, warp, vertices[index], moves, side_photo, cameras["side"], should_stop,
                             skin)
    after = _rms_error(vertices[index] + warp[index] + offsets, cameras, chosen)
    return ShapeFit(identity, cameras, vertices + warp, warp, before, after, fitted.expression)


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
