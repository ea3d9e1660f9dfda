"""One capture take as read from a producer's file: frame times and named channels.

Readers (:mod:`engine.capture.live_link_face`, :mod:`engine.capture.openface`,
:mod:`engine.capture.mediapipe_blendshapes`) turn each producer's columns into
one shared vocabulary, so that the retargeting (:mod:`engine.capture.retarget`)
knows nothing about file layouts and the readers nothing about the model:

* ARKit blendshapes by their camelCase names (``jawOpen``, ``eyeBlinkLeft``; Left
  and Right are the subject's sides), 0–1;
* FACS action-unit intensities ``AU01`` … ``AU45``, 0–5 (OpenFace's ``AUxx_r``);
* rotations in radians in the head's frame (+X the subject's left, +Y up, +Z
  out of the face), each right-handed about a fixed axis, named by what a
  positive value does: ``head_turn_rad`` (about +Y: towards the subject's
  left), ``head_nod_rad`` (about +X: chin down), ``head_tilt_rad`` (about +Z:
  the left ear up), ``eye_left_turn_rad`` / ``eye_right_turn_rad`` (about +Y:
  looking to the subject's left), ``eye_left_raise_rad`` / ``eye_right_raise_rad``
  (about −X: looking up).

>>> import numpy as np
>>> take = CaptureStream("take.csv", "arkit", np.array([0.0, 40.0]), {"jawOpen": np.array([0.0, 0.5])})
>>> take.frames, take.rate_hz
(2, 25.0)
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from engine.errors import UserError

#: The rotation channels, with the unit axis (head frame) each is right-handed about.
ROTATION_AXES: dict[str, tuple[float, float, float]] = {
    "head_turn_rad": (0.0, 1.0, 0.0),
    "head_nod_rad": (1.0, 0.0, 0.0),
    "head_tilt_rad": (0.0, 0.0, 1.0),
    "eye_left_turn_rad": (0.0, 1.0, 0.0),
    "eye_right_turn_rad": (0.0, 1.0, 0.0),
    "eye_left_raise_rad": (-1.0, 0.0, 0.0),
    "eye_right_raise_rad": (-1.0, 0.0, 0.0),
}


class CaptureFileError(UserError):
    """A capture file (Live Link Face, OpenFace or MediaPipe) is unreadable or not in the producer's format."""


@dataclass
class CaptureStream:
    """A take: ``times_ms`` (F,), rising, from 0 at the first frame; ``channels`` name → (F,) values."""

    source: str
    """The file read, named in messages."""
    format: str
    """``arkit``, ``openface`` or ``mediapipe``."""
    times_ms: np.ndarray
    channels: dict[str, np.ndarray]
    notes: list[str] = field(default_factory=list)
    """What the reader noticed and the user should know (frames without a face, a second face ignored)."""

    @property
    def frames(self) -> int:
        """Number of frames."""
        return len(self.times_ms)

    @property
    def rate_hz(self) -> float:
        """Frames per second from the median frame interval (60 for a single frame)."""
        if self.frames < 2:
            return 60.0
        return float(1000.0 / np.median(np.diff(self.times_ms)))
