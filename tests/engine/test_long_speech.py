"""Long texts and Festival's lifetime (issue 16 §3–4): utterance by utterance, linear, and never orphaned.

The paper's speakers read short stories (§2.1); the cost of a text must grow
with its length and no faster, and Festival must never outlive whoever
started it.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import time
import tracemalloc
from pathlib import Path

import numpy as np
import pytest

from engine.speech.articulation import load_articulation
from engine.speech.coarticulation import articulation_tracks, key_times
from engine.speech.synthesis import Segment
from tests.engine.test_festival import needs_festival

SENTENCE = "Pappa ampui pallon, ja Maija meni kotiin kauniina kesäpäivänä."


def random_phones(count: int, seed: int) -> list[Segment]:
    table = load_articulation()
    rng = np.random.default_rng(seed)
    names = sorted(table.rows)
    phones, start = [], 0.0
    for i in range(count):
        label = "##" if i in (0, count - 1) else names[rng.integers(len(names))]
        length = float(rng.choice([rng.uniform(20, 200), rng.uniform(400, 3000)], p=[0.95, 0.05]))
        phones.append(Segment(label, start, start + length))
        start += length
    return phones


def dense_reference(phones, table, times):
    """Σ D·T / Σ D over every phone at every time (the formula, with no window), then closures enforced."""
    value, dominance, anticipation, carryover, enforced = table.arrays([p.label for p in phones])
    middles = np.array([p.mid_ms for p in phones])
    tau = times[:, None] - middles[None, :]
    out = np.empty((times.size, value.shape[1]))
    for j in range(value.shape[1]):
        rate = np.where(tau < 0, anticipation[None, :, j], carryover[None, :, j])
        weight = dominance[None, :, j] * np.exp(-rate * np.abs(tau) ** table.exponent)
        out[:, j] = (weight * value[None, :, j]).sum(1) / weight.sum(1)
    starts, ends = np.array([p.start_ms for p in phones]), np.array([p.end_ms for p in phones])
    from engine.speech.coarticulation import closure_window
    for s, j in zip(*np.nonzero(enforced), strict=True):
        w = closure_window(times, starts[s], ends[s])
        out[:, j] = out[:, j] * (1 - w) + value[s, j] * w
    return out


@pytest.mark.parametrize("seed", range(2))
def test_windowed_coarticulation_equals_the_whole_sum(seed):
    """Leaving out phones too far to matter changes nothing beyond rounding (§2.1, Cohen–Massaro)."""
    table = load_articulation()
    phones = random_phones(200, seed)
    times = key_times(phones)
    assert np.allclose(articulation_tracks(phones, table, times), dense_reference(phones, table, times),
                       rtol=0, atol=1e-12)
    shuffled = np.random.default_rng(seed).permutation(times)          # any order of times, same values
    assert np.allclose(articulation_tracks(phones, table, shuffled),
                       dense_reference(phones, table, shuffled), rtol=0, atol=1e-12)


def test_coarticulation_memory_grows_linearly_with_the_text():
    """16× the phones may take about 16× the memory, never 256× (times × phones, the old dense sum)."""
    table = load_articulation()

    def peak(count):
        phones = random_phones(count, 7)
        times = key_times(phones)
        tracemalloc.start()
        articulation_tracks(phones, table, times)
        used = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        return used

    small, large = peak(400), peak(6400)
    assert large / small < 32, (small, large)


@needs_festival
@pytest.mark.slow
def test_a_long_text_is_spoken_utterance_by_utterance_without_gaps():
    from engine.speech.festival import FestivalSynthesizer

    utterance = FestivalSynthesizer().synthesize(" ".join([SENTENCE] * 6))
    assert [w.label for w in utterance.words][:9] == ["Pappa", "ampui", "pallon", "ja", "Maija", "meni", "kotiin",
                                                       "kauniina", "kesäpäivänä"]
    assert len(utterance.words) == 6 * 9
    for before, after in zip(utterance.phones, utterance.phones[1:], strict=False):
        assert after.start_ms == before.end_ms
    assert abs(utterance.phones[-1].end_ms - utterance.duration_ms) <= 1000 / utterance.sample_rate
    # six utterances: each ends in Suopuhe's closing pauses before the next begins
    assert sum(1 for a, b in zip(utterance.phones, utterance.phones[1:], strict=False)
               if a.label == "#" and b.label == "#") >= 5
    for word in utterance.words:                # the audio under every word is speech, not silence
        start, end = (round(t * utterance.sample_rate / 1000) for t in (word.start_ms, word.end_ms))
        assert np.abs(utterance.samples[start:end]).max() > 0.01, word


# ---------------------------------------------------------------------------
# Festival dies with whoever started it
# ---------------------------------------------------------------------------

def festival_children(parent: int) -> list[int]:
    """Processes whose parent is ``parent`` and whose program is Festival."""
    return children_named(parent, "festival")


def children_named(parent: int, program: str) -> list[int]:
    """Live processes whose parent is ``parent`` and whose program is ``program``."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        name, rest = stat[stat.index("(") + 1:stat.rindex(")")], stat[stat.rindex(")") + 2:].split()
        if name == program and int(rest[1]) == parent and rest[0] != "Z":
            found.append(int(entry.name))
    return found


def alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def wait_for(condition, seconds=30.0):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        result = condition()
        if result:
            return result
        time.sleep(0.05)
    return condition()


LONG_TEXT = " ".join([SENTENCE[:-1] + ","] * 400) + " loppu."
"""One endless sentence: Festival works on it for minutes without printing a line, so nothing but the
parent-death signal can stop it when its parent dies (a closed pipe would kill it only at its first write)."""


@needs_festival
@pytest.mark.slow
@pytest.mark.parametrize("how", [signal.SIGKILL, signal.SIGTERM])
def test_festival_dies_with_the_process_that_started_it(tmp_path, how):
    text = tmp_path / "long.txt"
    text.write_text(LONG_TEXT, encoding="utf-8")
    say = subprocess.Popen([sys.executable, "-m", "engine", "say", "--file", str(text), "-o", str(tmp_path / "x.wav")],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        children = wait_for(lambda: festival_children(say.pid))
        assert children, "say never started Festival"
        say.send_signal(how)                                 # `timeout 8 artificial-person say …`, or kill -9
        say.wait(30)
        assert wait_for(lambda: not any(alive(pid) for pid in children), 10), "Festival outlived its parent"
    finally:
        if say.poll() is None:
            say.kill()
            say.wait()
    assert not (tmp_path / "x.wav").exists()


@needs_festival
@pytest.mark.slow
def test_cancelling_a_synthesis_stops_festival():
    from engine.speech.festival import FestivalSynthesizer, SynthesisCancelled

    stop = threading.Event()
    synthesizer = FestivalSynthesizer(cancelled=stop.is_set)
    outcome: list[BaseException] = []

    def speak():
        try:
            synthesizer.synthesize(LONG_TEXT)
        except BaseException as error:
            outcome.append(error)

    worker = threading.Thread(target=speak)
    worker.start()
    children = wait_for(lambda: festival_children(os.getpid()))
    assert children
    stop.set()
    worker.join(30)
    assert not worker.is_alive()
    assert isinstance(outcome[0], SynthesisCancelled)
    assert wait_for(lambda: not any(alive(pid) for pid in children), 10)

