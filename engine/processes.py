"""Child processes that end with us: Festival, ffmpeg, the mesh and HDF5 probes.

A child we start must not outlive the process that started it, whatever ends
that process: an exception (the callers kill their children in ``finally``),
Ctrl-C, ``timeout``'s SIGTERM, or ``kill -9`` and a crash, where no Python code
runs at all. For those last, every child is started with Linux's parent-death
signal set: the kernel sends it SIGKILL when its parent dies. util-linux's
``setpriv --pdeathsig KILL --`` sets it and then runs the program (util-linux
is essential on Debian, so it is always there).

>>> command = with_parent_death_signal(["ffmpeg", "-version"])
>>> command[-2:]
['ffmpeg', '-version']
"""

from __future__ import annotations

import shutil
from collections.abc import Sequence

_SETPRIV = shutil.which("setpriv")


def with_parent_death_signal(command: Sequence[str]) -> list[str]:
    """``command``, run so that it gets SIGKILL when its parent dies (unchanged where setpriv is absent)."""
    prefix = [_SETPRIV, "--pdeathsig", "KILL", "--"] if _SETPRIV else []
    return [*prefix, *command]
