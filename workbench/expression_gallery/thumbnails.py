"""Thumbnails of gallery entries, rendered offscreen one at a time while the window stays responsive.

Rendering happens on the GUI thread (VTK's OpenGL contexts belong to the
thread that made them, and the viewport's lives there too) but in small
steps: each event-loop turn renders one queued thumbnail with one
:class:`engine.outputs.render.FrameRenderer` (about 0.1 s on the default head with
software OpenGL), so the window opens at once and the pictures fill in.
Nothing is rendered while the gallery is hidden. Pictures are cached per
model revision; the renderer is released as soon as the queue is empty.
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Qt, QTimer, Signal
from PySide6.QtGui import QImage, QPixmap

RENDER_SIZE = (240, 300)
FACE_CROP = (0.24, 0.30, 0.76, 0.88)
"""Left, top, right, bottom fractions of a front render of the default head: brows to chin."""
THUMBNAIL_SIZE = (104, 116)


class ThumbnailCache(QObject):
    """``ready(name)`` once the picture of an entry is in :attr:`pixmaps`."""

    ready = Signal(str)
    drained = Signal()

    def __init__(self, model_source, parent: QObject | None = None):
        super().__init__(parent)
        self._model_source = model_source         # callable → the current engine.Model
        self.pixmaps: dict[str, QPixmap] = {}
        self._queue: list = []
        self._renderer = None
        self._revision = None
        self.active = False
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(0)
        self._timer.timeout.connect(self._render_next)

    def clear(self) -> None:
        """Forget every picture (the model changed) and release the renderer."""
        self.pixmaps.clear()
        self._queue.clear()
        self.close()

    def request(self, entries) -> None:
        """Queue the entries that have no picture yet (in order)."""
        queued = {e.name for e in self._queue}
        self._queue += [e for e in entries if e.name not in self.pixmaps and e.name not in queued]
        self._schedule()

    def set_active(self, active: bool) -> None:
        """Render only while active (the gallery is visible)."""
        self.active = bool(active)
        if not self.active:
            self.close()                # no OpenGL context held while nobody looks (or the window closes)
        self._schedule()

    @property
    def pending(self) -> int:
        return len(self._queue)

    def render_all(self) -> None:
        """Render everything queued now (tests, screenshots)."""
        while self._queue:
            self._render_one(self._queue.pop(0))
        self.close()
        self.drained.emit()

    def close(self) -> None:
        renderer, self._renderer = self._renderer, None
        if renderer is not None:
            renderer.close()

    # -- work ----------------------------------------------------------------
    def _schedule(self) -> None:
        if self.active and self._queue and not self._timer.isActive():
            self._timer.start()

    def _render_next(self) -> None:
        if not self.active or not self._queue:
            return
        self._render_one(self._queue.pop(0))
        if self._queue:
            self._timer.start()
        else:
            self.close()
            self.drained.emit()

    def _render_one(self, entry) -> None:
        model = self._model_source()
        if self._revision != (id(model), model.revision):
            self.pixmaps.clear()
            self.close()
            self._revision = (id(model), model.revision)
        if self._renderer is None:
            from engine.outputs.render import FrameRenderer
            self._renderer = FrameRenderer(model, size=RENDER_SIZE, view="front", antialias=True)
        values = entry.pose(model)
        image = self._renderer.render(model.deform(values))
        self.pixmaps[entry.name] = _thumbnail(image, has_face_layout(model))
        self.ready.emit(entry.name)


def has_face_layout(model) -> bool:
    """Whether the model is framed like the default head (it has action units): crop to the face."""
    return any(name.startswith("AU") for name in model.parameters.names)


def _thumbnail(image, crop: bool) -> QPixmap:
    height, width = image.shape[:2]
    if crop:
        left, top, right, bottom = FACE_CROP
        image = image[int(top * height):int(bottom * height), int(left * width):int(right * width)]
    image = image.copy(order="C")
    qimage = QImage(image.data, image.shape[1], image.shape[0], 3 * image.shape[1], QImage.Format.Format_RGB888)
    return QPixmap.fromImage(qimage.copy()).scaled(*THUMBNAIL_SIZE, Qt.AspectRatioMode.KeepAspectRatio,
                                                    Qt.TransformationMode.SmoothTransformation)
