"""A video written in a fresh process (no test runner, no Qt, one thread), for ``test_render_helper.py``.

    python -m tests.engine.render_helper_run OUT.mp4 one|two|kill

``one``: drawn by one process; ``two``: with the second renderer; ``kill``:
with the second renderer killed after ten of its frames. Prints what it saw
as JSON: the frames, the helper's pid and the answers it gave.
"""

from __future__ import annotations

import json
import os
import signal
import sys

import numpy as np

import engine
from engine.outputs.render_helper import MIN_FRAMES, RenderHelper
from engine.outputs.video_writer import write_video

FRAMES = MIN_FRAMES + 11            # odd: the helper draws one frame fewer than the writer


def main(path: str, mode: str) -> int:
    os.environ["AP_RENDER_PROCESSES"] = "1" if mode == "one" else "2"
    seen: dict[str, list] = {"pids": [], "answers": []}
    init, frame = RenderHelper.__init__, RenderHelper.frame

    def recording_init(self, *args, **kwargs):
        init(self, *args, **kwargs)
        seen["pids"].append(self.pid)

    def killing_frame(self, n):
        if mode == "kill" and len(seen["answers"]) == 10:
            os.kill(self.pid, signal.SIGKILL)
        image = frame(self, n)
        seen["answers"].append(image is not None)
        return image

    RenderHelper.__init__ = recording_init          # type: ignore[method-assign]
    RenderHelper.frame = killing_frame              # type: ignore[method-assign]
    head = engine.load_model()
    times = np.arange(FRAMES) * (1000 / 30)
    values = np.column_stack([0.4 * (1 + np.sin(times / 150)) / 2, 0.2 * np.sin(times / 400)])
    audio = (0.1 * np.sin(np.arange(int(16000 * FRAMES / 30)) / 5)).astype(np.float32)
    stats = write_video(path, head, times, values, ["jaw_open", "head_turn"], fps=30, audio=audio,
                        sample_rate=16000, size=(160, 120))
    print(json.dumps({"frames": stats.frames, **seen}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
