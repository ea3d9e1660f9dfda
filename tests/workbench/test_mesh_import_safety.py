"""A mesh file that crashes VTK's reader must not take the workbench (and its unsaved work) with it."""

from __future__ import annotations

import sys

from tests.engine.test_mesh_child import SEGFAULTING_VTK, crashing_interpreter


def test_a_file_that_segfaults_vtk_leaves_the_window_and_its_model(window, tmp_path, captured_errors,
                                                                   monkeypatch):
    """The reader's child process dies of SIGSEGV (a stand-in interpreter does, every time, as VTK does on
    this file on most machines): the window shows one dialog naming the file and keeps its model."""
    model = window.document.model
    bad = tmp_path / "broken.vtk"
    bad.write_text(SEGFAULTING_VTK)
    monkeypatch.setattr(sys, "executable", crashing_interpreter(tmp_path))
    assert not window.files.new_from_mesh(bad)
    [(title, text)] = captured_errors
    assert "cannot import mesh" in title and str(bad) in text and "crashed" in text
    assert window.document.model is model


def test_a_slow_mesh_read_keeps_the_window_alive(window, qtbot, monkeypatch, tmp_path):
    """A slow read (a VTK format in its child process, up to its time limit) runs off the GUI thread: the
    window keeps handling events and shows a busy dialog, and the model arrives when the read ends."""
    import time

    from PySide6.QtCore import QTimer
    from PySide6.QtWidgets import QProgressDialog

    import workbench.window.file_controller as files
    from engine.formats.mesh_io import import_mesh

    cube = tmp_path / "cube.obj"
    cube.write_text("v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n")

    def slow_import(path):
        time.sleep(1.5)
        return import_mesh(path)

    monkeypatch.setattr(files, "import_mesh", slow_import)
    ticks, seen_busy = [], []
    timer = QTimer()
    timer.timeout.connect(lambda: (ticks.append(1), seen_busy.append(
        any(d.isVisible() for d in window.findChildren(QProgressDialog)))))
    timer.start(50)
    assert window.files.new_from_mesh(cube)
    timer.stop()
    assert len(ticks) >= 10 and any(seen_busy)          # events ran while the file was read
    assert window.document.model.n_vertices == 4
    assert not any(d.isVisible() for d in window.findChildren(QProgressDialog))
