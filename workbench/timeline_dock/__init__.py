"""The timeline dock and the player: play, scrub and look at an animation.

``install(context)`` adds the "Timeline" dock at the bottom (``window.timeline_dock``)
over the context's :attr:`~workbench.tools.ToolContext.player` (the window's, shared by
every tool that plays) and the "&Animation" menu with *Open animation…*
(a command file or a tracks CSV), play/pause, stop, frame steps and loop.
See ``docs/workbench-timeline.md``.

>>> window.timeline_dock.open_animation("nod.xml")     # doctest: +SKIP
True
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QFileDialog, QMessageBox

from engine.errors import UserError
from engine.timeline.animation_files import load_animation

from .. import settings
from ..document.playhead import DEFAULT_FPS
from ..tools import ToolContext
from ..window.actions import ActionSpec
from .dock import DOCK_NAME, TimelineDock

if TYPE_CHECKING:
    from ..window.main_window import MainWindow

MENU = "&Animation"
FILE_FILTER = "Animations (*.xml *.csv);;Command files (*.xml);;Tracks tables (*.csv);;All files (*)"
MESSAGE_MS = 4000

ANIMATION_ACTIONS: tuple[ActionSpec, ...] = (
    # PLW0108 below: the lambda defers the look-up, open_animation_dialog is defined further down
    ActionSpec("animation.open", "&Open animation…", MENU, triggered=lambda w: open_animation_dialog(w),  # noqa: PLW0108
               shortcut="Ctrl+Shift+O", icon="open-animation", toolbar=True, separator_before=True,
               tip="Play a command file (.xml, high or low level) or a tracks table (.csv)"),
    ActionSpec("animation.play_pause", "&Play", MENU, triggered=lambda w: w.player.toggle(),
               shortcut="Space", icon="play", separator_before=True, tip="Play (Space)"),
    ActionSpec("animation.stop", "&Stop", MENU, triggered=lambda w: w.player.stop(), icon="stop",
               tip="Stop and go back to the start; the animated parameters go back to their defaults"),
    ActionSpec("animation.step_back", "Step &back", MENU, triggered=lambda w: w.player.step(-1),
               shortcut="Left", icon="step-back", tip="One frame back (Left)"),
    ActionSpec("animation.step_forward", "Step &forward", MENU, triggered=lambda w: w.player.step(1),
               shortcut="Right", icon="step-forward", tip="One frame forward (Right)"),
    ActionSpec("animation.loop", "&Loop", MENU, toggled=lambda w, on: w.player.set_loop(on), icon="loop",
               tip="Start over at the end"),
)


def install(context: ToolContext) -> None:
    """Add the timeline dock and the Animation menu to the context's window."""
    window = context.window
    actions = context.add_actions(ANIMATION_ACTIONS)
    dock = TimelineDock(context.player, context.view_state, actions, window)
    dock.open_animation = lambda path: open_animation(context, path)
    window.timeline_dock = dock
    window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, dock)
    context.menus["&View"].addAction(dock.toggleViewAction())


def open_animation(context: ToolContext, path: str | Path) -> bool:
    """Load ``path`` into the player and show its first frame; a bad file → a dialog, nothing changes."""
    try:
        animation = load_animation(path, context.document.model, settings.library_folders(), fps=DEFAULT_FPS)
    except UserError as error:
        QMessageBox.warning(context.window, "Open animation", f"Cannot open this animation:\n\n{error}")
        return False
    context.player.load(animation.timeline, title=animation.title, fps=animation.fps)
    context.show_dock(DOCK_NAME)
    count = len(context.player.driven)
    context.status.showMessage(f"Animation {animation.title}: {count} parameter{'s' * (count != 1)}, "
                               f"{context.playhead.duration:.3f} s — Space plays", MESSAGE_MS)
    return True


def open_animation_dialog(window: MainWindow) -> bool:
    """Animation → Open animation…: a file dialog, then :func:`open_animation`."""
    store = QSettings()
    path, _ = QFileDialog.getOpenFileName(window, "Open animation", str(store.value(settings.LAST_DIR, "")),
                                          FILE_FILTER)
    if not path:
        return False
    store.setValue(settings.LAST_DIR, str(Path(path).parent))
    return open_animation(window.tools, path)
