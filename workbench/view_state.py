"""How the model is displayed (not what it is): wireframe, hidden parts.

Kept apart from :class:`~workbench.document.ModelDocument` because none of it
belongs in a model file; menus write it, the viewport listens.
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Signal


class ViewState(QObject):
    """Display options shared by the viewport and the menus.

    Signals
    -------
    wireframe_changed(bool)
    part_visibility_changed(str, bool)
        A part was shown (``True``) or hidden (``False``).
    """

    wireframe_changed = Signal(bool)
    part_visibility_changed = Signal(str, bool)

    def __init__(self, parent: QObject | None = None):
        super().__init__(parent)
        self._wireframe = False
        self._hidden: set[str] = set()

    @property
    def wireframe(self) -> bool:
        return self._wireframe

    def set_wireframe(self, on: bool) -> None:
        on = bool(on)
        if on != self._wireframe:
            self._wireframe = on
            self.wireframe_changed.emit(on)

    def is_part_visible(self, part: str) -> bool:
        return part not in self._hidden

    @property
    def hidden_parts(self) -> frozenset[str]:
        return frozenset(self._hidden)

    def set_part_visible(self, part: str, visible: bool) -> None:
        if visible == self.is_part_visible(part):
            return
        if visible:
            self._hidden.discard(part)
        else:
            self._hidden.add(part)
        self.part_visibility_changed.emit(part, bool(visible))

    def show_all_parts(self) -> None:
        """Make every part visible again (e.g. when another model is opened)."""
        for part in sorted(self._hidden):
            self.set_part_visible(part, True)
