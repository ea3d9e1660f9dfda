"""How long, how fine and how many: the bounds every command, timeline and sampling stays inside.

A command file or an option can ask for anything a float can hold
(``at="1e308"``, ``count="1e9"``, ``--fps 1e308``); without bounds that is an
overflow, an array of petabytes or a loop that never ends. These limits are
far beyond any real animation and are checked before anything is built, so
bad input ends with one error naming the file and line (``docs/robustness.md``).

>>> check_time(1000.0, "at")
1000.0
>>> check_time(1e308, "at")
Traceback (most recent call last):
engine.commands.limits.LimitProblem: at = 1e+308 ms is beyond the longest timeline, ±86400000 ms (24 hours)
"""

from __future__ import annotations

import math

MAX_TIME_MS = 24 * 3600 * 1000.0
"""Every key time, ``at``, ``end`` and duration lies within ±24 hours."""
MAX_FPS = 1000.0
"""Frames per second when sampling (a camera at 1000 fps is already a high-speed one)."""
MAX_FRAMES = 5_000_000
"""Frames sampled at once: 23 hours at 60 fps, 83 minutes at 1000 fps."""
MAX_VALUE = 1e6
"""Every key value lies within ±10⁶ parameter units (parameter ranges are a few units or degrees); larger
ones overflow when interpolated and summed."""
MAX_KEYS = 1_000_000
"""Keys one command may expand to (a periodic command of a million repetitions is a mistake)."""


class LimitProblem(ValueError):
    """A number beyond the limits of this module (callers add the file and line)."""


def check_time(value: float, what: str) -> float:
    """``value`` (ms) if it is finite and within :data:`MAX_TIME_MS` of 0."""
    if not (math.isfinite(value) and abs(value) <= MAX_TIME_MS):
        raise LimitProblem(f"{what} = {value:g} ms is beyond the longest timeline, ±{MAX_TIME_MS:.0f} ms (24 hours)")
    return value


def check_value(value: float, what: str) -> float:
    """``value`` (parameter units) if it is finite and within :data:`MAX_VALUE` of 0."""
    if not (math.isfinite(value) and abs(value) <= MAX_VALUE):
        raise LimitProblem(f"{what} = {value:g} is beyond ±{MAX_VALUE:g} parameter units")
    return value


def check_fps(fps: float) -> float:
    """``fps`` if it is a finite number in (0, :data:`MAX_FPS`]."""
    if not (math.isfinite(fps) and 0 < fps <= MAX_FPS):
        raise LimitProblem(f"frames per second must be a positive number, at most {MAX_FPS:g} (got {fps:g})")
    return fps


def frame_count(start: float, end: float, fps: float) -> int:
    """How many frames ``start, start + 1000/fps, …`` fit up to ``end`` (ms), checked against :data:`MAX_FRAMES`.

    >>> frame_count(0.0, 2000.0, 60.0)
    121
    """
    check_time(start, "the start time")
    check_time(end, "the end time")
    check_fps(fps)
    if end < start:
        raise LimitProblem(f"the end time {end:g} ms comes before the start time {start:g} ms")
    count = math.floor((end - start) * fps / 1000.0 + 1e-9) + 1
    if count > MAX_FRAMES:
        raise LimitProblem(f"{count} frames from {start:g} to {end:g} ms at {fps:g} fps are more than "
                           f"{MAX_FRAMES} (sample a shorter span or at fewer frames per second)")
    return count


def check_key_count(count: float, what: str) -> None:
    """Refuse an expansion to more than :data:`MAX_KEYS` keys before it is built."""
    if not count <= MAX_KEYS:
        raise LimitProblem(f"{what} would make {count:g} keys, more than {MAX_KEYS} in one command")
