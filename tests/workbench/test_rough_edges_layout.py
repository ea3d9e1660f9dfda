"""Issue 30 §4: a layout must not keep a dock squeezed (Tool options at 3 rows after the Identity dock was
opened once), neither while the window is open nor in the layout it remembers for the next start.

The window is the laptop-sized one of ``test_task_layouts.py`` on the default head, driven with the keys a
user presses (View → Identity's Ctrl+Shift+I) and the separator drag a user makes.
"""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSettings, Qt

import engine
from tests.workbench.test_rough_edges_gallery import CTRL, SHIFT, choose_layout, press
from tests.workbench.test_task_layouts import LAPTOP, in_front
from workbench import settings
from workbench.window.layouts import STATE_VERSION

DEFAULT_HEAD = engine.default_model_path()
pytestmark = pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="the default head is not built")
LAPTOP_SIZE = (LAPTOP.width(), LAPTOP.height())
USEFUL = 150     # px of Tool options' page on show: the parameter's title and four rows of its properties


def tool_options_room(window) -> int:
    """How much of the Tool options page is on show (the height of its scroll area's viewport)."""
    return window.tool_options.stack.currentWidget().viewport().height()


def laptop(make_window, qtbot, size=LAPTOP_SIZE):
    window = make_window(DEFAULT_HEAD, size=size)
    window.view_state.select_parameter("jaw_open")            # its properties in Tool options
    qtbot.wait(50)                                            # the docks laid out as the layout has them
    return window


def test_opening_the_identity_dock_leaves_tool_options_of_use_now_and_at_the_next_start(make_window, qtbot):
    window = laptop(make_window, qtbot)
    assert tool_options_room(window) >= USEFUL
    press(qtbot, window, Qt.Key.Key_I, CTRL | SHIFT)                     # View → Identity
    qtbot.waitUntil(lambda: window.identity_panel.built)
    assert in_front(window, window.identity_dock)
    assert tool_options_room(window) >= USEFUL, "opening Identity squeezed Tool options"
    press(qtbot, window, Qt.Key.Key_I, CTRL | SHIFT)                     # and closed again
    assert window.identity_dock.isHidden()
    assert tool_options_room(window) >= USEFUL
    assert window.close()

    again = laptop(make_window, qtbot, size=None)                              # the next start, as remembered
    qtbot.wait(50)
    assert again.layouts.current == "model"
    assert tool_options_room(again) >= USEFUL, "the remembered layout keeps Tool options squeezed"


def test_a_layout_remembered_with_a_squeezed_dock_is_restored_with_room_for_it(make_window, qtbot):
    window = laptop(make_window, qtbot)
    window.resizeDocks([window.tool_options], [1], Qt.Orientation.Vertical)   # as a layout stored before
    qtbot.waitUntil(lambda: tool_options_room(window) < USEFUL - 40)
    squeezed = bytes(window.saveState(STATE_VERSION))
    assert window.close()
    QSettings().setValue(settings.layout_key("model"), squeezed)        # what that older session left
    QSettings().setValue(settings.WINDOW_LAYOUT, "model")

    again = laptop(make_window, qtbot, size=None)
    qtbot.waitUntil(lambda: tool_options_room(again) >= USEFUL)         # put right once the docks are laid out
    choose_layout(qtbot, again, "painting")                             # leaving the layout stores it put right
    choose_layout(qtbot, again, "model")
    qtbot.wait(50)
    assert tool_options_room(again) >= USEFUL
    assert bytes(QSettings().value(settings.layout_key("model"))) != squeezed


def test_a_dock_dragged_small_is_not_stored_squeezed(make_window, qtbot):
    window = laptop(make_window, qtbot)
    window.resizeDocks([window.tool_options], [1], Qt.Orientation.Vertical)   # the user drags the separator
    qtbot.waitUntil(lambda: tool_options_room(window) < USEFUL - 40)
    choose_layout(qtbot, window, "painting")                           # leaving it remembers it, given room
    stored = bytes(QSettings().value(settings.layout_key("model")))
    assert window.restoreState(stored, STATE_VERSION)
    window.layout().activate()
    qtbot.wait(50)
    assert window.tool_options.height() >= USEFUL
