"""A worker of a stimulus set is one core (engine/stimuli/cores.py): real worker processes, real children."""

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
from engine.stimuli.cores import available_cores, claim_a_core, release_core
from engine.stimuli.run import _worker_start

pytestmark = pytest.mark.skipif(not hasattr(os, "sched_getaffinity"), reason="no CPU affinity on this system")


def cores_seen(_index: int = 0) -> tuple[list[int], list[int], str | None]:
    """This process's cores, those of a process it starts, and whether it may fork a second renderer."""
    import time

    time.sleep(0.2)                               # every worker gets tasks
    child = subprocess.run([sys.executable, "-c", "import os; print(sorted(os.sched_getaffinity(0)))"],
                           capture_output=True, text=True, check=True)
    return sorted(os.sched_getaffinity(0)), ast.literal_eval(child.stdout), os.environ.get(ENVIRONMENT)


@pytest.mark.skipif(len(available_cores()) < 2, reason="one core: nothing to share out")
def test_each_worker_and_every_process_it_starts_keep_to_a_core_no_other_worker_holds():
    with ProcessPoolExecutor(2, mp_context=get_context("spawn"), initializer=_worker_start) as pool:
        seen = list(pool.map(cores_seen, range(8)))
    for own, child, renderers in seen:
        assert len(own) == 1 and child == own and renderers == "1"
    assert len({own[0] for own, _, _ in seen}) == 2, "the two workers hold two different cores"


@pytest.mark.skipif(len(available_cores()) < 2, reason="one core: nothing to share out")
def test_a_second_set_at_the_same_time_takes_another_core_and_a_core_is_let_go_after():
    mine = claim_a_core()                         # as a worker of another set running now holds it
    assert mine == available_cores()[0]
    try:
        with ProcessPoolExecutor(1, mp_context=get_context("spawn"), initializer=_worker_start) as pool:
            [(other, _, _)] = list(pool.map(cores_seen, range(1)))
        assert len(other) == 1 and other != [mine], "a worker does not take a core another holds"
    finally:
        release_core(mine)
    with ProcessPoolExecutor(1, mp_context=get_context("spawn"), initializer=_worker_start) as pool:
        [(after, _, _)] = list(pool.map(cores_seen, range(1)))
    assert after == [mine], "once let go, the first core is free again"


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
