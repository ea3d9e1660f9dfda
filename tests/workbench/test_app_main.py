"""``workbench.main``: the entry point behind ``artificial-person workbench [MODEL]``."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication, QMessageBox

import workbench
import workbench.app
from workbench.window.main_window import MainWindow


def test_unloadable_model_gives_a_dialog_and_status_2(broken_model_path, monkeypatch, capsys):
    shown = []
    monkeypatch.setattr(QMessageBox, "critical", staticmethod(lambda parent, title, text: shown.append(text)))
    assert workbench.main(str(broken_model_path)) == 2
    assert len(shown) == 1 and shown[0].startswith(f"{broken_model_path}:")
    err = capsys.readouterr().err
    assert err == f"error: {shown[0]}\n"


def test_missing_model_file_gives_status_2(tmp_path, monkeypatch):
    shown = []
    monkeypatch.setattr(QMessageBox, "critical", staticmethod(lambda parent, title, text: shown.append(text)))
    assert workbench.main(str(tmp_path / "nowhere.xml")) == 2
    assert "no such file" in shown[0]


def test_main_shows_the_window_and_returns_0_when_it_is_closed(synthetic_model_path, qapp):
    seen = []

    def close_the_window():
        windows = [w for w in QApplication.topLevelWidgets() if isinstance(w, MainWindow) and w.isVisible()]
        seen.extend(w.windowTitle() for w in windows)
        for w in windows:
            w.close()

    QTimer.singleShot(200, close_the_window)
    QTimer.singleShot(20000, qapp.quit)  # never hang the suite if the window did not appear
    assert workbench.main(str(synthetic_model_path)) == 0
    assert seen == ["synthetic-head.xml[*] — Artificial Person"]


def test_python_dash_m_passes_the_model_on(monkeypatch):
    import workbench.__main__ as entry

    calls = []
    monkeypatch.setattr(entry, "main", lambda path: calls.append(path) or 0)
    assert entry.run(["head.xml"]) == 0
    assert entry.run([]) == 0
    assert calls == ["head.xml", None]


def test_importing_the_package_loads_no_qt_or_vtk():
    code = ("import sys, workbench; "
            "print(sorted(m for m in ('PySide6', 'vtk', 'pyvista') if m in sys.modules))")
    root = Path(workbench.__file__).resolve().parent.parent
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         cwd=root).stdout
    assert out.strip() == "[]"
