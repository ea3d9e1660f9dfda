"""The timeline dock and the player: play, scrub and look at an animation (issue 8).

``install(window)`` creates :attr:`window.player <workbench.player.Player>`
(first, other tools play through it), the "Timeline" dock at the bottom and
the "&Animation" menu. See ``docs/workbench-timeline.md``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..player import Player

if TYPE_CHECKING:
    from ..main_window import MainWindow


def install(window: "MainWindow") -> None:
    """Add the player, the timeline dock and the Animation menu to ``window``."""
    window.player = Player(window.document, window.playhead, window)
