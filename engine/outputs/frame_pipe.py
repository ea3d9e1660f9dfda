"""Frames into ffmpeg's stdin on a thread of their own, so drawing the next frame overlaps encoding this one.

:func:`engine.outputs.video_writer.encode_video` puts each frame it draws
(or its second renderer drew) into a :class:`FrameWriter`; the thread writes
them into the pipe in order, at most :data:`QUEUED_FRAMES` ahead of ffmpeg.
"""

from __future__ import annotations

import contextlib
import queue
import threading
from typing import IO

import numpy as np

QUEUED_FRAMES = 4                     # frames rendered ahead of the encoder


class FrameWriter:
    """A thread that writes frames into ffmpeg's stdin, so drawing the next frame
    overlaps with ffmpeg reading this one."""

    def __init__(self, pipe: IO[bytes]):
        self.pipe = pipe
        self.error: BaseException | None = None
        self._queue: queue.Queue[np.ndarray | None] = queue.Queue(maxsize=QUEUED_FRAMES)
        self._thread = threading.Thread(target=self._run, name="ffmpeg-writer", daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while True:
            frame = self._queue.get()
            if frame is None:
                break
            if self.error is not None:
                continue                      # keep draining so put() never blocks forever
            try:
                self.pipe.write(memoryview(np.ascontiguousarray(frame).data).cast("B"))
            except (OSError, ValueError) as exc:      # BrokenPipeError: ffmpeg exited
                self.error = exc
        try:
            self.pipe.close()
        except OSError as exc:
            if self.error is None:
                self.error = exc

    def put(self, frame: np.ndarray) -> bool:
        """Queue a frame (waits while the queue is full); False once writing has failed."""
        if self.error is not None:
            return False
        self._queue.put(frame)
        return self.error is None

    def close(self) -> None:
        """No more frames: finish writing and close the pipe (ffmpeg then sees the end)."""
        self._queue.put(None)
        self._thread.join()

    def abandon(self) -> None:
        """After a failure: stop the thread without waiting for ffmpeg (which is then killed)."""
        if self._thread.is_alive():
            self.error = self.error or RuntimeError("abandoned")
            try:
                while True:
                    self._queue.get_nowait()
            except queue.Empty:
                pass
            with contextlib.suppress(queue.Full):
                self._queue.put_nowait(None)
