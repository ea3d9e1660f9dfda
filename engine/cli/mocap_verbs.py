"""The ``mocap`` verbs: ``mocap import``, ``mocap pca``, ``mocap apply`` (§3.1), ``mocap animate``,
``mocap learn``.

Each step is one ``add_<step>(steps)``
function that adds its sub-parser and sets ``run``; :data:`STEPS` lists them.

>>> from engine.cli import main
>>> main(["mocap", "import", "take1.tsv", "--map", "face.map", "--labels", "take1.TextGrid",
...       "-o", "take1.h5"])                                              # doctest: +SKIP
>>> main(["mocap", "pca", "take1.h5", "--select", "V", "C", "--plot", "pcs.png", "-o", "art.h5"])  # doctest: +SKIP
>>> main(["mocap", "apply", "art.h5", "--held-out", "take1.h5", "-o", "head-pca.xml"])  # doctest: +SKIP
>>> main(["mocap", "animate", "take1.h5", "--articulation", "art.h5", "--audio", "take1.wav",
...       "--head-motion", "-o", "take1.mp4"])                            # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path
from typing import Any

from engine.cli.common import (
    VIEW_NAMES,
    add_model_option,
    load_model_argument,
    model_output,
    non_negative,
    output_file,
    positive_int,
    positive_number,
    quoted,
    size,
    time_ms,
)
from engine.errors import UserError

SESSION_SUFFIXES = (".h5", ".hdf5")


def add_verbs(verbs: Any) -> None:
    """Add ``mocap`` and its steps to the CLI's sub-parsers."""
    p = verbs.add_parser("mocap", help="motion capture: import marker files, multistage PCA (§3.1)")
    steps = p.add_subparsers(dest="mocap_step", metavar="STEP", required=True)
    for add in STEPS:
        add(steps)


def add_import(steps: Any) -> None:
    p = steps.add_parser("import", help="read a marker file (QTM TSV, C3D, TRC, CSV) into a session file",
                         description="Read a marker file, name the markers, fill short gaps, remove head "
                                     "motion and attach phone labels; writes a session (HDF5) and prints "
                                     "the gap report. See docs/mocap.md.")
    p.add_argument("file", metavar="FILE", help="marker file: .tsv (Qualisys QTM), .c3d, .trc or .csv")
    p.add_argument("--format", choices=("auto", "tsv", "c3d", "trc", "csv"), default="auto",
                   help="file format (default: from the content, then the extension)")
    p.add_argument("--map", dest="mapping", default=None, metavar="MAPFILE",
                   help="'label = id' lines naming the file's markers by MPEG-4 feature point (id '-' drops one)")
    p.add_argument("--max-gap", type=non_negative, default=100.0, metavar="MS",
                   help="fill gaps up to this long with a cubic spline; longer ones stay missing (default 100)")
    p.add_argument("--reference", type=_marker_list, default=None, metavar="ID,ID,...",
                   help="head-fixed markers to remove head motion with (default: the 9.x/10.x/11.x/20.x "
                        "reference points present; 'none' keeps the head motion)")
    p.add_argument("--reference-frame", type=_reference_frame, default="first", metavar="first|mean|N",
                   help="align to the first frame with every reference marker (default), their mean shape, "
                        "or frame N (0-based)")
    p.add_argument("--up", default="auto", metavar="auto|X|Y|Z|-X|-Y|-Z",
                   help="the file's up axis; the markers are turned to the toolkit's +Y up, +Z facing "
                        "(default auto: found from the MPEG-4-named markers, else kept)")
    labels = p.add_mutually_exclusive_group()
    labels.add_argument("--labels", default=None, metavar="TEXTGRID|LABELS",
                        help="phone labels: a Praat TextGrid, a 'start end label' file (seconds) or a phones CSV")
    labels.add_argument("--text", default=None, metavar="TEXT",
                        help="the spoken text: phone labels from Festival's timing of it")
    p.add_argument("--tier", default=None, metavar="NAME", help="TextGrid tier to read (default: the phone tier)")
    p.add_argument("--voice", default=None, metavar="V", help="Festival voice for --text")
    p.add_argument("--stretch-text", action="store_true",
                   help="stretch Festival's timing of --text over the whole recording")
    csv = p.add_argument_group("CSV tables")
    csv.add_argument("--columns", default=None, metavar="PATTERN",
                     help="marker column names with {marker} and {axis}, e.g. '{marker}_pos_{axis}' "
                          "(default: {marker}_{axis}, {marker}.{axis}, '{marker} {axis}', {marker}:{axis})")
    csv.add_argument("--time-column", default=None, metavar="NAME",
                     help="time column (default time_ms, time_s, time or t; _ms names are ms, others s)")
    csv.add_argument("--rate", type=positive_number, default=None, metavar="HZ",
                     help="frames per second (needed without a time column)")
    csv.add_argument("--units", choices=("mm", "cm", "m"), default="mm", help="coordinate unit (default mm)")
    p.add_argument("-o", "--output", required=True, metavar="SESSION.h5", help="session file to write")
    p.set_defaults(run=run_import)


