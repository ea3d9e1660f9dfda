"""OpenFace 2.x ``FeatureExtraction`` output (CSV).

The layout, as OpenFace's ``RecorderCSV`` writes it for a video (a comma and
a space between cells; which groups appear depends on the ``-aus -gaze
-pose -2Dfp -3Dfp -pdmparams`` flags)::

    frame, face_id, timestamp, confidence, success, gaze_0_x, …, gaze_angle_x, gaze_angle_y,
        eye_lmk_x_0, …, pose_Tx, pose_Ty, pose_Tz, pose_Rx, pose_Ry, pose_Rz, x_0, …, p_scale, …,
        AU01_r, …, AU45_r, AU01_c, …, AU45_c
    1, 0, 0.000, 0.98, 1, 0.118913, …

What is read: ``timestamp`` (s), ``success`` (rows with 0 carry no face and
are left out, the frames around them bridge the gap), the intensities
``AUxx_r`` (0–5), ``pose_Rx/Ry/Rz`` (radians, camera frame: x right in the
image, y down, z away from the camera; Rx pitch, Ry yaw, Rz roll) and
``gaze_angle_x/y`` (radians, camera frame; positive x looks to the subject's
left, positive y looks down). The camera frame is the head frame turned half
a turn about X, so ``head_turn = −Ry``, ``head_nod = +Rx``, ``head_tilt = −Rz``
(OpenFace: turning to one's right gives a positive Ry, tipping the head up a
negative Rx). Gaze is in the camera's frame, so the head's own turn and nod
are taken off to get the eyes' turn in the head. Where several faces were
tracked (``FaceLandmarkVidMulti``) the first ``face_id`` is read and the
others are noted. Image-sequence runs (``-fdir``) write ``timestamp`` 0 on
every row: give the frame rate (``fps``) and the frame numbers time them.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from engine.capture.stream import CaptureFileError, CaptureStream
from engine.capture.text_table import Rows, check_unique, check_width, number, read_rows, split_rows, whole_number

FIRST_COLUMNS = ["frame", "face_id", "timestamp", "confidence", "success"]
KNOWN_COLUMN = re.compile(r"gaze_[01]_[xyz]|gaze_angle_[xy]|eye_lmk_[xyXYZ]_\d{1,4}|pose_[TR][xyz]|[xyXYZ]_\d{1,4}"
                          r"|p_(scale|rx|ry|rz|tx|ty|\d{1,4})|AU\d\d_[rc]")
POSE = {"pose_Rx": ("head_nod_rad", 1.0), "pose_Ry": ("head_turn_rad", -1.0), "pose_Rz": ("head_tilt_rad", -1.0)}
MAX_INTENSITY = 5.0


def is_openface_header(cells: list[str]) -> bool:
    """Whether a first row looks like OpenFace's (``frame, face_id, timestamp, …`` or ``face, confidence``)."""
    return cells[:5] == FIRST_COLUMNS or cells[:2] == ["face", "confidence"]


def read_openface(path: str | Path, fps: float | None = None) -> CaptureStream:
    """Read an OpenFace ``FeatureExtraction`` CSV; ``fps`` times image-sequence runs (timestamps all 0)."""
    return _parse(read_rows(path), str(path), fps)


def parse_openface(text: str, name: str = "<openface>", fps: float | None = None) -> CaptureStream:
    """:func:`read_openface` on text."""
    return _parse(split_rows(text), name, fps)


