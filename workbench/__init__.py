"""Artificial Person workbench: the Qt GUI over the engine (DESIGN.md, "workbench/").

The model lives in :mod:`engine`; the workbench is a view over it.
:class:`~workbench.document.ModelDocument` holds the open model and pose and
announces changes; each widget (viewport, parameter panel, parts menu,
status bar) is one module that listens. Importing this package loads no Qt;
:func:`main` does.

>>> import workbench
>>> workbench.main("my-head.xml")       # doctest: +SKIP
0
"""

from __future__ import annotations

__all__ = ["main"]


def main(model_path: str | None = None) -> int:
    """Run the workbench on ``model_path`` (default head if ``None``); returns the exit status."""
    from .app import main as _main

    return _main(model_path)
