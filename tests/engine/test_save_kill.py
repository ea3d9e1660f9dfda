"""kill -9 during save_model: the model on disk is always the old one or the new one, whole (issue 16 §5).

A real process saves a model in a loop (tests/engine/save_kill_worker.py)
and gets SIGKILL at a random moment, then at each step of a save in turn.
After every kill the model must load and be exactly model A or model B (the
two it alternates between, which share one rig, so a mix of their files
would load if nothing checked it), and after the next save the folder must
hold the two files and nothing else.

``AP_KILL_TRIALS`` sets the number of random kills (default 100);
``AP_KILL_SEED`` their random seed.
"""

from __future__ import annotations

import hashlib
import os
import random
import signal
import subprocess
import sys
import time
from collections import Counter
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

import engine.formats.model_files as model_files
from engine import ModelFileError, load_model, save_model
from engine.mocap.articulation_file import load_articulation_file, save_articulation_file
from engine.mocap.session import load_session, save_session
from engine.model.model import Model
from tests.engine.save_kill_worker import articulations, models, sessions

ROOT = Path(__file__).resolve().parents[2]
KILL_TRIALS = int(os.environ.get("AP_KILL_TRIALS", "100"))
KILL_SEED = int(os.environ.get("AP_KILL_SEED", "16"))


class Worker:
    """The saving process: forks savers on request and reaps them (see save_kill_worker.py)."""

    def __init__(self) -> None:
        env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
        self.process = subprocess.Popen([sys.executable, str(ROOT / "tests/engine/save_kill_worker.py")],
                                        cwd=ROOT, env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        text=True, bufsize=1)

    def ask(self, line: str) -> str:
        assert self.process.stdin is not None and self.process.stdout is not None
        self.process.stdin.write(line + "\n")
        self.process.stdin.flush()
        reply = self.process.stdout.readline().strip()
        assert reply, f"the worker died answering {line!r}"
        return reply

    def fork(self, line: str) -> int:
        word, pid = self.ask(line).split()
        assert word == "pid"
        return int(pid)

    def reap(self, pid: int) -> int:
        word, status = self.ask(f"reap {pid}").split()
        assert word == "reaped"
        return int(status)

    def close(self) -> None:
        assert self.process.stdin is not None
        self.process.stdin.close()
        self.process.wait()


@pytest.fixture(scope="module")
def worker() -> Iterator[Worker]:
    running = Worker()
    yield running
    running.close()


def fingerprint(model: Model) -> str:
    """A digest of everything both files hold: the description, the mesh and every region."""
    digest = hashlib.sha256(model_files.model_to_xml(model, "m.h5"))
    arrays = [model.vertices, model.faces, model.vertex_part]
    for name in sorted(model.regions):
        region = model.regions[name]
        arrays += [region.indices, region.weights] + ([] if region.displacements is None else [region.displacements])
    for data in arrays:
        digest.update(np.ascontiguousarray(data).tobytes())
    return digest.hexdigest()


@pytest.fixture(scope="module")
def expected(tmp_path_factory) -> dict[str, str]:
    """``{fingerprint: "A" or "B"}`` of the two models, as they load."""
    folder = tmp_path_factory.mktemp("reference")
    a, b = models()
    return {fingerprint(load_model(save_model(a, folder / "a.xml"))): "A",
            fingerprint(load_model(save_model(b, folder / "b.xml"))): "B"}


