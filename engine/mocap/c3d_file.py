"""C3D marker files, through the PyPI reader ``c3d`` (pure Python, numpy only).

The reader parses the header and parameter section (labels ``POINT:LABELS``
and ``LABELS2``…, rate ``POINT:RATE``, scale ``POINT:SCALE``, units
``POINT:UNITS``); for Intel-format files the point data are then read in one
numpy pass instead of frame by frame (an hour at 60 fps reads in about a
second instead of ten). Other processor formats (DEC, MIPS) go through the
reader's own frame iterator. A sample is missing when its residual word is
negative, a coordinate is not finite, or it is exactly ``(0, 0, 0)``.
"""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import TYPE_CHECKING, BinaryIO

import numpy as np

from engine.mocap.errors import MarkerFileError
from engine.mocap.recording import Recording, unit_scale, zero_triplets_to_nan

if TYPE_CHECKING:
    import c3d


def read_c3d(path: str | Path) -> Recording:
    """Read the 3D points of a C3D file; positions in mm, invalid samples as NaN."""
    path = Path(path)
    try:
        import c3d
    except ImportError:
        raise MarkerFileError("reading C3D needs the Python package 'c3d' (pip install c3d)", file=path) from None
    with open(path, "rb") as fh:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # the reader warns about missing analog data and the like
                reader = c3d.Reader(fh)
                labels = _labels(reader)
                rate = float(reader.point_rate)
                n_points = int(reader.point_used)
                n_frames = int(reader.frame_count)
                units_param = reader.get("POINT:UNITS")
                units = units_param.string_value.strip() if units_param is not None else "mm"
        except MarkerFileError:
            raise
        except Exception as exc:  # the reader raises whatever its parsing hits: report, don't crash
            raise MarkerFileError(f"not a readable C3D file ({_describe(exc)})", file=path) from None
        if not (np.isfinite(rate) and rate > 0):
            raise MarkerFileError(f"POINT:RATE is {rate}: not a frame rate", file=path)
        if len(labels) < n_points:
            labels += [f"point{k + 1}" for k in range(len(labels), n_points)]
        labels = labels[:n_points]
        labels = _unique(labels)
        mm = unit_scale(units or "mm", path)
        if reader.proc_type in ("INTEL", "MIPS"):  # IEEE floats, little- or big-endian
            xyz, valid = _read_points(fh, reader, n_frames, n_points, path)
        else:
            xyz, valid = _read_points_slowly(reader, n_frames, n_points, path)
    xyz = xyz.astype(float) * mm
    xyz[~valid] = np.nan
    positions = zero_triplets_to_nan(xyz)
    return Recording(labels=labels, positions=positions, rate_hz=rate, source=path.name, format="c3d",
                     units=units or "mm", start_ms=1000.0 * (int(reader.first_frame) - 1) / rate)


def _labels(reader: c3d.Reader) -> list[str]:
    labels: list[str] = []
    for key in ["POINT:LABELS"] + [f"POINT:LABELS{k}" for k in range(2, 100)]:
        param = reader.get(key)
        if param is None:
            if key != "POINT:LABELS":
                break
            continue
        labels += [str(s).strip() for s in np.atleast_1d(param.string_array).ravel()]
    return labels


def _unique(labels: list[str]) -> list[str]:
    """Blank or repeated labels get numbered names, so every point has its own."""
    out, seen = [], set()
    for k, label in enumerate(labels):
        name = label or f"point{k + 1}"
        while name in seen:
            name = f"{name}_{k + 1}"
        seen.add(name)
        out.append(name)
    return out


def _read_points(fh: BinaryIO, reader: c3d.Reader, n_frames: int, n_points: int,
                 path: Path) -> tuple[np.ndarray, np.ndarray]:
    """All frames' point words in one read: (F, P, 3) coordinates (scaled) and (F, P) validity."""
    is_float = reader.point_scale < 0
    word = 4 if is_float else 2
    order = ">" if reader.proc_type == "MIPS" else "<"
    n_analog = int(reader.analog_used) * int(reader.analog_per_frame)
    frame_bytes = 4 * n_points * word + n_analog * word
    start = (int(reader.header.data_block) - 1) * 512
    fh.seek(start)
    data = fh.read(frame_bytes * n_frames)
    complete = len(data) // frame_bytes if frame_bytes else n_frames
    if complete < n_frames:
        raise MarkerFileError(f"the data end after {complete} of {n_frames} frames (truncated?)", file=path)
    if n_points == 0:
        return np.zeros((n_frames, 0, 3)), np.zeros((n_frames, 0), bool)
    frames = np.frombuffer(data, dtype=np.uint8).reshape(n_frames, frame_bytes)[:, :4 * n_points * word]
    if is_float:
        words = frames.copy().view(order + "f4").reshape(n_frames, n_points, 4)
        xyz = words[..., :3].astype(np.float64)
        # the fourth word is an integer (camera bits and residual) stored as a float; negative means invalid
        valid = np.nan_to_num(words[..., 3], nan=-1.0, posinf=-1.0, neginf=-1.0).astype(np.int64) >= 0
    else:
        words = frames.copy().view(order + "i2").reshape(n_frames, n_points, 4)
        xyz = words[..., :3].astype(np.float64) * abs(float(reader.point_scale))
        valid = words[..., 3] >= 0
    valid &= np.all(np.isfinite(xyz), axis=-1)
    return xyz, valid


def _read_points_slowly(reader: c3d.Reader, n_frames: int, n_points: int, path: Path) -> tuple[np.ndarray, np.ndarray]:
    xyz = np.full((n_frames, n_points, 3), np.nan)
    valid = np.zeros((n_frames, n_points), bool)
    count = 0
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for k, (_, points, _analog) in enumerate(reader.read_frames(copy=False, check_nan=True)):
            if k >= n_frames:
                break
            xyz[k] = points[:, :3]
            valid[k] = points[:, 3] >= 0
            count = k + 1
    if count < n_frames:
        note = f" ({caught[0].message})" if caught else ""
        raise MarkerFileError(f"the data end after {count} of {n_frames} frames (truncated?){note}", file=path)
    return xyz, valid


def _describe(exc: Exception) -> str:
    text = " ".join(str(exc).split())
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__
