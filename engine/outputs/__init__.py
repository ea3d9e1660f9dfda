"""What the animation becomes: pictures (offscreen VTK, imported lazily), videos with audio, glTF.

``render.py`` and ``video.py`` import pyvista/VTK inside their functions, so
importing this package loads no rendering library.

>>> from engine.outputs.render import render_model       # doctest: +SKIP
"""
