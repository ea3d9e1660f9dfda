"""File → Export → glTF… on the real window: the dialog, the export off the GUI thread, errors, cancel."""

from __future__ import annotations

import threading

import numpy as np
import pytest
from PySide6.QtWidgets import QDialogButtonBox, QMessageBox, QPushButton

import engine
import workbench.gltf_export.exporter as gltf_exporter
from engine.formats.gltf_read import METRES_PER_MM, read_gltf
from engine.paths import default_model_path

Button = QMessageBox.StandardButton


def open_dialog(window):
    window.actions_by_id["file.export_gltf"].trigger()
    dialog = window.files.gltf_dialog
    assert dialog is not None and dialog.isVisible()
    return dialog


def click_export(dialog) -> None:
    dialog.buttons.button(QDialogButtonBox.StandardButton.Ok).click()


def wait_for_export(window, qtbot, timeout=30000) -> None:
    qtbot.waitUntil(lambda: not window.files.gltf_exporter.busy, timeout=timeout)


@pytest.fixture
def warnings(monkeypatch):
    """QMessageBox.warning records its message instead of blocking the test."""
    shown: list[tuple[str, str]] = []
    monkeypatch.setattr(QMessageBox, "warning",
                        staticmethod(lambda parent, title, text, *a, **k: shown.append((title, text)) or Button.Ok))
    return shown


def test_file_export_submenu_holds_configuration_and_gltf(window):
    export_menu = window.menus["&File/&Export"]
    assert [a.text() for a in export_menu.actions()] == ["&Configuration…", "&glTF…"]
    assert export_menu.menuAction() in window.menus["&File"].actions()


def test_export_writes_the_chosen_targets_and_skeleton_off_the_gui_thread(window, qtbot, tmp_path):
    dialog = open_dialog(window)
    assert not dialog.arkit_box.isChecked()                   # not the shipped head: no ARKit by default
    dialog.file_edit.setText(str(tmp_path / "synthetic.gltf"))
    dialog.skeleton_box.setChecked(True)                      # head_turn becomes a joint
    assert dialog.parameter_table.topLevelItem(0).text(2) == "joint"
    assert dialog.parameter_table.topLevelItem(0).isDisabled()
    dialog.check_parameters(["head_turn", "brow_raise"])      # a joint ticked under a skeleton is left out
    dialog.set_value("brow_raise", 0.5)
    dialog.normals_box.setChecked(False)

    click_export(dialog)
    exporter = window.files.gltf_exporter
    assert exporter.busy and not (tmp_path / "synthetic.gltf").exists()   # the window runs on meanwhile
    assert "Exporting synthetic.gltf" in window.statusBar().currentMessage()
    wait_for_export(window, qtbot)

    mesh = read_gltf(tmp_path / "synthetic.gltf")
    assert (tmp_path / "synthetic.bin").is_file()
    assert mesh.target_names == ["brow_raise"] and mesh.skin is not None and "head_turn" in mesh.skin.names
    assert mesh.document["meshes"][0]["extras"]["targets"][0]["value"] == 0.5
    assert all("NORMAL" not in target for p in mesh.primitives for target in p.targets)
    model = window.document.model
    pose = mesh.model_positions(model.n_vertices, {"brow_raise": 1.0}, joints={"head_turn": 0.4})
    np.testing.assert_allclose(pose, model.deform({"brow_raise": 0.5, "head_turn": 0.4}) * METRES_PER_MM,
                               atol=1e-6)
    message = window.statusBar().currentMessage()
    assert message.startswith(f"Exported {tmp_path / 'synthetic.gltf'}: ")
    assert f"{mesh.n_points} vertices, 1 morph targets, 2 joints, " in message and message.endswith(" kB")


def test_every_parameter_by_default_as_the_command_line_does(window, qtbot, tmp_path):
    dialog = open_dialog(window)
    assert dialog.choices().names is None and dialog.choices().values == {}
    dialog.file_edit.setText(str(tmp_path / "plain"))         # no extension: .glb
    click_export(dialog)
    wait_for_export(window, qtbot)
    assert read_gltf(tmp_path / "plain.glb").target_names == window.document.model.parameters.names


