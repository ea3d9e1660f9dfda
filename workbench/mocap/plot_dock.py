"""The "Marker coordinates" dock: choose a marker and axis, see it over time, select and label frames.

A click on the plot selects one frame, a drag a range; each gets the phone
written in the *Phone* box and shows as a shaded span (and moves the shared
playhead there). *Select by phones* replaces the selection by one frame in
the middle of every phone matching the selectors — the engine's
:func:`~engine.mocap.frame_selection.select_frames` (``V C``: every vowel and consonant;
``a/p_p``: *a* between two *p*'s). Phone labels are imported from a
TextGrid or label file, or aligned from Festival's timing of the spoken
text (:mod:`engine.speech.labels`), and drawn along the time axis.
"""

from __future__ import annotations

from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDockWidget,
    QFileDialog,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from engine.mocap.errors import MocapError
from engine.mocap.frame_selection import select_frames
from engine.speech.labels import festival_phones, read_labels

from ..background import run_in_background, show_error
from ..flow_layout import FlowLayout
from ..window.dock_scroller import DockScroller
from .coordinate_plot import CoordinatePlot
from .import_dialog import LABEL_FILES
from .state import MocapState

AXES = ("x", "y", "z")
TITLE = "Marker coordinates"
USEFUL_WIDTH, USEFUL_HEIGHT = 640, 240


