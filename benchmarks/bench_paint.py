#!/usr/bin/env python3
"""Weight painting: time of one brush dab, and the one-off set-up cost.

Run from the project root::

    .venv/bin/python benchmarks/bench_paint.py [--dabs 200] [--json out.json]

Meshes: the default head (5 960 vertices) and its 4 × 4 linear subdivision
(~94k vertices, ``engine.model.subdivide``). A stroke of ``--dabs`` dabs runs
across the face at nose height, from one cheek to the other, on the front
surface, painting the jaw's influence region; every dab is

    compute_dab → apply to the weights (Stroke) → heat-map colours of the changed vertices written into
    the (N, 3) colour buffer

— what the workbench does per mouse move before handing the colours to VTK.
The "live preview" rows add ``LivePreview.update`` (the jaw held at 0.5
while its weights are painted: the posed positions of the changed vertices).
Brush: add, strength 0.3, smooth falloff, front faces only, surface-connected
selection, radius 15 mm and 40 mm; extra rows with the mirror on and the
smooth brush. Goal: under 16 ms on the default head and under 50 ms
at 100k vertices.

Side by side, on the same dabs:

* **peer** — the straightforward implementation: distances from the hit point
  to every vertex (numpy, no spatial index, no connectivity), blend, and
  recolour the whole mesh;
* **floor** — the least any dab must do: the KD-tree ball query and the colour
  look-up of the vertices it returns.

Single thread: BLAS and OpenMP are pinned to one thread before numpy loads.
No assertions: the figures are printed for docs/painting.md.
"""

from __future__ import annotations

import os

for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[var] = "1"

import argparse  # noqa: E402
import json  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import engine  # noqa: E402
from engine.model.subdivide import subdivide  # noqa: E402
from engine.painting import Brush, DenseRegion, LivePreview, PaintContext, Stroke, heat_colors  # noqa: E402
from engine.painting.heatmap import WEIGHT_RAMP  # noqa: E402
from engine.painting.mirror import mirror_map  # noqa: E402

VIEW = np.array([0.0, 0.0, -1.0])          # looking at the face from the front


def stroke_path(model, count):
    """Hit points across the face at nose height, on the front-most skin surface."""
    V = model.vertices
    skin = np.flatnonzero(model.vertex_part == model.parts.index("skin"))
    y0 = V[model.landmarks["9.3"], 1] if "9.3" in model.landmarks else np.median(V[:, 1])
    band = skin[np.abs(V[skin, 1] - y0) < 4.0]
    xs = np.linspace(-55.0, 55.0, count)
    pts = []
    for x in xs:
        col = band[np.abs(V[band, 0] - x) < 3.0]
        pts.append(V[col[np.argmax(V[col, 2])]] if len(col) else pts[-1])
    return np.array(pts)


def percentiles(times_ms):
    t = np.asarray(times_ms)
    return float(np.median(t)), float(np.percentile(t, 95)), float(t.max())


def time_dabs(ctx, brush, path, base, start, preview=None):
    weights = start.copy()
    colors = heat_colors(weights, base)
    stroke = Stroke(weights)
    live = None
    if preview is not None:
        model, name = preview
        dense = DenseRegion.from_model(model, name)
        dense.weights = weights
        live = LivePreview(model, name, dense, {name: 0.5})
    times, changed = [], []
    for p in path:
        t0 = time.perf_counter()
        change = stroke.dab(ctx, brush, p, VIEW)
        colors[change.indices] = heat_colors(change.after, base)
        if live is not None:
            live.update(change.indices)
        times.append((time.perf_counter() - t0) * 1e3)
        changed.append(len(change))
    t0 = time.perf_counter()
    step = stroke.finish()
    finish_ms = (time.perf_counter() - t0) * 1e3
    return times, changed, finish_ms, len(step)


def time_peer(ctx, brush, path, base, start):
    V = ctx.vertices
    weights = start.copy()
    times = []
    for p in path:
        t0 = time.perf_counter()
        d = np.sqrt(((V - p) ** 2).sum(axis=1))
        t = np.clip(d / brush.radius, 0.0, 1.0)
        a = brush.strength * (1.0 - t * t * (3.0 - 2.0 * t)) * (d < brush.radius)
        a *= (ctx.normals @ VIEW) < 0
        weights = np.clip(weights + a, 0.0, 1.0)
        heat_colors(weights, base)
        times.append((time.perf_counter() - t0) * 1e3)
    return times


