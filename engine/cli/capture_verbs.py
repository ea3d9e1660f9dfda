"""The ``capture`` verbs: ``capture animate`` (ARKit / OpenFace / MediaPipe streams onto the head).

>>> from engine.cli import main
>>> main(["capture", "animate", "take.csv", "-o", "take.mp4"])                 # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from engine.cli.common import VIEW_NAMES, add_model_option, frame_rate, load_model_argument, size


def add_verbs(verbs: Any) -> None:
    """Add ``capture`` and its steps to the CLI's sub-parsers."""
    p = verbs.add_parser("capture", help="face-capture streams (ARKit, OpenFace, MediaPipe) onto the head")
    steps = p.add_subparsers(dest="capture_step", metavar="STEP", required=True)
    add_animate(steps)


def add_animate(steps: Any) -> None:
    p = steps.add_parser("animate", help="a Live Link Face, OpenFace or MediaPipe take drives the head",
                         description="Read a face-capture take, map it onto the model's action units, jaw, lids, "
                                     "head and eyes (docs/capture-streams.md), and write the tracks table (.csv) "
                                     "or a video (.mp4).")
    p.add_argument("file", metavar="FILE", help="Live Link Face CSV, OpenFace CSV, or MediaPipe blendshapes "
                                                "(JSON or CSV)")
    p.add_argument("--format", choices=("auto", "arkit", "openface", "mediapipe"), default="auto",
                   help="the producer (default: from the header)")
    add_model_option(p)
    p.add_argument("--fps", type=frame_rate, default=None, metavar="N",
                   help="frames per second of the output (default: the take's rate); also times files "
                        "without times (OpenFace image sequences, MediaPipe frames without timestampMs)")
    p.add_argument("--audio", default=None, metavar="WAV", help="sound for the video, starting with the take")
    p.add_argument("--size", type=size, default=(640, 480), metavar="WxH", help="video size (default 640x480)")
    p.add_argument("--view", choices=VIEW_NAMES, default="front", help="camera for the video (default front)")
    p.add_argument("-o", "--output", required=True, metavar="OUT.(mp4|csv)", help="tracks table or video")
    p.set_defaults(run=run_animate)


def run_animate(args: argparse.Namespace) -> int:
    from engine.capture.animate import animate_capture

    model = load_model_argument(args.model)
    result = animate_capture(args.file, model, args.output, format=args.format, fps=args.fps, audio=args.audio,
                             size=args.size, view=args.view)
    for note in result.stream.notes:
        print(f"note: {note}", file=sys.stderr)
    for warning in result.mapped.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    for line in result.summary():
        print(line)
    return 0
