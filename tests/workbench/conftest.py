"""Fixtures for the workbench tests: the synthetic head on disk, a real main window, leak checks.

``window`` is a new main window for each test (``make_window`` makes more); a module whose tests do not
depend on a new window's construction overrides ``window`` with ``reused_window``: one window for the module,
reset before each test (the model read again, an empty undo stack, nothing selected, no tool or animation).

Run under a display server, e.g. ``xvfb-run -a .venv/bin/pytest tests/workbench``.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

import engine
from engine.painting import Brush
from tests.engine import conftest as engine_fixtures
from tests.workbench.synthetic_workbench_model import build_synthetic_model

#: The shipped default head, loaded once per run and shared with the engine's tests (read-only).
head = engine_fixtures.head


@pytest.fixture(scope="session")
def synthetic_model_dir(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("synthetic-model")


@pytest.fixture
def synthetic_model_path(synthetic_model_dir) -> Path:
    """The synthetic head saved with :func:`engine.save_model` (XML + HDF5)."""
    path = synthetic_model_dir / "synthetic-head.xml"
    if not path.exists():
        engine.save_model(build_synthetic_model(), path)
    return path


@pytest.fixture
def broken_model_path(tmp_path) -> Path:
    """A model description whose XML is cut off on line 3."""
    path = tmp_path / "broken.xml"
    path.write_text('<?xml version="1.0"?>\n<model format="artificial-person-model" version="1">\n  <parts>\n')
    return path


# ---------------------------------------------------------------------------
# Qt set-up and a real main window
# ---------------------------------------------------------------------------

@pytest.fixture(scope="session", autouse=True)
def _isolated_settings(qapp, tmp_path_factory):
    """Keep QSettings (last directory, recent files, layout) and recovery copies out of the user's files."""
    import os

    from PySide6.QtCore import QSettings

    qapp.setOrganizationName("Artificial Person Tests")
    qapp.setApplicationName("Workbench Tests")
    QSettings.setDefaultFormat(QSettings.Format.IniFormat)
    QSettings.setPath(QSettings.Format.IniFormat, QSettings.Scope.UserScope,
                      str(tmp_path_factory.mktemp("settings")))
    # QStandardPaths reads XDG_DATA_HOME on every call: recovery sessions land here.
    os.environ["XDG_DATA_HOME"] = str(tmp_path_factory.mktemp("data-home"))


@pytest.fixture(autouse=True)
def _fresh_settings():
    """Each test starts from empty settings (recent files, window layout, autosave interval)."""
    from PySide6.QtCore import QSettings

    QSettings().clear()
    yield
    QSettings().clear()


@pytest.fixture(autouse=True)
def _no_open_plotters():
    """Like pyvistaqt's own tests: fail if a test leaves a QtInteractor open."""
    yield
    from pyvista.plotting import _ALL_PLOTTERS

    open_plotters = [p for p in _ALL_PLOTTERS.values()
                     if not getattr(p, "_closed", True) and id(p) not in _REUSED_PLOTTERS]
    assert not open_plotters, f"plotters left open: {open_plotters}"


@pytest.fixture
def make_window(qtbot):
    """Factory: a shown :class:`MainWindow` on a model path.

    Afterwards every window is closed and deleted, and each one's QtInteractor
    must be closed, its C++ widget deleted and its VTK render window released.
    (That the Python objects are then garbage-collected too is checked by
    ``test_closed_window_is_garbage_collected``; here pytest still holds them.)
    """
    from workbench.window.main_window import MainWindow

    plotters = []

    def make(path, size=(1200, 760)) -> MainWindow:
        window = _shown_window(path, size)
        # pytest-qt closes its widgets before fixtures tear down: nothing unsaved to ask about then.
        qtbot.addWidget(window, before_close_func=_forget_changes)
        plotters.append(window.viewport.plotter)
        return window

    yield make
    import shiboken6
    from PySide6.QtCore import QCoreApplication, QEvent
    from PySide6.QtWidgets import QApplication

    for widget in QApplication.topLevelWidgets():
        if widget.__class__.__name__ == "MainWindow" and id(widget.viewport.plotter) not in _REUSED_PLOTTERS:
            _forget_changes(widget)
            widget.close()  # closeEvent closes the plotter
            widget.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    for plotter in plotters:
        assert plotter._closed, "a QtInteractor was left open"
        assert plotter.render_window is None, "a VTK render window outlived its window"
        assert not shiboken6.isValid(plotter), "a QtInteractor widget outlived its window"
    plotters.clear()


@pytest.fixture(autouse=True)
def _collect_deleted_windows(qapp) -> None:
    """Finish deleting earlier tests' windows and collect their Python wrappers before this test.

    pyvistaqt's QtInteractor refers to itself (``interactor``), so it outlives
    its deleted widget until the garbage collector runs, still holding
    wrappers of the widget's GL context and surface. Shiboken keeps those
    stale wrappers registered by address; a new Qt object allocated at the
    same address would come back as the old wrapper (a QMenu reported as a
    QOffscreenSurface), or crash. One window per process, as the app has,
    never meets this; a test suite making dozens does.
    """
    import gc

    from PySide6.QtCore import QCoreApplication, QEvent

    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    gc.collect()


def _forget_changes(window) -> None:
    window.document.undo_stack.setClean()


