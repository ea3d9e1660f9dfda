"""Issue 30 §4, the gallery and the View menu, with real keys and mouse on a laptop-sized window.

* Every face in the expression gallery has its name on show under it, in every task layout, on a
  1366×768 screen (the Library layout's gallery is too low for a row of expressions and one of action
  units: the two become tabs) and on a larger one.
* Ctrl+G shows the gallery in front and never hides it; View → Expression gallery is the checkable
  entry that opens and closes it, ticked while it is open.
* The View menu lists every dock, checkable, ticked while the dock is open.

The helpers here (keys through the window system, a menu entry clicked) serve the other
``test_rough_edges_*`` files too.
"""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QRect, Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QApplication, QDockWidget

import engine
from tests.workbench.test_task_layouts import DESKTOP, LAPTOP, in_front
from tests.workbench.test_task_layouts import laptop_window as laptop_window  # the fixture

DEFAULT_HEAD = engine.default_model_path()
pytestmark = pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="the default head is not built")
LAYOUT_KEYS = {"model": Qt.Key.Key_1, "painting": Qt.Key.Key_2, "mocap": Qt.Key.Key_3, "animation": Qt.Key.Key_4,
               "library": Qt.Key.Key_5}
CTRL, SHIFT, ALT = (Qt.KeyboardModifier.ControlModifier, Qt.KeyboardModifier.ShiftModifier,
                    Qt.KeyboardModifier.AltModifier)


def press(qtbot, window, key, modifiers=Qt.KeyboardModifier.NoModifier) -> None:
    """A key as the window system delivers it (through the QWindow), so the window's shortcuts see it."""
    window.activateWindow()
    qtbot.waitUntil(lambda: QApplication.activeWindow() is window)
    qtbot.keyClick(window.windowHandle(), key, modifiers)
    qtbot.wait(30)


def choose_layout(qtbot, window, layout_id: str) -> None:
    press(qtbot, window, LAYOUT_KEYS[layout_id], CTRL | ALT)            # View → Layout's shortcuts
    assert window.layouts.current == layout_id


def menu_entry(window, menu_title: str, text: str) -> QAction:
    found = [a for a in window.menus[menu_title].actions() if a.text().replace("&", "") == text]
    assert len(found) == 1, f"{menu_title.replace('&', '')} → {text}: {len(found)} entries"
    return found[0]


def click_menu_entry(qtbot, window, menu_title: str, text: str) -> QAction:
    """Open ``menu_title`` from the menu bar with the mouse and click its entry ``text``."""
    bar, menu = window.menuBar(), window.menus[menu_title]
    window.activateWindow()
    qtbot.waitUntil(lambda: QApplication.activeWindow() is window)
    qtbot.mouseClick(bar, Qt.MouseButton.LeftButton, pos=bar.actionGeometry(menu.menuAction()).center())
    qtbot.waitUntil(menu.isVisible)
    action = menu_entry(window, menu_title, text)
    qtbot.mouseClick(menu, Qt.MouseButton.LeftButton, pos=menu.actionGeometry(action).center())
    qtbot.waitUntil(lambda: not menu.isVisible())
    qtbot.wait(50)
    return action


def names_on_show(view) -> list[str]:
    """The entries of the first row of ``view`` whose face and name are both wholly on show."""
    visible = view.viewport().rect()
    top = view.visualItemRect(view.item(0)).top()
    first_row = [view.item(i) for i in range(view.count()) if view.visualItemRect(view.item(i)).top() <= top]
    shown = []
    for item in first_row:
        rect = view.visualItemRect(item)
        text_top = rect.top() + view.iconSize().height()
        name = QRect(rect.left(), text_top, rect.width(), view.fontMetrics().height() + 2)
        if visible.contains(rect.topLeft()) and visible.contains(name):
            shown.append(item.text())
    return shown


def on_show(window, widget) -> bool:
    return widget.isVisible() and widget.visibleRegion().boundingRect() == widget.rect() and \
        window.rect().contains(QRect(widget.mapTo(window, QPoint(0, 0)), widget.size()))


@pytest.mark.parametrize("layout_id, size", [("model", LAPTOP), ("animation", LAPTOP), ("library", LAPTOP),
                                             ("library", DESKTOP)],
                         ids=["model-1366x768", "animation-1366x768", "library-1366x768", "library-1600x1000"])
def test_every_face_in_the_gallery_has_its_name_on_show(make_window, qtbot, layout_id, size):
    window = make_window(DEFAULT_HEAD, size=(size.width(), size.height()))
    choose_layout(qtbot, window, layout_id)
    if not in_front(window, window.expression_gallery_dock):               # the Library layout shows it
        press(qtbot, window, Qt.Key.Key_G, CTRL)                            # Library → Expression gallery
    gallery = window.expression_gallery
    assert in_front(window, window.expression_gallery_dock)
    gallery.thumbnails.render_all()
    qtbot.wait(50)
    lists = {"Happy": gallery.expressions_list, "AU12_left": gallery.units_list}
    for name, view in lists.items():
        if getattr(gallery, "tabbed", False) and not view.isVisible():      # the other tab, clicked
            tabs = gallery.tabs
            index = 1 if view is gallery.units_list else 0
            qtbot.mouseClick(tabs, Qt.MouseButton.LeftButton, pos=tabs.tabRect(index).center())
            qtbot.wait(30)
        assert on_show(window, view), f"the list holding {name} is not on show"
        shown = names_on_show(view)
        assert len(shown) >= 3, f"{layout_id}: faces whose names are on show: {shown}"
        item = gallery.items[name]
        assert item.toolTip().startswith(f"{name}: ")                      # the whole name, however it is drawn
    if size == LAPTOP and layout_id == "library":
        assert getattr(gallery, "tabbed", False)                           # too low for both lists


