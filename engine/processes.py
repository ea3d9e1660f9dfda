"""Child processes that end with us: Festival, ffmpeg, the mesh and HDF5 probes.

A child we start must not outlive the process that started it, whatever ends
that process: an exception (the callers kill their children in ``finally``),
Ctrl-C, ``timeout``'s SIGTERM, or ``kill -9`` and a crash, where no Python code
runs at all. For those last, every child is started with Linux's parent-death
signal set: the kernel sends it SIGKILL when its parent dies. util-linux's
``setpriv --pdeathsig KILL --`` sets it and then runs the program (util-linux
is essential on Debian, so it is always there).

The kernel sends the signal when the *thread* that started the child ends,
not only the process: start a child from a thread that lives as long as the
child is needed. Ours do — the thread that starts Festival or ffmpeg waits
for it, and worker pools are started by the thread that waits for their
results. (The mesh reader's child watches a pipe instead:
``engine/formats/mesh_child.py``.)

>>> command = with_parent_death_signal(["ffmpeg", "-version"])
>>> command[-2:]
['ffmpeg', '-version']
"""

from __future__ import annotations

import ctypes
import shutil
import signal
import sys
from collections.abc import Sequence

_SETPRIV = shutil.which("setpriv")


def with_parent_death_signal(command: Sequence[str]) -> list[str]:
    """``command``, run so that it gets SIGKILL when its parent dies (unchanged where setpriv is absent)."""
    prefix = [_SETPRIV, "--pdeathsig", "KILL", "--"] if _SETPRIV else []
    return [*prefix, *command]


def die_with_parent() -> None:
    """Ask the kernel to kill this process when its parent dies (a worker process calls it at start).

    Linux only (``prctl(PR_SET_PDEATHSIG, SIGKILL)``); elsewhere nothing happens.
    """
    if not sys.platform.startswith("linux"):
        return
    libc = ctypes.CDLL(None, use_errno=True)
    libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)


_PR_SET_PDEATHSIG = 1