@pytest.fixture(autouse=True)
def unexpected_dialogs(monkeypatch):
    """A message box no test asked for would block the suite: record it, answer Cancel, fail the test.

    Tests that expect a dialog monkeypatch the QMessageBox function themselves.
    """
    from PySide6.QtWidgets import QMessageBox

    shown: list[tuple[str, str, str]] = []

    def recorder(kind):
        def show(parent, title, text, *args, **kwargs):
            shown.append((kind, title, text))
            return QMessageBox.StandardButton.Cancel
        return staticmethod(show)

    for kind in ("warning", "question", "critical", "information"):
        monkeypatch.setattr(QMessageBox, kind, recorder(kind))
    yield shown
    assert not shown, f"unexpected dialogs: {shown}"


@pytest.fixture
def window(make_window, synthetic_model_path):
    """The main window on the synthetic head."""
    return make_window(synthetic_model_path)


# ---------------------------------------------------------------------------
# One window per test module, reset between its tests (issue 35 item 5)
# ---------------------------------------------------------------------------

#: ids of the QtInteractors of the windows ``reused_window`` keeps: left open between tests on purpose.
_REUSED_PLOTTERS: set[int] = set()


def _shown_window(path, size=(1200, 760)):
    """A :class:`MainWindow` on the model at ``path``, shown, exposed and framed from the front."""
    from PySide6.QtTest import QTest

    from workbench.document.model_document import ModelDocument
    from workbench.window.main_window import MainWindow

    window = MainWindow(ModelDocument(engine.load_model(path), path))
    if size is not None:                 # None: keep the size the window restored from QSettings
        window.resize(*size)
    window.show()
    assert QTest.qWaitForWindowExposed(window, 5000), "the window was never shown"    # as qtbot.waitExposed
    window.viewport.set_view("front")  # frame again now that the widget has its real size
    return window


@pytest.fixture(scope="module")
def _module_window_slot():
    """Holds the window ``reused_window`` shares within one test module; closes and checks it at the end."""
    slot: dict = {}
    yield slot
    _dispose_reused(slot.pop("window", None))


def _dispose_reused(window) -> None:
    if window is None:
        return
    import shiboken6
    from PySide6.QtCore import QCoreApplication, QEvent

    plotter = window.viewport.plotter
    _REUSED_PLOTTERS.discard(id(plotter))
    if shiboken6.isValid(window):
        _forget_changes(window)
        window.close()
        window.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    assert plotter._closed, "a QtInteractor was left open"
    assert plotter.render_window is None, "a VTK render window outlived its window"
    assert not shiboken6.isValid(plotter), "a QtInteractor widget outlived its window"


def _reset(window, path) -> None:
    """Back to what a new window on ``path`` shows: the model read again from its file (parameters at their
    defaults, an empty clean undo stack), nothing selected, no animation, no tool active, default view."""
    paint = getattr(window, "paint", None)
    if paint is not None:                        # the paint tool off, with a new controller's brush
        paint.set_active(False)
        paint.set_tool("add")
        paint.set_brush(**{f.name: getattr(_NEW_BRUSH, f.name) for f in dataclasses.fields(_NEW_BRUSH)})
        paint.set_hold(False, 1.0)
    player = getattr(window, "player", None)
    if player is not None:
        player.stop()
        player.unload()
    view = window.view_state
    view.select_parameter(None)
    view.set_wireframe(False)
    view.set_landmarks(False)
    view.set_heat_map(True)
    for part in view.hidden_parts:
        view.set_part_visible(part, True)
    window.document.replace_model(engine.load_model(path), path)
    window.statusBar().clearMessage()
    window.resize(1200, 760)
    window.activateWindow()
    window.viewport.set_view("front")


#: The brush a new :class:`workbench.painting.controller.PaintController` starts with.
_NEW_BRUSH = Brush("add", radius=10.0, strength=0.5, falloff="smooth", front_faces_only=True)


@pytest.fixture
def reused_window(_module_window_slot, synthetic_model_path):
    """The main window on the synthetic head, shared by the tests of one module and reset before each
    (:func:`_reset`). For modules whose tests do not depend on a new window's construction; tests of
    start-up, recovery, settings persistence or closing take ``make_window``. A test that closes the
    shared window gets a new one for the next test."""
    import shiboken6

    window = _module_window_slot.get("window")
    if window is not None and (not shiboken6.isValid(window) or window._closed or not window.isVisible()):
        _dispose_reused(_module_window_slot.pop("window"))
        window = None
    if window is None:
        from PySide6.QtWidgets import QDockWidget

        window = _shown_window(synthetic_model_path)
        _module_window_slot["window"] = window
        _module_window_slot["docks"] = {dock: dock.isVisible() for dock in window.findChildren(QDockWidget)}
        _REUSED_PLOTTERS.add(id(window.viewport.plotter))
    else:
        _reset(window, synthetic_model_path)
        for dock, visible in _module_window_slot["docks"].items():    # the docks a new window shows
            dock.setVisible(visible)
    yield window
    if shiboken6.isValid(window):
        _forget_changes(window)


@pytest.fixture
def captured_errors(monkeypatch):
    """QMessageBox.critical records its message instead of blocking the test."""
    from PySide6.QtWidgets import QMessageBox

    errors: list[tuple[str, str]] = []

    def critical(parent, title, text, *args, **kwargs):
        errors.append((title, text))
        return QMessageBox.StandardButton.Ok

    monkeypatch.setattr(QMessageBox, "critical", staticmethod(critical))
    return errors
