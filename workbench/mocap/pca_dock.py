"""The multistage PCA wizard, a dock in three steps: stages → results → onto the model.

1. **Stages**: which markers guide each stage and how many components it
   takes (the paper's default: the jaw marker 2.1, one component; the lip
   contour 8.x, four), the frames chosen in the coordinate plot (all frames
   when none are). **Run PCA** calls :func:`engine.mocap.pca.multistage_pca`
   off the GUI thread.
2. **Results**: explained variance per component and stage (a bar chart and
   the engine's report), each component animated as marker motion over the
   face (±amplitude in standard deviations), **Save articulation file…**
   (:func:`~engine.mocap.articulation_file.save_articulation_file`).
3. **Apply to model**: one field translation parameter per component
   (:func:`~engine.mocap.apply.apply_articulation`, on a copy in the
   background, then added to the open model as one undo step), and the
   session's frames the PCA did not analyse reconstructed through the face
   (:func:`~engine.mocap.held_out.reconstruct_held_out`): the error in mm per
   marker in a table and as the colour of the marker spheres.
"""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QSize, Qt, QTimer, Signal
from PySide6.QtGui import QBrush, QColor, QFontDatabase
from PySide6.QtWidgets import (
    QComboBox,
    QDockWidget,
    QFileDialog,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QPlainTextEdit,
    QPushButton,
    QSlider,
    QSpinBox,
    QTableWidget,
    QTableWidgetItem,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from engine.mocap.animate import session_component_values
from engine.mocap.apply import apply_articulation
from engine.mocap.articulation_file import save_articulation_file
from engine.mocap.held_out import reconstruct_held_out
from engine.mocap.pca import DEFAULT_STAGES, Stage, multistage_pca

from ..background import run_in_background, show_error
from ..window.dock_scroller import DockScroller
from .apply_command import AddArticulationCommand
from .marker_overlay import error_colors
from .state import MocapState
from .variance_chart import VarianceChart

TITLE = "Multistage PCA"
AMPLITUDE_SD = 2.0
USEFUL_WIDTH, USEFUL_HEIGHT = 440, 380


class PcaDock(QDockWidget):
    """The wizard over a :class:`MocapState` and the window's document.

    ``preview_changed(object)``: ``(markers, points (M, 3) mm in marker space)``
    to draw instead of the session's frame while a component is shown, or ``None``.
    ``errors_changed(object)``: ``{marker: RMS error mm}`` after "Apply", or ``None``.
    ``recording_fitted(object)``: after "Apply", ``(names, values (frames × names))``: the whole session
    fitted by the new parameters, for the player to play through the face.
    """

    preview_changed = Signal(object)
    errors_changed = Signal(object)
    recording_fitted = Signal(object)

    def __init__(self, state: MocapState, document, parent: QWidget | None = None):
        super().__init__(TITLE, parent)
        self.setObjectName("dock:mocap-pca")
        self.state = state
        self.document = document
        self.job = None
        self.applied = None
        self.held_out = None
        self.tabs = QTabWidget()
        self.tabs.addTab(self._stages_page(), "1 Stages")
        self.tabs.addTab(self._results_page(), "2 Results")
        self.tabs.addTab(self._apply_page(), "3 Apply")
        self.setWidget(DockScroller(self.tabs))   # narrower than its content: scroll, not widen the window
        self._phase = 0.0
        self.timer = QTimer(self)
        self.timer.setInterval(40)
        self.timer.timeout.connect(self._tick)
        state.session_changed.connect(lambda _s: self._update_frames_label())
        state.selection_changed.connect(self._update_frames_label)
        state.articulation_changed.connect(self._on_articulation)
        self.set_stages([(",".join(s.markers), s.components) for s in DEFAULT_STAGES])
        self._update_frames_label()

    def useful_size(self) -> QSize:
        """Room for the stage table with its Components column and the Run PCA button (LayoutManager.reveal)."""
        return QSize(USEFUL_WIDTH, USEFUL_HEIGHT)

    # -- step 1: stages ---------------------------------------------------------------
    def _stages_page(self) -> QWidget:
        page = QWidget()
        self.stage_table = QTableWidget(0, 2)
        self.stage_table.setHorizontalHeaderLabels(["Markers (comma-separated, 8.* allowed)", "Components"])
        self.stage_table.horizontalHeader().setSectionResizeMode(0, QHeaderView.ResizeMode.Stretch)
        add = QPushButton("Add stage")
        add.clicked.connect(lambda: self._add_stage_row("", 1))
        remove = QPushButton("Remove stage")
        remove.clicked.connect(lambda: self.stage_table.removeRow(self.stage_table.rowCount() - 1))
        self.frames_label = QLabel()
        self.frames_label.setWordWrap(True)
        self.run_button = QPushButton("Run PCA")
        self.run_button.clicked.connect(self.run_pca)
        buttons = QHBoxLayout()
        for w in (add, remove):
            buttons.addWidget(w)
        buttons.addStretch(1)
        buttons.addWidget(self.run_button)
        layout = QVBoxLayout(page)
        layout.addWidget(_wrapped("Each stage takes the principal components of its markers in what the earlier "
                                  "stages left (§3.1.2): the jaw first, then the lips."))
        layout.addWidget(self.stage_table, 1)
        layout.addWidget(self.frames_label)
        layout.addLayout(buttons)
        return page

    def _add_stage_row(self, markers: str, components: int) -> None:
        row = self.stage_table.rowCount()
        self.stage_table.insertRow(row)
        self.stage_table.setItem(row, 0, QTableWidgetItem(markers))
        spin = QSpinBox()
        spin.setRange(1, 30)
        spin.setValue(int(components))
        self.stage_table.setCellWidget(row, 1, spin)

    def set_stages(self, stages) -> None:
        """``[(markers text, components), …]``, e.g. ``[("2.1", 1), ("8.*", 4)]``."""
        self.stage_table.setRowCount(0)
        for markers, components in stages:
            self._add_stage_row(markers, components)

    def stages(self) -> list[Stage]:
        out = []
        for row in range(self.stage_table.rowCount()):
            item = self.stage_table.item(row, 0)
            names = tuple(m for m in (item.text() if item else "").replace(" ", "").split(",") if m)
            out.append(Stage(names, self.stage_table.cellWidget(row, 1).value()))
        return out

    def _update_frames_label(self) -> None:
        session = self.state.session
        if session is None:
            self.frames_label.setText("No session: import a marker file or open a session first.")
        else:
            n = len(self.state.selected_frames())
            what = (f"{n} selected frames" if n else f"all {session.n_frames} frames (none selected)")
            self.frames_label.setText(f"Frames analysed: {what} of {session.source}; frames in which an analysed "
                                      "marker is missing are left out.")
        self.run_button.setEnabled(session is not None)

    def run_pca(self) -> None:
        """Multistage PCA of the session on the selected frames, in the background."""
        session = self.state.session
        if session is None:
            return
        try:
            stages = self.stages()
        except Exception as exc:
            show_error(self, TITLE, exc)
            return
        frames = self.state.frames_for_pca()
        if not len(frames):
            frames = None
        self.job = run_in_background(self, "Multistage PCA…",
                                     lambda: multistage_pca(session, stages=stages, frames=frames),
                                     self.state.set_articulation, title=TITLE)

    # -- step 2: results --------------------------------------------------------------
    def _results_page(self) -> QWidget:
        page = QWidget()
        self.chart = VarianceChart()
        self.report = QPlainTextEdit()
        self.report.setReadOnly(True)
        self.report.setFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont))
        self.component_combo = QComboBox()
        self.component_combo.currentIndexChanged.connect(self._show_component)
        self.amplitude = QSlider(Qt.Orientation.Horizontal)
        self.amplitude.setRange(-300, 300)
        self.amplitude.setToolTip("Component value in standard deviations (−3 … +3)")
        self.amplitude.valueChanged.connect(self._show_component)
        self.animate_button = QPushButton("Animate")
        self.animate_button.setCheckable(True)
        self.animate_button.toggled.connect(self.animate)
        stop = self.show_session_button = QPushButton("Show the session")
        stop.clicked.connect(self.stop_preview)
        self.save_button = QPushButton("Save articulation file…")
        self.save_button.clicked.connect(self._save_dialog)
        choose = QHBoxLayout()          # two short rows, not one long one: the dock stays narrow
        choose.addWidget(QLabel("Component"))
        choose.addWidget(self.component_combo)
        choose.addWidget(self.amplitude, 1)
        row = QHBoxLayout()
        for w in (self.animate_button, stop):
            row.addWidget(w)
        row.addStretch(1)
        row.addWidget(self.save_button)
        layout = QVBoxLayout(page)
        layout.addWidget(self.chart, 2)
        layout.addLayout(choose)
        layout.addLayout(row)
        layout.addWidget(self.report, 1)
        return page

    def _on_articulation(self, art) -> None:
        self.stop_preview()
        self.chart.set_articulation(art)
        self.report.setPlainText(art.report() if art is not None else "")
        self.component_combo.blockSignals(True)
        self.component_combo.clear()
        if art is not None:
            ratios = art.explained_variance_ratio
            self.component_combo.addItems([f"PC{k + 1} ({100 * ratios[k]:.1f} %)" for k in range(art.n_components)])
        self.component_combo.blockSignals(False)
        self.save_button.setEnabled(art is not None)
        self.apply_button.setEnabled(art is not None)
        self.applied = self.held_out = None
        self.error_table.setRowCount(0)
        self.apply_report.setPlainText("")
        self.errors_changed.emit(None)
        if art is not None:
            self.tabs.setCurrentIndex(1)

    def component_points(self, component: int, value_sd: float) -> np.ndarray:
        """Marker positions (M, 3) mm at ``value_sd`` standard deviations of ``component`` (others 0)."""
        art = self.state.articulation
        values = np.zeros(art.n_components)
        values[component] = value_sd
        return art.reconstruct(values)

    def show_component(self, component: int, value_sd: float) -> None:
        art = self.state.articulation
        if art is None:
            return
        self.preview_changed.emit((list(art.markers), self.component_points(component, value_sd)))

    def _show_component(self, *_args) -> None:
        if self.state.articulation is not None and self.component_combo.currentIndex() >= 0:
            self.show_component(self.component_combo.currentIndex(), self.amplitude.value() / 100.0)

    def animate(self, on: bool) -> None:
        """Move the markers along ±2 SD of the chosen component, over and over, while ``on``."""
        if on and self.state.articulation is not None:
            self.timer.start()
        else:
            self.timer.stop()

    def _tick(self) -> None:
        self._phase = (self._phase + 0.08) % (2 * np.pi)
        self.amplitude.setValue(round(100 * AMPLITUDE_SD * np.sin(self._phase)))

    def stop_preview(self) -> None:
        self.animate_button.setChecked(False)
        self.timer.stop()
        self.preview_changed.emit(None)

    def save_articulation(self, path) -> None:
        try:
            save_articulation_file(self.state.articulation, path)
        except Exception as exc:
            show_error(self, TITLE, exc)

    def _save_dialog(self) -> None:
        path, _ = QFileDialog.getSaveFileName(self, "Save articulation file", "articulation.h5",
                                              "Articulation files (*.h5)")
        if path:
            self.save_articulation(path)

    # -- step 3: apply -----------------------------------------------------------------
    def _apply_page(self) -> QWidget:
        page = QWidget()
        self.prefix_edit = QLineEdit("pca")
        self.prefix_edit.setToolTip("Parameter names: prefix1 … prefixN")
        self.apply_button = QPushButton("Apply to model")
        self.apply_button.setEnabled(False)
        self.apply_button.clicked.connect(self.apply_to_model)
        self.apply_report = QPlainTextEdit()
        self.apply_report.setReadOnly(True)
        self.error_table = QTableWidget(0, 2)
        self.error_table.setHorizontalHeaderLabels(["Marker", "Held-out RMS (mm)"])   # read whole at 1366 px
        self.error_table.horizontalHeaderItem(1).setToolTip(
            "Root-mean-square error of the marker, in mm, over the frames the PCA did not analyse, "
            "reconstructed through the face")
        header = self.error_table.horizontalHeader()
        header.setSectionResizeMode(0, QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(1, QHeaderView.ResizeMode.Stretch)
        self.error_table.verticalHeader().setVisible(False)
        row = QHBoxLayout()
        row.addWidget(QLabel("Parameter names"))
        row.addWidget(self.prefix_edit)
        row.addWidget(self.apply_button)
        row.addStretch(1)
        layout = QVBoxLayout(page)
        layout.addWidget(_wrapped("One translation parameter per component is added to the open model "
                                  "(one undo step); the session's other frames are then reconstructed "
                                  "through the face and compared with the captured markers."))
        layout.addLayout(row)
        body = QHBoxLayout()
        body.addWidget(self.error_table, 1)
        body.addWidget(self.apply_report, 1)
        layout.addLayout(body, 1)
        return page

    def apply_to_model(self) -> None:
        """Add the parameters (off the GUI thread on a copy, then one undo command) and measure the error."""
        art, session = self.state.articulation, self.state.session
        if art is None or session is None:
            return
        model = self.document.model.copy()
        prefix = self.prefix_edit.text().strip() or "pca"
        held = np.setdiff1d(np.arange(session.n_frames), art.frames)
        if not len(held):
            held = np.arange(session.n_frames)

        def work():
            applied = apply_articulation(model, art, prefix=prefix)
            error = reconstruct_held_out(model, applied, art, session.markers, session.positions[held])
            added = [(model.parameters[n], model.regions[n]) for n in applied.names]
            _, values, _ = session_component_values(model, applied, session)    # the recording through them
            return applied, error, added, values

        self.job = run_in_background(self, "Putting the components onto the face…", work, self._applied, title=TITLE)

    def _applied(self, result) -> None:
        applied, error, added, values = result
        try:
            self.document.push(AddArticulationCommand(self.document, added))
        except Exception as exc:
            show_error(self, TITLE, exc)
            return
        self.applied, self.held_out = applied, error
        self.apply_report.setPlainText(applied.report() + "\n" + error.report())
        colors = error_colors(error.per_marker_rms_mm)
        self.error_table.setRowCount(len(error.markers))
        for row, (marker, rms) in enumerate(zip(error.markers, error.per_marker_rms_mm, strict=True)):
            name = QTableWidgetItem(marker)
            value = QTableWidgetItem(f"{rms:.3f}")
            value.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
            value.setBackground(QBrush(QColor(*[int(c) for c in colors[row]])))
            for item in (name, value):
                item.setFlags(Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsSelectable)
            self.error_table.setItem(row, 0, name)
            self.error_table.setItem(row, 1, value)
        self.errors_changed.emit(dict(zip(error.markers, error.per_marker_rms_mm.tolist(), strict=True)))
        self.tabs.setCurrentIndex(2)
        self.recording_fitted.emit((list(applied.names), values))

    def shown_errors(self) -> dict[str, float]:
        """The error table as ``{marker: mm}`` (what the user reads)."""
        return {self.error_table.item(r, 0).text(): float(self.error_table.item(r, 1).text())
                for r in range(self.error_table.rowCount())}


def _wrapped(text: str) -> QLabel:
    """A label that wraps its lines to the dock's width instead of setting the dock's minimum width."""
    label = QLabel(text)
    label.setWordWrap(True)
    return label
