"""One helper interpreter that forks the HDF5 probe's readers where this process cannot fork.

Where forking here is not safe (a second Python thread, a Qt application:
:func:`engine.formats.hdf5_probe._one_thread`), a fresh interpreter for each
file would cost 0.2–0.3 s (Python, numpy and h5py started again): the
workbench would pay it at every open, a test suite at each of thousands of
loads. Instead one helper, started at the first such probe, with one thread
and no Qt, forks a reader per file as :func:`~engine.formats.hdf5_probe.read_in_fork`
does here where it can, waits for it within the time limit, and answers
with its wait status (a few milliseconds a file).

It ends with us: it reads its requests from a pipe only we hold and leaves
when that pipe closes, whatever ended us (even ``kill -9``); a reader it
forks has the parent-death signal set. A helper that dies or stops answering
is killed, and that one file is read the old way, by a fresh interpreter
(:func:`~engine.formats.hdf5_probe.probe_spawned`); the next file starts a
new helper.

This module is our side of the pipe; the helper's loop is
:func:`engine.formats.hdf5_probe.serve_as_helper`. The pipe carries one
JSON line per request, ``{"path", "budget", "filters", "seconds"}``, and
one per answer, ``{"status": WAIT_STATUS, "message": TEXT}`` or
``{"failed": REASON}`` (the reader hung) or ``{"error": TEXT}`` (no reader
could be forked).

>>> from engine.formats.hdf5_probe_helper import ask_helper
>>> ask_helper({"path": "/data/anna.h5", "budget": 1 << 30, "filters": [1], "seconds": 10}, 40)  # doctest: +SKIP
{'status': 0, 'message': ''}
"""

from __future__ import annotations

import atexit
import contextlib
import json
import os
import select
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

#: The program the helper runs: the probe's own file, whose ``--serve`` loop is
#: :func:`engine.formats.hdf5_probe.serve_as_helper`.
HELPER_SCRIPT = Path(__file__).resolve().with_name("hdf5_probe.py")
#: Seconds an answer may take beyond the reader's own time limit before the helper counts as stuck.
ANSWER_MARGIN = 30.0


class _Slot:
    """The helper now running (if any), and the lock that lets one thread at a time talk to it."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.process: subprocess.Popen[bytes] | None = None
        self.exit_hook_registered = False


_slot = _Slot()


def _forget_in_forked_child() -> None:
    """A child forked from here (a worker) starts its own helper; the pipes it inherited are its parent's."""
    _slot.lock = threading.Lock()
    _slot.process = None


os.register_at_fork(after_in_child=_forget_in_forked_child)


def ask_helper(request: dict[str, Any], patience: float) -> dict[str, Any] | None:
    """Send ``request`` to the helper (started if none runs) and return its answer; None if it gave none
    within ``patience`` seconds or ended (it is then ended here too)."""
    with _slot.lock:
        return _ask(request, patience)


def helper_pid() -> int | None:
    """The running helper's process id (None before the first probe that needs it, or after it ended)."""
    helper = _slot.process
    return None if helper is None or helper.poll() is not None else helper.pid


def _ask(request: dict[str, Any], patience: float) -> dict[str, Any] | None:
    try:
        if _slot.process is not None and _slot.process.poll() is not None:
            _stop()                      # it died (killed, out of memory): a new one
        if _slot.process is None:
            _slot.process = _start()
        helper = _slot.process
        assert helper.stdin is not None and helper.stdout is not None
        helper.stdin.write(json.dumps(request).encode() + b"\n")
        answer = json.loads(read_before(helper.stdout.fileno(), patience, line=True))
        if not isinstance(answer, dict):
            raise ValueError("not an answer")
        return answer
    except (OSError, ValueError, TimeoutError):
        _stop()
        return None


def _start() -> subprocess.Popen[bytes]:
    helper = subprocess.Popen([sys.executable, "-I", str(HELPER_SCRIPT), "--serve"], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, bufsize=0)
    if not _slot.exit_hook_registered:
        atexit.register(_stop)
        _slot.exit_hook_registered = True
    return helper


def read_before(fd: int, seconds: float, *, line: bool) -> bytes:
    """What ``fd`` gives within ``seconds``: up to the end of the stream, or with ``line`` up to a newline
    (:class:`TimeoutError` when time runs out first; with ``line``, :class:`OSError` if the stream ends)."""
    deadline = time.monotonic() + seconds
    chunks: list[bytes] = []
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            raise TimeoutError
        ready, _, _ = select.select([fd], [], [], left)
        if not ready:
            continue
        chunk = os.read(fd, 65536)
        if not chunk:
            if line:
                raise OSError("the helper ended")
            return b"".join(chunks)
        chunks.append(chunk)
        if line and chunk.endswith(b"\n"):
            return b"".join(chunks)


def _stop() -> None:
    """End the helper: close its pipe (it leaves by itself), and kill it if it does not."""
    helper, _slot.process = _slot.process, None
    if helper is None:
        return
    for stream in (helper.stdin, helper.stdout):
        with contextlib.suppress(OSError):
            if stream is not None:
                stream.close()
    try:
        helper.wait(timeout=2)
    except subprocess.TimeoutExpired:
        helper.kill()
        helper.wait()
