"""The wizard's fit page.

:class:`FitPage` runs :func:`engine.photofit.fit_photos` on a worker thread
(:class:`~workbench.jobs.Job`) as soon as it opens: a progress
bar follows the fit's steps, **Stop** (or the wizard's Cancel, or Back)
stops it and nothing is kept. The fit asks the job's ``cancelled`` flag
inside its long loops (``should_stop``, :mod:`engine.photofit.stopping`),
so the worker ends part-way through the step it is in. When it is done each
photograph shows the fitted head through its fitted camera: its landmarks
(green crosses, joined to the points placed) and its outline (dashed), so a
point placed badly shows, and Back takes you to it. The result page is
:mod:`.result`.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

import numpy as np
from PySide6.QtWidgets import QHBoxLayout, QLabel, QProgressBar, QPushButton, QVBoxLayout, QWizardPage
from scipy.spatial import ConvexHull

from engine.photofit.fit import FIT_STEPS
from engine.photofit.stopping import FitStopped

from ..jobs import Job
from .canvas import PhotoCanvas
from .session import VIEWS, PhotoFitSession

STEP_TEXT = {"shape": "Fitting cameras and face shape…", "head": "Making the head…",
             "rig": "Carrying the rig over…", "texture": "Painting the photographs into the texture…",
             "eyes": "Colouring the eyes…"}
CHIN_MARGIN = 10.0                 # mm below the chin the outline still follows

__all__ = ["FitPage", "FitStopped", "FitTrace"]


@dataclass
class FitTrace:
    """What one fit's worker thread did: the steps begun, and how often it asked whether to stop in each.

    ``asked_after_stop`` counts the questions answered "stop" (the fit ends at the first: it is 1 then).
    """

    steps: list[str] = field(default_factory=list)
    questions: Counter[str] = field(default_factory=Counter)
    asked_after_stop: int = 0


class FitPage(QWizardPage):
    def __init__(self, session: PhotoFitSession):
        super().__init__()
        self.session = session
        self.job: Job | None = None
        self.trace = FitTrace()
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

        trace = self.trace = FitTrace()

        def work(job: Job):
            def progress(step: str) -> None:
                trace.steps.append(step)
                job.report(FIT_STEPS.index(step), len(FIT_STEPS))

            def should_stop() -> bool:
                if job.cancelled:
                    trace.asked_after_stop += 1
                    return True
                trace.questions[trace.steps[-1] if trace.steps else ""] += 1
                return False

            return fit_photos(photos, points, progress=progress, should_stop=should_stop)

        job = self.job = Job(work)
        job.progress.connect(self._on_progress)
        job.ended.connect(self._on_ended)
        self.progress.setValue(0)
        self.status.setText("Starting…")
        self._show_running(True)
        job.start()

    def stop(self) -> None:
        """Stop the fit being made (its worker ends part-way through the step it is in; nothing is kept)."""
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
        # The fit (or its absence) first: _show_running tells the wizard to ask isComplete() again.
        self.session.fit = None if job.error is not None else job.result
        self._show_running(False)
        if job.error is not None:
            self.status.setText(f"The fit failed: {job.error}")
            return
        fit = self.session.fit
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

