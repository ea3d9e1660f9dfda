"""C3D marker files, read by our own parser (:mod:`engine.mocap.c3d_parameters`) and one numpy pass.

Labels come from ``POINT:LABELS`` (and ``LABELS2``…), the rate from
``POINT:RATE``, the scale from ``POINT:SCALE`` (negative: float data), the
unit from ``POINT:UNITS`` (one string, or one per marker; NUL padding
ignored), each falling back on the header. The frame count is the one the
header, ``POINT:FRAMES`` and ``TRIAL:ACTUAL_START/END_FIELD`` agree on with
the file's size (docs/capture-files.md says how disagreements are settled).

A sample is missing when its fourth word (camera mask and residual) is
negative — for float data, when the stored float is negative, whatever its
size (some writers put +1.7e38 there for valid samples) — when a coordinate
is not finite, or when it is exactly ``(0, 0, 0)``.

>>> rec = read_c3d("take1.c3d")           # doctest: +SKIP
>>> rec.positions.shape, rec.rate_hz      # doctest: +SKIP
((600, 32, 3), 60.0)
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from engine.mocap.c3d_parameters import C3dHeader, C3dParameters, decode_floats, int_order, read_parameters
from engine.mocap.errors import MarkerFileError
from engine.mocap.recording import Recording, check_rate, unit_scale, zero_triplets_to_nan

MAX_FILE_BYTES = 4 << 30
"""Larger files are refused rather than read into memory whole (4 GiB: about 10 hours of 100 markers at 100 Hz)."""


def read_c3d(path: str | Path) -> Recording:
    """Read the 3D points of a C3D file; positions in mm, invalid samples as NaN."""
    path = Path(path)
    data = _read_bytes(path)
    header, params = read_parameters(data, path)
    notes = list(params.notes)
    rate = _rate(header, params, path)
    n_points = _point_count(header, params, notes)
    labels = _unique(_labels(params, n_points))
    if n_points == 0:
        analog = params.number("ANALOG:USED") or 0
        raise MarkerFileError("the file holds no 3D marker points (POINT:USED is 0)"
                              + (f"; it holds {int(analog)} analog channels only, which are not marker data"
                                 if analog else ""), file=path)
    scales = _unit_scales(params, n_points, path)
    scale = _scale(header, params, notes, path)
    is_float = scale < 0
    word = 4 if is_float else 2
    start = _data_start(header, params, len(data), path)
    analog_words = _analog_words(header, params, rate, n_points, word, len(data) - start, notes)
    frame_bytes = (4 * n_points + analog_words) * word
    available = (len(data) - start) // frame_bytes
    n_frames = _frame_count(header, params, available, notes, path)
    frames = np.frombuffer(data, dtype=np.uint8, count=n_frames * frame_bytes, offset=start)
    frames = frames.reshape(n_frames, frame_bytes)[:, :4 * n_points * word]
    if is_float:
        words = decode_floats(frames.tobytes(), params.processor).reshape(n_frames, n_points, 4)
        xyz = words[..., :3].copy()
        valid = ~(words[..., 3] < 0)  # NaN or +1.7e38 is not "negative": the sample is valid
    else:
        ints = frames.copy().view(int_order(params.processor) + "i2").reshape(n_frames, n_points, 4)
        xyz = ints[..., :3].astype(np.float64) * abs(scale)
        valid = ints[..., 3] >= 0
    valid &= np.all(np.isfinite(xyz), axis=-1)
    xyz *= scales[None, :, None]
    xyz_read = xyz.copy() if not valid.any() else xyz
    xyz[~valid] = np.nan
    positions = zero_triplets_to_nan(xyz)
    if n_frames and not np.isfinite(positions).any():
        hidden = int(np.count_nonzero(np.any(xyz_read != 0, axis=-1) & np.all(np.isfinite(xyz_read), axis=-1)))
        raise MarkerFileError(f"every sample of all {n_points} points in {n_frames} frames is marked missing "
                              "(negative residual, not finite or 0 0 0): nothing to import"
                              + (f"; {hidden} samples hold coordinates but a negative residual word, which "
                                 "the writer uses for an invalid sample" if hidden else ""), file=path)
    first = _first_frame(header, params)
    units = sorted(set(_unit_texts(params, n_points)))
    return Recording(labels=labels, positions=positions, rate_hz=rate, source=path.name, format="c3d",
                     units="/".join(units) or "mm", start_ms=1000.0 * (first - 1) / rate, notes=notes,
                     up_hint=_screen_up(params))


def _screen_up(params: C3dParameters) -> str | None:
    """``POINT:Y_SCREEN`` (the axis a viewer shows upward, e.g. ``+Z``), when it names an axis."""
    param = params.get("POINT:Y_SCREEN")
    text = param.strings()[0].upper() if param is not None and param.strings() else ""
    return text if len(text) == 2 and text[0] in "+-" and text[1] in "XYZ" else None


def _read_bytes(path: Path) -> bytes:
    try:
        size = path.stat().st_size
        if size > MAX_FILE_BYTES:
            raise MarkerFileError(f"the file is {size / 2**30:.1f} GiB, more than the "
                                  f"{MAX_FILE_BYTES / 2**30:.0f} GiB read here", file=path)
        return path.read_bytes()
    except OSError as exc:
        raise MarkerFileError(f"cannot read: {exc.strerror or exc}", file=path) from None


def _rate(header: C3dHeader, params: C3dParameters, path: Path) -> float:
    rate = params.number("POINT:RATE")
    if rate is None or not (np.isfinite(rate) and rate > 0):
        rate = header.rate
    return check_rate(rate, "POINT:RATE", path)


def _whole(values: np.ndarray) -> int | None:
    """The first value as a count: None when there is none, or it is not a finite whole number from 0 to 2³¹."""
    if not values.size:
        return None
    value = float(values[0])
    return int(value) if np.isfinite(value) and 0 <= value < 2**31 and value == int(value) else None


def _scale(header: C3dHeader, params: C3dParameters, notes: list[str], path: Path) -> float:
    """The point scale (negative: float data): the header's, ``POINT:SCALE`` where the header has none.

    They differ in one file of the corpus (c3d.org sample 6, ``MACsample.c3d``),
    where the header's makes a body of human size (foot 19 cm, upper arm
    36 cm) and ``POINT:SCALE`` one of 40 % of it.
    """
    param = params.number("POINT:SCALE")
    header_ok = bool(np.isfinite(header.scale) and header.scale != 0 and abs(header.scale) < 1e30)
    param_ok = param is not None and bool(np.isfinite(param) and param != 0 and abs(param) < 1e30)
    if not param_ok or param is None:
        if not header_ok:
            raise MarkerFileError(f"no usable point scale (header {header.scale:g}, POINT:SCALE {param})", file=path)
        return header.scale
    if not header_ok:
        return param
    if abs(param - header.scale) > 1e-6 * abs(header.scale):
        notes.append(f"POINT:SCALE says {param:g}, the header {header.scale:g}; the header's used")
    return header.scale


def _point_count(header: C3dHeader, params: C3dParameters, notes: list[str]) -> int:
    used = params.get("POINT:USED")
    count = _whole(used.unsigned_words()) if used is not None and used.kind in (1, 2, 4) else None
    if count is None:
        return header.point_count
    if count != header.point_count:
        notes.append(f"POINT:USED says {count} points, the header {header.point_count}; POINT:USED used")
    return count


def _data_start(header: C3dHeader, params: C3dParameters, size: int, path: Path) -> int:
    """Byte offset of the frames: the header's block, else ``POINT:DATA_START`` (some writers put 1 there)."""
    for block in (header.data_block, params.number("POINT:DATA_START")):
        if block is not None and np.isfinite(block) and header.parameter_block < block and (block - 1) * 512 < size:
            return (int(block) - 1) * 512
    raise MarkerFileError(f"the point data are said to start in block {header.data_block}, outside the file",
                          file=path)


