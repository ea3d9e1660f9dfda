"""Run by ``test_laptop_session.py``: a whole working session on a laptop's screen, without moving a dock.

``python -m tests.workbench.laptop_session FOLDER`` runs on an Xvfb screen
of the size under test (1366×768), opens the default head with fresh
settings, and does what the workbench is for, as a user does it: the task
layouts from the toolbar switcher, the tools' own commands (Ctrl+L, Ctrl+G),
and mouse clicks on the buttons. Before every click the widget clicked must
be on show in full, inside the window, inside the screen: nothing is dragged,
floated, resized or scrolled to get there.

1. Painting: select ``jaw_open``, paint mode, hold it open (Live preview),
   paint a stroke across the chin: the weights change and the held pose moves.
2. Motion capture: import a recording with its phone labels, select frames
   by phones, run the multistage PCA, apply it to the model.
3. Library: open ``HeadNod.lib`` in the library editor and preview it.
4. The expression gallery: play an expression.
5. Speech: say a sentence with Festival and export it as MP4.

Each step writes a picture (``FOLDER/<step>.png``) and the script ends by
writing ``FOLDER/report.json``: the steps done and what each one checked.
Any failed check raises, which ends the process with a non-zero status.
"""

from __future__ import annotations

import json
import sys
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
from PySide6.QtCore import QPoint, QSettings, Qt, QTimer
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QAbstractButton, QApplication, QDockWidget, QWidget

import engine
from engine.mocap.sample_files import write_sample_recording
from engine.outputs.video_probe import probe
from workbench.background import running_jobs
from workbench.document.model_document import ModelDocument
from workbench.window.main_window import MainWindow

ROOT = Path(__file__).resolve().parents[2]
SENTENCE = "Hyvää huomenta! Mitä kuuluu?"


class SessionFailed(AssertionError):
    """A check of the session failed."""


def check(condition: bool, what: str) -> None:
    if not condition:
        raise SessionFailed(what)


def wait(seconds: float) -> None:
    QTest.qWait(round(seconds * 1000))


def wait_for(condition: Callable[[], bool], what: str, seconds: float = 120.0) -> None:
    end = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > end:
            raise SessionFailed(f"timed out waiting for {what}")
        wait(0.05)


def on_show(window: QWidget, widget: QWidget, what: str) -> None:
    """``widget`` is visible in full, inside the window and the screen (no part scrolled or clipped away)."""
    check(widget.isVisible(), f"{what} is not visible")
    seen = widget.visibleRegion().boundingRect()
    check(seen.size() == widget.rect().size(), f"{what} is partly hidden: {seen.width()}×{seen.height()} of "
                                                f"{widget.width()}×{widget.height()} px on show")
    top_left = widget.mapToGlobal(QPoint(0, 0))
    inside = window.frameGeometry()
    screen = window.screen().availableGeometry()
    for area, name in ((inside, "the window"), (screen, "the screen")):
        check(area.contains(top_left) and area.contains(top_left + QPoint(widget.width() - 1, widget.height() - 1)),
              f"{what} is not inside {name}")


def click(window: QWidget, button: QAbstractButton, what: str) -> None:
    on_show(window, button, what)
    check(button.isEnabled(), f"{what} is disabled")
    QTest.mouseClick(button, Qt.MouseButton.LeftButton)


def choose_layout(window: MainWindow, layout_id: str) -> None:
    """The toolbar's layout switcher, as a user picks from it."""
    switcher = window.layouts.switcher
    on_show(window, switcher, "the layout switcher")
    index = next(i for i in range(switcher.count()) if switcher.itemData(i) == layout_id)
    switcher.setCurrentIndex(index)
    switcher.activated.emit(index)
    wait(0.3)
    check(window.layouts.current == layout_id, f"the {layout_id} layout is not on")


def open_tool(window: MainWindow, action_id: str | None, dock: QDockWidget) -> None:
    """A tool's own command (its shortcut; ``None``: the dock's View-menu entry), as a user gives it
    when the tool is not on show."""
    if not dock.isVisible() or dock.visibleRegion().isEmpty():
        action = window.actions_by_id[action_id] if action_id else dock.toggleViewAction()
        action.trigger()
    wait(0.3)
    check(dock.isVisible() and not dock.visibleRegion().isEmpty(), f"{dock.windowTitle()} is not on show")


def dock_geometries(window: MainWindow) -> dict[str, tuple[bool, bool, int, int, int, int]]:
    out = {}
    for dock in window.findChildren(QDockWidget):
        g = dock.geometry()
        out[dock.objectName()] = (dock.isVisible(), dock.isFloating(), g.x(), g.y(), g.width(), g.height())
    return out