def test_arkit_targets_on_another_model_without_poses_show_the_engines_message(window, qtbot, tmp_path, warnings):
    dialog = open_dialog(window)
    dialog.file_edit.setText(str(tmp_path / "arkit.glb"))
    dialog.arkit_box.setChecked(True)
    click_export(dialog)
    wait_for_export(window, qtbot)
    assert warnings == [("Export glTF", "the shipped poses fit the shipped head only: give a poses file made "
                                        "for this model (--poses POSES.h5)")]
    assert not list(tmp_path.iterdir())                       # nothing written
    assert "nothing was written" in window.statusBar().currentMessage()


def test_a_bad_value_is_reported_before_anything_is_written(window, qtbot, tmp_path, warnings):
    dialog = open_dialog(window)
    dialog.file_edit.setText(str(tmp_path / "x.glb"))
    dialog.check_parameters(["jaw_open"])
    dialog.set_value("jaw_open", 0.0)                         # its default: the target would move nothing
    click_export(dialog)
    wait_for_export(window, qtbot)
    assert len(warnings) == 1 and "parameter 'jaw_open': its target value 0 is its default" in warnings[0][1]
    assert not (tmp_path / "x.glb").exists()


def test_an_existing_file_is_replaced_only_when_the_user_says_so(window, qtbot, tmp_path, monkeypatch):
    existing = tmp_path / "head.glb"
    existing.write_bytes(b"mine")
    asked = []
    monkeypatch.setattr(QMessageBox, "question", staticmethod(lambda *a, **k: asked.append(a[2]) or Button.No))
    dialog = open_dialog(window)
    dialog.file_edit.setText(str(existing))
    click_export(dialog)
    assert asked == [f"Replace head.glb in {tmp_path}?"] and not window.files.gltf_exporter.busy
    assert existing.read_bytes() == b"mine"


def test_cancel_before_the_file_is_written_leaves_none_and_the_window_stays_live(window, qtbot, tmp_path,
                                                                                 monkeypatch):
    release = threading.Event()
    real = gltf_exporter.export_targets

    def slow_targets(*args, **kwargs):
        release.wait(20)
        return real(*args, **kwargs)

    monkeypatch.setattr(gltf_exporter, "export_targets", slow_targets)
    outcomes = []
    dialog = open_dialog(window)
    dialog.file_edit.setText(str(tmp_path / "cancelled.glb"))
    click_export(dialog)
    exporter = window.files.gltf_exporter
    exporter.ended.connect(outcomes.append)
    progress = exporter.job.progress_dialog
    qtbot.waitUntil(progress.isVisible, timeout=3000)          # the progress shows while the work runs
    window.document.set_value("jaw_open", 0.5)                 # and the window answers meanwhile
    assert window.document.value("jaw_open") == 0.5
    progress.findChild(QPushButton).click()                   # Cancel
    release.set()
    wait_for_export(window, qtbot)
    assert outcomes == ["cancelled"] and not (tmp_path / "cancelled.glb").exists()
    assert window.statusBar().currentMessage() == "glTF export cancelled: nothing was written"


@pytest.mark.slow
def test_the_shipped_head_exports_its_arkit_targets_by_default(make_window, qtbot, tmp_path):
    if not default_model_path().exists():
        pytest.skip("the default head is not built")
    window = make_window(default_model_path())
    dialog = open_dialog(window)
    assert dialog.arkit_box.isChecked()
    assert [dialog.group_list.item(i).text() for i in range(dialog.group_list.count())] == ["expression_units"]
    dialog.file_edit.setText(str(tmp_path / "head.glb"))
    dialog.check_parameters(["jaw_open"])
    dialog.normals_box.setChecked(False)
    click_export(dialog)
    wait_for_export(window, qtbot)
    mesh = read_gltf(tmp_path / "head.glb")
    assert mesh.target_names[0] == "jaw_open" and len(mesh.target_names) == 1 + 52
    assert {"jawOpen", "mouthSmileLeft", "eyeBlinkRight"} <= set(mesh.target_names)
    assert "53 morph targets" in window.statusBar().currentMessage()
    assert isinstance(window.document.model, engine.Model)