def add_pca(steps: Any) -> None:
    p = steps.add_parser("pca", help="multistage PCA of a session → articulation file (§3.1.2)",
                         description="Stage 1 on the jaw marker(s), its contribution regressed out, stage 2 on "
                                     "the lips, …; writes the articulation file and prints the "
                                     "explained variance per component and stage. See docs/mocap-pca.md.")
    p.add_argument("session", metavar="SESSION.h5", help="session file from 'mocap import'")
    count = p.add_mutually_exclusive_group()
    count.add_argument("--components", type=positive_int, default=None, metavar="N",
                       help="N components: 1 from the jaw (2.1), N-1 from the lips (8.x) (default 5, as the paper)")
    count.add_argument("--stage", action="append", default=None, metavar="MARKERS:N",
                       help="one stage, e.g. '2.1:1' then '8.*:4' (repeat, in order; globs allowed)")
    frames = p.add_mutually_exclusive_group()
    frames.add_argument("--select", nargs="+", default=None, metavar="SEL",
                        help="frames at the middle of phones: V (vowels), C (consonants), 'm,p,b', contexts "
                             "like a/p_p (needs phone labels in the session)")
    frames.add_argument("--frames", default=None, metavar="LIST", help="explicit frames, e.g. '0-99,120,200-300:5'")
    p.add_argument("--analysed", type=_marker_list, default=None, metavar="ID,ID,...",
                   help="markers the components describe (default: those the stages name)")
    p.add_argument("--plot", default=None, metavar="PNG", help="also draw the components as marker displacements")
    p.add_argument("-o", "--output", required=True, metavar="ARTICULATION.h5", help="articulation file to write")
    p.set_defaults(run=run_pca)


def add_apply(steps: Any) -> None:
    p = steps.add_parser("apply", help="articulation components onto a model as translation parameters (§3.1.2)",
                         description="One field translation parameter per component, its displacement "
                                     "interpolated from the markers over the lips and jaw (cheeks outside). "
                                     "See docs/mocap-pca.md.")
    p.add_argument("articulation", metavar="ARTICULATION.h5", help="file from 'mocap pca'")
    add_model_option(p)
    p.add_argument("--names", default=None, metavar="articulatory|A,B,...",
                   help="parameter names: 'articulatory' (jaw-like, widen, …), or a comma list "
                        "(default pca1 … pcaN)")
    p.add_argument("--prefix", default=None, metavar="P", help="prefix for the default names (default 'pca')")
    p.add_argument("--parent", default="auto", metavar="NAME",
                   help="parent parameter (default: the rigid parameter carrying the upper lip)")
    p.add_argument("--range", dest="value_range", type=_value_range, default=(-3.0, 3.0), metavar="MIN,MAX",
                   help="range of each parameter in standard deviations (default -3,3)")
    p.add_argument("--inner", type=non_negative, default=8.0, metavar="MM",
                   help="surface distance from the markers where weights start to fall (default 8)")
    p.add_argument("--outer", type=positive_number, default=20.0, metavar="MM",
                   help="surface distance where weights reach 0 (default 20)")
    p.add_argument("--held-out", default=None, metavar="SESSION.h5",
                   help="reconstruct this session's frames through the face and report the error at the markers "
                        "(the analysed session: the frames the PCA did not use)")
    p.add_argument("--register", action="store_true", help="align --held-out to the articulation's markers first")
    p.add_argument("-o", "--output", required=True, metavar="MODEL.xml", help="model to write (with its .h5)")
    p.set_defaults(run=run_apply)


def add_animate(steps: Any) -> None:
    p = steps.add_parser("animate", help="a session drives the face through its articulation components",
                         description="Fit the articulation components to every frame's markers, optionally turn "
                                     "the head as the recording's head moved, and write the tracks table (.csv) "
                                     "or a video (.mp4) with the take's sound; report, per marker, the RMS "
                                     "distance between the recording and the animated face. "
                                     "See docs/mocap-pca.md.")
    p.add_argument("session", metavar="SESSION.h5", help="session from 'mocap import'")
    p.add_argument("--articulation", required=True, metavar="ARTICULATION.h5", help="file from 'mocap pca'")
    add_model_option(p)
    p.add_argument("--prefix", default=None, metavar="P",
                   help="component parameter names are P1 … PN (default 'pca', as 'mocap apply' names them)")
    p.add_argument("--head-motion", action="store_true",
                   help="turn, nod and tilt the head as the recording's head moved (from its first aligned frame)")
    p.add_argument("--audio", default=None, metavar="TAKE.wav", help="the take's sound, for a video")
    p.add_argument("--audio-offset", type=time_ms, default=0.0, metavar="MS",
                   help="when the sound's first sample plays relative to the first frame, ms (positive: later)")
    p.add_argument("--size", type=size, default=(640, 480), metavar="WxH", help="video size (default 640x480)")
    p.add_argument("--view", choices=VIEW_NAMES, default="front", help="camera for the video (default front)")
    p.add_argument("-o", "--output", required=True, metavar="OUT.(mp4|csv)", help="tracks table or video")
    p.set_defaults(run=run_animate)


