"""A closed window lets go of everything: Qt widgets, the QtInteractor and its VTK objects."""

from __future__ import annotations

import gc
import weakref

import shiboken6
from PySide6.QtCore import QCoreApplication, QEvent

import engine
from workbench.document.model_document import ModelDocument
from workbench.window.main_window import MainWindow


def _open_and_close(path, qtbot):
    document = ModelDocument(engine.load_model(path), path)
    window = MainWindow(document)
    window.show()
    qtbot.waitExposed(window)
    window.parameter_panel.row("jaw_open").slider.setValue(500)
    window.view_state.set_part_visible("eye_left", False)
    plotter = window.viewport.plotter
    actor = window.viewport.part_actor("skin")
    mesh = window.viewport.part_mesh("skin")
    refs = [weakref.ref(o) for o in (window, window.viewport, plotter, document, actor, mesh)]
    window.close()
    window.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    assert not shiboken6.isValid(plotter)
    return refs


def test_closed_window_is_garbage_collected(synthetic_model_path, qtbot):
    refs = _open_and_close(synthetic_model_path, qtbot)
    gc.collect()
    alive = [type(r()).__name__ for r in refs if r() is not None]
    assert alive == [], f"still alive after close: {alive}"
