"""The ``say`` verb: text (with inline commands) → audio, video and tables.

>>> from engine.cli import main
>>> main(["say", "Hyvää päivää <HeadNod amplitude='60' count='2'/> mitä kuuluu?", "-o", "hello.mp4"])  # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from engine.cli.common import (
    VIEW_NAMES,
    add_library_option,
    add_model_option,
    frame_rate,
    load_model_argument,
    read_text_file,
    seed,
    size,
)
from engine.cli.encoding_options import add_encoding_options, encoding_option
from engine.errors import UserError

OUTPUT_SUFFIXES = (".mp4", ".wav", ".xml")
#: The table options, in the order the old verb checked them: each is a kind of speech file.
TABLE_KINDS = ("tracks", "phones", "landmarks")


def add_verbs(verbs: Any) -> None:
    p = verbs.add_parser("say", help="speak text with inline commands: video, audio and tables (§2.1)")
    source = p.add_mutually_exclusive_group()
    source.add_argument("text", nargs="?", metavar="TEXT", help="the text, e.g. 'Hyvää päivää <Blink/> mitä kuuluu?'")
    source.add_argument("--file", metavar="F", help="read the text from a UTF-8 file instead")
    recorded = p.add_argument_group("a recorded voice instead of Festival (the text, if any, holds inline commands)")
    recorded.add_argument("--audio", metavar="TAKE.wav", help="the speaker's recording (PCM WAV), used unchanged")
    recorded.add_argument("--labels", metavar="LABELS",
                          help="its phone labels: a Praat TextGrid, a label file or a phones CSV")
    recorded.add_argument("--tier", default=None, metavar="NAME", help="TextGrid phone tier (default: as mocap import)")
    recorded.add_argument("--word-tier", default=None, metavar="NAME",
                          help="TextGrid word tier for inline commands (default: words, word, orthography, …)")
    recorded.add_argument("--phone-set", default="auto", metavar="NAME",
                          help="the labels' phone set: auto (default), arpabet, ipa, x-sampa, sampa, finnish, radio")
    recorded.add_argument("--phone-map", default=None, metavar="FILE",
                          help="your own labels → phones of the set: 'LABEL PHONE' per line")
    p.add_argument("--voice", default=None, metavar="V",
                   help="Festival voice (default suo_fi_lj_diphone; hy_fi_mv_diphone is the male Finnish voice)")
    p.add_argument("--festival", default=None, metavar="HOST:PORT",
                   help="synthesize with the Festival server (festival --server) at HOST:PORT, not a local Festival")
    add_model_option(p)
    add_library_option(p)
    p.add_argument("--articulation", default=None, metavar="TABLE",
                   help="phone → target table (default: the shipped table of the voice's phone set, "
                        "engine/library/articulation/*.phones; phones a table lacks get targets from their features)")
    p.add_argument("--coarticulation", choices=("cohen-massaro", "none"), default="cohen-massaro",
                   help="Cohen–Massaro dominance functions (default) or the paper's plain target interpolation")
    p.add_argument("--prosody", action="store_true",
                   help="add visual prosody: blinks, brows on accented words, nods at phrase ends")
    p.add_argument("--seed", type=seed, default=0, metavar="N", help="seed for --prosody (default 0)")
    p.add_argument("--fps", type=frame_rate, default=30.0, metavar="N", help="frames per second (default 30)")
    p.add_argument("--size", type=size, default=(640, 480), metavar="WxH", help="video size (default 640x480)")
    p.add_argument("--view", choices=VIEW_NAMES, default="front", help="camera (default front)")
    p.add_argument("--look", default=None, metavar="NAME",
                   help="lighting and shading: portrait (default), flat, legacy, or a JSON file of a look's "
                        "settings (docs/looks.md)")
    add_encoding_options(p)
    p.add_argument("-o", "--output", default=None, metavar="OUT.(mp4|wav|xml)",
                   help="video with audio (.mp4), the audio (.wav), or the low-level commands (.xml)")
    p.add_argument("--tracks", default=None, metavar="CSV", help="every parameter at every frame")
    p.add_argument("--phones", default=None, metavar="CSV", help="phone segments: start_ms,end_ms,phone,word")
    p.add_argument("--landmarks", default=None, metavar="CSV", help="landmark positions at every frame")
    p.add_argument("--quiet", action="store_true", help="no progress display")
    p.set_defaults(run=run_say)


def run_say(args: argparse.Namespace) -> int:
    """Speak the text; write every file asked for, all together (:mod:`engine.outputs.speech_files`)."""
    from engine.commands import load_library
    from engine.outputs.looks import look_option
    from engine.outputs.speech_files import write_speech_files
    from engine.outputs.video_writer import progress_printer
    from engine.speech.articulation import load_articulation
    from engine.speech.say import speak

    look = look_option(args.look) if args.look is not None else None      # a bad look before any work
    encoding = encoding_option(args)
    if not any(getattr(args, option) for option in ("output", *TABLE_KINDS)):
        raise UserError("nothing to write: give -o OUT.(mp4|wav|xml), --tracks, --phones or --landmarks")
    targets: dict[str, Path] = {}
    out = _checked_output(args.output)
    if out is not None:
        targets[out.suffix.lower().lstrip(".")] = out
    for kind in TABLE_KINDS:
        path = getattr(args, kind)
        if path is not None:
            if Path(path).suffix.lower() != ".csv":
                raise UserError(f"unknown extension '{Path(path).suffix or Path(path).name}' (use .csv)", file=path)
            targets[kind] = Path(path)
    text, name = _text(args)
    model = load_model_argument(args.model)
    library = load_library(args.library)
    table = load_articulation(args.articulation) if args.articulation else None
    prosody_seed = args.seed if args.prosody else None
    if args.audio is not None:
        from engine.speech.recorded import speak_recording

        speech = speak_recording(args.audio, args.labels, model, text=text, phone_set=args.phone_set, tier=args.tier,
                                 word_tier=args.word_tier, phone_map=args.phone_map, library=library, table=table,
                                 coarticulation=args.coarticulation, prosody_seed=prosody_seed, name=name)
    else:
        assert text is not None                                # _text refuses no text without --audio
        from engine.speech.festival_server import festival_synthesizer

        speech = speak(text, model, festival_synthesizer(args.festival), voice=args.voice, library=library, table=table,
                       coarticulation=args.coarticulation, prosody_seed=prosody_seed, name=name)
    for warning in speech.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    progress = None
    if "mp4" in targets and not args.quiet:
        progress = progress_printer("rendering", unit="frames" if len(targets) == 1 else "steps")
    write_speech_files(speech, model, targets, fps=args.fps, size=args.size, view=args.view, progress=progress,
                       look=look, encoding=encoding)
    return 0


def _checked_output(path: str | None) -> Path | None:
    if path is None:
        return None
    out = Path(path)
    if out.suffix.lower() not in OUTPUT_SUFFIXES:
        raise UserError(f"unknown output extension '{out.suffix or out.name}' for say (use .mp4, .wav or .xml)",
                        file=out)
    return out


def _text(args: argparse.Namespace) -> tuple[str | None, str]:
    recorded_options = ("labels", "tier", "word_tier", "phone_map")
    if args.audio is None:
        given = [option for option in recorded_options if getattr(args, option) is not None]
        if given or args.phone_set != "auto":
            raise UserError(f"--{(given or ['phone_set'])[0].replace('_', '-')} needs --audio TAKE.wav")
        if args.text is None and args.file is None:
            raise UserError("nothing to say: give TEXT, --file F, or --audio TAKE.wav --labels LABELS")
    else:
        if args.labels is None:
            raise UserError("--audio needs --labels (a TextGrid, label file or phones CSV with its phones)")
        if args.voice is not None:
            raise UserError("--voice applies to Festival; a recording speaks with its own voice")
        if args.festival is not None:
            raise UserError("--festival applies to synthesis; a recording speaks with its own voice")
    if args.file is None:
        return args.text, "<text>"
    return read_text_file(args.file), args.file

