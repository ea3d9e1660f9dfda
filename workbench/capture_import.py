"""File → *Import capture stream…*: a Live Link Face, OpenFace or MediaPipe take onto the timeline.

The take is read and mapped by the engine (:func:`engine.capture.animate.capture_table`,
the same steps as ``artificial-person capture animate``) and loaded into the
player as a tracks table, so it plays, scrubs and shows its tracks like an
opened animation. What the model cannot show (and what was clamped) is said
in a message box after loading; a bad file is refused in one, and nothing
changes. See ``docs/capture-streams.md``.

>>> import_capture_stream(window, "take.csv")     # doctest: +SKIP
True
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QFileDialog, QMessageBox

from engine.errors import UserError

from . import settings
from .tools import ToolContext
from .window.actions import ActionSpec, create_actions

if TYPE_CHECKING:
    from .window.main_window import MainWindow

FILE_FILTER = ("Capture streams (*.csv *.json);;Live Link Face / OpenFace / MediaPipe CSV (*.csv);;"
               "MediaPipe JSON (*.json);;All files (*)")
TITLE = "Import capture stream"
MESSAGE_MS = 4000

IMPORT_CAPTURE = ActionSpec(
    "file.import_capture", "Import &capture stream…", "&File",
    triggered=lambda w: import_capture_dialog(w),  # noqa: PLW0108  (defined below)
    icon="open-animation",
    tip="Play a face-capture take (Live Link Face, OpenFace, MediaPipe) on the model's action units, "
        "jaw, lids, head and eyes")


def install(context: ToolContext) -> None:
    """Put *Import capture stream…* in the File menu, above Quit."""
    actions = create_actions(context.window, (IMPORT_CAPTURE,))
    menu = context.menus["&File"]
    quit_action = context.actions.get("file.quit")
    if quit_action is not None and quit_action in menu.actions():
        menu.insertAction(quit_action, actions[IMPORT_CAPTURE.id])
    else:
        menu.addAction(actions[IMPORT_CAPTURE.id])
    context.actions.update(actions)


def import_capture_stream(window: MainWindow, path: str | Path, format: str = "auto") -> bool:
    """Map the take at ``path`` onto the window's model and load it into the player."""
    from engine.capture.animate import capture_table

    context = window.tools
    try:
        table, stream, mapped, fps = capture_table(path, context.document.model, format)
    except UserError as error:
        QMessageBox.warning(window, TITLE, f"Cannot import this capture stream:\n\n{error}")
        return False
    name = Path(path).stem
    context.player.load(table, title=name, fps=fps)
    context.show_dock("dock:timeline")           # the timeline tool's dock, where there is one
    said = [*stream.notes, *mapped.warnings]
    said += [f"clamped {n} in {c.frames} frame(s) (mapped {c.lowest:.3g} … {c.highest:.3g})"
             for n, c in mapped.clamped.items()]
    if said:
        QMessageBox.information(window, TITLE, f"{name}: {stream.format}, {stream.frames} frames.\n\n"
                                + "\n".join(said))
    context.status.showMessage(f"Capture {name}: {len(mapped.parameters)} parameters, "
                               f"{context.playhead.duration:.3f} s — Space plays", MESSAGE_MS)
    return True


def import_capture_dialog(window: MainWindow) -> bool:
    store = QSettings()
    path, _ = QFileDialog.getOpenFileName(window, TITLE, str(store.value(settings.LAST_DIR, "")), FILE_FILTER)
    if not path:
        return False
    store.setValue(settings.LAST_DIR, str(Path(path).parent))
    return import_capture_stream(window, path)
