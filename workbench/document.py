"""The open model and its current pose, announcing every change to the widgets.

:class:`ModelDocument` is the one object the workbench's widgets share. It
holds an :class:`engine.Model` and the value of every parameter, forwards
edits to the engine and emits a signal after each one; widgets listen and
redraw, they never talk to each other. Engine code never sees this class.
"""

from __future__ import annotations

from pathlib import Path
from typing import Mapping

import numpy as np
from PySide6.QtCore import QObject, Signal

import engine


class ModelDocument(QObject):
    """An :class:`engine.Model`, where it came from, and the pose being shown.

    Signals
    -------
    model_replaced(object)
        A different model is now open (after :meth:`open` or
        :meth:`replace_model`); every parameter is back at its default.
    values_changed(list)
        The listed parameters have new values; read them from :attr:`values`.
    path_changed(str)
        The file the model is associated with changed (e.g. after a save as).
    """

    model_replaced = Signal(object)
    values_changed = Signal(list)
    path_changed = Signal(str)

    def __init__(self, model: engine.Model, path: str | Path | None = None, parent: QObject | None = None):
        super().__init__(parent)
        self._model = model
        self._path = Path(path) if path is not None else None
        self._values = model.default_values()
        self._vertices: np.ndarray | None = None

    # -- state -----------------------------------------------------------
    @property
    def model(self) -> engine.Model:
        return self._model

    @property
    def path(self) -> Path | None:
        """The model's XML description on disk, or ``None`` for a model built in memory."""
        return self._path

    @property
    def values(self) -> dict[str, float]:
        """Current value of every parameter, by name (a copy)."""
        return dict(self._values)

    def value(self, name: str) -> float:
        self._model.parameters[name]  # unknown names raise ParameterError with a suggestion
        return self._values[name]

    def vertices(self) -> np.ndarray:
        """The deformed mesh for the current values, (N, 3) mm, computed once per change."""
        if self._vertices is None:
            self._vertices = self._model.deform(self._values)
        return self._vertices

    def is_at_rest(self) -> bool:
        return self._values == self._model.default_values()

    # -- pose edits --------------------------------------------------------
    def set_value(self, name: str, value: float) -> None:
        """Set one parameter; values outside its range raise :class:`engine.ParameterError`."""
        self.set_values({name: value})

    def set_values(self, values: Mapping[str, float]) -> None:
        """Set several parameters at once (one redraw); unchanged values are ignored."""
        values = {name: float(v) for name, v in values.items()}
        self._model.check_values(values)
        changed = [name for name, v in values.items() if self._values[name] != v]
        if not changed:
            return
        for name in changed:
            self._values[name] = values[name]
        self._vertices = None
        self.values_changed.emit(changed)

    def reset_value(self, name: str) -> None:
        """Put one parameter back to its default."""
        self.set_value(name, self._model.parameters[name].default)

    def reset_all(self) -> None:
        """Put every parameter back to its default: the rest pose."""
        self.set_values(self._model.default_values())

    # -- whole-model changes -------------------------------------------------
    def open(self, path: str | Path) -> None:
        """Load the model at ``path`` and make it current.

        Raises :class:`engine.UserError` (nothing changes) if it cannot be read.
        """
        model = engine.load_model(path)
        self.replace_model(model, path)

    def replace_model(self, model: engine.Model, path: str | Path | None = None) -> None:
        """Make ``model`` current, every parameter at its default."""
        self._model = model
        self._values = model.default_values()
        self._vertices = None
        self._set_path(path)
        self.model_replaced.emit(model)

    def save(self, path: str | Path) -> Path:
        """Write the model with :func:`engine.save_model` and remember the new path."""
        written = engine.save_model(self._model, path)
        self._set_path(written)
        return written

    def _set_path(self, path: str | Path | None) -> None:
        new = Path(path) if path is not None else None
        if new != self._path:
            self._path = new
            self.path_changed.emit(str(new) if new is not None else "")
