"""A face judged from the workbench (**Validate** in the expression gallery and the script panel).

The pictures are drawn on the GUI thread (VTK's contexts live there), in small steps so the
window stays responsive; the observers of :mod:`engine.validation` (their first load takes a few
seconds) judge them on a worker thread (:class:`~workbench.jobs.Job`), and the
verdict opens in a :class:`VerdictDialog`: the picture, the face found, the emotion meant and the
one judged with every class's probability, for a video the lips against the engine's, and
*Save report…* writing the one-page HTML report ``validate --report`` writes.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np
from PySide6.QtCore import Qt
from PySide6.QtGui import QImage, QPixmap
from PySide6.QtWidgets import (
    QApplication,
    QDialog,
    QDialogButtonBox,
    QFileDialog,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QMessageBox,
    QProgressBar,
    QProgressDialog,
    QVBoxLayout,
    QWidget,
)

from engine.errors import UserError

from .jobs import Job

STILL_SIZE = (640, 480)
VIDEO_SIZE = (480, 360)
VIDEO_FPS = 30.0
PICTURE_WIDTH = 260


def render_frames(model, poses: Sequence[np.ndarray], size: tuple[int, int], parent: QWidget | None = None,
                  title: str = "Drawing the faces to judge…") -> list[np.ndarray] | None:
    """The front-view pictures of ``model`` at each of ``poses`` (vertex positions), drawn on the GUI
    thread with a progress dialog for more than a few; None when the user cancels."""
    from engine.outputs.render import FrameRenderer

    progress = None
    if len(poses) > 3:
        progress = QProgressDialog(title, "Cancel", 0, len(poses), parent)
        progress.setWindowModality(Qt.WindowModality.WindowModal)
        progress.setMinimumDuration(300)
    frames = []
    with FrameRenderer(model, size=size, view="front") as renderer:
        for n, positions in enumerate(poses):
            if progress is not None:
                progress.setValue(n)
                QApplication.processEvents()
                if progress.wasCanceled():
                    return None
            frames.append(renderer.render(positions))
    if progress is not None:
        progress.setValue(len(poses))
    return frames


def judge_in_background(frames: list[np.ndarray], intended, lips, title: str, parent: QWidget,
                        fps: float | None = None, on_verdict: Callable | None = None) -> Job:
    """Judge ``frames`` (one still, or a video's frames when ``fps`` is given) on a worker thread; the
    verdict opens in a :class:`VerdictDialog` (and goes to ``on_verdict``)."""
    def work(job: Job):
        from engine.validation import judge_pixels
        from engine.validation.judge import judge_frames

        if fps is None:
            return judge_pixels(frames[0], title, intended)
        return judge_frames(frames, fps, title, intended, lips)

    job = Job(work)

    def ended() -> None:
        if job.error is not None:
            message = str(job.error) if isinstance(job.error, UserError) else f"{job.error}\n\n{job.error_details}"
            QMessageBox.warning(parent, "Validate", f"The face could not be judged:\n{message}")
            return
        if on_verdict is not None:
            on_verdict(job.result)
        dialog = VerdictDialog(job.result, frames[len(frames) // 2], parent)
        dialog.show()
        parent.verdict_dialog = dialog             # keep it alive while open (and for tests)

    job.ended.connect(ended)
    job.start()
    return job


class VerdictDialog(QDialog):
    """One verdict: the picture, what was found, the probabilities, and the report to save."""

    def __init__(self, verdict, picture: np.ndarray, parent: QWidget | None = None):
        super().__init__(parent)
        from engine.validation import EMOTIONS

        self.verdict = verdict
        self.setObjectName("validation.verdict")
        self.setWindowTitle(f"Validate: {Path(verdict.file).name}")
        image = QLabel()
        image.setPixmap(_pixmap(picture).scaledToWidth(PICTURE_WIDTH, Qt.TransformationMode.SmoothTransformation))
        self.summary = QLabel(_summary(verdict))
        self.summary.setObjectName("validation.summary")
        self.summary.setWordWrap(True)
        self.summary.setTextFormat(Qt.TextFormat.RichText)
        grid = QGridLayout()
        self.bars: dict[str, QProgressBar] = {}
        for row, emotion in enumerate(EMOTIONS):
            p = 0.0 if verdict.emotions is None else float(verdict.emotions[row])
            name = QLabel(f"<b>{emotion}</b>" if emotion == verdict.judged else emotion)
            if emotion == verdict.intended.emotion:
                name.setText(name.text() + "  (meant)")
            bar = QProgressBar()
            bar.setRange(0, 1000)
            bar.setValue(round(1000 * p))
            bar.setFormat(f"{p:.2f}")
            bar.setObjectName(f"validation.p_{emotion}")
            grid.addWidget(name, row, 0)
            grid.addWidget(bar, row, 1)
            self.bars[emotion] = bar
        right = QVBoxLayout()
        right.addWidget(self.summary)
        right.addLayout(grid)
        right.addStretch(1)
        top = QHBoxLayout()
        top.addWidget(image)
        top.addLayout(right, 1)
        note = QLabel("Observers trained on photographs of real people (docs/validation.md); the 68-point "
                      "landmark model is for research use only.")
        note.setWordWrap(True)
        note.setStyleSheet("color: palette(mid)")
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        self.save_button = buttons.addButton("Save report…", QDialogButtonBox.ButtonRole.ActionRole)
        self.save_button.clicked.connect(self.save_report)
        buttons.rejected.connect(self.close)
        layout = QVBoxLayout(self)
        layout.addLayout(top)
        layout.addWidget(note)
        layout.addWidget(buttons)

    def save_report(self, path: str | None = None) -> Path | None:
        """Write the HTML report of this verdict (asks where, unless ``path`` is given)."""
        from engine.validation import summarise, write_report

        if not path:
            path, _ = QFileDialog.getSaveFileName(self, "Save the validation report", "validation.html",
                                                  "HTML report (*.html)")
            if not path:
                return None
        try:
            write_report(summarise([self.verdict]), path, title=f"Validation of {Path(self.verdict.file).name}")
        except (UserError, OSError) as exc:
            QMessageBox.warning(self, "Save report", f"The report could not be written:\n{exc}")
            return None
        return Path(path)


def _summary(v) -> str:
    lines = [f"<b>{_escape(Path(v.file).name)}</b>: {_escape(v.status)}"]
    if v.faces:
        lines.append(f"face found ({v.faces}, detector score {v.face_score:.2f})")
    if v.judged is not None:
        meant = v.intended.emotion
        if meant is None:
            lines.append(f"judged <b>{v.judged}</b> ({v.judged_probability:.2f}); no emotion meant to score")
        else:
            verdict = "as meant" if v.read_as_intended else f"<span style='color:#b00'>not {meant}</span>"
            lines.append(f"judged <b>{v.judged}</b> ({v.judged_probability:.2f}), {verdict}; "
                         f"{meant}: {v.intended_probability:.2f}")
    if v.lips is not None:
        r = "—" if v.lips.r is None else f"{v.lips.r:.2f}"
        lines.append(f"lips against the engine's: r = {r}; bilabial closures seen {v.lips.closures_seen} of "
                     f"{v.lips.closures_intended}; face lost in {v.frames_lost} of {v.frames} frames")
    elif v.eye_opening is not None:
        lines.append(f"eye opening {v.eye_opening:.2f}, lip aperture {v.lip_aperture:.2f}, "
                     f"brow height {v.brow_height:.2f} (inter-ocular distances)")
    return "<br>".join(lines)


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def _pixmap(image: np.ndarray) -> QPixmap:
    image = np.ascontiguousarray(image[..., :3])
    qimage = QImage(image.data, image.shape[1], image.shape[0], 3 * image.shape[1], QImage.Format.Format_RGB888)
    return QPixmap.fromImage(qimage.copy())