class MarkerPlotDock(QDockWidget):
    """The coordinate plot and the frame selection, over a :class:`MocapState` and the window's playhead."""

    def __init__(self, state: MocapState, playhead, parent: QWidget | None = None):
        super().__init__(TITLE, parent)
        self.setObjectName("dock:mocap-plot")
        self.state = state
        self.playhead = playhead
        self.job = None

        self.marker_combo = QComboBox()
        self.marker_combo.setMinimumContentsLength(6)
        self.axis_combo = QComboBox()
        self.axis_combo.addItems(AXES)
        self.axis_combo.setCurrentText("y")
        self.phone_edit = QComboBox()
        self.phone_edit.setEditable(True)
        self.phone_edit.setMinimumContentsLength(4)
        self.phone_edit.setToolTip("The phone the next clicked or dragged frames stand for")
        self.selectors_edit = QLineEdit("V C")
        self.selectors_edit.setToolTip("Phone selectors, space-separated: V (vowels), C (consonants), #, a, "
                                       "m,p,b, a/p_p (a between p's), V/_# …")
        select_button = QPushButton("Select by phones")
        select_button.clicked.connect(self.select_by_phones_from_edit)
        remove_button = QPushButton("Remove last")
        remove_button.clicked.connect(self.remove_last_span)
        clear_button = QPushButton("Clear")
        clear_button.clicked.connect(state.clear_selection)
        labels_button = QPushButton("Labels…")
        labels_button.setToolTip("Import phone labels: Praat TextGrid, label file (s) or phones CSV")
        labels_button.clicked.connect(self._import_labels_dialog)
        festival_button = QPushButton("Festival…")
        festival_button.setToolTip("Phone labels from Festival's timing of the spoken text")
        festival_button.clicked.connect(self._festival_dialog)
        self.names_button = QPushButton("Marker names")
        self.names_button.setCheckable(True)
        self.names_button.setToolTip("Show the markers' names beside the plot: give each marker its MPEG-4 feature "
                                     "point (click it on the face or in the list)")
        self.names_button.setEnabled(False)             # until there is a panel to show
        self.count_label = QLabel()

        row = FlowLayout(spacing=4)     # one line when the dock is wide, wrapped when it is narrow
        for group in ((QLabel("Marker"), self.marker_combo, self.axis_combo), (QLabel("Phone"), self.phone_edit),
                      (self.selectors_edit, select_button), (remove_button, clear_button),
                      (labels_button, festival_button), (self.names_button,)):
            row.addWidget(_side_by_side(*group))
        row.addWidget(self.count_label, stretch=1)
        self.count_label.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        self.plot = CoordinatePlot()
        body = QWidget()
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 2, 4, 2)
        layout.addLayout(row)
        self._beside_plot = QHBoxLayout()
        self._beside_plot.addWidget(self.plot, 1)
        layout.addLayout(self._beside_plot, 1)
        self.setWidget(DockScroller(body))   # narrower than its content: scroll, not widen the window

        self.marker_combo.currentTextChanged.connect(self._update_curve)
        self.axis_combo.currentTextChanged.connect(self._update_curve)
        self.plot.frame_clicked.connect(self._on_clicked)
        self.plot.range_dragged.connect(self._on_dragged)
        state.session_changed.connect(self._on_session)
        state.markers_renamed.connect(self._on_renamed)
        state.phones_changed.connect(self._on_phones)
        state.selection_changed.connect(self._on_selection)
        playhead.time_changed.connect(self._on_playhead)
        self._on_session(state.session)


    #: Whether the playhead is the recording's (the player plays the session); set by the recording's playback.
    playhead_is_recording = True

    def _on_playhead(self, seconds: float) -> None:
        """The red line follows the playhead only while the player plays this recording."""
        self.plot.set_playhead(seconds if self.playhead_is_recording else None)

    def add_side_panel(self, panel: QWidget) -> None:
        """Put ``panel`` (the marker names) on the left of the plot, shown while *Marker names* is down."""
        self._beside_plot.insertWidget(0, panel)
        panel.setVisible(self.names_button.isChecked())
        self.names_button.toggled.connect(panel.setVisible)
        self.names_button.setEnabled(True)

    def useful_size(self) -> QSize:
        """Wide enough to read phones along the time axis, high enough for the curve (LayoutManager.reveal)."""
        return QSize(USEFUL_WIDTH, USEFUL_HEIGHT)

    # -- what is shown -------------------------------------------------------------------
    def show_coordinate(self, marker: str, axis: str) -> None:
        self.marker_combo.setCurrentText(marker)
        self.axis_combo.setCurrentText(axis)

    @property
    def marker(self) -> str:
        return self.marker_combo.currentText()

    def _on_session(self, session) -> None:
        self.marker_combo.blockSignals(True)
        self.marker_combo.clear()
        if session is not None:
            self.marker_combo.addItems(session.markers)
            self.marker_combo.setCurrentText("2.1" if "2.1" in session.markers else session.markers[0])
        self.marker_combo.blockSignals(False)
        self._update_curve()
        self._on_phones()
        self._on_selection()

    def _on_renamed(self, renames: dict) -> None:
        """Markers were renamed: the list follows, and so does the marker plotted."""
        current = renames.get(self.marker, self.marker)
        self.marker_combo.blockSignals(True)
        self.marker_combo.clear()
        self.marker_combo.addItems(self.state.session.markers)
        self.marker_combo.setCurrentText(current)
        self.marker_combo.blockSignals(False)
        self._update_curve()

    def _update_curve(self, *_args) -> None:
        session = self.state.session
        if session is None or self.marker not in session.markers:
            self.plot.set_curve([], 60.0)
            return
        axis = AXES.index(self.axis_combo.currentText())
        values = session.positions[:, session.marker_index(self.marker), axis]
        self.plot.set_curve(values, session.rate_hz, f"marker {self.marker}, {'xyz'[axis]} (mm)")

    def _on_phones(self) -> None:
        session = self.state.session
        phones = session.phones if session is not None else []
        self.plot.set_phones(phones)
        current = self.phone_edit.currentText()
        self.phone_edit.clear()
        self.phone_edit.addItems(sorted({p[2] for p in phones}))
        self.phone_edit.setCurrentText(current)

    def _on_selection(self) -> None:
        self.plot.set_spans(self.state.spans)
        n, spans = len(self.state.selected_frames()), len(self.state.spans)
        self.count_label.setText(f"{n} {'frame' if n == 1 else 'frames'} selected in {spans} "
                                 f"{'span' if spans == 1 else 'spans'}" if n else "no frames selected: PCA uses all")

    # -- selecting -------------------------------------------------------------------
    def _on_clicked(self, frame: int) -> None:
        if self.state.session is None:
            return
        self.state.add_span(frame, frame, self.phone_edit.currentText())
        self.playhead.set_frame(frame)

    def _on_dragged(self, first: int, second: int) -> None:
        if self.state.session is None:
            return
        self.state.add_span(first, second, self.phone_edit.currentText())
        self.playhead.set_frame(second)

    def select_by_phones(self, selectors) -> None:
        """Select one frame per phone matching ``selectors`` (engine :func:`select_frames`); errors → dialog."""
        session = self.state.session
        if session is None:
            return
        if not session.phones:
            show_error(self, TITLE, MocapError("the session has no phone labels: import a label file or align "
                                               "the text with Festival first"))
            return
        try:
            selection = select_frames(session.phones, session.n_frames, session.rate_hz, list(selectors))
        except Exception as exc:
            show_error(self, TITLE, exc)
            return
        self.state.set_phone_selection(selection)

    def select_by_phones_from_edit(self) -> None:
        self.select_by_phones(self.selectors_edit.text().split())

    def remove_last_span(self) -> None:
        if self.state.spans:
            self.state.remove_spans([len(self.state.spans) - 1])

    # -- phone labels ------------------------------------------------------------------
    def import_labels(self, path) -> None:
        try:
            phones = read_labels(path)
        except Exception as exc:
            show_error(self, TITLE, exc)
            return
        self.state.set_phones(phones)

    def align_with_festival(self, text: str, stretch: bool = True) -> None:
        """Phone labels from Festival's timing of ``text`` (stretched over the session), in the background."""
        session = self.state.session
        if session is None or not text.strip():
            return
        duration = session.n_frames * 1000.0 / session.rate_hz if stretch else None
        self.job = run_in_background(self, "Asking Festival for the phone timing…",
                                     lambda: festival_phones(text, duration_ms=duration), self.state.set_phones,
                                     title=TITLE)

    def _import_labels_dialog(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, "Import phone labels", "", LABEL_FILES)
        if path:
            self.import_labels(path)

    def _festival_dialog(self) -> None:
        dialog = QDialog(self)
        dialog.setWindowTitle("Phone labels from Festival")
        text = QLineEdit()
        text.setPlaceholderText("the text spoken in the recording")
        stretch = QCheckBox("stretch the timing over the whole recording")
        stretch.setChecked(True)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(dialog.accept)
        buttons.rejected.connect(dialog.reject)
        form = QFormLayout(dialog)
        form.addRow("Spoken text", text)
        form.addRow("", stretch)
        form.addRow(buttons)
        if dialog.exec() == QDialog.DialogCode.Accepted:
            self.align_with_festival(text.text(), stretch.isChecked())


def _side_by_side(*widgets: QWidget) -> QWidget:
    """Widgets that belong together (a label and its box), kept on one line when the row wraps."""
    holder = QWidget()
    layout = QHBoxLayout(holder)
    layout.setContentsMargins(0, 0, 0, 0)
    layout.setSpacing(4)
    for widget in widgets:
        layout.addWidget(widget)
    return holder
