"""Small writers the tool needs: mapping files, and marker/label files of a made-up recording.

The engine reads marker files, mapping files and label files; the
workbench also writes a few: the mapping the user edited
(:func:`write_mapping`, the ``label = id`` format
:func:`engine.mocap.naming.read_mapping` reads), and — so the whole
pipeline can be tried without a lab — a synthetic recording of the default
head (:func:`engine.mocap.synthetic.synthesize_recording`) written as a QTM
TSV or TRC file with its phone labels (:func:`write_sample_recording`).

>>> write_mapping("face.map", {"LipCornerL": "8.3", "Marker17": "-"})          # doctest: +SKIP
>>> paths = write_sample_recording("/tmp/take", text="Papu ja kala.")          # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from engine.formats.atomic import atomic_path

SAMPLE_TEXT = "Papu ja kala. Hyvää päivää, mitä kuuluu?"


def write_mapping(path: str | Path, mapping: dict[str, str]) -> Path:
    """Write ``{label: id}`` (``-`` drops the marker) as a mapping file, one ``label = id`` a line."""
    path = Path(path)
    width = max((len(label) for label in mapping), default=0)
    lines = ["# marker label = MPEG-4 feature point id ('-' drops the marker); written by the workbench"]
    lines += [f"{label:<{width}} = {target}" for label, target in mapping.items()]
    with atomic_path(path) as tmp:
        Path(tmp).write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def write_qtm_tsv(path: str | Path, labels, positions: np.ndarray, rate_hz: float) -> Path:
    """A Qualisys QTM 3D TSV export (header, column row, ``0 0 0`` for gaps), positions in mm."""
    p = np.nan_to_num(np.asarray(positions, dtype=float), nan=0.0)
    lines = [f"NO_OF_FRAMES\t{len(p)}", "NO_OF_CAMERAS\t6", f"NO_OF_MARKERS\t{len(labels)}",
             f"FREQUENCY\t{rate_hz:g}", "NO_OF_ANALOG\t0", "ANALOG_FREQUENCY\t0", "DESCRIPTION\t--",
             "DATA_INCLUDED\t3D", "MARKER_NAMES\t" + "\t".join(labels),
             "Frame\tTime\t" + "\t".join(f"{n} {a}" for n in labels for a in "XYZ")]
    for f, frame in enumerate(p):
        lines.append("\t".join([str(f + 1), f"{f / rate_hz:.5f}"] + [f"{v:.4f}" for v in frame.ravel()]))
    return _write_text(path, "\n".join(lines) + "\n")


def write_trc(path: str | Path, labels, positions: np.ndarray, rate_hz: float) -> Path:
    """A TRC file (Motion Analysis / OpenSim), mm, empty cells for gaps."""
    p = np.asarray(positions, dtype=float)
    n = len(labels)
    lines = [f"PathFileType\t4\t(X/Y/Z)\t{Path(path).name}",
             "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames",
             f"{rate_hz:.2f}\t{rate_hz:.2f}\t{len(p)}\t{n}\tmm\t{rate_hz:.2f}\t1\t{len(p)}",
             "Frame#\tTime\t" + "\t\t\t".join(labels) + "\t\t",
             "\t\t" + "\t".join(f"{a}{k + 1}" for k in range(n) for a in "XYZ"), ""]
    for f, frame in enumerate(p):
        cells = ["" if np.isnan(v) else f"{v:.4f}" for v in frame.ravel()]
        lines.append("\t".join([str(f + 1), f"{f / rate_hz:.6f}"] + cells))
    return _write_text(path, "\n".join(lines) + "\n")


def write_phones_csv(path: str | Path, phones) -> Path:
    """Phone labels as the phones CSV ``say --phones`` writes (``start_ms,end_ms,phone,word``).

    Not a label file: there ``#`` starts a comment, and Festival's pauses are ``#``.
    """
    lines = ["start_ms,end_ms,phone,word"] + [f"{a:.3f},{b:.3f},{label}," for a, b, label in phones]
    return _write_text(path, "\n".join(lines) + "\n")


def write_sample_recording(stem: str | Path, text: str = SAMPLE_TEXT, fmt: str = "tsv", seed: int = 0,
                           labels=None, **synthesis) -> dict[str, Path]:
    """Synthesise a recording of ``text`` on the default head and write ``stem.tsv|trc`` and ``stem.phones.csv``.

    ``labels`` renames the markers in the file (``{id: file label}``), as a
    lab's own marker set would; ``synthesis`` goes to
    :func:`~engine.mocap.synthetic.synthesize_recording`. Returns the paths
    (``markers``, ``labels``) and keeps the recording in ``["recording"]``.
    """
    from engine.mocap.synthetic import synthesize_recording

    recording = synthesize_recording(text, seed=seed, **synthesis)
    names = [(labels or {}).get(m, m) for m in recording.markers]
    stem = Path(stem)
    writer = {"tsv": write_qtm_tsv, "trc": write_trc}[fmt]
    markers = writer(stem.with_suffix(f".{fmt}"), names, recording.positions, recording.rate_hz)
    phones = write_phones_csv(stem.with_suffix(".phones.csv"), recording.phones)
    return {"markers": markers, "labels": phones, "recording": recording}


def _write_text(path: str | Path, text: str) -> Path:
    path = Path(path)
    with atomic_path(path) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")
    return path
