"""Python's cyclic garbage collector, run on the GUI thread only.

Python collects reference cycles in whatever thread happens to allocate when
a generation's threshold is crossed. The workbench runs long jobs in worker
threads (Festival, video export, motion-capture import); a collection there
may finalise Qt and VTK objects that belong to the GUI thread — a closed
dialog, a window's OpenGL context wrapper — and Qt crashes. This was seen as
a segmentation fault in the video export's thread, "Garbage-collecting"
while it imported a module.

:func:`collect_on_gui_thread` turns automatic collection off and instead
checks the same thresholds twice a second from a timer on the GUI thread,
collecting the generations that are due, as Python would have. Objects
without cycles are still freed at once by reference counting.

>>> collect_on_gui_thread()          # doctest: +SKIP   (once a QApplication exists)
"""

from __future__ import annotations

import gc

from PySide6.QtCore import QCoreApplication, QObject, QTimer

INTERVAL_MS = 500


class GuiThreadCollector(QObject):
    """Collects due generations from a timer in the thread of the QApplication it belongs to."""

    def __init__(self, app: QCoreApplication):
        super().__init__(app)
        self.thresholds = gc.get_threshold()
        gc.disable()
        self.timer = QTimer(self)
        self.timer.timeout.connect(self.collect_due)
        self.timer.start(INTERVAL_MS)

    def collect_due(self) -> None:
        young, middle, old = gc.get_count()
        if young > self.thresholds[0]:
            generation = 0
            if middle > self.thresholds[1]:
                generation = 2 if old > self.thresholds[2] else 1
            gc.collect(generation)


def collect_on_gui_thread() -> GuiThreadCollector | None:
    """Make the running QApplication's thread the only one that collects cycles (once per application)."""
    app = QCoreApplication.instance()
    if app is None:
        return None
    existing = app.findChild(GuiThreadCollector)
    return existing if existing is not None else GuiThreadCollector(app)
