"""The player: one loaded animation (timeline, audio, phones) driven by the shared playhead.

The player owns playback. Loading sets the playhead's range (seconds) from
the timeline's last key and the audio's length; from then on **every**
playhead move — playing, scrubbing the ruler, a frame step, another tool's
``playhead.set_time`` — puts the pose of that time on the document:
``document.set_values(timeline.values_at(ms))`` for the parameters the
timeline drives, and only those. The engine works in milliseconds, the
playhead in seconds: time ``t`` s on the playhead is ``1000 t`` ms on the
timeline.

Playing advances the playhead in real time: a ~60 Hz timer reads a
monotonic clock (or, while sound is heard, the audio position), so a slow
frame is dropped instead of slowing the animation down. At the end the
player pauses on the last frame (or starts over when looping). ``stop``
goes back to 0 and puts the driven parameters back to their defaults.

>>> player = window.player                                          # doctest: +SKIP
>>> player.load(timeline, audio="hello.wav", phones=phones, title="Hello")   # doctest: +SKIP
>>> player.play()                                                   # doctest: +SKIP
>>> window.playhead.set_time(0.5)       # scrub: the pose of 500 ms  # doctest: +SKIP

Anything with ``values_at(ms) -> dict``, ``end`` (ms) and ``parameters``
plays; the parameters it drives are ``driven`` if it has that attribute,
else those its ``activations`` name (an engine Timeline), else all.
"""

from __future__ import annotations

import time as _time

from PySide6.QtCore import QObject, Qt, QTimer, Signal

from ..document.playhead import DEFAULT_FPS
from .audio_output import AudioClip, AudioOutput, load_clip

TICK_MS = 16
MIN_SPEED, MAX_SPEED = 0.25, 2.0


def driven_parameters(timeline) -> list[str]:
    """The parameters ``timeline`` moves, in its parameter order."""
    if timeline is None:
        return []
    driven = getattr(timeline, "driven", None)
    if driven is None:
        activations = getattr(timeline, "activations", None)
        if activations is None:
            return list(timeline.parameters)
        driven = {a.parameter for a in activations}
    driven = set(driven)
    return [name for name in timeline.parameters if name in driven]


