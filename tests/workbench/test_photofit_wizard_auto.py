"""The photo wizard starts with the points found by themselves (issue 33, item 1), in the real window.

scikit-image's astronaut (public domain) is a real portrait: her points are found by dlib's detector and
68-point predictor (the ``validate`` extra's observers) and the markers start on them; the ones the 68 points do
not give are placed from them and left out. A photograph with no face, two faces or a face too small says so in
a dialog and the markers start at the head centred on the photograph, as they do when the photographs page's box
is unticked.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from PIL import Image
from PySide6.QtWidgets import QMessageBox
from skimage import data

import engine
from engine.photofit.initial_points import initial_points, visible_landmarks
from engine.photofit.points import REQUIRED_FRONT
from tests.engine.test_photofit_auto_landmarks import no_face, small_face, two_faces
from tests.engine.test_photofit_outline import ASTRONAUT_POINTS
from tests.workbench.test_photofit_wizard import FIT_TIMEOUT_MS, LAPTOP, open_wizard
from workbench.jobs import wait_for_all

pytestmark = pytest.mark.slow


@pytest.fixture
def head_window(make_window):
    yield make_window(engine.default_model_path(), size=(LAPTOP.width(), LAPTOP.height()))
    wait_for_all(FIT_TIMEOUT_MS)


@pytest.fixture
def warnings(monkeypatch):
    """QMessageBox.warning records its message instead of blocking the test."""
    said: list[tuple[str, str]] = []

    def warning(parent, title, text, *args, **kwargs):
        said.append((title, text))
        return QMessageBox.StandardButton.Ok

    monkeypatch.setattr(QMessageBox, "warning", staticmethod(warning))
    return said


def test_the_points_start_where_the_face_is_found(head_window, tmp_path, qtbot, warnings):
    photo = tmp_path / "astronaut.png"
    Image.fromarray(data.astronaut()).save(photo)
    wizard = open_wizard(head_window, qtbot)
    assert wizard.photos_page.find_box.isChecked()
    assert wizard.photos_page.choose("front", photo)
    wizard.next()
    page = wizard.landmark_page
    front = page.canvases["front"]
    assert not warnings and page.undo_stack.count() == 0
    placed = json.loads(ASTRONAUT_POINTS.read_text())["front"]          # placed by eye
    for key in ("3.5", "3.6", "9.3", "8.3", "8.4", "2.1", "3.7", "3.12"):
        marker = front.markers[key]
        assert marker.used
        assert np.hypot(marker.pos().x() - placed[key][0], marker.pos().y() - placed[key][1]) < 4.5, key
    assert {"ibug.0", "ibug.16", "ibug.27"} <= page.found["front"]
    assert not front.markers["2.10"].used and not front.markers["9.1"].used       # not among the 68: left out
    assert set(REQUIRED_FRONT) <= set(page.points()["front"])
    assert page.problem() is None
    found = front.state()

    # Place the rest keeps every point found; Reset goes back to them
    page.place_button.click()
    after = front.state()
    assert all(after[k] == pytest.approx(found[k]) for k in page.found["front"])
    nose = front.markers["9.3"]
    nose.setPos(nose.pos().x() + 9, nose.pos().y())
    page.reset_button.click()
    assert front.state()["9.3"] == pytest.approx(found["9.3"])

    # unticked on the photographs page: the first guess is the head centred on the photograph again
    wizard.back()
    wizard.photos_page.find_box.setChecked(False)
    wizard.next()
    guess = initial_points(wizard.session.landmark_head(), "front", 512, 512)
    assert front.state()["9.3"][:2] == pytest.approx(guess["9.3"])
    assert not page.found["front"]
    wizard.reject()


@pytest.mark.parametrize(("make", "words"), [
    (no_face, "no face found"), (two_faces, "2 faces found"), (small_face, "too small to place its points on")])
def test_a_photograph_without_one_usable_face_says_so_and_starts_at_a_first_guess(head_window, tmp_path, qtbot,
                                                                                   warnings, make, words):
    photo = make(tmp_path)
    wizard = open_wizard(head_window, qtbot)
    assert wizard.photos_page.choose("front", photo)
    wizard.next()
    page = wizard.landmark_page
    assert wizard.currentPage() is page
    assert len(warnings) == 1
    title, text = warnings[0]
    assert title == "New head from photographs" and str(photo) in text and words in text, text
    assert "drag the points onto the face yourself" in text
    height, width = wizard.session.photos["front"].shape[:2]
    guess = initial_points(wizard.session.landmark_head(), "front", width, height)
    state = page.canvases["front"].state()
    assert set(state) == set(visible_landmarks(wizard.session.landmark_head(), "front"))
    assert state["9.3"][:2] == pytest.approx(guess["9.3"])
    assert not state["ibug.3"][2] and state["9.3"][2]      # the jaw line left out, the MPEG-4 points used
    wizard.reject()
