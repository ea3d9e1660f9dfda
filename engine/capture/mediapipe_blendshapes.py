"""MediaPipe Face Landmarker blendshape scores, as JSON or CSV.

The Face Landmarker (``output_face_blendshapes=True``) gives, per frame and
face, 52 ARKit-named categories plus ``_neutral``, each with a ``score`` 0–1.
MediaPipe writes no file of its own; these are the shapes accepted, being
how its results serialise:

**JSON** — a list of frames, or an object ``{"frames": [...]}``. A frame is
an object with

* the time: ``timestampMs`` or ``timestamp_ms`` (ms; the value passed to
  ``detect_for_video``), in every frame or in none (then ``fps`` times them);
* the scores: ``faceBlendshapes`` (the JavaScript ``FaceLandmarkerResult``
  through ``JSON.stringify``: per face ``{"categories": [...], "headIndex": …}``)
  or ``face_blendshapes`` (Python: per face a list of categories, e.g.
  ``dataclasses.asdict`` of each ``Category``). The first face is read; an
  empty list is a frame without a face (left out; the frames around bridge it).
  A category is ``{"categoryName"|"category_name": name, "score": number}``;
  ``index`` and ``displayName``/``display_name`` may be there too.

``facialTransformationMatrixes`` (JavaScript) or
``facial_transformation_matrixes`` (Python), where present in every frame
with a face, give the head's turn, nod and tilt
(:mod:`engine.capture.mediapipe_pose`). Other keys (``faceLandmarks``) are
allowed and not read.

**CSV** — a header ``timestamp_ms`` or ``time_ms`` (ms) or ``frame`` (with
``fps``), then the 52 names (``_neutral`` allowed), in any order; one row per
frame.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from engine.capture.arkit_names import ARKIT_BLENDSHAPES
from engine.capture.mediapipe_pose import ANGLE_CHANNELS, head_angles, matrix_rows
from engine.capture.stream import CaptureFileError, CaptureStream
from engine.capture.text_table import MAX_CAPTURE_BYTES, check_unique, check_width, number, split_rows
from engine.formats.text_files import read_bounded_text

NEUTRAL = "_neutral"
TIME_KEYS = ("timestampMs", "timestamp_ms")
BLENDSHAPE_KEYS = ("faceBlendshapes", "face_blendshapes")
MATRIX_KEYS = ("facialTransformationMatrixes", "facial_transformation_matrixes")
CSV_TIME_COLUMNS = {"timestamp_ms": "ms", "time_ms": "ms", "frame": "frame"}
KNOWN = frozenset(ARKIT_BLENDSHAPES) | {NEUTRAL}


def looks_like_json(text: str) -> bool:
    """Whether ``text`` starts like a JSON document (``[`` or ``{``)."""
    return text.lstrip()[:1] in ("[", "{")


def is_mediapipe_csv_header(cells: list[str]) -> bool:
    """Whether a first CSV row looks like a MediaPipe blendshape table."""
    return bool(cells) and cells[0] in CSV_TIME_COLUMNS and "eyeBlinkLeft" in cells


def read_mediapipe(path: str | Path, fps: float | None = None) -> CaptureStream:
    """Read MediaPipe blendshape scores from a JSON or CSV file (see the module notes for the shapes)."""
    text = read_bounded_text(path, limit=MAX_CAPTURE_BYTES, error=CaptureFileError, what="capture file")
    return parse_mediapipe(text, str(path), fps)


def parse_mediapipe(text: str, name: str = "<mediapipe>", fps: float | None = None) -> CaptureStream:
    """:func:`read_mediapipe` on text."""
    if looks_like_json(text):
        return _parse_json(text, name, fps)
    return _parse_csv(text, name, fps)


# ---------------------------------------------------------------------------
# JSON

def _parse_json(text: str, source: str, fps: float | None) -> CaptureStream:
    try:
        document = json.loads(text)
    except json.JSONDecodeError as exc:
        raise CaptureFileError(f"not JSON: {exc.msg}", file=source, line=exc.lineno) from None
    except RecursionError:
        raise CaptureFileError("not JSON this reader takes: nested too deeply", file=source) from None
    frames = document.get("frames") if isinstance(document, dict) else document
    if not isinstance(frames, list):
        raise CaptureFileError("expected a list of frames, or an object with \"frames\": a list", file=source)
    if not frames:
        raise CaptureFileError("no frames", file=source)
    lines = _frame_lines(text, len(frames))
    stamps: list[float | None] = []
    rows: list[list[float]] = []
    poses: list[np.ndarray | None] = []
    kept: list[int] = []
    empty = 0
    for i, frame in enumerate(frames):
        where = f"frame {i}"
        if not isinstance(frame, dict):
            raise CaptureFileError(f"{where} is not an object", file=source, line=lines[i])
        stamp = _frame_time(frame, where, source, lines[i])
        categories = _first_face(frame, where, source, lines[i])
        if categories is None:
            empty += 1
            stamps.append(stamp)
            continue
        rows.append(_scores(categories, where, source, lines[i]))
        poses.append(_first_pose(frame, where, source, lines[i]))
        stamps.append(stamp)
        kept.append(i)
    timed = [s is not None for s in stamps]
    if any(timed) and not all(timed):
        bad = timed.index(not timed[0])
        raise CaptureFileError(f"frame {bad}: a time in some frames but not in others", file=source, line=lines[bad])
    if not rows:
        raise CaptureFileError("no frame with a face (every faceBlendshapes list is empty)", file=source)
    if all(timed):
        times = np.array([stamps[i] for i in kept], dtype=float)
    elif fps is not None:
        times = np.array(kept, dtype=float) * (1000.0 / fps)
    else:
        raise CaptureFileError("the frames carry no timestampMs: give the frame rate with --fps", file=source)
    _check_rising(times, [lines[i] for i in kept], source, "timestampMs")
    notes = [f"{empty} frame(s) without a face left out; the frames around bridge them"] if empty else []
    stream = _stream(source, times - times[0], np.array(rows), notes)
    posed = [p is not None for p in poses]
    if any(posed) and not all(posed):
        bad = kept[posed.index(not posed[0])]
        raise CaptureFileError(f"frame {bad}: a transformation matrix in some frames with a face but not in "
                               "others", file=source, line=lines[bad])
    if all(posed):
        angles = np.array([head_angles(p) for p in poses if p is not None])
        for j, channel in enumerate(ANGLE_CHANNELS):
            stream.channels[channel] = angles[:, j]
    return stream


def _first_pose(frame: Mapping[str, Any], where: str, source: str, line: int | None) -> np.ndarray | None:
    key = next((k for k in MATRIX_KEYS if k in frame), None)
    if key is None:
        return None
    matrices = frame[key]
    if not isinstance(matrices, list):
        raise CaptureFileError(f"{where}: {key} is not a list (one matrix per face)", file=source, line=line)
    return matrix_rows(matrices[0], where, source, line) if matrices else None


def _frame_lines(text: str, count: int) -> list[int | None]:
    """Line of each frame where the document has one frame per line (else None: errors name the frame)."""
    lines = text.splitlines()
    if len(lines) == 1:
        return [1] * count
    starts = [n for n, line in enumerate(lines, start=1) if line.lstrip().startswith("{")]
    if len(starts) == count:
        return list(starts)
    return [None] * count


def _frame_time(frame: Mapping[str, Any], where: str, source: str, line: int | None) -> float | None:
    for key in TIME_KEYS:
        if key in frame:
            value = frame[key]
            if not _finite(value):
                raise CaptureFileError(f"{where}: {key} is not a number", file=source, line=line)
            return float(value)
    return None


def _first_face(frame: Mapping[str, Any], where: str, source: str, line: int | None) -> list[Any] | None:
    key = next((k for k in BLENDSHAPE_KEYS if k in frame), None)
    if key is None:
        raise CaptureFileError(f"{where}: no faceBlendshapes (was output_face_blendshapes on?)",
                               file=source, line=line)
    faces = frame[key]
    if not isinstance(faces, list):
        raise CaptureFileError(f"{where}: {key} is not a list (one entry per face)", file=source, line=line)
    if not faces:
        return None
    face = faces[0]
    if isinstance(face, dict):
        face = face.get("categories")
    if not isinstance(face, list):
        raise CaptureFileError(f"{where}: a face in {key} is neither a list of categories nor "
                               "{\"categories\": [...]}", file=source, line=line)
    return face


def _scores(categories: list[Any], where: str, source: str, line: int | None) -> list[float]:
    found: dict[str, float] = {}
    for category in categories:
        if not isinstance(category, dict):
            raise CaptureFileError(f"{where}: a category is not an object", file=source, line=line)
        name = category.get("categoryName", category.get("category_name"))
        score: Any = category.get("score")
        if not isinstance(name, str):
            raise CaptureFileError(f"{where}: a category without categoryName", file=source, line=line)
        if name not in KNOWN:
            raise CaptureFileError(f"{where}: unknown blendshape '{name[:40]}'", file=source, line=line)
        if name in found:
            raise CaptureFileError(f"{where}: blendshape '{name}' twice", file=source, line=line)
        if not _finite(score):
            raise CaptureFileError(f"{where}: the score of '{name}' is not a finite number", file=source, line=line)
        found[name] = float(score)
    missing = [n for n in ARKIT_BLENDSHAPES if n not in found]
    if missing:
        raise CaptureFileError(f"{where}: {len(missing)} blendshape(s) missing: {', '.join(missing[:4])}"
                               + (" …" if len(missing) > 4 else ""), file=source, line=line)
    return [found[n] for n in ARKIT_BLENDSHAPES]


# ---------------------------------------------------------------------------
# CSV

def _parse_csv(text: str, source: str, fps: float | None) -> CaptureStream:
    rows = split_rows(text)
    if not rows:
        raise CaptureFileError("empty file: no header", file=source, line=1)
    header_line, header = rows[0]
    if not header or header[0] not in CSV_TIME_COLUMNS:
        raise CaptureFileError("not a MediaPipe blendshape CSV: the first column is not timestamp_ms, time_ms "
                               "or frame", file=source, line=header_line)
    check_unique(header, source, header_line)
    unknown = [n for n in header[1:] if n not in KNOWN]
    if unknown:
        raise CaptureFileError(f"unknown blendshape column '{unknown[0][:40]}'", file=source, line=header_line)
    missing = [n for n in ARKIT_BLENDSHAPES if n not in header]
    if missing:
        raise CaptureFileError(f"{len(missing)} blendshape column(s) missing: {', '.join(missing[:4])}"
                               + (" …" if len(missing) > 4 else ""), file=source, line=header_line)
    if CSV_TIME_COLUMNS[header[0]] == "frame" and fps is None:
        raise CaptureFileError("a 'frame' column needs the frame rate: give --fps", file=source, line=header_line)
    if len(rows) < 2:
        raise CaptureFileError("no frames after the header", file=source, line=header_line)
    order = [header.index(n) for n in ARKIT_BLENDSHAPES]
    times = np.empty(len(rows) - 1)
    table = np.empty((len(rows) - 1, len(ARKIT_BLENDSHAPES)))
    lines: list[int] = []
    for i, (line, cells) in enumerate(rows[1:]):
        lines.append(line)
        check_width(cells, len(header), source, line)
        times[i] = number(cells[0], source, line, header[0])
        table[i] = [number(cells[j], source, line, header[j]) for j in order]
    if CSV_TIME_COLUMNS[header[0]] == "frame":
        assert fps is not None
        times = times * (1000.0 / fps)
    _check_rising(times, lines, source, header[0])
    return _stream(source, times - times[0], table, [])


def _check_rising(times: np.ndarray, lines: list[int | None] | list[int], source: str, what: str) -> None:
    steps = np.diff(times)
    if len(steps) and steps.min() <= 0:
        bad = int(np.argmax(steps <= 0)) + 1
        raise CaptureFileError(f"{what} does not rise from the frame before", file=source, line=lines[bad])


def _finite(value: Any) -> bool:
    """Whether a JSON value is a finite number (not a boolean, not a string, not 1e999)."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return False
    try:
        return math.isfinite(float(value))
    except OverflowError:
        return False


def _stream(source: str, times: np.ndarray, table: np.ndarray, notes: list[str]) -> CaptureStream:
    channels = {name: table[:, j] for j, name in enumerate(ARKIT_BLENDSHAPES)}
    return CaptureStream(source, "mediapipe", times, channels, notes)
