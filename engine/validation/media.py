"""The files a user validates: a still picture or the frames of a video, told apart by content.

:func:`open_media` looks at a file: a picture Pillow knows is a :class:`Picture`; anything
ffprobe finds a video stream in is a :class:`Video`, whose frames :meth:`Video.frames` decodes
one at a time through an ffmpeg pipe (a long video never sits in memory whole). A file that
is neither, is too large, or is cut short raises :class:`MediaError`, whose message is the
plain status the validation table shows for it.

>>> import numpy as np, tempfile, os
>>> from PIL import Image
>>> path = os.path.join(tempfile.mkdtemp(), "p.png")
>>> Image.fromarray(np.zeros((4, 6, 3), dtype=np.uint8)).save(path)
>>> open_media(path).kind, open_media(path).pixels.shape
('image', (4, 6, 3))
"""

from __future__ import annotations

import json
import os
import stat
import subprocess
import tempfile
import warnings
from collections.abc import Iterator
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

import numpy as np

from engine.errors import UserError
from engine.formats.pictures import MAX_PICTURE_PIXELS, read_picture, too_many_pixels
from engine.outputs.video_tools import find_tool, stderr_tail
from engine.processes import with_parent_death_signal

MAX_FRAME_SIDE = 1920
"""Video frames are decoded at most this wide or high (larger ones are scaled down by ffmpeg)."""
MAX_FRAMES = 200_000
"""The most frames of one video judged (an hour at 55 fps)."""


class MediaError(UserError):
    """A file that cannot be judged: not a picture or a video, too large, unreadable."""


@dataclass
class Picture:
    """A still picture: its pixels, (H, W, 3) uint8 RGB."""

    path: Path
    pixels: np.ndarray
    kind: str = "image"


@dataclass
class Video:
    """A video's stream facts; its frames come from :meth:`frames`."""

    path: Path
    width: int
    height: int
    fps: float
    declared_frames: int
    kind: str = "video"
    problems: list[str] = field(default_factory=list)
    """What went wrong while decoding (ffmpeg's complaint about a truncated file), after :meth:`frames`."""

    def frames(self) -> Iterator[np.ndarray]:
        """Each frame, (H, W, 3) uint8 RGB, in order; a file cut short ends early with a problem noted."""
        width, height = _decoded_size(self.width, self.height)
        command = [find_tool("ffmpeg"), "-v", "error", "-nostdin", "-i", str(self.path), "-map", "0:v:0",
                   "-frames:v", str(MAX_FRAMES)]
        if (width, height) != (self.width, self.height):
            command += ["-vf", f"scale={width}:{height}:flags=area"]
        command += ["-fps_mode", "passthrough", "-f", "rawvideo", "-pix_fmt", "rgb24", "pipe:1"]
        frame_bytes = width * height * 3
        with tempfile.TemporaryFile() as errors:
            process = subprocess.Popen(with_parent_death_signal(command), stdout=subprocess.PIPE, stderr=errors,
                                       stdin=subprocess.DEVNULL)
            assert process.stdout is not None
            try:
                while True:
                    data = process.stdout.read(frame_bytes)
                    if len(data) < frame_bytes:
                        break
                    yield np.frombuffer(data, dtype=np.uint8).reshape(height, width, 3)
            finally:
                process.stdout.close()
                if process.poll() is None:
                    process.kill()
                process.wait()
                errors.seek(0)
                complaint = errors.read()
            if process.returncode not in (0, -9) or complaint.strip():
                self.problems.append(f"ffmpeg: {stderr_tail(complaint)}")


def open_media(path: str | Path, max_pixels: int = MAX_PICTURE_PIXELS) -> Picture | Video:
    """The picture or video in ``path``; :class:`MediaError` with a plain reason otherwise."""
    from PIL import Image, UnidentifiedImageError

    path = Path(path)
    try:
        info = os.stat(path)
    except (OSError, ValueError):
        raise MediaError("no such file", file=path) from None
    if not stat.S_ISREG(info.st_mode):
        raise MediaError("not a regular file", file=path)
    if info.st_size == 0:
        raise MediaError("an empty file", file=path)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", Image.DecompressionBombWarning)
            with Image.open(path):         # Pillow identifies the format from the first bytes
                is_picture = True
    except (UnidentifiedImageError, OSError, ValueError, SyntaxError):
        is_picture = False
    except (Image.DecompressionBombError, Image.DecompressionBombWarning) as exc:
        raise MediaError(too_many_pixels(exc, max_pixels), file=path) from None
    if is_picture:
        return Picture(path, read_picture(path, max_pixels=max_pixels, error=MediaError))
    return _video(path)


def _video(path: Path) -> Video:
    result = subprocess.run(with_parent_death_signal([find_tool("ffprobe"), "-v", "error", "-print_format", "json",
                                                      "-show_streams", "-select_streams", "v:0", str(path)]),
                            capture_output=True, timeout=60, check=False)
    streams = []
    if result.returncode == 0:
        try:
            streams = json.loads(result.stdout).get("streams", [])
        except ValueError:
            streams = []
    if not streams:
        raise MediaError("not a picture or a video", file=path)
    video = streams[0]
    try:
        width, height = int(video["width"]), int(video["height"])
        fps = float(Fraction(video.get("avg_frame_rate") or video.get("r_frame_rate") or "0"))
    except (KeyError, ValueError, ZeroDivisionError):
        raise MediaError("a video stream with no picture size or frame rate", file=path) from None
    if width <= 0 or height <= 0:
        raise MediaError("a video stream with no picture size", file=path)
    return Video(path, width, height, fps if fps > 0 else 0.0, int(video.get("nb_frames") or 0))


def _decoded_size(width: int, height: int) -> tuple[int, int]:
    scale = MAX_FRAME_SIDE / max(width, height)
    if scale >= 1:
        return width, height
    return max(2, round(width * scale / 2) * 2), max(2, round(height * scale / 2) * 2)