def _parse(rows: Rows, source: str, fps: float | None) -> CaptureStream:
    if not rows:
        raise CaptureFileError("empty file: no OpenFace header", file=source, line=1)
    header_line, header = rows[0]
    if header[:2] == ["face", "confidence"]:
        raise CaptureFileError("OpenFace output for single images (face, confidence …) has no frames in time: "
                               "run FeatureExtraction on the video", file=source, line=header_line)
    if header[:5] != FIRST_COLUMNS:
        raise CaptureFileError("not an OpenFace FeatureExtraction CSV: the header does not start with "
                               "frame, face_id, timestamp, confidence, success", file=source, line=header_line)
    check_unique(header, source, header_line)
    for name in header[5:]:
        if KNOWN_COLUMN.fullmatch(name) is None:
            raise CaptureFileError(f"unknown OpenFace column '{name[:40]}'", file=source, line=header_line)
    index = {name: i for i, name in enumerate(header)}
    wanted = [n for n in header if n.endswith("_r") and n.startswith("AU")] + \
             [n for n in ("pose_Rx", "pose_Ry", "pose_Rz", "gaze_angle_x", "gaze_angle_y") if n in index]
    if not wanted:
        raise CaptureFileError("no AU intensities (AUxx_r), head pose or gaze angles in the header "
                               "(run FeatureExtraction with -aus, -pose or -gaze)", file=source, line=header_line)
    first_face: int | None = None
    other_faces: set[int] = set()
    frames: list[int] = []
    stamps: list[float] = []
    kept_lines: list[int] = []
    values: list[list[float]] = []
    failed = 0
    for line, cells in rows[1:]:
        check_width(cells, len(header), source, line)
        frame = whole_number(cells[0], source, line, "frame")
        face = whole_number(cells[1], source, line, "face_id")
        stamp = number(cells[2], source, line, "timestamp")
        number(cells[3], source, line, "confidence")
        success = whole_number(cells[4], source, line, "success")
        if success > 1:
            raise CaptureFileError(f"column 'success': {success} is not 0 or 1", file=source, line=line)
        row = [number(cells[index[n]], source, line, n) for n in wanted]
        if first_face is None:
            first_face = face
        if face != first_face:
            other_faces.add(face)
            continue
        if not success:
            failed += 1
            continue
        frames.append(frame)
        stamps.append(stamp)
        kept_lines.append(line)
        values.append(row)
    if not values:
        raise CaptureFileError("no frame where OpenFace found the face (success is 0 on every row)",
                               file=source, line=rows[-1][0])
    times = _times_ms(np.array(frames, dtype=float), np.array(stamps), kept_lines, source, fps)
    table = np.array(values)
    channels: dict[str, np.ndarray] = {}
    for j, name in enumerate(wanted):
        column = table[:, j]
        if name.startswith("AU"):
            if column.min() < 0 or column.max() > MAX_INTENSITY:
                bad = int(np.argmax((column < 0) | (column > MAX_INTENSITY)))
                raise CaptureFileError(f"column '{name}': intensity {column[bad]:g} is outside 0–5",
                                       file=source, line=kept_lines[bad])
            channels[name[:4]] = column
        elif name in POSE:
            channel, sign = POSE[name]
            channels[channel] = sign * column
    if "gaze_angle_x" in index and "gaze_angle_y" in index:
        turn = table[:, wanted.index("gaze_angle_x")]
        down = table[:, wanted.index("gaze_angle_y")]
        eye_turn = turn - channels.get("head_turn_rad", 0.0)
        eye_raise = -down + channels.get("head_nod_rad", 0.0)
        for side in ("left", "right"):
            channels[f"eye_{side}_turn_rad"] = np.asarray(eye_turn, dtype=float)
            channels[f"eye_{side}_raise_rad"] = np.asarray(eye_raise, dtype=float)
    notes = []
    if failed:
        notes.append(f"{failed} frame(s) without a tracked face (success 0) left out; the frames around bridge them")
    if other_faces:
        notes.append(f"face {first_face} read; face(s) {', '.join(map(str, sorted(other_faces)))} left out")
    return CaptureStream(source, "openface", times, channels, notes)


def _times_ms(frames: np.ndarray, stamps: np.ndarray, lines: list[int], source: str,
              fps: float | None) -> np.ndarray:
    if fps is None and len(stamps) > 1 and np.all(stamps == stamps[0]):
        raise CaptureFileError("every timestamp is the same (an image-sequence run?): give the frame rate "
                               "with --fps", file=source, line=lines[0])
    times = (frames - frames[0]) * (1000.0 / fps) if fps is not None else (stamps - stamps[0]) * 1000.0
    steps = np.diff(times)
    if len(steps) and steps.min() <= 0:
        bad = int(np.argmax(steps <= 0)) + 1
        what = "frame number" if fps is not None else "timestamp"
        raise CaptureFileError(f"the {what} does not rise from the row before", file=source, line=lines[bad])
    return times