def add_learn(steps: Any) -> None:
    p = steps.add_parser("learn", help="learn the coarticulation of a phone table from phone-labelled sessions",
                         description="Read the sessions as the model's articulatory tracks, fit every seen phone's "
                                     "targets, dominances and rates (Cohen–Massaro) toward the starting table, "
                                     "report the trajectory error at the lip markers on held-out utterances "
                                     "(learned, starting table, plain interpolation) and write the learned "
                                     "table for 'say --articulation'. See docs/mocap-learn.md.")
    p.add_argument("sessions", nargs="+", metavar="SESSION.h5", help="sessions from 'mocap import' with phone labels")
    p.add_argument("--articulation", required=True, metavar="ARTICULATION.h5",
                   help="file from 'mocap pca' on a take of the same speaker and markers: its markers are the ones "
                        "fitted and measured, its alignment places them on the model")
    add_model_option(p)
    p.add_argument("--table", default=None, metavar="TABLE.phones",
                   help="the phone table to start from and regularise toward (default: the shipped Finnish one)")
    p.add_argument("--holdout", default="0%", metavar="PERCENT",
                   help="utterances (speech between pauses) kept out of the fit and measured, e.g. 20%% (default 0%%)")
    p.add_argument("-o", "--output", required=True, metavar="LEARNED.phones", help="phone table to write")
    p.set_defaults(run=run_learn)


STEPS = [add_import, add_pca, add_apply, add_animate, add_learn]


def run_learn(args: argparse.Namespace) -> int:
    from engine.mocap.articulation_file import load_articulation_file
    from engine.mocap.coarticulation_learning import learn_coarticulation, parse_holdout
    from engine.mocap.session import load_session
    from engine.speech.articulation import load_articulation
    from engine.speech.articulation_writer import write_articulation

    out = _suffix(args.output, (".phones",), "a phone table")
    holdout = parse_holdout(args.holdout)
    table = load_articulation(args.table)
    model = load_model_argument(args.model)
    art = load_articulation_file(args.articulation)
    sessions = [(str(path), load_session(path)) for path in args.sessions]
    learned = learn_coarticulation(sessions, art, model, table, holdout)
    write_articulation(learned.table, out, learned.header())
    print(learned.report(), end="")
    print(f"wrote {out}")
    return 0


def run_import(args: argparse.Namespace) -> int:
    from engine.mocap.csv_table import CsvLayout
    from engine.mocap.importer import format_report, import_marker_file
    from engine.mocap.session import save_session

    out = Path(args.output)
    if out.suffix.lower() not in SESSION_SUFFIXES:
        raise UserError(f"unknown output extension '{out.suffix or out.name}' for a session (use .h5)", file=out)
    output_file(args.output)
    csv_given = args.columns or args.time_column or args.rate or args.units != "mm"
    if csv_given and Path(args.file).is_file():
        from engine.mocap.readers import detect_format

        if (detect_format(args.file) if args.format == "auto" else args.format) != "csv":
            raise UserError("--columns, --time-column, --rate and --units apply to CSV tables only")
    layout = CsvLayout(columns=args.columns, time_column=args.time_column, rate_hz=args.rate, units=args.units)
    if args.tier is not None and args.labels is None:
        raise UserError("--tier needs --labels TEXTGRID")
    if (args.voice or args.stretch_text) and args.text is None:
        raise UserError("--voice and --stretch-text need --text")
    session = import_marker_file(args.file, format=args.format, mapping=args.mapping, max_gap_ms=args.max_gap,
                                 reference=args.reference, reference_frame=args.reference_frame,
                                 labels=args.labels, tier=args.tier, text=args.text, voice=args.voice,
                                 stretch_text=args.stretch_text, csv_layout=layout, up=args.up)
    save_session(session, out)
    print(format_report(session))
    print(f"wrote {out}")
    return 0


