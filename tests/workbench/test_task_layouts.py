"""Task layouts in the real window: switching, remembering, resetting, and docks that open where they can be used.

The window is given the size a fresh start picks on a 1366×768 laptop screen
(``fresh_window_size``), on the default head, whose long parameter names make
the Parameters dock as wide as it gets. That the window then stays on such a
screen is ``test_layout_fits_screen.py``'s business.
"""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QRect, QSettings, Qt
from PySide6.QtWidgets import QWidget

import engine
from workbench import settings
from workbench.tree_editor import TOOL_ID
from workbench.window.layouts import fresh_window_size
from workbench.window.task_layouts import LAYOUTS

LAPTOP = fresh_window_size(QRect(0, 0, 1366, 768))
DESKTOP = fresh_window_size(QRect(0, 0, 1600, 1000))


@pytest.fixture
def laptop_window(make_window):
    window = make_window(engine.default_model_path(), size=(LAPTOP.width(), LAPTOP.height()))
    return window


def on_screen(window, widget: QWidget) -> bool:
    """``widget`` is shown whole: inside the window, not clipped by a scroll area, not a tab behind another."""
    if not widget.isVisible():
        return False
    top_left = widget.mapTo(window, QPoint(0, 0))
    inside = window.rect().contains(QRect(top_left, widget.size()))
    return inside and widget.visibleRegion().boundingRect() == widget.rect()


def in_front(window, dock) -> bool:
    """What the window shows in the middle of ``dock`` belongs to ``dock`` (not to a tab in front of it)."""
    centre = dock.mapTo(window, dock.rect().center())
    return dock.isVisible() and dock.isAncestorOf(window.childAt(centre))


def test_layouts_switch_from_the_view_menu_and_the_toolbar(laptop_window, qtbot):
    window = laptop_window
    layouts = window.layouts
    assert layouts.current == "model"
    menu = layouts.menu
    assert menu.menuAction() in window.menus["&View"].actions()
    assert [a.text() for a in menu.actions() if a.isCheckable()] == [layout.title for layout in LAYOUTS] == \
        ["Model", "Painting", "Motion capture", "Animation/Speech", "Library"]

    window.actions_by_id["layout.mocap"].trigger()                       # View → Layout → Motion capture
    qtbot.wait(20)
    mocap = window.mocap
    assert layouts.current == "mocap" and layouts.switcher.currentText() == "Motion capture"
    assert in_front(window, mocap.plot_dock) and in_front(window, mocap.pca_dock)
    assert in_front(window, window.timeline_dock)                       # Space plays the recording there
    assert not window.tool_options.isVisible() and not window.script_dock.isVisible()
    assert window.actions_by_id["layout.mocap"].isChecked()

    switcher = layouts.switcher                                          # the toolbar's switcher
    index = switcher.findText("Library")
    switcher.setCurrentIndex(index)
    switcher.activated.emit(index)
    qtbot.wait(20)
    assert layouts.current == "library" and window.actions_by_id["layout.library"].isChecked()
    assert in_front(window, window.library_editor_dock) and in_front(window, window.expression_gallery_dock)
    assert not mocap.plot_dock.isVisible()
    # the editor's text pane has most of the window's width
    assert window.library_editor.text.width() > 0.35 * window.width()
    assert QSettings().value(settings.WINDOW_LAYOUT) == "library"


def test_a_changed_layout_is_remembered_and_reset_puts_it_back(make_window, qtbot):
    window = make_window(engine.default_model_path(), size=(DESKTOP.width(), DESKTOP.height()))
    layouts = window.layouts
    layouts.switch("painting")
    qtbot.wait(50)
    dock = window.tool_options
    built = dock.height()
    window.resizeDocks([dock], [built - 120], Qt.Orientation.Vertical)       # the user drags a separator
    qtbot.waitUntil(lambda: dock.height() < built - 30)
    changed = dock.height()
    layouts.switch("model")                                 # leaving it remembers it …
    qtbot.wait(50)
    assert layouts.is_remembered("painting") and not layouts.is_remembered("model")   # model was not changed
    assert abs(dock.height() - changed) > 30
    layouts.switch("painting")                              # … and coming back restores it
    qtbot.wait(50)
    assert abs(dock.height() - changed) <= 2
    assert window.close()

    again = make_window(engine.default_model_path(), size=None)     # the next start: the same layout, as changed
    qtbot.wait(50)
    assert again.layouts.current == "painting" and again.layouts.switcher.currentText() == "Painting"
    assert abs(again.tool_options.height() - changed) <= 2
    again.actions_by_id["layout.reset"].trigger()           # View → Layout → Reset layout
    qtbot.wait(50)
    assert abs(again.tool_options.height() - built) <= 2
    assert not again.layouts.is_remembered("painting")


