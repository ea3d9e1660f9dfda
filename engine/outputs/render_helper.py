"""A second process that draws every other video frame, so a video uses both cores of a small machine.

On a machine without a GPU the frames are drawn by Mesa's software OpenGL,
whose cost is almost all on the calling thread: a second thread inside it
gains nothing (benchmarks/bench_video.py), a second process does. Before
:func:`~engine.outputs.video_writer.encode_video` opens its own renderer it
forks a :class:`RenderHelper`: a copy of itself that opens its own offscreen
renderer, draws frames ``offset, offset + step, …`` with the same code, and
writes their pixels into a pipe, in order; the writer draws the others and
reads these in turn. The frames are the ones one process would draw, byte
for byte (tested).

The helper dies with its parent (``PR_SET_PDEATHSIG``), ends with
``os._exit`` (no atexit handler, no buffered output of the parent runs
twice), and is reaped by :meth:`RenderHelper.close`. If it stops early (an
OpenGL error in the child, a kill), :meth:`RenderHelper.frame` returns
``None`` and the writer draws the rest itself.

``AP_RENDER_PROCESSES=1`` turns it off (a stimulus set on every core does,
its workers already fill them); it is used only on Linux, with two or more
cores, for videos of :data:`MIN_FRAMES` frames or more, and only from a
process with one thread and no Qt (the command line, a stimulus worker; not
the workbench).
"""

from __future__ import annotations

import contextlib
import os
import sys
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from engine.outputs.video_writer import VideoRequest

MIN_FRAMES = 60                  # shorter videos: starting the helper costs more than it saves
ENVIRONMENT = "AP_RENDER_PROCESSES"
_PIPE_BYTES = 1 << 20            # the pipe holds up to this many bytes (Linux's default ceiling) …
_F_SETPIPE_SZ = 1031             # … set with fcntl(F_SETPIPE_SZ)


def helper_wanted(frames: int) -> bool:
    """Whether a video of ``frames`` frames should be drawn by two processes here.

    Never from a process that runs other threads or a Qt application (the
    workbench): a fork copies only the calling thread, and what the others
    held would stay held in the copy.
    """
    import threading

    setting = os.environ.get(ENVIRONMENT, "").strip()
    if setting == "1" or threading.active_count() > 1 or "PySide6.QtCore" in sys.modules:
        return False
    if setting:
        return True
    return sys.platform.startswith("linux") and (os.cpu_count() or 1) >= 2 and frames >= MIN_FRAMES


class RenderHelper:
    """Frames ``offset, offset + step, …`` of ``request``, drawn by a forked copy of this process."""

    def __init__(self, request: VideoRequest, antialias: bool, offset: int = 1, step: int = 2,
                 positions: bool = False) -> None:
        width, height = request.size
        self.frame_bytes = width * height * 3
        self.shape = (height, width, 3)
        self.offset, self.step = offset, step
        # with ``positions``, each frame's picture is followed by the vertex positions it was drawn from
        self.positions_shape = (request.model.n_vertices, 3) if positions else None
        self.positions_bytes = request.model.n_vertices * 3 * 8 if positions else 0
        self.positions: np.ndarray | None = None
        """The vertex positions (mm, float64) of the frame :meth:`frame` returned last, when asked for."""
        read_end, write_end = os.pipe()
        with contextlib.suppress(OSError):            # a larger pipe lets the helper draw ahead
            import fcntl

            fcntl.fcntl(write_end, _F_SETPIPE_SZ, min(_PIPE_BYTES, 4 * (self.frame_bytes + self.positions_bytes)))
        self.pid = os.fork()
        if self.pid == 0:                             # the helper: draw, write, leave
            os.close(read_end)
            _draw_frames(request, antialias, offset, step, write_end, positions)
        os.close(write_end)
        self._pipe = os.fdopen(read_end, "rb")
        self.alive = True

    def frame(self, n: int) -> np.ndarray | None:
        """Frame ``n`` (one of the helper's, asked for in order), or ``None`` once the helper has stopped."""
        if not self.alive:
            return None
        assert (n - self.offset) % self.step == 0, "not one of the helper's frames"
        data = self._pipe.read(self.frame_bytes + self.positions_bytes)
        if data is None or len(data) < self.frame_bytes + self.positions_bytes:
            self.close()
            return None
        if self.positions_shape is not None:
            self.positions = np.frombuffer(data, dtype=np.float64, offset=self.frame_bytes).reshape(
                self.positions_shape)
        return np.frombuffer(data, dtype=np.uint8, count=self.frame_bytes).reshape(self.shape)

    def owns(self, n: int) -> bool:
        """Whether frame ``n`` is the helper's to draw (while it is alive)."""
        return self.alive and n >= self.offset and (n - self.offset) % self.step == 0

    def close(self) -> None:
        """Stop the helper if it still runs and reap it (idempotent)."""
        self.alive = False
        with contextlib.suppress(OSError):
            self._pipe.close()
        if self.pid <= 0:
            return
        with contextlib.suppress(ProcessLookupError, ChildProcessError):
            os.kill(self.pid, 9)
        with contextlib.suppress(ChildProcessError):
            os.waitpid(self.pid, 0)
        self.pid = -1

    def __del__(self) -> None:
        with contextlib.suppress(Exception):
            self.close()


def _draw_frames(request: VideoRequest, antialias: bool, offset: int, step: int, pipe: int,
                 positions: bool = False) -> None:
    """In the forked helper: draw the frames and write them to ``pipe`` (each followed by its vertex
    positions when ``positions``); never returns."""
    code = 1
    try:
        from engine.outputs.render import FrameRenderer
        from engine.processes import die_with_parent

        die_with_parent()
        deformer = request.model.deformer()
        with FrameRenderer(request.model, size=request.size, view=request.view, antialias=antialias,
                           look=request.look) as renderer, \
                os.fdopen(pipe, "wb", buffering=0) as out:
            for n in range(offset, request.frames, step):
                moved = deformer.deform(request.values[n])
                image = renderer.render(moved)
                parts = [image] + ([np.asarray(moved, dtype=np.float64)] if positions else [])
                for part in parts:
                    view = memoryview(np.ascontiguousarray(part).data).cast("B")
                    while view:
                        written = out.write(view)
                        view = view[written:]
        code = 0
    except BaseException:                              # the parent draws what is missing
        code = 1
    finally:
        os._exit(code)
