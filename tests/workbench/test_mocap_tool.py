"""The motion-capture tool: import dialog, marker view, frame selection, multistage PCA wizard.

Driven as a user would, in a real main window on the default head (it has
the lip and jaw landmarks the PCA needs), on recordings made up by
:func:`engine.mocap.synthetic.synthesize_recording` and written as QTM TSV
and TRC files. Every number shown is checked against the engine's own call
on the same data.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtWidgets import QDockWidget, QMessageBox

import engine
from engine.mocap.articulation_file import load_articulation_file
from engine.mocap.frame_selection import select_frames
from engine.mocap.naming import write_mapping
from engine.mocap.pca import multistage_pca
from engine.mocap.sample_files import write_sample_recording
from engine.mocap.session import load_session
from workbench.background import running_jobs
from workbench.mocap.import_dialog import EXCLUDED, FILLED, GAPS, LONGEST, MISSING, POINT
from workbench.mocap.marker_overlay import MARKER_COLOR, error_colors

TEXT = "Papu ja kala. Hyvää päivää, mitä kuuluu? Öljyä ja syötävää."
FILE_LABELS = {"2.1": "FP2_1", "8.1": "fp8.1", "8.2": "MPEG4_8.2", "11.1": "FP11_1"}   # auto-suggested back


@pytest.fixture(scope="module")
def take(tmp_path_factory):
    folder = tmp_path_factory.mktemp("mocap")
    return write_sample_recording(folder / "take1", TEXT, fmt="tsv", seed=3, labels=FILE_LABELS)


@pytest.fixture
def head_window(make_window):
    return make_window(engine.default_model_path(), size=(1400, 900))


def wait_jobs(qtbot):
    qtbot.waitUntil(lambda: running_jobs() == 0, timeout=60000)
    qtbot.wait(20)          # the queued result reaches its slot


def read_into_dialog(window, qtbot, path):
    dialog = window.mocap.import_dialog_for(path)
    wait_jobs(qtbot)
    assert dialog.recording is not None
    return dialog


def table_column(dialog, column) -> list[str]:
    return [dialog.table.item(r, column).text() for r in range(dialog.table.rowCount())]


def model_state(model):
    return ([(p.name, p.kind, p.parent, p.minimum, p.maximum, p.default, p.field) for p in model.parameters],
            {n: (r.indices.copy(), r.weights.copy(), None if r.displacements is None else r.displacements.copy())
             for n, r in model.regions.items()})


def same_state(a, b) -> bool:
    if a[0] != b[0] or a[1].keys() != b[1].keys():
        return False
    for name, (i, w, d) in a[1].items():
        j, v, e = b[1][name]
        if not (np.array_equal(i, j) and np.array_equal(w, v) and (d is None) == (e is None)):
            return False
        if d is not None and not np.array_equal(d, e):
            return False
    return True


def test_import_select_pca_apply_undo(head_window, qtbot, take, tmp_path):
    window = head_window
    mocap = window.mocap
    rec = take["recording"]
    dialog = read_into_dialog(window, qtbot, take["markers"])

    # the mapping is suggested from the labels; the reference set is the engine's default
    assert [dialog.table.item(r, POINT).text() for r in range(dialog.table.rowCount())] == rec.markers
    assert dialog.references() == ["9.12", "11.1", "11.2", "11.3"]
    dialog.labels_edit.setText(str(take["labels"]))
    session_path = tmp_path / "take1.h5"
    dialog.session_edit.setText(str(session_path))
    dialog.start_import()
    wait_jobs(qtbot)
    session = mocap.state.session
    assert session is not None and session.markers == rec.markers and not dialog.isVisible()

    # the gap statistics shown equal the engine's report of the session imported
    gaps = session.report["gaps"]
    for column, key in ((GAPS, "gaps"), (FILLED, "filled_frames"), (EXCLUDED, "missing_frames")):
        assert table_column(dialog, column) == [str(gaps[m][key]) for m in session.markers]
    absent = np.isnan(rec.positions).any(axis=2).sum(axis=0)
    assert table_column(dialog, MISSING) == [str(int(a)) for a in absent]
    assert max(int(x) for x in table_column(dialog, LONGEST)) == 90      # the long gap the generator puts in
    assert sum(g["missing_frames"] for g in gaps.values()) > 0           # some gaps are excluded, some filled
    assert sum(g["filled_frames"] for g in gaps.values()) > 0

    # the session file holds what the tool shows
    again = load_session(session_path)
    np.testing.assert_array_equal(again.positions, session.positions)
    assert again.phones == session.phones and len(session.phones) > 20

    # the playhead spans the recording; the markers sit on the face and follow it
    assert window.playhead.duration == pytest.approx((session.n_frames - 1) / session.rate_hz)
    overlay = mocap.overlay
    assert overlay.visible
    model = window.document.model
    window.playhead.set_frame(0)
    frame = mocap.current_frame()
    chin = overlay.to_model(session.positions[frame, session.marker_index("2.1")])
    assert np.linalg.norm(chin - model.vertices[model.landmarks["2.1"]]) < 8.0
    window.playhead.set_frame(120)
    present = np.isfinite(session.positions[120]).all(axis=1)
    np.testing.assert_allclose(overlay.shown_points, overlay.to_model(session.positions[120][present]))

    # frames: by phone labels (the engine's select_frames), then one more range by a drag on the plot
    plot_dock = mocap.plot_dock
    plot_dock.show_coordinate("2.1", "y")
    np.testing.assert_array_equal(plot_dock.plot.values, session.positions[:, session.marker_index("2.1"), 1])
    plot_dock.selectors_edit.setText("V C")
    plot_dock.select_by_phones_from_edit()
    expected = select_frames(session.phones, session.n_frames, session.rate_hz, ["V", "C"])
    np.testing.assert_array_equal(mocap.state.selected_frames(), expected.frames)
    assert [s.label for s in mocap.state.spans] == expected.labels
    plot_dock.phone_edit.setCurrentText("a")
    plot = plot_dock.plot
    plot.resize(900, 240)
    y = plot.height() // 2
    qtbot.mousePress(plot, Qt.MouseButton.LeftButton, pos=QPoint(int(plot.x_of_frame(200)), y))
    qtbot.mouseMove(plot, QPoint(int(plot.x_of_frame(210)), y))
    qtbot.mouseRelease(plot, Qt.MouseButton.LeftButton, pos=QPoint(int(plot.x_of_frame(210)), y))
    span = mocap.state.spans[-1]
    assert span.label == "a" and abs(span.start - 200) <= 1 and abs(span.end - 210) <= 1
    frames = mocap.state.selected_frames()
    assert set(expected.frames) | set(range(span.start, span.end + 1)) == set(frames)

    # the PCA: the paper's stages, run in the background; the variances equal the engine's
    pca = mocap.pca_dock
    assert [(s.markers, s.components) for s in pca.stages()] == [(("2.1",), 1), (("8.*",), 4)]
    pca.run_pca()
    wait_jobs(qtbot)
    art = mocap.state.articulation
    reference = multistage_pca(session, frames=frames)
    np.testing.assert_allclose(art.explained_variance_ratio, reference.explained_variance_ratio, rtol=1e-12)
    np.testing.assert_allclose(pca.chart.bar_heights_percent(), 100 * reference.explained_variance_ratio)
    assert art.n_components == 5 and "stage 1 on 2.1" in pca.report.toPlainText()

    # a component shown as marker motion over the face
    pca.component_combo.setCurrentIndex(0)
    pca.amplitude.setValue(200)
    moved = art.reconstruct(np.array([2.0, 0, 0, 0, 0]))
    np.testing.assert_allclose(overlay.shown_points, overlay.to_model(moved))
    pca.stop_preview()
    path = tmp_path / "articulation.h5"
    pca.save_articulation(path)
    np.testing.assert_allclose(load_articulation_file(path).components, art.components)

    # apply: five translation parameters on jaw and lips, one undo step
    before = model_state(model)
    steps = window.document.undo_stack.count()
    pca.apply_to_model()
    wait_jobs(qtbot)
    names = [f"pca{k}" for k in range(1, 6)]
    assert [p.name for p in model.parameters][-5:] == names
    assert window.document.undo_stack.count() == steps + 1
    for name in names:
        parameter, region = model.parameters[name], model.regions[name]
        assert parameter.kind == "translation" and parameter.field
        weights = dict(zip(region.indices.tolist(), region.weights.tolist(), strict=True))
        for marker in ("2.1", "8.1", "8.2", "8.3", "8.4"):
            assert weights.get(model.landmarks[marker]) == 1.0
        assert model.landmarks["3.7"] not in weights          # an eye corner is outside the region
    errors = pca.shown_errors()
    assert set(errors) == set(art.markers)
    assert all(0 < e < 2.0 for e in errors.values()), errors
    np.testing.assert_allclose(list(errors.values()), pca.held_out.per_marker_rms_mm, atol=5e-4)
    window.playhead.set_frame(30)
    present = [m for m in session.markers if np.isfinite(session.positions[30, session.marker_index(m)]).all()]
    expected_colors = error_colors([errors.get(m, np.nan) for m in present])
    np.testing.assert_array_equal(overlay.shown_colors, expected_colors)

    window.undo()
    assert same_state(model_state(model), before)
    window.redo()
    assert [p.name for p in model.parameters][-5:] == names
    window.undo()
    assert same_state(model_state(model), before)


def test_trc_with_a_mapping_file_and_festival_labels(head_window, qtbot, tmp_path):
    window = head_window
    labels = {"2.1": "Chin", "8.3": "LipCornerL", "8.4": "LipCornerR", "9.12": "NoseBridge"}
    files = write_sample_recording(tmp_path / "take2", "Papu ja kala.", fmt="trc", seed=5, labels=labels)
    rec = files["recording"]
    dialog = read_into_dialog(window, qtbot, files["markers"])
    assert "Chin" in dialog.labels() and dialog.names()[dialog.labels().index("Chin")] == "Chin"
    mapping = tmp_path / "lab.map"
    write_mapping(mapping, {label: marker for marker, label in labels.items()} | {"3.7": "-"})
    dialog.load_mapping(mapping)
    assert dialog.names() == [m if m != "3.7" else None for m in rec.markers]
    assert dialog.references() == ["9.12", "11.1", "11.2", "11.3"]
    dialog.save_mapping(tmp_path / "saved.map")
    dialog.load_mapping(tmp_path / "saved.map")
    assert dialog.names() == [m if m != "3.7" else None for m in rec.markers]
    dialog.save_check.setChecked(False)
    dialog.start_import()
    wait_jobs(qtbot)
    session = window.mocap.state.session
    assert session.markers == [m for m in rec.markers if m != "3.7"] and session.phones == []

    window.mocap.plot_dock.align_with_festival("Papu ja kala.", stretch=True)
    wait_jobs(qtbot)
    phones = session.phones
    assert phones and phones[-1][1] == pytest.approx(session.n_frames * 1000 / session.rate_hz)
    assert window.mocap.plot_dock.plot.phones == phones


def test_bad_files_end_in_a_dialog_and_keep_the_work(head_window, qtbot, take, tmp_path, monkeypatch):
    shown = []
    monkeypatch.setattr(QMessageBox, "warning",
                        staticmethod(lambda parent, title, text, *a, **k: shown.append(text)))
    window = head_window
    dialog = read_into_dialog(window, qtbot, take["markers"])
    good = dialog.recording
    lines = Path(take["markers"]).read_text().splitlines()
    bad = tmp_path / "cut.tsv"
    bad.write_text("\n".join(lines[:40]) + "\n")
    dialog.set_path(bad)
    wait_jobs(qtbot)
    assert len(shown) == 1 and "cut.tsv:" in shown[0] and "truncated" in shown[0]
    assert dialog.isVisible() and dialog.recording is None            # nothing of take1 stays on show
    assert dialog.table.rowCount() == 0 and "cut.tsv:" in dialog.summary.text()
    assert not dialog.import_button.isEnabled()
    dialog.start_import()                                             # nothing to import: nothing happens
    wait_jobs(qtbot)
    assert window.mocap.state.session is None and len(shown) == 1

    dialog.set_path(take["markers"])                                  # a file that reads: Import is back
    wait_jobs(qtbot)
    assert dialog.recording is not good and dialog.recording.labels == good.labels
    assert dialog.table.rowCount() == len(good.labels) and dialog.import_button.isEnabled()
    dialog.table.item(1, POINT).setText("2.1")           # two markers named 2.1: the engine refuses
    dialog.start_import()
    wait_jobs(qtbot)
    assert len(shown) == 2 and "2.1" in shown[1] and "both" in shown[1]
    assert dialog.isVisible() and window.mocap.state.session is None and dialog.import_button.isEnabled()

    dialog.labels_edit.setText(str(tmp_path / "missing.lab"))
    dialog.table.item(1, POINT).setText("8.1")
    dialog.start_import()
    wait_jobs(qtbot)
    assert len(shown) == 3 and "missing.lab" in shown[2]
    assert window.mocap.state.session is None

    dialog.set_path(take["markers"])                  # Cancel while the file is read: no table of another file
    dialog.job.cancel()
    wait_jobs(qtbot)
    assert dialog.recording is None and dialog.table.rowCount() == 0 and not dialog.import_button.isEnabled()
    assert "cancelled" in dialog.summary.text() and len(shown) == 3
    window.mocap.import_dialog.close()


NOD = '<commands>\n  <HeadNod at="200" amplitude="60" count="2"/>\n</commands>\n'


def import_session(window, qtbot, take):
    """Read ``take`` in the import dialog and import it (no session file), as a user would."""
    dialog = read_into_dialog(window, qtbot, take["markers"])
    dialog.labels_edit.setText(str(take["labels"]))
    dialog.save_check.setChecked(False)
    dialog.start_import()
    wait_jobs(qtbot)
    return window.mocap.state.session


def markers_on_screen(window) -> bool:
    """The marker spheres are drawn in the viewport, and pixels of their colour are in its picture."""
    overlay = window.mocap.overlay
    drawn = overlay.visible
    window.viewport.render_now()
    image = window.viewport.plotter.screenshot(return_img=True)
    yellow = np.all(np.abs(image[..., :3].astype(int) - MARKER_COLOR) < 40, axis=-1).sum()
    assert drawn == (yellow > 20), (drawn, yellow)      # what the overlay says is what the user sees
    return drawn


def test_the_markers_show_only_while_their_recording_is_on_the_player(head_window, qtbot, take, tmp_path):
    window = head_window
    mocap, player, playhead = window.mocap, window.player, window.playhead
    session = import_session(window, qtbot, take)
    recording = mocap.playback.timeline
    assert markers_on_screen(window) and player.timeline is recording
    assert playhead.fps == session.rate_hz and "take1" in player.title and len(player.phones) == len(session.phones)

    # Space plays the recording: the markers move on with the playhead in real time
    view = window.timeline_dock.track_view
    window.activateWindow()
    view.setFocus()
    qtbot.waitUntil(lambda: window.isActiveWindow() and view.hasFocus())
    qtbot.keyClick(view, Qt.Key.Key_Space)
    qtbot.waitUntil(lambda: playhead.frame >= 30, timeout=10000)
    player.pause()
    present = np.isfinite(session.positions[playhead.frame]).all(axis=1)
    np.testing.assert_allclose(mocap.overlay.shown_points,
                               mocap.overlay.to_model(session.positions[playhead.frame][present]))

    # the library editor's preview takes the player: the markers go, and stay gone while it plays and is scrubbed
    window.library_editor_dock.show()
    editor = window.library_editor
    assert editor.open_file(editor.command_list.commands["HeadNod"])
    qtbot.mouseClick(editor.preview_button, Qt.MouseButton.LeftButton)
    assert player.is_playing and "library editor preview" in player.title
    qtbot.wait(150)
    assert not markers_on_screen(window)
    player.pause()
    playhead.set_time(0.4)
    assert not markers_on_screen(window)
    assert mocap.plot_dock.plot.playhead_s is None         # nor does the marker plot's line follow the preview

    # Motion capture ▸ Show the recording: back, on the recording's clock
    window.actions_by_id["mocap.show"].trigger()
    assert player.timeline is recording and markers_on_screen(window)
    playhead.set_time(0.5)
    assert mocap.plot_dock.plot.playhead_s == pytest.approx(0.5)
    assert playhead.duration == pytest.approx((session.n_frames - 1) / session.rate_hz)

    # the gallery's preview; a click on the marker plot brings the recording back at the frame clicked
    assert window.expression_gallery.preview("Happy") is not None
    assert player.is_playing and not markers_on_screen(window)
    plot = mocap.plot_dock.plot
    window.mocap.plot_dock.show()
    plot.resize(900, 240)
    qtbot.mouseClick(plot, Qt.MouseButton.LeftButton, pos=QPoint(int(plot.x_of_frame(150)), plot.height() // 2))
    assert player.timeline is recording and abs(playhead.frame - 150) <= 1 and markers_on_screen(window)
    present = np.isfinite(session.positions[playhead.frame]).all(axis=1)
    np.testing.assert_allclose(mocap.overlay.shown_points,
                               mocap.overlay.to_model(session.positions[playhead.frame][present]))

    # an animation file opened; a PCA run ending does not take the player back, a component shown does
    nod = tmp_path / "nod.xml"
    nod.write_text(NOD)
    assert window.timeline_dock.open_animation(nod)
    assert not markers_on_screen(window)
    pca = mocap.pca_dock
    mocap.plot_dock.select_by_phones(["V", "C"])
    pca.run_pca()
    wait_jobs(qtbot)
    assert player.timeline is not recording and not markers_on_screen(window)
    pca.component_combo.setCurrentIndex(1)
    pca.amplitude.setValue(150)
    assert player.timeline is recording and markers_on_screen(window)

    # a component animating stops when the gallery takes the player (its timer would take it back)
    pca.animate_button.setChecked(True)
    qtbot.wait(100)
    window.expression_gallery.preview("Sad")
    qtbot.wait(150)
    assert not pca.animate_button.isChecked() and "Sad" in player.title and not markers_on_screen(window)
    qtbot.mouseClick(pca.show_session_button, Qt.MouseButton.LeftButton)        # "Show the session"
    assert player.timeline is recording and markers_on_screen(window)
    np.testing.assert_allclose(mocap.overlay.shown_points, mocap.overlay.to_model(session.positions[0][
        np.isfinite(session.positions[0]).all(axis=1)]))


@pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed")
def test_speech_puts_the_markers_away_until_the_recording_is_shown(head_window, qtbot, take):
    window = head_window
    import_session(window, qtbot, take)
    panel = window.script_panel
    panel.editor.setPlainText("Hyvää huomenta.")
    with qtbot.waitSignal(window.player.loaded, timeout=60000):
        panel.say()
    assert window.player.is_playing and not markers_on_screen(window)
    qtbot.wait(200)
    assert not markers_on_screen(window)
    window.actions_by_id["mocap.show"].trigger()
    assert markers_on_screen(window) and not window.player.is_playing


SCREENSHOTS = os.environ.get("AP_SCREENSHOT_DIR")


def test_screenshots(head_window, qtbot, take, tmp_path):
    """docs/images/workbench-mocap-*.png (AP_SCREENSHOT_DIR=docs/images to refresh them)."""
    folder = Path(SCREENSHOTS or tmp_path)
    window = head_window
    dialog = read_into_dialog(window, qtbot, take["markers"])
    dialog.labels_edit.setText(str(take["labels"]))
    dialog.session_edit.setText(str(tmp_path / "take1.h5"))
    qtbot.wait(50)
    assert dialog.grab().save(str(folder / "workbench-mocap-import.png"))
    dialog.start_import()
    wait_jobs(qtbot)
    mocap = window.mocap
    for dock in window.findChildren(QDockWidget):      # other tools' docks: room for the face
        if dock.objectName() not in ("dock:mocap-plot", "dock:mocap-pca", "dock:parameters"):
            dock.hide()
    window.resizeDocks([mocap.plot_dock], [250], Qt.Orientation.Vertical)
    window.resizeDocks([window.parameter_dock], [820], Qt.Orientation.Horizontal)
    mocap.plot_dock.select_by_phones(["V"])
    window.playhead.set_frame(150)
    window.viewport.render_now()
    qtbot.wait(50)
    assert window.grab().save(str(folder / "workbench-mocap-markers.png"))
    mocap.pca_dock.run_pca()
    wait_jobs(qtbot)
    mocap.pca_dock.show_component(0, 2.0)
    qtbot.wait(50)
    assert window.grab().save(str(folder / "workbench-mocap-pca.png"))
    mocap.pca_dock.apply_to_model()
    wait_jobs(qtbot)
    window.viewport.render_now()
    qtbot.wait(50)
    assert window.grab().save(str(folder / "workbench-mocap-apply.png"))


def test_after_apply_the_recording_plays_through_the_face(head_window, qtbot, take):
    """Issue 22 §1: after Apply, the timeline plays the recording through the model, markers and face together."""
    from engine.mocap.animate import session_component_values

    window = head_window
    mocap, player, playhead, document = window.mocap, window.player, window.playhead, window.document
    session = import_session(window, qtbot, take)
    assert player.timeline.driven == ()                       # before Apply only the markers move
    pca = mocap.pca_dock
    pca.run_pca()
    wait_jobs(qtbot)
    pca.apply_to_model()
    wait_jobs(qtbot)
    names = [f"pca{k}" for k in range(1, 6)]
    timeline = player.timeline
    assert timeline is mocap.playback.timeline and list(timeline.driven) == names
    _, expected, _ = session_component_values(document.model, pca.applied, session)

    # the frame where the lower lip is farthest from the face at rest (in the alignment Apply found)
    lip = session.marker_index("8.2")
    lower_lip = document.model.landmarks["8.2"]
    in_model = pca.applied.to_model(session.positions[:, lip])
    frame = int(np.nanargmax(np.linalg.norm(in_model - document.model.vertices[lower_lip], axis=1)))
    playhead.set_frame(frame)
    got = [document.values[name] for name in names]
    low = [document.model.parameters[n].minimum for n in names]
    high = [document.model.parameters[n].maximum for n in names]
    np.testing.assert_allclose(got, np.clip(expected[frame], low, high), atol=1e-9)
    # the face follows the recording there: its lower lip is by the marker, not where it rests
    moved = np.linalg.norm(document.vertices()[lower_lip] - in_model[frame])
    rest = np.linalg.norm(document.model.vertices[lower_lip] - in_model[frame])
    assert rest > 5.0 and moved < 0.2 * rest, (moved, rest)
    assert mocap.overlay.visible                              # and the markers are drawn with it

    window.undo()                                             # Apply undone: the markers play on alone
    playhead.set_frame(60)
    assert all(name not in document.model.parameters.names for name in names)
