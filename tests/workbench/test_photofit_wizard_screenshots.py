"""Pictures of the photo-fit wizard for docs/workbench-photofit.md, made by the real window.

A real portrait, ``skimage.data.astronaut()`` (public domain, NASA), fitted
front-only with the landmarks of ``docs/images/photofit/astronaut_points.json``,
then saying the test sentence on the result page (real Festival; the picture
is the frame in the middle of its longest "a", paused there); and the default
head rendered from the front and the side, fitted from both.
Writes ``wizard-*.png`` into ``$AP_SCREENSHOT_DIR/photofit`` when that names a
folder (``AP_SCREENSHOT_DIR=docs/images`` refreshes the docs' pictures), else
into the test's own temporary folder: a test run leaves the work tree alone.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from PySide6.QtCore import QRect, QRectF

import engine
from engine.photofit.points import REQUIRED_FRONT
from tests.workbench.test_photofit_wizard import FIT_TIMEOUT_MS, open_wizard, photographs  # noqa: F401
from tests.workbench.test_photofit_wizard_speaking import mouth_gap, open_vowel_ms
from workbench.jobs import wait_for_all
from workbench.photofit_wizard.landmarks import MoveMarker
from workbench.window.layouts import fresh_window_size

DOCS = Path(__file__).resolve().parents[2] / "docs" / "images" / "photofit"
LAPTOP = fresh_window_size(QRect(0, 0, 1366, 768))
WIZARD_SIZE = (1240, 720)
FACE = QRectF(120, 30, 220, 210)          # the astronaut's face, pixels: zoomed to as the wheel would


@pytest.fixture
def head_window(make_window):
    yield make_window(engine.default_model_path(), size=(LAPTOP.width(), LAPTOP.height()))
    wait_for_all(FIT_TIMEOUT_MS)


def shoot(wizard, qtbot, folder: Path, name: str) -> Path:
    qtbot.wait(50)                     # let the page lay itself out and paint
    path = folder / name
    assert wizard.grab().save(str(path))
    return path


def test_screenshots_of_a_real_portrait_and_a_two_view_fit(head_window, photographs, tmp_path, qtbot):  # noqa: F811
    shots = Path(os.environ["AP_SCREENSHOT_DIR"]) / "photofit" if os.environ.get("AP_SCREENSHOT_DIR") else tmp_path
    shots.mkdir(parents=True, exist_ok=True)
    data = pytest.importorskip("skimage.data")
    portrait = tmp_path / "astronaut.png"
    Image.fromarray(data.astronaut()).save(portrait)
    wizard = open_wizard(head_window, qtbot)
    wizard.resize(*WIZARD_SIZE)
    wizard.result_page.say_box.setChecked(False)
    assert wizard.photos_page.choose("front", portrait)
    shoot(wizard, qtbot, shots, "wizard-photos.png")
    wizard.next()
    shoot(wizard, qtbot, shots, "wizard-landmarks-start.png")
    page = wizard.landmark_page
    front = page.canvases["front"]
    placed_by_eye = json.loads((DOCS / "astronaut_points.json").read_text())["front"]
    for key in REQUIRED_FRONT:                      # the six red points dragged to where they were placed by eye
        marker = front.markers[key]
        page.undo_stack.push(MoveMarker(front, key, (marker.pos().x(), marker.pos().y()), tuple(placed_by_eye[key])))
    page.place_button.click()
    front.zoom_to(FACE)        # the face, as the wheel zooms to it
    shoot(wizard, qtbot, shots, "wizard-landmarks-placed.png")
    others = [k for k in placed_by_eye if k not in REQUIRED_FRONT]
    d = np.array([np.subtract(front.state()[k][:2], placed_by_eye[k]) for k in others])
    print(f"astronaut: Place the rest puts {len(others)} points {np.sqrt((d ** 2).sum(axis=1).mean()):.1f} px RMS "
          "from where they were placed by eye")
    assert page.load(DOCS / "astronaut_points.json")
    shoot(wizard, qtbot, shots, "wizard-landmarks.png")
    wizard.next()
    qtbot.waitUntil(wizard.fit_page.isComplete, timeout=FIT_TIMEOUT_MS)
    wizard.fit_page.canvases["front"].zoom_to(FACE)
    shoot(wizard, qtbot, shots, "wizard-fit.png")
    wizard.next()
    written = shoot(wizard, qtbot, shots, "wizard-result.png")
    result = wizard.result_page
    result.say_button.click()
    qtbot.waitUntil(lambda: result.player.is_playing, timeout=FIT_TIMEOUT_MS)
    result.player.pause()
    result.playhead.set_time(open_vowel_ms(result.speech) / 1000)
    head = result.document.model
    assert mouth_gap(result.document.vertices(), head) > mouth_gap(head.vertices, head) + 2.0      # mm: open
    result.viewport.set_view("front")
    speaking = shoot(wizard, qtbot, shots, "wizard-result-speaking.png")
    wizard.reject()

    wizard = open_wizard(head_window, qtbot)
    wizard.resize(*WIZARD_SIZE)
    assert wizard.photos_page.choose("front", photographs / "front.png")
    assert wizard.photos_page.choose("side", photographs / "side.png")
    wizard.next()
    assert wizard.landmark_page.load(photographs / "points.json")
    wizard.next()
    qtbot.waitUntil(wizard.fit_page.isComplete, timeout=FIT_TIMEOUT_MS)
    two = shoot(wizard, qtbot, shots, "wizard-fit-two-views.png")
    wizard.reject()
    for path in (written, speaking, two):
        with Image.open(path) as picture:
            assert picture.size == WIZARD_SIZE
