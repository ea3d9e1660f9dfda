"""Start the workbench: ``artificial-person workbench [MODEL]`` and ``python -m workbench``."""

from __future__ import annotations

import sys
from pathlib import Path

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication, QMessageBox

import engine

from . import testing_hooks
from .document.model_document import ModelDocument
from .icons import APP_ICON, icon
from .window.main_window import TITLE, MainWindow

EXIT_USER_ERROR = 2  # errors in user input exit with status 2, as on the command line


def application(argv: list[str] | None = None) -> QApplication:
    """The running QApplication, created (and named, for QSettings) if there is none yet."""
    app = QApplication.instance()
    if app is None:
        app = QApplication(argv if argv is not None else sys.argv[:1])
    app.setApplicationName("Artificial Person Workbench")
    app.setOrganizationName("Artificial Person")
    app.setWindowIcon(icon(APP_ICON))
    return app


def open_window(model_path: str | Path | None = None) -> MainWindow:
    """Load a model (``None``: the default head) into a new, not yet shown, main window.

    Raises :class:`engine.UserError` if the model cannot be loaded.
    """
    model = engine.load_model(model_path)
    path = Path(model_path) if model_path is not None else engine.default_model_path()
    return MainWindow(ModelDocument(model, path))


def main(model_path: str | None = None) -> int:
    """Show the workbench on ``model_path`` (default head if ``None``) until it is closed.

    If a workbench that did not shut down cleanly left unsaved changes
    behind, offers to recover them once the window shows.
    Returns the exit status: 0, or 2 when the model cannot be loaded, after
    saying why in a dialog and in one ``error:`` line on stderr.
    """
    app = application()
    try:
        window = open_window(model_path)
    except engine.UserError as exc:
        print(f"error: {exc}", file=sys.stderr)
        QMessageBox.critical(None, f"{TITLE}: cannot open model", str(exc))
        return EXIT_USER_ERROR
    hooks = testing_hooks.active()
    if hooks:
        testing_hooks.prepare(window)
    window.show()
    window.files.offer_recovery()
    window.library_editor.offer_recovery()     # the library editor's unsaved text, likewise
    if hooks:
        QTimer.singleShot(0, lambda: testing_hooks.run(window))
    status = app.exec()
    window.viewport.close_plotter()  # idempotent; the window may have been closed already
    window.deleteLater()
    return int(status)
