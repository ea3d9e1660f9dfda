"""Read a whole HDF5 file in a child process first, so that a file that hangs or crashes the library cannot.

Some damage sends the HDF5 library itself into an endless loop (a global
heap whose object sizes were changed hangs the read of a string attribute)
or could crash it; no check in Python can stop that once the call is made.
:func:`probe_in_child` therefore reads every attribute and every dataset the
file holds — reached through hard links, within the size bound of
:mod:`engine.formats.hdf5_reading` — in a child process with a time limit;
only a file the child read completely is then read here. Forked from this
process where that is safe (one thread), else forked by a helper
interpreter that does nothing else (:mod:`engine.formats.hdf5_probe_helper`),
or, where no helper can be had, read by a fresh interpreter running this
file, which needs nothing but h5py and numpy.

The time limit is ``AP_HDF5_PROBE_SECONDS`` if set, else 10 s plus 1 s per
20 MB of file.
"""

from __future__ import annotations

import contextlib
import faulthandler
import gc
import json
import math
import os
import signal
import subprocess
import sys
import threading
import warnings
from pathlib import Path

import h5py
import numpy as np

from engine.formats import hdf5_probe_helper
from engine.processes import die_with_parent, with_parent_death_signal

#: Objects (groups and datasets) a probe visits at most: our files hold a few hundred.
MAX_OBJECTS = 100_000
MAX_DEPTH = 32


