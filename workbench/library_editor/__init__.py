"""The library editor: write a §2.3 library file and see the head perform it a second later.

:func:`install` adds the dock ``dock:library-editor`` (hidden until Library →
Library editor, Ctrl+L), the Library menu's commands, and a guard that asks
about unsaved library edits before the window closes. The editor is
``window.library_editor`` (a :class:`LibraryEditor`); the library folders and
the "library changed" signal are ``window.library_sources``
(:class:`LibrarySources`), shared with the expression gallery.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, QSize, Qt
from PySide6.QtWidgets import QDockWidget

from ..icons import icon
from ..window.actions import ActionSpec, add_actions
from .editor import LibraryEditor
from .folders import LibrarySources

DOCK_NAME = "dock:library-editor"
USEFUL_SIZE = QSize(760, 320)
MENU = "&Library"

__all__ = ["DOCK_NAME", "LibraryEditor", "LibrarySources", "install", "library_sources"]


def library_sources(window) -> LibrarySources:
    """The window's :class:`LibrarySources`, made on first use (the gallery may be installed alone)."""
    sources = getattr(window, "library_sources", None)
    if sources is None:
        sources = window.library_sources = LibrarySources(window)
    return sources


class _CloseGuard(QObject):
    """Asks about unsaved library edits before the main window's own close handling runs.

    An event filter sees the window's Close event first; ignoring the event
    and returning True stops the close, exactly as the window's closeEvent
    would (nothing in main_window.py had to change).
    """

    def __init__(self, window, editor: LibraryEditor):
        super().__init__(window)
        self.editor = editor

    def eventFilter(self, watched, event) -> bool:
        if event.type() == QEvent.Type.Close and not self.editor.maybe_save("closing the window"):
            event.ignore()
            return True
        return False


def _show(window) -> None:
    window.layouts.reveal(window.library_editor_dock)
    window.library_editor.text.setFocus()


def install(window) -> None:
    sources = library_sources(window)
    editor = LibraryEditor(window, sources)
    dock = QDockWidget("Library editor", window)
    dock.setObjectName(DOCK_NAME)
    dock.setWidget(editor)
    window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, dock)   # the task layouts give it its place
    dock.hide()
    dock.useful_size = lambda: USEFUL_SIZE      # the text pane wide, a dozen lines high (LayoutManager.reveal)
    editor.title_changed.connect(dock.setWindowTitle)
    window.library_editor = editor
    window.library_editor_dock = dock
    guard = _CloseGuard(window, editor)
    window.installEventFilter(guard)
    window.library_editor_guard = guard

    toggle = dock.toggleViewAction()
    toggle.setIcon(icon("library-editor"))
    toggle.setText("Library &editor")
    toggle.setShortcut("Ctrl+L")
    toggle.setToolTip("Write and try command library files (§2.3)")
    add_actions(window, (
        ActionSpec("library.new_command", "&New command from template…", MENU,
                   triggered=lambda w: (_show(w), w.library_editor.new_dialog()), icon="library-new",
                   tip="Start a library file from a template"),
        ActionSpec("library.open", "&Open library file…", MENU,
                   triggered=lambda w: (_show(w), w.library_editor.open_dialog()),
                   icon="library-open", tip="Open a command library file (.lib) in the library editor"),
        ActionSpec("library.folders", "Library &folders…", MENU,
                   triggered=lambda w: w.library_editor.folders_dialog(), icon="library-folders",
                   tip="Choose the folders your own library files are read from"),
    ))
    menu = window.menus[MENU]
    menu.insertAction(menu.actions()[0], toggle)
    menu.insertSeparator(menu.actions()[1])
    window.toolbar.addSeparator()
    window.toolbar.addAction(toggle)
    window.actions_by_id["library.editor"] = toggle
