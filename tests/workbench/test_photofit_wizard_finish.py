"""The photo wizard's Next after a fit, and what Finish does to the document's file (issue 30, section 4).

In the real window, through the wizard's own buttons: a fit that ends must
enable Next (the button, not only ``isComplete``); after Finish the head is a
new person, so the document has no file any more (Save asks, proposing a
name after the photograph in the previous document's folder) and the
previous person's file is never written over, by Save or by the recovery
copy's "belongs to". Undo gives the previous head its file back.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QFileDialog, QWizard

import engine
from tests.workbench.test_photofit_wizard import (  # noqa: F401  (photographs: a fixture)
    FIT_TIMEOUT_MS,
    LAPTOP,
    open_wizard,
    photographs,
    wait_for_jobs,
)
from tests.workbench.test_viewport_keys import press, press_over_the_head, vtk_state
from workbench.jobs import wait_for_all

Next = QWizard.WizardButton.NextButton
Finish = QWizard.WizardButton.FinishButton


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.fixture
def anna(tmp_path, head) -> Path:
    """Another person's head saved in a folder of its own: the document the wizard starts from."""
    folder = tmp_path / "people"
    folder.mkdir()
    return engine.save_model(head, folder / "anna.xml")


@pytest.fixture
def anna_window(make_window, anna):
    yield make_window(anna, size=(LAPTOP.width(), LAPTOP.height()))
    wait_for_all(FIT_TIMEOUT_MS)


def fit_through_the_buttons(window, photographs, qtbot):  # noqa: F811
    """Open the wizard, a front photograph and its points, Next to the fit; returns the wizard once the fit ended."""
    wizard = open_wizard(window, qtbot)
    assert wizard.photos_page.choose("front", photographs / "front.png")
    qtbot.mouseClick(wizard.button(Next), Qt.MouseButton.LeftButton)
    assert wizard.landmark_page.load(photographs / "front-points.json")
    qtbot.mouseClick(wizard.button(Next), Qt.MouseButton.LeftButton)
    page = wizard.fit_page
    assert wizard.currentPage() is page and page.running
    assert not wizard.button(Next).isEnabled()                  # not while fitting
    qtbot.waitUntil(lambda: not page.running, timeout=FIT_TIMEOUT_MS)
    assert wizard.session.fit is not None, page.status.text()
    return wizard


def test_next_is_enabled_once_the_first_fit_is_done(anna_window, photographs, qtbot):  # noqa: F811
    wizard = fit_through_the_buttons(anna_window, photographs, qtbot)
    assert wizard.button(Next).isEnabled(), "the fit is done: Next must take the user to the result"
    qtbot.mouseClick(wizard.button(Next), Qt.MouseButton.LeftButton)
    assert wizard.currentPage() is wizard.result_page

    # the result's 3-D view ignores VTK's keys too, and Escape there reaches the wizard (Cancel)
    plotter = wizard.result_page.viewport.plotter
    state = vtk_state(plotter)
    press_over_the_head(plotter, qtbot, "w3p")
    assert vtk_state(plotter) == state
    rejected: list[bool] = []
    wizard.rejected.connect(lambda: rejected.append(True))
    press(plotter, qtbot, Qt.Key.Key_Escape)
    assert rejected == [True]
    wait_for_jobs(qtbot)


def test_finish_leaves_the_previous_persons_file_alone(anna_window, anna, photographs, qtbot,  # noqa: F811
                                                       monkeypatch):
    window, document = anna_window, anna_window.document
    arrays = anna.with_suffix(".h5")
    before = (digest(anna), digest(arrays))
    anna_head = document.model
    wizard = fit_through_the_buttons(window, photographs, qtbot)
    fit = wizard.session.fit
    wizard.next()
    wizard.result_page.say_box.setChecked(False)                 # no Festival needed here
    qtbot.mouseClick(wizard.button(Finish), Qt.MouseButton.LeftButton)
    assert document.model is fit.head

    # a new person: no file, modified, and the title no longer names anna.xml
    assert document.path is None
    assert document.is_modified
    assert "anna" not in window.windowTitle()

    # Undo: anna's head with anna.xml, nothing to save; Redo: untitled and modified again
    window.undo()
    assert document.model is anna_head and document.path == anna and not document.is_modified
    window.redo()
    assert document.model is fit.head and document.path is None and document.is_modified

    # the recovery copy does not say it belongs to anna.xml
    assert window.autosaver.autosave_now()
    info = json.loads(window.autosaver.session.info_path.read_text())
    assert info["original"] is None

    # Save asks, proposing the photograph's name in anna's folder; anna's files stay as they were
    asked: list[str] = []
    target = anna.parent / "new-person.xml"

    def save_dialog(parent, caption, start, *args, **kwargs):
        asked.append(start)
        return str(target), ""

    monkeypatch.setattr(QFileDialog, "getSaveFileName", staticmethod(save_dialog))
    window.actions_by_id["file.save"].trigger()
    assert asked == [str(anna.parent / "front.xml")]
    assert document.path == target and not document.is_modified
    assert [image.name for image in engine.load_model(target).texture.images] == ["photo"]
    assert (digest(anna), digest(arrays)) == before

    # after the save, Undo: anna's head with anna's file again; Redo: the new person with its own file
    window.undo()
    assert document.model is anna_head and document.path == anna
    window.redo()
    assert document.model is fit.head and document.path == target and not document.is_modified
    window.actions_by_id["file.save"].trigger()                 # nothing asked: it has its own file now
    assert len(asked) == 1
    assert (digest(anna), digest(arrays)) == before
    wait_for_jobs(qtbot)



def test_a_head_from_the_shipped_head_is_proposed_in_the_file_dialogs_folder(make_window, tmp_path, qtbot):
    """The shipped head's folder is never written into: the name goes to the folder Save as would open."""
    from PySide6.QtCore import QSettings

    from workbench import settings
    from workbench.photofit_wizard.session import PhotoFitSession
    from workbench.photofit_wizard.wizard import suggested_path

    window = make_window(engine.default_model_path())
    QSettings().setValue(settings.LAST_DIR, str(tmp_path))
    session = PhotoFitSession(window.document.model, paths={"front": Path("/photos/IMG_2031.jpg")})
    assert suggested_path(window, session) == tmp_path / "IMG_2031.xml"