class ProbeFailed(Exception):
    """The child did not read the file: ``reason`` says whether it hung, crashed or hit an error."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


def read_everything(path: str | Path, budget: int, allowed_filters: frozenset[int]) -> None:
    """Open ``path`` and read every attribute and every dataset our readers might read (raises on damage)."""
    with h5py.File(path, "r") as f:
        pending: list[tuple[h5py.Group | h5py.Dataset, int]] = [(f, 0)]
        visited = 0
        while pending:
            node, depth = pending.pop()
            visited += 1
            if visited > MAX_OBJECTS or depth > MAX_DEPTH:
                raise ValueError("too many objects or too deep a hierarchy")
            for key in list(node.attrs.keys()):
                node.attrs.get(key)
            if isinstance(node, h5py.Dataset):
                _read_dataset(node, budget, allowed_filters)
                continue
            for name in list(node.keys()):
                link = node.get(name, getlink=True)
                if isinstance(link, h5py.HardLink):
                    child = node[name]
                    if isinstance(child, (h5py.Group, h5py.Dataset)):
                        pending.append((child, depth + 1))


def _read_dataset(data: h5py.Dataset, budget: int, allowed_filters: frozenset[int]) -> None:
    plist = data.id.get_create_plist()
    if plist.get_layout() == h5py.h5d.VIRTUAL or plist.get_external_count() > 0:
        return                          # refused by the reader without reading
    if any(plist.get_filter(i)[0] not in allowed_filters for i in range(plist.get_nfilters())):
        return
    shape = data.shape
    if shape is None or math.prod(shape) * max(int(data.dtype.itemsize), 1) > budget:
        return
    np.asarray(data[()])


def probe_in_child(path: str | Path, budget: int, allowed_filters: frozenset[int],
                   seconds: float | None = None) -> None:
    """Read the whole file in a child process; :class:`ProbeFailed` if it hangs, crashes or fails."""
    path = Path(path)
    if seconds is None:
        seconds = float(os.environ.get("AP_HDF5_PROBE_SECONDS", "0") or 0) or \
            10.0 + path.stat().st_size / 20e6
    if hasattr(os, "fork") and _one_thread():
        _probe_forked(path, budget, allowed_filters, seconds)
    else:
        _probe_in_helper(path, budget, allowed_filters, seconds)


def _probe_in_helper(path: Path, budget: int, allowed_filters: frozenset[int], seconds: float) -> None:
    request = {"path": os.path.abspath(path), "budget": budget, "filters": sorted(allowed_filters),
               "seconds": seconds}
    answer = hdf5_probe_helper.ask_helper(request, seconds + hdf5_probe_helper.ANSWER_MARGIN)
    if answer is None:                   # no helper to be had: this file the old way
        probe_spawned(path, budget, allowed_filters, seconds)
    elif "failed" in answer:
        raise ProbeFailed(str(answer["failed"]))
    elif "error" in answer:
        raise OSError(str(answer["error"]))
    else:
        judge(int(answer["status"]), str(answer["message"]))


def _one_thread() -> bool:
    """True if only one thread runs Python here and no Qt application exists: then forking is safe.

    Native threads that never call into Python or h5py (a BLAS pool) hold no
    lock the child needs; a second Python thread might be inside h5py, and a
    running Qt application has threads of its own, so those spawn a fresh
    interpreter instead.
    """
    if threading.active_count() != 1:
        return False
    qt = sys.modules.get("PySide6.QtCore")
    return qt is None or qt.QCoreApplication.instance() is None


def _probe_forked(path: Path, budget: int, allowed_filters: frozenset[int], seconds: float) -> None:
    judge(*read_in_fork(path, budget, allowed_filters, seconds))


def read_in_fork(path: Path, budget: int, allowed_filters: frozenset[int], seconds: float) -> tuple[int, str]:
    """Fork a reader of ``path``: its wait status and its message; :class:`ProbeFailed` if it hangs."""
    read_end, write_end = os.pipe()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)       # Python 3.12 warns of the idle BLAS threads
        pid = os.fork()
    if pid == 0:                        # the child: read, report, and leave without running any cleanup
        die_with_parent()
        status = 0
        gc.disable()                    # collecting would copy the parent's pages, for nothing
        faulthandler.disable()          # a crash is reported by the parent in one line, not as a stack dump
        with contextlib.suppress(OSError):
            os.dup2(os.open(os.devnull, os.O_WRONLY), 2)
        try:
            os.close(read_end)
            read_everything(path, budget, allowed_filters)
        except BaseException as exc:    # every failure is reported to the parent
            status = 1
            with contextlib.suppress(BaseException):
                os.write(write_end, f"{type(exc).__name__}: {exc}".encode("utf-8", "replace")[:2000])
        os._exit(status)
    os.close(write_end)
    try:
        message = hdf5_probe_helper.read_before(read_end, seconds, line=False)
    except TimeoutError:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        raise ProbeFailed(f"reading it did not finish in {seconds:.0f} s (the HDF5 library hangs on it)") from None
    except BaseException:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        raise
    finally:
        os.close(read_end)
    _, status = os.waitpid(pid, 0)
    return status, message.decode("utf-8", "replace")


def probe_spawned(path: Path, budget: int, allowed_filters: frozenset[int], seconds: float) -> None:
    command = [sys.executable, "-I", str(Path(__file__).resolve()), str(path), str(budget),
               ",".join(map(str, sorted(allowed_filters)))]
    try:
        done = subprocess.run(with_parent_death_signal(command), capture_output=True, timeout=seconds, check=False)
    except subprocess.TimeoutExpired:
        raise ProbeFailed(f"reading it did not finish in {seconds:.0f} s (the HDF5 library hangs on it)") from None
    status = done.returncode
    wait_status = (-status) if status < 0 else (status << 8)        # as os.waitpid reports it
    last_lines = done.stderr.decode("utf-8", "replace").strip().splitlines()[-1:]
    judge(wait_status, last_lines[0] if last_lines else "")


def judge(wait_status: int, message: str) -> None:
    if os.WIFSIGNALED(wait_status):
        raise ProbeFailed(f"the HDF5 library crashed reading it (signal {os.WTERMSIG(wait_status)})")
    if os.WEXITSTATUS(wait_status) != 0:
        raise ProbeFailed(" ".join(message.split())[:300] or "the HDF5 library failed reading it")


def serve_as_helper() -> None:
    """The helper's loop (:mod:`engine.formats.hdf5_probe_helper`): a request a line from stdin, an answer a
    line to stdout, until stdin closes."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)     # Ctrl-C is for the program we serve; it closes our pipe
    for line in sys.stdin.buffer:
        try:
            request = json.loads(line)
            status, message = read_in_fork(Path(request["path"]), int(request["budget"]),
                                           frozenset(int(f) for f in request["filters"]), float(request["seconds"]))
            answer: dict[str, object] = {"status": status, "message": message}
        except ProbeFailed as exc:
            answer = {"failed": exc.reason}
        except (ValueError, KeyError, TypeError) as exc:
            answer = {"error": f"a request the helper cannot read ({exc})"}
        except OSError as exc:
            answer = {"error": f"no process to read the file in ({exc.strerror or exc})"}
        try:
            sys.stdout.buffer.write(json.dumps(answer).encode() + b"\n")
            sys.stdout.buffer.flush()
        except OSError:                  # the program we serve has gone
            return


if __name__ == "__main__":
    if sys.argv[1:] == ["--serve"]:
        serve_as_helper()
    else:
        read_everything(sys.argv[1], int(sys.argv[2]), frozenset(int(c) for c in sys.argv[3].split(",") if c))