def time_floor(ctx, brush, path):
    times = []
    for p in path:
        t0 = time.perf_counter()
        idx = np.asarray(ctx.tree.query_ball_point(p, brush.radius), dtype=np.int64)
        np.take(WEIGHT_RAMP, np.full(len(idx), 128), axis=0)
        times.append((time.perf_counter() - t0) * 1e3)
    return times


def setup_costs(model, repeats=3):
    """Best of ``repeats``: context (topology, normals, KD-tree, components) and the mirror map."""
    best_ctx, best_mirror, best_kd = np.inf, np.inf, np.inf
    from scipy.spatial import cKDTree
    for _ in range(repeats):
        t0 = time.perf_counter()
        ctx = PaintContext(model)
        best_ctx = min(best_ctx, time.perf_counter() - t0)
        t0 = time.perf_counter()
        cKDTree(model.vertices)
        best_kd = min(best_kd, time.perf_counter() - t0)
        t0 = time.perf_counter()
        ctx.mirror = mirror_map(ctx)
        best_mirror = min(best_mirror, time.perf_counter() - t0)
    return ctx, best_ctx * 1e3, best_kd * 1e3, best_mirror * 1e3


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dabs", type=int, default=200)
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)
    head = engine.load_model()
    t0 = time.perf_counter()
    fine = subdivide(head, 4)
    print(f"(subdividing the head 4 × 4 took {time.perf_counter() - t0:.1f} s; not part of painting)")
    rows, setups = [], []
    for label, model in (("default head", head), ("subdivided 4×4", fine)):
        ctx, ctx_ms, kd_ms, mirror_ms = setup_costs(model)
        mm = ctx.mirror
        setups.append(dict(mesh=label, vertices=model.n_vertices, context_ms=ctx_ms, kdtree_ms=kd_ms,
                           mirror_ms=mirror_ms, mirror=mm.summary(ctx.parts, ctx.vertex_part)))
        print(f"\n{label}: {model.n_vertices} vertices; set-up: context {ctx_ms:.1f} ms (of which KD-tree "
              f"{kd_ms:.1f} ms), mirror map {mirror_ms:.1f} ms — {mm.summary(ctx.parts, ctx.vertex_part)}")
        path = stroke_path(model, args.dabs)
        base = np.full(3, 205, dtype=np.uint8)
        start = DenseRegion.from_model(model, "jaw_open").weights     # paint onto a real region
        for radius in (15.0, 40.0):
            variants = [
                ("add", Brush("add", radius, 0.3, "smooth", front_faces_only=True, connected=True)),
                ("add, mirror", Brush("add", radius, 0.3, "smooth", front_faces_only=True, connected=True,
                                      mirror=True)),
                ("add, not connected", Brush("add", radius, 0.3, "smooth", front_faces_only=True, connected=False)),
                ("smooth", Brush("smooth", radius, 0.5, "smooth", front_faces_only=True, connected=True)),
                ("add + live preview", Brush("add", radius, 0.3, "smooth", front_faces_only=True, connected=True)),
            ]
            for name, brush in variants:
                preview = (model, "jaw_open") if "preview" in name else None
                times, changed, finish_ms, n_step = time_dabs(ctx, brush, path, base, start, preview)
                med, p95, worst = percentiles(times)
                row = dict(mesh=label, vertices=model.n_vertices, radius=radius, brush=name, median_ms=med,
                           p95_ms=p95, max_ms=worst, changed_median=float(np.median(changed)),
                           finish_ms=finish_ms, stroke_vertices=n_step)
                if name == "add":
                    row["peer_median_ms"], row["peer_p95_ms"], _ = percentiles(time_peer(ctx, brush, path, base, start))
                    row["floor_median_ms"], row["floor_p95_ms"], _ = percentiles(time_floor(ctx, brush, path))
                rows.append(row)
                extra = ""
                if "peer_median_ms" in row:
                    extra = (f" | peer {row['peer_median_ms']:.2f} / {row['peer_p95_ms']:.2f} ms"
                             f" | floor {row['floor_median_ms']:.3f} / {row['floor_p95_ms']:.3f} ms")
                print(f"  r={radius:>4.0f} mm {name:<19} dab median {med:6.2f} ms  p95 {p95:6.2f} ms  "
                      f"max {worst:6.2f} ms  ({row['changed_median']:.0f} vertices changed per dab; "
                      f"stroke.finish {finish_ms:.2f} ms){extra}")
    if args.json:
        args.json.write_text(json.dumps(dict(setup=setups, dabs=rows), indent=1))


if __name__ == "__main__":
    main()
