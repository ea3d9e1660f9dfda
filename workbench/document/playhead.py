"""The current time of the animation shown, shared by every time-based view.

The timeline dock moves it (play, scrub, frame step); the marker view, the
parameter sliders and anything else that shows "the frame now" listen to
:attr:`Playhead.time_changed`. Times are seconds (the GUI's clock; files and the command line use ms), the
frame rate is the one of whatever is loaded (60 fps by default).
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Signal

DEFAULT_FPS = 60.0


class Playhead(QObject):
    """A time in seconds within ``[0, duration]`` and a frame rate.

    Signals
    -------
    time_changed(float)
        The playhead moved to this time (s).
    range_changed(float, float)
        New duration (s) and frame rate (fps).
    """

    time_changed = Signal(float)
    range_changed = Signal(float, float)

    def __init__(self, parent: QObject | None = None):
        super().__init__(parent)
        self._time = 0.0
        self._duration = 0.0
        self._fps = DEFAULT_FPS

    @property
    def time(self) -> float:
        return self._time

    @property
    def duration(self) -> float:
        return self._duration

    @property
    def fps(self) -> float:
        return self._fps

    @property
    def frame(self) -> int:
        """The frame at the current time (frame ``k`` is at ``k / fps`` s)."""
        return round(self._time * self._fps)

    @property
    def n_frames(self) -> int:
        return round(self._duration * self._fps) + 1

    def set_range(self, duration: float, fps: float = DEFAULT_FPS) -> None:
        """Set the length (s) and frame rate of what is loaded; clamps the time into it."""
        if fps <= 0:
            raise ValueError(f"frame rate must be positive, not {fps}")
        self._duration = max(0.0, float(duration))
        self._fps = float(fps)
        self.range_changed.emit(self._duration, self._fps)
        if self._time > self._duration:
            self.set_time(self._duration)

    def set_time(self, seconds: float) -> None:
        """Move to ``seconds`` (clamped to ``[0, duration]``); emits only on a real move."""
        t = min(max(0.0, float(seconds)), self._duration)
        if t != self._time:
            self._time = t
            self.time_changed.emit(t)

    def set_frame(self, frame: int) -> None:
        self.set_time(frame / self._fps)
