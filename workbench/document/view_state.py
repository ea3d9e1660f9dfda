"""How the model is displayed (not what it is): wireframe, landmarks, hidden parts, the selected parameter.

Kept apart from :class:`~workbench.document.model_document.ModelDocument` because none of it
belongs in a model file; menus write it, the viewport listens.
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Signal


class ViewState(QObject):
    """Display options shared by the viewport and the menus.

    Signals
    -------
    wireframe_changed(bool)
    landmarks_changed(bool)
        The model's landmarks are drawn (``True``) or not.
    part_visibility_changed(str, bool)
        A part was shown (``True``) or hidden (``False``).
    selected_parameter_changed(object)
        The parameter selected in the tree (its name), or ``None``. Tools
        act on it (painting paints its weights).
    heat_map_changed(bool)
        The selected parameter's influence region is drawn as a heat map
        on the mesh (``True``) or the mesh shows its own colours.
    """

    wireframe_changed = Signal(bool)
    landmarks_changed = Signal(bool)
    part_visibility_changed = Signal(str, bool)
    selected_parameter_changed = Signal(object)
    heat_map_changed = Signal(bool)

    def __init__(self, parent: QObject | None = None):
        super().__init__(parent)
        self._wireframe = False
        self._landmarks = False
        self._hidden: set[str] = set()
        self._selected: str | None = None
        self._heat_map = True

    @property
    def selected_parameter(self) -> str | None:
        return self._selected

    def select_parameter(self, name: str | None) -> None:
        if name != self._selected:
            self._selected = name
            self.selected_parameter_changed.emit(name)

    @property
    def heat_map(self) -> bool:
        """Whether the selected parameter's weights are shown as colours (on by default)."""
        return self._heat_map

    def set_heat_map(self, on: bool) -> None:
        on = bool(on)
        if on != self._heat_map:
            self._heat_map = on
            self.heat_map_changed.emit(on)

    @property
    def wireframe(self) -> bool:
        return self._wireframe

    def set_wireframe(self, on: bool) -> None:
        on = bool(on)
        if on != self._wireframe:
            self._wireframe = on
            self.wireframe_changed.emit(on)

    @property
    def landmarks(self) -> bool:
        """Whether the model's landmarks are drawn (off by default)."""
        return self._landmarks

    def set_landmarks(self, on: bool) -> None:
        on = bool(on)
        if on != self._landmarks:
            self._landmarks = on
            self.landmarks_changed.emit(on)

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
