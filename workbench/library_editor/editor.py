"""The library editor: one library file open, checked as you type, its command plotted and previewed.

Layout, left to right: the library's commands (:class:`CommandList`), the
text (:class:`CodeEditor`) with a status line under it, and the command's
arguments (:class:`ArgumentsForm`), a Preview button and the plot of its
curves (:class:`CurvePlot`).

300 ms after the last keystroke the text is parsed by the engine
(:func:`check_library_text`, the same parser the command line uses) and
bound to the open model; problems are underlined at their line and listed in
the status line, and the chosen command is translated with the form's
arguments and plotted. Preview plays the same translation through
``context.player``. Blank text is not an error: the editor shows what to type
(an example in the empty text, links to a template and to a file in the
status line) until there is text to check.

Unsaved text is autosaved for crash recovery by :class:`LibraryAutosaver`
(``editor.autosaver``); :meth:`LibraryEditor.offer_recovery` offers what a
crashed workbench left behind.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt, QTimer, Signal
from PySide6.QtWidgets import (
    QComboBox,
    QFileDialog,
    QHBoxLayout,
    QLabel,
    QMessageBox,
    QPushButton,
    QSplitter,
    QToolBar,
    QVBoxLayout,
    QWidget,
)

from engine.commands.analysis import CheckResult, Problem, check_library_text
from engine.errors import UserError
from engine.formats.atomic import atomic_write_text
from engine.timeline.command_curves import CommandCurves, command_curves

from ..icons import icon
from ..tools import ToolContext
from ..window.recovery import LibraryCopy
from .arguments_form import ArgumentsForm
from .autosave import LibraryAutosaver, recovery_question
from .code_editor import CodeEditor
from .command_list import CommandList
from .curve_plot import CurvePlot
from .dialogs import LibraryFoldersDialog, NewCommandDialog
from .folders import LAST_DIR, LAST_FILE, is_shipped, recall, remember
from .templates import example_text, template_text

CHECK_DELAY_MS = 300
FILE_FILTER = "Library files (*.lib);;All files (*)"
HINT = ("Type a library file in the text, or start from a template: <a href='new'>New command…</a> "
        "or <a href='open'>Open a library file…</a>")
HINT_COLOUR = "#5f6368"
Button = QMessageBox.StandardButton


class LibraryEditor(QWidget):
    """Edits one library file for the window of ``context`` (its document, its player, its library sources).

    Signals: ``checked(list[Problem])`` after every check; ``title_changed(str)``.
    """

    checked = Signal(list)
    title_changed = Signal(str)

    def __init__(self, context: ToolContext, parent: QWidget | None = None):
        super().__init__(parent)
        self.context = context
        self.window_ = context.window     # the parent of its dialogs
        sources = context.library_sources
        self.sources = sources
        self.path: Path | None = None
        self.result = CheckResult()
        self.curves: CommandCurves | None = None
        self._confirmed_discard = False

        self.text = CodeEditor()
        self.status = QLabel()
        self.status.setWordWrap(True)
        self.status.setTextInteractionFlags(Qt.TextInteractionFlag.LinksAccessibleByMouse)
        self.status.linkActivated.connect(self._status_link)
        self.command_list = CommandList(sources)
        self.command_list.file_activated.connect(self._open_from_list)
        self.command_choice = QComboBox()
        self.command_choice.currentIndexChanged.connect(self._command_chosen)
        self.form = ArgumentsForm()
        self.form.changed.connect(self.refresh_plot)
        self.preview_button = QPushButton(icon("library-preview"), "Preview")
        self.preview_button.setToolTip("Play the command with these arguments on the model (at = 0)")
        self.preview_button.clicked.connect(self.preview)
        self.plot = CurvePlot()

        self.toolbar = QToolBar()
        self.toolbar.setIconSize(self.toolbar.iconSize() * 0.75)
        for text, icon_name, slot, tip in (
                ("New…", "library-new", self.new_dialog, "New command from a template"),
                ("Open…", "open", self.open_dialog, "Open a library file (.lib)"),
                ("Save", "save", self.save, "Write the library file (atomically)"),
                ("Save as…", "save-as", self.save_as_dialog, "Write the library file under a new name"),
                ("Folders…", "library-folders", self.folders_dialog, "Choose your library folders")):
            action = self.toolbar.addAction(icon(icon_name), text, slot)
            action.setToolTip(tip)
        self.toolbar.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextBesideIcon)

        middle = QWidget()
        middle_layout = QVBoxLayout(middle)
        middle_layout.setContentsMargins(0, 0, 0, 0)
        middle_layout.addWidget(self.text, 1)
        middle_layout.addWidget(self.status)
        right = QWidget()
        right_layout = QVBoxLayout(right)
        right_layout.setContentsMargins(0, 0, 0, 0)
        top = QHBoxLayout()
        top.addWidget(QLabel("Command"))
        top.addWidget(self.command_choice, 1)
        top.addWidget(self.preview_button)
        right_layout.addLayout(top)
        right_layout.addWidget(self.form)
        right_layout.addWidget(self.plot, 1)
        self.splitter = QSplitter(Qt.Orientation.Horizontal)
        for widget, stretch in ((self.command_list, 0), (middle, 2), (right, 2)):
            self.splitter.addWidget(widget)
            self.splitter.setStretchFactor(self.splitter.count() - 1, stretch)
        self.splitter.setSizes([170, 430, 430])
        layout = QVBoxLayout(self)
        layout.setContentsMargins(2, 2, 2, 2)
        layout.addWidget(self.toolbar)
        layout.addWidget(self.splitter, 1)

        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(CHECK_DELAY_MS)
        self._timer.timeout.connect(self.check_now)
        self.text.textChanged.connect(self._timer.start)
        self.text.textChanged.connect(self._text_changed)
        self.text.modificationChanged.connect(self._modification_changed)
        self.autosaver = LibraryAutosaver(self)
        self.autosaver.autosaved.connect(self._autosaved)
        self.autosaver.failed.connect(self._autosave_failed)
        document = context.document
        document.model_replaced.connect(self._model_changed)
        document.parameters_changed.connect(self._model_changed)
        sources.changed.connect(self.command_list.reload)
        self._model_changed()             # the example in the empty text, and the first check

    # -- state ----------------------------------------------------------------
    @property
    def is_modified(self) -> bool:
        return self.text.document().isModified()

    @property
    def is_blank(self) -> bool:
        """Whether there is no text to check yet (nothing, or only white space)."""
        return not self.text.toPlainText().strip()

    @property
    def edits_discarded(self) -> bool:
        """Whether the user chose Discard for the unsaved edits (and has not typed since)."""
        return self._confirmed_discard

    @property
    def check_pending(self) -> bool:
        """Whether an edit is waiting for its (debounced) check."""
        return self._timer.isActive()

    def display_name(self) -> str:
        return self.path.name if self.path is not None else "untitled.lib"

    def title(self) -> str:
        return f"Library editor — {self.display_name()}{'*' if self.is_modified else ''}"

    def definition(self):
        """The command chosen for the plot and the preview (``None`` when the text does not parse)."""
        index = self.command_choice.currentIndex()
        return self.result.definitions[index] if 0 <= index < len(self.result.definitions) else None

    def set_text(self, text: str, path: Path | None = None, *, modified: bool = False) -> None:
        """Replace the text; ``modified`` says whether it differs from ``path`` (a new file does)."""
        self.path = path
        self.text.setPlainText(text)
        self.text.document().setModified(modified)
        self._confirmed_discard = False
        self.check_now()
        self.title_changed.emit(self.title())

    # -- checking ---------------------------------------------------------------
    def check_now(self) -> CheckResult:
        """Parse and bind the text now (the debounce timer calls this 300 ms after typing stops)."""
        self._timer.stop()
        if self.is_blank:                 # nothing written yet is not an error: _show_status says what to do
            self.result = CheckResult()
        else:
            self.result = check_library_text(self.text.toPlainText(), self.display_name(),
                                             self.context.document.model)
        self.text.set_problems({p.line or 1: p.message for p in self.result.problems})
        self._show_status(self.result.problems)
        names = [d.name for d in self.result.definitions]
        current = self.command_choice.currentText()
        self.command_choice.blockSignals(True)
        self.command_choice.clear()
        self.command_choice.addItems(names)
        self.command_choice.setCurrentIndex(names.index(current) if current in names else 0 if names else -1)
        self.command_choice.blockSignals(False)
        self._command_chosen()
        self.checked.emit(list(self.result.problems))
        return self.result

    def _show_status(self, problems: list[Problem]) -> None:
        if self.is_blank:
            self.status.setText(HINT)
            self.status.setStyleSheet(f"color: {HINT_COLOUR}")
            return
        if not problems:
            count = len(self.result.definitions)
            self.status.setText(f"✓ {count} command{'s' if count != 1 else ''}, fits the model "
                                f"'{self.context.document.model.name}'")
            self.status.setStyleSheet("color: #26734d")
            return
        lines = [f"<a href='{p.line or 1}'>line {p.line}</a>: {_escape(p.message)}" if p.line
                 else _escape(p.message) for p in problems[:3]]
        more = f" (and {len(problems) - 3} more)" if len(problems) > 3 else ""
        self.status.setText("<br>".join(lines) + more)
        self.status.setStyleSheet("color: #c0392b")

    def _command_chosen(self, *_args) -> None:
        self.form.set_definition(self.definition())
        self.refresh_plot()

    def refresh_plot(self) -> CommandCurves | None:
        """Translate the chosen command with the form's arguments and plot its curves."""
        definition = self.definition()
        self.curves = None
        if definition is None:
            self.plot.set_message("Nothing to plot yet: no command written" if self.is_blank
                                  else "Nothing to plot: the text does not define a command yet"
                                  if self.result.problems else "No command")
        else:
            try:
                self.curves = command_curves(definition, self.context.document.model, self.form.values())
            except UserError as exc:
                self.plot.set_message(f"Cannot plot {definition.name}: {exc.message}")
            else:
                self.plot.set_curves(self.curves.curves)
        self.preview_button.setEnabled(self.curves is not None)
        return self.curves

    def _model_changed(self, *_args) -> None:
        self.text.setPlaceholderText(example_text(self.context.document.model.parameters.names))
        self.check_now()

    # -- preview ------------------------------------------------------------------
    def preview(self) -> bool:
        """Play the chosen command (``at = 0``, the form's arguments) through ``context.player``."""
        curves = self.refresh_plot()
        player = self.context.player
        if curves is None:
            return False
        if player is None:
            self.context.status.showMessage("Preview needs the timeline player, which is not installed", 4000)
            return False
        player.load(curves.timeline, title=f"{self.definition().name} (library editor preview)")
        player.play()
        return True

    # -- questions (replaced by tests) -------------------------------------------
    def ask_unsaved(self, reason: str) -> QMessageBox.StandardButton:
        """Save, Discard or Cancel, before ``reason`` (e.g. "closing") would drop the unsaved edits."""
        return QMessageBox.question(
            self, "Unsaved library file",
            f"The library file {self.display_name()} has unsaved edits. Save them before {reason}?",
            Button.Save | Button.Discard | Button.Cancel, Button.Save)

    def ask_recover(self, copy: LibraryCopy) -> QMessageBox.StandardButton:
        """Yes (recover), Discard (delete the copy) or Ignore (ask again next time)."""
        return recovery_question(self, copy)

    # -- crash recovery -------------------------------------------------------------
    def offer_recovery(self) -> bool:
        """Offer the unsaved text a crashed workbench left behind (:meth:`LibraryAutosaver.offer_recovery`)."""
        return self.autosaver.offer_recovery()

    # -- files --------------------------------------------------------------------
    def maybe_save(self, reason: str = "closing") -> bool:
        """Ask Save / Discard / Cancel when the text has unsaved edits; False means stop.

        Discard also drops the recovery copy: the user chose to lose the edits.
        """
        if not self.is_modified or self._confirmed_discard:
            return True
        answer = self.ask_unsaved(reason)
        if answer == Button.Save:
            return self.save()
        if answer == Button.Discard:
            self._confirmed_discard = True
            self.autosaver.clear()
            return True
        return False

    def open_file(self, path: str | Path, line: int = 1) -> bool:
        path = Path(path)
        if path == self.path and self.is_modified:
            self.text.go_to_line(line)
            return True
        if not self.maybe_save("opening another file"):
            return False
        try:
            text = path.read_bytes().decode("utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            QMessageBox.warning(self, "Cannot open library file", f"{path}: {getattr(exc, 'strerror', None) or exc}")
            return False
        self.set_text(text, path)
        remember(LAST_FILE, str(path))
        remember(LAST_DIR, str(path.parent))
        self.text.go_to_line(line)
        return True

    def save(self) -> bool:
        if self.path is None or is_shipped(self.path):
            return self.save_as_dialog()
        return self.save_as(self.path)

    def save_as(self, path: str | Path) -> bool:
        """Write the text to ``path`` atomically; the library list and the gallery reload."""
        path = Path(path)
        if path.suffix != ".lib":
            path = path.with_suffix(".lib")
        try:
            atomic_write_text(path, self.text.toPlainText())
        except (UserError, OSError) as exc:
            QMessageBox.warning(self, "Cannot save library file", str(exc))
            return False
        self.path = path
        self.text.document().setModified(False)
        remember(LAST_FILE, str(path))
        remember(LAST_DIR, str(path.parent))
        self.check_now()
        self.title_changed.emit(self.title())
        self.context.status.showMessage(f"Saved {path}", 4000)
        self.sources.notify_saved(path)
        return True

    def save_as_dialog(self) -> bool:
        folders = self.sources.existing_folders()
        if self.path is not None and not is_shipped(self.path):
            start = str(self.path)
        elif folders:                     # a shipped file is saved into the user's first folder
            start = str(folders[0] / self.display_name())
        else:
            start = str(Path(recall(LAST_DIR) or Path.home()) / self.display_name())
        name, _ = QFileDialog.getSaveFileName(self, "Save library file", start, FILE_FILTER)
        return bool(name) and self.save_as(name)

    def open_dialog(self) -> bool:
        name, _ = QFileDialog.getOpenFileName(self, "Open library file", recall(LAST_DIR), FILE_FILTER)
        return bool(name) and self.open_file(name)

    def new_from_template(self, name: str, kind: str, parameter: str) -> bool:
        """Start an untitled file defining ``name`` from the ``kind`` template, driving ``parameter``."""
        if not self.maybe_save("starting a new command"):
            return False
        self.set_text(template_text(kind, name, parameter), modified=True)
        return True

    def new_dialog(self) -> bool:
        model = self.context.document.model
        dialog = NewCommandDialog(model.parameters.names, self.context.view_state.selected_parameter, self)
        if not dialog.exec():
            return False
        return self.new_from_template(*dialog.choice())

    def folders_dialog(self) -> bool:
        dialog = LibraryFoldersDialog(self.sources.folders(), self)
        if not dialog.exec():
            return False
        self.sources.set_folders(dialog.folders())
        return True

    def _open_from_list(self, path: str, line: int) -> None:
        self.open_file(path, line)

    def _status_link(self, link: str) -> None:
        if link == "new":
            self.new_dialog()
        elif link == "open":
            self.open_dialog()
        else:
            self.text.go_to_line(int(link))

    def _text_changed(self) -> None:
        self._confirmed_discard = False   # edits made after Discard are new edits, worth keeping

    def _modification_changed(self, modified: bool) -> None:
        if modified:
            self._confirmed_discard = False
        self.title_changed.emit(self.title())

    def _autosaved(self, _path: str) -> None:
        self.context.status.showMessage(
            f"Autosaved the library text of {self.display_name()}: a crash would not lose its edits", 4000)

    def _autosave_failed(self, message: str) -> None:
        self.context.status.showMessage(f"Autosave of the library file failed: {message}", 4000)


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