def _analog_words(header: C3dHeader, params: C3dParameters, point_rate: float, n_points: int, word: int,
                  data_bytes: int, notes: list[str]) -> int:
    """Analog samples stored after each frame's points.

    ANALOG:USED × (ANALOG:RATE / POINT:RATE) and the header's count usually
    agree; where they do not, the one whose frames fill the data to the
    declared frame count wins (the header's when both or neither do).
    """
    used_param, rate = params.get("ANALOG:USED"), params.number("ANALOG:RATE")
    used = _whole(used_param.unsigned_words()) if used_param is not None else None
    if used is None or rate is None or not (np.isfinite(rate) and 0 < rate / point_rate < 2**31):
        return header.analog_per_frame
    from_parameters = used * round(rate / point_rate)
    if from_parameters == header.analog_per_frame:
        return from_parameters
    frames = params.get("POINT:FRAMES")
    declared = (_whole(frames.unsigned_words()) if frames is not None else None) or (
        header.last_frame - header.first_frame + 1)

    def fills(analog: int) -> bool:
        return data_bytes // ((4 * n_points + analog) * word) == declared

    chosen = from_parameters if fills(from_parameters) and not fills(header.analog_per_frame) \
        else header.analog_per_frame
    notes.append(f"analog samples per frame: the header says {header.analog_per_frame}, ANALOG:USED × rate ratio "
                 f"{from_parameters}; {chosen} used, as the data fill")
    return chosen


