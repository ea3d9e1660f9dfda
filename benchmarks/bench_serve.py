"""The live service over loopback (issue 21): how soon a request shows on the frame clock, and on the screen.

    .venv/bin/python benchmarks/bench_serve.py [--sets 300] [--says 5] [--festival-server] [--lsl] [--json out.json]
    xvfb-run -a .venv/bin/python benchmarks/bench_serve.py --window [--size 320x240] ...

* ``set`` → the frame that shows it: the client notes ``time.monotonic()`` before sending, the server
  names the frame (``applied`` event, ``t``), and that frame's moment on the same clock is
  ``epoch_monotonic_s + t/1000`` (server and client share the computer's monotonic clock). p50/p95,
  in ms and in 60 Hz frames; also the time until the ``applied`` event is back at the client.
  With ``--window`` (``serve --window``: a real window drawn with OpenGL) also ``set`` → the end of the
  swap of the frame showing it (``presented_t``); headless that is the frame's moment itself.
* ``say`` → its first audio sample (``speech_start``: sample 0 is presented at that frame), beside
  Festival's own time for the same text synthesized in this process (``FestivalSynthesizer``).
* pipelined ``state`` requests answered per second on one connection.
* ``--festival-server``: the same ``say`` measure with ``serve --festival`` pointing at a
  ``festival --server`` this script starts on 127.0.0.1, beside that server's own time for the text.
* ``--lsl``: ``serve --lsl`` (its loopback-only liblsl configuration; this process uses the same),
  and how long after its frame moment (the marker's timestamp) each marker reaches an inlet here.

Real server in a subprocess (``artificial-person serve --headless|--window --port 0``), real Festival.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import signal
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from engine.live.client import LiveClient  # noqa: E402
from engine.processes import with_parent_death_signal  # noqa: E402

FRAME_MS = 1000.0 / 60.0
TEXTS = ["Hyvää päivää, mitä kuuluu?", "Moi.", "Tänään on kaunis ilma ja aurinko paistaa.",
         "Katso vasemmalle.", "Kiitos, näkemiin."]


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(q / 100.0 * (len(ordered) - 1)))]


def start_server(*options: str) -> tuple[subprocess.Popen, str]:
    shown = [] if "--window" in options else ["--headless"]
    process = subprocess.Popen([sys.executable, "-m", "engine", "serve", *shown, "--port", "0", *options],
                               cwd=ROOT, stdout=subprocess.PIPE, text=True)
    assert process.stdout is not None
    line = process.stdout.readline()
    match = re.search(r"ws://\S+", line)
    if match is None:
        process.kill()
        raise SystemExit(f"the server did not start: {line!r}")
    return process, match.group(0)


def bench_set(head: LiveClient, count: int) -> dict[str, float]:
    to_frame, to_event, to_screen = [], [], []
    for i in range(count):
        sent = time.monotonic()
        reply = head.set({"head_turn": 0.25 if i % 2 else -0.25})
        event = head.next_event()
        received = time.monotonic()
        assert event["event"] == "applied" and event["id"] == reply["id"]
        to_frame.append((head.to_local_monotonic(event["t"]) - sent) * 1000.0)
        to_event.append((received - sent) * 1000.0)
        to_screen.append((head.to_local_monotonic(event["presented_t"]) - sent) * 1000.0)
        time.sleep(0.003 * (i % 7))                       # requests land at different phases of the frame
    return {"set_to_frame_p50_ms": percentile(to_frame, 50), "set_to_frame_p95_ms": percentile(to_frame, 95),
            "set_to_frame_max_ms": max(to_frame), "set_to_applied_event_p50_ms": percentile(to_event, 50),
            "set_to_applied_event_p95_ms": percentile(to_event, 95),
            "set_to_presented_p50_ms": percentile(to_screen, 50), "set_to_presented_p95_ms": percentile(to_screen, 95),
            "set_to_presented_max_ms": max(to_screen)}


def start_festival_server() -> tuple[subprocess.Popen, int]:
    """``festival --server`` on 127.0.0.1 and a free port (Festival admits only localhost by default)."""
    import socket

    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = int(probe.getsockname()[1])
    process = subprocess.Popen(with_parent_death_signal(["festival", f"(set! server_port {port})", "--server"]),
                               stdin=subprocess.DEVNULL,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.monotonic() + 60
    while True:
        try:
            socket.create_connection(("127.0.0.1", port), timeout=1).close()
            return process, port
        except OSError:
            if process.poll() is not None or time.monotonic() > deadline:
                raise SystemExit("festival --server did not start") from None
            time.sleep(0.1)


def bench_say(head: LiveClient, count: int, festival_port: int | None = None) -> dict[str, float]:
    from engine.speech.festival import FestivalSynthesizer
    from engine.speech.festival_server import FestivalServerSynthesizer

    festival = FestivalSynthesizer() if festival_port is None else FestivalServerSynthesizer("127.0.0.1", festival_port)
    served, own = [], []
    for i in range(count):
        text = TEXTS[i % len(TEXTS)]
        started = time.monotonic()
        festival.synthesize(text)
        own.append((time.monotonic() - started) * 1000.0)
        sent = time.monotonic()
        say_id = head.say(text)
        first_sample = None
        for event in head.events_until(say_id, "finished"):
            if event["event"] == "speech_start" and event["id"] == say_id:
                first_sample = head.to_local_monotonic(event["t"])
        assert first_sample is not None
        served.append((first_sample - sent) * 1000.0)
    return {"say_to_first_sample_median_ms": statistics.median(served),
            "festival_alone_median_ms": statistics.median(own),
            "say_added_median_ms": statistics.median(s - f for s, f in zip(served, own, strict=True)),
            "say_added_max_ms": max(s - f for s, f in zip(served, own, strict=True))}


def bench_pipelined_state(head: LiveClient, count: int) -> dict[str, float]:
    started = time.monotonic()
    for i in range(count):
        head.send_raw(json.dumps({"type": "state", "id": f"p{i}"}))
    for i in range(count):
        assert head.reply_to(f"p{i}")["ok"]
    return {"pipelined_state_per_s": count / (time.monotonic() - started)}


def bench_lsl_markers(head: LiveClient, url: str, count: int) -> dict[str, float]:
    """Markers of ``count`` sets: inlet arrival (LSL clock) minus the marker's timestamp (the frame's moment)."""
    import pylsl

    from engine.live.lsl import lsl_source_id

    host, port = url.removeprefix("ws://").rsplit(":", 1)
    [info] = pylsl.resolve_byprop("source_id", lsl_source_id(host, int(port)), minimum=1, timeout=30)
    inlet = pylsl.StreamInlet(info)
    inlet.open_stream(timeout=30)
    delays = []
    for i in range(count):
        head.set({"head_turn": 0.25 if i % 2 else -0.25})
        sample, stamp = inlet.pull_sample(timeout=30)
        while sample is not None and json.loads(sample[0])["event"] != "applied":
            sample, stamp = inlet.pull_sample(timeout=30)
        delays.append((pylsl.local_clock() - stamp) * 1000.0)
        time.sleep(0.003 * (i % 7))
    return {"lsl_marker_after_frame_p50_ms": percentile(delays, 50),
            "lsl_marker_after_frame_p95_ms": percentile(delays, 95), "lsl_marker_after_frame_max_ms": max(delays)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sets", type=int, default=300)
    parser.add_argument("--says", type=int, default=5)
    parser.add_argument("--festival-server", action="store_true",
                        help="synthesize through a festival --server started here (serve --festival)")
    parser.add_argument("--lsl", action="store_true", help="serve --lsl, and measure the markers' delay")
    parser.add_argument("--window", action="store_true", help="serve --window (needs a display: run under xvfb-run)")
    parser.add_argument("--size", default="320x240", help="with --window: its size (default 320x240)")
    parser.add_argument("--json", default=None)
    args = parser.parse_args()
    options: list[str] = ["--window", "--size", args.size] if args.window else []
    festival_process, festival_port = None, None
    if args.festival_server:
        festival_process, festival_port = start_festival_server()
        options += ["--festival", f"127.0.0.1:{festival_port}"]
    if args.lsl:
        from engine.live.lsl import use_lsl_config

        use_lsl_config(None)          # loopback-only, for this process and (inherited) the server
        options.append("--lsl")
    process, url = start_server(*options)
    try:
        with LiveClient(url) as head:
            head.state()
            results = bench_set(head, args.sets)
            results.update(bench_say(head, args.says, festival_port))
            results.update(bench_pipelined_state(head, 1000))
            if args.lsl:
                results.update(bench_lsl_markers(head, url, min(args.sets, 300)))
    finally:
        process.terminate()
        process.wait(timeout=30)
        if festival_process is not None:
            os.killpg(festival_process.pid, signal.SIGTERM)
            festival_process.wait(timeout=30)
    results["set_to_frame_p95_frames"] = results["set_to_frame_p95_ms"] / FRAME_MS
    results["set_to_presented_p95_frames"] = results["set_to_presented_p95_ms"] / FRAME_MS
    for name, value in results.items():
        print(f"{name:34s} {value:10.2f}")
    if args.json:
        Path(args.json).write_text(json.dumps(results, indent=2) + "\n")


if __name__ == "__main__":
    main()
