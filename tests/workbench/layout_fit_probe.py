"""Run by ``test_layout_fits_screen.py`` in a process of its own, on an Xvfb screen of the size under test.

``python -m tests.workbench.layout_fit_probe REPORT.json`` opens the workbench on
the default head with fresh settings (the caller points ``XDG_CONFIG_HOME`` at
an empty folder), then, in every task layout, opens every dock the way a user
does (its View-menu entry, then the tools' own commands: Ctrl+L, Ctrl+G, the
Motion capture menu), and finally reopens the window from the geometry of a
larger screen. After each step it writes down the window's frame; the report
is ``{"available": [x, y, w, h], "steps": [[what, [x, y, w, h]], …]}``.
"""

from __future__ import annotations

import json
import sys

from PySide6.QtCore import QSettings
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QDockWidget

import engine
from workbench.document.model_document import ModelDocument
from workbench.window.main_window import MainWindow

TOOL_ACTIONS = ("library.editor", "library.gallery", "mocap.plot", "mocap.pca")


def _settle() -> None:
    for _ in range(4):
        QTest.qWait(25)


def _frame(window) -> list[int]:
    frame = window.frameGeometry()
    return [frame.x(), frame.y(), frame.width(), frame.height()]


def _open_window() -> MainWindow:
    path = engine.default_model_path()
    window = MainWindow(ModelDocument(engine.load_model(path), path))
    window.show()
    QTest.qWaitForWindowExposed(window)
    _settle()
    return window


def _close(window: MainWindow) -> None:
    window.document.undo_stack.setClean()
    window.close()
    window.deleteLater()
    _settle()


def probe() -> dict:
    steps: list[tuple[str, list[int]]] = []
    window = _open_window()
    available = window.screen().availableGeometry()
    steps.append(("fresh start", _frame(window)))
    layouts = getattr(window, "layouts", None)
    layout_ids = [action.objectName().removeprefix("layout.") for action in layouts.menu.actions()
                  if action.isCheckable()] if layouts is not None else ["as opened"]
    for layout_id in layout_ids:
        if layouts is not None:
            layouts.switch(layout_id)
            _settle()
            steps.append((f"{layout_id}", _frame(window)))
        for dock in window.findChildren(QDockWidget):
            if dock.isHidden():
                dock.toggleViewAction().trigger()          # View → the dock's entry
                _settle()
                steps.append((f"{layout_id}: View → {dock.windowTitle()}", _frame(window)))
        for action_id in TOOL_ACTIONS:
            action = window.actions_by_id[action_id]
            if action.isCheckable() and action.isChecked():
                action.trigger()                           # a toggle: closed, then opened again below
                _settle()
            action.trigger()
            _settle()
            steps.append((f"{layout_id}: {action_id}", _frame(window)))
    # a layout remembered on a larger screen
    window.showNormal()
    window.move(available.topLeft())
    window.resize(available.width() + 600, available.height() + 400)
    _settle()
    window.save_layout()
    _close(window)
    window = _open_window()
    steps.append(("reopened from a larger screen's geometry", _frame(window)))
    _close(window)
    return {"available": [available.x(), available.y(), available.width(), available.height()], "steps": steps}


def main(report_path: str) -> int:
    app = QApplication(sys.argv[:1])
    app.setOrganizationName("Artificial Person Layout Probe")
    app.setApplicationName("Workbench")
    QSettings().clear()
    report = probe()
    with open(report_path, "w", encoding="utf-8") as out:
        json.dump(report, out, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
