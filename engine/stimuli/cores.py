"""A worker is one core: it, and the Festival, ffmpeg and decoder processes it starts, run on a core of its own.

``stimuli --workers N`` makes N stimuli at a time on N cores of this computer
(CPU affinity, Linux), and a Dask worker running the toolkit keeps to one core
of its computer the same way; the other cores stay free for whatever else runs
there. A stimulus alone uses more than one core when it can (its video's
second renderer, :mod:`engine.outputs.render_helper`; ffmpeg encoding and the
checks' decoders beside the drawing), so without this a worker spreads over
one and a half cores and N workers over an unknown number.

Which core: the first of this process's cores that no other worker on the
computer holds. A worker holds a core by an advisory lock (``flock``) on a
file named after it in the temporary folder, kept while the worker lives (the
system lets it go when the process ends, however it ends), so two stimulus sets
made at once, or a set and a Dask worker, take different cores. When every
core is held the worker is not kept to one. Where the system has no CPU
affinity (macOS, Windows) workers are not kept to a core.

>>> with kept_to_a_core():
...     len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else 1
1
"""

from __future__ import annotations

import fcntl
import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from engine.outputs.render_helper import ENVIRONMENT

_held: dict[int, int] = {}
"""Core → the file descriptor whose lock holds it, for this process."""


def available_cores() -> list[int]:
    """The cores this process may run on (all of the computer's where the system does not say)."""
    if hasattr(os, "sched_getaffinity"):
        return sorted(os.sched_getaffinity(0))
    return list(range(os.cpu_count() or 1))


def claim_a_core() -> int | None:
    """Hold the first of this process's cores no other process holds (``None``: every one is held)."""
    for core in available_cores():
        if core in _held:
            return core
        path = Path(tempfile.gettempdir()) / f"artificial-person-core-{core}.lock"
        try:
            descriptor = os.open(path, os.O_RDONLY | os.O_CREAT, 0o644)
        except OSError:
            continue
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(descriptor)
            continue
        _held[core] = descriptor
        return core
    return None


def release_core(core: int) -> None:
    """Let another worker take ``core``."""
    descriptor = _held.pop(core, None)
    if descriptor is not None:
        os.close(descriptor)                       # closing the only descriptor releases the lock


def keep_to_a_core() -> int | None:
    """From now on this process, and every process it starts, runs on a core of its own, drawing alone (the core;
    ``None`` when every core is held: then it runs where the system puts it)."""
    os.environ[ENVIRONMENT] = "1"                     # no second renderer: it would only share the core
    if not hasattr(os, "sched_setaffinity"):
        return None
    core = claim_a_core()
    if core is not None:
        os.sched_setaffinity(0, {core})
    return core


@contextmanager
def kept_to_a_core() -> Iterator[int | None]:
    """:func:`keep_to_a_core` for the block only (a set made in this very process, ``--workers 1``)."""
    before_cores = os.sched_getaffinity(0) if hasattr(os, "sched_getaffinity") else None
    before_renderers = os.environ.get(ENVIRONMENT)
    held_before = set(_held)
    core = keep_to_a_core()
    try:
        yield core
    finally:
        if before_cores is not None:
            os.sched_setaffinity(0, before_cores)
        if core is not None and core not in held_before:
            release_core(core)
        if before_renderers is None:
            os.environ.pop(ENVIRONMENT, None)
        else:
            os.environ[ENVIRONMENT] = before_renderers
