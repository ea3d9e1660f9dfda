"""File → New head from photographs…: a wizard from a front (and side) photograph to a textured, speaking head.

Pages: photographs (:mod:`.photos`), landmarks to drag
(:mod:`.landmarks`, its own undo stack), the fit on a worker
thread with the fitted head laid over each photograph
(:mod:`.fit`), and the result in a 3-D view saying a test
sentence (:mod:`.result`). Cancel on any page, or Stop during
the fit, leaves the document as it was; Finish makes the fitted head the
document's model as one undo step ("New head from photographs"), with no
file: Save asks, proposing a name after the front photograph, and never
writes over the previous person's file; and, if
asked, says the sentence again through the window's player as the script
panel does. See docs/workbench-photofit.md.
"""

from __future__ import annotations

import dataclasses
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QSize
from PySide6.QtGui import QUndoStack
from PySide6.QtWidgets import QMessageBox, QWidget, QWizard

from ..document.undo_commands import ReplaceModelCommand
from .fit import FitPage
from .landmarks import LandmarkPage
from .photos import PhotosPage
from .result import ResultPage
from .session import TITLE, PhotoFitSession

if TYPE_CHECKING:
    import engine
    from engine.photofit import PhotoFit

    from ..document.model_document import ModelDocument
    from ..window.main_window import MainWindow

UNDO_TEXT = "New head from photographs"
WANTED_SIZE = QSize(1240, 760)
SCREEN_MARGIN = QSize(40, 70)             # the window frame and a panel or two


class PhotoFitWizard(QWizard):
    def __init__(self, session: PhotoFitSession, parent: QWidget | None = None, voice: str | None = None):
        super().__init__(parent)
        self.session = session
        self.setWindowTitle(TITLE)
        self.setObjectName("photofit_wizard")
        self.setWizardStyle(QWizard.WizardStyle.ClassicStyle)
        self.setOption(QWizard.WizardOption.NoBackButtonOnStartPage)
        self.undo_stack = QUndoStack(self)
        self.photos_page = PhotosPage(session)
        self.landmark_page = LandmarkPage(session, self.undo_stack)
        self.fit_page = FitPage(session)
        self.result_page = ResultPage(session, voice)
        for page in (self.photos_page, self.landmark_page, self.fit_page, self.result_page):
            self.addPage(page)
        self.rejected.connect(self.fit_page.stop)
        self.finished.connect(self.result_page.close_view)      # Finish or Cancel: Festival and the view end
        self.resize(self.size_for_screen())

    def size_for_screen(self) -> QSize:
        screen = self.screen()
        return WANTED_SIZE if screen is None else size_for(screen.availableGeometry().size())


def size_for(available: QSize) -> QSize:
    """The wizard's size on a screen with ``available`` room: :data:`WANTED_SIZE`, smaller if need be."""
    return WANTED_SIZE.boundedTo(available - SCREEN_MARGIN)


def open_photofit_wizard(window: MainWindow) -> PhotoFitWizard:
    """Show the wizard over ``window`` (window-modal); Finish puts the head into its document."""
    panel = getattr(window, "script_panel", None)
    voice = (panel.voice_box.currentText() or None) if panel is not None else None
    wizard = PhotoFitWizard(PhotoFitSession(window.document.model), window, voice)
    window.photofit_wizard = wizard
    wizard.accepted.connect(lambda: finish(window, wizard))
    wizard.finished.connect(wizard.deleteLater)
    wizard.open()
    return wizard


def finish(window: MainWindow, wizard: PhotoFitWizard) -> None:
    fit = wizard.session.fit
    if fit is None:
        return
    adopt(window, fit, suggested_path(window, wizard.session))
    sentence = wizard.result_page.test_sentence()
    if sentence is not None:
        say_test_sentence(window, sentence)


def adopt(window: MainWindow, fit: PhotoFit, suggested: Path | None = None) -> None:
    """The fitted head becomes the document's model, with no file (``suggested``: the name Save proposes):
    one undo step."""
    window.document.push(NewPersonCommand(window.document, fit.head, UNDO_TEXT, suggested))
    window.viewport.set_view("front")
    window.statusBar().showMessage("New head from photographs: File → Save asks where to write it", 6000)


def suggested_path(window: MainWindow, session: PhotoFitSession) -> Path:
    """Where Save proposes to write the new head: named after the front photograph, in the previous model's
    folder (the file dialog's usual folder when that was the shipped head or had no file)."""
    from ..window.file_controller import is_shipped

    previous = window.document.path
    folder = previous.parent if previous is not None and not is_shipped(previous) else Path(window.files.start_dir())
    photo = session.paths.get("front")
    return folder / f"{photo.stem if photo is not None else 'person'}.xml"


class NewPersonCommand(ReplaceModelCommand):
    """Another person's head replaces the model: the document has no file while it is current, so Save asks
    (proposing ``suggested``) and never writes over the previous person's file; undo gives that file back,
    redo the file the new head was saved to meanwhile, if it was."""

    def __init__(self, document: ModelDocument, model: engine.Model, text: str, suggested: Path | None):
        super().__init__(document, model, text)
        self.other_file: tuple[Path | None, Path | None] = (None, suggested)    # the file the other head has

    def apply(self) -> None:
        super().apply()
        self.other_file = self.document.apply_file(*self.other_file)

    def revert(self) -> None:
        super().revert()
        self.other_file = self.document.apply_file(*self.other_file)


def say_test_sentence(window: MainWindow, text: str):
    """Say ``text`` with the document's model through the window's player, with the script panel's voice.

    Returns the :class:`~workbench.jobs.Job` (``None`` where the window has no script panel).
    """
    from engine.speech.requests import run_say

    from ..jobs import Job

    panel = getattr(window, "script_panel", None)
    if panel is None:
        return None
    request = dataclasses.replace(panel.request(), text=text, model=window.document.model, audio=None, labels=None,
                                  voice=panel.voice_box.currentText() or None)
    folder = _scratch_folder()
    job = Job(lambda job: run_say(request, folder, lambda: job.cancelled))
    window.photofit_speech = job

    def said() -> None:
        if job.error is not None:
            QMessageBox.warning(window, TITLE, f"The test sentence could not be said: {job.error}")
            return
        if window.isVisible() and window.document.model is request.model:
            panel.adopt(job.result)
            panel._play(job.result)            # as the script panel's own Say plays it

    job.ended.connect(said)
    window.statusBar().showMessage(f"Saying: {text}", 6000)
    job.start()
    return job


_SCRATCH: list[tempfile.TemporaryDirectory] = []


def _scratch_folder():
    if not _SCRATCH:
        _SCRATCH.append(tempfile.TemporaryDirectory(prefix="artificial-person-photofit-say-"))
    return Path(_SCRATCH[0].name)
