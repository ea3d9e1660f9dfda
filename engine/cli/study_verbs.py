"""``study`` and ``study-analyse``: a rating study of a stimulus set, built and analysed (docs/study.md).

>>> from engine.cli import main
>>> main(["study", "examples/study/katsyri2003.toml", "-o", "study/"])                        # doctest: +SKIP
>>> main(["study-analyse", "data/", "--set", "study/set", "-o", "report/"])                   # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from engine.cli.common import positive_int
from engine.errors import UserError


def add_verbs(verbs: Any) -> None:
    p = verbs.add_parser("study", help="a self-contained jsPsych rating study of a stimulus set (identification, "
                                       "ratings; static, dynamic, human) for a folder, a lab, JATOS, Pavlovia, "
                                       "Cognition.run")
    p.add_argument("design", metavar="DESIGN.toml", help="the study design")
    p.add_argument("-o", "--output", required=True, metavar="STUDY/", help="the folder to write (new, empty or an "
                                                                           "earlier study)")
    p.add_argument("--workers", type=positive_int, default=None, metavar="N",
                   help="workers for making the stimulus set first (as 'stimuli --workers')")
    p.set_defaults(run=run_study)

    a = verbs.add_parser("study-analyse", help="a study's CSVs summed up: recognition, confusions, Wagner's Hu, "
                                               "ratings, contrasts, the validate verdicts beside; HTML and CSV")
    a.add_argument("results", nargs="+", metavar="RESULTS",
                   help="the participants' CSVs (or folders of them, or a host's export)")
    a.add_argument("--set", metavar="SETDIR", help="the study's stimulus set: checked against the data and judged by "
                                                   "the validate observers")
    a.add_argument("--no-validate", action="store_true", help="with --set: do not run the validate observers")
    a.add_argument("--keep-inattentive", action="store_true",
                   help="keep participants who failed attention checks (default: leave them out)")
    a.add_argument("-o", "--output", required=True, metavar="REPORT/", help="the folder for report.html, figures/, "
                                                                            "and the tables")
    a.set_defaults(run=run_study_analyse)


def run_study(args: argparse.Namespace) -> int:
    from engine.study import build_study

    built = build_study(args.design, args.output, workers=args.workers,
                        progress=lambda text: print(text, file=sys.stderr) if sys.stderr.isatty() else None)
    document = built.document
    kinds = sorted({f"{t['source']} {t['presentation']}" for t in document["trials"]})
    print(f"study '{document['name']}' (study_id {document['study_id']}): {len(document['trials'])} trials per "
          f"participant ({', '.join(kinds)}), {len(document['choices'])} choices, {len(document['scales'])} scales, "
          f"{len(document['procedure']['orders'])} block orders")
    print(f"wrote {built.folder}/: index.html (open it, or python3 run-lab.py), HOSTS.md; "
          f"{built.files} files, {built.bytes / 1e6:.1f} MB" + (f"; the set made in {built.set_folder}"
                                                                if built.made_set else ""))
    return 0


def run_study_analyse(args: argparse.Namespace) -> int:
    from engine.study.analysis import analyse
    from engine.study.machine import beside_people, check_set
    from engine.study.report import write_report
    from engine.study.results import read_results

    results = read_results(_result_files(args.results))
    set_folder = Path(args.set) if args.set is not None else None
    if set_folder is not None:
        check_set(results, set_folder)
    analysis = analyse(results, min_attention=0.0 if args.keep_inattentive else 1.0)
    if set_folder is not None and not args.no_validate:
        beside_people(analysis, set_folder)
    for note in analysis.notes:
        print(f"warning: {note}", file=sys.stderr)
    written = write_report(analysis, args.output)
    kept = sum(p["included"] for p in analysis.participants)
    print(f"study '{results.study}' (study_id {results.study_id}): {kept} of {len(analysis.participants)} "
          f"participants, {len(analysis.included)} test trials")
    for row in analysis.recognition:
        if row["emotion"] == "all":
            print(f"  {row['source']} {row['presentation']}: recognised {row['hits']} of {row['trials']} "
                  f"({100 * row['rate']:.0f} %, 95 % {100 * row['ci_low']:.0f}–{100 * row['ci_high']:.0f} %), "
                  f"mean Hu {row['hu_mean']:.2f} (chance {row['pc_mean']:.2f})")
    print(f"wrote {args.output}/: report.html, {len(written) - 1} tables and figures")
    return 0


def _result_files(given: list[str]) -> list[Path]:
    files: list[Path] = []
    for name in given:
        path = Path(name)
        if path.is_dir():
            found = sorted(p for p in path.iterdir() if p.suffix.lower() in (".csv", ".txt") and p.is_file())
            if not found:
                raise UserError("holds no .csv or .txt results", file=path)
            files += found
        else:
            files.append(path)
    return files
