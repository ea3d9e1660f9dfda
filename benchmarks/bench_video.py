#!/usr/bin/env python3
"""Poses → MP4: time to render and encode a talking-head video, as a real-time factor.

Run from the project root::

    .venv/bin/python benchmarks/bench_video.py [--seconds 10] [--fps 30] [--size 640x480]
                                               [--antialias off|on|both] [--looks legacy,portrait]
                                               [--json out.json]

The default head (``engine.load_model()``) moves for ``--seconds`` at
``--fps``: the jaw opening and closing three times a second, the head turning,
nodding and tilting slowly, brows and eyelids moving, all on sine waves; the
audio is a 16 kHz tone (Festival's rate), so the MP4 carries AAC as ``say``'s
does. Stages, each timed on its own and then all together:

* **setup** — :class:`engine.outputs.render.FrameRenderer` made (pyvista/VTK import,
  OpenGL context, shaders compiled on the first frame);
* **deform** — ``Deformer.deform`` for every frame;
* **render** — ``FrameRenderer.render`` for every frame (new points and
  normals, draw, read the picture back);
* **encode** — the same frames piped into ffmpeg alone (libx264 + AAC, the
  settings of :mod:`engine.outputs.video_writer`), wall clock and ffmpeg's CPU time;
* **write_video** — the real thing, end to end: drawing and encoding
  overlap (ffmpeg runs in its own process), so its time is less than the sum.

Every look of ``--looks`` (docs/looks.md) is measured with every anti-aliasing
setting, one after the other in one run, and a last table puts them side by
side, each against the first (``legacy`` without anti-aliasing: the videos as
they were made before looks). Anti-aliasing "on" is the look's own method:
8× multisampling for ``legacy``, FXAA on the read-back frame for the others.

Real-time factor = wall-clock time / video length (below 1: faster than real
time). The machine is shared: the load average and how much CPU two busy
processes can get are printed with the figures, and CPU seconds per second
of video (all processes) give the cost independent of the load. The first
line names the OpenGL that draws (``software (Mesa llvmpipe)`` or ``GPU (…)``,
:mod:`engine.outputs.render_backend`).

Issue 36 at 1280 × 720 and 1920 × 1080. Before: one run each, first session, load 2.7–5.2.
After back faces were culled, the gradient put under the head in numpy and FXAA's edge search
narrowed: one run each, 2026-12-03, load 16.5–20.5. Both on software (Mesa llvmpipe), in CPU-s of
all processes per video second (``--profile 20`` gives each step of a frame; docs/export.md,
"Speed"):

=========== ======== ============= ============ ============= =============== ============
size        look     anti-aliasing render CPU  CPU-s/video-s encoder alone   before
=========== ======== ============= ============ ============= =============== ============
1280 × 720  portrait FXAA          58 ms/frame  2.98          0.67            5.12
1280 × 720  legacy   8× MSAA       187 ms/frame 6.19          0.69            8.85
1920 × 1080 portrait FXAA          93 ms/frame  4.60          1.22            9.11
=========== ======== ============= ============ ============= =============== ============
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import engine
from engine.outputs import render_backend, video_probe, video_writer
from engine.outputs.render import FrameRenderer

MOTION = {  # parameter: (centre, amplitude as a fraction of the half range, frequency Hz)
    "jaw_open": (None, 1.0, 3.0),
    "head_turn": (None, 0.5, 0.2),
    "head_nod": (None, 0.4, 0.35),
    "head_tilt": (None, 0.3, 0.15),
    "brow_raise": (None, 0.8, 0.5),
    "eyelid_left_close": (None, 1.0, 0.3),
    "eyelid_right_close": (None, 1.0, 0.3),
}


def motion(model, seconds: float, fps: float):
    """Frame times (ms), the names moved and their values (frames × names), inside each range."""
    times = np.arange(round(seconds * fps)) * (1000.0 / fps)
    names = [n for n in MOTION if n in model.parameters]
    columns = []
    for k, name in enumerate(names):
        p = model.parameters[name]
        _, amplitude, frequency = MOTION[name]
        centre, half = (p.minimum + p.maximum) / 2, (p.maximum - p.minimum) / 2
        wave = np.sin(2 * np.pi * frequency * times / 1000.0 + k)
        columns.append(np.clip(centre + amplitude * half * wave, p.minimum, p.maximum))
    return times, names, np.stack(columns, axis=1)


def tone(seconds: float, rate: int = 16000) -> np.ndarray:
    t = np.arange(int(seconds * rate)) / rate
    return (0.3 * np.sin(2 * np.pi * 220 * t) * (0.6 + 0.4 * np.sin(2 * np.pi * 4 * t))).astype(np.float32)


def children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(seconds: float, fps: float, size: tuple[int, int], antialias: bool, scratch: Path,
        look: str = "legacy") -> dict:
    model = engine.load_model()
    times, names, values = motion(model, seconds, fps)
    frames = len(times)
    full = np.tile(model.values_array(), (frames, 1))
    full[:, [model.parameters.names.index(n) for n in names]] = values
    deformer = model.deformer()
    audio = tone(seconds)

    t = time.perf_counter()
    renderer = FrameRenderer(model, size=size, antialias=antialias, look=look)
    renderer.render(model.vertices)                       # first frame: shaders compiled
    setup = time.perf_counter() - t

    t = time.perf_counter()
    positions = [deformer.deform(row) for row in full]
    deform = time.perf_counter() - t

    cpu = time.process_time()
    t = time.perf_counter()
    pictures = [renderer.render(p) for p in positions]
    render = time.perf_counter() - t
    render_cpu = time.process_time() - cpu
    renderer.close()

    wav = scratch / "tone.wav"
    video_writer._write_wav(wav, video_writer._fit_audio(audio, 16000, 0.0, frames, fps), 16000)
    out = scratch / "encode-only.mp4"
    command = ["ffmpeg", "-hide_banner", "-nostdin", "-loglevel", "error", "-y", "-f", "rawvideo",
               "-pix_fmt", "rgb24", "-s", f"{size[0]}x{size[1]}", "-framerate", video_writer._rate_text(fps),
               "-i", "pipe:0", "-i", str(wav), "-map", "0:v:0", "-map", "1:a:0", *video_writer.AUDIO_ARGS,
               *video_writer.VIDEO_ARGS, "-movflags", "+faststart", "-f", "mp4", str(out)]
    cpu = children_cpu()
    t = time.perf_counter()
    process = subprocess.Popen(command, stdin=subprocess.PIPE)
    for picture in pictures:
        process.stdin.write(picture.tobytes())
    process.stdin.close()
    process.wait()
    encode = time.perf_counter() - t
    encode_cpu = children_cpu() - cpu
    del pictures

    out = scratch / "write_video.mp4"
    cpu, children = time.process_time(), children_cpu()
    stats = video_writer.write_video(out, model, times, values, names, fps, audio=audio, sample_rate=16000,
                              size=size, antialias=antialias, look=look)
    own_cpu = time.process_time() - cpu
    info = video_probe.probe(out)
    whole = {
        "seconds": stats.total, "real_time_factor": stats.total / seconds,
        "deform": stats.deform, "render": stats.render,
        "waiting_for_encoder": stats.encoder_wait, "finishing": stats.finish,
        "encoder_cpu": stats.encoder_cpu, "python_process_cpu": own_cpu,
        "cpu_per_video_second": (own_cpu + children_cpu() - children) / seconds,
        "file_bytes": out.stat().st_size,
        "video_duration_s": info.video_duration, "audio_duration_s": info.audio_duration,
    }
    return {
        "look": look, "antialias": antialias, "frames": frames, "seconds": seconds, "fps": fps, "size": list(size),
        "setup_s": setup,
        "deform_ms_per_frame": 1000 * deform / frames,
        "render_ms_per_frame": 1000 * render / frames, "render_cpu_ms_per_frame": 1000 * render_cpu / frames,
        "encode_ms_per_frame": 1000 * encode / frames, "encode_cpu_ms_per_frame": 1000 * encode_cpu / frames,
        "sum_of_stages_s": setup + deform + render + encode,
        "write_video": whole,
        "available_cores": available_cores(),
        "load_average": os.getloadavg(),
    }


def profile(size: tuple[int, int], look: str, frames: int = 20) -> dict[str, float]:
    """CPU ms per frame (this process's, llvmpipe's threads included) of each step of
    ``FrameRenderer.render``, done one by one as it does them (docs/export.md, "Speed")."""
    from engine.outputs.antialias import fxaa
    from engine.outputs.render import _OPAQUE, copy_pose

    model = engine.load_model()
    _, names, values = motion(model, frames / 30.0, 30.0)
    full = np.tile(model.values_array(), (len(values), 1))
    full[:, [model.parameters.names.index(n) for n in names]] = values
    deformer = model.deformer()
    renderer = FrameRenderer(model, size=size, look=look)
    renderer.render(model.vertices)
    window, (width, height) = renderer._window, size
    steps: dict[str, float] = {}

    def timed(name, work, *args):
        cpu = time.process_time()
        out = work(*args)
        steps[name] = steps.get(name, 0.0) + 1000 * (time.process_time() - cpu) / len(full)
        return out

    def background_under(pixels):
        drawn = renderer._vtk_to_numpy(pixels).view(np.uint32).reshape(height, width)[::-1]
        whole = np.where(drawn >= _OPAQUE, drawn, renderer._background)
        return np.ascontiguousarray(whole.view(np.uint8).reshape(height, width, 4)[:, :, :3])

    with open(os.devnull, "wb") as sink:
        for row in full:
            positions = timed("deform", deformer.deform, row)
            timed("points and normals into VTK", copy_pose, renderer._layout, renderer._meshes, positions)
            timed("draw (llvmpipe: rasterise, shade)", lambda: (window.Render(), window.WaitForCompletion()))
            if renderer._background is not None:
                timed("read-back (RGBA)", lambda: window.GetRGBACharPixelData(0, 0, width - 1, height - 1, 1,
                                                                               renderer._pixels, 0))
                image = timed("flip, background under the head", lambda: background_under(renderer._pixels))
            else:
                timed("read-back (RGB)", lambda: window.GetPixelData(0, 0, width - 1, height - 1, 1,
                                                                      renderer._pixels, 0))
                image = timed("flip", lambda: np.ascontiguousarray(
                    renderer._vtk_to_numpy(renderer._pixels).reshape(height, width, -1)[::-1, :, :3]))
            if renderer._fxaa:
                image = timed("FXAA (numpy)", fxaa, image, False)
            timed("pipe write (rgb24, no copy)", sink.write, memoryview(image.data).cast("B"))
    renderer.close()
    return steps


def available_cores(seconds: float = 1.0) -> float:
    """How many cores' worth of CPU two busy processes get right now (the machine is shared)."""
    code = ("import time\nt = time.perf_counter(); c = time.process_time()\n"
            f"while time.perf_counter() - t < {seconds}: pass\n"
            "print(time.process_time() - c)")
    spinners = [subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
                for _ in range(os.cpu_count() or 1)]
    return sum(float(p.communicate()[0]) for p in spinners) / seconds


