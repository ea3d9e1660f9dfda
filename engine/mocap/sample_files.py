"""Marker files of a made-up recording, so the whole motion-capture pipeline can be tried without a lab (§3.1).

The engine reads marker files (:func:`engine.mocap.readers.read_marker_file`);
these writers make the two text formats it reads from any (F, M, 3)
positions in mm: a Qualisys QTM 3D TSV export (:func:`write_qtm_tsv`) and a
TRC file (:func:`write_trc`). :func:`write_sample_recording` writes a
synthetic recording of the default head
(:func:`engine.mocap.synthetic.synthesize_recording`) in either format, with
its phone labels; the workbench's motion-capture tool offers it as a sample.
Every file is written atomically.

>>> import tempfile
>>> import numpy as np
>>> from engine.mocap.readers import read_marker_file
>>> positions = np.arange(2 * 2 * 3, dtype=float).reshape(2, 2, 3)
>>> path = write_trc(f"{tempfile.mkdtemp()}/take.trc", ["8.3", "8.4"], positions, rate_hz=60)
>>> np.array_equal(read_marker_file(path).positions, positions)
True
>>> paths = write_sample_recording("/tmp/take", text="Papu ja kala.")          # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from engine.formats.atomic import atomic_write_text
from engine.mocap.errors import MarkerFileError

SAMPLE_TEXT = "Papu ja kala. Hyvää päivää, mitä kuuluu?"
SAMPLE_FORMATS = ("tsv", "trc")
QTM_DECIMALS = 4
"""Digits after the point of a QTM TSV position (mm): a tenth of a micrometre."""
TRC_DECIMALS = 4
"""Digits after the point of a TRC position (mm)."""


def write_qtm_tsv(path: str | Path, labels: Sequence[str], positions: ArrayLike, rate_hz: float) -> Path:
    """A Qualisys QTM 3D TSV export of (F, M, 3) ``positions`` (mm) at ``rate_hz`` frames a second.

    Header lines, then a column row ``Frame Time <label> X …``, one row per
    frame. Missing samples (NaN) are written as QTM writes them, ``0 0 0``.
    """
    p = _checked(labels, positions, rate_hz)
    p = np.nan_to_num(p, nan=0.0)
    lines = [f"NO_OF_FRAMES\t{len(p)}", "NO_OF_CAMERAS\t6", f"NO_OF_MARKERS\t{len(labels)}",
             f"FREQUENCY\t{rate_hz:g}", "NO_OF_ANALOG\t0", "ANALOG_FREQUENCY\t0", "DESCRIPTION\t--",
             "DATA_INCLUDED\t3D", "MARKER_NAMES\t" + "\t".join(labels),
             "Frame\tTime\t" + "\t".join(f"{n} {a}" for n in labels for a in "XYZ")]
    for f, frame in enumerate(p):
        lines.append("\t".join([str(f + 1), f"{f / rate_hz:.5f}", *(f"{v:.{QTM_DECIMALS}f}" for v in frame.ravel())]))
    return _write_text(path, "\n".join(lines) + "\n")


def write_trc(path: str | Path, labels: Sequence[str], positions: ArrayLike, rate_hz: float) -> Path:
    """A TRC file (Motion Analysis / OpenSim) of (F, M, 3) ``positions`` (mm); missing samples are empty cells."""
    p = _checked(labels, positions, rate_hz)
    n = len(labels)
    lines = [f"PathFileType\t4\t(X/Y/Z)\t{Path(path).name}",
             "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames",
             f"{rate_hz:.2f}\t{rate_hz:.2f}\t{len(p)}\t{n}\tmm\t{rate_hz:.2f}\t1\t{len(p)}",
             "Frame#\tTime\t" + "\t\t\t".join(labels) + "\t\t",
             "\t\t" + "\t".join(f"{a}{k + 1}" for k in range(n) for a in "XYZ"), ""]
    for f, frame in enumerate(p):
        cells = ["" if np.isnan(v) else f"{v:.{TRC_DECIMALS}f}" for v in frame.ravel()]
        lines.append("\t".join([str(f + 1), f"{f / rate_hz:.6f}", *cells]))
    return _write_text(path, "\n".join(lines) + "\n")


def write_phone_segments_csv(path: str | Path, phones: Iterable[tuple[float, float, str]]) -> Path:
    """``(start_ms, end_ms, label)`` phones as the phones CSV ``say --phones`` writes (``start_ms,end_ms,phone,word``).

    Not a label file: there ``#`` starts a comment, and Festival's pauses are ``#``.
    """
    lines = ["start_ms,end_ms,phone,word"] + [f"{a:.3f},{b:.3f},{label}," for a, b, label in phones]
    return _write_text(path, "\n".join(lines) + "\n")


def write_sample_recording(stem: str | Path, text: str = SAMPLE_TEXT, fmt: str = "tsv", seed: int = 0,
                           labels: Mapping[str, str] | None = None, **synthesis: Any) -> dict[str, Any]:
    """Synthesise a recording of ``text`` on the default head; write ``stem.tsv|trc`` and ``stem.phones.csv``.

    ``labels`` renames the markers in the file (``{id: file label}``), as a
    lab's own marker set would; ``synthesis`` goes to
    :func:`~engine.mocap.synthetic.synthesize_recording` (which runs Festival
    unless given ``phones``). Returns the paths (``markers``, ``labels``) and
    keeps the recording in ``["recording"]``.
    """
    if fmt not in SAMPLE_FORMATS:
        raise MarkerFileError(f"unknown sample format '{fmt}' (use {' or '.join(SAMPLE_FORMATS)})")
    from engine.mocap.synthetic import synthesize_recording

    recording = synthesize_recording(text, seed=seed, **synthesis)
    names = [(labels or {}).get(m, m) for m in recording.markers]
    stem = Path(stem)
    writer = write_qtm_tsv if fmt == "tsv" else write_trc
    markers = writer(stem.with_suffix(f".{fmt}"), names, recording.positions, recording.rate_hz)
    phones = write_phone_segments_csv(stem.with_suffix(".phones.csv"), recording.phones)
    return {"markers": markers, "labels": phones, "recording": recording}


def _checked(labels: Sequence[str], positions: ArrayLike, rate_hz: float) -> np.ndarray:
    p = np.asarray(positions, dtype=float)
    if p.ndim != 3 or p.shape[2] != 3:
        raise ValueError(f"positions must be (frames, markers, 3), not {p.shape}")
    if p.shape[1] != len(labels):
        raise ValueError(f"{len(labels)} labels for {p.shape[1]} markers")
    if not (rate_hz > 0 and np.isfinite(rate_hz)):
        raise ValueError(f"the frame rate must be a positive number of Hz, not {rate_hz!r}")
    return p


def _write_text(path: str | Path, text: str) -> Path:
    atomic_write_text(path, text, MarkerFileError)
    return Path(path)
