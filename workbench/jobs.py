"""Work that runs off the GUI thread: one :class:`Job` per Say or export.

A job runs a plain function in its own QThread. When it ends, ``ended`` is
emitted on the GUI thread (connect plain functions and lambdas to it, not to
QThread's ``finished``, which is emitted on the worker thread), and the job
holds either ``result`` or ``error``. Cancelling sets a flag the function may poll
(``job.cancelled``); a function that cannot be stopped half-way (a
Festival run) simply has its result ignored by whoever cancelled it.

Running jobs are kept alive here (not by their panel), so closing a window
never destroys a thread that still runs; when the application quits, they
are cancelled and waited for.

>>> job = Job(lambda job: 6 * 7)                                # doctest: +SKIP
>>> job.ended.connect(lambda: print(job.result)); job.start()  # doctest: +SKIP
42
"""

from __future__ import annotations

import threading
import traceback
from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QThread, Signal

_RUNNING: set[Job] = set()
#: Dynamic property marking the application whose ``aboutToQuit`` already waits for the jobs.
_QUIT_HOOKED = "ap_jobs_quit_hooked"


class Job(QThread):
    """``work(job)`` on a thread of its own.

    Signals: ``progress(done, total)`` as the work reports it (from the worker
    thread: connect bound methods of QObjects, which Qt queues to their thread);
    ``ended()`` on the GUI thread once the work is over.
    """

    progress = Signal(int, int)
    ended = Signal()

    def __init__(self, work: Callable[[Job], object]):
        super().__init__()
        self._work = work
        self._cancel = threading.Event()
        self.result = None
        self.error: BaseException | None = None
        self.error_details = ""
        self.finished.connect(self._forget)

    @property
    def cancelled(self) -> bool:
        return self._cancel.is_set()

    def cancel(self) -> None:
        """Ask the work to stop (it polls :attr:`cancelled`)."""
        self._cancel.set()

    def report(self, done: int, total: int) -> None:
        """Called by the work (any thread): emits ``progress``."""
        self.progress.emit(int(done), int(total))

    def start(self) -> None:
        _hook_quit()
        _RUNNING.add(self)
        super().start()

    def run(self) -> None:  # the worker thread
        try:
            self.result = self._work(self)
        except BaseException as error:
            self.error = error
            self.error_details = traceback.format_exc()

    def _forget(self) -> None:          # queued to the GUI thread: the job lives there
        _RUNNING.discard(self)
        self.ended.emit()
        self.deleteLater()


def running_jobs() -> list[Job]:
    return list(_RUNNING)


def wait_for_all(timeout_ms: int = 30000) -> None:
    """Cancel every running job and wait for it (the application is quitting)."""
    for job in list(_RUNNING):
        job.cancel()
        job.wait(timeout_ms)


def _hook_quit() -> None:
    app = QCoreApplication.instance()
    if app is not None and not app.property(_QUIT_HOOKED):
        app.aboutToQuit.connect(wait_for_all)
        app.setProperty(_QUIT_HOOKED, True)
