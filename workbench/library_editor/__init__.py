"""The library editor: write a §2.3 library file and see the head perform it a second later.

:func:`install` adds the dock ``dock:library-editor`` (hidden until Library →
Library editor, Ctrl+L), the Library menu's commands, and a guard that asks
about unsaved library edits before the window closes. The editor is
``window.library_editor`` (a :class:`LibraryEditor`); the library folders and
the "library changed" signal are the context's ``library_sources``
(:class:`~workbench.library_sources.LibrarySources`), shared with the expression gallery.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, QSize, Qt
from PySide6.QtWidgets import QDockWidget

from ..icons import icon
from ..library_sources import LibrarySources
from ..tools import ToolContext
from ..window.actions import ActionSpec
from .editor import LibraryEditor

DOCK_NAME = "dock:library-editor"
USEFUL_SIZE = QSize(760, 320)
MENU = "&Library"

__all__ = ["DOCK_NAME", "LibraryEditor", "LibrarySources", "install"]


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


def _show(context: ToolContext, dock: QDockWidget, editor: LibraryEditor) -> None:
    context.reveal(dock)
    editor.text.setFocus()


def install(context: ToolContext) -> None:
    """Add the library editor's dock, the Library menu's commands and the close guard."""
    window = context.window
    editor = LibraryEditor(context)
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
    context.add_actions((
        ActionSpec("library.new_command", "&New command from template…", MENU,
                   triggered=lambda _w: (_show(context, dock, editor), editor.new_dialog()), icon="library-new",
                   tip="Start a library file from a template"),
        ActionSpec("library.open", "&Open library file…", MENU,
                   triggered=lambda _w: (_show(context, dock, editor), editor.open_dialog()),
                   icon="library-open", tip="Open a command library file (.lib) in the library editor"),
        ActionSpec("library.folders", "Library &folders…", MENU,
                   triggered=lambda _w: editor.folders_dialog(), icon="library-folders",
                   tip="Choose the folders your own library files are read from"),
    ))
    menu = context.menus[MENU]
    menu.insertAction(menu.actions()[0], toggle)
    menu.insertSeparator(menu.actions()[1])
    context.toolbar.addSeparator()
    context.toolbar.addAction(toggle)
    context.actions["library.editor"] = toggle
