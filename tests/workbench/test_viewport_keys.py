"""VTK's own keys do nothing in our 3-D views; our shortcuts and the mouse still work (issue 30, section 4).

VTK's interactor style answers keys of its own: ``w`` wireframe, ``s``
surface, ``3`` red-blue stereo (the whole view turns magenta), ``p`` a red
pick box, ``r`` the rubber-band mode (after which a drag no longer turns the
head), ``f`` fly to, ``e``/``q`` quit, … Real key presses go to the view
widget here (``QTest.keyClick``), with the mouse over the head so that the
keys that pick have something to pick.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtTest import QTest

VTK_KEYS = "wsp3frequjtcamilWSPR"
SURFACE = 2                                   # VTK_SURFACE, a property's representation
SCREENSHOT = Path("/tmp/viewport-after-vtk-keys.png")


def actors(renderer) -> list:
    collection = renderer.GetActors()
    collection.InitTraversal()
    return [collection.GetNextActor() for _ in range(collection.GetNumberOfItems())]


def vtk_state(plotter) -> dict:
    """What VTK's keys change: stereo, the actors' representation, the props drawn, the camera, the plotter open."""
    renderer = plotter.renderer
    camera = renderer.GetActiveCamera()
    return {"stereo": bool(plotter.render_window.GetStereoRender()),
            "representations": sorted({actor.GetProperty().GetRepresentation() for actor in actors(renderer)}),
            "props": renderer.GetViewProps().GetNumberOfItems(),
            "camera": np.round([*camera.GetPosition(), *camera.GetFocalPoint(), *camera.GetViewUp()], 6).tolist(),
            "open": not plotter._closed}


def press(view, qtbot, key, modifiers=Qt.KeyboardModifier.NoModifier) -> None:
    """Press ``key`` with the focus in ``view``, through its QWindow as the window system delivers keys (so Qt's
    shortcut map sees them first)."""
    window = view.window()
    window.activateWindow()
    qtbot.waitActive(window)
    view.setFocus()
    assert window.focusWidget() is view
    qtbot.keyClick(window.windowHandle(), key, modifiers)
    qtbot.wait(10)


def press_over_the_head(plotter, qtbot, keys: str) -> None:
    QTest.mouseMove(plotter, plotter.rect().center())        # VTK's pick keys pick where the mouse was last
    qtbot.wait(10)
    for key in keys:
        press(plotter, qtbot, key)


def drag(plotter, qtbot, by: QPoint) -> None:
    start = plotter.rect().center()
    QTest.mousePress(plotter, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, start)
    for step in range(1, 6):
        QTest.mouseMove(plotter, start + by * step / 5)
        qtbot.wait(5)
    QTest.mouseRelease(plotter, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, start + by)


def test_vtk_keys_change_nothing_in_the_main_viewport(window, qtbot):
    plotter = window.viewport.plotter
    plotter.render()
    before = vtk_state(plotter)
    assert not before["stereo"] and before["representations"] == [SURFACE] and before["open"]
    changed, last = [], before
    for key in VTK_KEYS:
        press_over_the_head(plotter, qtbot, key)
        if vtk_state(plotter) != last:
            changed.append(key)
            last = vtk_state(plotter)
    plotter.render()
    window.grab().save(str(SCREENSHOT))
    assert not changed, f"VTK acted on the keys {changed}"
    state = vtk_state(plotter)
    assert not state["stereo"], "red-blue stereo stays off"
    assert state["representations"] == [SURFACE], "the head stays a surface"
    assert state["props"] == before["props"], "no pick box or other prop was added"
    assert window.isVisible() and state["open"]

    # the mouse still turns the head (VTK's 'r' would have put the left button in rubber-band mode)
    drag(plotter, qtbot, QPoint(60, 0))
    assert vtk_state(plotter)["camera"] != before["camera"]
    assert vtk_state(plotter)["props"] == before["props"]


def test_our_shortcuts_still_act_from_the_viewport(window, qtbot):
    plotter, viewport = window.viewport.plotter, window.viewport
    ctrl_shift = Qt.KeyboardModifier.ControlModifier | Qt.KeyboardModifier.ShiftModifier
    press(plotter, qtbot, Qt.Key.Key_W, ctrl_shift)                                 # View → Wireframe
    assert window.view_state.wireframe
    assert all(viewport.part_actor(p).prop.style == "Wireframe" for p in viewport.part_names)
    press(plotter, qtbot, Qt.Key.Key_W, ctrl_shift)
    assert not window.view_state.wireframe
    press(plotter, qtbot, Qt.Key.Key_2, Qt.KeyboardModifier.ControlModifier)      # View → Side
    camera = plotter.camera
    direction = np.subtract(camera.position, camera.focal_point)
    np.testing.assert_allclose(direction / np.linalg.norm(direction), (1, 0, 0), atol=1e-9)


def test_a_key_the_view_does_not_use_goes_on_to_the_window_around_it(qtbot):
    """The keys pass the view by, on to its parent (Escape in a dialog, F11 in the live window), not into VTK."""
    from PySide6.QtWidgets import QVBoxLayout, QWidget

    import engine
    from workbench.document.model_document import ModelDocument
    from workbench.document.view_state import ViewState
    from workbench.viewport.view import Viewport

    seen: list[int] = []

    class Around(QWidget):
        def keyPressEvent(self, event) -> None:  # noqa: N802  (Qt's name)
            seen.append(event.key())

    around = Around()
    qtbot.addWidget(around)
    viewport = Viewport(ModelDocument(engine.load_model(engine.default_model_path())), ViewState(around), around)
    QVBoxLayout(around).addWidget(viewport)
    around.resize(400, 400)
    around.show()
    qtbot.waitExposed(around)
    try:
        press_over_the_head(viewport.plotter, qtbot, "3")
        press(viewport.plotter, qtbot, Qt.Key.Key_Escape)
        assert seen == [Qt.Key.Key_3, Qt.Key.Key_Escape]
        assert not viewport.plotter.render_window.GetStereoRender()
    finally:
        viewport.close_plotter()


@pytest.fixture
def live_window(qtbot):
    from workbench.live_window import LiveWindow, close_window

    window = LiveWindow((300, 400))
    window.show()
    qtbot.waitExposed(window)
    window.view.Initialize()
    window.render_window.Render()
    yield window
    close_window(window)


def test_the_live_window_ignores_vtk_keys_and_f11_reaches_it_from_the_view(live_window, qtbot):
    view = live_window.view
    for key in VTK_KEYS:
        press(view, qtbot, key)
    assert not live_window.render_window.GetStereoRender()
    press(view, qtbot, Qt.Key.Key_F11)                 # the view has the focus, as when the window opens
    assert live_window.windowState() & Qt.WindowState.WindowFullScreen
    press(view, qtbot, Qt.Key.Key_Escape)
    assert not live_window.windowState() & Qt.WindowState.WindowFullScreen


def test_every_vtk_view_the_workbench_makes_keeps_the_keys_from_vtk():
    """A new VTK view widget anywhere in the workbench must go through ``keep_keys_from_vtk`` as these do."""
    import re

    workbench = Path(__file__).resolve().parents[2] / "workbench"
    makers = re.compile(r"\b(QtInteractor|BackgroundPlotter|MultiPlotter|QVTKRenderWindowInteractor)\(")
    found = {path.relative_to(workbench).as_posix(): "keep_keys_from_vtk(" in path.read_text(encoding="utf-8")
             for path in workbench.rglob("*.py") if makers.search(path.read_text(encoding="utf-8"))}
    assert found == {"viewport/view.py": True, "live_window.py": True}
