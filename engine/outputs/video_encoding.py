"""How a video's frames are compressed: the x264 preset and quality (CRF), or lossless for analysis.

The default (``veryfast``, CRF 20, 4:2:0) plays everywhere and is what every video had before the choice
existed. A slower preset makes a smaller file of the same quality (the frames are the same, the encoder
spends more time); a lower CRF a better picture and a larger file (0 is the best, 51 the worst; about 6
more halves the size); ``lossless`` keeps every RGB pixel exactly (H.264 4:4:4 RGB, ``libx264rgb`` at
``-qp 0``), for analysis: it plays in ffmpeg, VLC and mpv, not in web browsers.

The sound (AAC) and the timing of frames and audio samples do not depend on the choice.

>>> encoding_from({"preset": "slow", "crf": 18}).ffmpeg_args()[:6]
['-c:v', 'libx264', '-preset', 'slow', '-crf', '18']
>>> encoding_from("lossless").settings()
{'preset': 'veryfast', 'crf': None, 'lossless': True}
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from engine.errors import UserError

#: x264's presets, fastest first.
PRESETS = ("ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow")
DEFAULT_PRESET, DEFAULT_CRF = "veryfast", 20.0
CRF_RANGE = (0.0, 51.0)
_KEYS = ("preset", "crf", "lossless")


@dataclass(frozen=True)
class Encoding:
    """An H.264 encoding: ``preset`` (:data:`PRESETS`), ``crf`` (0–51, lower is better) or ``lossless``."""

    preset: str = DEFAULT_PRESET
    crf: float = DEFAULT_CRF
    lossless: bool = False

    def ffmpeg_args(self) -> list[str]:
        """ffmpeg's output options for the video stream."""
        if self.lossless:       # RGB kept exactly: no conversion to YUV, quantiser 0
            return ["-c:v", "libx264rgb", "-preset", self.preset, "-qp", "0", "-pix_fmt", "rgb24"]
        return ["-c:v", "libx264", "-preset", self.preset, "-crf", f"{self.crf:g}", "-pix_fmt", "yuv420p",
                "-colorspace", "smpte170m"]      # swscale converts RGB → YUV with BT.601: say so

    def settings(self) -> dict[str, Any]:
        """As recorded in a set's provenance and a manifest (JSON): preset, crf (None when lossless), lossless."""
        return {"preset": self.preset, "crf": None if self.lossless else self.crf, "lossless": self.lossless}

    @property
    def name(self) -> str:
        """Short text for a table cell: ``veryfast/crf20`` or ``lossless``."""
        return "lossless" if self.lossless else f"{self.preset}/crf{self.crf:g}"


def encoding_from(value: object = None) -> Encoding:
    """An :class:`Encoding` from ``None`` (the default), ``"lossless"``, ``"default"``, a preset's name, a
    table ``{"preset": …, "crf": …, "lossless": …}`` (any of them) or an :class:`Encoding`; a
    :class:`UserError` ``encoding: …`` naming the setting otherwise."""
    if value is None or value == "default":
        return Encoding()
    if isinstance(value, Encoding):
        return value
    if value == "lossless":
        return Encoding(lossless=True)
    if isinstance(value, str):
        return Encoding(preset=_preset(value))
    if not isinstance(value, dict):
        raise UserError(f"encoding: must be \"lossless\", a preset ({', '.join(PRESETS)}) or a table of "
                        "preset, crf and lossless")
    unknown = sorted(str(k) for k in value if k not in _KEYS)
    if unknown:
        raise UserError(f"encoding: unknown setting '{unknown[0]}' (known: {', '.join(_KEYS)})")
    lossless = value.get("lossless", False)
    if not isinstance(lossless, bool):
        raise UserError("encoding: lossless must be true or false")
    crf = value.get("crf", DEFAULT_CRF)
    if lossless and "crf" in value:
        raise UserError("encoding: crf has no meaning in a lossless video (leave one of them out)")
    return Encoding(_preset(value.get("preset", DEFAULT_PRESET)), check_crf(crf), lossless)


def check_crf(value: object) -> float:
    """A CRF (a number from 0 to 51), or ``UserError``."""
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value) \
            or not CRF_RANGE[0] <= value <= CRF_RANGE[1]:
        raise UserError(f"encoding: crf must be a number from {CRF_RANGE[0]:g} to {CRF_RANGE[1]:g} "
                        f"(lower is better; got {value!r})")
    return float(value)


def _preset(value: object) -> str:
    if value not in PRESETS:
        raise UserError(f"encoding: preset must be one of {', '.join(PRESETS)} (got {value!r})")
    return str(value)
