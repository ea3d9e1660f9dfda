#!/usr/bin/env python3
"""Fit to photographs (issue 19): the time split for two 2-megapixel photographs (goal < 30 s in all).

Run from the project root::

    .venv/bin/python benchmarks/bench_photofit.py [--json out.json]

The photographs are the synthetic ground truth of ``tests/engine/test_photofit.py``
(a known identity with a patterned texture rendered by ``render_model`` from
the front and the side, 1224 × 1632 = 2.0 megapixels each) written as JPEG
files with a POINTS.json, so the time includes reading and decoding them, as
``fit-photos`` does. Stages: landmarks (reading the photographs and
POINTS.json) → shape (cameras, identity, residual warp with the side profile and outline, rig carried
over) →
texture (z-buffers, atlas, blend), as wall-clock and as this process's CPU time (steadier on a shared
machine). No assertions: the figures are printed.
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

SIZE = (1224, 1632)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", help="also write the figures here")
    args = parser.parse_args()

    from PIL import Image

    from engine.photofit import fit_photo_files
    from tests.engine import test_photofit as synthetic

    synthetic.PHOTO_SIZE = SIZE
    _, photos, points, _ = synthetic.synthetic.__wrapped__()
    with tempfile.TemporaryDirectory() as folder:
        files = {}
        for view, photo in photos.items():
            files[view] = Path(folder) / f"{view}.jpg"
            Image.fromarray(photo).save(files[view], quality=92)
        landmarks = Path(folder) / "points.json"
        landmarks.write_text(json.dumps({v: {k: list(p) for k, p in pts.items()} for v, pts in points.items()}))
        started, cpu_started = time.perf_counter(), time.process_time()
        result = fit_photo_files(files["front"], files["side"], landmarks)
        total, cpu = time.perf_counter() - started, time.process_time() - cpu_started
    figures = {"megapixels": SIZE[0] * SIZE[1] / 1e6, **{f"{k}_s": round(v, 3) for k, v in result.seconds.items()},
               **{f"cpu_{k}_s": round(v, 3) for k, v in result.cpu_seconds.items()},
               "total_s": round(total, 3), "cpu_total_s": round(cpu, 3),
               "landmark_error_px": round(result.shape.error, 3)}
    print(f"two photographs of {figures['megapixels']:.1f} MP: landmarks {figures['landmarks_s']:.2f} s → shape "
          f"{figures['shape_s']:.2f} s → texture {figures['texture_s']:.2f} s; total {total:.2f} s "
          f"(goal < 30 s); landmark error {result.shape.error:.2f} px")
    print(f"CPU time (this process): landmarks {figures['cpu_landmarks_s']:.2f} s → shape {figures['cpu_shape_s']:.2f} "
          f"s → texture {figures['cpu_texture_s']:.2f} s; total {cpu:.2f} s")
    if args.json:
        Path(args.json).write_text(json.dumps(figures, indent=1))


if __name__ == "__main__":
    main()
