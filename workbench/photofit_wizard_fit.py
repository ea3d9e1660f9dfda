"""The wizard's fit and result pages.

:class:`FitPage` runs :func:`engine.photofit.fit_photos` on a worker thread
(:class:`~workbench.script_panel.jobs.Job`) as soon as it opens: a progress
bar follows the fit's steps, **Stop** (or the wizard's Cancel, or Back)
stops it at the next step and nothing is kept. When it is done each
photograph shows the fitted head through its fitted camera: its landmarks
(green crosses, joined to the points placed) and its outline (dashed), so a
point placed badly shows, and Back takes you to it.

:class:`ResultPage` shows the textured head rendered from the front and
three-quarter, the fit's figures, and offers to say a test sentence once the
head is the document's model (Finish).
"""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import Qt
from PySide6.QtGui import QImage, QPixmap
from PySide6.QtWidgets import (
    QCheckBox,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QProgressBar,
    QPushButton,
    QVBoxLayout,
    QWizardPage,
)
from scipy.spatial import ConvexHull

from engine.photofit.fit import FIT_STEPS

from .photofit_wizard_canvas import PhotoCanvas
from .photofit_wizard_session import VIEWS, PhotoFitSession
from .script_panel.jobs import Job

STEP_TEXT = {"shape": "Fitting cameras and face shape…", "head": "Making the head…",
             "rig": "Carrying the rig over…", "texture": "Painting the photographs into the texture…",
             "eyes": "Colouring the eyes…"}
RESULT_SIZE = (300, 400)
TEST_SENTENCE = "Pappa ampui pallon."
CHIN_MARGIN = 10.0                 # mm below the chin the outline still follows


class FitStopped(Exception):
    """Raised from the fit's progress callback when the user stopped it."""


class FitPage(QWizardPage):
    def __init__(self, session: PhotoFitSession):
        super().__init__()
        self.session = session
        self.job: Job | None = None
        self.setTitle("Fit")
        self.setSubTitle("The head is fitted to the points. Green crosses: the fitted head's landmarks, joined to "
                         "your points; dashed: its outline. Go Back to move a point and fit again.")
        self.progress = QProgressBar()
        self.progress.setRange(0, len(FIT_STEPS))
        self.status = QLabel("")
        self.stop_button = QPushButton("Stop")
        self.stop_button.setToolTip("Stop the fit: nothing is kept")
        self.stop_button.clicked.connect(self.stop)
        self.again_button = QPushButton("Fit again")
        self.again_button.clicked.connect(self.start)
        top = QHBoxLayout()
        top.addWidget(self.progress, 1)
        top.addWidget(self.stop_button)
        top.addWidget(self.again_button)
        self.canvases = {view: PhotoCanvas() for view in VIEWS}
        row = QHBoxLayout()
        for canvas in self.canvases.values():
            row.addWidget(canvas, 1)
        layout = QVBoxLayout(self)
        layout.addLayout(top)
        layout.addWidget(self.status)
        layout.addLayout(row, 1)

    @property
    def running(self) -> bool:
        return self.job is not None

    # -- QWizardPage ---------------------------------------------------------------------
    def initializePage(self) -> None:
        for view, canvas in self.canvases.items():
            photo = self.session.photos.get(view)
            canvas.setVisible(photo is not None)
            if photo is not None:
                canvas.set_photo(photo)
                points = self.session.points.get(view, {})
                canvas.set_markers({k: (x, y, True) for k, (x, y) in points.items()}, (), editable=False)
        self.start()

    def cleanupPage(self) -> None:            # Back: the fit being made is not wanted any more
        self.stop()

    def isComplete(self) -> bool:
        return self.session.fit is not None and not self.running

    # -- the fit ---------------------------------------------------------------------------
    def start(self) -> None:
        from engine.photofit import fit_photos

        self.stop()
        photos = dict(self.session.photos)
        points = {view: dict(p) for view, p in self.session.points.items() if view in photos}

        def work(job: Job):
            def progress(step: str) -> None:
                if job.cancelled:
                    raise FitStopped
                job.report(FIT_STEPS.index(step), len(FIT_STEPS))
            return fit_photos(photos, points, progress=progress)

        job = self.job = Job(work)
        job.progress.connect(self._on_progress)
        job.ended.connect(self._on_ended)
        self.progress.setValue(0)
        self.status.setText("Starting…")
        self._show_running(True)
        job.start()

    def stop(self) -> None:
        """Stop the fit being made (it ends at its next step; its result is thrown away)."""
        if self.job is None:
            return
        self.job.cancel()
        self.job = None
        self.session.fit = None
        self.status.setText("Stopped: nothing was kept.")
        self._show_running(False)

    def _on_progress(self, done: int, _total: int) -> None:
        if self.job is not None and self.sender() is self.job:
            self.progress.setValue(done)
            self.status.setText(STEP_TEXT.get(FIT_STEPS[done], ""))

    def _on_ended(self) -> None:
        job = self.sender()
        if job is not self.job:                       # stopped: its end means nothing
            return
        self.job = None
        self._show_running(False)
        if job.error is not None:
            self.session.fit = None
            self.status.setText(f"The fit failed: {job.error}")
            return
        fit = self.session.fit = job.result
        self.progress.setValue(len(FIT_STEPS))
        seconds = sum(fit.seconds.values())
        self.status.setText(f"Fitted in {seconds:.1f} s: landmarks {fit.shape.error:.1f} px RMS from your points "
                            f"({fit.shape.error_before_warp:.1f} px before the warp).")
        self.show_fit()

    def show_fit(self) -> None:
        fit = self.session.fit
        if fit is None:
            return
        head = fit.head
        skin = head.vertex_part == head.parts.index("skin") if "skin" in head.parts else np.ones(head.n_vertices, bool)
        if "2.1" in head.landmarks:      # the head's outline down to the chin: the neck's cut edge is no outline
            skin &= head.vertices[:, 1] >= head.vertices[head.landmarks["2.1"], 1] - CHIN_MARGIN
        for view, camera in fit.shape.cameras.items():
            ids = [k for k in self.session.points.get(view, {}) if k in head.landmarks]
            fitted = camera.project(head.vertices[[head.landmarks[k] for k in ids]]) if ids else np.zeros((0, 2))
            flat = camera.project(head.vertices[skin])
            outline = flat[ConvexHull(flat).vertices]
            self.canvases[view].show_fit({k: (float(x), float(y)) for k, (x, y) in zip(ids, fitted, strict=True)},
                                         outline)

    def _show_running(self, running: bool) -> None:
        self.stop_button.setEnabled(running)
        self.again_button.setEnabled(not running)
        if running:
            for canvas in self.canvases.values():
                canvas.clear_fit()
        self.completeChanged.emit()


