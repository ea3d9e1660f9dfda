"""Capture files in the producers' own layouts, written the way the producers write them.

OpenFace: the header and number formats of OpenFace 2.2's ``RecorderCSV.cpp``
(``-aus -gaze -pose``, 56 eye landmarks), with the separators of a real
FeatureExtraction output (``samples/recover_au_test/test_bash1.csv`` of
github.com/Kaz-Ishibashi/RecoverAUFromOpenFace, read, not copied: two spaces
after each comma up to the AU columns, one among them). MediaPipe: the Face Landmarker result
as the JavaScript API's ``JSON.stringify`` gives it, as the Python API's
``Category`` dataclasses give it, and a CSV of the scores. Live Link Face: the
header of the real takes in ``tests/data/capture_streams/`` with rows built
here (for frames a test needs, such as jawOpen exactly 1).
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from engine.capture.arkit_names import ARKIT_BLENDSHAPES

DATA = Path(__file__).parents[1] / "data" / "capture_streams"
LLF_MOUTH = DATA / "llf_rom_mouth.csv"
LLF_EYES = DATA / "llf_rom_eyes.csv"
LLF_ROTATIONS = ["HeadYaw", "HeadPitch", "HeadRoll", "LeftEyeYaw", "LeftEyePitch", "LeftEyeRoll", "RightEyeYaw",
                 "RightEyePitch", "RightEyeRoll"]
OPENFACE_AUS_R = ["AU01", "AU02", "AU04", "AU05", "AU06", "AU07", "AU09", "AU10", "AU12", "AU14", "AU15", "AU17",
                  "AU20", "AU23", "AU25", "AU26", "AU45"]
OPENFACE_AUS_C = sorted([*OPENFACE_AUS_R, "AU28"])
EYE_LANDMARKS = 56


def llf_header() -> str:
    return LLF_MOUTH.read_text().splitlines()[0]


def llf_text(frames: Sequence[Mapping[str, float]], start: str = "10:00:00", rate: int = 60, step: int = 2) -> str:
    """Live Link Face rows: frame ``i`` at timecode ``start`` + ``i·step`` frames of ``rate``, values by name."""
    names = llf_header().split(",")[2:]
    hours, minutes, seconds = (int(x) for x in start.split(":"))
    lines = [llf_header()]
    for i, frame in enumerate(frames):
        total = i * step
        sec = seconds + total // rate
        code = f"{hours:02d}:{minutes + sec // 60:02d}:{sec % 60:02d}:{total % rate:02d}.{137:03d}"
        lines.append(",".join([code, str(len(names))] + [f"{frame.get(n, 0.0):.10f}" for n in names]))
    return "\n".join(lines) + "\n"


def openface_text(frames: Sequence[Mapping[str, float]], timestamps: bool = True, fps: float = 30.0) -> str:
    """An OpenFace FeatureExtraction CSV (-aus -gaze -pose) with AU intensities/pose/gaze by name."""
    header = ["frame", "face_id", "timestamp", "confidence", "success",
              "gaze_0_x", "gaze_0_y", "gaze_0_z", "gaze_1_x", "gaze_1_y", "gaze_1_z", "gaze_angle_x", "gaze_angle_y"]
    for group in ("x", "y", "X", "Y", "Z"):
        header += [f"eye_lmk_{group}_{i}" for i in range(EYE_LANDMARKS)]
    header += ["pose_Tx", "pose_Ty", "pose_Tz", "pose_Rx", "pose_Ry", "pose_Rz"]
    header += [f"{au}_r" for au in OPENFACE_AUS_R] + [f"{au}_c" for au in OPENFACE_AUS_C]
    lines = [", ".join(header)]
    for i, frame in enumerate(frames):
        stamp = i / fps if timestamps else 0.0
        cells = [str(i + 1), str(int(frame.get("face_id", 0))), f"{stamp:.3f}", f"{frame.get('confidence', 0.98):.2f}",
                 str(int(frame.get("success", 1)))]
        cells += [f"{v:.6f}" for v in (0.1, 0.2, -0.97, -0.1, 0.2, -0.97)]
        cells += [f"{frame.get('gaze_angle_x', 0.0):.3f}", f"{frame.get('gaze_angle_y', 0.0):.3f}"]
        cells += [f"{300.0 + k % 20:.1f}" for k in range(EYE_LANDMARKS * 2)]
        cells += [f"{-20.0 + k % 40:.1f}" for k in range(EYE_LANDMARKS * 3)]
        cells += ["12.3", "-4.5", "480.2"] + [f"{frame.get(n, 0.0):.3f}" for n in ("pose_Rx", "pose_Ry", "pose_Rz")]
        aus = [f"{frame.get(au, 0.0):.2f}" for au in OPENFACE_AUS_R]
        aus += [f"{1.0 if frame.get(au, 0.0) > 1 else 0.0:.2f}" for au in OPENFACE_AUS_C]
        # a real FeatureExtraction output has two spaces after the commas before the AUs, one among them
        lines.append(",  ".join(cells) + ", " + ", ".join(aus))
    return "\n".join(lines) + "\n"


def mediapipe_json(frames: Sequence[Mapping[str, float]], style: str = "js", step_ms: float = 33.0,
                   matrices: Sequence[Any] | None = None) -> str:
    """Face Landmarker results, one per line: ``js`` (JSON.stringify) or ``python`` (dataclasses.asdict).

    ``matrices``: a 4×4 facial transformation matrix (row-major numpy) per frame, serialised as each API does.
    """
    out = []
    for i, frame in enumerate(frames):
        matrix = None if matrices is None else np.asarray(matrices[i], dtype=float)
        names = ["_neutral", *ARKIT_BLENDSHAPES]
        if style == "js":
            categories = [{"index": k, "score": frame.get(n, 0.0), "categoryName": n, "displayName": ""}
                          for k, n in enumerate(names)]
            result = {"timestampMs": round(i * step_ms, 3), "faceLandmarks": [[{"x": 0.5, "y": 0.5, "z": 0.0}]],
                      "faceBlendshapes": [{"categories": categories, "headIndex": -1, "headName": ""}],
                      "facialTransformationMatrixes": [] if matrix is None else
                      [{"rows": 4, "columns": 4, "data": matrix.T.ravel().tolist()}]}
        else:
            categories = [{"index": k, "score": frame.get(n, 0.0), "display_name": "", "category_name": n}
                          for k, n in enumerate(names)]
            result = {"timestamp_ms": int(i * step_ms), "face_blendshapes": [categories]}
            if matrix is not None:
                result["facial_transformation_matrixes"] = [matrix.tolist()]
        out.append(json.dumps(result))
    return "[\n" + ",\n".join(out) + "\n]\n"


def mediapipe_csv(frames: Sequence[Mapping[str, float]], step_ms: float = 33.0) -> str:
    header = ["timestamp_ms", "_neutral", *ARKIT_BLENDSHAPES]
    lines = [",".join(header)]
    for i, frame in enumerate(frames):
        lines.append(",".join([f"{i * step_ms:g}"] + [f"{frame.get(n, 0.0):.6f}" for n in header[1:]]))
    return "\n".join(lines) + "\n"
