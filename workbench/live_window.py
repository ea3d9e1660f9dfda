"""``serve --window``: the served head in a plain window of its own, at the display's refresh rate, with sound.

Not the workbench: one 3D view, no panels. The Qt event loop runs on the main
thread and draws; the live server (:class:`engine.live.server.LiveServer`) runs
its asyncio loop on a second thread and hands each frame's pose to the
:class:`WindowPresenter`. The presenter keeps only the newest frame (when the
drawing falls behind, frames are skipped, never queued), draws it, waits for
the swap to finish (``glFinish``) and tells the server the moment, so every
event of that frame — and of any frame skipped before it — leaves stamped with
``presented_t``. An utterance's sound starts in the frame that shows its first
sample (from the right sample when that frame is late), through PortAudio
(:mod:`workbench.playback.audio_output`); ``audio_t`` is the moment PortAudio says the
first sample reaches the output, or ``None`` where the computer has no sound
output.

Keys: F11 toggles full screen, Escape leaves it; closing the window ends the
server. SIGINT and SIGTERM end it too.

The window opens at the size asked for (``--size``, 600 × 800 unless told),
made smaller, its shape kept, where that and the window's frame do not fit
the screen's free area (:func:`fitted_size`; a 768-pixel laptop screen would
cut it at the chin): a note on stderr says so. The camera is framed for the
window's shape, so the head is whole at any size.

>>> from engine.live.server import LiveServer                                  # doctest: +SKIP
>>> serve_in_window(lambda presenter: LiveServer(load_model(), presenter=presenter),
...                 fullscreen=False, size=(600, 800), ready=print)              # doctest: +SKIP
serving ws://127.0.0.1:8765 window 60 Hz
"""

from __future__ import annotations

import os
import re
import signal
import sys
import threading
import time
import traceback
from collections.abc import Callable
from typing import Any, NoReturn

import numpy as np
from PySide6.QtCore import QObject, Qt, QTimer, Signal
from PySide6.QtWidgets import QApplication, QVBoxLayout, QWidget

from engine.errors import UserError
from engine.live.presentation import Sound, SoundKey
from engine.model.model import Model
from workbench.playback.audio_output import AudioClip, AudioOutput
from workbench.viewport.keys import keep_keys_from_vtk
from workbench.window.layouts import FRESH_MARGIN

VIEW = "front"
SIGNAL_POLL_MS = 200         # how often Python gets the chance to run a SIGINT/SIGTERM handler
SOFTWARE_OPENGL = re.compile(r"renderer string:.*(llvmpipe|softpipe|swrast|SwiftShader)", re.IGNORECASE)


class LiveWindow(QWidget):
    """A top-level window holding one VTK view of the head (front camera, as ``render --view front``)."""

    def __init__(self, size: tuple[int, int]):
        super().__init__()
        import vtkmodules.qt
        import vtkmodules.vtkRenderingOpenGL2

        vtkmodules.qt.PyQtImpl = "PySide6"
        from vtkmodules.qt.QVTKRenderWindowInteractor import QVTKRenderWindowInteractor

        self.setWindowTitle("Artificial Person — live")
        self.view = QVTKRenderWindowInteractor(self)
        keep_keys_from_vtk(self.view)                 # VTK's keys ('3' stereo, ...) do nothing; F11 reaches us
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.view)
        self.resize(*size)
        self.render_window: Any = self.view.GetRenderWindow()
        if hasattr(self.render_window, "SetSwapControl"):
            self.render_window.SetSwapControl(1)            # wait for the display's vertical blank where there is one
        self.view.setAttribute(Qt.WidgetAttribute.WA_TransparentForMouseEvents)   # a viewer: the camera stays put
        self.resized: Callable[[], None] = lambda: None
        self.closing: Callable[[], None] = lambda: None

    def keyPressEvent(self, event: Any) -> None:
        if event.key() == Qt.Key.Key_F11:
            self.setWindowState(self.windowState() ^ Qt.WindowState.WindowFullScreen)
        elif event.key() == Qt.Key.Key_Escape and self.isFullScreen():
            self.showNormal()
        else:
            super().keyPressEvent(event)

    def resizeEvent(self, event: Any) -> None:
        super().resizeEvent(event)
        self.resized()

    def closeEvent(self, event: Any) -> None:
        self.closing()
        super().closeEvent(event)

    def pixel_size(self) -> tuple[int, int]:
        """The view's size in device pixels: the window's (the view fills it, and is laid out only after the
        window's own resize event)."""
        ratio = self.devicePixelRatioF()
        return max(1, round(self.width() * ratio)), max(1, round(self.height() * ratio))


