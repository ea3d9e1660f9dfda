"""Text → finished MP4 (640×480, 30 fps) for a ~10-second Finnish utterance.

Reports the real-time factor (wall-clock seconds per second of speech; below
1 is faster than real time) of the whole ``say`` pipeline, broken down into
its stages, with Festival's own synthesis time beside it as the floor:
nothing can be faster than the synthesizer that produces the audio.

    .venv/bin/python benchmarks/bench_say.py [--runs 3] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import statistics
import tempfile
import time
from pathlib import Path

from engine import load_model
from engine.outputs.video_writer import write_video
from engine.speech.festival import FestivalSynthesizer
from engine.speech.say import speak

TEXT = ("Hyvää päivää <HeadNod amplitude='60' count='2'/> ja tervetuloa. "
        "Pappa osti mummolle paljon uusia omenoita, ja äiti ja isä menivät kauppaan. "
        "Vaaleanpunainen pallo pomppi pitkin lattiaa, kun kissa katsoi sitä ikkunasta.")


def run_once(model, folder: Path) -> dict:
    synthesizer = FestivalSynthesizer()
    t0 = time.perf_counter()
    speech = speak(TEXT, model, synthesizer=synthesizer)
    t1 = time.perf_counter()
    times = speech.frame_times(30)
    values = speech.timeline.sample(times)
    t2 = time.perf_counter()
    stats = write_video(folder / "say.mp4", model, times, values, speech.timeline.parameters, 30,
                        audio=speech.utterance.samples, sample_rate=speech.utterance.sample_rate,
                        size=(640, 480))
    t3 = time.perf_counter()
    audio_s = speech.duration_ms / 1000.0
    return {
        "audio_s": audio_s,
        "total_s": t3 - t0,
        "speak_s": t1 - t0,
        "festival_s": synthesizer.last_run_seconds,
        "sample_s": t2 - t1,
        "video_s": t3 - t2,
        "deform_s": stats.deform,
        "render_s": stats.render,
        "encode_wait_s": stats.encoder_wait + stats.finish,
        "rtf": (t3 - t0) / audio_s,
        "festival_rtf": synthesizer.last_run_seconds / audio_s,
    }


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--json", default=None)
    args = parser.parse_args(argv)
    model = load_model()
    with tempfile.TemporaryDirectory() as tmp:
        results = [run_once(model, Path(tmp)) for _ in range(args.runs)]
    keys = ["audio_s", "total_s", "rtf", "festival_s", "festival_rtf", "speak_s", "sample_s", "video_s",
            "deform_s", "render_s", "encode_wait_s"]
    print(f"text → MP4, 640×480 at 30 fps, {results[0]['audio_s']:.1f} s of speech, {args.runs} runs")
    for key in keys:
        values = [r[key] for r in results]
        print(f"  {key:<14} median {statistics.median(values):7.3f}   range {min(values):.3f}–{max(values):.3f}")
    best = min(r["rtf"] for r in results)
    print(f"real-time factor {best:.2f} (goal < 1); Festival alone {min(r['festival_rtf'] for r in results):.3f}")
    if args.json:
        Path(args.json).write_text(json.dumps(results, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
