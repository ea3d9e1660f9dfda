"""The workbench wizard's engine hooks: first landmark guesses on a photograph, and the fit's progress/cancel.

The photographs are the default head rendered by the toolkit's own renderer
(a perspective camera); its landmarks' true pixels come from that camera
(``tests.engine.test_photofit.project``).
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.outputs.render import render_model
from engine.photofit import fit_photos
from engine.photofit.face_points import point_vertices
from engine.photofit.fit import FIT_STEPS
from engine.photofit.initial_points import initial_points, place_from, visible_landmarks
from engine.photofit.points import REQUIRED_FRONT
from tests.engine.test_photofit import project

SIZE = (450, 600)


@pytest.fixture(scope="module")
def front_photo(head):
    return render_model(head, view="front", size=SIZE)


def true_pixels(head, view):
    pixels = project(head, view, *SIZE)
    where = point_vertices(head)
    return {k: pixels[where[k]] for k in visible_landmarks(head, view)}


@pytest.mark.parametrize("view", ["front", "side"])
def test_the_first_guess_puts_the_face_near_where_a_portrait_shows_it(head, view):
    guess, truth = initial_points(head, view, *SIZE), true_pixels(head, view)
    assert sorted(guess) == sorted(truth)
    error = np.array([np.subtract(guess[k], truth[k]) for k in truth])
    # centred and scaled to the frame like the renderer does: within a tenth of the picture's width
    assert np.sqrt((error ** 2).sum(axis=1).mean()) < 0.1 * SIZE[0]
    if view == "side":     # from the subject's left: the right eye's outer corner is behind the face
        assert "3.6" not in guess and "3.5" in guess


def test_placing_the_required_points_puts_the_others_within_a_few_pixels(head):
    truth = true_pixels(head, "front")
    placed = {k: tuple(truth[k]) for k in REQUIRED_FRONT}
    guess = place_from(head, "front", placed)
    assert {k: guess[k] for k in REQUIRED_FRONT} == placed
    others = np.array([np.subtract(guess[k], truth[k]) for k in truth if k not in placed])
    assert np.sqrt((others ** 2).sum(axis=1).mean()) < 12      # px, of a head about 400 px tall
    with pytest.raises(ValueError, match="at least two"):
        place_from(head, "front", {"3.5": (1.0, 2.0)})


class Stop(Exception):
    pass


def test_the_fit_reports_each_step_and_an_exception_from_progress_stops_it(head, front_photo):
    points = {"front": {k: tuple(v) for k, v in true_pixels(head, "front").items()}}
    steps: list[str] = []
    result = fit_photos({"front": front_photo}, points, head, progress=steps.append)
    assert tuple(steps) == FIT_STEPS
    assert result.head.texture is not None

    seen: list[str] = []

    def cancel_at_texture(step: str) -> None:
        seen.append(step)
        if step == "texture":
            raise Stop

    with pytest.raises(Stop):
        fit_photos({"front": front_photo}, points, head, progress=cancel_at_texture)
    assert seen == ["shape", "head", "rig", "texture"]