def report(r: dict) -> None:
    print(f"\n== {r['look']}, {r['seconds']:g} s at {r['fps']:g} fps, {r['size'][0]}x{r['size'][1]}, "
          f"antialias {_method(r) if r['antialias'] else 'off'}: {r['frames']} frames "
          f"(load average {r['load_average'][0]:.2f}; {r['available_cores']:.2f} of {os.cpu_count()} cores "
          f"free for two busy processes)")
    print(f"  setup (renderer, first frame)   {r['setup_s']:7.2f} s")
    print(f"  deform                          {r['deform_ms_per_frame']:7.2f} ms/frame")
    print(f"  render (points, draw, read)     {r['render_ms_per_frame']:7.2f} ms/frame  "
          f"(CPU {r['render_cpu_ms_per_frame']:.1f} ms)")
    print(f"  encode alone (x264 + AAC)       {r['encode_ms_per_frame']:7.2f} ms/frame  "
          f"(ffmpeg CPU {r['encode_cpu_ms_per_frame']:.1f} ms)")
    print(f"  stages one after another        {r['sum_of_stages_s']:7.2f} s  "
          f"= {r['sum_of_stages_s'] / r['seconds']:.2f}x real time")
    w = r["write_video"]
    print(f"  write_video, end to end         {w['seconds']:7.2f} s  = {w['real_time_factor']:.2f}x real time   "
          f"({w['file_bytes'] / 1e6:.2f} MB; {w['cpu_per_video_second']:.2f} CPU-s per video second)")
    print(f"    in it: deform {w['deform']:.2f} s, render {w['render']:.2f} s, waiting for ffmpeg "
          f"{w['waiting_for_encoder']:.2f} s, finishing {w['finishing']:.2f} s; CPU: ffmpeg "
          f"{w['encoder_cpu']:.2f} s, this process {w['python_process_cpu']:.2f} s (OpenGL threads included)")
    print(f"  durations: video {w['video_duration_s']:.3f} s, audio {w['audio_duration_s']:.3f} s")


