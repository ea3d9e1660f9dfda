"""ARKit face tracking as Epic's Live Link Face app exports it (CSV).

The layout, as the app writes it (checked on the public takes in
``tests/data/capture_streams/``)::

    Timecode,BlendShapeCount,EyeBlinkLeft,EyeLookDownLeft,…,TongueOut,HeadYaw,HeadPitch,HeadRoll,
        LeftEyeYaw,LeftEyePitch,LeftEyeRoll,RightEyeYaw,RightEyePitch,RightEyeRoll
    13:13:04:31.652,61,0.1236470118,…

* ``Timecode`` is SMPTE ``HH:MM:SS:FF.fff``: ``FF`` counts frames of the
  timecode rate (60 on the iPhone, whatever rate the take was recorded at),
  ``.fff`` is the fraction of a frame. The rate is found from the file: the
  standard rate above the largest ``FF`` that makes the frame intervals most
  even (where the take never crosses a second, 60, the app's rate).
* ``BlendShapeCount`` is the number of values after it (61 = 52 + 9).
* 52 blendshapes, 0–1, in the app's capitalisation (``EyeBlinkLeft``).
* Head and eye rotations in radians (optional; absent or all zero when the
  app was set not to stream the head). Their signs, read off the takes: a
  positive eye yaw looks to the subject's right and a positive pitch looks
  down (the eye columns follow ``EyeLookOut``/``EyeLookIn``/``EyeLookUp``
  with correlation −0.999), so the frame is the head frame with Y and Z
  reversed; head yaw, pitch and roll are read in that same frame. The roll
  of the eyes is not used.

>>> take = read_live_link_face("tests/data/capture_streams/llf_rom_mouth.csv")   # doctest: +SKIP
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from engine.capture.arkit_names import ARKIT_BLENDSHAPES, canonical_blendshape
from engine.capture.stream import CaptureFileError, CaptureStream
from engine.capture.text_table import Rows, check_unique, check_width, number, read_rows, split_rows, whole_number

#: Rotation columns → (channel, sign): the app's frame has Y and Z reversed from the head frame.
ROTATION_COLUMNS: dict[str, tuple[str, float]] = {
    "headyaw": ("head_turn_rad", -1.0), "headpitch": ("head_nod_rad", 1.0), "headroll": ("head_tilt_rad", -1.0),
    "lefteyeyaw": ("eye_left_turn_rad", -1.0), "lefteyepitch": ("eye_left_raise_rad", -1.0),
    "righteyeyaw": ("eye_right_turn_rad", -1.0), "righteyepitch": ("eye_right_raise_rad", -1.0),
    "lefteyeroll": ("", 0.0), "righteyeroll": ("", 0.0),
}
TIMECODE = re.compile(r"(\d{2}):(\d{2}):(\d{2})[:;.](\d{2,3})(?:\.(\d{1,9}))?")
TIMECODE_RATES = (24, 25, 30, 48, 50, 60, 72, 96, 100, 120, 240)
APP_TIMECODE_RATE = 60
MAX_ANGLE_RAD = 2 * np.pi


def is_live_link_face_header(cells: list[str]) -> bool:
    """Whether a first row looks like Live Link Face's (``Timecode,BlendShapeCount,…``)."""
    return len(cells) >= 2 and cells[0].lower() == "timecode" and cells[1].lower() == "blendshapecount"


def read_live_link_face(path: str | Path) -> CaptureStream:
    """Read a Live Link Face CSV; times from the timecode, ms from the first frame."""
    return _parse(read_rows(path), str(path))


def parse_live_link_face(text: str, name: str = "<live link face>") -> CaptureStream:
    """:func:`read_live_link_face` on text."""
    return _parse(split_rows(text), name)


