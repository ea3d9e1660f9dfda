"""The Identity panel's work: live previews while a slider moves, and the new head made off the GUI thread.

:class:`IdentityHeads` serves one :class:`~workbench.document.model_document.ModelDocument`
and its viewport. While a slider is dragged, :meth:`IdentityHeads.preview`
asks for the head of an identity; at the next turn of the event loop the
latest one asked for is drawn (:func:`engine.identity.identity_vertices`,
a few ms, plus the pose the document shows; drawn without multisampling
until the head is made, as a brush stroke is until its release), so a fast
drag draws no stale frames. On release, :meth:`IdentityHeads.request` makes the whole head
(:func:`engine.identity.make_identity_head`, 0.3–0.8 s: the rig carried over)
on a worker thread and pushes it as one :class:`ReplaceModelCommand`: one
undo step per drag, and undo puts the old head back.

Where heads come from (the choice the panel makes about the rig):

* a model with no identity (the default head, perhaps with painted weights or
  an edited tree) is its own base: its identities carry its rig, edits included;
* a head made here is replaced by a new head made from the same base, so
  edits made to the head itself since (undo steps after it) would be lost:
  :attr:`IdentityHeads.ask_discard` asks first;
* a head opened from a file is made again from the shipped default head; if
  its rig differs from the default head's (parameters, weights), the same
  question is asked.

Models without the default head's mesh get no identities (:meth:`IdentityHeads.unavailable`).
"""

from __future__ import annotations

import time
from collections import deque
from collections.abc import Callable
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass
from functools import cache
from typing import TYPE_CHECKING

import numpy as np
from PySide6.QtCore import QObject, QTimer, Signal

import engine
from engine.errors import UserError

from ..document.undo_commands import ReplaceModelCommand

if TYPE_CHECKING:
    from engine.identity import Identity

    from ..document.model_document import ModelDocument
    from ..viewport.view import Viewport

POLL_MS = 20
_EXECUTOR = ThreadPoolExecutor(max_workers=1, thread_name_prefix="identity")   # one head at a time: 2 cores


@cache
def default_head() -> engine.Model:
    """The shipped default head, read once (compared with, never edited)."""
    return engine.load_model()


def default_mesh_size() -> int:
    from engine.identity.build import default_head_sources

    return len(default_head_sources())


def identity_of(model: engine.Model) -> Identity:
    """The model's identity (the default one when it has none); :class:`engine.UserError` if it is invalid here."""
    from engine.identity import Identity

    record = getattr(model, "identity", None)
    return Identity(record.values if record is not None else {})


def has_identity(model: engine.Model) -> bool:
    record = getattr(model, "identity", None)
    return record is not None and bool(record.values)


def rig_matches_default(model: engine.Model) -> bool:
    """Whether ``model``'s parameters and weights are the default head's (an identity head nobody edited)."""
    reference = default_head()
    if model.parameters.names != reference.parameters.names:
        return False
    for p in model.parameters:
        q = reference.parameters[p.name]
        if (p.kind, p.parent, p.minimum, p.maximum, p.default) != (q.kind, q.parent, q.minimum, q.maximum, q.default):
            return False
        mine, theirs = model.regions[p.name], reference.regions[p.name]
        if not (np.array_equal(mine.indices, theirs.indices) and np.array_equal(mine.weights, theirs.weights)):
            return False
    return True


def beyond_identity(model: engine.Model, base: engine.Model | None = None) -> str | None:
    """What a head has that its identity alone (made from ``base``, default: the default head) does not make
    (a photograph's shape or texture), or ``None``."""
    from engine.identity import identity_vertices
    from engine.identity.skin import SKIN_IMAGE

    def photographs(head: engine.Model | None) -> bool:
        # the skin an identity paints for itself (engine.identity.skin) is made again with the new identity
        return head is not None and head.texture is not None and any(
            image.name != SKIN_IMAGE for image in head.texture.images)

    images = photographs(model) and not photographs(base)
    skin = model.vertex_part == model.parts.index("skin") if "skin" in model.parts else np.ones(model.n_vertices, bool)
    try:
        shape = identity_vertices(identity_of(model), base)
    except UserError:
        return None
    reshaped = shape.shape != model.vertices.shape or np.abs(shape[skin] - model.vertices[skin]).max() > 1e-6
    if not (images or reshaped):
        return None
    what = " and ".join(w for w, present in (("shape", reshaped), ("texture", images)) if present)
    return (f"This head's {what} is more than its identity makes (a head fitted to photographs, or reshaped). "
            "A new identity is made from the default head, without it.")


