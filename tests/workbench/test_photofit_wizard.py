"""File → New head from photographs… in the real window on the default head (issue 19's workbench part).

The photographs are the default head rendered by the toolkit's own renderer
from the front and the side; their true landmark pixels come from that
renderer's camera (as in ``tests/engine/test_photofit.py``). The fit is the
real engine's, on the wizard's worker thread; the tests wait for it through
the Qt event loop (``qtbot.waitUntil``). Finish says a test sentence with the
real Festival.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from PySide6.QtCore import QPoint, QRect, QSize, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QFileDialog, QWizard

import engine
from engine.outputs.render import render_model
from engine.photofit.face_points import point_vertices
from engine.photofit.initial_points import visible_landmarks
from tests.engine.test_photofit import project
from workbench.jobs import running_jobs, wait_for_all
from workbench.photofit_wizard.fit import FitStopped
from workbench.photofit_wizard.wizard import SCREEN_MARGIN, UNDO_TEXT, PhotoFitWizard, size_for
from workbench.window.layouts import fresh_window_size

LAPTOP = fresh_window_size(QRect(0, 0, 1366, 768))
PHOTO_SIZE = (450, 600)
FIT_TIMEOUT_MS = 300_000              # the fit on a loaded 2-core machine; normally a few seconds
SCREENSHOTS = Path(__file__).resolve().parents[2] / "docs" / "images" / "photofit"


def write_photographs(folder, head, size, decimals=None):
    """Front and side PNGs of ``head`` at ``size`` in ``folder``, and points.json with its landmarks' true pixels
    (rounded to ``decimals`` when given); returns the points."""
    points = {}
    for view in ("front", "side"):
        Image.fromarray(render_model(head, view=view, size=size)).save(folder / f"{view}.png")
        pixels = project(head, view, *size)
        points[view] = {k: [float(c) if decimals is None else round(float(c), decimals)
                            for c in pixels[point_vertices(head)[k]]] for k in visible_landmarks(head, view)}
    (folder / "points.json").write_text(json.dumps(points))
    return points


@pytest.fixture(scope="module")
def photographs(tmp_path_factory, head):
    """Front and side PNGs of the default head, and POINTS.json with its landmarks' true pixels."""
    folder = tmp_path_factory.mktemp("photographs")
    points = write_photographs(folder, head, PHOTO_SIZE, decimals=2)
    (folder / "front-points.json").write_text(json.dumps({"front": points["front"]}))
    return folder


@pytest.fixture
def head_window(make_window):
    yield make_window(engine.default_model_path(), size=(LAPTOP.width(), LAPTOP.height()))
    wait_for_all(FIT_TIMEOUT_MS)             # a fit or a Say a failed test left running ends before the window


def open_wizard(window, qtbot) -> PhotoFitWizard:
    window.actions_by_id["file.new_from_photos"].trigger()           # File → New head from photographs…
    wizard = window.photofit_wizard
    qtbot.waitExposed(wizard)
    return wizard


def wait_for_jobs(qtbot) -> None:
    qtbot.waitUntil(lambda: not running_jobs(), timeout=FIT_TIMEOUT_MS)


def on_screen(canvas, x: float, y: float) -> QPoint:
    """The canvas viewport's pixel showing photograph pixel (x, y)."""
    from PySide6.QtCore import QPointF

    return canvas.mapFromScene(QPointF(x, y))


def drag(canvas, start: QPoint, end: QPoint, qtbot) -> None:
    viewport = canvas.viewport()
    QTest.mousePress(viewport, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, start)
    for step in range(1, 6):
        QTest.mouseMove(viewport, start + (end - start) * step / 5)
        qtbot.wait(5)
    QTest.mouseRelease(viewport, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, end)


