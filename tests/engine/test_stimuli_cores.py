"""A local worker of a stimulus set is one core (engine/stimuli/cores.py): real worker processes, real children."""

from __future__ import annotations

import ast
import os
import shutil
import subprocess
import sys
from concurrent.futures import ProcessPoolExecutor
from multiprocessing import get_context

import pytest

from engine.outputs.render_helper import ENVIRONMENT
from engine.stimuli import make_set, parse_design
from engine.stimuli.cores import available_cores
from engine.stimuli.run import _worker_start

pytestmark = pytest.mark.skipif(not hasattr(os, "sched_getaffinity"), reason="no CPU affinity on this system")


def cores_seen() -> tuple[list[int], list[int], str | None]:
    """This process's cores, those of a process it starts, and whether it may fork a second renderer."""
    child = subprocess.run([sys.executable, "-c", "import os; print(sorted(os.sched_getaffinity(0)))"],
                           capture_output=True, text=True, check=True)
    return sorted(os.sched_getaffinity(0)), ast.literal_eval(child.stdout), os.environ.get(ENVIRONMENT)


def test_each_worker_and_every_process_it_starts_keep_to_a_core_of_its_own():
    cores = available_cores()
    context = get_context("spawn")
    free = context.Queue()
    for k in range(2):
        free.put(cores[k % len(cores)])
    with ProcessPoolExecutor(2, mp_context=context, initializer=_worker_start, initargs=(free,)) as pool:
        seen = list(pool.map(cores_seen_by_a_busy_worker, range(8)))
    for own, child, renderers in seen:
        assert len(own) == 1 and child == own and renderers == "1"
    if len(cores) >= 2:
        assert {own[0] for own, _, _ in seen} <= set(cores[:2])


def cores_seen_by_a_busy_worker(_index: int) -> tuple[list[int], list[int], str | None]:
    import time

    time.sleep(0.2)                               # both workers get tasks
    return cores_seen()


@pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed")
def test_a_set_made_in_this_process_keeps_to_one_core_and_gives_the_cores_back(tmp_path):
    before, renderers = os.sched_getaffinity(0), os.environ.get(ENVIRONMENT)
    design = parse_design('[factors]\ntext = ["Moi."]\n[output]\nkinds = ["wav"]\n', tmp_path / "d.toml")
    seen: list[set[int]] = []
    result = make_set(design, tmp_path / "out", workers=1,
                      progress=lambda *_: seen.append(os.sched_getaffinity(0)))
    assert len(result.records) == 1
    assert any(len(cores) == 1 for cores in seen), "kept to one core while making"
    assert os.sched_getaffinity(0) == before and os.environ.get(ENVIRONMENT) == renderers
