"""Run by ``test_layout_screenshots.py``: the workbench in each task layout, on a screen of one size.

``python -m tests.workbench.layout_screenshots FOLDER WIDTH HEIGHT`` runs on an
Xvfb screen of that size, opens the default head with fresh settings at the
size a first start picks, and in each layout does what the layout is for
before it takes the picture ``FOLDER/layout-<layout>-<W>x<H>.png``:

* **Model**: the parameter ``jaw_open`` selected, its properties in Tool options;
* **Painting**: painting ``jaw_open`` with the live preview holding it open;
* **Motion capture**: a synthetic recording imported with its phone labels,
  one frame selected per vowel, multistage PCA run (``mocap``: the stages,
  ``mocap-results``: the first component shown on the face);
* **Animation/Speech**: a sentence said (needs Festival), an expression chosen in the gallery;
* **Library**: ``HeadNod.lib`` open in the library editor and previewed.
"""

import sys
import tempfile
from pathlib import Path

from PySide6.QtCore import QSettings
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication

import engine
from engine.mocap.importer import import_marker_file
from engine.mocap.sample_files import write_sample_recording
from workbench.background import running_jobs
from workbench.document.model_document import ModelDocument
from workbench.window.main_window import MainWindow

ROOT = Path(__file__).resolve().parents[2]
SENTENCE = "Hyvää <Happy/> huomenta! Mitä kuuluu?"
SHOTS = ("model", "painting", "mocap", "mocap-results", "animation", "library")


def wait(app, seconds: float) -> None:
    QTest.qWait(round(seconds * 1000))
    app.processEvents()


def wait_for(app, condition, seconds: float = 60.0) -> None:
    import time

    end = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > end:
            raise TimeoutError("the workbench did not get there in time")
        wait(app, 0.05)


def shoot(window, app, folder: Path, layout_id: str, size: str) -> None:
    window.viewport.render_now()
    wait(app, 0.3)
    path = folder / f"layout-{layout_id}-{size}.png"
    if not window.grab().save(str(path)):
        raise OSError(f"cannot write {path}")


def shoot_every_layout(folder: Path, width: int, height: int) -> None:
    app = QApplication(sys.argv[:1])
    app.setOrganizationName("Artificial Person Screenshots")
    app.setApplicationName("Workbench")
    QSettings().clear()
    path = engine.default_model_path()
    window = MainWindow(ModelDocument(engine.load_model(path), path))
    window.show()
    wait(app, 1.0)
    size = f"{width}x{height}"
    layouts = window.layouts

    layouts.switch("model")
    window.view_state.select_parameter("jaw_open")
    window.document.set_values({"jaw_open": 0.35})
    shoot(window, app, folder, "model", size)

    layouts.switch("painting")
    window.paint.set_hold(enabled=True, fraction=0.6)
    window.actions_by_id["paint.mode"].trigger()
    shoot(window, app, folder, "painting", size)
    window.actions_by_id["paint.mode"].trigger()
    window.view_state.select_parameter(None)        # no heat map over the other tasks' faces
    window.document.reset_all()

    layouts.switch("mocap")
    with tempfile.TemporaryDirectory() as scratch:
        take = write_sample_recording(Path(scratch) / "take1", "Papu ja kala. Hyvää päivää, mitä kuuluu?", seed=3)
        session = import_marker_file(take["markers"], labels=take["labels"])
    window.mocap.state.set_session(session)
    wait(app, 0.5)
    window.mocap.plot_dock.select_by_phones(["V"])
    window.mocap.pca_dock.run_pca()
    wait_for(app, lambda: running_jobs() == 0 and window.mocap.state.articulation is not None)
    window.playhead.set_frame(150)
    window.mocap.pca_dock.tabs.setCurrentIndex(0)
    shoot(window, app, folder, "mocap", size)
    window.mocap.pca_dock.tabs.setCurrentIndex(1)
    window.mocap.pca_dock.show_component(0, 2.0)
    shoot(window, app, folder, "mocap-results", size)
    window.mocap.pca_dock.stop_preview()

    layouts.switch("animation")
    panel = window.script_panel
    panel.editor.setPlainText(SENTENCE)
    panel.say()
    wait_for(app, lambda: not panel.busy)
    window.player.pause()
    window.playhead.set_time(0.9)
    gallery = window.expression_gallery
    gallery.thumbnails.render_all()
    gallery.expressions_list.setCurrentItem(gallery.items["Happy"])
    shoot(window, app, folder, "animation", size)

    layouts.switch("library")
    gallery.thumbnails.render_all()
    window.library_editor.open_file(ROOT / "engine" / "library" / "HeadNod.lib")
    wait(app, 0.6)
    window.library_editor.preview()
    window.player.pause()
    window.playhead.set_time(0.45)
    shoot(window, app, folder, "library", size)

    window.document.undo_stack.setClean()
    window.close()


if __name__ == "__main__":
    shoot_every_layout(Path(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]))
