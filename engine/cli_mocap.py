"""The ``mocap`` verbs: ``mocap import`` (and the later analysis steps), §3.1.

Each step is one ``add_<step>(steps, add_model_option, positive_number)``
function that adds its sub-parser and sets ``run``; :data:`STEPS` lists them.

>>> from engine.cli import main
>>> main(["mocap", "import", "take1.tsv", "--map", "face.map", "--labels", "take1.TextGrid",
...       "-o", "take1.h5"])                                              # doctest: +SKIP
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .errors import UserError

SESSION_SUFFIXES = (".h5", ".hdf5")


def add_verbs(verbs, add_model_option, positive_number) -> None:
    """Add ``mocap`` and its steps to the CLI's sub-parsers."""
    p = verbs.add_parser("mocap", help="motion capture: import marker files, multistage PCA (§3.1)")
    steps = p.add_subparsers(dest="mocap_step", metavar="STEP", required=True)
    for add in STEPS:
        add(steps, add_model_option, positive_number)


def add_import(steps, add_model_option, positive_number) -> None:
    p = steps.add_parser("import", help="read a marker file (QTM TSV, C3D, TRC, CSV) into a session file",
                         description="Read a marker file, name the markers, fill short gaps, remove head "
                                     "motion and attach phone labels; writes a session (HDF5) and prints "
                                     "the gap report. See docs/mocap.md.")
    p.add_argument("file", metavar="FILE", help="marker file: .tsv (Qualisys QTM), .c3d, .trc or .csv")
    p.add_argument("--format", choices=("auto", "tsv", "c3d", "trc", "csv"), default="auto",
                   help="file format (default: from the content, then the extension)")
    p.add_argument("--map", dest="mapping", default=None, metavar="MAPFILE",
                   help="'label = id' lines naming the file's markers by MPEG-4 feature point (id '-' drops one)")
    p.add_argument("--max-gap", type=_non_negative, default=100.0, metavar="MS",
                   help="fill gaps up to this long with a cubic spline; longer ones stay missing (default 100)")
    p.add_argument("--reference", type=_marker_list, default=None, metavar="ID,ID,...",
                   help="head-fixed markers to remove head motion with (default: the 9.x/10.x/11.x/20.x "
                        "reference points present; 'none' keeps the head motion)")
    p.add_argument("--reference-frame", type=_reference_frame, default="first", metavar="first|mean|N",
                   help="align to the first frame with every reference marker (default), their mean shape, "
                        "or frame N (0-based)")
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


STEPS = [add_import]


def run_import(args) -> int:
    from .mocap.csv_table import CsvLayout
    from .mocap.importer import format_report, import_marker_file
    from .mocap.session import save_session

    out = Path(args.output)
    if out.suffix.lower() not in SESSION_SUFFIXES:
        raise UserError(f"unknown output extension '{out.suffix or out.name}' for a session (use .h5)", file=out)
    csv_given = args.columns or args.time_column or args.rate or args.units != "mm"
    if csv_given and Path(args.file).is_file():
        from .mocap.readers import detect_format

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
                                 stretch_text=args.stretch_text, csv_layout=layout)
    save_session(session, out)
    print(format_report(session))
    print(f"wrote {out}")
    return 0


# -- argument types ------------------------------------------------------------

def _non_negative(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
    if not (value >= 0 and value != float("inf")):
        raise argparse.ArgumentTypeError(f"'{text}' must be 0 or more")
    return value


def _marker_list(text: str) -> list[str]:
    if text.strip().lower() == "none":
        return []
    names = [t.strip() for t in text.split(",") if t.strip()]
    if not names:
        raise argparse.ArgumentTypeError(f"'{text}' names no markers (e.g. 9.3,11.1,20.1 or none)")
    return names


def _reference_frame(text: str):
    if text in ("first", "mean"):
        return text
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not first, mean or a frame number") from None
