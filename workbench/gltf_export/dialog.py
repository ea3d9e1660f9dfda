"""File → Export → glTF…: the choices of ``artificial-person export-gltf``, in a dialog.

:class:`GltfExportDialog` only gathers :class:`GltfExportChoices`, one
widget per option of the command line: the parameters exported as morph
targets and the value each shows at weight 1 (``--parameters``,
``--value``), the ARKit-52 targets (``--arkit``/``--no-arkit``; on by
default for the shipped head only), the poses file and its pose groups
(``--poses``, ``--pose-group``), the skeleton (``--skeleton``), the
targets' normals (``--no-target-normals``) and the file, ``.glb`` or
``.gltf``. Which targets those choices make, and whether they are allowed,
is decided by the engine (:func:`engine.outputs.gltf_export.export_targets`),
which :class:`workbench.gltf_export.exporter.GltfExporter` calls off the GUI thread.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import (
    QAbstractItemView,
    QCheckBox,
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
    QListWidget,
    QListWidgetItem,
    QPushButton,
    QTreeWidget,
    QTreeWidgetItem,
    QVBoxLayout,
    QWidget,
)

import engine
from engine.outputs.gltf_export import is_shipped_head, pose_group_names, skeleton_parameters, target_value

PREFIX = "gltf_export/"
FILE_FILTER = "glTF binary (*.glb);;glTF JSON with its buffer beside it as .bin (*.gltf)"
POSES_FILTER = "Poses (*.h5);;All files (*)"
ARKIT = "arkit"
NAME, VALUE, KIND = range(3)                # the parameter table's columns
Button = QDialogButtonBox.StandardButton


@dataclass
class GltfExportChoices:
    """One export's options, as ``export-gltf`` takes them (``names=None``: every parameter that can be a target)."""

    path: Path
    names: list[str] | None = None
    values: dict[str, float] = field(default_factory=dict)
    arkit: bool = False
    poses: Path | None = None
    pose_groups: list[str] = field(default_factory=list)
    skeleton: bool = False
    target_normals: bool = True


