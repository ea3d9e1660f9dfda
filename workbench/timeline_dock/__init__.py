"""The timeline dock and the player: play, scrub and look at an animation.

``install(window)`` creates :attr:`window.player <workbench.playback.player.Player>`
(first: other tools play through it), the "Timeline" dock at the bottom
(``window.timeline_dock``) and the "&Animation" menu with *Open animation…*
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
from ..playback.player import Player
from ..window.actions import ActionSpec, add_actions
from .dock import TimelineDock

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


def install(window: MainWindow) -> None:
    """Add the player, the timeline dock and the Animation menu to ``window``."""
    window.player = Player(window.document, window.playhead, window)
    actions = add_actions(window, ANIMATION_ACTIONS)
    dock = TimelineDock(window.player, window.view_state, actions, window)
    dock.open_animation = lambda path: open_animation(window, path)
    window.timeline_dock = dock
    window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, dock)
    window.menus["&View"].addAction(dock.toggleViewAction())


def open_animation(window: MainWindow, path: str | Path) -> bool:
    """Load ``path`` into the player and show its first frame; a bad file → a dialog, nothing changes."""
    try:
        animation = load_animation(path, window.document.model, settings.library_folders(), fps=DEFAULT_FPS)
    except UserError as error:
        QMessageBox.warning(window, "Open animation", f"Cannot open this animation:\n\n{error}")
        return False
    window.player.load(animation.timeline, title=animation.title, fps=animation.fps)
    window.timeline_dock.show()
    count = len(window.player.driven)
    window.statusBar().showMessage(f"Animation {animation.title}: {count} parameter{'s' * (count != 1)}, "
                                   f"{window.playhead.duration:.3f} s — Space plays", MESSAGE_MS)
    return True


def open_animation_dialog(window: MainWindow) -> bool:
    store = QSettings()
    path, _ = QFileDialog.getOpenFileName(window, "Open animation", str(store.value(settings.LAST_DIR, "")),
                                          FILE_FILTER)
    if not path:
        return False
    store.setValue(settings.LAST_DIR, str(Path(path).parent))
    return open_animation(window, path)
