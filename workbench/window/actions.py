"""The workbench's commands, declared as data and turned into QActions in one place.

Each :class:`ActionSpec` names an action, its menu, shortcut and icon, and
a callback taking the main window. Adding a command is adding one entry to
:data:`ACTIONS`; menus and the toolbar follow.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from importlib import import_module
from typing import TYPE_CHECKING

from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QMenu, QMenuBar, QToolBar

from ..icons import icon

if TYPE_CHECKING:
    from .main_window import MainWindow

Shortcut = QKeySequence.StandardKey | str | None


@dataclass(frozen=True)
class ActionSpec:
    """One command: where it shows, how it is invoked, what it does.

    ``triggered(window)`` runs for plain actions; checkable actions use
    ``toggled(window, checked)`` instead.
    """

    id: str
    text: str
    menu: str
    triggered: Callable[[MainWindow], object] | None = None
    toggled: Callable[[MainWindow, bool], object] | None = None
    shortcut: Shortcut = None
    icon: str | None = None
    tip: str = ""
    toolbar: bool = False
    separator_before: bool = False


def _photofit_wizard(window: MainWindow) -> None:
    # By name, when first opened, as features.py installs the tools: the wizard stands on tools
    # (the script panel's jobs) that stand on this module.
    import_module("workbench.photofit_wizard.wizard").open_photofit_wizard(window)


ACTIONS: tuple[ActionSpec, ...] = (
    ActionSpec("file.new_from_mesh", "&New from mesh…", "&File", triggered=lambda w: w.files.new_from_mesh_dialog(),
               shortcut=QKeySequence.StandardKey.New, icon="new-from-mesh",
               tip="Start a new model from a mesh file (OBJ, PLY, STL, VTK, glTF, …)"),
    ActionSpec("file.new_from_photos", "New head from &photographs…", "&File", triggered=_photofit_wizard,
               icon="new-from-photos",
               tip="Fit the head to a front (and side) photograph of a person, textured from them"),
    ActionSpec("file.open", "&Open model…", "&File", triggered=lambda w: w.files.open_dialog(),
               shortcut=QKeySequence.StandardKey.Open, icon="open", toolbar=True,
               tip="Open a model description (.xml)"),
    ActionSpec("file.save", "&Save", "&File", triggered=lambda w: w.files.save(),
               shortcut=QKeySequence.StandardKey.Save, icon="save", toolbar=True,
               tip="Write the model to its file (.xml + .h5)"),
    ActionSpec("file.save_as", "Save model &as…", "&File", triggered=lambda w: w.files.save_as_dialog(),
               shortcut=QKeySequence.StandardKey.SaveAs, icon="save-as",
               tip="Write the model to a new .xml + .h5 pair"),
    ActionSpec("file.export", "&Configuration…", "&File/&Export", triggered=lambda w: w.files.export_dialog(),
               shortcut="Ctrl+E", icon="export-configuration", separator_before=True,
               tip="Copy the model and the command library files it uses into a folder for a colleague"),
    ActionSpec("file.export_gltf", "&glTF…", "&File/&Export", triggered=lambda w: w.files.export_gltf_dialog(),
               icon="export-gltf",
               tip="Write the model with its parameters as glTF 2.0 morph targets (Blender, Unity, Unreal, three.js)"),
    ActionSpec("file.quit", "&Quit", "&File", triggered=lambda w: w.close(),
               shortcut=QKeySequence.StandardKey.Quit, separator_before=True),
    ActionSpec("edit.undo", "&Undo", "&Edit", triggered=lambda w: w.undo(),
               shortcut=QKeySequence.StandardKey.Undo, icon="undo", toolbar=True, separator_before=True,
               tip="Take back the last change to the model"),
    ActionSpec("edit.redo", "&Redo", "&Edit", triggered=lambda w: w.redo(),
               shortcut=QKeySequence.StandardKey.Redo, icon="redo", toolbar=True,
               tip="Make the change taken back again"),
    ActionSpec("pose.reset_all", "&Reset all", "&Pose", triggered=lambda w: w.document.reset_all(),
               shortcut="Ctrl+R", icon="reset", toolbar=True, separator_before=True,
               tip="Put every parameter back to its default (the rest pose)"),
    ActionSpec("view.front", "&Front", "&View", triggered=lambda w: w.viewport.set_view("front"),
               shortcut="Ctrl+1", icon="view-front", toolbar=True, separator_before=True,
               tip="Look at the face straight on"),
    ActionSpec("view.side", "&Side", "&View", triggered=lambda w: w.viewport.set_view("side"),
               shortcut="Ctrl+2", icon="view-side", toolbar=True, tip="Look at the head in profile"),
    ActionSpec("view.three_quarter", "&Three-quarter", "&View",
               triggered=lambda w: w.viewport.set_view("three-quarter"),
               shortcut="Ctrl+3", icon="view-three-quarter", toolbar=True, tip="Look from halfway round"),
    ActionSpec("view.wireframe", "&Wireframe", "&View", toggled=lambda w, on: w.view_state.set_wireframe(on),
               shortcut="Ctrl+Shift+W", icon="wireframe", toolbar=True, separator_before=True,
               tip="Draw the polygons' edges instead of shaded surfaces"),
    ActionSpec("view.landmarks", "&Landmarks", "&View", toggled=lambda w, on: w.view_state.set_landmarks(on),
               shortcut="Ctrl+Shift+L", icon="landmarks", toolbar=True,
               tip="Show the model's landmarks (MPEG-4 feature points) with their ids"),
)


def create_actions(window: MainWindow, specs: tuple[ActionSpec, ...] = ACTIONS) -> dict[str, QAction]:
    """One QAction per spec, parented to ``window`` and connected to its callback."""
    actions: dict[str, QAction] = {}
    for spec in specs:
        action = QAction(spec.text, window)
        action.setObjectName(spec.id)
        if spec.shortcut is not None:
            action.setShortcut(QKeySequence(spec.shortcut))
        if spec.icon:
            action.setIcon(icon(spec.icon))
        if spec.tip:
            action.setToolTip(spec.tip)
            action.setStatusTip(spec.tip)
        if spec.toggled is not None:
            action.setCheckable(True)
            action.toggled.connect(lambda on, spec=spec: spec.toggled(window, on))
        elif spec.triggered is not None:
            action.triggered.connect(lambda _checked=False, spec=spec: spec.triggered(window))
        actions[spec.id] = action
    return actions


def populate(menubar: QMenuBar, toolbar: QToolBar, actions: dict[str, QAction],
             specs: tuple[ActionSpec, ...] = ACTIONS) -> dict[str, QMenu]:
    """Put the actions into menus (created in order of first mention) and the toolbar."""
    menus: dict[str, QMenu] = {}
    for spec in specs:
        menu = _menu(spec, menus, menubar)
        menu.addAction(actions[spec.id])
        if spec.toolbar:
            if spec.separator_before and toolbar.actions():
                toolbar.addSeparator()
            toolbar.addAction(actions[spec.id])
    return menus


def _menu(spec: ActionSpec, menus: dict[str, QMenu], menubar: QMenuBar) -> QMenu:
    """The menu ``spec`` goes into, made at the end of the menu bar on first mention; a name
    ``"&File/&Export"`` is a submenu, made at the end of its parent (after a separator if asked)."""
    menu = menus.get(spec.menu)
    if menu is not None:
        if spec.separator_before:
            menu.addSeparator()
        return menu
    parent_name, _, title = spec.menu.rpartition("/")
    if not parent_name:
        menu = menubar.addMenu(title)
    else:
        parent = menus[parent_name]
        if spec.separator_before:
            parent.addSeparator()
        menu = parent.addMenu(title)
    menus[spec.menu] = menu
    return menu


def add_actions(window: MainWindow, specs: tuple[ActionSpec, ...]) -> dict[str, QAction]:
    """Add a tool's actions to a built window: menus (new ones go before none), toolbar, ``actions_by_id``.

    A tool's :func:`install` calls this with its own specs; menus it names
    that do not exist yet are appended to the menu bar.
    """
    actions = create_actions(window, specs)
    for spec in specs:
        menu = _menu(spec, window.menus, window.menuBar())
        menu.addAction(actions[spec.id])
        if spec.toolbar:
            if spec.separator_before and window.toolbar.actions():
                window.toolbar.addSeparator()
            window.toolbar.addAction(actions[spec.id])
    window.actions_by_id.update(actions)
    return actions
