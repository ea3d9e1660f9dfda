"""``validate`` on one core: pictures per second, video frames per second, and a 40-stimulus set
judged beside the time it took to make it (the goal: validating a set costs less than making it).

* Pictures: renders of the default head at 320×240 and 640×480, and scikit-image's astronaut
  (512×512, a photograph), each judged whole (face, 68 points, emotion, descriptor).
* Video: a 3 s clip of the head speaking at 320×240 and 640×480, 30 fps, judged frame by frame;
  beside it, ffmpeg decoding the same frames alone (the floor: nothing judges a frame it has
  not decoded).
* A set: N clips (default 40) made by ``stimuli`` with one worker (MP4 + PNG, 320×240), then
  judged by ``validate``; both in this process, on the same core.

The observers' start-up (loading 130 MB of models) is timed once and left out of the rates.

    .venv/bin/python benchmarks/bench_validate.py [--clips 40] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
import time
from pathlib import Path

from engine.formats.model_files import load_model
from engine.outputs.render import FrameRenderer
from engine.stimuli import make_set, parse_design
from engine.validation import judge_file, judge_pixels, validate
from engine.validation.media import open_media
from engine.validation.observers import observers

SENTENCES = ["Pappa ampui pallon.", "Maija meni kotiin.", "Tule tänne heti.", "Mitä kuuluu?",
             "Kissa istui ikkunalla.", "Hyvää huomenta.", "Äiti osti omenoita.", "Ovi on auki.",
             "Lapset leikkivät pihalla.", "Juna lähtee kello kuusi."]


def one_core() -> None:
    """Keep this process (and the ffmpeg and Festival it starts) to one core."""
    core = min(os.sched_getaffinity(0))
    os.sched_setaffinity(0, {core})


def pictures(repeats: int = 5) -> dict[str, float]:
    from skimage import data

    head = load_model()
    out = {}
    for size in ((320, 240), (640, 480)):
        renderer = FrameRenderer(head, size=size, view="front")
        try:
            frame = renderer.render(head.deform({}))
        finally:
            renderer.close()
        out[f"render {size[0]}×{size[1]}"] = _rate(lambda f=frame: judge_pixels(f, "render"), repeats)
    photo = data.astronaut()
    out["astronaut 512×512"] = _rate(lambda: judge_pixels(photo, "astronaut"), repeats)
    return out


def video(folder: Path) -> dict[str, dict[str, float]]:
    from engine.cli import main

    out = {}
    for size in ("320x240", "640x480"):
        path = folder / f"clip-{size}.mp4"
        status = main(["say", "Pappa ampui pallon, mamma meni mökille.", "--size", size, "--fps", "30",
                       "--quiet", "-o", str(path)])
        assert status == 0
        frames = sum(1 for _ in open_media(path).frames())
        started = time.perf_counter()
        sum(1 for _ in open_media(path).frames())
        decode = time.perf_counter() - started
        started = time.perf_counter()
        verdict = judge_file(path)
        judged = time.perf_counter() - started
        assert verdict.frames == frames, verdict.status
        out[size] = {"frames": frames, "frames_per_s": frames / judged, "decode_only_frames_per_s": frames / decode}
    return out


def a_set(folder: Path, clips: int) -> dict[str, float]:
    texts = (SENTENCES * (clips // len(SENTENCES) + 1))[:clips]
    levels = ", ".join(json.dumps(t + " " * i) for i, t in enumerate(texts))
    design = parse_design(f'[factors]\ntext = [{levels}]\n[output]\nkinds = ["mp4", "png"]\nsize = "320x240"\n'
                          "fps = 30\n", folder / "set.toml")
    out = folder / "set"
    started = time.perf_counter()
    make_set(design, out, workers=1)
    made = time.perf_counter() - started
    started = time.perf_counter()
    summary = validate([out])
    judged = time.perf_counter() - started
    assert all(v.status == "ok" for v in summary.verdicts), [v.status for v in summary.verdicts]
    return {"clips": clips, "make_s": made, "validate_s": judged, "validate_over_make": judged / made}


def _rate(call: object, repeats: int) -> float:
    assert callable(call)
    call()
    started = time.perf_counter()
    for _ in range(repeats):
        call()
    return repeats / (time.perf_counter() - started)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clips", type=int, default=40)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args(argv)
    one_core()
    started = time.perf_counter()
    observers()
    load = time.perf_counter() - started
    print(f"observers loaded in {load:.2f} s (once a process)", flush=True)
    rates = pictures()
    for name, rate in rates.items():
        print(f"picture, {name}: {rate:.2f} pictures/s", flush=True)
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        clips = video(folder)
        for size, figures in clips.items():
            print(f"video {size}, {figures['frames']:.0f} frames: {figures['frames_per_s']:.1f} frames/s "
                  f"(ffmpeg decoding alone: {figures['decode_only_frames_per_s']:.0f} frames/s)", flush=True)
        made = a_set(folder, args.clips)
        print(f"{args.clips} stimuli (MP4 + PNG, 320×240): made in {made['make_s']:.1f} s, validated in "
              f"{made['validate_s']:.1f} s ({made['validate_over_make']:.2f}× the making)", flush=True)
    results = {"load_s": load, "pictures_per_s": rates, "video": clips, "set": made}
    if args.json:
        args.json.write_text(json.dumps(results, indent=2, default=float))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
