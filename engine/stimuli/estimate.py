"""How long a stimulus set will take here: one stimulus made for real, the rest scaled from it.

``stimuli --dry-run`` makes the set's first stimulus still to make in a
temporary folder (thrown away), times it, and scales that time to every
other stimulus by its expected length: the characters of its text (or the
duration of its recording), its video kinds and frame rate, the same for
every stimulus of a design. The estimate is of this machine, with its load
at the moment; the cost of making each identity's head (once per worker) is
in the measured stimulus when it has one.
"""

from __future__ import annotations

import tempfile
import time
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from engine.errors import UserError
from engine.script.inline_commands import parse_script
from engine.speech.synthesis import read_wav_layout
from engine.stimuli.cores import kept_to_a_core
from engine.stimuli.design import Design, Stimulus
from engine.stimuli.make import make_stimulus

SET_SECONDS = 3.0       # the set's own work: starting workers, checks, manifest, contact sheet


@dataclass(frozen=True)
class Estimate:
    """Seconds for the stimuli to make, on ``workers`` workers, and the measured stimulus they come from."""

    seconds: float
    sample_id: str
    sample_seconds: float


def relative_length(design: Design, stimulus: Stimulus) -> float:
    """A stimulus's expected length in arbitrary units (characters spoken, or 15 per second recorded)."""
    levels = stimulus.levels
    if "audio" in levels:
        seconds = _recording_seconds(design.extra_files[levels["audio"]])
        return 30.0 if seconds is None else 15.0 * seconds
    texts = [str(levels.get(k, "")) for k in ("text", "audio_text") if k in levels]
    spoken = max((len(parse_script(t).text.strip()) for t in texts), default=0)
    return 8.0 + spoken + abs(float(levels.get("av_offset_ms", 0.0))) / 1000.0 * 15.0


def _recording_seconds(path: Path) -> float | None:
    """A recording's length, or None if it cannot be read as a WAV (the stimulus that uses it then says why);
    read once however many stimuli use it (until the file changes)."""
    try:
        info = path.stat()
    except (OSError, ValueError):
        return None
    return _wav_seconds(path, info.st_mtime_ns, info.st_size)


@lru_cache(maxsize=256)
def _wav_seconds(path: Path, _mtime_ns: int, _size: int) -> float | None:
    try:
        return read_wav_layout(path).duration_ms / 1000.0
    except UserError:
        return None


def estimate(design: Design, todo: list[Stimulus], workers: int) -> Estimate | None:
    """Make the first of ``todo`` in a temporary folder and scale its time to all of them (None if none)."""
    if not todo:
        return None
    sample = todo[0]
    with tempfile.TemporaryDirectory(prefix="ap-estimate-") as folder, kept_to_a_core():
        start = time.perf_counter()
        make_stimulus(design, sample, Path(folder))                   # as a worker makes it: on one core
        took = time.perf_counter() - start
    unit = took / relative_length(design, sample)
    workers = max(1, min(workers, len(todo)))
    # each worker's first stimulus pays the start-up the sample paid here; then the rest share the workers
    first = max(unit * relative_length(design, s) for s in todo[:workers])
    rest = sum(unit * relative_length(design, s) for s in todo[workers:]) / workers
    return Estimate(first + rest + SET_SECONDS, sample.id, took)
