"""A local worker is one core: it, and the Festival, ffmpeg and decoder processes it starts, run on a core of its own.

``stimuli --workers N`` makes N stimuli at a time on N cores of this computer
(CPU affinity, Linux); the other cores stay free for whatever else runs there.
A stimulus alone uses more than one core when it can (its video's second
renderer, :mod:`engine.outputs.render_helper`; ffmpeg encoding and the checks'
decoders beside the drawing), so without this a worker spreads over one and a
half cores and N workers over an unknown number. Where the system has no CPU
affinity (macOS, Windows) workers are not kept to a core.

>>> with kept_to_core(available_cores()[0]):
...     len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else 1
1
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager

from engine.outputs.render_helper import ENVIRONMENT


def available_cores() -> list[int]:
    """The cores this process may run on (all of the computer's where the system does not say)."""
    if hasattr(os, "sched_getaffinity"):
        return sorted(os.sched_getaffinity(0))
    return list(range(os.cpu_count() or 1))


def keep_to_core(core: int) -> None:
    """From now on this process, and every process it starts, runs on ``core`` only, drawing alone."""
    os.environ[ENVIRONMENT] = "1"                     # no second renderer: it would only share the core
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {core})


@contextmanager
def kept_to_core(core: int) -> Iterator[None]:
    """:func:`keep_to_core` for the block only (a set made in this very process, ``--workers 1``)."""
    before_cores = os.sched_getaffinity(0) if hasattr(os, "sched_getaffinity") else None
    before_renderers = os.environ.get(ENVIRONMENT)
    keep_to_core(core)
    try:
        yield
    finally:
        if before_cores is not None:
            os.sched_setaffinity(0, before_cores)
        if before_renderers is None:
            os.environ.pop(ENVIRONMENT, None)
        else:
            os.environ[ENVIRONMENT] = before_renderers
