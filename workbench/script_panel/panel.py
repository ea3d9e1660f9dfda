"""The script panel: the paper's user command interpreter (§2) in a dock.

Type text with inline commands (``Hyvää <Happy/> huomenta!``), choose a
voice and the coarticulation, press **Say** (Ctrl+Return): Festival and the
articulation run on a worker thread while a busy bar shows (Cancel forgets
the run), then the result is loaded into the window's player — the head
speaks it with the audio, the phones appear on the timeline. Errors (an
inline command the library does not know, a missing voice, a character
Festival cannot read) open a dialog naming line and column and put the
cursor there; the text is never touched. The text, voice and coarticulation
are kept across sessions (QSettings ``script_panel/…``).
"""

from __future__ import annotations

import contextlib
import functools
import tempfile
from pathlib import Path

from PySide6.QtCore import QSettings, Qt, Signal
from PySide6.QtGui import QFont, QTextCursor
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QMessageBox,
    QPlainTextEdit,
    QProgressBar,
    QPushButton,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from engine.errors import UserError
from engine.speech.requests import SayRequest, SayResult, described_error, error_location, run_say

from ..icons import icon
from ..jobs import Job
from ..tools import ToolContext
from .highlighter import InlineCommandHighlighter
from .recording_chooser import RecordingChooser
from .table_chooser import PhoneTableChooser

KEY_TEXT = "script_panel/text"
KEY_VOICE = "script_panel/voice"
KEY_COARTICULATION = "script_panel/coarticulation"
KEY_PROSODY = "script_panel/prosody"
KEY_SEED = "script_panel/prosody_seed"
DEFAULT_TEXT = "Hyvää <Happy/> huomenta! Mitä kuuluu?"
DEFAULT_VOICE = "suo_fi_lj_diphone"
#: The library expressions whose emotion the classifier knows (a script holding one of them means it).
EXPRESSION_NAMES = frozenset({"Happy", "Sad", "Surprise", "Fear", "Anger", "Disgust", "Neutral"})
#: The coarticulation menu: label → the engine's name for it.
COARTICULATIONS = (("Cohen–Massaro", "cohen-massaro"), ("none (target interpolation)", "none"))
MESSAGE_MS = 6000


@functools.cache
def _shared_festival():
    """One FestivalSynthesizer for listing voices: it remembers them, so a second window asks no more."""
    from engine.speech.festival import FestivalSynthesizer

    return FestivalSynthesizer()


