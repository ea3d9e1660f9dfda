"""The import dialog: a marker file → a session, with the marker list, gap statistics, naming and reference.

Choose a file (QTM TSV, C3D, TRC or CSV; a CSV table's column pattern, time
column, rate and units), and the dialog reads it in the background and
lists its markers: the file's label, the MPEG-4 feature point it becomes
(suggested by :func:`engine.mocap.naming.normalise_label`, editable, ``-``
drops the marker; loaded from or saved as a mapping file), whether it is a
head-fixed reference for removing head motion, and its gaps — frames
missing, gaps, the longest gap, and what the max-gap setting fills and
leaves missing (:func:`engine.mocap.gaps.marker_gap_stats`, by the very
rule the import then applies). Labels that would reach the session with no
MPEG-4 feature point name are counted and named in a warning above the
table (:func:`engine.mocap.marker_assignment.unmapped_labels`). The file's
up axis is found from the names, or chosen. Phone labels come from a
TextGrid or label file, or from Festival's timing of the spoken text.
**Import** runs :func:`engine.mocap.importer.import_marker_file` off the GUI
thread and saves the session file (HDF5), by default beside the project
(``folder()``, :mod:`.session_files`), not beside the marker file.

A file that cannot be read ends in a dialog naming file and line; the
table and summary then show nothing of any earlier file (the summary says
what went wrong) and Import stays off until a file reads. An import that
fails ends in the same dialog, and the dialog stays open with everything as
it was.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDoubleSpinBox,
    QFileDialog,
    QFormLayout,
    QGroupBox,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from engine.mocap.csv_table import CsvLayout
from engine.mocap.gaps import marker_gap_stats, max_gap_frames
from engine.mocap.importer import DEFAULT_MAX_GAP_MS, import_marker_file
from engine.mocap.marker_assignment import unmapped_labels
from engine.mocap.naming import DROP, default_reference, normalise_label, read_mapping, write_mapping
from engine.mocap.readers import FORMAT_NAMES, read_marker_file
from engine.mocap.session import save_session

from ..background import run_in_background, show_error

MARKER_FILES = "Marker files (*.tsv *.c3d *.trc *.csv *.txt);;All files (*)"
LABEL_FILES = "Phone labels (*.TextGrid *.lab *.txt *.csv);;All files (*)"
COLUMNS = ("Label in file", "Feature point", "Reference", "Missing frames", "Gaps", "Longest gap",
           "Filled frames", "Excluded frames")
LABEL, POINT, REFERENCE, MISSING, GAPS, LONGEST, FILLED, EXCLUDED = range(len(COLUMNS))
TITLE = "Import motion capture"
MAX_GAP_TIP = "Gaps up to this long are filled by a cubic spline; longer ones are excluded"
UP_AXES = (("found from the names", "auto"), ("+Z", "Z"), ("+Y", "Y"), ("+X", "X"), ("-Z", "-Z"), ("-Y", "-Y"),
           ("-X", "-X"))
NAMED_IN_WARNING = 8           # labels named in the warning's text; the tooltip has them all
WARNING_STYLE = "QLabel { background: #fff3cd; color: #5c4300; border: 1px solid #e3c46d; padding: 4px; }"


class ImportDialog(QDialog):
    """Read a marker file, adjust naming and options, import it as a session.

    ``session_imported(session, path)`` is emitted with the new
    :class:`~engine.mocap.session.Session` and the session file written
    (``None`` when saving was switched off).
    """

    session_imported = Signal(object, object)

    def __init__(self, parent: QWidget | None = None, folder=None):
        super().__init__(parent)
        self._folder = folder or Path.cwd          # where the session file is suggested
        self.setWindowTitle(TITLE)
        self.setObjectName("mocap-import-dialog")
        self.recording = None          # the file as read (engine Recording), for the table
        self._references_edited = False
        self._updating = False
        self.job = None

        self.path_edit = QLineEdit()
        self.path_edit.setPlaceholderText("a QTM .tsv, .c3d, .trc or .csv marker file")
        self.path_edit.editingFinished.connect(self.read_file)
        browse = QPushButton("Browse…")
        browse.clicked.connect(self._browse)
        self.format_combo = QComboBox()
        self.format_combo.addItem("Detect", "auto")
        for key, name in FORMAT_NAMES.items():
            self.format_combo.addItem(name, key)
        self.format_combo.currentIndexChanged.connect(self._on_format_changed)
        file_row = QHBoxLayout()
        file_row.addWidget(self.path_edit, 1)
        file_row.addWidget(browse)
        file_row.addWidget(self.format_combo)

        self.csv_box = QGroupBox("CSV columns")
        self.csv_columns = QLineEdit()
        self.csv_columns.setPlaceholderText("{marker}_{axis} (default: tried in turn)")
        self.csv_time = QLineEdit()
        self.csv_time.setPlaceholderText("time_ms, time_s, time or t")
        self.csv_rate = QDoubleSpinBox()
        self.csv_rate.setRange(0, 10000)
        self.csv_rate.setSpecialValueText("from the time column")
        self.csv_rate.setSuffix(" Hz")
        self.csv_units = QComboBox()
        self.csv_units.addItems(["mm", "cm", "m"])
        csv_form = QFormLayout(self.csv_box)
        csv_form.addRow("Column pattern", self.csv_columns)
        csv_form.addRow("Time column", self.csv_time)
        csv_form.addRow("Frame rate", self.csv_rate)
        csv_form.addRow("Units", self.csv_units)
        self.csv_box.setVisible(False)
        reread = QPushButton("Read again")
        reread.clicked.connect(self.read_file)
        csv_form.addRow("", reread)

        self.summary = QLabel("No file read yet.")
        self.summary.setWordWrap(True)
        self.unmapped_warning = QLabel()
        self.unmapped_warning.setObjectName("mocap-unmapped-labels")
        self.unmapped_warning.setWordWrap(True)
        self.unmapped_warning.setStyleSheet(WARNING_STYLE)
        self.unmapped_warning.setVisible(False)
        self.max_gap = QDoubleSpinBox()
        self.max_gap.setRange(0, 10000)
        self.max_gap.setDecimals(0)
        self.max_gap.setSuffix(" ms")
        self.max_gap.setValue(DEFAULT_MAX_GAP_MS)
        self.max_gap.setToolTip(MAX_GAP_TIP)
        self.max_gap.valueChanged.connect(self._refresh_gaps)

        self.table = QTableWidget(0, len(COLUMNS))
        self.table.setHorizontalHeaderLabels(COLUMNS)
        self.table.verticalHeader().setVisible(False)
        self.table.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        self.table.horizontalHeader().setStretchLastSection(True)
        self.table.itemChanged.connect(self._on_item_changed)
        load_map = QPushButton("Load mapping…")
        load_map.clicked.connect(self._load_mapping_dialog)
        save_map = QPushButton("Save mapping…")
        save_map.clicked.connect(self._save_mapping_dialog)
        suggest = QPushButton("Suggest names")
        suggest.setToolTip("Name every marker by the feature point its label spells (FP8_3 → 8.3)")
        suggest.clicked.connect(self.suggest_names)
        map_row = QHBoxLayout()
        for w in (QLabel("Fill gaps up to"), self.max_gap):
            map_row.addWidget(w)
        map_row.addStretch(1)
        for w in (suggest, load_map, save_map):
            map_row.addWidget(w)

        self.reference_frame = QComboBox()
        self.reference_frame.addItem("first complete frame", "first")
        self.reference_frame.addItem("mean reference shape", "mean")
        self.up_combo = QComboBox()
        for text, key in UP_AXES:
            self.up_combo.addItem(text, key)
        self.up_combo.setToolTip("The file's up axis; the markers are turned to +Y up, +Z facing. Found from the "
                                 "MPEG-4 names (mouth below the eyes) unless chosen here")
        self.labels_edit = QLineEdit()
        self.labels_edit.setPlaceholderText("TextGrid, label file or phones CSV (optional)")
        labels_browse = QPushButton("Browse…")
        labels_browse.clicked.connect(self._browse_labels)
        labels_row = QHBoxLayout()
        labels_row.addWidget(self.labels_edit, 1)
        labels_row.addWidget(labels_browse)
        self.text_edit = QLineEdit()
        self.text_edit.setPlaceholderText("or the spoken text, for Festival's phone timing")
        self.stretch = QCheckBox("stretch Festival's timing over the recording")
        self.save_check = QCheckBox("Save the session to")
        self.save_check.setChecked(True)
        self.session_edit = QLineEdit()
        save_row = QHBoxLayout()
        save_row.addWidget(self.save_check)
        save_row.addWidget(self.session_edit, 1)
        options = QFormLayout()
        options.addRow("Head motion: align to", self.reference_frame)
        options.addRow("Up axis in the file", self.up_combo)
        options.addRow("Phone labels", labels_row)
        options.addRow("Spoken text", self.text_edit)
        options.addRow("", self.stretch)
        options.addRow(save_row)

        self.buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Cancel)
        self.import_button = self.buttons.addButton("Import", QDialogButtonBox.ButtonRole.AcceptRole)
        self.import_button.setEnabled(False)
        self.buttons.accepted.connect(self.start_import)
        self.buttons.rejected.connect(self.reject)

        layout = QVBoxLayout(self)
        layout.addLayout(file_row)
        layout.addWidget(self.csv_box)
        layout.addWidget(self.summary)
        layout.addWidget(self.unmapped_warning)
        layout.addLayout(map_row)
        layout.addWidget(self.table, 1)
        layout.addLayout(options)
        layout.addWidget(self.buttons)
        self.resize(860, 640)

    # -- reading -------------------------------------------------------------------
    def set_path(self, path: str | Path) -> None:
        """Choose a marker file and read it (in the background)."""
        self.path_edit.setText(str(path))
        self.session_edit.setText(str(self.default_session_path(path)))
        self.read_file()

    def default_session_path(self, path: str | Path) -> Path:
        """``<folder()>/<marker file's name>.h5``: beside the project, not the data."""
        return Path(self._folder()) / (Path(path).stem + ".h5")

    def read_file(self) -> None:
        text = self.path_edit.text().strip()
        if not text:
            return
        path = Path(text)
        if not self.session_edit.text():
            self.session_edit.setText(str(self.default_session_path(path)))
        self.csv_box.setVisible(self._format() == "csv" or path.suffix.lower() == ".csv")
        fmt, layout = self._format(), self.csv_layout()
        self.import_button.setEnabled(False)
        job = self.job = run_in_background(self, f"Reading {path.name}…", lambda: read_marker_file(path, fmt, layout),
                                           self._on_read, self._on_read_failed, title=TITLE,
                                           on_finished=lambda: self._on_read_ended(job, path))

    def csv_layout(self) -> CsvLayout:
        return CsvLayout(columns=self.csv_columns.text().strip() or None,
                         time_column=self.csv_time.text().strip() or None,
                         rate_hz=self.csv_rate.value() or None, units=self.csv_units.currentText())

    def _on_read(self, recording) -> None:
        self.recording = recording
        self._references_edited = False
        self.summary.setText(f"{Path(recording.source).name}: {FORMAT_NAMES.get(recording.format, recording.format)}, "
                             f"{recording.n_frames} frames at {recording.rate_hz:g} Hz "
                             f"({recording.n_frames / recording.rate_hz:.1f} s), {len(recording.labels)} markers, "
                             f"file units {recording.units}"
                             + "".join(f"\nnote: {note}" for note in recording.notes))   # e.g. a file cut short
        self._updating = True
        self.table.setRowCount(len(recording.labels))
        for row, label in enumerate(recording.labels):
            item = QTableWidgetItem(label)
            item.setFlags(item.flags() & ~Qt.ItemFlag.ItemIsEditable)
            self.table.setItem(row, LABEL, item)
            self.table.setItem(row, POINT, QTableWidgetItem(""))
            check = QTableWidgetItem()
            check.setFlags(Qt.ItemFlag.ItemIsUserCheckable | Qt.ItemFlag.ItemIsEnabled)
            check.setCheckState(Qt.CheckState.Unchecked)
            self.table.setItem(row, REFERENCE, check)
            for column in range(MISSING, len(COLUMNS)):
                cell = QTableWidgetItem()
                cell.setFlags(Qt.ItemFlag.ItemIsEnabled)
                cell.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
                self.table.setItem(row, column, cell)
        self._updating = False
        self.suggest_names()
        self._refresh_gaps()
        self.import_button.setEnabled(True)

    def _on_read_failed(self, exc: Exception) -> None:
        self._forget_recording(f"Could not read the file: {exc}")
        show_error(self, TITLE, exc)

    def _on_read_ended(self, job, path: Path) -> None:
        if job.outcome == "cancelled" and job is self.job:       # not when a later read has begun
            self._forget_recording(f"Reading {path.name} was cancelled: choose a file or read it again.")

    def _forget_recording(self, why: str) -> None:
        """No file read: nothing of an earlier one stays in the table, ``why`` in the summary, Import off."""
        self.recording = None
        self._references_edited = False
        self._updating = True
        self.table.setRowCount(0)
        self._updating = False
        self.max_gap.setToolTip(MAX_GAP_TIP)
        self.import_button.setEnabled(False)
        self.summary.setText(why)
        self._update_warning()

    # -- naming and reference ----------------------------------------------------------
    def labels(self) -> list[str]:
        return [self.table.item(r, LABEL).text() for r in range(self.table.rowCount())]

    def names(self) -> list[str | None]:
        """The session name of every row (``None``: dropped)."""
        out = []
        for r, label in enumerate(self.labels()):
            target = self.table.item(r, POINT).text().strip() or label
            out.append(None if target == DROP else target)
        return out

    def mapping(self) -> dict[str, str]:
        """``{file label: feature point id or '-'}`` for every row."""
        return {label: (self.table.item(r, POINT).text().strip() or label) for r, label in enumerate(self.labels())}

    def set_mapping(self, mapping: dict[str, str]) -> None:
        """Name the rows by ``mapping`` (labels it lacks keep the suggestion)."""
        self._updating = True
        for r, label in enumerate(self.labels()):
            self.table.item(r, POINT).setText(mapping.get(label, normalise_label(label) or label))
        self._updating = False
        self._suggest_references()
        self._update_warning()

    def unmapped(self) -> list[str]:
        """The labels that would be imported under a name that is no MPEG-4 feature point."""
        return unmapped_labels(self.labels(), self.names())

    def _update_warning(self) -> None:
        """Say how many labels, and which, map to no feature point (hidden when every marker has one)."""
        unmapped = self.unmapped() if self.recording is not None else []
        self.unmapped_warning.setVisible(bool(unmapped))
        if not unmapped:
            self.unmapped_warning.clear()
            return
        named = ", ".join(unmapped[:NAMED_IN_WARNING])
        more = len(unmapped) - NAMED_IN_WARNING
        names = f"{named} and {more} more" if more > 0 else named
        kept = sum(name is not None for name in self.names())
        self.unmapped_warning.setText(
            f"⚠ {len(unmapped)} of {kept} labels map to no MPEG-4 feature point and would keep their file labels: "
            f"{names}. PCA and Apply look for feature points (2.1, 8.*): type them under Feature point, load a "
            "mapping, or click the markers on the face after the import and assign them there.")
        self.unmapped_warning.setToolTip("Labels with no feature point:\n" + "\n".join(unmapped))

    def suggest_names(self) -> None:
        self.set_mapping({})

    def references(self) -> list[str]:
        names = self.names()
        return [names[r] for r in range(self.table.rowCount())
                if names[r] is not None and self.table.item(r, REFERENCE).checkState() == Qt.CheckState.Checked]

    def set_references(self, names) -> None:
        wanted = set(names)
        self._updating = True
        for r, name in enumerate(self.names()):
            state = Qt.CheckState.Checked if name in wanted else Qt.CheckState.Unchecked
            self.table.item(r, REFERENCE).setCheckState(state)
        self._updating = False
        self._references_edited = True

    def _suggest_references(self) -> None:
        if self._references_edited:
            return
        names = self.names()
        self.set_references(default_reference([n for n in names if n is not None]))
        self._references_edited = False

    def _on_item_changed(self, item: QTableWidgetItem) -> None:
        if self._updating:
            return
        if item.column() == REFERENCE:
            self._references_edited = True
        elif item.column() == POINT:
            self._suggest_references()
            self._update_warning()

    def _load_mapping_dialog(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, "Load mapping file", "", "Mapping files (*.map *.txt);;All (*)")
        if path:
            self.load_mapping(path)

    def load_mapping(self, path: str | Path) -> None:
        try:
            self.set_mapping(read_mapping(path))
        except Exception as exc:
            show_error(self, TITLE, exc)

    def _save_mapping_dialog(self) -> None:
        path, _ = QFileDialog.getSaveFileName(self, "Save mapping file", "face.map", "Mapping files (*.map)")
        if path:
            self.save_mapping(path)

    def save_mapping(self, path: str | Path) -> None:
        try:
            write_mapping(path, self.mapping())
        except Exception as exc:
            show_error(self, TITLE, exc)

    # -- gaps ----------------------------------------------------------------------
    def gap_frames(self) -> int:
        return max_gap_frames(self.max_gap.value(), self.recording.rate_hz) if self.recording else 0

    def gap_stats(self) -> list[dict]:
        return marker_gap_stats(self.recording.positions, self.gap_frames()) if self.recording else []

    def _refresh_gaps(self) -> None:
        if self.recording is None:
            return
        self._updating = True
        for r, stats in enumerate(self.gap_stats()):
            values = (stats["absent_frames"], stats["gaps"], stats["longest_gap"], stats["filled_frames"],
                      stats["missing_frames"])
            for column, value in zip((MISSING, GAPS, LONGEST, FILLED, EXCLUDED), values, strict=True):
                self.table.item(r, column).setText(str(value))
        self._updating = False
        self.max_gap.setToolTip(f"{self.gap_frames()} frames at {self.recording.rate_hz:g} Hz: shorter gaps are "
                                "filled by a cubic spline, longer ones excluded from analysis")

    # -- import --------------------------------------------------------------------
    def start_import(self) -> None:
        """Import with the current settings, off the GUI thread; on success emit and close."""
        if self.recording is None:
            return
        path = Path(self.path_edit.text().strip())
        options = dict(format=self._format(), mapping=self.mapping(), max_gap_ms=self.max_gap.value(),
                       reference=self.references(), reference_frame=self.reference_frame.currentData(),
                       csv_layout=self.csv_layout(), up=self.up_combo.currentData())
        labels = self.labels_edit.text().strip()
        text = self.text_edit.text().strip()
        if labels:
            options["labels"] = labels
        if text:
            options["text"] = text
            options["stretch_text"] = self.stretch.isChecked()
        target = Path(self.session_edit.text().strip()) if self.save_check.isChecked() else None

        def work():
            session = import_marker_file(path, **options)
            if target is not None:
                save_session(session, target)
            return session

        self.import_button.setEnabled(False)
        self.job = run_in_background(self, f"Importing {path.name}…", work,
                                     lambda session: self._imported(session, target), title=TITLE,
                                     on_finished=lambda: self.import_button.setEnabled(self.recording is not None))

    def _imported(self, session, target) -> None:
        self.session_imported.emit(session, target)
        self.accept()

    # -- helpers -------------------------------------------------------------------
    def _format(self) -> str:
        return self.format_combo.currentData()

    def _on_format_changed(self) -> None:
        self.csv_box.setVisible(self._format() == "csv" or self.path_edit.text().lower().endswith(".csv"))

    def _browse(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, "Choose a marker file", "", MARKER_FILES)
        if path:
            self.set_path(path)

    def _browse_labels(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, "Choose phone labels", "", LABEL_FILES)
        if path:
            self.labels_edit.setText(path)