class Player(QObject):
    """Plays one animation on ``document`` through ``playhead``.

    Signals: ``loaded()``, ``state_changed(str)`` (``"playing" | "paused" | "stopped"``),
    ``finished()`` (reached the end, not looping), ``loop_changed(bool)``, ``speed_changed(float)``.
    """

    loaded = Signal()
    state_changed = Signal(str)
    finished = Signal()
    loop_changed = Signal(bool)
    speed_changed = Signal(float)

    def __init__(self, document, playhead, parent: QObject | None = None):
        super().__init__(parent)
        self.document = document
        self.playhead = playhead
        self._timeline = None
        self._driven: list[str] = []
        self._clip: AudioClip | None = None
        self._audio_source = None
        self._phones: list = []
        self._title = ""
        self._state = "stopped"
        self._loop = False
        self._speed = 1.0
        self._anchor_wall = 0.0             # monotonic clock at the last (re)start
        self._anchor_time = 0.0             # playhead time then
        self._advancing = False             # the playhead move is ours (not a scrub)
        self.output = AudioOutput()
        self._sound_on = False
        self._timer = QTimer(self)
        self._timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._timer.setInterval(TICK_MS)
        self._timer.timeout.connect(self._tick)
        playhead.time_changed.connect(self._on_time_changed)
        document.model_replaced.connect(self._on_model_replaced)

    # -- what is loaded ----------------------------------------------------
    @property
    def timeline(self):
        return self._timeline

    @property
    def audio(self):
        """The audio as given to :meth:`load` (a path), or ``None``."""
        return self._audio_source

    @property
    def clip(self) -> AudioClip | None:
        return self._clip

    @property
    def phones(self) -> list:
        return self._phones

    @property
    def title(self) -> str:
        return self._title

    @property
    def driven(self) -> list[str]:
        """The parameters the loaded timeline sets."""
        return list(self._driven)

    @property
    def duration(self) -> float:
        """Seconds: the later of the timeline's last key and the audio's end."""
        ends = [0.0]
        if self._timeline is not None:
            ends.append(float(self._timeline.end) / 1000.0)
        if self._clip is not None:
            ends.append(self._clip.duration)
        return max(ends)

    @property
    def state(self) -> str:
        return self._state

    @property
    def is_playing(self) -> bool:
        return self._state == "playing"

    @property
    def loop(self) -> bool:
        return self._loop

    def set_loop(self, loop: bool) -> None:
        loop = bool(loop)
        if loop != self._loop:
            self._loop = loop
            self.loop_changed.emit(loop)

    @property
    def speed(self) -> float:
        return self._speed

    def set_speed(self, speed: float) -> None:
        """Playback speed, 0.25× … 2× (sound plays only at 1×)."""
        speed = min(MAX_SPEED, max(MIN_SPEED, float(speed)))
        if speed == self._speed:
            return
        self._speed = speed
        if self.is_playing:
            self._restart_clock(self.playhead.time)
        self.speed_changed.emit(speed)

    @property
    def sound_on(self) -> bool:
        """Whether sound is coming out now (False where there is no output device)."""
        return self._sound_on and self.output.is_playing

    def load(self, timeline, *, audio=None, phones=None, title: str = "", fps: float = DEFAULT_FPS) -> None:
        """Load an animation: a timeline (or ``None`` for audio only), a WAV, phone segments.

        Reads the audio first, so a bad WAV raises (a :class:`~engine.errors.UserError`)
        and changes nothing.
        """
        clip = load_clip(audio) if audio is not None else None
        self.stop()
        self._timeline = timeline
        self._driven = driven_parameters(timeline)
        self._clip = clip
        self._audio_source = audio
        self._phones = list(phones or [])
        self._title = title
        self.playhead.set_range(self.duration, fps)
        self.playhead.set_time(0.0)
        self._apply_pose(0.0)
        self.loaded.emit()

    def unload(self) -> None:
        """Forget the animation (the driven parameters go back to their defaults)."""
        self.load(None)

    # -- transport ---------------------------------------------------------
    def play(self) -> None:
        if self.is_playing or self.duration <= 0:
            return
        if self.playhead.time >= self.playhead.duration:
            self._move_to(0.0)
        self._restart_clock(self.playhead.time)
        self._timer.start()
        self._set_state("playing")

    def pause(self) -> None:
        if not self.is_playing:
            return
        self._timer.stop()
        self._stop_sound()
        self._set_state("paused")

    def stop(self) -> None:
        """Stop, go back to 0 and put the driven parameters back to their defaults."""
        self._timer.stop()
        self._stop_sound()
        self._move_to(0.0)
        self._reset_pose()
        self._set_state("stopped")

    def toggle(self) -> None:
        self.pause() if self.is_playing else self.play()

    def step(self, frames: int) -> None:
        """Move ``frames`` frames (negative: back), pausing first."""
        self.pause()
        self.playhead.set_frame(self.playhead.frame + int(frames))

    # -- internals ---------------------------------------------------------
    def _set_state(self, state: str) -> None:
        if state != self._state:
            self._state = state
            self.state_changed.emit(state)

    def _restart_clock(self, at: float) -> None:
        self._anchor_wall = _time.monotonic()
        self._anchor_time = at
        self._stop_sound()
        if self._clip is not None and self._speed == 1.0 and at < self._clip.duration:
            self._sound_on = self.output.start(self._clip, at)

    def _stop_sound(self) -> None:
        if self._sound_on:
            self.output.stop()
        self._sound_on = False

    def _clock(self) -> float:
        if self._sound_on:
            heard = self.output.position()
            if heard is not None:
                return max(heard, self.playhead.time)      # never back
            # The clip ended (the animation may go on): continue from the clip's end.
            self._sound_on = False
            self._anchor_wall = _time.monotonic()
            self._anchor_time = max(self.playhead.time, self._clip.duration if self._clip else 0.0)
        return self._anchor_time + (_time.monotonic() - self._anchor_wall) * self._speed

    def _tick(self) -> None:
        now = self._clock()
        end = self.playhead.duration
        if now < end:
            self._move_to(now)
            return
        if self._loop and end > 0:
            self._move_to(0.0)
            self._restart_clock(0.0)
            return
        self._move_to(end)
        self._timer.stop()
        self._stop_sound()
        self._set_state("paused")
        self.finished.emit()

    def _move_to(self, seconds: float) -> None:
        self._advancing = True
        try:
            self.playhead.set_time(seconds)
        finally:
            self._advancing = False

    def _on_time_changed(self, seconds: float) -> None:
        self._apply_pose(seconds)
        if self.is_playing and not self._advancing:      # a scrub while playing: go on from there
            self._restart_clock(seconds)

    def _apply_pose(self, seconds: float) -> None:
        if self._timeline is None or not self._driven:
            return
        values = self._timeline.values_at(seconds * 1000.0)
        tree = self.document.model.parameters
        pose = {}
        for name in self._driven:
            if name in tree.names:
                parameter = tree[name]
                pose[name] = min(parameter.maximum, max(parameter.minimum, float(values[name])))
        self.document.set_values(pose)

    def _reset_pose(self) -> None:
        tree = self.document.model.parameters
        names = tree.names
        self.document.set_values({name: tree[name].default for name in self._driven if name in names})

    def _on_model_replaced(self, _model) -> None:
        # Another model: its parameters may differ; keep the animation, drop what no longer exists.
        self._timer.stop()
        self._stop_sound()
        self._set_state("stopped")
        self._move_to(0.0)
        self._apply_pose(0.0)
