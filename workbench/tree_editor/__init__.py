"""The parameter tree editor (§2.2, Fig. 3): add, remove, rename and move parameters, edit their properties.

``install(window)`` adds

* the **Parameter tree** dock (``dock:parameter-tree``): every parameter with
  its group (1 · rigid for parameters with children, 2 · leaf otherwise) and
  type; rename in place, drag a row onto another to move it under it;
* the **property sheet** on the ``tree-editor`` page of the Tool options dock
  (type, axis, pivot typed or picked on the mesh, direction, range, default);
* the **gizmo** in the viewport: the selected parameter's pivot and axis;
* the **Parameters** menu: Add parameter, Remove parameter, Rename (F2).

Every edit is one undo step. ``window.tree_editor`` is the
:class:`~workbench.tree_editor.editor.TreeEditor` holding the pieces.
"""

from __future__ import annotations

from PySide6.QtCore import Qt

from ..tools import ToolContext
from ..window.actions import ActionSpec
from .dock import ParameterTreeDock
from .editor import TreeEditor
from .gizmo import ParameterGizmo
from .property_sheet import TOOL_ID, PropertySheet

__all__ = ["TOOL_ID", "TreeEditor", "install"]

MENU = "&Parameters"
ACTIONS = (
    ActionSpec("parameters.add", "&Add parameter", MENU, triggered=lambda w: w.tree_editor.add_parameter(),
               shortcut="Ctrl+Shift+A", icon="parameter-add", toolbar=True, separator_before=True,
               tip="Add a parameter under the selected one (or at the top when none is selected)"),
    ActionSpec("parameters.remove", "&Remove parameter…", MENU,
               triggered=lambda w: w.tree_editor.remove_parameter(), icon="parameter-remove", toolbar=True,
               tip="Remove the selected parameter, everything below it and their influence regions"),
    ActionSpec("parameters.rename", "Re&name", MENU, triggered=lambda w: w.tree_editor.start_rename(),
               shortcut="F2", icon="parameter-rename", tip="Rename the selected parameter"),
    ActionSpec("parameters.move_up", "Move &up", MENU, triggered=lambda w: w.tree_editor.move_among_siblings(-1),
               shortcut="Ctrl+Shift+Up", icon="parameter-move-up", separator_before=True,
               tip="Move the selected parameter before its previous sibling (the order it is shown and saved in)"),
    ActionSpec("parameters.move_down", "Move &down", MENU,
               triggered=lambda w: w.tree_editor.move_among_siblings(+1), shortcut="Ctrl+Shift+Down",
               icon="parameter-move-down", tip="Move the selected parameter after its next sibling"),
)


def install(context: ToolContext) -> None:
    """Add the tree editor's dock, property page, gizmo and actions to the context's window."""
    window = context.window
    editor = TreeEditor(context)
    window.tree_editor = editor
    editor.dock = ParameterTreeDock(context.document, context.view_state, editor.rename, editor.reparent, window)
    editor.dock.view.delete_requested.connect(editor.remove_parameter)
    window.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, editor.dock)
    editor.sheet = PropertySheet(editor)
    tool_options = context.tool_options
    tool_options.add_page(TOOL_ID, editor.sheet)     # the dock scrolls every page
    editor.dock.picked_by_user.connect(lambda name: tool_options.show_page(TOOL_ID))
    # With no tool active, Tool options shows the selected parameter's properties rather than "no tool".
    view_state = context.view_state
    tool_options.set_idle_page(TOOL_ID, lambda: view_state.selected_parameter is not None)
    view_state.selected_parameter_changed.connect(tool_options.refresh_idle)
    editor.gizmo = ParameterGizmo(context.viewport, context.document, context.view_state, editor)
    editor.actions = context.add_actions(ACTIONS)
    context.menus["&View"].addAction(editor.dock.toggleViewAction())
    # Bound methods, not lambdas, on the document: it may outlive the window.
    view_state.selected_parameter_changed.connect(editor.update_actions)
    context.document.parameters_changed.connect(editor.update_actions)
    context.document.model_replaced.connect(editor.update_actions)
    editor.update_actions()
