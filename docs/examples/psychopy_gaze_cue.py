"""A gaze-cueing trial driven over the live service: speak, nod at a word, look left on cue, log every event.

    artificial-person serve --window &          # or --headless: nothing drawn, the same events
    python docs/examples/psychopy_gaze_cue.py --url ws://127.0.0.1:8765 --log gaze_cue_log.csv

Each trial: the head says a sentence whose inline ``<HeadNod/>`` nods at the word after it; when the
sentence has finished, the head looks left 500 ms later (a ``set`` placed at a frame-clock time);
then it looks ahead again. Every event is written to the log with the frame it was shown in (``t``),
when it was due (``onset_t``), when that frame was on the screen (``presented_t``: with
``serve --window`` the end of its swap, headless the frame's moment), the audio sample clock
(``sample``; ``audio_t``, in a window, when the first sample reached the sound output), and — for
this computer's clock — the frame's and the presentation's ``time.monotonic()`` moments and when the
event reached this script.

The same script works unchanged when the server synthesizes with a Festival server on another
computer (``serve --headless --festival speech-pc:1314``) or also sends every event to an EEG
recording as Lab Streaming Layer markers (``serve --headless --lsl``): the tests run it both ways.

In PsychoPy, ``psychopy.core.getTime()`` is ``time.monotonic()``-based on Linux too (PsychoPy's
``MonotonicClock``), so ``frame_monotonic_s`` lines up with your own stimulus and response times on
the same computer. PsychoPy itself is not needed to run this script.
"""

from __future__ import annotations

import argparse
import csv
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from engine.live.client import LiveClient

SENTENCE = "Katso <HeadNod amplitude='40'/> tänne, ja sitten vasemmalle."
LOOK_LEFT = {"head_turn": 0.3, "eye_left_turn": 0.4, "eye_right_turn": 0.4}   # + towards the head's own left
LOOK_AHEAD = {"head_turn": 0.0, "eye_left_turn": 0.0, "eye_right_turn": 0.0}
CUE_DELAY_MS = 500.0
COLUMNS = ("trial", "request", "event", "word", "phone", "command", "t", "onset_t", "presented_t", "sample",
           "sample_rate", "audio_t", "frame_monotonic_s", "presented_monotonic_s", "received_monotonic_s")


def run_trial(head: LiveClient, trial: int, log: csv.DictWriter) -> None:
    def write(event: dict, request: str) -> None:
        row = {name: event.get(name, "") for name in COLUMNS}
        received = time.monotonic()
        row.update(trial=trial, request=request, frame_monotonic_s=f"{head.to_local_monotonic(event['t']):.6f}",
                   presented_monotonic_s=f"{head.to_local_monotonic(event['presented_t']):.6f}",
                   received_monotonic_s=f"{received:.6f}")
        log.writerow(row)

    say_id = head.say(SENTENCE)
    finished_t = None
    for event in head.events_until(say_id, "finished"):
        write(event, "say")
        if event.get("id") == say_id and event["event"] == "finished":
            finished_t = event["t"]
    assert finished_t is not None
    for values, request, at in ((LOOK_LEFT, "look_left", finished_t + CUE_DELAY_MS),
                                (LOOK_AHEAD, "look_ahead", finished_t + 2 * CUE_DELAY_MS)):
        reply = head.set(values, at=at)
        event = head.next_event()
        while event.get("id") != reply["id"]:
            event = head.next_event()
        write({**event, "onset_t": at}, request)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--url", default="ws://127.0.0.1:8765")
    parser.add_argument("--token", default=None)
    parser.add_argument("--trials", type=int, default=1)
    parser.add_argument("--log", default="gaze_cue_log.csv")
    args = parser.parse_args()
    with LiveClient(args.url, token=args.token) as head, open(args.log, "w", newline="", encoding="utf-8") as out:
        log = csv.DictWriter(out, fieldnames=COLUMNS)
        log.writeheader()
        head.state()                                               # the clock, for frame_monotonic_s
        for trial in range(1, args.trials + 1):
            run_trial(head, trial, log)


if __name__ == "__main__":
    main()