def picture(window: MainWindow, folder: Path, name: str) -> None:
    window.viewport.render_now()
    wait(0.2)
    window.grab().save(str(folder / f"{name}.png"))


def paint_weights(window: MainWindow, folder: Path, done: dict) -> None:
    choose_layout(window, "painting")
    window.view_state.select_parameter("jaw_open")          # a click on its row in the parameter tree
    paint = window.paint
    window.actions_by_id["paint.mode"].trigger()
    check(paint.active, "paint mode did not start")
    page = window.paint_options
    check(page.isVisible(), "the paint page is not in Tool options")
    on_show(window, page.live_preview, "the Live preview section")
    if not page.hold.isChecked():
        on_show(window, page.hold, "Hold the parameter at")
        QTest.mouseClick(page.hold, Qt.MouseButton.LeftButton)
    wait(0.2)
    held = window.document.value("jaw_open")
    check(held > 0, "holding the parameter did not open the jaw")
    model = window.document.model
    before = model.regions["jaw_open"].weights.copy(), model.regions["jaw_open"].indices.copy()
    viewport = window.viewport
    on_show(window, viewport, "the viewport")
    # a stroke across the middle of the face, from left to right of the window's centre
    plotter = viewport.plotter
    y = int(plotter.height() * 0.62)
    xs = [int(plotter.width() * f) for f in (0.44, 0.47, 0.50, 0.53, 0.56)]
    paint.press(xs[0], y)
    for x in xs[1:]:
        paint.drag(x, y)
    paint.release(xs[-1], y)
    after = model.regions["jaw_open"]
    changed = not (np.array_equal(after.indices, before[1]) and np.array_equal(after.weights, before[0]))
    check(changed, "the stroke changed no weight of jaw_open")
    check(window.document.undo_stack.undoText().startswith("Paint"), "the stroke is not an undo step")
    picture(window, folder, "1-painting")
    window.actions_by_id["paint.mode"].trigger()
    window.view_state.select_parameter(None)
    done["painting"] = {"held_jaw_open": held, "undo": window.document.undo_stack.undoText()}


def capture_to_parameters(window: MainWindow, folder: Path, scratch: Path, done: dict) -> None:
    choose_layout(window, "mocap")
    take = write_sample_recording(scratch / "take1", "Papu ja kala. Hyvää päivää, mitä kuuluu?", seed=3)
    mocap = window.mocap
    dialog = mocap.import_dialog_for(take["markers"])        # what Motion capture ▸ Import…'s file dialog does
    wait_for(lambda: running_jobs() == 0 and dialog.recording is not None, "the recording to be read")
    check(window.screen().availableGeometry().contains(dialog.frameGeometry()), "the import dialog is off screen")
    dialog.labels_edit.setText(str(take["labels"]))
    dialog.session_edit.setText(str(scratch / "take1.h5"))
    click(dialog, dialog.import_button, "Import")            # the dialog is a window of its own
    wait_for(lambda: running_jobs() == 0 and mocap.state.session is not None, "the import")
    wait(0.3)
    session = mocap.state.session
    plot = mocap.plot_dock
    on_show(window, plot.selectors_edit, "the phone selectors")
    plot.selectors_edit.setText("V C")
    select_button = next(b for b in plot.findChildren(QAbstractButton) if b.text() == "Select by phones")
    click(window, select_button, "Select by phones")
    frames = mocap.state.selected_frames()
    check(len(frames) > 10, "selecting by phones selected no frames")
    pca = mocap.pca_dock
    pca.tabs.setCurrentIndex(0)
    click(window, pca.run_button, "Run PCA")
    wait_for(lambda: running_jobs() == 0 and mocap.state.articulation is not None, "the PCA")
    wait(0.3)
    picture(window, folder, "2-mocap-pca")
    pca.tabs.setCurrentIndex(2)
    wait(0.2)
    names_before = list(window.document.model.parameters.names)
    click(window, pca.apply_button, "Apply to model")
    wait_for(lambda: running_jobs() == 0 and len(window.document.model.parameters) > len(names_before),
             "the PCA parameters on the model")
    wait(0.3)
    added = [n for n in window.document.model.parameters.names if n not in names_before]
    check(len(added) == mocap.state.articulation.n_components, f"apply added {added}")
    picture(window, folder, "3-mocap-applied")
    done["mocap"] = {"frames": int(session.n_frames), "selected": len(frames), "added": added}


