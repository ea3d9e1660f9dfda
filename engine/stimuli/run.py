"""Making a whole design: in parallel processes on this machine, or on a Dask cluster; resumable.

Each stimulus is made by :func:`engine.stimuli.make.make_stimulus` in a worker
(a local process, one per core by default and each kept to a core of its own,
:mod:`engine.stimuli.cores`; or a Dask worker when a scheduler address is
given). A stimulus is done when its record is on disk and every file it names
has the recorded SHA-256; ``resume`` skips those and makes the
rest. When every stimulus is done, the manifest, the PsychoPy conditions
table, the checks and the provenance are written together
(:mod:`engine.stimuli.manifest`).

>>> from engine.stimuli.design import load_design
>>> result = make_set(load_design("examples/stimuli/minimal.toml"), "out", workers=2)   # doctest: +SKIP
>>> len(result.records), result.failed                                                # doctest: +SKIP
(6, [])
"""

from __future__ import annotations

import json
import os
import shutil
import time
from collections.abc import Callable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from multiprocessing import get_context
from pathlib import Path
from typing import Any

from engine.errors import UserError
from engine.formats.atomic import finish_interrupted_writes
from engine.stimuli.cores import keep_to_a_core, kept_to_a_core
from engine.stimuli.design import Design, Stimulus
from engine.stimuli.make import RECORDS, make_stimulus, sha256_of
from engine.stimuli.manifest import MANIFEST, write_set_files

Progress = Callable[[int, int, str], None]
"""``progress(done, total, message)``."""


@dataclass
class SetResult:
    records: list[dict[str, Any]]
    made: int
    reused: int
    failed: list[str] = field(default_factory=list)
    """Ids of stimuli whose check missed the specification."""


def done_records(design: Design, outdir: Path) -> dict[str, dict[str, Any]]:
    """The records of stimuli whose files are all on disk with the recorded hashes."""
    done = {}
    folder = outdir / RECORDS
    for stimulus in design.stimuli:
        path = folder / f"{stimulus.id}.json"
        try:
            record = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue
        if record.get("levels") != stimulus.levels:
            continue
        files = record.get("files", {})
        if set(files) != set(design.output.kinds):
            continue
        if all((outdir / f["name"]).is_file() and sha256_of(outdir / f["name"]) == f["sha256"]
               for f in files.values()):
            done[stimulus.id] = record
    return done


def make_set(design: Design, outdir: str | Path, workers: int | None = None, scheduler: str | None = None,
             resume: bool = False, progress: Progress | None = None) -> SetResult:
    """Make every stimulus of ``design`` into ``outdir``, then the set's tables."""
    outdir = Path(outdir)
    if outdir.exists() and not outdir.is_dir():
        raise UserError("not a folder", file=outdir)
    if ((outdir / MANIFEST).exists() or (outdir / RECORDS).is_dir()) and not resume:
        raise UserError("this folder already holds a stimulus set: give --resume to finish or check it, "
                        "or choose another folder", file=outdir)
    created = not outdir.exists()
    outdir.mkdir(parents=True, exist_ok=True)
    if resume:                                   # a killed run's temporaries: finished or removed
        finish_interrupted_writes(outdir)
        if (outdir / RECORDS).is_dir():
            finish_interrupted_writes(outdir / RECORDS)
    done = done_records(design, outdir) if resume else {}
    todo = [s for s in design.stimuli if s.id not in done]
    total = len(design.stimuli)
    report = progress or (lambda *_: None)
    report(len(done), total, f"{len(done)} already made" if done else "starting")
    if todo:
        runner = _run_on_dask if scheduler else _run_locally
        try:
            for record in runner(design, todo, outdir, workers, scheduler):
                done[record["id"]] = record
                report(len(done), total, f"stimulus {record['id']}")
        except UserError as exc:
            _leave_tidy(exc, outdir, created, len(done), total)
            raise
    records = [done[s.id] for s in design.stimuli]
    write_set_files(design, outdir, records)
    failed = [r["id"] for r in records if not r.get("check", {}).get("ok", True)]
    return SetResult(records, len(todo), total - len(todo), failed)


def _leave_tidy(exc: UserError, outdir: Path, created: bool, made: int, total: int) -> None:
    """After a stimulus failed: a folder this run made and filled with nothing finished is removed (no empty
    set left behind); where stimuli were finished, the error says they are kept and how to go on."""
    if created and made == 0:
        shutil.rmtree(outdir, ignore_errors=True)
    elif made:
        exc.message += (f" ({made} of {total} stimuli were finished and are kept in {outdir}: fix this and run "
                        "again with --resume to make the rest)")


def default_workers() -> int:
    return max(1, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1))


def _run_locally(design: Design, todo: list[Stimulus], outdir: Path, workers: int | None,
                 _scheduler: str | None) -> Iterator[dict[str, Any]]:
    count = max(1, min(workers or default_workers(), len(todo)))
    if count == 1:
        with kept_to_a_core():
            for stimulus in todo:
                yield make_stimulus(design, stimulus, outdir)
        return
    pending = list(todo)
    attempts: dict[str, int] = {}
    while pending:
        # spawn: a fresh interpreter per worker (no forked VTK or Festival state); workers die with us
        with ProcessPoolExecutor(count, mp_context=get_context("spawn"), initializer=_worker_start) as pool:
            futures: dict[Future, Stimulus] = {pool.submit(make_stimulus, design, s, outdir): s for s in pending}
            pending = []
            try:
                while futures:
                    finished, _ = wait(futures, return_when=FIRST_COMPLETED)
                    for future in finished:
                        stimulus = futures.pop(future)
                        yield future.result()
            except BrokenProcessPool:                     # a worker died (killed, out of memory): redo its work
                for stimulus in futures.values():
                    attempts[stimulus.id] = attempts.get(stimulus.id, 0) + 1
                    if attempts[stimulus.id] > 3:
                        raise UserError(f"stimulus {stimulus.id}: its worker died three times") from None
                pending = list(futures.values())


def _make_on_a_worker(design: Design, stimulus: Stimulus, outdir: Path) -> dict[str, Any]:
    """:func:`make_stimulus` on a Dask worker, which keeps to a core of its own from its first stimulus on."""
    keep_to_a_core()                              # the core it already holds, after the first time
    return make_stimulus(design, stimulus, outdir)


def _worker_start() -> None:
    from engine.processes import die_with_parent

    die_with_parent()
    keep_to_a_core()                              # a core no other worker on this computer holds


def _run_on_dask(design: Design, todo: list[Stimulus], outdir: Path, _workers: int | None,
                 scheduler: str | None) -> Iterator[dict[str, Any]]:
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise UserError("--scheduler needs the 'distributed' package (pip install distributed)") from None
    try:
        client = Client(scheduler, timeout=30)
    except (OSError, TimeoutError) as exc:
        raise UserError(f"cannot reach the Dask scheduler at {scheduler}: {exc}") from None
    with client:
        futures = [client.submit(_make_on_a_worker, design, stimulus, outdir.resolve(), key=f"stimulus-{stimulus.id}-"
                                 f"{design.sha256[:12]}-{time.time_ns()}", pure=False, retries=2)
                   for stimulus in todo]
        for future in as_completed(futures):
            yield future.result()