def test_photographs_to_a_textured_speaking_head_in_one_undo_step(head_window, photographs, qtbot, monkeypatch):
    window = head_window
    document = window.document
    before, steps_before = document.model, document.undo_stack.count()
    wizard = open_wizard(window, qtbot)
    photos = wizard.photos_page
    assert not photos.isComplete()
    assert photos.choose("front", photographs / "front.png")
    assert photos.choose("side", photographs / "side.png")
    assert photos.isComplete()
    wizard.next()
    page = wizard.landmark_page
    assert wizard.currentPage() is page
    front = page.canvases["front"]
    assert set(front.markers) == set(visible_landmarks(before, "front"))      # MPEG-4 and the jaw line's points
    assert set(page.canvases["side"].markers) == set(visible_landmarks(before, "side"))
    qtbot.waitUntil(lambda: front.isVisible() and front.viewport().width() > 100)

    # drag the nose tip with the mouse, then Ctrl+Z
    nose = front.markers["9.3"]
    was = (nose.pos().x(), nose.pos().y())
    start = on_screen(front, *was)
    drag(front, start, start + QPoint(30, 12), qtbot)
    moved = (nose.pos().x(), nose.pos().y())
    scale = front.transform().m11()
    assert moved[0] - was[0] == pytest.approx(30 / scale, abs=2 / scale)
    assert moved[1] - was[1] == pytest.approx(12 / scale, abs=2 / scale)
    assert page.undo_stack.count() == 1 and page.undo_stack.undoText() == "Move 9.3"
    QTest.keyClick(wizard, Qt.Key.Key_Z, Qt.KeyboardModifier.ControlModifier)
    assert (nose.pos().x(), nose.pos().y()) == pytest.approx(was)
    QTest.keyClick(wizard, Qt.Key.Key_Z, Qt.KeyboardModifier.ControlModifier | Qt.KeyboardModifier.ShiftModifier)
    assert (nose.pos().x(), nose.pos().y()) == pytest.approx(moved)

    # right-click leaves an optional point out
    optional = front.markers["9.15"]
    QTest.mouseClick(front.viewport(), Qt.MouseButton.RightButton, Qt.KeyboardModifier.NoModifier,
                     on_screen(front, optional.pos().x(), optional.pos().y()))
    assert not optional.used and "9.15" not in page.points()["front"]
    page.undo_stack.undo()
    assert optional.used

    # the true points from a file (one undo step), saved back the same
    assert page.load(photographs / "points.json")
    assert page.undo_stack.undoText() == "Load points.json"
    truth = json.loads((photographs / "points.json").read_text())
    assert page.points()["front"]["9.3"] == pytest.approx(tuple(truth["front"]["9.3"]))
    page.save(photographs / "saved.json")
    saved = json.loads((photographs / "saved.json").read_text())
    assert saved["front"]["2.1"] == pytest.approx(truth["front"]["2.1"], abs=0.01)
    assert set(saved) == {"front", "side"}

    # the fit, then the fitted head over each photograph
    wizard.next()
    fit_page = wizard.fit_page
    assert wizard.currentPage() is fit_page
    qtbot.waitUntil(fit_page.isComplete, timeout=FIT_TIMEOUT_MS)
    fit = wizard.session.fit
    assert fit is not None and fit.shape.error < 4.0           # px: the points are the true ones
    for view in ("front", "side"):
        assert len(fit_page.canvases[view].fit_items()) == 3   # joins, crosses, outline
    assert document.model is before and document.undo_stack.count() == steps_before   # nothing until Finish

    # Back to adjust a point: the points and their undo steps are kept, Next fits again
    placed, steps = page.points(), page.undo_stack.count()
    wizard.back()
    assert wizard.currentPage() is page and page.points() == placed and page.undo_stack.count() == steps
    chin = front.markers["2.1"]
    start = on_screen(front, chin.pos().x(), chin.pos().y())
    drag(front, start, start + QPoint(0, 3), qtbot)
    assert page.undo_stack.undoText() == "Move 2.1"
    wizard.next()
    assert fit_page.running and not fit_page.isComplete()
    qtbot.waitUntil(fit_page.isComplete, timeout=FIT_TIMEOUT_MS)
    assert wizard.session.fit is not fit and wizard.session.points["front"]["2.1"] != placed["front"]["2.1"]
    fit = wizard.session.fit

    wizard.next()
    result = wizard.result_page
    assert result.document.model is fit.head and result.document is not document     # the page's own
    assert result.viewport.textures_shown()                     # the 3-D view draws the photo texture
    assert result.test_sentence() == "Pappa ampui pallon."
    wizard.button(QWizard.WizardButton.FinishButton).click()

    # one undo step; the head is textured and differs from the one before
    assert document.model is fit.head
    assert [image.name for image in document.model.texture.images] == ["photo"]
    assert before.texture is None or not before.texture.images
    assert not np.allclose(document.model.vertices, before.vertices)
    assert document.undo_stack.count() == steps_before + 1
    assert document.undo_stack.undoText() == UNDO_TEXT

    # ... and it says the test sentence (real Festival) through the player
    qtbot.waitUntil(lambda: window.script_panel.result is not None, timeout=FIT_TIMEOUT_MS)
    assert window.script_panel.result.request.model is fit.head
    assert window.player.duration > 0.5
    window.player.stop()

    # File → Save model as… writes it with its texture
    target = photographs / "saved" / "person.xml"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", staticmethod(lambda *a, **k: (str(target), "")))
    window.actions_by_id["file.save_as"].trigger()
    assert [image.name for image in engine.load_model(target).texture.images] == ["photo"]

    window.undo()
    assert document.model is before
    window.redo()
    assert document.model is fit.head
    wait_for_jobs(qtbot)


