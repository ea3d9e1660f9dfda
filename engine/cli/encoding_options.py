"""The video encoding options of the verbs that write an MP4 (``say``): ``--preset``, ``--crf``, ``--lossless``
(:mod:`engine.outputs.video_encoding`)."""

from __future__ import annotations

import argparse
from typing import Any

from engine.errors import UserError
from engine.outputs.video_encoding import DEFAULT_CRF, DEFAULT_PRESET, PRESETS, Encoding, check_crf, encoding_from


def add_encoding_options(parser: Any) -> None:
    group = parser.add_argument_group("video encoding (H.264; the frames' timing and the audio do not change)")
    group.add_argument("--preset", choices=PRESETS, default=None, metavar="NAME",
                       help=f"x264 preset: slower makes a smaller file of the same quality (default {DEFAULT_PRESET}; "
                            f"{', '.join(PRESETS)})")
    group.add_argument("--crf", type=_crf, default=None, metavar="N",
                       help=f"quality, 0 (best) to 51 (worst); about 6 more halves the file (default {DEFAULT_CRF:g})")
    group.add_argument("--lossless", action="store_true",
                       help="every RGB pixel kept exactly, for analysis (H.264 4:4:4 RGB: plays in ffmpeg, VLC, "
                            "mpv, not in web browsers)")


def encoding_option(args: argparse.Namespace) -> Encoding:
    """The :class:`Encoding` the options ask for (``--crf`` with ``--lossless`` is refused)."""
    table: dict[str, Any] = {}
    if args.preset is not None:
        table["preset"] = args.preset
    if args.crf is not None:
        table["crf"] = args.crf
    if args.lossless:
        table["lossless"] = True
    return encoding_from(table)


def _crf(text: str) -> float:
    try:
        return check_crf(float(text))
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number from 0 to 51, not '{text[:40]}'") from None
    except UserError as exc:                      # out of range: in argparse's own message form
        raise argparse.ArgumentTypeError(str(exc).removeprefix("encoding: crf ")) from None
