"""Stopping a fit part-way: its long loops ask ``should_stop()`` and end with :class:`FitStopped`.

A front end that runs :func:`engine.photofit.fit_photos` on a worker thread
passes ``should_stop`` (a callable answering whether the user pressed Stop);
the fit asks it between its steps and inside every loop that runs longer
than a few tens of milliseconds, so a stopped fit ends promptly instead of
finishing the step it is in. ``None`` means the fit is never stopped.

>>> stop_if_asked(None)
>>> stop_if_asked(lambda: False)
>>> stop_if_asked(lambda: True)
Traceback (most recent call last):
    ...
engine.photofit.stopping.FitStopped: the fit was stopped
"""

from __future__ import annotations

from collections.abc import Callable

#: Answers whether the fit should end now; ``None``: never.
ShouldStop = Callable[[], bool] | None


class FitStopped(Exception):
    """The fit ended early because its ``should_stop`` said so; nothing of it is returned."""


def stop_if_asked(should_stop: ShouldStop) -> None:
    """Raise :class:`FitStopped` when ``should_stop`` answers ``True``."""
    if should_stop is not None and should_stop():
        raise FitStopped("the fit was stopped")
