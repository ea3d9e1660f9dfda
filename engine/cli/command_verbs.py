"""Command-line verbs of the command language (§2.3): ``translate``, ``tracks``, ``library``.

>>> from engine.cli import main
>>> main(["translate", "script.xml", "-o", "low.xml"])                  # doctest: +SKIP
>>> main(["tracks", "script.xml", "--fps", "60", "-o", "tracks.csv"])    # doctest: +SKIP
>>> main(["library", "-L", "my-commands"])                               # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from engine.cli.common import (
    add_library_option,
    add_model_option,
    frame_rate,
    load_model_argument,
    require_suffix,
    time_ms,
)

if TYPE_CHECKING:
    from engine.commands.command_files import Activation
    from engine.model import Model


def add_verbs(verbs: Any) -> None:
    """Add the command-language verbs to the CLI's sub-parsers."""
    p = verbs.add_parser("translate", help="translate high-level commands into low-level ones (§2.3)")
    p.add_argument("input", metavar="IN.xml", help="command file (<commands> …)")
    add_library_option(p)
    add_model_option(p)
    p.add_argument("-o", "--output", default=None, metavar="OUT.xml",
                   help="low-level command file to write (default: print it)")
    p.set_defaults(run=run_translate)

    p = verbs.add_parser("tracks", help="sample every parameter on the timeline to a CSV table")
    p.add_argument("input", metavar="IN.xml", help="command file, high- or low-level")
    add_library_option(p)
    add_model_option(p)
    p.add_argument("--fps", type=frame_rate, default=60.0, metavar="N", help="frames per second (default 60)")
    p.add_argument("--end", type=time_ms, default=None, metavar="MS",
                   help="last time to sample (default: the last key)")
    p.add_argument("-o", "--output", required=True, metavar="OUT.csv", help="tracks table to write")
    p.set_defaults(run=run_tracks)

    p = verbs.add_parser("library", help="list the command library and check it against a model")
    add_library_option(p)
    add_model_option(p)
    p.set_defaults(run=run_library)


def _add_library_option(p: argparse.ArgumentParser) -> None:
    p.add_argument("-L", "--library", dest="library", action="append", default=[], metavar="LIBDIR",
                   help="a folder of *.lib files (or one file) searched after the shipped library; "
                        "its commands override shipped ones of the same name (may be repeated)")


def _activations(args: argparse.Namespace) -> tuple[list[Activation], Model]:
    from engine.commands import load_library, read_commands, translate

    commands = read_commands(args.input)
    library = load_library(args.library)
    model = load_model_argument(args.model)
    return translate(commands, library, model), model


def run_translate(args: argparse.Namespace) -> int:
    from engine.commands import low_level_xml, write_low_level

    activations, _ = _activations(args)
    if args.output is None:
        sys.stdout.write(low_level_xml(activations))
    else:
        write_low_level(activations, require_suffix(args.output, (".xml",), "translate"))
    return 0


def run_tracks(args: argparse.Namespace) -> int:
    from engine.timeline.timeline import Timeline

    out = require_suffix(args.output, (".csv",), "tracks")
    activations, model = _activations(args)
    Timeline(activations, model).write_tracks(out, fps=args.fps, end=args.end)
    return 0


def run_library(args: argparse.Namespace) -> int:
    from engine.commands import load_library

    library = load_library(args.library)
    model = load_model_argument(args.model)
    for name in library:
        definition = library[name]
        arguments = ", ".join(f"{k}" if v is None else f"{k}={v:g}" for k, v in definition.arguments().items())
        print(f"{name:<14} {definition.procedure:<20} {arguments}")
        print(f"{'':<14} {Path(definition.file).name}:{definition.line}"
              + (f" — {definition.description}" if definition.description else ""))
    problems = library.check(model)
    for problem in problems:
        print(f"error: {problem}", file=sys.stderr)
    return 2 if problems else 0