class ScriptPanel(QWidget):
    """The dock's widget. ``result`` is the last :class:`SayResult` (``None`` before the first Say).

    Signals: ``busy_changed(bool)``, ``said(object)`` (a :class:`SayResult`),
    ``say_failed(str)`` (the message shown).
    """

    busy_changed = Signal(bool)
    said = Signal(object)
    say_failed = Signal(str)

    def __init__(self, context: ToolContext, parent: QWidget | None = None):
        super().__init__(parent)
        self.context = context
        self.window = context.window      # the parent of its dialogs
        self.result: SayResult | None = None
        self.synthesizer = None                  # None: Festival on PATH (tests may put another here)
        self.job: Job | None = None
        self._voices_job: Job | None = None
        self._scratch = tempfile.TemporaryDirectory(prefix="artificial-person-say-")
        self._build()
        self._restore()
        self.list_voices()

    # -- widgets -------------------------------------------------------------
    def _build(self) -> None:
        self.editor = QPlainTextEdit()
        self.editor.setObjectName("script_panel.editor")
        self.editor.setPlaceholderText("Text to speak, with inline commands: Hyvää <Happy/> huomenta!")
        self.editor.setFont(QFont("Monospace", 10))
        self.editor.setTabChangesFocus(True)
        self.highlighter = InlineCommandHighlighter(self.editor.document())
        self.voice_box = QComboBox()
        self.voice_box.setObjectName("script_panel.voice")
        self.voice_box.setToolTip("The Festival voice (suo_fi_lj_diphone: Finnish, female; "
                                  "hy_fi_mv_diphone: Finnish, male)")
        self.recording_chooser = RecordingChooser()
        self.recording_chooser.changed.connect(self._on_recording_changed)
        self.coarticulation_box = QComboBox()
        self.coarticulation_box.setObjectName("script_panel.coarticulation")
        for label, value in COARTICULATIONS:
            self.coarticulation_box.addItem(label, value)
        self.coarticulation_box.setToolTip("Cohen–Massaro dominance functions, or the paper's plain "
                                           "interpolation between each phone's targets")
        self.table_chooser = PhoneTableChooser()
        self.prosody_box = QCheckBox("&Visual prosody, seed")
        self.prosody_box.setObjectName("script_panel.prosody")
        self.prosody_box.setToolTip("Add blinks, brows raised on accented words and nods at phrase ends "
                                    "(the library's Blink, BrowRaise, HeadNod); the same seed gives the same face")
        self.seed_box = QSpinBox()
        self.seed_box.setObjectName("script_panel.seed")
        self.seed_box.setRange(0, 999999)
        self.prosody_box.toggled.connect(self.seed_box.setEnabled)
        self.say_button = QPushButton(icon("say"), "Say")
        self.say_button.setObjectName("script_panel.say")
        self.say_button.setToolTip("Speak the text (Ctrl+Return)")
        self.say_button.clicked.connect(self.say)
        self.cancel_button = QPushButton("Cancel")
        self.cancel_button.setObjectName("script_panel.cancel")
        self.cancel_button.clicked.connect(self.cancel)
        self.export_button = QPushButton(icon("export-speech"), "Export…")
        self.export_button.setObjectName("script_panel.export")
        self.export_button.setToolTip("Write the last utterance as MP4, WAV and CSV files")
        self.export_button.setEnabled(False)
        self.validate_button = QPushButton("Validate")
        self.validate_button.setObjectName("script_panel.validate")
        self.validate_button.setToolTip("Judge the last utterance's face, frame by frame, with observers trained on "
                                        "photographs of people: face found, emotion, lips against the engine's")
        self.validate_button.setEnabled(False)
        self.validate_button.clicked.connect(lambda _checked=False: self.validate())
        self.validation_job: Job | None = None
        self.busy_bar = QProgressBar()
        self.busy_bar.setRange(0, 0)                 # "busy", no known length
        self.busy_bar.setTextVisible(False)
        self.busy_bar.setMaximumHeight(10)
        self.info = QLabel("")
        self.info.setObjectName("script_panel.info")
        self.info.setWordWrap(True)
        self.info.setTextFormat(Qt.TextFormat.PlainText)

        form = QFormLayout()
        form.addRow("&Voice:", self.voice_box)
        form.addRow("Recording:", self.recording_chooser)
        form.addRow("&Coarticulation:", self.coarticulation_box)
        form.addRow("Phone table:", self.table_chooser)
        prosody = QHBoxLayout()
        prosody.addWidget(self.prosody_box)
        prosody.addWidget(self.seed_box)
        prosody.addStretch(1)
        form.addRow("", prosody)
        buttons = QHBoxLayout()
        buttons.addWidget(self.say_button)
        buttons.addWidget(self.cancel_button)
        buttons.addStretch(1)
        buttons.addWidget(self.validate_button)
        buttons.addWidget(self.export_button)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 6, 6, 6)
        layout.addWidget(self.editor, 1)
        layout.addLayout(form)
        layout.addLayout(buttons)
        layout.addWidget(self.busy_bar)
        layout.addWidget(self.info)
        self._show_busy(False)

    def _restore(self) -> None:
        store = QSettings()
        self.editor.setPlainText(str(store.value(KEY_TEXT, DEFAULT_TEXT)))
        self.voice_box.addItem(str(store.value(KEY_VOICE, DEFAULT_VOICE)))
        index = self.coarticulation_box.findData(str(store.value(KEY_COARTICULATION, "cohen-massaro")))
        self.coarticulation_box.setCurrentIndex(max(0, index))
        self.prosody_box.setChecked(str(store.value(KEY_PROSODY, "false")).lower() == "true")
        self.seed_box.setValue(int(store.value(KEY_SEED, 0)))
        self.seed_box.setEnabled(self.prosody_box.isChecked())
        # Every keystroke is remembered: nothing typed is lost, even in a crash.
        self.editor.textChanged.connect(lambda: QSettings().setValue(KEY_TEXT, self.editor.toPlainText()))
        self.voice_box.currentTextChanged.connect(self._remember_voice)
        self.coarticulation_box.currentIndexChanged.connect(
            lambda _i: QSettings().setValue(KEY_COARTICULATION, self.coarticulation_box.currentData()))
        self.prosody_box.toggled.connect(lambda on: QSettings().setValue(KEY_PROSODY, "true" if on else "false"))
        self.seed_box.valueChanged.connect(lambda seed: QSettings().setValue(KEY_SEED, seed))

    def _on_recording_changed(self) -> None:
        recorded = self.recording_chooser.recording is not None
        self.voice_box.setEnabled(not recorded)      # a recording speaks with its own voice
        self.editor.setPlaceholderText("Inline commands for the recording, anchored to its words: "
                                       "Hello <Happy/> world" if recorded else
                                       "Text to speak, with inline commands: Hyvää <Happy/> huomenta!")

    def _remember_voice(self, voice: str) -> None:
        if voice:
            QSettings().setValue(KEY_VOICE, voice)

    # -- voices --------------------------------------------------------------
    def list_voices(self) -> None:
        """Ask Festival for its voices (off the GUI thread); the chooser fills in when it answers."""
        synthesizer = self.synthesizer or _shared_festival()
        job = self._voices_job = Job(lambda _job: synthesizer.voices())
        job.ended.connect(self._on_voices)          # a bound method: nothing arrives once the panel is gone
        job.start()

    def _on_voices(self) -> None:
        job = self.sender()
        if job is not self._voices_job:
            return
        self._voices_job = None
        if job.error is not None:
            self.voice_box.setToolTip(str(job.error))   # Say will show the same message in a dialog
            return
        current = self.voice_box.currentText()
        self.voice_box.blockSignals(True)
        self.voice_box.clear()
        self.voice_box.addItems(job.result)
        if current and current not in job.result:
            self.voice_box.addItem(current)             # keep the choice: Say then names the missing package
        self.voice_box.setCurrentText(current or DEFAULT_VOICE)
        self.voice_box.blockSignals(False)

    @property
    def voices(self) -> list[str]:
        return [self.voice_box.itemText(i) for i in range(self.voice_box.count())]

    # -- Say ---------------------------------------------------------------------
    @property
    def busy(self) -> bool:
        return self.job is not None

    def request(self) -> SayRequest:
        """What Say would speak now."""
        recording = self.recording_chooser.recording
        return SayRequest(self.editor.toPlainText(), self.context.document.model,
                          voice=None if recording else (self.voice_box.currentText() or None),
                          audio=recording[0] if recording else None, labels=recording[1] if recording else None,
                          coarticulation=self.coarticulation_box.currentData(),
                          table=self.table_chooser.path,
                          prosody_seed=self.seed_box.value() if self.prosody_box.isChecked() else None,
                          synthesizer=self.synthesizer)

    def say(self) -> None:
        """Speak the text: synthesis on a worker thread, then the player plays it."""
        if self.busy:
            return
        request = self.request()
        folder = Path(self._scratch.name)
        job = self.job = Job(lambda job: run_say(request, folder, lambda: job.cancelled))
        job.ended.connect(self._on_said)
        self._show_busy(True)
        self.info.setText("Synthesizing…")
        job.start()

    def cancel(self) -> None:
        """Stop the running Say: Festival is killed within 0.1 s and nothing it made is kept."""
        if self.job is None:
            return
        self.job.cancel()
        self.job = None
        self._show_busy(False)
        self.info.setText("Cancelled.")

    def _on_said(self) -> None:
        job = self.sender()
        if job is not self.job:                 # cancelled: drop it
            return
        self.job = None
        self._show_busy(False)
        if job.error is not None:
            self._report_error(job.error)
            return
        self.adopt(job.result)
        if self.window.isVisible():             # a window closed meanwhile stays silent
            self._play(job.result)

    def adopt(self, result: SayResult) -> None:
        """Make ``result`` the last utterance (what Export writes) without playing it."""
        self._forget_previous_wav(result)
        self.result = result
        self.export_button.setEnabled(True)
        self.validate_button.setEnabled(True)
        phones = result.speech.utterance.phones
        summary = (f"{result.duration:.2f} s, {len(phones)} phone{'s' * (len(phones) != 1)}, "
                   f"voice {result.speech.utterance.voice}")
        tokens = [warning.token for warning in result.speech.reading_warnings]
        if tokens:   # what Festival read oddly, in one short line; the whole advice in the tooltip
            shown = ", ".join(f"'{t}'" for t in tokens[:4]) + (" …" if len(tokens) > 4 else "")
            summary += f"\nFestival reads {shown} oddly: write out in words"
        self.info.setToolTip("\n".join(f"Warning: {w}" for w in result.speech.warnings))
        self.info.setText(summary)
        self.said.emit(result)

    def validate(self) -> Job | None:
        """Judge the last utterance as a video (front view, 30 fps): drawn here, judged on a worker
        thread, the verdict in a dialog (:mod:`workbench.validation_view`). Returns the job."""
        import numpy as np

        from engine.validation import Intended, intended_emotion, lip_track

        from ..validation_view import VIDEO_FPS, VIDEO_SIZE, judge_in_background, render_frames

        result = self.result
        if result is None:
            return None
        model, speech = result.request.model, result.speech
        times = np.arange(0.0, max(speech.end_ms, 1000.0 / VIDEO_FPS), 1000.0 / VIDEO_FPS)
        values = speech.timeline.sample(times)
        deformer = model.deformer()
        frames = render_frames(model, [deformer.deform(row) for row in values], VIDEO_SIZE, self)
        if frames is None:
            return None
        expressions = {c.command.name for c in speech.script.commands} & EXPRESSION_NAMES
        meant = "neutral" if not expressions else intended_emotion(expressions.pop()) if len(expressions) == 1 \
            else None
        text = " ".join(speech.script.text.split())
        title = text if len(text) <= 40 else text[:39] + "…"
        self.info.setText("Judging the face… (the observers take a few seconds to load)")
        self.validation_job = judge_in_background(frames, Intended(emotion=meant, expression=", ".join(
            sorted(expressions)) or "none"), lip_track(model, times, values), title, self, fps=VIDEO_FPS)
        return self.validation_job

    def _play(self, result: SayResult) -> None:
        player = self.context.player
        text = " ".join(result.speech.script.text.split())
        title = text if len(text) <= 40 else text[:39] + "…"
        player.load(result.speech.timeline, audio=str(result.wav), phones=result.speech.utterance.phones,
                    title=title)
        player.play()
        self.context.status.showMessage(f"Saying: {title}", MESSAGE_MS)

    def _report_error(self, error: BaseException) -> None:
        if isinstance(error, UserError):
            message = described_error(error)
            where = error_location(error)
            if where is not None:
                self._put_cursor(*where)
        else:                                       # a bug of ours: say so, keep the text, no crash
            message = f"Say failed: {type(error).__name__}: {error}"
        self.info.setText(message)
        self.say_failed.emit(message)
        QMessageBox.warning(self.window, "Say", message)

    def _put_cursor(self, line: int, column: int) -> None:
        block = self.editor.document().findBlockByLineNumber(line - 1)
        if not block.isValid():
            return
        cursor = QTextCursor(block)
        cursor.movePosition(QTextCursor.MoveOperation.Right, QTextCursor.MoveMode.MoveAnchor,
                            min(column - 1, max(0, block.length() - 1)))
        self.editor.setTextCursor(cursor)
        self.editor.setFocus()

    def _forget_previous_wav(self, result: SayResult) -> None:
        # The player has read the previous clip into memory; only the newest WAV is kept on disk.
        if self.result is not None and self.result.wav != result.wav:
            with contextlib.suppress(OSError):
                self.result.wav.unlink()

    def _show_busy(self, busy: bool) -> None:
        self.busy_bar.setVisible(busy)
        self.cancel_button.setEnabled(busy)
        self.say_button.setEnabled(not busy)
        self.busy_changed.emit(busy)
