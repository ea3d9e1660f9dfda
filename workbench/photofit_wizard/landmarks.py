"""The wizard's landmark page: each photograph with the head's landmarks to drag onto it.

On the front photograph the markers start where dlib's face detector and
68-point predictor put them (:func:`engine.photofit.auto_landmarks.find_face_points`,
when the photographs page asks for it): the MPEG-4 points and the jaw line's,
brows', nose's points (``ibug.N``, small, with their number). A photograph
where no single face of a usable size is found says so in a dialog, and
the markers start at a first guess instead: where the current head's
landmarks fall with the face centred and scaled to the photograph
(:func:`engine.photofit.initial_points.initial_points`); so does the side
photograph always (dlib finds no profile). **Place the rest** fits that camera
to the points found or moved so far and puts the others where the head says
they are, so dragging the six required points (red) brings the rest close. Every drag, right-click (leave an optional
point out or take it back), Place the rest, Reset and Load is one step of
the wizard's own undo stack (Ctrl+Z, Ctrl+Shift+Z). Points are saved and
loaded as POINTS.json (``docs/photofit.md``).
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtGui import QKeySequence, QUndoCommand, QUndoStack
from PySide6.QtWidgets import (
    QApplication,
    QFileDialog,
    QHBoxLayout,
    QLabel,
    QMessageBox,
    QPushButton,
    QToolButton,
    QVBoxLayout,
    QWidget,
    QWizardPage,
)

import engine
from engine.photofit import PhotoFitError, read_points
from engine.photofit.auto_landmarks import find_face_points
from engine.photofit.face_points import known_ids
from engine.photofit.initial_points import initial_points, place_from, visible_landmarks
from engine.photofit.points import REQUIRED_FRONT, parse_points

from .canvas import PhotoCanvas, PointState
from .session import TITLE, VIEWS, PhotoFitSession

ViewState = dict[str, dict[str, PointState]]


class MoveMarker(QUndoCommand):
    """A marker dragged from ``old`` to ``new`` (already there when pushed)."""

    def __init__(self, canvas: PhotoCanvas, key: str, old: tuple[float, float], new: tuple[float, float]):
        super().__init__(f"Move {key}")
        self.canvas, self.key, self.old, self.new = canvas, key, old, new

    def redo(self) -> None:
        self.canvas.markers[self.key].setPos(*self.new)

    def undo(self) -> None:
        self.canvas.markers[self.key].setPos(*self.old)


class SetPoints(QUndoCommand):
    """Every marker of every view from one state to another (toggle, place the rest, reset, load)."""

    def __init__(self, page: LandmarkPage, old: ViewState, new: ViewState, text: str):
        super().__init__(text)
        self.page, self.old, self.new = page, old, new

    def redo(self) -> None:
        self.page.apply_state(self.new)

    def undo(self) -> None:
        self.page.apply_state(self.old)


class LandmarkPage(QWizardPage):
    def __init__(self, session: PhotoFitSession, undo_stack: QUndoStack):
        super().__init__()
        self.session, self.undo_stack = session, undo_stack
        self.setTitle("Landmarks")
        self.setSubTitle("Drag each point onto the photograph: red points are required, cyan ones help. "
                         "Right-click a cyan point to leave it out. Wheel zooms, double-click shows it all.")
        self.canvases = {view: PhotoCanvas() for view in VIEWS}
        self._placed_for: dict[str, tuple[object, bool]] = {}
        self.first: ViewState = {}                   # each view's first guesses (Reset goes back to them)
        self.found: dict[str, set[str]] = {}         # the points dlib found on each view
        self.problems: dict[str, str] = {}           # why none were found, as the dialog said
        row = QHBoxLayout()
        self.columns: dict[str, QWidget] = {}
        for view, canvas in self.canvases.items():
            column = self.columns[view] = QWidget()      # hidden whole when there is no such photograph
            inside = QVBoxLayout(column)
            inside.setContentsMargins(0, 0, 0, 0)
            inside.addWidget(QLabel(f"<b>{view.capitalize()}</b>"))
            inside.addWidget(canvas, 1)
            row.addWidget(column, 1)
            canvas.on_moved = lambda key, old, new, canvas=canvas: self.undo_stack.push(
                MoveMarker(canvas, key, old, new))
            canvas.on_toggled = lambda key, used, view=view: self._toggle(view, key, used)
        buttons = QHBoxLayout()
        self.undo_button = self._tool(undo_stack.createUndoAction(self, "Undo"), QKeySequence.StandardKey.Undo)
        self.redo_button = self._tool(undo_stack.createRedoAction(self, "Redo"), QKeySequence.StandardKey.Redo)
        self.place_button = QPushButton("Place the rest")
        self.place_button.setToolTip("Put the points you have not moved where the head says they are, "
                                     "given the ones you have moved (at least two)")
        self.place_button.clicked.connect(self.place_the_rest)
        self.reset_button = QPushButton("Reset")
        self.reset_button.setToolTip("Every point back to its first guess")
        self.reset_button.clicked.connect(self.reset)
        self.load_button = QPushButton("Load points…")
        self.load_button.clicked.connect(self.load_dialog)
        self.save_button = QPushButton("Save points…")
        self.save_button.clicked.connect(self.save_dialog)
        for widget in (self.undo_button, self.redo_button, self.place_button, self.reset_button):
            buttons.addWidget(widget)
        buttons.addStretch(1)
        buttons.addWidget(self.load_button)
        buttons.addWidget(self.save_button)
        layout = QVBoxLayout(self)
        layout.addLayout(row, 1)
        layout.addLayout(buttons)

    def _tool(self, action, shortcut) -> QToolButton:
        action.setShortcut(QKeySequence(shortcut))
        self.addAction(action)              # the shortcut works anywhere on the page
        button = QToolButton()
        button.setDefaultAction(action)
        return button

    # -- QWizardPage ---------------------------------------------------------------------
    def initializePage(self) -> None:
        """Markers at their first guesses for each photograph chosen anew; kept for one already placed."""
        replaced = False
        for view, canvas in self.canvases.items():
            photo = self.session.photos.get(view)
            self.columns[view].setVisible(photo is not None)
            if photo is None:
                self._placed_for.pop(view, None)
                continue
            placed_for = self._placed_for.get(view)
            if placed_for is not None and placed_for[0] is photo and placed_for[1] == self.session.find_points:
                continue
            canvas.set_photo(photo)
            self.first[view] = self.first_guess(view, photo)
            canvas.set_markers(self.first[view], self._required(view))
            self._placed_for[view] = (photo, self.session.find_points)
            replaced = True
        if replaced:
            self.undo_stack.clear()       # steps on markers that are gone would undo nothing

    def validatePage(self) -> bool:
        problem = self.problem()
        if problem is not None:
            QMessageBox.warning(self, TITLE, problem)
            return False
        self.session.points = self.points()
        return True

    # -- state ---------------------------------------------------------------------------
    def views(self) -> list[str]:
        return [view for view in VIEWS if view in self.session.photos]

    def state(self) -> ViewState:
        return {view: self.canvases[view].state() for view in self.views()}

    def apply_state(self, state: Mapping[str, Mapping[str, PointState]]) -> None:
        for view, points in state.items():
            self.canvases[view].apply_state(points)

    def points(self) -> dict[str, dict[str, tuple[float, float]]]:
        """POINTS.json's content: the used points of each photograph."""
        return {view: self.canvases[view].used_points() for view in self.views()}

    def problem(self) -> str | None:
        """Why these points cannot be fitted (the engine's own checks), or ``None``."""
        try:
            as_json = {view: {k: [x, y] for k, (x, y) in points.items()} for view, points in self.points().items()}
            parse_points(as_json, known_ids(self.session.landmark_head()), "the points")
        except PhotoFitError as error:
            return error.message
        for view in self.views():
            height, width = self.session.photos[view].shape[:2]
            for key, (x, y) in self.canvases[view].used_points().items():
                if not (0 <= x <= width and 0 <= y <= height):
                    return f"The {view} point {key} is outside the photograph: drag it back onto it."
        return None

    def first_guess(self, view: str, photo) -> dict[str, PointState]:
        """Where the markers start: the points dlib finds on the front photograph (the others placed from them
        and left out), else the head centred on the photograph (its jaw-line points left out)."""
        model = self.session.landmark_head()
        height, width = photo.shape[:2]
        guess = initial_points(model, view, width, height)
        self.found[view] = set()
        self.problems.pop(view, None)
        state = {k: (x, y, not k.startswith("ibug.")) for k, (x, y) in guess.items()}
        if view != "front" or not self.session.find_points:
            return state
        QApplication.setOverrideCursor(Qt.CursorShape.WaitCursor)
        try:
            found = find_face_points(photo, visible_landmarks(model, view), self.session.paths.get(view),
                                     hint="drag the points onto the face yourself").pixels
        except PhotoFitError as error:
            QApplication.restoreOverrideCursor()
            self.problems[view] = str(error)
            QMessageBox.warning(self, TITLE, f"{error}\n\nThe points start at a first guess instead.")
            return state
        QApplication.restoreOverrideCursor()
        placed = place_from(model, view, found)
        self.found[view] = set(found)
        required = self._required(view)
        return {k: (*found[k], True) if k in found else (*placed[k], k in required) for k in guess}

    def _required(self, view: str) -> tuple[str, ...]:
        return REQUIRED_FRONT if view == "front" else ()

    # -- edits -----------------------------------------------------------------------------
    def _change(self, new: ViewState, text: str) -> None:
        old = self.state()
        if new != old:
            self.undo_stack.push(SetPoints(self, old, new, text))

    def _toggle(self, view: str, key: str, used: bool) -> None:
        new = self.state()
        x, y, _ = new[view][key]
        new[view][key] = (x, y, used)
        self._change(new, f"{'Use' if used else 'Leave out'} {key}")

    def place_the_rest(self) -> None:
        """Points of each photograph neither found nor moved placed by the camera that fits those that were."""
        model = self.session.landmark_head()
        new = self.state()
        for view in self.views():
            guess, found = self.first[view], self.found.get(view, set())
            points = new[view]
            moved = {k: (x, y) for k, (x, y, _) in points.items()
                     if k in found or abs(x - guess[k][0]) + abs(y - guess[k][1]) > 0.5}
            if len(moved) < 2:
                continue
            placed = place_from(model, view, moved)
            new[view] = {k: (*placed[k], used) for k, (_, _, used) in points.items()}
        self._change(new, "Place the rest")

    def reset(self) -> None:
        """Every point back to its first guess (one undo step)."""
        self._change({view: dict(self.first[view]) for view in self.views()}, "Reset points")

    # -- files -----------------------------------------------------------------------------
    def load_dialog(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, "Load landmarks", "", "Landmarks (*.json);;All files (*)")
        if path:
            self.load(path)

    def load(self, path: str | Path) -> bool:
        """Points of a POINTS.json file: the ones it names placed and used, the others left out."""
        try:
            points = read_points(path, known=known_ids(self.session.landmark_head()))
            if "side" in points and "side" not in self.session.photos:
                raise PhotoFitError("the file has 'side' points but no side photograph was chosen", file=path)
        except PhotoFitError as error:
            QMessageBox.critical(self, TITLE, str(error))
            return False
        new = self.state()
        hidden: list[str] = []
        model = self.session.landmark_head()
        for view in self.views():
            given = points.get(view, {})
            shown = {k: xy for k, xy in given.items() if k in new[view]}
            # the points the file leaves out: left out, and put where the file's points say they are
            guess = place_from(model, view, shown) if len(shown) >= 2 else {}
            new[view] = {k: (*given[k], True) if k in given else (*guess.get(k, (x, y)), k in self._required(view))
                         for k, (x, y, _) in new[view].items()}
            hidden += [f"{view} {k}" for k in sorted(given.keys() - new[view].keys())]
        self._change(new, f"Load {Path(path).name}")
        if hidden:
            QMessageBox.information(self, TITLE, "Not shown in its photograph, so left out: " + ", ".join(hidden))
        return True

    def save_dialog(self) -> None:
        path, _ = QFileDialog.getSaveFileName(self, "Save landmarks", "points.json", "Landmarks (*.json)")
        if path:
            self.save(path)

    def save(self, path: str | Path) -> None:
        rounded = {view: {k: [round(x, 2), round(y, 2)] for k, (x, y) in points.items()}
                   for view, points in self.points().items()}
        try:
            Path(path).write_text(json.dumps(rounded, indent=1) + "\n", encoding="utf-8")
        except OSError as error:
            QMessageBox.critical(self, TITLE, str(engine.UserError(f"cannot write: {error.strerror}", file=path)))