class ResultPage(QWizardPage):
    def __init__(self, session: PhotoFitSession):
        super().__init__()
        self.session = session
        self.setTitle("Result")
        self.setSubTitle("Finish makes this head the model (Edit → Undo brings the previous one back); "
                         "File → Save model as… writes it.")
        self.pictures = [QLabel() for _ in range(2)]
        row = QHBoxLayout()
        for picture in self.pictures:
            picture.setAlignment(Qt.AlignmentFlag.AlignCenter)
            picture.setMinimumSize(RESULT_SIZE[0] // 2, RESULT_SIZE[1] // 2)
            row.addWidget(picture, 1)
        self.say_box = QCheckBox("After Finish, say:")
        self.say_box.setChecked(True)
        self.sentence = QLineEdit(TEST_SENTENCE)
        say_row = QHBoxLayout()
        say_row.addWidget(self.say_box)
        say_row.addWidget(self.sentence, 1)
        layout = QVBoxLayout(self)
        layout.addLayout(row, 1)
        layout.addLayout(say_row)

    def initializePage(self) -> None:
        from engine.outputs.render import FrameRenderer

        fit = self.session.fit
        if fit is None:
            return
        head = fit.head
        for picture, view in zip(self.pictures, ("front", "three-quarter"), strict=True):
            with FrameRenderer(head, size=RESULT_SIZE, view=view) as renderer:
                image = np.ascontiguousarray(renderer.render(head.deform()))
            qimage = QImage(image.data, image.shape[1], image.shape[0], 3 * image.shape[1],
                            QImage.Format.Format_RGB888)
            picture.setPixmap(QPixmap.fromImage(qimage.copy()))

    def test_sentence(self) -> str | None:
        """The sentence to say after Finish, or ``None``."""
        text = self.sentence.text().strip()
        return text if self.say_box.isChecked() and text else None
