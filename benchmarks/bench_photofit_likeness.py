#!/usr/bin/env python3
"""Does the fitted head look like the person? Issue 33's goals, measured on real portraits.

Each portrait of ``benchmarks/data/portraits`` (public domain, see its README) is fitted front-only by
``fit_photo_files`` with its landmarks found by themselves (dlib), then rendered from the front, 480 × 600:

* **untextured**: the fitted shape in the default head's colours, against the default head the same way;
* **textured**: the fitted head with its photo texture; against the same person's second photograph too,
  where there is one (``*-second.jpg``, not used by the fit);
* **neutral**: what the emotion classifier reads on the textured head at rest (the photographs smile).

Distances are dlib's face descriptor (``engine.validation``; same person below 0.6). The timing run fits one
2-megapixel front photograph (a portrait enlarged to 1414 × 1414) on one core: landmarks (reading the
photograph and finding its points, the observers' start-up included) and the fit, as this process's CPU
time (``cpu_*``: what the goal is about, steady on a shared machine) and wall-clock time.

    .venv/bin/python benchmarks/bench_photofit_likeness.py [--only NAME ...] [--pictures DIR] [--json out.json]

No assertions: the figures are printed (and written with ``--json``).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
PORTRAITS = HERE / "data" / "portraits"
PEOPLE = ("astronaut", "obama", "biden", "jeffries", "meng", "klobuchar", "lewis", "bera", "lee", "lofgren",
          "labrador", "chu")
SIZE = (480, 600)
SAME_PERSON = 0.6


def one_core() -> None:
    """Keep this process to one core (and numpy's BLAS to one thread, set before numpy is imported)."""
    os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})


def untextured(head):
    bare = head.copy()
    bare.texture = None
    return bare


def seen_by_observers(picture):
    from engine.validation.faces import look

    return look(picture, detector="auto")


def distance(a, b) -> float:
    import numpy as np

    if a is None or b is None or a.descriptor is None or b.descriptor is None:
        return float("nan")
    return float(np.linalg.norm(a.descriptor - b.descriptor))


def measure(name: str, folder: Path, pictures: Path | None) -> dict:
    from PIL import Image

    from engine.formats.model_files import load_model
    from engine.outputs.render import render_model
    from engine.photofit import fit_photo_files, read_photo

    path = PORTRAITS / f"{name}.jpg"
    photo = read_photo(path)
    person = seen_by_observers(photo)
    started = time.perf_counter()
    fit = fit_photo_files(path, None, None, found_to=folder / f"{name}-landmarks.json")
    seconds = time.perf_counter() - started
    default_picture = render_model(load_model(), size=SIZE)
    bare_picture = render_model(untextured(fit.head), size=SIZE)
    textured_picture = render_model(fit.head, size=SIZE)
    default_seen, bare_seen = seen_by_observers(default_picture), seen_by_observers(bare_picture)
    textured_seen = seen_by_observers(textured_picture)
    row = {"person": name, "seconds": round(seconds, 2), "landmark_error_px": round(fit.shape.error, 2),
           "default": distance(default_seen, person), "untextured": distance(bare_seen, person),
           "textured": distance(textured_seen, person),
           "neutral_reads": textured_seen.judged, "neutral_p": _p_neutral(textured_seen),
           "untextured_reads": bare_seen.judged,
           "identity": {k: round(v, 3) for k, v in fit.shape.identity.values.items()},
           "expression": {k: round(v, 3) for k, v in getattr(fit.shape, "expression", {}).items()}}
    second = PORTRAITS / f"{name}-second.jpg"
    if second.exists():
        row["textured_second"] = distance(textured_seen, seen_by_observers(read_photo(second)))
    if pictures is not None:
        tiles = [photo, default_picture, bare_picture, textured_picture]
        height = 300
        images = [Image.fromarray(t).resize((round(t.shape[1] * height / t.shape[0]), height)) for t in tiles]
        sheet = Image.new("RGB", (sum(i.width for i in images), height), "white")
        x = 0
        for image in images:
            sheet.paste(image, (x, 0))
            x += image.width
        sheet.save(pictures / f"{name}.png")
    return row


def _p_neutral(seen) -> float:
    from engine.validation.observers import EMOTIONS

    return float("nan") if seen.emotions is None else round(float(seen.emotions[EMOTIONS.index("neutral")]), 3)


def timing(folder: Path) -> dict:
    """Landmarks and fit of one 2-megapixel front photograph, on one core."""
    from PIL import Image

    from engine.photofit import fit_photo_files

    big = folder / "big.jpg"
    Image.open(PORTRAITS / "biden.jpg").resize((1414, 1414), Image.Resampling.LANCZOS).save(big, quality=92)
    started, cpu_started = time.perf_counter(), time.process_time()
    fit = fit_photo_files(big, None, None, found_to=folder / "big-landmarks.json")
    total, cpu = time.perf_counter() - started, time.process_time() - cpu_started
    return {"megapixels": 1414 * 1414 / 1e6, "cpu_total_s": round(cpu, 2), "total_s": round(total, 2),
            **{f"cpu_{k}_s": round(v, 2) for k, v in fit.cpu_seconds.items()},
            **{f"{k}_s": round(v, 2) for k, v in fit.seconds.items()}}


def summary(rows: list[dict]) -> dict:
    import numpy as np

    def values(key: str) -> np.ndarray:
        return np.array([r[key] for r in rows if key in r], dtype=float)

    out = {}
    for key in ("default", "untextured", "textured", "textured_second"):
        v = values(key)
        if len(v):
            out[key] = {"mean": round(float(np.nanmean(v)), 3), "below_0.6": int(np.sum(v < SAME_PERSON)),
                        "of": len(v)}
    out["neutral"] = {"reads_neutral": sum(r["neutral_reads"] == "neutral" for r in rows), "of": len(rows)}
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", nargs="*", help="these portraits only")
    parser.add_argument("--pictures", type=Path, help="write each person's photograph | default | untextured | "
                                                      "textured here")
    parser.add_argument("--no-timing", action="store_true")
    parser.add_argument("--json", help="also write the figures here")
    args = parser.parse_args()
    one_core()
    if args.pictures:
        args.pictures.mkdir(parents=True, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        timed = None if args.no_timing else timing(Path(folder))
        for name in args.only or PEOPLE:
            row = measure(name, Path(folder), args.pictures)
            rows.append(row)
            print(f"{name:10s} default {row['default']:.3f}  untextured {row['untextured']:.3f}  textured "
                  f"{row['textured']:.3f}  second {row.get('textured_second', float('nan')):.3f}  reads "
                  f"{row['neutral_reads']} ({row['neutral_p']:.2f} neutral)  {row['seconds']:.1f} s  "
                  f"{row['landmark_error_px']:.1f} px", flush=True)
            print(f"           identity {row['identity']}", flush=True)
            if row["expression"]:
                print(f"           expression {row['expression']}", flush=True)
    figures = {"people": rows, "summary": summary(rows), "timing": timed}
    print(json.dumps(figures["summary"], indent=1))
    if timed:
        print(f"2-megapixel front photograph on one core: {timed}")
    if args.json:
        Path(args.json).write_text(json.dumps(figures, indent=1))


if __name__ == "__main__":
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    main()
