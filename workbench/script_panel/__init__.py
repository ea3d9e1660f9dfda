"""The script panel (dock ``dock:script``): type text with inline commands, Say it, export it.

``install(context)`` adds the dock, ``window.script_panel`` (a
:class:`~.panel.ScriptPanel`), ``window.speech_exporter`` (a
:class:`~.export_dialog.SpeechExporter`) and the **Speech** menu:
Say (Ctrl+Return) and Export speech…. The head speaks through
the context's ``player`` (the window's, shared with the timeline). See
docs/workbench-script-panel.md.
"""

from __future__ import annotations

import re

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDialog, QDockWidget, QMessageBox

from ..tools import ToolContext
from ..window.actions import ActionSpec
from .export_dialog import ExportSpeechDialog, SpeechExporter
from .panel import ScriptPanel

MENU = "&Speech"


def install(context: ToolContext) -> None:
    """Add the Script dock and the Speech menu's Say and Export speech…"""
    window = context.window
    panel = window.script_panel = ScriptPanel(context)
    window.speech_exporter = SpeechExporter(context)
    dock = window.script_dock = QDockWidget("Script", window)
    dock.setObjectName("dock:script")
    dock.setWidget(panel)
    window.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, dock)
    panel.export_button.clicked.connect(lambda: export_speech_dialog(window))
    actions = context.add_actions((
        ActionSpec("speech.say", "&Say", MENU, triggered=lambda w: w.script_panel.say(),
                   shortcut="Ctrl+Return", icon="say", toolbar=True, separator_before=True,
                   tip="Speak the script panel's text: the head says it, with audio"),
        ActionSpec("speech.export", "&Export speech…", MENU, triggered=export_speech_dialog,
                   icon="export-speech", tip="Write the last utterance as MP4 with audio, WAV, tracks and "
                                             "landmarks CSV"),
    ))
    actions["speech.export"].setEnabled(False)
    panel.busy_changed.connect(lambda busy: actions["speech.say"].setEnabled(not busy))
    panel.said.connect(lambda _result: actions["speech.export"].setEnabled(True))
    context.menus[MENU].addSeparator()
    context.menus[MENU].addAction(dock.toggleViewAction())


def export_speech_dialog(window) -> None:
    """Ask what to write for the last utterance, then write it with a progress dialog."""
    result = window.script_panel.result
    if result is None:
        QMessageBox.information(window, "Export speech", "Nothing to export yet: press Say first.")
        return
    dialog = ExportSpeechDialog(window, base=base_name(result.speech.script.text), document_path=window.document.path)
    if dialog.exec() != QDialog.DialogCode.Accepted:
        return
    dialog.remember()
    window.speech_exporter.export(dialog.plan(), result.speech, result.request.model)


def base_name(text: str, words: int = 3) -> str:
    """A file name from the first words of what was said.

    >>> base_name("Hyvää huomenta! Mitä kuuluu?")
    'hyvää-huomenta-mitä'
    """
    found = re.findall(r"[^\W_]+", text.lower())[:words]
    return "-".join(found) or "speech"