def hidden_files(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


def killed_by_sigkill(status: int) -> bool:
    return os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGKILL


def test_kill_9_at_random_moments_leaves_the_old_or_the_new_model(tmp_path, worker, expected):
    path = tmp_path / "m.xml"
    a, _ = models()
    one_save = float(worker.ask(f"time {path}").split()[1])
    save_model(a, path)
    rng = random.Random(KILL_SEED)
    outcomes: Counter[str] = Counter()
    leftovers_after_kill = during_renames = 0
    for trial in range(KILL_TRIALS):
        pid = worker.fork(f"loop {path}")
        time.sleep(rng.uniform(0.0, 3.0 * one_save))       # where the kill lands, not a timing assertion
        os.kill(pid, signal.SIGKILL)
        assert killed_by_sigkill(worker.reap(pid))
        leftovers_after_kill += bool(hidden_files(tmp_path))
        during_renames += any(name.endswith(".journal") for name in hidden_files(tmp_path))
        try:
            loaded = load_model(path)
        except ModelFileError as exc:
            pytest.fail(f"trial {trial}: the model does not load after kill -9: {exc}")
        which = expected.get(fingerprint(loaded))
        assert which is not None, f"trial {trial}: the model loads but is neither A nor B (a mix of two saves)"
        outcomes[which] += 1
        save_model(a, path)
        assert sorted(p.name for p in tmp_path.iterdir()) == ["m.h5", "m.xml"], f"trial {trial}"
    print(f"\nkill -9 trials: {KILL_TRIALS}, loadable {sum(outcomes.values())}, old/new A={outcomes['A']} "
          f"B={outcomes['B']}, kills that left temporaries {leftovers_after_kill} (a journal: {during_renames}), "
          f"leftover after the next save 0 (one save {one_save * 1000:.1f} ms)")


@pytest.mark.parametrize("point,result", [
    ("journal", "A"),       # the journal half written: nothing renamed, the save never happened
    ("rename-1", "B"),      # the journal complete: the save is committed, the next load finishes it
    ("rename-2", "B"),      # new arrays beside the old description: the renames are completed
    ("unjournal", "B"),     # both renamed, the journal left behind
])
def test_kill_9_at_each_step_of_a_save(tmp_path, worker, expected, point, result):
    path = tmp_path / "m.xml"
    a, _ = models()
    save_model(a, path)
    pid = worker.fork(f"stop {path} {point}")
    assert killed_by_sigkill(worker.reap(pid)), "the saver was not killed where it should be"
    assert hidden_files(tmp_path), "the kill left nothing behind to clean up"
    assert expected[fingerprint(load_model(path))] == result
    assert hidden_files(tmp_path) == []                    # loading finished the save and removed the rest
    save_model(a, path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.h5", "m.xml"]


def test_a_save_cleans_what_a_killed_save_left(tmp_path, worker):
    """A save (not only a load) finishes a killed save's renames and removes its temporary files."""
    path = tmp_path / "m.xml"
    a, b = models()
    save_model(a, path)
    assert killed_by_sigkill(worker.reap(worker.fork(f"stop {path} rename-2")))
    save_model(b, path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.h5", "m.xml"]


KIND_TRIALS = max(1, KILL_TRIALS // 4)


@pytest.mark.parametrize("kind", ["session", "articulation"])
def test_kill_9_while_saving_a_session_or_articulation_file(tmp_path, worker, kind):
    """One file, one rename: old or new after any kill, and the next save leaves no temporary behind."""
    make, save, load, same = {
        "session": (sessions, save_session, load_session, lambda x, y: np.array_equal(x.positions, y.positions)),
        "articulation": (articulations, save_articulation_file, load_articulation_file,
                         lambda x, y: np.array_equal(x.components, y.components)),
    }[kind]
    first, second = make()
    path = tmp_path / f"{kind}.h5"
    started = time.perf_counter()
    save(first, path)
    one_save = time.perf_counter() - started
    rng = random.Random(KILL_SEED)
    outcomes: Counter[str] = Counter()
    for trial in range(KIND_TRIALS):
        pid = worker.fork(f"loop {path} {kind}")
        time.sleep(rng.uniform(0.0, 3.0 * one_save))           # where the kill lands, not a timing assertion
        os.kill(pid, signal.SIGKILL)
        assert killed_by_sigkill(worker.reap(pid))
        loaded = load(path)
        which = "old" if same(loaded, first) else "new" if same(loaded, second) else None
        assert which is not None, f"trial {trial}: neither the old nor the new file"
        outcomes[which] += 1
        save(first, path)
        assert sorted(p.name for p in tmp_path.iterdir()) == [path.name], f"trial {trial}"
    print(f"\n{kind}: {KIND_TRIALS} kill -9 trials, loadable {sum(outcomes.values())}, "
          f"A={outcomes['old']} B={outcomes['new']}, leftover after the next save 0")


def test_a_mixed_pair_is_refused_naming_both_saves(tmp_path):
    a, b = models()
    first, second = save_model(a, tmp_path / "a" / "m.xml"), save_model(b, tmp_path / "b" / "m.xml")
    first.with_suffix(".h5").write_bytes(second.with_suffix(".h5").read_bytes())
    with pytest.raises(ModelFileError, match="come from different saves") as caught:
        load_model(first)
    assert caught.value.file == str(first) and caught.value.line == 2


def test_files_without_a_generation_still_load(tmp_path):
    """Files written before the generation token existed (or written by hand) load as before."""
    import h5py

    a, _ = models()
    path = save_model(a, tmp_path / "m.xml")
    text = path.read_text(encoding="utf-8")
    start = text.index(' generation="')
    path.write_text(text[:start] + text[text.index('"', start + 13) + 1:], encoding="utf-8")
    with h5py.File(path.with_suffix(".h5"), "a") as f:
        del f.attrs["generation"]
    assert load_model(path).n_vertices == a.n_vertices
