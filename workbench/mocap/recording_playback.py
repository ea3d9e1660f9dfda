"""The capture session on the window's player: the markers show while their recording is what plays.

The player and its playhead are shared: a library-editor or gallery preview
and the script panel's speech load their own animation into it. Markers that
followed the playhead through someone else's animation would float beside a
face moving by another clock, so the session is played like any animation:
importing or opening one loads it into the player as a
:class:`RecordingTimeline` (it drives no parameter; its length, frame rate
and phones are the recording's). Space then plays the markers in real time
and the timeline scrubs them; when another animation takes the player the
markers are put away (:meth:`MarkerOverlay.set_active`) and a PCA component
animation stops.

They come back when the user turns to the session again — Motion capture ▸
*Show the recording*, a click or drag on the marker plot, *Show the session*
or a component shown in the PCA dock — which loads the recording back.

Once the components are on the face (*Apply to model*), the recording also
drives them: every frame's markers fitted by the components, as
``artificial-person mocap animate`` fits them
(:func:`engine.mocap.animate.session_component_values`), so Space plays the
markers and the face together and the timeline shows the component tracks.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from PySide6.QtCore import QObject

from engine.speech.synthesis import Segment


class RecordingTimeline:
    """A capture session as the player plays it: ``end`` (ms) is its last frame.

    Without ``names`` it sets no parameter (only the markers move). With the
    applied components' ``names`` and their ``values`` (frames × names) it
    drives them, linearly between frames.
    """

    def __init__(self, session, names: tuple[str, ...] = (), values: np.ndarray | None = None):
        self.session = session
        self.end = 1000.0 * (session.n_frames - 1) / session.rate_hz
        self.parameters: tuple[str, ...] = tuple(names)
        self.driven: tuple[str, ...] = tuple(names)
        self._times = np.arange(session.n_frames) * (1000.0 / session.rate_hz)
        self._values = np.zeros((session.n_frames, 0)) if values is None else np.asarray(values, dtype=float)

    def values_at(self, ms: float) -> dict[str, float]:
        return {name: float(np.interp(ms, self._times, self._values[:, k])) for k, name in enumerate(self.driven)}

    def sample(self, times_ms) -> np.ndarray:
        """(T, driven): the driven parameters' values at ``times_ms``."""
        times = np.asarray(times_ms, dtype=float)
        return np.column_stack([np.interp(times, self._times, self._values[:, k]) for k in range(len(self.driven))]
                               ) if self.driven else np.zeros((len(times), 0))


def session_title(session) -> str:
    return f"Capture {Path(session.source).name}" if session.source else "Capture session"


class RecordingPlayback(QObject):
    """Keeps the open session on ``tool.context.player`` while the user works with it, its markers with it.

    ``tool`` is the :class:`~workbench.mocap.MocapTool`: its state (the session),
    its marker overlay, the marker plot and the PCA dock, whose gestures turn
    the user back to the recording.
    """

    def __init__(self, tool):
        super().__init__(tool)
        self.state = tool.state
        self.player = tool.context.player
        self.overlay = tool.overlay
        self.pca_dock = tool.pca_dock
        self.plot_dock = tool.plot_dock
        self.timeline: RecordingTimeline | None = None
        self._drive: tuple[object, tuple[str, ...], np.ndarray] | None = None   # (session, names, values)
        self.player.loaded.connect(self._on_player_loaded)
        self.state.phones_changed.connect(self._on_phones_changed)
        tool.plot_dock.plot.frame_clicked.connect(self.show_frame)
        tool.plot_dock.plot.range_dragged.connect(self._on_range_dragged)
        self.pca_dock.show_session_button.clicked.connect(self.show_session)
        self.pca_dock.preview_changed.connect(self._on_preview)
        self.pca_dock.recording_fitted.connect(self.drive)

    @property
    def on_player(self) -> bool:
        """Whether the player plays the open session now (and its markers are drawn)."""
        return self.timeline is not None and self.player.timeline is self.timeline

    def show_session(self) -> None:
        """Put the open session on the player (from its start) unless it is there already."""
        session = self.state.session
        if session is None:
            if self.on_player:
                self.player.unload()
            self.timeline = None
            return
        if self.timeline is None or self.timeline.session is not session:
            self.timeline = self._timeline_for(session)
        if not self.on_player:
            self._load()

    def drive(self, fitted) -> None:
        """The applied components' ``(names, values)`` for the open session: the recording now moves the face
        as well as the markers, and is put on the player."""
        session = self.state.session
        if session is None:
            return
        names, values = fitted
        self._drive = (session, tuple(names), np.asarray(values, dtype=float))
        at = self.player.playhead.time if self.on_player else 0.0
        self.timeline = self._timeline_for(session)
        self._load(at=at)

    def _timeline_for(self, session) -> RecordingTimeline:
        if self._drive is not None and self._drive[0] is session:
            return RecordingTimeline(session, self._drive[1], self._drive[2])
        return RecordingTimeline(session)

    def show_frame(self, frame: int) -> None:
        """The session on the player, the playhead on ``frame`` (a frame picked on the marker plot)."""
        if self.state.session is None or self.on_player:
            return                          # the plot has moved the playhead itself
        self.show_session()
        self.player.playhead.set_frame(frame)

    # -- internals ---------------------------------------------------------------------
    def _load(self, at: float = 0.0) -> None:
        session = self.timeline.session
        phones = [Segment(label, start, end) for start, end, label in session.phones]
        self.player.load(self.timeline, phones=phones, title=session_title(session), fps=session.rate_hz)
        if at:
            self.player.playhead.set_time(at)

    def _on_player_loaded(self) -> None:
        mine = self.on_player
        self.overlay.set_active(mine)
        self.plot_dock.playhead_is_recording = mine
        self.plot_dock.plot.set_playhead(self.player.playhead.time if mine else None)
        if not mine:
            self.pca_dock.animate_button.setChecked(False)     # its timer would take the player back

    def _on_phones_changed(self) -> None:
        if self.on_player:                  # the timeline's phone row shows the new labels
            self._load(at=self.player.playhead.time)

    def _on_range_dragged(self, _first: int, last: int) -> None:
        self.show_frame(last)

    def _on_preview(self, preview) -> None:
        if preview is not None:             # a component shown: the user is looking at the session
            self.show_session()