def run_pca(args: argparse.Namespace) -> int:
    from engine.mocap.articulation_file import save_articulation_file
    from engine.mocap.component_plot import plot_components
    from engine.mocap.frame_selection import parse_frame_list, select_frames
    from engine.mocap.pca import default_stages, multistage_pca, parse_stage
    from engine.mocap.session import load_session

    out = _suffix(args.output, (".h5", ".hdf5"), "an articulation file")
    plot = _suffix(args.plot, (".png",), "the plot") if args.plot else None
    session = load_session(args.session)
    stages = [parse_stage(s) for s in args.stage] if args.stage else default_stages(args.components or 5)
    frames = None
    if args.select:
        if not session.phones:
            raise UserError("the session has no phone labels to select frames by: import it with --labels or "
                            "--text, or give --frames", file=args.session)
        frames = select_frames(session.phones, session.n_frames, session.rate_hz, args.select)
    elif args.frames:
        frames = parse_frame_list(args.frames, session.n_frames)
    art = multistage_pca(session, stages=stages, frames=frames, analysed=args.analysed,
                         source_name=str(args.session))
    save_articulation_file(art, out)
    if plot is not None:
        plot_components(art, plot)
    print(art.report())
    print(f"wrote {out}" + (f" and {plot}" if plot else ""))
    return 0


def run_apply(args: argparse.Namespace) -> int:
    import numpy as np

    from engine.formats.model_files import save_model
    from engine.mocap.apply import apply_articulation
    from engine.mocap.articulation_file import load_articulation_file
    from engine.mocap.frame_selection import reselect_frames
    from engine.mocap.held_out import reconstruct_held_out
    from engine.mocap.session import load_session

    out = _suffix(args.output, (".xml",), "a model")
    model_output(out)
    if args.inner >= args.outer:
        raise UserError(f"--inner ({args.inner:g} mm) must be less than --outer ({args.outer:g} mm)")
    art = load_articulation_file(args.articulation)
    model = load_model_argument(args.model)
    names = args.names
    if names is not None and names != "articulatory":
        names = [n.strip() for n in names.split(",") if n.strip()]
    applied = apply_articulation(model, art, names=names, prefix=args.prefix,
                                 parent=None if args.parent == "none" else args.parent,
                                 value_range=args.value_range, inner_mm=args.inner, outer_mm=args.outer)
    print(applied.report())
    for warning in applied.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    if args.held_out:
        session = load_session(args.held_out)
        frames = np.arange(session.n_frames)
        same_session = bool(art.source) and Path(args.held_out).resolve() == Path(art.source).resolve()
        if same_session:
            used = reselect_frames(art.selection, session.phones, session.n_frames, session.rate_hz)
            frames = np.setdiff1d(frames, used)
        if frames.size == 0:
            raise UserError("no held-out frames: the PCA analysed every frame of this session", file=args.held_out)
        error = reconstruct_held_out(model, applied, art, session.markers, session.positions[frames],
                                     register=args.register)
        print(error.report())
    save_model(model, out)
    print(f"wrote {out}")
    return 0


def _suffix(path: str, allowed: tuple[str, ...], what: str) -> Path:
    out = Path(path)
    if out.suffix.lower() not in allowed:
        raise UserError(f"unknown extension '{out.suffix or out.name}' for {what} (use {' or '.join(allowed)})",
                        file=out)
    return output_file(path)


# -- argument types ------------------------------------------------------------

def _value_range(text: str) -> tuple[float, float]:
    parts = text.split(",")
    try:
        lo, hi = (float(p) for p in parts)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{quoted(text)} is not MIN,MAX (e.g. -3,3)") from None
    if not (math.isfinite(lo) and math.isfinite(hi)):
        raise argparse.ArgumentTypeError(f"{quoted(text)}: MIN and MAX must be finite numbers")
    if not lo < hi:
        raise argparse.ArgumentTypeError(f"'{text}': MIN must be less than MAX")
    return lo, hi


def _marker_list(text: str) -> list[str]:
    if text.strip().lower() == "none":
        return []
    names = [t.strip() for t in text.split(",") if t.strip()]
    if not names:
        raise argparse.ArgumentTypeError(f"'{text}' names no markers (e.g. 9.3,11.1,20.1 or none)")
    return names


def _reference_frame(text: str) -> str | int:
    if text in ("first", "mean"):
        return text
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not first, mean or a frame number") from None


def run_animate(args: argparse.Namespace) -> int:
    from engine.mocap.animate import animate_session, write_session_animation
    from engine.mocap.articulation_file import load_articulation_file
    from engine.mocap.session import load_session
    from engine.outputs.animation_file import check_output

    if args.audio is None and args.audio_offset != 0.0:
        raise UserError("--audio-offset needs --audio")
    check_output(args.output, args.audio)
    model = load_model_argument(args.model)
    session = load_session(args.session)
    art = load_articulation_file(args.articulation)
    animation = animate_session(session, art, model, head_motion=args.head_motion, prefix=args.prefix)
    out = write_session_animation(animation, args.output, audio=args.audio, audio_offset_ms=args.audio_offset,
                                  size=args.size, view=args.view)
    for warning in animation.applied.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    print(animation.report(), end="")
    print(f"wrote {out}")
    return 0

