"""A process that saves models until it is killed, for tests/engine/test_save_kill.py.

It imports the engine once, then forks a saver on request, so each kill -9
trial costs a fork rather than a Python start-up. Commands, one per line on
stdin; one reply line each on stdout:

``loop PATH [KIND]``
    fork a child that saves B, A, B, A, … to ``PATH`` until killed; reply
    ``pid <PID>``. ``KIND``: ``model`` (the default), ``session`` or
    ``articulation`` (the pairs of :func:`sessions` and :func:`articulations`).
``stop PATH POINT``
    fork a child that saves model B over ``PATH`` and kills itself (SIGKILL)
    at ``POINT`` of the save: ``journal`` (half-way through writing the
    journal), ``rename-1`` / ``rename-2`` (just before the first / second
    rename), ``unjournal`` (after both renames, before the journal is
    removed); reply ``pid <PID>``.
``reap PID``
    wait for that child; reply ``reaped <wait status>``.
``time PATH``
    save A and B to ``PATH`` once each; reply ``seconds <time of one save>``.

Models A and B come from :func:`models` (the test builds the same ones): the
same rig, with other vertex positions, weights and description, so that a
mix of their two files would load if nothing checked it.
"""

from __future__ import annotations

import os
import signal
import sys
import time
from pathlib import Path

import numpy as np

import engine.formats.atomic as atomic
from engine import save_model
from engine.mocap.articulation_file import save_articulation_file
from engine.mocap.pca import Articulation, Stage, multistage_pca
from engine.mocap.session import Session, save_session
from engine.model.model import Model
from tests.engine.synthetic import random_model


def models() -> tuple[Model, Model]:
    """Model A and model B: one rig, different contents in both files."""
    a = random_model(7, n_vertices=3000, n_parameters=8, depth=3)
    a.description = "model A"
    b = a.copy()
    b.vertices = b.vertices + 1.5
    b.description = "model B"
    for region in b.regions.values():
        region.weights = region.weights * 0.5
    return a, b


def sessions() -> tuple[Session, Session]:
    """Two motion-capture sessions of one layout, different contents."""
    rng = np.random.default_rng(5)
    positions = rng.normal(size=(400, 12, 3)) * 10

    def session(shift: float) -> Session:
        return Session(markers=[f"m{i}" for i in range(12)], positions=positions + shift, raw=positions,
                       rate_hz=60, missing=np.zeros((400, 12), bool), alignment=np.tile(np.eye(4), (400, 1, 1)),
                       source=f"shift {shift}")

    return session(0.0), session(2.5)


def articulations() -> tuple[Articulation, Articulation]:
    """Two articulation files of one layout, different contents."""
    rng = np.random.default_rng(6)
    markers = [f"m{i}" for i in range(12)]
    return tuple(multistage_pca(markers, rng.normal(size=(200, 12, 3)) * scale, stages=[Stage(("m*",), 3)])
                 for scale in (1.0, 2.0))                    # type: ignore[return-value]


def die() -> None:
    os.kill(os.getpid(), signal.SIGKILL)


def arm(point: str) -> None:
    """Make this process kill itself at ``point`` of the next save."""
    if point == "journal":
        def half_journal(first_target, temporaries):           # the journal file exists, half written
            journal = atomic._new_temporary(first_target, ".journal")
            journal.write_bytes(b'{"format": "artificial-person-rename-jou')
            die()

        atomic._write_journal = half_journal
    elif point in ("rename-1", "rename-2"):
        real_replace, calls = os.replace, []

        def replace(src, dst):
            calls.append(dst)
            if len(calls) == int(point[-1]):
                die()
            real_replace(src, dst)

        atomic.os.replace = replace                              # type: ignore[assignment]
    elif point == "unjournal":
        real_remove = atomic._remove

        def remove(paths):
            paths = list(paths)
            if any(str(p).endswith(".journal") for p in paths):
                die()
            real_remove(paths)

        atomic._remove = remove
    else:
        raise ValueError(point)


SAVERS = {"model": (models, save_model), "session": (sessions, save_session),
          "articulation": (articulations, save_articulation_file)}


def main() -> None:
    a, b = models()
    for line in sys.stdin:
        command, *args = line.split()
        if command == "loop":
            pid = os.fork()
            if pid == 0:
                path = Path(args[0])
                make, save = SAVERS[args[1] if len(args) > 1 else "model"]
                first, second = make()
                while True:
                    save(second, path)
                    save(first, path)
            reply = f"pid {pid}"
        elif command == "stop":
            pid = os.fork()
            if pid == 0:
                arm(args[1])
                save_model(b, Path(args[0]))
                os._exit(3)                                      # the kill point was never reached
            reply = f"pid {pid}"
        elif command == "reap":
            _, status = os.waitpid(int(args[0]), 0)
            reply = f"reaped {status}"
        elif command == "time":
            started = time.perf_counter()
            save_model(a, Path(args[0]))
            save_model(b, Path(args[0]))
            reply = f"seconds {(time.perf_counter() - started) / 2:.6f}"
        else:
            reply = f"unknown {command}"
        print(reply, flush=True)


if __name__ == "__main__":
    main()
