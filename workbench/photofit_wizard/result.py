"""The wizard's result page: the fitted, textured head in a 3-D view, saying a test sentence.

The page has a document of its own (:class:`~workbench.document.model_document.ModelDocument`
holding the fitted head, not the window's: nothing reaches the window's
model before Finish), shown by the workbench's own :class:`~workbench.viewport.view.Viewport`
and played by its own :class:`~workbench.playback.player.Player` and
:class:`~workbench.document.playhead.Playhead`, the classes the main window uses.
**Say** synthesizes the sentence with Festival through the engine's
:func:`engine.speech.say.speak` on a worker thread (a
:class:`~workbench.jobs.Job`), so the page keeps answering;
**Stop**, Back or the wizard's Cancel end the synthesis (Festival is
killed) or the playing. Finish can say the sentence again in the main window
(:func:`workbench.photofit_wizard.wizard.finish`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtWidgets import (
    QCheckBox,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWizardPage,
)

from ..document.playhead import Playhead
from ..jobs import Job
from .session import PhotoFitSession

if TYPE_CHECKING:
    from engine.speech.say import Speech

    from ..document.model_document import ModelDocument
    from ..playback.player import Player
    from ..viewport.view import Viewport

TEST_SENTENCE = "Pappa ampui pallon."
VIEW_MINIMUM = (360, 300)                 # px: the 3-D view's least size
TITLE_LENGTH = 40


class ResultPage(QWizardPage):
    def __init__(self, session: PhotoFitSession, voice: str | None = None):
        super().__init__()
        self.session = session
        self.voice = voice
        self.document: ModelDocument | None = None        # the page's own, made when the page first opens
        self.viewport: Viewport | None = None
        self.player: Player | None = None
        self.playhead = Playhead(self)
        self.job: Job | None = None
        self.speech: Speech | None = None
        self.setTitle("Result")
        self.setSubTitle("The fitted head, textured with your photographs. Say makes it speak; drag the view to "
                         "turn it. Finish makes this head the model (Edit → Undo brings the previous one back).")
        self.view_box = QVBoxLayout()
        self.sentence = QLineEdit(TEST_SENTENCE)
        self.sentence.setToolTip("A sentence for the head to say (inline commands work as in the script panel)")
        self.sentence.returnPressed.connect(self.say)
        self.say_button = QPushButton("Say")
        self.say_button.setToolTip("Synthesize the sentence with Festival and play it on this head")
        self.say_button.clicked.connect(self.say)
        self.stop_button = QPushButton("Stop")
        self.stop_button.setToolTip("Stop the synthesis or the playing")
        self.stop_button.clicked.connect(self.stop_speaking)
        self.stop_button.setEnabled(False)
        self.status = QLabel("")
        self.status.setWordWrap(True)
        self.say_box = QCheckBox("After Finish, say it again in the main window")
        self.say_box.setChecked(True)
        say_row = QHBoxLayout()
        say_row.addWidget(QLabel("Sentence:"))
        say_row.addWidget(self.sentence, 1)
        say_row.addWidget(self.say_button)
        say_row.addWidget(self.stop_button)
        layout = QVBoxLayout(self)
        layout.addLayout(self.view_box, 1)
        layout.addLayout(say_row)
        layout.addWidget(self.status)
        layout.addWidget(self.say_box)

    # -- QWizardPage ---------------------------------------------------------------------
    def initializePage(self) -> None:
        fit = self.session.fit
        if fit is None:
            return
        if self.document is None:
            self._make_view(fit.head)
        elif self.document.model is not fit.head:
            self.stop_speaking()
            self.document.replace_model(fit.head)
        assert self.viewport is not None
        self.viewport.set_view("three-quarter")
        self.status.setText("")

    def cleanupPage(self) -> None:            # Back: whatever is being said is not wanted any more
        self.stop_speaking()

    def _make_view(self, head) -> None:
        from ..document.model_document import ModelDocument
        from ..document.view_state import ViewState
        from ..playback.player import Player
        from ..viewport.view import Viewport

        self.document = ModelDocument(head, parent=self)
        self.viewport = Viewport(self.document, ViewState(self), self)
        self.viewport.setObjectName("photofit_wizard.result_view")
        self.viewport.setMinimumSize(*VIEW_MINIMUM)
        self.view_box.addWidget(self.viewport)
        self.player = Player(self.document, self.playhead, self)
        self.player.state_changed.connect(self._show_state)

    def close_view(self) -> None:
        """Stop speaking and release the 3-D view's render window (the wizard is going away)."""
        self.stop_speaking()
        if self.viewport is not None:
            self.viewport.close_plotter()

    # -- speaking ---------------------------------------------------------------------------
    @property
    def synthesizing(self) -> bool:
        return self.job is not None

    def say(self) -> Job | None:
        """Say the sentence with the fitted head: Festival on a worker thread, then the page's player."""
        text = self.sentence.text().strip()
        if not text or self.document is None:
            return None
        self.stop_speaking()
        model, voice = self.document.model, self.voice

        def work(job: Job):
            from engine.speech.festival import FestivalSynthesizer
            from engine.speech.say import speak

            return speak(text, model, synthesizer=FestivalSynthesizer(cancelled=lambda: job.cancelled), voice=voice)

        job = self.job = Job(work)
        job.ended.connect(self._on_said)
        self.status.setText(f"Synthesizing: {text}")
        self.stop_button.setEnabled(True)
        job.start()
        return job

    def stop_speaking(self) -> None:
        """End the synthesis (Festival is killed) and the playing; the head goes back to rest."""
        if self.job is not None:
            self.job.cancel()
            self.job = None
            self.status.setText("Stopped.")
        if self.player is not None:
            self.player.stop()
        self.stop_button.setEnabled(False)

    def _on_said(self) -> None:
        from engine.errors import UserError
        from engine.speech.requests import described_error

        job = self.sender()
        if job is not self.job or self.player is None or self.document is None:      # stopped: means nothing
            return
        self.job = None
        self.stop_button.setEnabled(False)
        if job.error is not None:
            error = job.error
            self.status.setText(described_error(error) if isinstance(error, UserError)
                                else f"Say failed: {type(error).__name__}: {error}")
            return
        speech = self.speech = job.result
        if speech.timeline.model is not self.document.model:         # another fit came meanwhile
            return
        text = " ".join(speech.script.text.split())
        title = text if len(text) <= TITLE_LENGTH else text[:TITLE_LENGTH - 1] + "…"
        self.player.load(speech.timeline, audio=speech.utterance, phones=speech.utterance.phones, title=title)
        self.player.play()
        self.status.setText(f"Saying: {title}")

    def _show_state(self, state: str) -> None:
        if self.job is None:
            self.stop_button.setEnabled(state == "playing")

    def test_sentence(self) -> str | None:
        """The sentence to say in the main window after Finish, or ``None``."""
        text = self.sentence.text().strip()
        return text if self.say_box.isChecked() and text else None