def _method(r: dict) -> str:
    from engine.outputs.looks import look_from

    return {"msaa": "on (8x MSAA)", "fxaa": "on (FXAA)", "none": "on (none)"}[look_from(r["look"]).antialias]


def side_by_side(results: list[dict]) -> None:
    """One line per run: CPU time per frame drawn and per video second, each against the first run's."""
    first = results[0]
    print(f"\n== side by side, {first['size'][0]}x{first['size'][1]} (against {first['look']}, antialias "
          f"{'on' if first['antialias'] else 'off'})")
    print(f"  {'look':10s} {'antialias':14s} {'render CPU ms/frame':>20s} {'x':>6s} {'CPU-s/video-s':>14s} {'x':>6s}")
    for r in results:
        cpu = r["render_cpu_ms_per_frame"]
        whole = r["write_video"]["cpu_per_video_second"]
        print(f"  {r['look']:10s} {_method(r) if r['antialias'] else 'off':14s} {cpu:20.1f} "
              f"{cpu / first['render_cpu_ms_per_frame']:6.2f} {whole:14.2f} "
              f"{whole / first['write_video']['cpu_per_video_second']:6.2f}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--fps", type=float, default=30.0)
    parser.add_argument("--size", default="640x480", help="WxH (default 640x480)")
    parser.add_argument("--antialias", choices=("off", "on", "both"), default="both")
    parser.add_argument("--looks", default="legacy,portrait", help="looks to measure, comma-separated "
                                                                   "(default legacy,portrait)")
    parser.add_argument("--json", default=None, metavar="OUT", help="also write the figures as JSON")
    parser.add_argument("--profile", type=int, default=0, metavar="FRAMES",
                        help="first, the CPU of each step of drawing a frame, over FRAMES frames of the first look")
    args = parser.parse_args(argv)
    size = tuple(int(s) for s in args.size.lower().split("x"))
    modes = {"off": [False], "on": [True], "both": [False, True]}[args.antialias]
    results = []
    print(f"OpenGL: {render_backend.probe()['kind']}", flush=True)     # software (Mesa llvmpipe) or GPU (…)
    if args.profile:
        look = args.looks.split(",")[0]
        steps = profile(size, look, args.profile)
        print(f"\n== one frame of {look} at {size[0]}x{size[1]}, step by step ({args.profile} frames, load average "
              f"{os.getloadavg()[0]:.2f}): CPU ms per frame")
        for name, ms in steps.items():
            print(f"  {name:36s} {ms:7.2f}")
        print(f"  {'all':36s} {sum(steps.values()):7.2f}", flush=True)
    with tempfile.TemporaryDirectory(prefix="bench-video-") as scratch:
        for look in args.looks.split(","):
            for antialias in modes:
                results.append(run(args.seconds, args.fps, size, antialias, Path(scratch), look))
                report(results[-1])
    side_by_side(results)
    if args.json:
        Path(args.json).write_text(json.dumps(results, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
