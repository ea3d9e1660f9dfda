"""Which producer wrote a capture file, and reading it with the right reader.

>>> detect_format_of_text("Timecode,BlendShapeCount,EyeBlinkLeft\\n")
'arkit'
>>> detect_format_of_text("frame, face_id, timestamp, confidence, success, AU01_r\\n")
'openface'
>>> detect_format_of_text('[{"timestampMs": 0, "faceBlendshapes": []}]')
'mediapipe'
"""

from __future__ import annotations

from pathlib import Path

from engine.capture.live_link_face import is_live_link_face_header, parse_live_link_face
from engine.capture.mediapipe_blendshapes import is_mediapipe_csv_header, looks_like_json, parse_mediapipe
from engine.capture.openface import is_openface_header, parse_openface
from engine.capture.stream import CaptureFileError, CaptureStream
from engine.capture.text_table import MAX_CAPTURE_BYTES, split_rows
from engine.formats.text_files import read_bounded_text

FORMATS = ("arkit", "openface", "mediapipe")


def detect_format_of_text(text: str) -> str | None:
    """``arkit``, ``openface`` or ``mediapipe`` from the header, or None."""
    if looks_like_json(text):
        return "mediapipe"
    first = split_rows(text.split("\n", 1)[0] if "\n" in text else text)
    cells = first[0][1] if first else []
    if is_live_link_face_header(cells):
        return "arkit"
    if is_openface_header(cells):
        return "openface"
    if is_mediapipe_csv_header(cells):
        return "mediapipe"
    return None


def read_capture(path: str | Path, format: str = "auto", fps: float | None = None) -> CaptureStream:
    """Read a Live Link Face, OpenFace or MediaPipe file; ``format="auto"`` goes by the header.

    ``fps`` times files that carry no times of their own (OpenFace image
    sequences, MediaPipe frames without timestamps); others keep their own.
    """
    text = read_bounded_text(path, limit=MAX_CAPTURE_BYTES, error=CaptureFileError, what="capture file")
    source = str(path)
    if format == "auto":
        found = detect_format_of_text(text)
        if found is None:
            raise CaptureFileError("not a capture stream this toolkit reads (Live Link Face CSV, OpenFace CSV, "
                                   "MediaPipe blendshapes as JSON or CSV); name one with --format", file=source,
                                   line=1)
        format = found
    if format == "arkit":
        return parse_live_link_face(text, source)
    if format == "openface":
        return parse_openface(text, source, fps)
    if format == "mediapipe":
        return parse_mediapipe(text, source, fps)
    raise CaptureFileError(f"unknown capture format '{format}' (use auto, {', '.join(FORMATS)})", file=source)
