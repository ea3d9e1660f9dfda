"""Stopping a photo fit part-way through a step (issue 19: the wizard's Stop takes effect at once).

The fit asks its ``should_stop`` callable between steps and inside the long
loops of each step. These tests count those questions on a real fit (the
default head rendered by the toolkit's renderer, its true landmark pixels):
a full fit asks many times inside the shape and texture steps; a fit told to
stop half-way through a step raises :class:`FitStopped` at the very question
that said so, before that step's work is done and before the next step
begins. No clock is read: what is asserted is where the fit stopped.
"""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

from engine.outputs.render import render_model
from engine.photofit import FitStopped, fit_photos
from engine.photofit.face_points import point_vertices
from engine.photofit.fit import FIT_STEPS
from engine.photofit.initial_points import visible_landmarks
from engine.photofit.raster import rasterize
from tests.engine.test_photofit import project

SIZE = (450, 600)


@pytest.fixture(scope="module")
def photo_and_points(head):
    photos = {"front": render_model(head, view="front", size=SIZE)}
    pixels = project(head, "front", *SIZE)
    where = point_vertices(head)
    points = {"front": {k: tuple(pixels[where[k]]) for k in visible_landmarks(head, "front")}}
    return photos, points


class CountingStop:
    """A ``should_stop`` that counts the questions asked in each step and says stop at the ``stop_at``-th
    question of step ``step`` (never when ``step`` is None)."""

    def __init__(self, step: str | None = None, stop_at: int = 0):
        self.step, self.stop_at = step, stop_at
        self.current = "before"
        self.asked: Counter[str] = Counter()
        self.asked_after_stop = 0
        self.steps: list[str] = []

    def progress(self, step: str) -> None:
        self.current = step
        self.steps.append(step)

    def __call__(self) -> bool:
        if self.asked_after_stop:
            self.asked_after_stop += 1
            return True
        self.asked[self.current] += 1
        if self.current == self.step and self.asked[self.current] >= self.stop_at:
            self.asked_after_stop = 1
            return True
        return False


@pytest.fixture(scope="module")
def full_fit_questions(head, photo_and_points):
    photos, points = photo_and_points
    counter = CountingStop()
    result = fit_photos(photos, points, head, progress=counter.progress, should_stop=counter)
    assert result.head.texture is not None and tuple(counter.steps) == FIT_STEPS
    return counter.asked


def test_a_full_fit_asks_often_inside_its_long_steps(full_fit_questions):
    # the shape step asks once per sampled identity parameter and per evaluation of the optimiser;
    # the head step between the stages of making the identity's head; the rig step between its refits;
    # the texture step every 128 triangles drawn (atlas and visibility buffers)
    assert full_fit_questions["shape"] > 20, full_fit_questions
    assert full_fit_questions["head"] >= 6, full_fit_questions
    assert full_fit_questions["texture"] > 20, full_fit_questions
    assert full_fit_questions["rig"] >= 4, full_fit_questions


@pytest.mark.parametrize("step", ["shape", "head", "texture"])
def test_stop_half_way_through_a_step_ends_the_fit_inside_it(head, photo_and_points, full_fit_questions, step):
    photos, points = photo_and_points
    half = full_fit_questions[step] // 2
    counter = CountingStop(step, stop_at=half)
    with pytest.raises(FitStopped):
        fit_photos(photos, points, head, progress=counter.progress, should_stop=counter)
    assert counter.steps[-1] == step                                 # no later step began
    assert counter.asked[step] == half < full_fit_questions[step]    # the step's own work was not finished
    assert counter.asked_after_stop == 1                             # nothing went on after the answer


def test_stop_between_steps_ends_before_the_next_one(head, photo_and_points):
    photos, points = photo_and_points
    counter = CountingStop("rig", stop_at=1)
    with pytest.raises(FitStopped):
        fit_photos(photos, points, head, progress=counter.progress, should_stop=counter)
    assert counter.steps == ["shape", "head", "rig"] and counter.asked_after_stop == 1


def test_the_rasterizer_stops_part_way_and_draws_the_same_when_not_stopped():
    rng = np.random.default_rng(3)
    triangles = rng.uniform(0, 64, size=(1000, 3, 2))
    asked: list[int] = []

    def stop_at_the_third_question() -> bool:
        asked.append(1)
        return len(asked) >= 3

    with pytest.raises(FitStopped):
        rasterize(triangles, 64, 64, should_stop=stop_at_the_third_question)
    assert len(asked) == 3                                           # 2 × 128 triangles drawn, not 1000
    plain = rasterize(triangles, 64, 64)
    asked_never = rasterize(triangles, 64, 64, should_stop=lambda: False)
    assert all(np.array_equal(a, b) for a, b in zip(plain, asked_never, strict=True))