def test_stopping_the_fit_and_cancelling_leave_the_document_as_it_was(head_window, photographs, qtbot):
    window = head_window
    document = window.document
    before, steps_before = document.model, document.undo_stack.count()
    wizard = open_wizard(window, qtbot)
    assert wizard.photos_page.choose("front", photographs / "front.png")
    wizard.next()
    assert wizard.landmark_page.load(photographs / "front-points.json")
    ended: list[object] = []
    wizard.next()
    page = wizard.fit_page
    assert page.running
    job = page.job
    job.ended.connect(lambda: ended.append(job.error))
    page.stop_button.click()                                   # Stop mid-fit
    assert not page.running and not page.isComplete() and wizard.session.fit is None
    qtbot.waitUntil(lambda: bool(ended), timeout=FIT_TIMEOUT_MS)
    assert isinstance(ended[0], FitStopped)                    # the fit itself stopped at its next step
    assert "Stopped" in page.status.text()

    page.again_button.click()                                  # fit again, then Cancel the wizard mid-fit
    assert page.running
    wizard.button(QWizard.WizardButton.CancelButton).click()
    assert not wizard.isVisible()
    wait_for_jobs(qtbot)
    assert document.model is before and document.undo_stack.count() == steps_before
    assert not document.is_modified


def test_a_bad_photograph_or_points_file_is_a_dialog_naming_it(head_window, photographs, tmp_path, qtbot,
                                                                captured_errors):
    wizard = open_wizard(head_window, qtbot)
    page = wizard.photos_page
    not_a_picture = tmp_path / "holiday.jpg"
    not_a_picture.write_text("these are not pixels")
    assert not page.choose("front", not_a_picture)
    gif = tmp_path / "face.gif"
    Image.new("RGB", (40, 40)).save(gif)
    assert not page.choose("front", gif)
    assert not page.choose("front", tmp_path / "missing.png")
    assert [title for title, _ in captured_errors] == ["New head from photographs"] * 3
    assert "holiday.jpg" in captured_errors[0][1] and "GIF" in captured_errors[1][1]
    assert "missing.png" in captured_errors[2][1]
    assert not page.isComplete() and "front" not in wizard.session.photos

    assert page.choose("front", photographs / "front.png")
    wizard.next()
    bad = tmp_path / "points.json"
    bad.write_text('{"front": {"3.5": [1, 2]}}')
    assert not wizard.landmark_page.load(bad)
    assert "points.json" in captured_errors[-1][1] and "9.3" in captured_errors[-1][1]
    assert wizard.landmark_page.undo_stack.count() == 0
    wizard.reject()


