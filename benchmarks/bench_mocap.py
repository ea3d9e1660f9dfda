"""Import + multistage PCA of one hour of motion capture at 60 fps with 32 markers.

The recording is made up by :func:`engine.mocap.synthetic.synthesize_recording`
(a Finnish sentence spoken by the default head, with head motion, noise,
dropouts and gaps), repeated with fresh noise to one hour, and written as a
C3D file and a Qualisys TSV file (cached in the temporary folder between
runs). Timed: ``import_marker_file`` (read, name, fill gaps, remove head
motion) and ``multistage_pca`` (5 components, every frame), beside a plain
scikit-learn PCA of the same frames × coordinates matrix as the floor.

    .venv/bin/python benchmarks/bench_mocap.py [--minutes 60] [--formats c3d tsv]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

from engine import load_model
from engine.mocap.importer import import_marker_file
from engine.mocap.pca import multistage_pca
from engine.mocap.synthetic import synthesize_recording

RATE = 60.0
N_MARKERS = 32
CACHE = Path(tempfile.gettempdir()) / "artificial-person-bench-mocap"


def one_hour(minutes: float, seed: int = 0):
    """(labels, F × 32 × 3 positions with NaN gaps) for ``minutes`` of recording."""
    rec = synthesize_recording(model=load_model(), seed=seed, rate_hz=RATE)
    labels = list(rec.markers)[:N_MARKERS]
    block = rec.positions[:, :N_MARKERS]
    frames = int(minutes * 60 * RATE)
    rng = np.random.default_rng(seed)
    repeats = -(-frames // len(block))
    tiles = [block + rng.normal(0, 0.05, block.shape) for _ in range(repeats)]
    return labels, np.concatenate(tiles)[:frames]


def write_c3d(path: Path, labels, positions) -> None:
    import c3d

    writer = c3d.Writer(point_rate=RATE, point_scale=-1.0, point_units="mm  ")
    writer.set_point_labels(labels)
    frames = []
    empty = np.zeros((0, 0))
    for frame in positions:
        points = np.zeros((len(labels), 5), np.float32)
        gap = np.isnan(frame[:, 0])
        points[:, :3] = np.nan_to_num(frame)
        points[gap, 3] = -1
        frames.append((points, empty))
    writer.add_frames(frames)
    with open(path, "wb") as fh:
        writer.write(fh)


def write_tsv(path: Path, labels, positions) -> None:
    head = [f"NO_OF_FRAMES\t{len(positions)}", "NO_OF_CAMERAS\t8", f"NO_OF_MARKERS\t{len(labels)}",
            f"FREQUENCY\t{RATE:g}", "NO_OF_ANALOG\t0", "ANALOG_FREQUENCY\t0", "DESCRIPTION\t--",
            "TIME_STAMP\t2026-11-22, 10:00:00\t0", "DATA_INCLUDED\t3D", "MARKER_NAMES\t" + "\t".join(labels)]
    body = np.nan_to_num(positions.reshape(len(positions), -1), nan=0.0)
    with open(path, "w") as fh:
        fh.write("\n".join(head) + "\n")
        np.savetxt(fh, body, fmt="%.3f", delimiter="\t")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=60.0)
    parser.add_argument("--formats", nargs="+", default=["c3d", "tsv"], choices=["c3d", "tsv"])
    args = parser.parse_args(argv)
    CACHE.mkdir(exist_ok=True)
    data = None
    files = {}
    for fmt in args.formats:
        path = CACHE / f"hour-{args.minutes:g}min.{fmt}"
        if not path.exists():
            if data is None:
                print("making the recording …", flush=True)
                data = one_hour(args.minutes)
            print(f"writing {path} …", flush=True)
            (write_c3d if fmt == "c3d" else write_tsv)(path, *data)
        files[fmt] = path

    from sklearn.decomposition import PCA

    print(f"{args.minutes:g} min at {RATE:g} fps, {N_MARKERS} markers")
    print(f"{'file':<6} {'MB':>6} {'import s':>9} {'PCA s':>7} {'total s':>8} {'sklearn PCA s (floor)':>22}")
    for fmt, path in files.items():
        t0 = time.perf_counter()
        session = import_marker_file(path)
        t1 = time.perf_counter()
        art = multistage_pca(session)
        t2 = time.perf_counter()
        analysed = [session.markers.index(m) for m in art.markers]
        matrix = session.positions[:, analysed].reshape(session.n_frames, -1)
        matrix = matrix[~np.isnan(matrix).any(axis=1)]
        t3 = time.perf_counter()
        PCA(n_components=art.n_components, svd_solver="full").fit(matrix)
        t4 = time.perf_counter()
        size = path.stat().st_size / 1e6
        print(f"{fmt:<6} {size:6.0f} {t1 - t0:9.2f} {t2 - t1:7.2f} {t2 - t0:8.2f} {t4 - t3:22.2f}"
              f"   ({session.n_frames} frames, {matrix.shape[0]} complete, {matrix.shape[1]} coordinates)")
    print("goal: import + PCA under 5 s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
