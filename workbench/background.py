"""Long work off the GUI thread: one engine call on a worker thread, a progress dialog with Cancel.

The engine's import, PCA and apply functions do not report progress, so the
dialog shows a busy bar and the step being done. Cancel closes the dialog
and throws the result away when it arrives (the engine call itself runs to
its end in the background, touching nothing the GUI holds): nothing changes.
Errors come back to the GUI thread; a :class:`engine.errors.UserError` is
shown as it reads (file, line, what is wrong), anything else as an
unexpected error, never a traceback.

>>> job = run_in_background(window, "Importing take1.tsv…", lambda: import_marker_file(path),
...                         on_done=state.set_session)                                  # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Callable
from concurrent.futures import Future, ThreadPoolExecutor

from PySide6.QtCore import QObject, Qt, QTimer
from PySide6.QtWidgets import QMessageBox, QProgressDialog, QWidget

from engine.errors import UserError

POLL_MS = 25
_EXECUTOR = ThreadPoolExecutor(max_workers=1, thread_name_prefix="mocap")   # one job at a time: 2 cores shared
_RUNNING: set[BackgroundJob] = set()    # jobs whose work has not ended, whoever dropped them


class BackgroundJob(QObject):
    """``work()`` on a worker thread; the GUI thread polls for its end and calls back there.

    No Qt object crosses threads: the worker only runs the engine call, a
    :class:`QTimer` in the GUI thread looks at the :class:`Future`.
    """

    def __init__(self, work: Callable[[], object], on_done, on_error, on_finished, parent: QObject | None = None):
        super().__init__(parent)
        self.cancelled = False
        self.outcome: str | None = None     # once ended: "done", "failed" or "cancelled" (the result thrown away)
        self._on_done, self._on_error, self._on_finished = on_done, on_error, on_finished
        self.future: Future = _EXECUTOR.submit(work)
        self._timer = QTimer(self)
        self._timer.setInterval(POLL_MS)
        self._timer.timeout.connect(self._poll)
        self._timer.start()
        _RUNNING.add(self)

    def cancel(self) -> None:
        """Throw the result away when it comes (the engine call cannot be interrupted)."""
        self.cancelled = True

    @property
    def done(self) -> bool:
        return self.future.done()

    def _poll(self) -> None:
        if not self.future.done():
            return
        self._timer.stop()
        _RUNNING.discard(self)
        try:
            if self.cancelled:
                self.outcome = "cancelled"
            else:
                exc = self.future.exception()
                self.outcome = "done" if exc is None else "failed"
                if exc is None:
                    self._on_done(self.future.result())
                else:
                    self._on_error(exc)
        finally:
            self._on_finished()
            self.deleteLater()


def run_in_background(parent: QWidget, text: str, work: Callable[[], object], on_done: Callable[[object], None],
                      on_error: Callable[[Exception], None] | None = None, title: str = "Motion capture",
                      on_finished: Callable[[], None] | None = None) -> BackgroundJob:
    """Start ``work`` in the background with a cancellable progress dialog; call ``on_done(result)`` after.

    ``on_error(exception)`` defaults to a warning dialog with ``str(exception)``;
    ``on_finished()`` runs in every case (done, failed or cancelled) once the work ends.
    """
    dialog = QProgressDialog(text, "Cancel", 0, 0, parent)
    dialog.setWindowTitle(title)
    dialog.setWindowModality(Qt.WindowModality.WindowModal)
    dialog.setMinimumDuration(300)
    dialog.setValue(0)      # starts the minimum-duration clock: without a value Qt shows the dialog after 4 s
    dialog.setAutoClose(False)
    dialog.setAutoReset(False)

    def done(result) -> None:
        dialog.close()
        on_done(result)

    def failed(exc: Exception) -> None:
        dialog.close()
        if on_error is not None:
            on_error(exc)
        else:
            show_error(parent, title, exc)

    def finished() -> None:
        dialog.close()
        dialog.deleteLater()
        if on_finished is not None:
            on_finished()

    job = BackgroundJob(work, done, failed, finished, parent)
    job.progress_dialog = dialog
    dialog.canceled.connect(job.cancel)
    dialog.canceled.connect(dialog.close)
    return job


def show_error(parent: QWidget | None, title: str, exc: BaseException) -> None:
    """A warning dialog: the engine's message for a :class:`UserError`, else 'unexpected error: …'."""
    text = str(exc) if isinstance(exc, UserError) else f"unexpected error: {type(exc).__name__}: {exc}"
    QMessageBox.warning(parent, title, text)


def running_jobs() -> int:
    """Background jobs not yet ended and reported (tests wait for 0)."""
    return len(_RUNNING)