@dataclass
class _Build:
    """One head being made: from what, for which state of the document, and the undo text."""

    future: Future
    replaced: engine.Model
    stack_index: int
    text: str
    base: engine.Model | None


class IdentityHeads(QObject):
    """Previews and makes identity heads for ``document``, drawn in ``viewport``.

    Signals
    -------
    busy_changed(bool)
        A head is being made (``True``) or the last one wanted is done.
    failed(str)
        Making a head failed; the message says why (the document is unchanged).
    settled()
        No head is being made or waiting: the panel shows the document's identity again.
    """

    busy_changed = Signal(bool)
    failed = Signal(str)
    settled = Signal()

    def __init__(self, document: ModelDocument, viewport: Viewport, parent: QObject | None = None):
        super().__init__(parent)
        self.document = document
        self.viewport = viewport
        #: Asked before a change would drop edits; gets the reason, returns whether to go on. Tests replace it.
        self.ask_discard: Callable[[str], bool] = lambda _reason: True
        self.preview_ms: deque[float] = deque(maxlen=1000)   # time of each preview drawn (vertices + viewport), ms
        self._wanted_preview: Identity | None = None
        self._shown_preview: np.ndarray | None = None
        self._pending: tuple[Identity, str] | None = None
        self._build: _Build | None = None
        self._preview_timer = QTimer(self)
        self._preview_timer.setSingleShot(True)
        self._preview_timer.setInterval(0)       # the next turn of the event loop: moves in between coalesce
        self._preview_timer.timeout.connect(self._draw_preview)
        self._poll_timer = QTimer(self)
        self._poll_timer.setInterval(POLL_MS)
        self._poll_timer.timeout.connect(self._poll)
        document.model_replaced.connect(self._forget_preview)
        document.values_changed.connect(self._forget_preview)

    # -- state -------------------------------------------------------------------------------
    @property
    def busy(self) -> bool:
        """A head is being made or waits to be."""
        return self._build is not None or self._pending is not None

    def unavailable(self) -> str | None:
        """Why the open model can have no identity (another mesh), or ``None``."""
        n, wanted = self.document.model.n_vertices, default_mesh_size()
        if n != wanted:
            return (f"Identities are made on the default head's mesh ({wanted:,} vertices); "
                    f"this model has {n:,}. Open the default head or a head made from it.")
        return None

    def base(self) -> tuple[engine.Model | None, str | None]:
        """What the next head is made from (``None``: the default head), and what the change would lose, if anything."""
        document = self.document
        model, stack = document.model, document.undo_stack
        if not has_identity(model):
            return model, None
        for index in range(stack.index() - 1, -1, -1):
            command = stack.command(index)
            if isinstance(command, ReplaceModelCommand) and command.made is model:
                if index == stack.index() - 1:
                    return command.base, beyond_identity(model, command.base)
                return command.base, ("This head has been edited since it was made (the last "
                                      f"{stack.index() - 1 - index} undo steps). A new identity is made "
                                      "from the head it came from, without those edits.")
        beyond = beyond_identity(model)
        if stack.index() == 0 and rig_matches_default(model) and beyond is None:
            return None, None
        if beyond is not None:
            return None, beyond
        return None, ("This head has an identity and a rig that differs from the default head's (edited "
                      "weights or parameters). A new identity is made from the default head, without those edits.")

    # -- live preview ---------------------------------------------------------------------------
    def preview(self, identity: Identity) -> None:
        """Draw ``identity``'s head at the next turn of the event loop (only the latest one asked for)."""
        self._wanted_preview = identity
        if not self._preview_timer.isActive():
            self._preview_timer.start()

    def end_preview(self) -> None:
        """Drop a preview that will not become a head: the viewport shows the document again."""
        self._preview_timer.stop()
        self._wanted_preview = None
        self.viewport.set_fast_rendering(False)
        if self._shown_preview is not None:
            self._shown_preview = None
            vertices = self.document.vertices()
            self.viewport.update_points(np.arange(len(vertices)), vertices)

    def draw_preview_now(self) -> None:
        """Draw the preview asked for, if any, without waiting for the event loop (benchmarks)."""
        self._preview_timer.stop()
        self._draw_preview()

    def _draw_preview(self) -> None:
        identity, self._wanted_preview = self._wanted_preview, None
        if identity is None or self.unavailable() is not None:
            return
        from engine.identity import identity_vertices

        started = time.perf_counter()
        base, _loss = self.base()
        document = self.document
        try:
            rest = identity_vertices(identity, base)
        except UserError as error:
            self.failed.emit(str(error))
            return
        vertices = rest + (document.vertices() - document.model.vertices)     # the pose shown, on the new face
        shown = self._shown_preview if self._shown_preview is not None else document.vertices()
        moved = np.flatnonzero(np.any(vertices != shown, axis=1))
        if len(moved):
            self.viewport.set_fast_rendering(True)      # no multisampling while dragging, as a brush stroke
            self.viewport.update_points(moved, vertices[moved])
        self._shown_preview = vertices
        self.preview_ms.append(1000.0 * (time.perf_counter() - started))

    def _forget_preview(self, *_args) -> None:
        self._shown_preview = None       # the viewport drew the document again

    # -- making heads -------------------------------------------------------------------------
    def request(self, identity: Identity, text: str) -> None:
        """Make ``identity``'s head and make it the document's model, one undo step called ``text``.

        Asked again while a head is being made, the newest wish waits (in
        place of an older waiting one, whose values the panel's newer wish
        holds too) and is made once the head being made now is in.
        """
        self._pending = (identity, text)
        if self._build is None:
            self._start_next()

    def _start_next(self) -> None:
        wish, self._pending = self._pending, None
        if wish is None:
            self._finish()
            return
        identity, text = wish
        from engine.identity import make_identity_head

        base, loss = self.base()
        if loss is not None and not self.ask_discard(loss):
            self.end_preview()
            self._finish()
            return
        if base is not None and base is self.document.model:
            base = base.copy()          # the worker reads its own copy while the GUI may go on editing
        document = self.document
        future = _EXECUTOR.submit(make_identity_head, identity, base)
        self._build = _Build(future, document.model, document.undo_stack.index(), text, base)
        self.busy_changed.emit(True)
        self._poll_timer.start()

    def stop(self) -> None:
        """Make no more heads (the window is closing): a head being made is thrown away when it comes."""
        self._preview_timer.stop()
        self._poll_timer.stop()
        self._wanted_preview = None
        self._pending = None
        self._build = None

    def _poll(self) -> None:
        build = self._build
        if build is None or not build.future.done():
            return
        self._build = None
        document = self.document
        error = build.future.exception()
        if error is not None:
            self.end_preview()
            unexpected = f"unexpected error: {type(error).__name__}: {error}"
            self.failed.emit(str(error) if isinstance(error, UserError) else unexpected)
        elif document.model is build.replaced and document.undo_stack.index() == build.stack_index:
            document.push(ReplaceModelCommand(document, build.future.result(), build.text, build.base))
        else:
            self.end_preview()          # the document changed meanwhile (an undo, another model): drop the head
        self._start_next()

    def _finish(self) -> None:
        self._poll_timer.stop()
        if self._build is None and self._pending is None:
            self.viewport.set_fast_rendering(False)     # the head is in: drawn with anti-aliasing again
            self.busy_changed.emit(False)
            self.settled.emit()
