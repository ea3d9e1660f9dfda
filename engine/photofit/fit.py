"""A person's head from a front (and optionally a side) photograph: shape, rig and texture."""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from engine.formats.model_files import load_model
from engine.identity import make_identity_head
from engine.identity.articulation_refit import refit_articulation
from engine.identity.carry_over import Similarity, carry_rig_over, similarity
from engine.identity.rest_fit import keep_fields_off_the_eyes, keep_lids_off_the_eyes, refit_eyelid_angles
from engine.model import Model
from engine.model.texture import ModelTexture, TextureImage
from engine.photofit.auto_landmarks import find_face_points, write_points
from engine.photofit.errors import PhotoFitError
from engine.photofit.expression_fit import posed
from engine.photofit.eyes import recolour_irises
from engine.photofit.face_points import known_ids, point_vertices
from engine.photofit.photos import read_photo
from engine.photofit.points import PhotoPoints, read_points
from engine.photofit.shape import ShapeFit, fit_shape
from engine.photofit.stopping import ShouldStop, stop_if_asked
from engine.photofit.texture import IMAGE_NAME, bake_texture
from engine.photofit.texture_cleanup import mouth_bag, mouth_opening, shadow_vertices


@dataclass
class PhotoFit:
    head: Model
    shape: ShapeFit
    seconds: dict[str, float] = field(default_factory=dict)     # landmarks, shape, texture (wall-clock)
    cpu_seconds: dict[str, float] = field(default_factory=dict)  # the same stages, this process's CPU time
    found_points: Path | None = None                             # where the points found by themselves went


#: The steps :func:`fit_photos` reports to its ``progress`` callback, in order.
FIT_STEPS = ("shape", "head", "rig", "texture", "eyes")


def fit_photos(photos: Mapping[str, np.ndarray], points: PhotoPoints, base: Model | None = None, *,
               progress: Callable[[str], object] | None = None, should_stop: ShouldStop = None) -> PhotoFit:
    """Fit the default head to ``photos`` (view → RGB pixels) and their landmarks (view → id → pixel).

    ``progress(step)`` is called as each of :data:`FIT_STEPS` begins; an exception it raises stops the
    fit there and propagates. ``should_stop()`` is asked between the steps and inside their long loops
    (how the workbench's Stop ends a fit part-way through a step): once it answers ``True`` the fit
    raises :class:`~engine.photofit.stopping.FitStopped`.
    """
    with one_blas_thread():
        return _fit_photos(photos, points, base, progress, should_stop)


def _fit_photos(photos: Mapping[str, np.ndarray], points: PhotoPoints, base: Model | None,
                progress: Callable[[str], object] | None, should_stop: ShouldStop) -> PhotoFit:
    def report(step: str) -> None:
        stop_if_asked(should_stop)
        if progress is not None:
            progress(step)

    base = base if base is not None else load_model()
    seconds: dict[str, float] = {"landmarks": 0.0}
    cpu: dict[str, float] = {"landmarks": 0.0}
    started, cpu_started = time.perf_counter(), time.process_time()
    report("shape")
    shape = fit_shape(base, {v: p for v, p in points.items() if v in photos}, photos.get("side"), should_stop,
                      photos.get("front"))
    report("head")
    head = (make_identity_head(shape.identity, _photographed(base), lambda: stop_if_asked(should_stop))
            if shape.identity.values else base.copy())
    moved = head.vertices + shape.warp
    rigid: dict[str, Similarity] = {}
    for part in ("eye_left", "eye_right"):
        if part in head.parts:
            inside = head.vertex_part == head.parts.index(part)
            rigid[part] = similarity(head.vertices[inside], moved[inside])
    report("rig")
    fitted = carry_rig_over(head, moved, rigid)
    # the warp moved lips and lids: fit the rig to them again as make_identity_head does for its own shape
    stop_if_asked(should_stop)
    refit_articulation(base, fitted)
    stop_if_asked(should_stop)
    refit_eyelid_angles(base, fitted)
    stop_if_asked(should_stop)
    keep_fields_off_the_eyes(fitted)
    stop_if_asked(should_stop)
    keep_lids_off_the_eyes(fitted)
    fitted.identity = head.identity
    fitted.name = "person-from-photos"
    fitted.description = f"{base.description} Fitted to photographs ({', '.join(photos)})."
    seconds["shape"], cpu["shape"] = time.perf_counter() - started, time.process_time() - cpu_started
    started, cpu_started = time.perf_counter(), time.process_time()
    report("texture")
    # the photographs show the head in their expression: read them through the head posed so
    seen = posed(fitted, shape.expression)
    hidden = {}
    if "front" in photos and "front" in points:
        hidden["front"] = mouth_opening(photos["front"].shape, points["front"], shape.cameras["front"].scale)
    fitted.texture, _ = bake_texture(fitted, seen, {v: p for v, p in photos.items() if v in shape.cameras},
                                     shape.cameras, should_stop=should_stop, hidden=hidden,
                                     own_colours=mouth_bag(base),
                                     shadows=shadow_vertices(fitted, fitted.vertices, point_vertices(fitted)))
    report("eyes")
    if "front" in photos:
        fitted.vertex_colors = None if fitted.vertex_colors is None else fitted.vertex_colors.copy()
        recolour_irises(fitted, photos["front"], dict(points["front"]), shape.cameras["front"].scale)
    fitted.changed()
    seconds["texture"], cpu["texture"] = time.perf_counter() - started, time.process_time() - cpu_started
    return PhotoFit(fitted, shape, seconds, cpu)