class WindowPresenter(QObject):
    """Draws the newest frame the server handed over, then stamps it (``engine.live.presentation.Presenter``)."""

    frame_waiting = Signal()

    def __init__(self, window: LiveWindow, fps: float, audio: AudioOutput | None = None):
        super().__init__()
        self.window = window
        self.fps = float(fps)
        self.audio = audio if audio is not None else AudioOutput()
        self.presented: Callable[[int, float, dict[SoundKey, float | None]], None] = lambda *_: None
        self._lock = threading.Lock()
        self._newest: tuple[int, float, Model, np.ndarray] | None = None
        self._waiting_sounds: dict[SoundKey, Sound] = {}
        self._silenced: set[SoundKey] = set()
        self._playing: SoundKey | None = None
        self._model: Model | None = None
        self._scene: tuple[Any, Any, list[Any]] | None = None     # renderer, layout, meshes
        self._shown: np.ndarray | None = None                        # the values on the screen now
        self.frame_waiting.connect(self._draw, Qt.ConnectionType.QueuedConnection)
        window.resized = self._aim

    # -- called on the server's thread ---------------------------------------------------------

    def show(self, frame: int, t: float, model: Model, values: np.ndarray) -> None:
        with self._lock:
            post = self._newest is None
            self._newest = (frame, t, model, values)
        if post:
            self.frame_waiting.emit()

    def play(self, sound: Sound) -> None:
        with self._lock:
            self._waiting_sounds[sound.key] = sound
            self._silenced.discard(sound.key)

    def silence(self, key: SoundKey) -> None:
        with self._lock:
            self._waiting_sounds.pop(key, None)
            self._silenced.add(key)

    def close(self) -> None:
        self.audio.stop()

    # -- the GUI thread -------------------------------------------------------------------------

    def _draw(self) -> None:
        with self._lock:
            newest, self._newest = self._newest, None
            if newest is None:
                return
            frame, t, model, values = newest
            due = [s for s in self._waiting_sounds.values() if s.start_t <= t]
            for sound in due:
                del self._waiting_sounds[sound.key]
            silenced, self._silenced = self._silenced, set()
        if self._playing in silenced:
            self.audio.stop()
            self._playing = None
        if model is not self._model:
            self._build(model)
        if self._shown is not None and np.array_equal(values, self._shown):
            swap_s = time.monotonic()                 # the screen shows this pose already: nothing to draw
        else:
            from engine.outputs.render import copy_pose

            assert self._scene is not None
            _, layout, meshes = self._scene
            copy_pose(layout, meshes, model.deformer().deform(values))
            self.window.render_window.Render()
            self.window.render_window.WaitForCompletion()
            swap_s = time.monotonic()
            self._shown = values
        audio = {sound.key: self._start_sound(sound, t) for sound in due[-1:]}   # the newest, when two fall due
        self.presented(frame, swap_s, audio)

    def _start_sound(self, sound: Sound, t: float) -> float | None:
        """Start ``sound`` at the sample that belongs to frame time ``t``: the moment its first sample reaches the
        output (``time.monotonic()``), or ``None`` when there is no sound output (silent)."""
        offset_s = max(0.0, (t - sound.start_t) / 1000.0)
        clip = AudioClip(np.asarray(sound.samples, dtype=np.float32), int(sound.sample_rate), "<speech>")
        started = self.audio.start(clip, offset_s)
        self._playing = sound.key if started else None
        if not started:
            return None
        latency = self.audio.latency()
        return time.monotonic() + (latency or 0.0) - offset_s

    def _build(self, model: Model) -> None:
        from engine.outputs.part_layout import PartLayout
        from engine.outputs.render import scene_renderer

        if self._scene is not None:
            self.window.render_window.RemoveRenderer(self._scene[0])
        layout = PartLayout(model)
        width, height = self.window.pixel_size()
        renderer, meshes = scene_renderer(model, layout, VIEW, width, height)
        self.window.render_window.AddRenderer(renderer)
        self._model, self._scene, self._shown = model, (renderer, layout, meshes), None

    def _aim(self) -> None:
        if self._scene is None or self._model is None:
            return
        from engine.outputs.render import aim_camera

        aim_camera(self._scene[0], self._model, VIEW, *self.window.pixel_size())
        self._shown = None                                            # drawn again in the next frame