def test_a_long_name_wraps_onto_a_second_line_under_its_face(window, qtbot, tmp_path):
    long_name = "VeryLongExpressionNameForTheLab"
    (tmp_path / f"{long_name}.lib").write_text(
        f"$command = {long_name}\n$mandatory = at\n$optional = amplitude=100, onset=200, apex=600, offset=300\n"
        "$interp = cosine\njaw_open = 0.5\n$proc = attack-hold-release\n")
    window.library_sources.set_folders([tmp_path])
    press(qtbot, window, Qt.Key.Key_G, CTRL)
    gallery = window.expression_gallery
    view = gallery.expressions_list
    item = gallery.items[long_name]
    view.scrollToItem(item)
    qtbot.wait(30)
    rect = view.visualItemRect(item)
    image = view.viewport().grab().toImage()
    line = view.fontMetrics().lineSpacing()
    text_top = rect.top() + view.iconSize().height()

    def ink(top: int, bottom: int) -> int:          # dark (text) pixels between these rows of the item
        return sum(1 for y in range(max(top, 0), min(bottom, image.height()))
                   for x in range(rect.left(), rect.right()) if image.pixelColor(x, y).lightness() < 110)

    assert ink(text_top, text_top + line + 3) > 20, "the name's first line"
    assert ink(text_top + line + 3, rect.bottom()) > 20, "the name goes on under the face, on a second line"
    assert item.toolTip().startswith(long_name)


def test_ctrl_g_shows_the_gallery_and_never_hides_it_the_view_entry_toggles_it(laptop_window, qtbot):
    window = laptop_window
    dock = window.expression_gallery_dock
    entry = menu_entry(window, "&View", "Expression gallery")
    assert entry.isCheckable() and not entry.isChecked() and dock.isHidden()
    press(qtbot, window, Qt.Key.Key_G, CTRL)
    assert in_front(window, dock) and entry.isChecked()
    press(qtbot, window, Qt.Key.Key_G, CTRL)                                # again: it stays
    assert in_front(window, dock) and entry.isChecked()
    window.script_dock.raise_()                                             # behind another tab …
    qtbot.wait(30)
    press(qtbot, window, Qt.Key.Key_G, CTRL)                                # … Ctrl+G brings it to the front
    assert in_front(window, dock)
    click_menu_entry(qtbot, window, "&View", "Expression gallery")          # the View entry closes it
    assert dock.isHidden() and not entry.isChecked()
    click_menu_entry(qtbot, window, "&View", "Expression gallery")          # and opens it
    assert in_front(window, dock) and entry.isChecked()
    library_entry = menu_entry(window, "&Library", "Expression gallery")
    assert library_entry.shortcut().toString() == "Ctrl+G" and not library_entry.isCheckable()


def test_the_view_menu_lists_every_dock_ticked_while_it_is_open(laptop_window, qtbot):
    window = laptop_window
    view_menu = window.menus["&View"]
    docks = [d for d in window.findChildren(QDockWidget) if d.objectName()]
    assert {"Script", "Expression gallery", "Library editor", "Marker coordinates", "Multistage PCA", "Identity",
            "Timeline", "Tool options", "Parameter tree", "Parameters"} <= {d.windowTitle() for d in docks}
    for dock in docks:
        entry = menu_entry(window, "&View", dock.windowTitle())
        assert entry in view_menu.actions() and entry.isCheckable() and entry.isEnabled(), dock.windowTitle()
        assert entry.isChecked() == dock.isVisible(), dock.windowTitle()
    script = window.script_dock
    click_menu_entry(qtbot, window, "&View", "Script")                      # open in the Model layout: closes
    assert script.isHidden() and not menu_entry(window, "&View", "Script").isChecked()
    click_menu_entry(qtbot, window, "&View", "Script")
    assert in_front(window, script) and menu_entry(window, "&View", "Script").isChecked()
    click_menu_entry(qtbot, window, "&View", "Library editor")
    assert in_front(window, window.library_editor_dock) and menu_entry(window, "&View", "Library editor").isChecked()
    window.library_editor_dock.close()                                      # its own close button: the tick goes
    qtbot.wait(30)
    assert not menu_entry(window, "&View", "Library editor").isChecked()
    press(qtbot, window, Qt.Key.Key_I, CTRL | SHIFT)                        # View → Identity's shortcut
    assert in_front(window, window.identity_dock) and menu_entry(window, "&View", "Identity").isChecked()
    click_menu_entry(qtbot, window, "&View", "Parameters")                  # cannot close: comes to the front
    assert in_front(window, window.parameter_dock) and menu_entry(window, "&View", "Parameters").isChecked()