def _photographed(base: Model) -> Model:
    """``base`` with a placeholder photograph as its texture image (its texture coordinates kept), for
    :func:`make_identity_head`: a head whose texture shows a photograph keeps it, so the identity's own skin
    image (``engine.identity.skin``, about 5 s of CPU on the 1024² atlas) is not painted only to be replaced by
    the photographs' (:func:`bake_texture` reads the texture coordinates alone)."""
    if base.texture is None:
        return base
    shell = base.copy()
    assert shell.texture is not None
    placeholder = TextureImage(IMAGE_NAME, np.zeros((1, 1, 3), dtype=np.uint8))
    shell.texture = ModelTexture(shell.texture.corner_uv, [placeholder],
                                 np.where(shell.texture.face_image >= 0, 0, -1))
    return shell


@contextlib.contextmanager
def one_blas_thread() -> Iterator[None]:
    """BLAS on one thread for the fit: its matrices are small (a few hundred rows), and on a busy machine
    OpenBLAS's threads made each factorisation ten times slower."""
    try:
        from threadpoolctl import threadpool_limits  # type: ignore[import-untyped]
    except ImportError:
        yield
        return
    with threadpool_limits(1, user_api="blas"):
        yield


def fit_photo_files(front: str | Path, side: str | Path | None, landmarks: str | Path | None,
                    found_to: str | Path | None = None) -> PhotoFit:
    """:func:`fit_photos` of files: the photographs (JPEG/PNG) and POINTS.json; errors name the file.

    Without ``landmarks`` the front photograph's points are found by dlib's detector and predictor
    (:mod:`engine.photofit.auto_landmarks`) and, with ``found_to``, written there as POINTS.json
    (``result.found_points`` is that file); a side photograph then is refused (dlib finds no profile).
    """
    started, cpu_started = time.perf_counter(), time.process_time()
    base = load_model()
    photos = {"front": read_photo(front)}
    if side is not None:
        photos["side"] = read_photo(side)
    if landmarks is None:
        points = find_points(base, photos, {"front": front, "side": side})
        where = landmarks = Path(found_to) if found_to is not None else None
    else:
        points = read_points(landmarks, known=known_ids(base))
        where = None
    if side is not None and not points.get("side"):
        raise PhotoFitError("a --side photograph needs landmarks of its own: the landmark file has no 'side' "
                            "points", file=landmarks)
    if "side" in points and side is None:
        raise PhotoFitError("the landmark file has a 'side' view but no --side photograph was given", file=landmarks)
    for view, photo in photos.items():
        height, width = photo.shape[:2]
        for key, (x, y) in points.get(view, {}).items():
            if not (0 <= x <= width and 0 <= y <= height):
                raise PhotoFitError(f"'{view}' landmark {key} at ({x:g}, {y:g}) is outside the {width}×{height} "
                                    "photograph", file=landmarks)
    if where is not None:
        write_points(where, points)
    read, read_cpu = time.perf_counter() - started, time.process_time() - cpu_started
    result = fit_photos(photos, points, base)
    result.seconds["landmarks"], result.cpu_seconds["landmarks"] = read, read_cpu
    result.found_points = where
    return result


def find_points(base: Model, photos: Mapping[str, np.ndarray],
                paths: Mapping[str, str | Path | None]) -> PhotoPoints:
    """The front photograph's points found by dlib. A side photograph's are not found (dlib's models see faces
    from the front only): refused, before the front's are looked for."""
    if "side" in photos:
        raise PhotoFitError("a side photograph's points are not found by themselves (dlib's models find frontal "
                            "faces only): place them in the workbench's photo wizard, or give --landmarks "
                            "POINTS.json with a 'side' view", file=paths.get("side"))
    return {"front": dict(find_face_points(photos["front"], known_ids(base), paths.get("front")).pixels)}
