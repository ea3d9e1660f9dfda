"""The 3D view of the main window: the head's parts drawn by pyvista, picking, point overlays, colours.

`view.py` (:class:`~workbench.viewport.view.Viewport`) with its parts (`parts.py`), picking
(`picking.py`), point overlays (`points.py`, `landmark_overlay.py`), keys (`keys.py`), the normals of
the live view (`local_normals.py`) and the base vertex colours (`colors.py`).
"""