def _parse(rows: Rows, source: str) -> CaptureStream:
    if not rows:
        raise CaptureFileError("empty file: no Live Link Face header", file=source, line=1)
    header_line, header = rows[0]
    if not is_live_link_face_header(header):
        raise CaptureFileError("not a Live Link Face CSV: the header does not start with Timecode,BlendShapeCount",
                               file=source, line=header_line)
    check_unique(header, source, header_line)
    columns = _columns(header, source, header_line)
    if len(rows) < 2:
        raise CaptureFileError("no frames after the header", file=source, line=header_line)
    stamps: list[tuple[int, int, int, int, float]] = []
    lines: list[int] = []
    values = np.empty((len(rows) - 1, len(header) - 2))
    for i, (line, cells) in enumerate(rows[1:]):
        lines.append(line)
        check_width(cells, len(header), source, line)
        stamps.append(_timecode(cells[0], source, line))
        count = whole_number(cells[1], source, line, "BlendShapeCount")
        if count != len(header) - 2:
            raise CaptureFileError(f"BlendShapeCount {count} but the header has {len(header) - 2} values",
                                   file=source, line=line)
        for j, cell in enumerate(cells[2:]):
            values[i, j] = number(cell, source, line, header[j + 2])
    times = _times_ms(stamps, lines, source)
    channels: dict[str, np.ndarray] = {}
    for j, (channel, sign) in enumerate(columns):
        if not channel:
            continue
        column = values[:, j]
        if channel.endswith("_rad"):
            worst = int(np.argmax(np.abs(column)))
            if abs(column[worst]) > MAX_ANGLE_RAD:
                raise CaptureFileError(f"column '{header[j + 2]}': {column[worst]:g} is not an angle in radians",
                                       file=source, line=lines[worst])
        channels[channel] = sign * column
    return CaptureStream(source, "arkit", times, channels)


def _columns(header: list[str], source: str, line: int) -> list[tuple[str, float]]:
    """(channel, sign) per value column; the 52 blendshapes are required, the rotations optional."""
    columns: list[tuple[str, float]] = []
    for name in header[2:]:
        blendshape = canonical_blendshape(name)
        if blendshape is not None:
            columns.append((blendshape, 1.0))
        elif name.lower() in ROTATION_COLUMNS:
            columns.append(ROTATION_COLUMNS[name.lower()])
        else:
            raise CaptureFileError(f"unknown column '{name[:40]}' (not an ARKit blendshape or a head/eye rotation)",
                                   file=source, line=line)
    missing = [n for n in ARKIT_BLENDSHAPES if n not in {c for c, _ in columns}]
    if missing:
        raise CaptureFileError(f"{len(missing)} ARKit blendshape column(s) missing: {', '.join(missing[:4])}"
                               + (" …" if len(missing) > 4 else ""), file=source, line=line)
    return columns


def _timecode(cell: str, source: str, line: int) -> tuple[int, int, int, int, float]:
    match = TIMECODE.fullmatch(cell)
    if match is None:
        raise CaptureFileError(f"timecode '{cell[:40]}' is not HH:MM:SS:FF.fff", file=source, line=line)
    hours, minutes, seconds, frame = (int(g) for g in match.groups()[:4])
    fraction = float("0." + match.group(5)) if match.group(5) else 0.0
    if hours > 23 or minutes > 59 or seconds > 59:
        raise CaptureFileError(f"timecode '{cell}' is not a time of day", file=source, line=line)
    return hours, minutes, seconds, frame, fraction


def _times_ms(stamps: list[tuple[int, int, int, int, float]], lines: list[int], source: str) -> np.ndarray:
    """Frame times (ms from the first frame) at the timecode rate that makes the intervals most even."""
    whole = np.array([h * 3600 + m * 60 + s for h, m, s, _, _ in stamps], dtype=float)
    whole = whole + 86400.0 * np.concatenate([[0], np.cumsum(np.diff(whole) < -43200)])   # past midnight
    frames = np.array([f + x for _, _, _, f, x in stamps], dtype=float)
    top = int(max(f for _, _, _, f, _ in stamps))
    rates = [r for r in TIMECODE_RATES if r > top]
    if not rates:
        raise CaptureFileError(f"timecode frame {top} is above every standard rate", file=source,
                               line=lines[[f for _, _, _, f, _ in stamps].index(top)])
    if len(set(whole.tolist())) == 1 and APP_TIMECODE_RATE in rates:
        rates = [APP_TIMECODE_RATE]               # within one second nothing tells the rates apart
    best: tuple[float, np.ndarray] | None = None
    for rate in rates:
        seconds = whole + frames / rate
        steps = np.diff(seconds)
        if len(steps) and steps.min() <= 0:
            continue
        spread = float(steps.max() / steps.min()) if len(steps) else 1.0
        if best is None or spread < best[0] - 1e-9:
            best = (spread, seconds)
    if best is None:
        steps = np.diff(whole + frames / rates[0])
        bad = int(np.argmax(steps <= 0)) + 1
        raise CaptureFileError("the timecode does not rise from the row before", file=source, line=lines[bad])
    seconds = best[1]
    return (seconds - seconds[0]) * 1000.0
