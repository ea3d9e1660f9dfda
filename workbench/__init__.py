"""Artificial Person workbench: the Qt GUI over the engine.

The model lives in :mod:`engine`; the workbench is a view over it.
:class:`~workbench.document.model_document.ModelDocument` holds the open model and pose and
announces changes; each widget (viewport, parameter panel, parts menu,
status bar) is one module that listens. Importing this package loads no Qt;
:func:`main` does. It does arrange for ``matplotlib.pyplot``, which pyvista
imports but the workbench does not use, to run only when first used
(:mod:`.deferred_imports`).

>>> import workbench
>>> workbench.main("my-head.xml")       # doctest: +SKIP
0
"""

from __future__ import annotations

from . import deferred_imports

__all__ = ["main"]

deferred_imports.install()    # before anything imports pyvista: 0.3 s off the start


def main(model_path: str | None = None) -> int:
    """Run the workbench on ``model_path`` (default head if ``None``); returns the exit status."""
    from .app import main as _main

    return _main(model_path)
