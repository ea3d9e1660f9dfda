"""The ``web-export`` verb: a folder that plays the head in a web browser, offline (docs/web-export.md).

>>> from engine.cli import main
>>> main(["web-export", "--say", "Pappa osti omenoita.", "-o", "site"])                    # doctest: +SKIP
>>> main(["web-export", "--tracks", "t.csv", "--audio", "t.wav", "-o", "site"])           # doctest: +SKIP
>>> main(["web-export", "--stimuli", "set", "-o", "site"])                                # doctest: +SKIP
>>> main(["web-export", "--stimuli", "set", "--design", "identities.toml", "-o", "site"])   # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from engine.cli.common import (
    add_library_option,
    add_model_option,
    frame_rate,
    load_model_argument,
    read_text_file,
    size,
)
from engine.errors import UserError


def add_verbs(verbs: Any) -> None:
    """Add ``web-export`` to the CLI's sub-parsers."""
    p = verbs.add_parser("web-export", help="an offline web page that plays the head (index.html?t=MS: paused at MS)")
    add_model_option(p)
    source = p.add_mutually_exclusive_group()
    source.add_argument("--say", metavar="TEXT", help="speak this text (with inline commands) with Festival")
    source.add_argument("--file", metavar="F", help="speak the text of this UTF-8 file")
    source.add_argument("--tracks", metavar="CSV", help="play a tracks CSV (time_ms,<parameter>,...) ...")
    source.add_argument("--stimuli", metavar="OUTDIR", help="every stimulus of a set made by 'stimuli' (with the "
                                                            "kinds tracks and wav): index.html?stimulus=ID")
    p.add_argument("--design", metavar="DESIGN.toml", help="with --stimuli: the design the set was made from, "
                                                           "for a set with model or identity factors (each "
                                                           "stimulus's head is made again from it)")
    p.add_argument("--audio", metavar="WAV", help="... with this audio (PCM WAV, copied unchanged)")
    p.add_argument("--phones", metavar="CSV", help="... and the words of this phones CSV for the word events")
    p.add_argument("--voice", default=None, metavar="V", help="Festival voice (default suo_fi_lj_diphone)")
    add_library_option(p)
    p.add_argument("--fps", type=frame_rate, default=60.0, metavar="N",
                   help="frames per second of the animation table for --say/--file (default 60)")
    p.add_argument("--size", type=size, default=(600, 800), metavar="WxH",
                   help="the picture's size in pixels, as render --size (default 600x800)")
    p.add_argument("--look", default=None, metavar="NAME",
                   help="lighting and shading, as render --look (default portrait; with --stimuli: the set's own)")
    p.add_argument("-o", "--output", required=True, metavar="SITE/", help="the folder to write (new, empty or an "
                                                                          "earlier site)")
    p.set_defaults(run=run_web_export)


def run_web_export(args: argparse.Namespace) -> int:
    """Write the site and print what it holds and its size."""
    from engine.outputs.looks import look_option
    from engine.web.site import check_folder, write_speech_site, write_tracks_site

    out = Path(args.output)
    look = look_option(args.look) if args.look is not None else None
    check_folder(out)                # before any synthesis: a folder of other files is refused at once
    if args.stimuli is not None:
        from engine.web.stimuli_site import write_stimuli_site

        for option in ("audio", "phones", "voice"):
            if getattr(args, option) is not None:
                raise UserError(f"--{option} does not go with --stimuli (the set holds its own)")
        heads = None
        if args.design is not None:
            if args.model is not None:
                raise UserError("-m does not go with --design (the design names each stimulus's head)")
            from engine.stimuli.design import load_design
            from engine.stimuli.set_heads import DesignHeads

            heads = DesignHeads(load_design(args.design), args.stimuli)
        model = load_model_argument(args.model) if heads is None else None
        sizes = write_stimuli_site(model, args.stimuli, out, size=args.size, heads=heads, look=look)
        count = sum(1 for name in sizes if name.endswith(".json") and name.startswith("stimuli/"))
        glbs = sorted(name for name in sizes if name.endswith(".glb"))
        print(f"wrote {out}/: {count} stimuli, {len(glbs)} head{'s' if len(glbs) > 1 else ''} "
              f"({sum(sizes[name] for name in glbs) / 1e3:.0f} kB); {sum(sizes.values()) / 1e6:.2f} MB in all")
        return 0
    if args.design is not None:
        raise UserError("--design goes with --stimuli OUTDIR")
    if args.tracks is not None:
        if args.audio is None:
            raise UserError("--tracks needs --audio WAV (the sound the tracks go with)")
        if args.voice is not None:
            raise UserError("--voice applies to --say and --file; tracks come with their own audio")
        model = load_model_argument(args.model)
        sizes = write_tracks_site(model, args.tracks, args.audio, out, phones=args.phones, size=args.size, look=look)
    else:
        for option in ("audio", "phones"):
            if getattr(args, option) is not None:
                raise UserError(f"--{option} goes with --tracks CSV")
        text, name = _text(args)
        from engine.commands import load_library
        from engine.speech.festival_server import festival_synthesizer
        from engine.speech.say import speak

        model = load_model_argument(args.model)
        library = load_library(args.library)
        speech = speak(text, model, festival_synthesizer(None), voice=args.voice, library=library, name=name)
        for warning in speech.warnings:
            print(f"warning: {warning}", file=sys.stderr)
        sizes = write_speech_site(speech, model, out, fps=args.fps, size=args.size, look=look)
    total = sum(sizes.values())
    print(f"wrote {out}/: {site_files_text(sizes)}; {total / 1e6:.2f} MB in all")
    return 0


def _text(args: argparse.Namespace) -> tuple[str, str]:
    if args.say is not None:
        return args.say, "<text>"
    if args.file is None:
        raise UserError("nothing to play: give --say TEXT, --file F, --tracks CSV --audio WAV or --stimuli OUTDIR")
    return read_text_file(args.file), args.file


def site_files_text(sizes: dict[str, int]) -> str:
    """The files a site was written with and their sizes, as the verb reports them (the player bundles
    three.js; its licence is three-LICENSE.txt).

    >>> site_files_text({"index.html": 900, "player.js": 700_000, "head.glb": 1_500})
    'index.html (1 kB), player.js (700 kB), head.glb (2 kB)'
    """
    return ", ".join(f"{name} ({size / 1e3:.0f} kB)" for name, size in sizes.items())