def _frame_count(header: C3dHeader, params: C3dParameters, available: int, notes: list[str], path: Path) -> int:
    """The declared frame count that the file's data hold; a file cut short is read as far as it goes, with a
    note (as the reference reader reads it, but saying so)."""
    declared = []
    start, end = params.get("TRIAL:ACTUAL_START_FIELD"), params.get("TRIAL:ACTUAL_END_FIELD")
    if start is not None and end is not None and start.kind == end.kind == 2 and len(start.raw) >= 4 \
            and len(end.raw) >= 4:
        lo_hi = end.unsigned_words()[:2] - start.unsigned_words()[:2]
        declared.append(int(lo_hi[0] + 65536 * lo_hi[1]) + 1)
    if header.last_frame >= header.first_frame:
        declared.append(header.last_frame - header.first_frame + 1)
    frames = params.get("POINT:FRAMES")
    from_parameter = _whole(frames.unsigned_words()) if frames is not None else None
    if from_parameter is not None:
        declared.append(from_parameter)
    declared = [n for n in declared if n > 0]
    if not declared:
        raise MarkerFileError("the file declares no frames (the header's last frame is before its first)",
                              file=path)
    fitting = [n for n in declared if n <= available]
    if fitting:
        n = max(fitting)
        if len(set(declared)) > 1:
            notes.append(f"frame counts disagree ({', '.join(map(str, dict.fromkeys(declared)))}); "
                         f"{n} frames read, as the data hold")
        return n
    wanted = min(declared)
    if available < 1:
        raise MarkerFileError(f"the data end before the first of {wanted} frames (truncated?)", file=path)
    if wanted - available == 1:
        notes.append(f"the data end one frame early ({available} of {wanted} frames); {available} read")
    else:                               # a cut file: what is there is read, and the report says so
        notes.append(f"the file is cut short: its data end after {available} of the {wanted} frames it "
                     f"declares; the {available} there are read")
    return available


def _first_frame(header: C3dHeader, params: C3dParameters) -> int:
    start = params.get("TRIAL:ACTUAL_START_FIELD")
    if start is not None and start.kind == 2 and len(start.raw) >= 4:
        lo, hi = start.unsigned_words()[:2]
        return max(1, int(lo + 65536 * hi))
    return max(1, header.first_frame)


def _labels(params: C3dParameters, n_points: int) -> list[str]:
    labels: list[str] = []
    for key in ["POINT:LABELS"] + [f"POINT:LABELS{k}" for k in range(2, 100)]:
        param = params.get(key)
        if param is None:
            if key != "POINT:LABELS":
                break
            continue
        labels += param.strings()
    labels += [f"point{k + 1}" for k in range(len(labels), n_points)]
    return labels[:n_points]


def _unit_texts(params: C3dParameters, n_points: int) -> list[str]:
    param = params.get("POINT:UNITS")
    texts = [t for t in param.strings() if t] if param is not None else []
    return texts or ["mm"]


def _unit_scales(params: C3dParameters, n_points: int, path: Path) -> np.ndarray:
    """Millimetres per file unit for each point (POINT:UNITS may give one unit or one per point)."""
    texts = _unit_texts(params, n_points)
    if len(texts) == 1 or len(set(texts)) == 1:
        return np.full(n_points, unit_scale(texts[0], path))
    if len(texts) < n_points:
        raise MarkerFileError(f"POINT:UNITS gives {len(texts)} different units for {n_points} points", file=path)
    return np.array([unit_scale(t, path) for t in texts[:n_points]])


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
