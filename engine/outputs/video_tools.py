"""The ffmpeg programs the video modules run, and the errors they raise.

Writing (:mod:`engine.outputs.video_writer`) and inspecting
(:mod:`engine.outputs.video_probe`) a video both need ``ffmpeg`` (and
``ffprobe``), from the Debian package ``ffmpeg``; without it they raise
:class:`FFmpegMissing`, which says how to install it.

>>> find_tool("ffmpeg")                                      # doctest: +SKIP
'/usr/bin/ffmpeg'
>>> stderr_tail(b"frame=1\\n\\nInvalid argument\\n")
'frame=1; Invalid argument'
"""

from __future__ import annotations

import shutil

from engine.errors import UserError

FFMPEG_PACKAGE = "ffmpeg"            # Debian package with both ffmpeg and ffprobe
STDERR_LINES = 8                      # how much of ffmpeg's complaint goes into an error message


class FFmpegMissing(UserError):
    """The ``ffmpeg`` (or ``ffprobe``) program is not installed."""


class VideoError(UserError):
    """ffmpeg failed, or a video could not be read."""


def find_tool(name: str) -> str:
    """Full path of ``ffmpeg`` or ``ffprobe``, or :class:`FFmpegMissing` naming the Debian package."""
    found = shutil.which(name)
    if found is None:
        raise FFmpegMissing(f"{name} is not installed; it comes with the Debian package {FFMPEG_PACKAGE}: "
                            f"sudo apt-get install {FFMPEG_PACKAGE}")
    return found


def stderr_tail(stderr: bytes) -> str:
    """The last :data:`STDERR_LINES` non-empty lines of a program's complaint, on one line."""
    lines = [line.strip() for line in stderr.decode("utf-8", "replace").splitlines() if line.strip()]
    return "; ".join(lines[-STDERR_LINES:]) or "no message"
