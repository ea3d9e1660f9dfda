#!/usr/bin/env python3
"""Deformation time per frame (§2.2): engine vs a dense LBS peer vs a memory-copy floor.

Run from the project root::

    .venv/bin/python benchmarks/bench_deform.py [--frames 200] [--json out.json]

Meshes: the default head and its 4 × 4 linear subdivision (~94k vertices;
``engine.model.subdivide``) as produced and after ``engine.deform.deformer.
optimise_vertex_order`` (a one-off renumbering that makes the deformer's
internal order the model's own, so no frame pays for reordering; the
shipped head is saved in that order). Every parameter is set to a random
value inside its range each frame (the worst case: all parameters active).

* **engine** — ``Model.deform``: ``engine.deform.Deformer`` with the compiled
  vertex pass (``engine/deform/_kernel.c``) when it is built; the row below
  it times the numpy fallback (``Deformer(model, kernel=False)``) on the same
  frames.
* **peer** — dense linear-blend skinning written the way ``smplx.lbs`` does
  it: weights V × K dense, blend the K homogeneous 4×4 matrices per vertex
  (``W @ A.reshape(K, 16)``), apply with a batched matmul. It gets the same
  propagated matrices, so only the vertex work is compared (it cannot express
  leaves acting in the rest frame, so it does less than the engine).
* **floor** — copying the bytes one frame must read and write: the rest
  vertices and every region's indices and weights read, the N × 3 output
  written (``np.copyto`` into preallocated buffers).

Single thread: BLAS and OpenMP are pinned to one thread before numpy loads.
No assertions: the figures are printed, to be compared with benchmarks/README.md.
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
from engine.deform.deformer import Deformer, optimise_vertex_order  # noqa: E402
from engine.model.subdivide import subdivide  # noqa: E402


def random_frames(model, count, seed=0):
    rng = np.random.default_rng(seed)
    lo = np.array([p.minimum for p in model.parameters])
    hi = np.array([p.maximum for p in model.parameters])
    return lo + (hi - lo) * rng.random((count, len(lo)))


class DenseLBS:
    """smplx.lbs-style dense skinning: T = W @ A (V × 16), v' = T · [v, 1]."""

    def __init__(self, model):
        names = model.parameters.names
        self.W = np.zeros((model.n_vertices, len(names)))
        for k, n in enumerate(names):
            if model.parameters.is_leaf(n):
                continue                  # skinning weights are the rigid (group-1) ones; K stays all parameters
            r = model.regions[n]
            self.W[r.indices, k] = r.weights
        s = self.W.sum(axis=1, keepdims=True)
        np.divide(self.W, s, out=self.W, where=s > 0)
        self.vh = np.hstack([model.vertices, np.ones((model.n_vertices, 1))])[:, :, None]
        self.deformer = model.deformer()

    def deform(self, values):
        _, world = self.deformer.transforms(values)
        A = np.stack([T.T for T in world])                     # column convention, like smplx
        T = (self.W @ A.reshape(len(A), 16)).reshape(-1, 4, 4)
        return np.matmul(T, self.vh)[:, :3, 0]


class CopyFloor:
    """The memory traffic a frame cannot avoid: read rest + weights, write the output."""

    def __init__(self, model):
        self.rest = model.vertices
        self.out = np.empty_like(self.rest)
        regions = [model.regions[n] for n in model.parameters.names]
        self.src = [a for r in regions for a in (r.indices, r.weights)]
        self.dst = [np.empty_like(a) for a in self.src]

    def deform(self, values):
        for s, d in zip(self.src, self.dst, strict=True):
            np.copyto(d, s)
        np.copyto(self.out, self.rest)
        return self.out


def time_per_frame(fn, frames, repeats=5):
    fn(frames[0])                                  # warm caches and lazy structures
    best = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for v in frames:
            fn(v)
        best.append((time.perf_counter() - t0) / len(frames))
    return float(np.median(best)) * 1e3


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--frames", type=int, default=200)
    ap.add_argument("--subdivision", type=int, default=4)
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)

    head = engine.load_model()
    fine = subdivide(head, args.subdivision)
    meshes = [("default head", head),
              (f"subdivided ×{args.subdivision}²", fine),
              ("  same, order optimised", optimise_vertex_order(fine)[0])]
    rows = []
    path = "compiled kernel" if engine.deform.deformer.compiled is not None else "numpy (kernel not built)"
    print(f"engine = Model.deform: {path}; single thread")
    print(f"{'mesh':22s} {'vertices':>9s} {'engine ms':>10s} {'peer ms':>9s} {'floor ms':>9s} "
          f"{'peer/engine':>12s} {'engine/floor':>13s}")
    for label, model in meshes:
        frames = random_frames(model, args.frames)
        deformer = model.deformer()
        fallback = Deformer(model, kernel=False) if deformer.kernel else None
        peer, floor = DenseLBS(model), CopyFloor(model)
        # the peer must agree with the engine where the two formulations coincide (no leaves active)
        check = frames[0].copy()
        for k, n in enumerate(model.parameters.names):
            if model.parameters.is_leaf(n):
                check[k] = 0.0
        err = np.abs(peer.deform(check) - deformer.deform(check)).max()
        t_engine = time_per_frame(deformer.deform, frames)
        t_peer = time_per_frame(peer.deform, frames[: max(20, args.frames // 5)])
        t_floor = time_per_frame(floor.deform, frames)
        t_numpy = time_per_frame(fallback.deform, frames) if fallback is not None else None
        rows.append(dict(mesh=label, vertices=model.n_vertices, engine_path=path, engine_ms=t_engine,
                         numpy_path_ms=t_numpy, peer_ms=t_peer, floor_ms=t_floor,
                         speedup_vs_peer=t_peer / t_engine, engine_over_floor=t_engine / t_floor,
                         peer_max_difference_mm=float(err)))
        print(f"{label:22s} {model.n_vertices:9d} {t_engine:10.3f} {t_peer:9.3f} {t_floor:9.3f} "
              f"{t_peer / t_engine:11.1f}× {t_engine / t_floor:12.2f}×   (peer = engine to {err:.1e} mm "
              "with leaves at 0)")
        if t_numpy is not None:
            print(f"{'    numpy fallback':22s} {'':9s} {t_numpy:10.3f} {'':9s} {'':9s} "
                  f"{t_peer / t_numpy:11.1f}× {t_numpy / t_floor:12.2f}×")
    print("goal on the large mesh: ≥ 10× faster than the peer, ≤ 4× the floor")
    if args.json:
        args.json.write_text(json.dumps(rows, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