def preview_head_nod(window: MainWindow, folder: Path, done: dict) -> None:
    choose_layout(window, "library")
    open_tool(window, "library.editor", window.library_editor_dock)     # Ctrl+L, unless on show already
    editor = window.library_editor
    check(editor.open_file(ROOT / "engine" / "library" / "HeadNod.lib"), "HeadNod.lib did not open")   # Library ▸ Open…
    wait(0.6)
    on_show(window, editor.text, "the library editor's text")
    check(editor.text.width() >= 400, f"the library text pane is {editor.text.width()} px wide")
    click(window, editor.preview_button, "Preview")
    wait(0.2)
    check(window.player.is_playing and "head_nod" in window.player.driven, "HeadNod is not playing")
    wait(0.5)
    window.player.pause()
    picture(window, folder, "4-library")
    done["library"] = {"driven": sorted(window.player.driven)}


def play_expression(window: MainWindow, folder: Path, done: dict) -> None:
    choose_layout(window, "animation")
    open_tool(window, "library.gallery", window.expression_gallery_dock)   # Ctrl+G, unless on show already
    wait(0.2)
    gallery = window.expression_gallery
    item = gallery.items["Happy"]
    view = item.listWidget()
    rect = view.visualItemRect(item)
    on_show(window, view, "the gallery's expressions")
    check(view.viewport().rect().contains(rect), "the Happy face is not on show in the gallery")
    QTest.mouseClick(view.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    wait(0.2)
    check(window.player.is_playing and any(n.startswith("AU12") for n in window.player.driven),
          "Happy is not playing")
    wait(0.6)
    window.player.pause()
    picture(window, folder, "5-gallery")
    done["gallery"] = {"driven": sorted(window.player.driven)}


def say_and_export(window: MainWindow, folder: Path, scratch: Path, done: dict) -> None:
    choose_layout(window, "animation")
    open_tool(window, None, window.script_dock)               # View ▸ Script, if the gallery's tab is in front
    panel = window.script_panel
    on_show(window, panel.editor, "the script's text")
    panel.editor.setPlainText(SENTENCE)
    click(window, panel.say_button, "Say")
    wait_for(lambda: not panel.busy, "Festival", seconds=180)
    check(panel.export_button.isEnabled(), "nothing said: Export is disabled")
    window.player.pause()
    picture(window, folder, "6-said")
    out = scratch / "export"
    out.mkdir()

    def fill() -> None:
        dialog = QApplication.activeModalWidget()
        check(dialog is not None and dialog.objectName() == "script_panel.export_dialog", "no export dialog")
        check(window.screen().availableGeometry().contains(dialog.frameGeometry()), "the export dialog is off screen")
        dialog.folder_edit.setText(str(out))
        dialog.base_edit.setText("hello")
        dialog.width_box.setValue(320)
        dialog.height_box.setValue(240)
        dialog.fps_box.setValue(15.0)
        for kind, box in dialog.kind_boxes.items():
            box.setChecked(kind == "mp4")
        dialog.accept()

    QTimer.singleShot(0, fill)
    click(window, panel.export_button, "Export…")
    wait_for(lambda: (out / "hello.mp4").exists() and not window.speech_exporter.busy, "the MP4", seconds=300)
    info = probe(out / "hello.mp4")
    check((info.width, info.height) == (320, 240) and info.audio_codec == "aac", f"the MP4 is {info}")
    done["speech"] = {"mp4": [info.width, info.height, info.frames, info.audio_codec]}


def run(folder: Path) -> None:
    app = QApplication(sys.argv[:1])
    app.setOrganizationName("Artificial Person Laptop Session")
    app.setApplicationName("Workbench")
    QSettings().clear()
    path = engine.default_model_path()
    window = MainWindow(ModelDocument(engine.load_model(path), path))
    window.show()
    QTest.qWaitForWindowExposed(window)
    wait(1.0)
    screen = window.screen().availableGeometry()
    done: dict = {"screen": [screen.width(), screen.height()]}
    check(screen.contains(window.frameGeometry()), "the window does not fit the screen at the start")
    import tempfile

    with tempfile.TemporaryDirectory() as scratch_name:
        scratch = Path(scratch_name)
        steps = (lambda: paint_weights(window, folder, done),
                 lambda: capture_to_parameters(window, folder, scratch, done),
                 lambda: preview_head_nod(window, folder, done),
                 lambda: play_expression(window, folder, done),
                 lambda: say_and_export(window, folder, scratch, done))
        for step in steps:
            layouts_before = window.layouts.current
            step()
            check(screen.contains(window.frameGeometry()), f"the window left the screen after {layouts_before}")
            floating = [name for name, g in dock_geometries(window).items() if g[0] and g[1]]
            check(not floating, f"docks floating: {floating}")
    done["window"] = [window.frameGeometry().width(), window.frameGeometry().height()]
    (folder / "report.json").write_text(json.dumps(done, indent=1))
    window.document.undo_stack.setClean()
    window.close()


if __name__ == "__main__":
    run(Path(sys.argv[1]))
