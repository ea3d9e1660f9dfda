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

import subprocess
from pathlib import Path

from engine.errors import UserError

FFMPEG_PACKAGE = "ffmpeg"            # Debian package with both ffmpeg and ffprobe
STDERR_LINES = 8                      # how much of ffmpeg's complaint goes into an error message


class FFmpegMissing(UserError):
    """The ``ffmpeg`` (or ``ffprobe``) program is not installed."""


class VideoError(UserError):
    """ffmpeg failed, or a video could not be read."""


def find_tool(name: str) -> str:
    """Full path of ``ffmpeg`` or ``ffprobe`` (``$AP_FFMPEG``/``$AP_FFPROBE``, else on ``PATH``:
    :mod:`engine.programs`), or :class:`FFmpegMissing` saying how to install it."""
    from engine.programs import find_program, missing_message

    found = find_program(name)
    if found is None:
        raise FFmpegMissing(missing_message(name))
    return found


def stderr_tail(stderr: bytes) -> str:
    """The last :data:`STDERR_LINES` non-empty lines of a program's complaint, on one line."""
    lines = [line.strip() for line in stderr.decode("utf-8", "replace").splitlines() if line.strip()]
    return "; ".join(lines[-STDERR_LINES:]) or "no message"


def copy_without_audio(source: str | Path, destination: str | Path, name: str | Path | None = None) -> None:
    """The video stream of the MP4 ``source`` into the MP4 ``destination`` as it is (copied, not encoded
    again: the same frames, bit for bit), without its sound. ``name`` is the file errors name (default
    ``destination``)."""
    from engine.processes import with_parent_death_signal

    command = [find_tool("ffmpeg"), "-hide_banner", "-nostdin", "-loglevel", "error", "-y", "-i", str(source),
               "-map", "0:v:0", "-c", "copy", "-movflags", "+faststart", "-f", "mp4", str(destination)]
    result = subprocess.run(with_parent_death_signal(command), capture_output=True, timeout=600, check=False)
    if result.returncode != 0:
        raise VideoError(f"ffmpeg failed copying the video: {stderr_tail(result.stderr)}",
                         file=destination if name is None else name)