def serve_in_window(make_server: Callable[[WindowPresenter], Any], fullscreen: bool, size: tuple[int, int],
                    ready: Callable[[str], None]) -> None:
    """Open the window, serve with :class:`WindowPresenter` (``make_server(presenter)`` makes the server) on a
    second thread until the window closes or SIGINT/SIGTERM comes, then end the process (:func:`leave_process`:
    run it in a process of its own, as the CLI does); a failure to serve (the port taken) is raised instead."""
    app = QApplication.instance() or QApplication([sys.argv[0]])
    window = LiveWindow(size)
    screen = window.screen() or app.primaryScreen()
    if screen is not None and not fullscreen:
        place_on_screen(window, size, screen.availableGeometry())
    fps = screen.refreshRate() if screen is not None and screen.refreshRate() >= 20 else 60.0
    presenter = WindowPresenter(window, fps)
    server = make_server(presenter)
    presenter.presented = server.presented
    presenter._build(server.model)
    failure: list[BaseException] = []

    def run_server() -> None:
        import asyncio

        try:
            asyncio.run(server.run(ready=ready))
        except BaseException as exc:               # reported on the main thread, after the window closed
            failure.append(exc)
        finally:
            QTimer.singleShot(0, app, app.quit)

    window.closing = server.close_soon
    if fullscreen:
        if screen is not None:
            window.setGeometry(screen.geometry())     # what full screen is where no window manager honours the state
        window.showFullScreen()
        window.setCursor(Qt.CursorShape.BlankCursor)
    else:
        window.show()
    window.view.Initialize()
    window.render_window.Render()
    if SOFTWARE_OPENGL.search(window.render_window.ReportCapabilities() or ""):
        window.render_window.SetMultiSamples(0)       # on the CPU, multisampling costs half again per frame
    previous = {signum: signal.signal(signum, lambda *_: app.quit()) for signum in (signal.SIGINT, signal.SIGTERM)}
    poll = QTimer()
    poll.timeout.connect(lambda: None)              # lets Python run the signal handlers above
    poll.start(SIGNAL_POLL_MS)
    thread = threading.Thread(target=run_server, name="live-server", daemon=True)
    thread.start()
    try:
        app.exec()
    finally:
        poll.stop()
        for signum, handler in previous.items():
            signal.signal(signum, handler)
        server.close_soon()
        thread.join(10.0)
        presenter.close()
        close_window(window)
    if failure:
        exc = failure[0]
        if isinstance(exc, (UserError, OSError)):
            raise exc
        print(f"internal error in the live server:\n{''.join(traceback.format_exception(exc))}", file=sys.stderr)
        leave_process(1)
    leave_process(0)


def fitted_size(size: tuple[int, int], free: tuple[int, int]) -> tuple[int, int]:
    """``size`` (w, h px), made smaller with its shape kept until it and a window's frame (:data:`FRESH_MARGIN`, as
    the workbench leaves for it) fit the screen's ``free`` area (w, h px); as it is when it fits.

    >>> fitted_size((600, 800), (1366, 768)), fitted_size((600, 800), (1920, 1080))
    ((534, 712), (600, 800))
    """
    room = free[0] - FRESH_MARGIN.width(), free[1] - FRESH_MARGIN.height()
    scale = min(1.0, room[0] / size[0], room[1] / size[1])
    if scale >= 1.0:
        return size
    return max(1, int(size[0] * scale)), max(1, int(size[1] * scale))


def place_on_screen(window: LiveWindow, size: tuple[int, int], free: Any) -> tuple[int, int]:
    """Give ``window`` its :func:`fitted_size` on the screen whose free area is ``free`` (a ``QRect``), centred
    there; a size made smaller is a note on stderr. Returns the size."""
    fitted = fitted_size(size, (free.width(), free.height()))
    if fitted != size:
        print(f"note: the window is {fitted[0]}x{fitted[1]}, not {size[0]}x{size[1]}: that does not fit the "
              f"screen ({free.width()}x{free.height()} free); F11 for full screen", file=sys.stderr, flush=True)
    window.resize(*fitted)
    frame = fitted[0] + FRESH_MARGIN.width(), fitted[1] + FRESH_MARGIN.height()
    window.move(free.x() + max(0, (free.width() - frame[0]) // 2), free.y() + max(0, (free.height() - frame[1]) // 2))
    return fitted


def leave_process(status: int) -> NoReturn:
    """End the process now, after the exit handlers and with the output flushed, but without the interpreter's
    last garbage collection: there PySide6's and VTK's wrappers, torn down in whatever order it finds them,
    sometimes crash (``bool_dealloc``, SIGABRT) although everything was closed above."""
    import atexit

    atexit._run_exitfuncs()
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)


def close_window(window: LiveWindow) -> None:
    """Close the window and release its OpenGL context now, while Qt and VTK are both still there (left to the
    interpreter's last garbage collection, the two tear each other down in the wrong order and it crashes)."""
    window.closing = lambda: None
    window.close()
    window.render_window.Finalize()
    window.view.setParent(None)
    window.view.deleteLater()
    window.deleteLater()
    app = QApplication.instance()
    if app is not None:
        app.processEvents()
