"""Stimulus sets: one 10 s sentence to MP4, and a set of short clips on 1 and 2 workers and on Dask.

* Real-time factor of one ~10 s Finnish sentence to a 320×240 MP4 through
  ``make_stimulus`` (wall-clock seconds per second of speech), beside Festival
  alone (the floor: nothing is faster than the synthesizer that makes the audio).
* A set of N short clips (default 40): stimuli per minute with one local
  worker, two local workers (each kept to a core of its own: a worker is a
  core, engine/stimuli/cores.py), and one- and two-worker Dask clusters of
  local processes (127.0.0.1), and the speed-up of two over one.

    .venv/bin/python benchmarks/bench_stimuli.py [--clips 40] [--size 1280x720] [--local-only] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

from engine.speech.festival import FestivalSynthesizer
from engine.stimuli import make_set, parse_design
from engine.stimuli.make import make_stimulus

LONG = ("Sää on kaunis tänään, vaikka eilen satoi vettä koko päivän. Huomenna aurinko paistaa taas "
        "ja lämpötila nousee yli kahdenkymmenen asteen.")
SENTENCES = ["Pappa ampui pallon.", "Maija meni kotiin.", "Tule tänne heti.", "Mitä kuuluu?",
             "Kissa istui ikkunalla.", "Hyvää huomenta.", "Äiti osti omenoita.", "Ovi on auki.",
             "Lapset leikkivät pihalla.", "Juna lähtee kello kuusi."]


def one_sentence(folder: Path) -> dict[str, float]:
    design = parse_design(f'[factors]\ntext = ["{LONG}"]\n[output]\nkinds = ["mp4"]\nsize = "320x240"\n'
                          "fps = 30\n", folder / "long.toml")
    festival = FestivalSynthesizer()
    festival.synthesize(LONG)                                     # warm: voices listed, caches filled
    started = time.perf_counter()
    festival.synthesize(LONG)
    festival_s = time.perf_counter() - started
    make_stimulus(design, design.stimuli[0], folder)             # warm: model and library loaded
    started = time.perf_counter()
    record = make_stimulus(design, design.stimuli[0], folder)
    total_s = time.perf_counter() - started
    audio_s = record["duration_ms"] / 1000.0
    return {"audio_s": audio_s, "total_s": total_s, "rtf": total_s / audio_s, "festival_rtf": festival_s / audio_s}


def clip_set(folder: Path, clips: int, workers: int, scheduler: str | None = None, size: str = "320x240") -> float:
    texts = (SENTENCES * (clips // len(SENTENCES) + 1))[:clips]
    levels = ", ".join(json.dumps(t + " " * i) for i, t in enumerate(texts))   # distinct levels
    design = parse_design(f'[factors]\ntext = [{levels}]\n[output]\nkinds = ["mp4"]\nsize = "{size}"\nfps = 30\n',
                          folder / "set.toml")
    out = folder / f"set-{workers}-{'dask' if scheduler else 'local'}"
    started = time.perf_counter()
    make_set(design, out, workers=workers, scheduler=scheduler)
    return clips / ((time.perf_counter() - started) / 60.0)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clips", type=int, default=40)
    parser.add_argument("--json", type=Path)
    parser.add_argument("--size", default="320x240", help="the set's WxH (issue 36: 1280x720)")
    parser.add_argument("--local-only", action="store_true", help="only the set on 1 and 2 local workers")
    args = parser.parse_args(argv)
    if args.local_only:
        with tempfile.TemporaryDirectory() as name:
            one = clip_set(Path(name), args.clips, 1, size=args.size)
            two = clip_set(Path(name), args.clips, 2, size=args.size)
        print(f"{args.clips} clips at {args.size}: 1 local worker {one:5.1f}, 2 local workers {two:5.1f} "
              f"stimuli/min ({two / one:.2f}×)", flush=True)
        return 0
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        single = one_sentence(folder)
        print(f"one sentence, {single['audio_s']:.1f} s of speech → MP4 320×240: real-time factor "
              f"{single['rtf']:.2f} (Festival alone, the floor: {single['festival_rtf']:.3f})", flush=True)
        one = clip_set(folder, args.clips, 1, size=args.size)
        print(f"{args.clips} clips, 1 local worker:  {one:5.1f} stimuli/min", flush=True)
        two = clip_set(folder, args.clips, 2, size=args.size)
        print(f"{args.clips} clips, 2 local workers: {two:5.1f} stimuli/min ({two / one:.2f}×)", flush=True)
        from distributed import LocalCluster

        dask = {}
        for workers in (1, 2):
            with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                              dashboard_address=None, silence_logs=50) as cluster:
                dask[workers] = clip_set(folder, args.clips, workers, cluster.scheduler_address, args.size)
        print(f"{args.clips} clips, 1 Dask worker:   {dask[1]:5.1f} stimuli/min", flush=True)
        print(f"{args.clips} clips, 2 Dask workers:  {dask[2]:5.1f} stimuli/min ({dask[2] / dask[1]:.2f}× one Dask "
              f"worker, {dask[2] / one:.2f}× one local worker)", flush=True)
    if args.json:
        args.json.write_text(json.dumps({**single, "one_worker_per_min": one, "two_workers_per_min": two,
                                         "dask_one_worker_per_min": dask[1], "dask_two_workers_per_min": dask[2]},
                                        indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
