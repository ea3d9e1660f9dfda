"""The motion-capture tool's shared state: the session, the selected frames, the PCA result.

:class:`MocapState` is to the mocap widgets what
:class:`~workbench.document.model_document.ModelDocument` is to the model widgets: one
object that holds the data and announces each change; the import dialog,
the marker overlay, the coordinate plot and the PCA dock listen to it and
never talk to each other.

Frames are chosen as *spans* (inclusive frame ranges, each with a phone
label): a click adds one frame, a drag a range, "select by phones" one frame
per matching phone (the engine's :func:`~engine.mocap.frame_selection.select_frames`).

>>> state = MocapState()                                           # doctest: +SKIP
>>> state.set_session(load_session("take1.h5"), "take1.h5")        # doctest: +SKIP
>>> state.add_span(10, 20, "a"); state.selected_frames()[:3]       # doctest: +SKIP
array([10, 11, 12])
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PySide6.QtCore import QObject, Signal
from PySide6.QtGui import QUndoStack

from engine.mocap.marker_assignment import rename_markers
from engine.mocap.session import Session


@dataclass(frozen=True)
class Span:
    """Frames ``start`` … ``end`` (inclusive) of the session, standing for the phone ``label``."""

    start: int
    end: int
    label: str = ""

    def frames(self) -> np.ndarray:
        return np.arange(self.start, self.end + 1, dtype=np.int64)


class MocapState(QObject):
    """The open capture session (if any), its frame selection and the last PCA.

    Signals
    -------
    session_changed(object)
        A session was loaded or imported (or ``None``: closed). The selection is cleared.
    phones_changed()
        The session's phone labels were replaced (imported or aligned by Festival).
    selection_changed()
        Spans were added or removed.
    articulation_changed(object)
        A new PCA result (:class:`engine.mocap.pca.Articulation`) or ``None``.
    markers_renamed(dict)
        Markers of the session were renamed, ``{old name: new name}`` (a feature point assigned, undone, a map).

    The session's own edits (marker names) go on :attr:`undo_stack`, which
    is emptied with each new session and clean while the session is as
    its file has it.
    """

    session_changed = Signal(object)
    phones_changed = Signal()
    selection_changed = Signal()
    articulation_changed = Signal(object)
    markers_renamed = Signal(dict)

    def __init__(self, parent: QObject | None = None):
        super().__init__(parent)
        self.session: Session | None = None
        self.session_path: Path | None = None
        self.spans: list[Span] = []
        self.phone_selection = None      # the FrameSelection the spans came from, while they all did
        self.articulation = None
        self.undo_stack = stack = QUndoStack(self)
        # Going away, the stack empties itself and says so; the widgets listening may be gone already.
        self.destroyed.connect(lambda *_: stack.blockSignals(True))

    # -- session ---------------------------------------------------------------
    def set_session(self, session: Session | None, path: str | Path | None = None) -> None:
        self.undo_stack.clear()              # its commands rename the markers of the session before
        self.session = session
        self.session_path = Path(path) if path else None
        self.spans = []
        self.phone_selection = None
        self.articulation = None
        self.session_changed.emit(session)
        self.articulation_changed.emit(None)

    def set_phones(self, phones) -> None:
        """Replace the session's phone labels ``(start_ms, end_ms, label)``."""
        if self.session is None:
            return
        self.session.phones = [(float(a), float(b), str(c)) for a, b, c in phones]
        self.phones_changed.emit()

    def rename_markers(self, renames: dict[str, str]) -> dict[str, str]:
        """Rename the session's markers (:func:`engine.mocap.marker_assignment.rename_markers`); the undoing renames.

        The frame selection stays (frames do not change); a PCA that analysed
        a renamed marker no longer matches the session, so it is dropped.
        """
        if self.session is None or not renames:
            return {}
        undo = rename_markers(self.session, renames)
        done = {old: new for new, old in undo.items()}
        if self.articulation is not None and set(done) & set(self.articulation.markers):
            self.set_articulation(None)
        self.markers_renamed.emit(done)
        return undo

    # -- selection -------------------------------------------------------------
    def add_span(self, start: int, end: int, label: str = "") -> Span:
        """Select frames ``start`` … ``end`` (either order, clamped to the session) labelled ``label``."""
        last = self.session.n_frames - 1 if self.session is not None else max(start, end)
        a, b = sorted((int(start), int(end)))
        span = Span(min(max(a, 0), last), min(max(b, 0), last), label.strip())
        self.spans.append(span)
        self.phone_selection = None
        self.selection_changed.emit()
        return span

    def set_phone_selection(self, selection) -> None:
        """Replace the spans by one frame per phone of an engine :class:`FrameSelection`."""
        self.spans = [Span(int(f), int(f), label) for f, label in zip(selection.frames, selection.labels, strict=True)]
        self.phone_selection = selection
        self.selection_changed.emit()

    def remove_spans(self, indices) -> None:
        drop = {int(i) for i in indices}
        self.spans = [s for i, s in enumerate(self.spans) if i not in drop]
        self.phone_selection = None
        self.selection_changed.emit()

    def clear_selection(self) -> None:
        self.spans = []
        self.phone_selection = None
        self.selection_changed.emit()

    def selected_frames(self) -> np.ndarray:
        """Every selected frame once, sorted."""
        if not self.spans:
            return np.zeros(0, dtype=np.int64)
        return np.unique(np.concatenate([s.frames() for s in self.spans]))

    def frames_for_pca(self):
        """What to hand :func:`~engine.mocap.pca.multistage_pca`: the phone selection itself, or the frames."""
        if self.phone_selection is not None:
            return self.phone_selection
        return self.selected_frames()

    # -- PCA --------------------------------------------------------------------
    def set_articulation(self, articulation) -> None:
        self.articulation = articulation
        self.articulation_changed.emit(articulation)
