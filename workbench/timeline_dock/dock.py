"""The "Timeline" dock: transport controls over the track view.

Controls, left to right: play/pause, stop, one frame back, one frame
forward, loop, playback speed (0.25×–2×), and the time and frame now. The
buttons carry the Animation menu's actions, so they share shortcuts and
state (Space, Left, Right — active while the dock has the keyboard focus).
The row wraps in a narrow dock (the frame and the rate go onto a second
line) instead of cutting its text; the two readouts are as wide as their
longest text for what is loaded, so playing does not reflow them.
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import (
    QComboBox,
    QDockWidget,
    QHBoxLayout,
    QLabel,
    QScrollArea,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from ..flow_layout import FlowLayout
from ..icons import icon
from .track_view import TrackView

SPEEDS = (0.25, 0.5, 0.75, 1.0, 1.5, 2.0)
DOCK_NAME = "dock:timeline"


class TimelineDock(QDockWidget):
    """Transport row + :class:`TrackView` in a vertical scroll area."""

    def __init__(self, player, view_state, actions: dict[str, QAction], parent: QWidget | None = None):
        super().__init__("Timeline", parent)
        self.setObjectName(DOCK_NAME)
        self.player = player
        self.playhead = player.playhead
        self.animation_actions = actions
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 2, 4, 4)
        layout.setSpacing(2)

        transport = QWidget(body)
        controls = QHBoxLayout(transport)
        controls.setContentsMargins(0, 0, 0, 0)
        controls.setSpacing(2)
        self.buttons: dict[str, QToolButton] = {}
        for action_id in ("animation.play_pause", "animation.stop", "animation.step_back",
                          "animation.step_forward", "animation.loop"):
            button = QToolButton(body)
            button.setDefaultAction(actions[action_id])
            button.setAutoRaise(True)
            button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
            controls.addWidget(button)
            self.buttons[action_id] = button
        self.speed_box = QComboBox(body)
        self.speed_box.setToolTip("Playback speed (sound plays at 1× only)")
        self.speed_box.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        for speed in SPEEDS:
            self.speed_box.addItem(f"{speed:g}×", speed)
        self.speed_box.setCurrentIndex(SPEEDS.index(1.0))
        self.speed_box.currentIndexChanged.connect(lambda i: player.set_speed(self.speed_box.itemData(i)))
        player.speed_changed.connect(self._show_speed)
        controls.addSpacing(8)
        controls.addWidget(self.speed_box)
        self.time_label = QLabel(body)              # "0.900 / 2.944 s"
        self.frame_label = QLabel(body)             # "frame 54 / 177 at 60 fps"
        row = FlowLayout(spacing=10)
        row.addWidget(transport)
        for label in (self.time_label, self.frame_label):
            label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
            row.addWidget(label)
        layout.addLayout(row)

        self.track_view = TrackView(player, view_state, body)
        self.scroll = QScrollArea(body)
        self.scroll.setWidgetResizable(True)
        self.scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.scroll.setWidget(self.track_view)
        self.scroll.setFocusProxy(self.track_view)
        layout.addWidget(self.scroll, 1)
        self.setWidget(body)
        self.setFocusProxy(self.track_view)

        for action_id in ("animation.play_pause", "animation.stop", "animation.step_back", "animation.step_forward"):
            action = actions[action_id]
            action.setShortcutContext(Qt.ShortcutContext.WidgetWithChildrenShortcut)
            self.addAction(action)
        player.state_changed.connect(self._show_state)
        player.loop_changed.connect(actions["animation.loop"].setChecked)
        self.playhead.time_changed.connect(self._show_time)
        self.playhead.range_changed.connect(self._fit_readouts)
        player.loaded.connect(self._on_loaded)
        self._on_loaded()

    def _on_loaded(self) -> None:
        self._fit_readouts()
        self._show_state(self.player.state)
        loaded = self.playhead.duration > 0
        for action_id in ("animation.play_pause", "animation.stop", "animation.step_back", "animation.step_forward"):
            self.animation_actions[action_id].setEnabled(loaded)

    def _show_state(self, state: str) -> None:
        action = self.animation_actions["animation.play_pause"]
        playing = state == "playing"
        action.setIcon(icon("pause" if playing else "play"))
        action.setText("&Pause" if playing else "&Play")
        action.setToolTip("Pause (Space)" if playing else "Play (Space)")

    def _show_speed(self, speed: float) -> None:
        index = self.speed_box.findData(speed)
        if index >= 0:
            self.speed_box.setCurrentIndex(index)

    def _readouts(self, time: float, frame: int) -> tuple[str, str]:
        playhead = self.playhead
        return (f"{time:.3f} / {playhead.duration:.3f} s",
                f"frame {frame} / {playhead.n_frames - 1} at {playhead.fps:g} fps")

    def _fit_readouts(self, *_args) -> None:
        """Each readout as wide as its longest text for this duration and rate (the end's)."""
        widest = self._readouts(self.playhead.duration, self.playhead.n_frames - 1)
        for label, text in zip((self.time_label, self.frame_label), widest, strict=True):
            label.setMinimumWidth(label.fontMetrics().horizontalAdvance(text) + 4)
        self._show_time()

    def _show_time(self, *_args) -> None:
        time_text, frame_text = self._readouts(self.playhead.time, self.playhead.frame)
        self.time_label.setText(time_text)
        self.frame_label.setText(frame_text)
