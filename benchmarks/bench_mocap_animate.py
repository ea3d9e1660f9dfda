#!/usr/bin/env python3
"""``mocap animate``: a capture session through the face, at 1×, 4× and 16× the take's length (issue 22 §1).

    .venv/bin/python benchmarks/bench_mocap_animate.py

A synthetic take (the default head speaking the tests' training phones, 60 Hz,
noise, gaps, head motion) is repeated 1, 4 and 16 times. For each length:
``animate_session`` (components put on the face, every frame fitted, the head
motion split) and its tracks table written, beside two references measured in
the same run: the floor, the per-frame least-squares fit alone
(``fit_frames``), and the peer, the held-out reconstruction the toolkit already
had (``reconstruct_held_out``), which does the same fit and measures it. The
cost per frame should stay flat as the take grows.
"""

import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import numpy as np

from engine import load_model
from engine.mocap.animate import animate_session, write_session_animation
from engine.mocap.apply import apply_articulation
from engine.mocap.held_out import fit_frames, reconstruct_held_out
from engine.mocap.importer import build_session
from engine.mocap.pca import multistage_pca
from engine.mocap.recording import Recording
from engine.mocap.synthetic import synthesize_recording
from tests.engine.mocap_samples import TRAINING_PHONES, parse_phones


def timed(fn):
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def session_of(rec, times: int):
    positions = np.concatenate([rec.positions] * times)
    recording = Recording(labels=list(rec.markers), positions=positions, rate_hz=rec.rate_hz,
                          source="synthetic", format="synthetic")
    return build_session(recording)


def main() -> int:
    rec = synthesize_recording(phones=parse_phones(TRAINING_PHONES), model=load_model(), seed=22)
    art = multistage_pca(session_of(rec, 1))
    head = load_model()
    applied = apply_articulation(head, art)
    print(f"{'take':>6s} {'frames':>7s} {'animate+csv':>12s} {'per frame':>10s} {'floor: fit':>11s} "
          f"{'peer: held-out':>15s}")
    with tempfile.TemporaryDirectory() as folder:
        for times in (1, 4, 16):
            session = session_of(rec, times)
            columns = [session.markers.index(m) for m in applied.markers]
            target = applied.to_model(session.positions[:, columns])
            total = timed(lambda s=session: write_session_animation(
                animate_session(s, art, load_model(), head_motion=True), Path(folder) / "take.csv"))
            floor = timed(lambda x=target: fit_frames(head, applied, x))
            peer = timed(lambda s=session: reconstruct_held_out(head, applied, art, s.markers, s.positions))
            print(f"{times:>5d}× {session.n_frames:>7d} {total:>10.2f} s {1000 * total / session.n_frames:>7.2f} ms "
                  f"{floor:>9.2f} s {peer:>13.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
