"""A recorded voice for Say: a WAV and its phone labels instead of Festival (issue 24).

One row of the script panel: what is chosen (``take.wav + take.TextGrid``),
**Choose…** (the WAV, then its labels: a Praat TextGrid, a label file or a
phones CSV; a labels file beside the WAV with the same name is offered
first) and **×** (clear: back to Festival). The choice is kept across sessions
(QSettings ``script_panel/recording_*``) as long as both files still exist.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QSettings, Signal
from PySide6.QtWidgets import QFileDialog, QWidget

from .file_choice_row import FileChoiceRow

KEY_AUDIO = "script_panel/recording_audio"
KEY_LABELS = "script_panel/recording_labels"
LABEL_SUFFIXES = (".TextGrid", ".textgrid", ".lab", ".csv", ".txt")
LABEL_FILTER = "Phone labels (*.TextGrid *.textgrid *.lab *.csv *.txt);;All files (*)"


class RecordingChooser(FileChoiceRow):
    """``recording`` is ``(wav, labels)`` or ``None`` (Festival speaks); ``changed`` fires when it changes."""

    changed = Signal()

    def __init__(self, parent: QWidget | None = None):
        super().__init__(
            "recording", "none",
            "Speak with a recorded voice: a WAV file and its phone labels (TextGrid, label file or phones CSV); "
            "the text then holds only the inline commands, anchored to the labels' word tier",
            "Back to Festival's voice", self.choose, lambda: self.set_recording(None), parent,
            empty_tip="No recording: Festival speaks the text with the voice chosen above")
        self.recording: tuple[Path, Path] | None = None
        self._restore()

    def choose(self) -> None:
        """Ask for the WAV, then for its labels; nothing changes if either is cancelled."""
        start = str(self.recording[0].parent) if self.recording else ""
        audio, _ = QFileDialog.getOpenFileName(self, "Recorded voice: the audio", start,
                                               "WAV audio (*.wav *.WAV);;All files (*)")
        if not audio:
            return
        beside = next((Path(audio).with_suffix(s) for s in LABEL_SUFFIXES if Path(audio).with_suffix(s).is_file()),
                      Path(audio).parent)
        labels, _ = QFileDialog.getOpenFileName(self, f"Phone labels of {Path(audio).name}", str(beside),
                                                LABEL_FILTER)
        if labels:
            self.set_recording((Path(audio), Path(labels)))

    def set_recording(self, recording: tuple[Path, Path] | None) -> None:
        self.recording = (Path(recording[0]), Path(recording[1])) if recording else None
        self.show_choice(f"{self.recording[0].name} + {self.recording[1].name}" if self.recording else "",
                         "\n".join(str(p) for p in self.recording) if self.recording else "",
                         self.recording is not None)
        store = QSettings()
        store.setValue(KEY_AUDIO, str(self.recording[0]) if self.recording else "")
        store.setValue(KEY_LABELS, str(self.recording[1]) if self.recording else "")
        self.changed.emit()

    def _restore(self) -> None:
        store = QSettings()
        audio, labels = str(store.value(KEY_AUDIO, "") or ""), str(store.value(KEY_LABELS, "") or "")
        kept = audio and labels and Path(audio).is_file() and Path(labels).is_file()
        self.set_recording((Path(audio), Path(labels)) if kept else None)