def test_exif_orientation_is_honoured(head_window, photographs, tmp_path, qtbot):
    """A phone's sideways-stored JPEG (EXIF orientation 6) is shown and fitted upright."""
    upright = Image.open(photographs / "front.png")
    stored = upright.transpose(Image.Transpose.ROTATE_90)          # as the sensor stored it
    exif = Image.Exif()
    exif[0x0112] = 6                                                 # rotate 90° clockwise to view
    stored.save(tmp_path / "phone.jpg", exif=exif, quality=95)
    wizard = open_wizard(head_window, qtbot)
    assert wizard.photos_page.choose("front", tmp_path / "phone.jpg")
    assert wizard.session.photos["front"].shape[:2] == (PHOTO_SIZE[1], PHOTO_SIZE[0])
    wizard.reject()


def test_the_wizard_fits_a_laptop_screen(head_window, qtbot):
    """On a 1366 × 768 laptop (a 28 px panel) the wizard's size leaves room for its frame, and every page fits in it."""
    wizard = open_wizard(head_window, qtbot)
    size = size_for(QSize(1366, 768 - 28))
    assert size.width() + SCREEN_MARGIN.width() <= 1366 and size.height() + SCREEN_MARGIN.height() <= 740
    needed = wizard.minimumSizeHint()
    assert needed.width() <= size.width() and needed.height() <= size.height(), (needed, size)
    for page_id in wizard.pageIds():
        hint = wizard.page(page_id).minimumSizeHint()
        assert hint.width() <= size.width() and hint.height() <= size.height() - 150      # title, buttons
    wizard.reject()


def test_place_the_rest_puts_the_unmoved_points_near_their_places(head_window, photographs, qtbot):
    """After the six required points are on their pixels, Place the rest brings the others close: one undo step."""
    from engine.photofit.points import REQUIRED_FRONT
    from workbench.photofit_wizard.landmarks import MoveMarker

    wizard = open_wizard(head_window, qtbot)
    assert wizard.photos_page.choose("front", photographs / "front.png")
    wizard.photos_page.find_box.setChecked(False)        # the first guesses are the head centred on the photograph
    wizard.next()
    page = wizard.landmark_page
    front = page.canvases["front"]
    truth = json.loads((photographs / "points.json").read_text())["front"]
    first = {k: (m.pos().x(), m.pos().y()) for k, m in front.markers.items()}
    for key in REQUIRED_FRONT:                     # as dragging them would
        page.undo_stack.push(MoveMarker(front, key, first[key], tuple(truth[key])))

    def error(state) -> float:
        d = np.array([np.subtract(state[k][:2], truth[k]) for k in truth if k not in REQUIRED_FRONT])
        return float(np.sqrt((d ** 2).sum(axis=1).mean()))

    before = error(front.state())
    page.place_button.click()
    after = error(front.state())
    assert after < 8.0 and after < 0.5 * before, (before, after)          # px, of a head about 400 px tall
    assert page.undo_stack.undoText() == "Place the rest"
    assert all(front.state()[k][:2] == pytest.approx(tuple(truth[k])) for k in REQUIRED_FRONT)

    # a required point cannot be left out; Reset is one step back to the first guesses
    required = front.markers["9.3"]
    QTest.mouseClick(front.viewport(), Qt.MouseButton.RightButton, Qt.KeyboardModifier.NoModifier,
                     on_screen(front, required.pos().x(), required.pos().y()))
    assert required.used and page.undo_stack.undoText() == "Place the rest"
    page.reset_button.click()
    assert error(front.state()) == pytest.approx(error({k: (*xy, True) for k, xy in first.items()}))
    page.undo_stack.undo()
    assert error(front.state()) == pytest.approx(after)
    wizard.reject()


def test_a_model_of_another_mesh_gets_the_default_heads_landmarks(window, photographs, qtbot):
    """The synthetic head has none of the default head's landmarks: the wizard places the default head's."""
    from workbench.identity_panel.heads import default_head

    wizard = open_wizard(window, qtbot)
    assert wizard.session.landmark_head() is default_head()
    assert wizard.photos_page.choose("front", photographs / "front.png")
    wizard.next()
    assert set(wizard.landmark_page.canvases["front"].markers) == set(visible_landmarks(default_head(), "front"))
    wizard.reject()
    assert window.document.undo_stack.count() == 0
