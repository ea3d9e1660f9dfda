"""What makes a frame cheaper must not change it beyond a stated tolerance (issue 36; docs/export.md "Speed").

Counted and compared, not timed: the timings are benchmarks/bench_video.py's.
"""

from __future__ import annotations

import numpy as np
import pytest

import engine
from engine.outputs import render
from engine.outputs.render import FrameRenderer

SIZE = (640, 360)
# back faces left out: at most this share of the pixels differs, by at most this much on average (all pixels)
CULLED_SHARE, CULLED_MEAN = 0.0005, 0.05


def _poses(model: engine.Model) -> list[np.ndarray]:
    names, deformer = model.parameters.names, model.deformer()
    poses = []
    for jaw, turn, lips in ((0.0, 0.0, 0.0), (0.8, 0.0, 0.0), (0.4, 0.6, 0.0), (0.1, -0.4, 0.8)):
        values = model.values_array().copy()
        values[names.index("jaw_open")] = jaw
        values[names.index("head_turn")] = turn
        values[names.index("lower_lip_raise")] = lips
        poses.append(deformer.deform(values))
    return poses


def _frames(model: engine.Model, look: str) -> np.ndarray:
    with FrameRenderer(model, size=SIZE, look=look, antialias=False) as renderer:
        return np.stack([renderer.render(p) for p in _poses(model)])


@pytest.fixture(scope="module")
def model() -> engine.Model:
    return engine.load_model()


def _actors(renderer: FrameRenderer) -> list:
    assert renderer._window is not None
    actors = renderer._window.GetRenderers().GetFirstRenderer().GetActors()
    return [actors.GetItemAsObject(i) for i in range(actors.GetNumberOfItems())]


def test_a_physically_based_look_culls_back_faces_and_legacy_does_not(model: engine.Model) -> None:
    with FrameRenderer(model, size=(32, 24), look="portrait") as renderer:
        assert all(a.GetProperty().GetBackfaceCulling() for a in _actors(renderer))
    with FrameRenderer(model, size=(32, 24), look="legacy") as renderer:
        assert not any(a.GetProperty().GetBackfaceCulling() for a in _actors(renderer))


def test_culling_back_faces_changes_the_picture_within_the_tolerance(model: engine.Model,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    culled = _frames(model, "portrait")
    monkeypatch.setattr(render, "CULL_BACK_FACES", False)
    drawn = _frames(model, "portrait")
    difference = np.abs(culled.astype(int) - drawn.astype(int)).max(axis=3)
    face = (drawn != drawn[:, :, :1]).any(axis=3).mean()    # not the background (each row's first pixel)
    assert face > 0.1
    assert (difference > 0).mean() <= CULLED_SHARE, float((difference > 0).mean())
    assert difference.mean() <= CULLED_MEAN, float(difference.mean())


@pytest.mark.parametrize(("look", "antialias"), [("portrait", True), ("flat", False)])
def test_the_background_put_under_the_head_afterwards_gives_the_same_bytes(
        model: engine.Model, monkeypatch: pytest.MonkeyPatch, look: str, antialias: bool) -> None:
    def frames() -> tuple[np.ndarray, bool]:
        with FrameRenderer(model, size=SIZE, look=look, antialias=antialias) as renderer:
            return np.stack([renderer.render(p) for p in _poses(model)]), renderer._background is not None

    afterwards, composited = frames()
    monkeypatch.setattr(render, "BACKGROUND_AFTER_DRAWING", False)
    drawn, composited_before = frames()
    assert composited and not composited_before
    assert np.array_equal(afterwards, drawn)
    if look == "portrait":                                       # a gradient, not one colour (flat's is)
        assert len(np.unique(afterwards[0][:, 0, 1])) > 1


def test_the_legacy_look_draws_its_own_background(model: engine.Model) -> None:
    with FrameRenderer(model, size=(32, 24), look="legacy") as renderer:
        assert renderer._background is None
    with FrameRenderer(model, size=(32, 24), look="portrait") as renderer:
        assert renderer._background is not None and renderer._background.shape == (24, 32)