def test_ctrl_g_shows_the_gallery_in_front_three_faces_across(laptop_window, qtbot):
    window = laptop_window
    gallery_action = window.actions_by_id["library.gallery"]
    assert gallery_action.shortcut().toString() == "Ctrl+G"
    gallery_action.trigger()
    qtbot.wait(50)
    dock, gallery = window.expression_gallery_dock, window.expression_gallery
    assert in_front(window, dock), "the gallery opened as a tab hidden behind another dock"
    faces = gallery.expressions_list
    assert faces.viewport().width() // faces.gridSize().width() >= 3
    assert faces.viewport().height() >= faces.gridSize().height()          # a whole row of faces
    assert window.viewport.width() >= 0.3 * window.width()                  # and the face is still there


def test_ctrl_g_brings_the_gallery_from_behind_a_tab_instead_of_closing_it(laptop_window, qtbot):
    """On a laptop the Animation/Speech layout tabs the gallery with the script panel: Ctrl+G while the
    script is in front shows the gallery (it was open, but the user could not see it); again, it stays;
    View → Expression gallery closes it (test_rough_edges_gallery.py drives these with the keys)."""
    window = laptop_window
    window.layouts.switch("animation")
    qtbot.wait(50)
    gallery, script = window.expression_gallery_dock, window.script_dock
    if gallery not in window.tabifiedDockWidgets(script):
        window.tabifyDockWidget(script, gallery)
    script.raise_()
    qtbot.wait(50)
    assert in_front(window, script) and not in_front(window, gallery) and not gallery.isHidden()
    action = window.actions_by_id["library.gallery"]
    action.trigger()
    qtbot.wait(50)
    toggle = window.actions_by_id["view.gallery"]
    assert in_front(window, gallery) and not gallery.isHidden() and toggle.isChecked()
    action.trigger()                                   # now on show: the same command keeps it there
    qtbot.wait(50)
    assert in_front(window, gallery) and toggle.isChecked()
    toggle.trigger()                                   # View → Expression gallery closes it
    qtbot.wait(50)
    assert gallery.isHidden() and not toggle.isChecked()


def test_ctrl_l_opens_the_library_editor_with_a_wide_text_pane(laptop_window, qtbot):
    window = laptop_window
    window.actions_by_id["library.editor"].trigger()
    qtbot.wait(50)
    assert in_front(window, window.library_editor_dock)
    text = window.library_editor.text
    assert text.width() >= 400 and text.height() >= 150
    assert window.frameGeometry().width() <= LAPTOP.width()


def test_the_motion_capture_layout_shows_the_plot_wide_and_the_pca_run_button(laptop_window, qtbot):
    window = laptop_window
    window.layouts.switch("mocap")
    qtbot.wait(50)
    pca, plot = window.mocap.pca_dock, window.mocap.plot_dock
    assert on_screen(window, pca.run_button), "Run PCA is off screen"
    table = pca.stage_table
    header = table.horizontalHeader()
    assert header.model().headerData(1, Qt.Orientation.Horizontal) == "Components"
    components = QRect(header.sectionViewportPosition(1), 0, header.sectionSize(1), header.height())
    assert header.viewport().rect().contains(components) and on_screen(window, table)
    assert plot.plot.width() >= 0.6 * window.width() and plot.plot.height() >= 150, "the plot is a sliver"
    assert on_screen(window, plot.plot)


def test_after_painting_tool_options_shows_the_selected_parameter(window, qtbot):
    window.view_state.select_parameter("jaw_open")
    paint = window.actions_by_id["paint.mode"]
    paint.trigger()
    assert window.tool_options.current_tool == "paint"
    paint.trigger()                                         # paint mode off, jaw_open still selected
    assert not window.paint.active
    sheet = window.tree_editor.sheet
    assert window.tool_options.current_tool == TOOL_ID and sheet.isVisible()
    assert "jaw_open" in sheet.title.text()
    window.view_state.select_parameter(None)                # nothing selected: the hint that no tool is active
    assert window.tool_options.current_tool == "none"


@pytest.mark.parametrize("size", [LAPTOP, DESKTOP], ids=["1366x768", "1600x1000"])
def test_the_live_preview_is_on_show_in_the_painting_layout(make_window, qtbot, size):
    window = make_window(engine.default_model_path(), size=(size.width(), size.height()))
    window.layouts.switch("painting")
    window.view_state.select_parameter("jaw_open")
    window.actions_by_id["paint.mode"].trigger()
    qtbot.wait(50)
    live = window.paint_options.live_preview
    scroller = window.tool_options.stack.currentWidget()
    top = live.mapTo(scroller.viewport(), QPoint(0, 0)).y()
    assert top >= 0 and top + live.height() <= scroller.viewport().height(), "Live preview is below the fold"
    assert on_screen(window, window.paint_options.hold)
    window.actions_by_id["paint.mode"].trigger()
