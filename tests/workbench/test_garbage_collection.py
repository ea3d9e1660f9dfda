"""Cycles are collected on the GUI thread only: a worker thread must never finalise Qt objects."""

from __future__ import annotations

import gc
import threading
import weakref

from workbench.garbage_collection import GuiThreadCollector, collect_on_gui_thread


class Cycle:
    def __init__(self):
        self.me = self
        self.finalised_in = None

    def __del__(self):
        Cycle.finalised_in = threading.current_thread().name


def test_a_window_makes_the_gui_thread_the_only_collector(window, qtbot):
    assert not gc.isenabled()
    collector = collect_on_gui_thread()
    assert isinstance(collector, GuiThreadCollector) and collect_on_gui_thread() is collector   # once
    assert collector.timer.isActive()

    Cycle.finalised_in = None
    ref = weakref.ref(Cycle())

    def allocate_a_lot():                      # garbage cycles: automatic collection would run here
        for _ in range(20_000):
            node = {}
            node["me"] = node

    worker = threading.Thread(target=allocate_a_lot, name="worker")
    worker.start()
    worker.join()
    assert ref() is not None and Cycle.finalised_in is None     # the worker collected nothing
    qtbot.waitUntil(lambda: ref() is None, timeout=3000)          # the GUI thread's timer did
    assert Cycle.finalised_in == threading.main_thread().name
