"""``validate``: observers trained on photographs of real people judge pictures, videos or a stimulus set.

>>> from engine.cli import main
>>> main(["validate", "stimuli/", "--report", "report.html", "-o", "validation.csv"])   # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import sys
from typing import Any


def add_verbs(verbs: Any) -> None:
    from engine.validation.faces import DETECTORS

    p = verbs.add_parser("validate", help="judge pictures, videos or a stimulus set with models trained on "
                                          "photographs of people: face found, emotion, identity, lips")
    p.add_argument("inputs", nargs="+", metavar="IMAGE|VIDEO|SETDIR",
                   help="pictures and videos, a folder of them, or a stimulus set's folder (its manifest.csv "
                        "says what each stimulus was meant to show)")
    p.add_argument("--intended", metavar="CSV",
                   help="what files we did not make were meant to show: columns file and any of emotion, "
                        "identity, landmarks")
    p.add_argument("--report", metavar="R.html", help="also write a one-page HTML report with the figures")
    p.add_argument("--detector", choices=DETECTORS, default="auto",
                   help="face detector: hog (fast, frontal), cnn (slow, any pose), auto (HOG, then the CNN on "
                        "a still where HOG finds no face; default)")
    p.add_argument("-o", "--output", required=True, metavar="VALIDATION.csv",
                   help="the table, one row a file (with -confusion.csv and -identities.csv beside it)")
    p.set_defaults(run=run_validate)


def run_validate(args: argparse.Namespace) -> int:
    from engine.cli.common import require_suffix
    from engine.validation import validate, write_report, write_tables

    require_suffix(args.output, (".csv",), "a CSV table")
    if args.report is not None:
        require_suffix(args.report, (".html", ".htm"), "an HTML report")
    summary = validate(args.inputs, intended=args.intended, detector=args.detector, progress=_progress())
    written = write_tables(summary, args.output)
    if args.report is not None:
        shown = ", ".join(args.inputs) if len(args.inputs) <= 3 else f"{len(args.inputs)} files"
        write_report(summary, args.report, title=f"Validation of {shown}")
        written.append(args.report)
    faces = sum(1 for v in summary.verdicts if v.emotions is not None)
    print(f"{len(summary.verdicts)} files judged, {faces} with a face")
    if summary.scored:
        print(f"emotion read as intended: {summary.read} of {summary.scored} "
              f"({100 * summary.read / summary.scored:.0f} %)")
    if len(summary.identities) > 1:
        pairs = len(summary.identities) * (len(summary.identities) - 1) // 2
        print(f"identities: {pairs - len(summary.same_person_pairs)} of {pairs} pairs are different people")
    for path in written:
        print(f"wrote {path}")
    return 0


def _progress() -> Any:
    if not sys.stderr.isatty():
        return None

    def show(done: int, total: int, name: str) -> None:
        end = "\n" if done == total else ""
        print(f"\rvalidate: {done}/{total} {name[-60:]:<60}", end=end, file=sys.stderr, flush=True)

    return show
