"""``render --info``: which OpenGL would draw the pictures and videos here, and how it was chosen.

Drawing is most of what a picture or a video costs, and a GPU draws it many
times faster than Mesa's software rasteriser (docs/export.md, "Speed"), so the
first thing to know about a machine is which of the two it has. The report is
:func:`engine.outputs.render_backend.probe`'s, one ``name: value`` a line::

    $ artificial-person render --info
    backend: software (Mesa llvmpipe)
    window: vtkEGLRenderWindow (offscreen, EGL)
    ...
"""

from __future__ import annotations

import argparse
from collections.abc import Mapping, Sequence
from typing import Any

__all__ = ["RenderInfoAction", "info_lines"]

_LABELS = (("kind", "backend"), ("window", "window"), ("vendor", "OpenGL vendor"), ("renderer", "OpenGL renderer"),
           ("version", "OpenGL version"), ("vtk", "VTK"), ("gpu_render_nodes", "GPU render nodes"),
           ("llvmpipe_threads", "llvmpipe threads (LP_NUM_THREADS)"))


def info_lines(report: Mapping[str, str]) -> list[str]:
    """The lines ``render --info`` prints for a :func:`~engine.outputs.render_backend.probe` report.

    >>> info_lines({"kind": "software (Mesa llvmpipe)", "window": "vtkEGLRenderWindow", "vendor": "Mesa"})
    ['backend: software (Mesa llvmpipe)', 'window: vtkEGLRenderWindow (offscreen, EGL)', 'OpenGL vendor: Mesa']
    """
    windows = {"vtkEGLRenderWindow": "offscreen, EGL", "vtkOSOpenGLRenderWindow": "offscreen, OSMesa",
               "vtkXOpenGLRenderWindow": "X display"}
    lines = []
    for key, label in _LABELS:
        if key not in report:
            continue
        value = report[key]
        if key == "window" and value in windows:
            value = f"{value} ({windows[value]})"
        lines.append(f"{label}: {value}")
    return lines


class RenderInfoAction(argparse.Action):
    """``--info``: print the backend's report and end (status 0), as ``--version`` does; status 1 with one
    ``error:`` line when no OpenGL can be opened at all."""

    def __init__(self, option_strings: Sequence[str], dest: str, **kwargs: Any) -> None:
        super().__init__(option_strings, dest, nargs=0, default=argparse.SUPPRESS, **kwargs)

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace, values: Any,
                 option_string: str | None = None) -> None:
        from engine.outputs.render_backend import probe

        try:
            report = probe()
        except Exception as exc:      # VTK's own errors: no OpenGL on this machine
            parser.exit(1, f"error: no OpenGL could be opened to draw: {exc}\n")
        print("\n".join(info_lines(report)), flush=True)
        parser.exit(0)
