"""A mesh file that crashes VTK's reader must not take the workbench (and its unsaved work) with it."""

from __future__ import annotations

import pytest
from PySide6.QtWidgets import QMessageBox

from tests.engine.test_mesh_child import SEGFAULTING_VTK


@pytest.fixture
def captured_errors(monkeypatch):
    """QMessageBox.critical records its message instead of blocking the test."""
    errors: list[tuple[str, str]] = []

    def critical(parent, title, text, *args, **kwargs):
        errors.append((title, text))
        return QMessageBox.StandardButton.Ok

    monkeypatch.setattr(QMessageBox, "critical", staticmethod(critical))
    return errors


def test_a_file_that_segfaults_vtk_leaves_the_window_and_its_model(window, tmp_path, captured_errors):
    model = window.document.model
    bad = tmp_path / "broken.vtk"
    bad.write_text(SEGFAULTING_VTK)
    assert not window.files.new_from_mesh(bad)
    [(title, text)] = captured_errors
    assert "cannot import mesh" in title and str(bad) in text and "crashed" in text
    assert window.document.model is model
