"""Environment variables that let a test drive a real workbench process (crash-recovery tests).

Only read by :func:`workbench.app.main`; a normal start sets none of them.

``AP_WORKBENCH_TEST_EDIT="weights NAME VALUE"``
    Once the window is up, give every vertex of parameter NAME's region the
    weight VALUE, as one undoable edit (the model is then modified).
``AP_WORKBENCH_TEST_RECOVERY=recover|discard|later``
    Answer the crash-recovery question without showing it.
``AP_WORKBENCH_TEST_REPORT=PATH.json``
    Once the window is up (after any recovery and edit), write a report of
    the window's state and a copy of the model beside it (``PATH`` with
    suffix ``.xml``), then close the window discarding unsaved changes.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QMessageBox

from engine.formats.atomic import atomic_write_text

from .document.undo_commands import WeightsChangedCommand

if TYPE_CHECKING:
    from .window.main_window import MainWindow

EDIT = "AP_WORKBENCH_TEST_EDIT"
RECOVERY = "AP_WORKBENCH_TEST_RECOVERY"
REPORT = "AP_WORKBENCH_TEST_REPORT"
_ANSWERS = {"recover": QMessageBox.StandardButton.Yes, "discard": QMessageBox.StandardButton.Discard,
            "later": QMessageBox.StandardButton.Ignore}


def active() -> bool:
    return any(os.environ.get(name) for name in (EDIT, RECOVERY, REPORT))


def prepare(window: MainWindow) -> None:
    """Before the window shows: answer the questions the hooks ask to have answered."""
    answer = os.environ.get(RECOVERY)
    if answer:
        window.files.ask_recover = lambda _entry: _ANSWERS[answer]
    if os.environ.get(REPORT):
        window.files.ask_unsaved = lambda _doing: QMessageBox.StandardButton.Discard


def run(window: MainWindow) -> None:
    """After the window shows: make the scripted edit, then report and close."""
    edit = os.environ.get(EDIT)
    if edit:
        verb, name, value = edit.split()
        if verb != "weights":
            raise ValueError(f"{EDIT}: unknown edit '{verb}' (known: weights)")
        region = window.document.model.regions[name]
        window.document.push(WeightsChangedCommand(window.document, name, region.indices,
                                                   np.full(len(region.indices), float(value))))
    report = os.environ.get(REPORT)
    if report:
        path = Path(report)
        copy = window.document.save_copy(path.with_suffix(".xml"))
        state = {"title": window.windowTitle(), "modified": window.isWindowModified(),
                 "document_path": str(window.document.path) if window.document.path else None,
                 "model_copy": str(copy), "recovery_folder": str(window.autosaver.session.folder)}
        atomic_write_text(path, json.dumps(state, indent=2) + "\n")
        QTimer.singleShot(0, window.close)
