"""Fixtures for the workbench tests: the synthetic head on disk, a real main window, leak checks.

Run under a display server, e.g. ``xvfb-run -a .venv/bin/pytest tests/workbench``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import engine
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

    open_plotters = [p for p in _ALL_PLOTTERS.values() if not getattr(p, "_closed", True)]
    assert not open_plotters, f"plotters left open: {open_plotters}"


@pytest.fixture
def make_window(qtbot):
    """Factory: a shown :class:`MainWindow` on a model path.

    Afterwards every window is closed and deleted, and each one's QtInteractor
    must be closed, its C++ widget deleted and its VTK render window released.
    (That the Python objects are then garbage-collected too is checked by
    ``test_closed_window_is_garbage_collected``; here pytest still holds them.)
    """
    from workbench.document import ModelDocument
    from workbench.main_window import MainWindow

    plotters = []

    def make(path, size=(1200, 760)) -> MainWindow:
        document = ModelDocument(engine.load_model(path), path)
        window = MainWindow(document)
        # pytest-qt closes its widgets before fixtures tear down: nothing unsaved to ask about then.
        qtbot.addWidget(window, before_close_func=_forget_changes)
        if size is not None:                 # None: keep the size the window restored from QSettings
            window.resize(*size)
        window.show()
        qtbot.waitExposed(window)
        window.viewport.set_view("front")  # frame again now that the widget has its real size
        plotters.append(window.viewport.plotter)
        return window

    yield make
    import shiboken6
    from PySide6.QtCore import QCoreApplication, QEvent
    from PySide6.QtWidgets import QApplication

    for widget in QApplication.topLevelWidgets():
        if widget.__class__.__name__ == "MainWindow":
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
