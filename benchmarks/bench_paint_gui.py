#!/usr/bin/env python3
"""Weight painting in the workbench: time of one brush dab in the real window.

Run from the project root under a display (Xvfb is enough)::

    xvfb-run -a .venv/bin/python benchmarks/bench_paint_gui.py [--dabs 120] [--json out.json]

Meshes: the default head (``engine.load_model()``, 5 960 vertices) and its
4 × 4 subdivision (93 689 vertices, ``engine.model.subdivide``). The workbench
window (1280 × 800) paints ``jaw_open`` with the add brush (strength 0.3,
smooth falloff, front faces only, surface-connected); a stroke of
``--dabs`` dabs crosses the face at mouth height. Per dab it measures

* **dab** — ``PaintController.dab``: the engine's ``Stroke.dab`` on the dense
  weights, heat-map colours of the changed vertices written into the VTK
  colour arrays (``Viewport.update_colors``), and with the live preview the
  posed positions of the changed vertices (``LivePreview.update`` →
  ``Viewport.update_points``);
* **render** — one VTK render of the window's view (software OpenGL here;
  without multisampling during a stroke, as the tool draws it — anti-aliasing
  returns on release; a still render with 4× MSAA is printed beside it);
* **dab + render** — the two together: what one dab costs before the screen
  shows it (goal: under 16 ms on the head, under 50 ms at 100k);
* **floors** — redrawing the same view with nothing changed (what the
  rasteriser costs for this mesh at this size, whatever the tool does) and
  redrawing the view with every part hidden (the window alone). *render −
  same view* is what the dab's colour change costs to draw;
* **pick** — mapping one mouse position to the rest mesh (``Viewport.pick_cell``),
  done once per mouse move, not per dab.

Only the painting tool is installed in the window (other tools add docks
that do not take part in a dab). No assertions: figures for
benchmarks/README.md.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
os.environ.setdefault("XDG_DATA_HOME", tempfile.mkdtemp(prefix="ap-bench-data-"))

import engine
from engine.model.subdivide import subdivide


def stroke_points(model, count):
    """Rest-mesh points across the face at mouth height, front surface (nearest vertices)."""
    v = model.vertices
    skin = np.flatnonzero(model.vertex_part == model.parts.index("skin")) if "skin" in model.parts else \
        np.arange(len(v))
    lo, hi = v[skin].min(axis=0), v[skin].max(axis=0)
    y = lo[1] + 0.3 * (hi[1] - lo[1])
    xs = np.linspace(lo[0] + 0.3 * (hi[0] - lo[0]), hi[0] - 0.3 * (hi[0] - lo[0]), count)
    points = []
    for x in xs:
        near = skin[np.abs(v[skin, 1] - y) < 0.03 * (hi[1] - lo[1])]
        near = near[np.abs(v[near, 0] - x) < 0.03 * (hi[0] - lo[0])]
        points.append(v[near[np.argmax(v[near, 2])]] if len(near) else np.array([x, y, hi[2]]))
    return np.array(points)


def stats(times):
    t = np.asarray(times) * 1e3
    return {"median_ms": float(np.median(t)), "p95_ms": float(np.percentile(t, 95)), "n": len(t)}


def measure(window, app, count, live):
    paint, viewport = window.paint, window.viewport
    document = window.document
    window.view_state.select_parameter("jaw_open")
    paint.set_brush(mode="add", radius=15.0, strength=0.3, falloff="smooth", front_faces_only=True, connected=True)
    paint.set_hold(enabled=live, fraction=0.5)
    if not paint.active:
        paint.set_active(True)
    viewport.set_view("front")
    viewport.render_now()
    app.processEvents()
    points = stroke_points(document.model, count)
    dab_t, render_t, both_t, changed = [], [], [], []
    paint._begin_stroke()
    viewport.set_fast_rendering(True)        # what a mouse press does
    for p in points:
        t0 = time.perf_counter()
        change = paint.dab(p)
        t1 = time.perf_counter()
        viewport.render_now()
        t2 = time.perf_counter()
        dab_t.append(t1 - t0)
        render_t.append(t2 - t1)
        both_t.append(t2 - t0)
        changed.append(len(change))
    unchanged, empty = [], []                # the floors: redrawing this same view, and an empty one
    for _ in range(count // 2):
        t0 = time.perf_counter()
        viewport.render_now()
        unchanged.append(time.perf_counter() - t0)
    shown = [part for part in viewport.part_names if viewport.part_actor(part).GetVisibility()]
    for part in shown:
        viewport.part_actor(part).SetVisibility(False)
    for _ in range(count // 4):
        t0 = time.perf_counter()
        viewport.render_now()
        empty.append(time.perf_counter() - t0)
    for part in shown:
        viewport.part_actor(part).SetVisibility(True)
    t0 = time.perf_counter()
    paint.release()                          # commit: Model.set_region + redraw from the document
    commit = time.perf_counter() - t0
    app.processEvents()
    pick_t = []
    for p in points[:: max(1, count // 30)]:
        x, y = viewport.world_to_widget(p)
        t0 = time.perf_counter()
        viewport.pick_cell(x, y)
        pick_t.append(time.perf_counter() - t0)
    still = []
    for _ in range(5):
        t0 = time.perf_counter()
        viewport.render_now()
        still.append(time.perf_counter() - t0)
    document.undo_stack.undo()
    app.processEvents()
    return {"still_render": stats(still), "dab": stats(dab_t), "render": stats(render_t), "dab_render": stats(both_t),
            "pick": stats(pick_t), "redraw_unchanged": stats(unchanged), "redraw_empty": stats(empty),
            "changed_median": float(np.median(changed)), "commit_ms": commit * 1e3, "live": live}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--dabs", type=int, default=120)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args(argv)

    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QApplication

    app = QApplication.instance() or QApplication(sys.argv[:1])
    app.setOrganizationName("Artificial Person Benchmarks")
    QSettings.setDefaultFormat(QSettings.Format.IniFormat)
    QSettings.setPath(QSettings.Format.IniFormat, QSettings.Scope.UserScope, tempfile.mkdtemp(prefix="ap-bench-"))
    from workbench import features
    from workbench.document.model_document import ModelDocument
    from workbench.window.main_window import MainWindow

    features.INSTALLERS[:] = ["painting:install"]
    head = engine.load_model()
    meshes = [("default head", head), ("subdivided 4×4", subdivide(head, 4))]
    results = []
    for label, model in meshes:
        window = MainWindow(ModelDocument(model, None), autosave_seconds=3600)
        window.resize(1280, 800)
        window.show()
        for _ in range(20):
            app.processEvents()
            time.sleep(0.01)
        t0 = time.perf_counter()
        window.view_state.select_parameter("jaw_open")
        window.paint.set_active(True)
        enter = (time.perf_counter() - t0) * 1e3
        for live in (False, True):
            r = measure(window, app, args.dabs, live)
            r.update(mesh=label, vertices=model.n_vertices, enter_paint_mode_ms=enter)
            results.append(r)
            print(f"{label:16s} {model.n_vertices:6d} v  live={'on ' if live else 'off'}  "
                  f"dab {r['dab']['median_ms']:.2f}/{r['dab']['p95_ms']:.2f} ms  "
                  f"render {r['render']['median_ms']:.2f}/{r['render']['p95_ms']:.2f} ms  "
                  f"dab+render {r['dab_render']['median_ms']:.2f}/{r['dab_render']['p95_ms']:.2f} ms  "
                  f"floors: same view {r['redraw_unchanged']['median_ms']:.2f} ms, "
                  f"empty view {r['redraw_empty']['median_ms']:.2f} ms  "
                  f"still render {r['still_render']['median_ms']:.1f} ms  "
                  f"pick {r['pick']['median_ms']:.2f}/{r['pick']['p95_ms']:.2f} ms  "
                  f"changed {r['changed_median']:.0f}  stroke commit {r['commit_ms']:.0f} ms  "
                  f"enter paint mode {enter:.0f} ms   (median/p95)", flush=True)
        window.document.undo_stack.setClean()
        window.close()
        window.deleteLater()
        app.processEvents()
    if args.json:
        args.json.write_text(json.dumps(results, indent=2) + "\n")


if __name__ == "__main__":
    main()
