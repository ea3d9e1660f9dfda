"""Which OpenGL draws the frames: a GPU, or Mesa's software rasteriser (llvmpipe/OSMesa).

Drawing is most of a stimulus's cost (benchmarks/bench_video.py): at 1280 × 720 on Mesa's
llvmpipe a frame costs 70–100 ms of CPU, the encoder about 20. A set's provenance and
``render --info`` name the backend, so a figure or a pixel difference can be traced to it.

:func:`gpu_render_nodes` lists the machine's DRM render nodes (``/dev/dri/renderD*``: a GPU
that EGL can draw on without a display); :func:`describe` reads the OpenGL vendor, renderer
and version strings from an open VTK render window and says in words what kind it is.

>>> classify("llvmpipe (LLVM 15.0.6, 256 bits)")
'software (Mesa llvmpipe)'
>>> classify("Mesa Offscreen")
'software (OSMesa)'
>>> classify("NVIDIA GeForce RTX 3060/PCIe/SSE2")
'GPU (NVIDIA GeForce RTX 3060/PCIe/SSE2)'
"""

from __future__ import annotations

import ctypes.util
import glob
import os
import sys
from typing import Any

__all__ = ["classify", "describe", "gpu_render_nodes", "is_software", "probe"]

_SOFTWARE = (("llvmpipe", "software (Mesa llvmpipe)"), ("softpipe", "software (Mesa softpipe)"),
             ("swrast", "software (Mesa swrast)"), ("offscreen", "software (OSMesa)"),
             ("swiftshader", "software (SwiftShader)"), ("software", "software"))


def choose_offscreen_backend() -> None:
    """Without a display, ask VTK for EGL (or OSMesa) instead of letting it fail on X first."""
    if not sys.platform.startswith("linux") or os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"):
        return
    if ctypes.util.find_library("EGL"):
        os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    elif ctypes.util.find_library("OSMesa"):
        os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkOSOpenGLRenderWindow")


def gpu_render_nodes(pattern: str = "/dev/dri/renderD*") -> list[str]:
    """The DRM render nodes present (none on a machine without a GPU or inside most containers)."""
    return sorted(glob.glob(pattern))


def classify(renderer: str) -> str:
    """``software (…)`` for a software rasteriser's OpenGL renderer string, ``GPU (…)`` otherwise."""
    lowered = renderer.lower()
    for key, kind in _SOFTWARE:
        if key in lowered:
            return kind
    return f"GPU ({renderer.strip()})" if renderer.strip() else "unknown"


def is_software(kind: str) -> bool:
    """Whether :func:`classify`'s answer is a software rasteriser."""
    return kind.startswith("software")


def describe(window: Any) -> dict[str, str]:
    """The backend of an open (already rendered once) VTK render window: its class, the OpenGL
    vendor/renderer/version strings, :func:`classify`'s kind, VTK's version, the GPU render nodes
    seen and, for llvmpipe, its thread count (``LP_NUM_THREADS``: ``render --info`` prints them all,
    a stimulus set's ``provenance.json`` records them as ``"render_backend"``)."""
    strings = {"vendor": "", "renderer": "", "version": ""}
    for line in str(window.ReportCapabilities()).splitlines():
        for key in strings:
            prefix = f"OpenGL {key} string:"
            if line.startswith(prefix):
                strings[key] = line[len(prefix):].strip()
    from vtkmodules.vtkCommonCore import vtkVersion

    kind = classify(strings["renderer"])
    report = {"window": type(window).__name__, **strings, "kind": kind, "vtk": vtkVersion.GetVTKVersion(),
              "gpu_render_nodes": ", ".join(gpu_render_nodes()) or "none"}
    if "llvmpipe" in kind:
        report["llvmpipe_threads"] = os.environ.get("LP_NUM_THREADS") or "one per core the process may use"
    return report


def probe() -> dict[str, str]:
    """:func:`describe` of a tiny offscreen VTK window opened the way every renderer here opens
    one (EGL or OSMesa without a display, as :mod:`engine.outputs.render` chooses)."""

    choose_offscreen_backend()
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL window classes)
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(8, 8)
    window.AddRenderer(vtkRenderer())
    try:
        window.Render()
        return describe(window)
    finally:
        window.Finalize()
