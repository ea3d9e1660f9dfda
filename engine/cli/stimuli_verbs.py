"""``stimuli``: a design file in, a reproducible, checked set of stimuli out (docs/stimuli.md)."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from engine.cli.common import positive_int
from engine.errors import UserError


def add_verbs(verbs: Any) -> None:
    p = verbs.add_parser("stimuli", help="make a stimulus set from a design file (TOML): every combination, "
                                         "with manifest, checks and provenance")
    p.add_argument("design", metavar="DESIGN.toml", help="the design: factors, levels, outputs")
    p.add_argument("-o", "--output", required=True, metavar="OUTDIR", help="folder for the set")
    p.add_argument("--workers", type=positive_int, default=None, metavar="N",
                   help="parallel processes on this machine, each kept to a core of its own (default: one per core)")
    p.add_argument("--scheduler", default=None, metavar="tcp://HOST:PORT",
                   help="make the stimuli on a running Dask cluster instead (OUTDIR must be shared with it)")
    p.add_argument("--resume", action="store_true",
                   help="finish a set that was stopped: stimuli already made (and matching their hashes) stay")
    p.add_argument("--dry-run", action="store_true", help="list what would be made, and an estimate of the time")
    p.set_defaults(run=run_stimuli)


def run_stimuli(args: argparse.Namespace) -> int:
    from pathlib import Path

    from engine.outputs.video_writer import progress_printer
    from engine.stimuli import load_design, make_set
    from engine.stimuli.run import default_workers, done_records

    design = load_design(args.design)
    if args.scheduler is not None and not args.scheduler.startswith(("tcp://", "tls://", "inproc://")):
        raise UserError(f"--scheduler must be an address like tcp://HOST:PORT, not {args.scheduler!r}")
    if args.dry_run:
        outdir = Path(args.output)
        done = done_records(design, outdir) if outdir.is_dir() else {}
        for stimulus in design.stimuli:
            mark = "made" if stimulus.id in done else "to make"
            levels = ", ".join(f"{k}={v!r}" for k, v in stimulus.levels.items())
            print(f"{stimulus.id}  {mark:8s} {levels}")
        todo = [s for s in design.stimuli if s.id not in done]
        workers = 1 if args.scheduler else (args.workers or default_workers())
        from engine.stimuli.estimate import estimate

        found = estimate(design, todo, workers)
        timing = (f"about {_duration(found.seconds)} with "
                  f"{'the cluster' if args.scheduler else f'{workers} worker(s)'} (stimulus {found.sample_id} "
                  f"made here in {found.sample_seconds:.1f} s, the others scaled by their length)"
                  if found is not None else "nothing to make")
        print(f"{len(design.stimuli)} stimuli, {len(todo)} to make, {timing}; kinds: "
              f"{', '.join(design.output.kinds)}")
        return 0
    printer = progress_printer("stimuli", unit="stimuli")
    result = make_set(design, args.output, workers=args.workers, scheduler=args.scheduler, resume=args.resume,
                      progress=lambda done, total, _message: printer(done, total))
    print(f"{len(result.records)} stimuli in {args.output} ({result.made} made, {result.reused} already there); "
          "manifest.csv, conditions.csv, check.csv, provenance.json")
    if result.failed:
        for record in result.records:
            if record["id"] in result.failed:
                print(f"error: stimulus {record['id']} misses its specification: {record['check']['problem']}",
                      file=sys.stderr)
        return 1
    return 0


def _duration(seconds: float) -> str:
    return f"{seconds:.0f} s" if seconds < 120 else f"{seconds / 60:.0f} min"
