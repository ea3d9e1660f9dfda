"""Keys pass our VTK views by: VTK's own key bindings never act, the key goes on to the widgets around the view.

VTK's interactor style answers keys of its own in every render window
interactor: ``w`` wireframe, ``s`` surface, ``3`` red-blue stereo (the whole
view turns magenta), ``p`` a red pick box, ``r`` reset the camera (pyvista's
rubber-band style: the left button then draws a box instead of turning the
head), ``f`` fly to, ``e``/``q`` quit, and the ``i`` of VTK's widgets. In
the workbench only our own shortcuts and actions may act. A VTK view widget
(a ``QVTKRenderWindowInteractor``, which pyvistaqt's ``QtInteractor`` is)
hands each key press to VTK in its ``keyPressEvent``, and keeps it there;
:func:`keep_keys_from_vtk` puts a filter in front of that: the key is not
given to VTK but ignored, so Qt offers it to the view's parent, and on up to
the window (Escape in a dialog, F11 in ``serve --window``'s window). Shortcuts
are not affected: Qt matches them before the key reaches any widget. The
mouse still goes to VTK (turning, panning, zooming, picking).

Every VTK view we make goes through it: the viewport (:class:`~workbench.viewport.view.Viewport`,
also the photo wizard's result view) and the live window (:mod:`workbench.live_window`).
No VTK import here: the filter is plain Qt.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QWidget

KEY_EVENTS = (QEvent.Type.KeyPress, QEvent.Type.KeyRelease)


class KeysPastVtk(QObject):
    """An event filter: key presses and releases never reach the VTK view it watches; its parents get them."""

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        if event.type() in KEY_EVENTS:
            event.ignore()          # not accepted: Qt offers it to the view's parent next
            return True             # ... and the view's own keyPressEvent (VTK's) never sees it
        return False


def keep_keys_from_vtk(view: QWidget) -> KeysPastVtk:
    """Install the filter on the VTK view widget ``view`` (owned by it); returns the filter."""
    keys = KeysPastVtk(view)
    keys.setObjectName("keys_past_vtk")
    view.installEventFilter(keys)
    return keys