class GltfExportDialog(QDialog):
    """The options of one glTF export of ``model`` (loaded from ``model_file``, or untitled); :meth:`choices`."""

    def __init__(self, model: engine.Model, model_file: Path | None, path: Path, parent: QWidget | None = None):
        super().__init__(parent)
        self.setWindowTitle("Export glTF")
        self.setObjectName("gltf_export_dialog")
        store = QSettings()
        self._model = model
        try:
            self._joints = set(skeleton_parameters(model))
        except engine.UserError:          # the export says why, if the skeleton is asked for
            self._joints = set()

        self.file_edit = QLineEdit(str(path))
        self.file_edit.setObjectName("file")
        self.file_edit.setMinimumWidth(360)
        browse_file = QPushButton("&Browse…")
        browse_file.clicked.connect(self._browse_file)
        file_row = QHBoxLayout()
        file_row.addWidget(self.file_edit, 1)
        file_row.addWidget(browse_file)
        file_form = QFormLayout()
        file_form.addRow(_buddy_label("&File:", self.file_edit), file_row)
        file_form.addRow("", _note(".glb: one binary file; .gltf: JSON with its buffer beside it as .bin"))

        self.parameter_table = self._make_parameter_table(model)
        every, none = QPushButton("&All"), QPushButton("N&one")
        every.clicked.connect(lambda: self.check_parameters(self._items))
        none.clicked.connect(lambda: self.check_parameters([]))
        select_row = QHBoxLayout()
        select_row.addWidget(every)
        select_row.addWidget(none)
        select_row.addStretch(1)
        parameters = QGroupBox("&Parameters as morph targets")
        parameters_layout = QVBoxLayout(parameters)
        parameters_layout.addWidget(self.parameter_table, 1)
        parameters_layout.addLayout(select_row)
        parameters_layout.addWidget(_note("A target shows the parameter at the value given, at weight 1; "
                                          "rotations are straight-line (chord) targets."))

        self.skeleton_box = QCheckBox("&Skeleton: the rigid parameters (head, jaw, eyes) as joints")
        self.skeleton_box.setToolTip("exact at every value, and the leaves ride on the joints as here; "
                                     "those parameters are then not morph targets")
        self.skeleton_box.setChecked(store.value(PREFIX + "skeleton", False, type=bool))
        self.skeleton_box.toggled.connect(self._show_joints)
        self.normals_box = QCheckBox("Target &normals (about twice the size; better shading when morphing)")
        self.normals_box.setChecked(store.value(PREFIX + "target_normals", True, type=bool))
        self.arkit_box = QCheckBox("A&RKit-52 face targets (jawOpen, mouthSmileLeft, …)")
        self.arkit_box.setToolTip("from the poses file; the shipped poses fit the shipped head only")
        self.arkit_box.setChecked(is_shipped_head(model_file))
        self.poses_edit = QLineEdit()
        self.poses_edit.setObjectName("poses")
        self.poses_edit.setPlaceholderText("the shipped head's reference poses")
        self.poses_edit.editingFinished.connect(self._refresh_groups)
        browse_poses = QPushButton("Bro&wse…")
        browse_poses.clicked.connect(self._browse_poses)
        poses_row = QHBoxLayout()
        poses_row.addWidget(self.poses_edit, 1)
        poses_row.addWidget(browse_poses)
        self.group_list = QListWidget()
        self.group_list.setObjectName("pose_groups")
        self.group_list.setMaximumHeight(90)
        self.poses_note = _note("")
        poses = QGroupBox("Poses (displacement fields)")
        poses_form = QFormLayout(poses)
        poses_form.addRow(self.arkit_box)
        poses_form.addRow(_buddy_label("Poses fi&le:", self.poses_edit), poses_row)
        poses_form.addRow(_buddy_label("Pose &groups:", self.group_list), self.group_list)
        poses_form.addRow(self.poses_note)
        options = QVBoxLayout()
        options.addWidget(self.skeleton_box)
        options.addWidget(self.normals_box)
        options.addWidget(poses)
        options.addStretch(1)

        columns = QHBoxLayout()
        columns.addWidget(parameters, 3)
        columns.addLayout(options, 2)
        self.buttons = QDialogButtonBox(Button.Ok | Button.Cancel)
        self.buttons.button(Button.Ok).setText("&Export")
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        self.file_edit.textChanged.connect(self._update_button)
        layout = QVBoxLayout(self)
        layout.addLayout(file_form)
        layout.addLayout(columns, 1)
        layout.addWidget(self.buttons)
        self._refresh_groups()
        self._show_joints(self.skeleton_box.isChecked())
        self._update_button()
        self.resize(960, 560)             # fits a 1366×768 screen; the parameter table scrolls

    # -- what the user chose ----------------------------------------------------------
    def choices(self) -> GltfExportChoices:
        """The options as chosen; a file name without an extension gets ``.glb``."""
        path = Path(self.file_edit.text().strip()).expanduser()
        if not path.suffix:
            path = path.with_suffix(".glb")
        allowed = [name for name in self._items if not self._is_joint_now(name)]
        checked = [name for name in allowed if self._items[name].checkState(NAME) == Qt.CheckState.Checked]
        values = {name: self._value_boxes[name].value() for name in checked
                  if self._value_boxes[name].value() != self._initial_values[name]}
        poses = self.poses_edit.text().strip()
        groups = [self.group_list.item(i).text() for i in range(self.group_list.count())
                  if self.group_list.item(i).checkState() == Qt.CheckState.Checked]
        return GltfExportChoices(path, None if checked == allowed else checked, values,
                                 arkit=self.arkit_box.isChecked(), poses=Path(poses).expanduser() if poses else None,
                                 pose_groups=groups, skeleton=self.skeleton_box.isChecked(),
                                 target_normals=self.normals_box.isChecked())

    def check_parameters(self, names) -> None:
        """Tick exactly ``names`` in the parameter table."""
        wanted = set(names)
        for name, item in self._items.items():
            item.setCheckState(NAME, Qt.CheckState.Checked if name in wanted else Qt.CheckState.Unchecked)

    def set_value(self, name: str, value: float) -> None:
        """The value ``name``'s target shows at weight 1."""
        self._value_boxes[name].setValue(value)

    def check_pose_groups(self, names) -> None:
        wanted = set(names)
        for i in range(self.group_list.count()):
            item = self.group_list.item(i)
            item.setCheckState(Qt.CheckState.Checked if item.text() in wanted else Qt.CheckState.Unchecked)

    def accept(self) -> None:
        store = QSettings()
        store.setValue(PREFIX + "skeleton", self.skeleton_box.isChecked())
        store.setValue(PREFIX + "target_normals", self.normals_box.isChecked())
        super().accept()

    # -- the parameter table ------------------------------------------------------------
    def _make_parameter_table(self, model: engine.Model) -> QTreeWidget:
        table = QTreeWidget()
        table.setObjectName("parameters")
        table.setColumnCount(3)
        table.setHeaderLabels(["Parameter", "Value at weight 1", "Exported as"])
        table.setRootIsDecorated(False)      # flat: a disabled joint must not disable its children
        table.setSelectionMode(QAbstractItemView.SelectionMode.NoSelection)
        table.header().setSectionResizeMode(NAME, QHeaderView.ResizeMode.Stretch)
        table.header().setStretchLastSection(False)
        self._items: dict[str, QTreeWidgetItem] = {}
        self._value_boxes: dict[str, QDoubleSpinBox] = {}
        self._initial_values: dict[str, float] = {}
        for name, depth in model.parameters.depth_first():
            parameter = model.parameters[name]
            item = QTreeWidgetItem(table, ["\u2003" * depth + name, "", ""])
            item.setFlags(item.flags() | Qt.ItemFlag.ItemIsUserCheckable)
            item.setCheckState(NAME, Qt.CheckState.Checked)
            box = QDoubleSpinBox()
            box.setDecimals(3)
            box.setRange(parameter.minimum, parameter.maximum)
            box.setSingleStep(0.05)
            box.setValue(target_value(parameter))
            box.setToolTip(f"{parameter.kind}, range {parameter.minimum:g} … {parameter.maximum:g}, "
                           f"rest {parameter.default:g}")
            table.setItemWidget(item, VALUE, box)
            self._items[name], self._value_boxes[name] = item, box
            self._initial_values[name] = box.value()
        table.header().setSectionResizeMode(VALUE, QHeaderView.ResizeMode.ResizeToContents)
        table.header().setSectionResizeMode(KIND, QHeaderView.ResizeMode.ResizeToContents)
        table.setMinimumSize(460, 240)
        return table

    def _is_joint_now(self, name: str) -> bool:
        return self.skeleton_box.isChecked() and name in self._joints

    def _show_joints(self, _skeleton: bool) -> None:
        for name, item in self._items.items():
            joint = self._is_joint_now(name)
            item.setDisabled(joint)
            self._value_boxes[name].setEnabled(not joint)
            item.setText(KIND, "joint" if joint else "morph target")

    # -- files -------------------------------------------------------------------------------
    def _update_button(self) -> None:
        self.buttons.button(Button.Ok).setEnabled(bool(self.file_edit.text().strip()))

    def _browse_file(self) -> None:
        path, chosen = QFileDialog.getSaveFileName(self, "Export glTF", self.file_edit.text(), FILE_FILTER)
        if path:
            if not Path(path).suffix:
                path += ".gltf" if "gltf)" in chosen else ".glb"
            self.file_edit.setText(path)

    def _browse_poses(self) -> None:
        start = self.poses_edit.text() or str(Path(self.file_edit.text()).parent)
        path, _ = QFileDialog.getOpenFileName(self, "Poses file", start, POSES_FILTER)
        if path:
            self.poses_edit.setText(path)
            self._refresh_groups()

    def _refresh_groups(self) -> None:
        """List the poses file's groups (but ``arkit``, which has its own box), keeping those ticked."""
        ticked = {self.group_list.item(i).text() for i in range(self.group_list.count())
                  if self.group_list.item(i).checkState() == Qt.CheckState.Checked}
        self.group_list.clear()
        poses = self.poses_edit.text().strip()
        try:
            groups = pose_group_names(Path(poses).expanduser() if poses else None)
        except engine.UserError as exc:
            self.poses_note.setText(str(exc))
            return
        self.poses_note.setText("" if ARKIT in groups else "This file has no ARKit-52 poses (group 'arkit').")
        for group in groups:
            if group != ARKIT:
                item = QListWidgetItem(group, self.group_list)
                item.setFlags(item.flags() | Qt.ItemFlag.ItemIsUserCheckable)
                item.setCheckState(Qt.CheckState.Checked if group in ticked else Qt.CheckState.Unchecked)


def _buddy_label(text: str, buddy: QWidget) -> QLabel:
    """A form label whose ``&`` mnemonic focuses ``buddy`` (without one, QLabel shows the ``&``)."""
    label = QLabel(text)
    label.setBuddy(buddy)
    return label


def _note(text: str) -> QLabel:
    label = QLabel(text)
    label.setWordWrap(True)
    label.setStyleSheet("color: palette(mid);")
    return label
