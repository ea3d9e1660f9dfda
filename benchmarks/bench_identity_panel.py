#!/usr/bin/env python3
"""The Identity panel in the real window: time of one live update while a slider is dragged, and of a release.

Run from the project root under a display (Xvfb is enough)::

    xvfb-run -a .venv/bin/python benchmarks/bench_identity_panel.py [--updates 60] [--releases 3] [--json out.json]

The workbench window (1280 × 800) on the default head (5 960 vertices) with
the Identity dock open. A drag is ``--updates`` slider positions across the
range, each one as the panel gets it (``valueChanged`` while the slider is
held down) and drawn as the event loop would draw it:

* **preview** — :meth:`IdentityHeads.draw_preview_now`: the identity's rest
  vertices (:func:`engine.identity.identity_vertices`), the document's pose
  added, the moved vertices written into the viewport's meshes with their
  normals (``Viewport.update_points``);
* **render** — one VTK render of the window's view (software OpenGL here);
* **update** — the two together: what one step of a drag costs before the
  screen shows it (goal: interactive, under 50 ms; a frame at 60 Hz is 17 ms);
* **floors** — :func:`identity_vertices` alone (the engine's part) and a
  render of the unchanged view without multisampling, as during a drag (the
  rasteriser's part);
* **peer** — what the update would cost without the preview path: the whole
  head with its rig (:func:`engine.identity.make_identity_head`), which the
  panel makes only once, on release.

Two sliders: ``sex`` (a macro parameter: every vertex moves) and
``nose-scale-horiz-decr-incr`` (a face modifier: a few hundred vertices).

A release is timed from the slider's release to the new head on screen (made
on the worker thread, pushed as one undo step, the viewport rebuilt), with
the longest pause of the GUI thread's event loop meanwhile (a 5 ms timer
counts the gaps: the window must not freeze), separately for the time the
worker makes the head and for the moment the window takes the new model
(``model_replaced``: the viewport and the docks rebuild). Loading the default head
(``engine.load_model``) is printed beside it. No assertions: figures for
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
os.environ.setdefault("XDG_CONFIG_HOME", tempfile.mkdtemp(prefix="ap-bench-config-"))   # no remembered layout

import engine

SLIDERS = ("sex", "nose-scale-horiz-decr-incr")


def stats(times_s):
    t = np.asarray(times_s) * 1e3
    return {"median_ms": float(np.median(t)), "p95_ms": float(np.percentile(t, 95)), "n": len(t)}


def drag(window, name, updates):
    """One drag of ``name`` across its range: per step, the preview and the render (seconds)."""
    panel = window.identity_panel
    heads, viewport = panel.heads, window.viewport
    row = panel.rows[name]
    row.group.set_expanded(True)
    positions = np.linspace(row.position_of(row.parameter.minimum), row.position_of(row.parameter.maximum),
                            updates).round().astype(int)
    preview, render, moved = [], [], []
    row.slider.setSliderDown(True)
    for position in positions:
        row.slider.setValue(int(position))            # what a mouse move does: the panel asks for a preview
        before = heads._shown_preview.copy() if heads._shown_preview is not None else window.document.vertices()
        t0 = time.perf_counter()
        heads.draw_preview_now()
        t1 = time.perf_counter()
        viewport.render_now()
        t2 = time.perf_counter()
        preview.append(t1 - t0)
        render.append(t2 - t1)
        moved.append(int(np.any(heads._shown_preview != before, axis=1).sum()))
    heads.end_preview()
    with_signals_blocked(row.slider, lambda: row.slider.setSliderDown(False))   # no release: nothing is made
    row.show_value(row.parameter.default)
    return preview, render, moved


def with_signals_blocked(widget, action):
    from PySide6.QtCore import QSignalBlocker

    with QSignalBlocker(widget):
        action()


def floors(window, updates):
    from engine.identity import Identity, identity_vertices

    viewport = window.viewport
    engine_only, still = [], []
    viewport.set_fast_rendering(True)                  # as during a drag
    for k in range(updates):
        identity = Identity({"sex": k / max(updates - 1, 1)})
        t0 = time.perf_counter()
        identity_vertices(identity, window.document.model)
        engine_only.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        viewport.render_now()
        still.append(time.perf_counter() - t0)
    viewport.set_fast_rendering(False)
    return engine_only, still


def peer(window, count):
    from engine.identity import Identity, make_identity_head

    times = []
    for k in range(count):
        t0 = time.perf_counter()
        make_identity_head(Identity({"sex": 0.2 + 0.6 * k / max(count - 1, 1)}), window.document.model.copy())
        times.append(time.perf_counter() - t0)
    return times


def releases(window, app, count):
    """Release → head on screen, through the real panel; and the longest event-loop gap meanwhile."""
    from PySide6.QtCore import QEventLoop, QTimer

    panel = window.identity_panel
    row = panel.rows["age"]
    times, gaps, waiting_gaps = [], [], []
    arrived: list[float] = []             # when the head made on the worker is pushed (before the window rebuilds)
    document = window.document
    push = document.push

    def timed_push(command) -> None:
        arrived.append(time.perf_counter())
        push(command)

    document.push = timed_push
    for k in range(count):
        ticks = []
        timer = QTimer()
        timer.setInterval(5)
        timer.timeout.connect(lambda ticks=ticks: ticks.append(time.perf_counter()))
        row.slider.setSliderDown(True)
        row.slider.setValue(row.position_of(30.0 + 20.0 * k))
        panel.heads.draw_preview_now()                     # the drag's last step is on screen …
        window.viewport.render_now()
        t0 = time.perf_counter()
        timer.start()
        row.slider.setSliderDown(False)                   # … then the release: the head is made off the GUI thread
        loop = QEventLoop()                                # the event loop runs (and lets the worker run)
        watcher = QTimer()
        watcher.setInterval(2)
        watcher.timeout.connect(lambda loop=loop: None if panel.heads.busy else loop.quit())
        watcher.start()
        loop.exec()
        watcher.stop()
        window.viewport.render_now()
        times.append(time.perf_counter() - t0)
        timer.stop()
        points = np.array([t0, *ticks, time.perf_counter()])
        gaps.append(float(np.diff(points).max()))
        starts, ends = points[:-1], points[1:]
        making = ends <= arrived[-1]          # gaps before the push: while the worker made the head
        waiting_gaps.append(float((ends - starts)[making].max(initial=0.0)))
    document.push = push
    return times, gaps, waiting_gaps


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--updates", type=int, default=60, help="slider positions per drag")
    parser.add_argument("--releases", type=int, default=3, help="releases (heads made) to time")
    parser.add_argument("--json", type=Path, help="write the figures here too")
    args = parser.parse_args(argv)

    from PySide6.QtWidgets import QApplication

    app = QApplication.instance() or QApplication([])
    app.setOrganizationName("Artificial Person Benchmarks")
    from workbench.document.model_document import ModelDocument
    from workbench.window.main_window import MainWindow

    t0 = time.perf_counter()
    model = engine.load_model()
    load_s = time.perf_counter() - t0
    path = engine.default_model_path()
    window = MainWindow(ModelDocument(model, path))
    window.resize(1280, 800)
    window.show()
    app.processEvents()
    t0 = time.perf_counter()
    window.actions_by_id["view.identity"].trigger()
    app.processEvents()
    window.identity_panel.ensure_built()
    first_open_s = time.perf_counter() - t0
    window.viewport.set_view("front")
    window.viewport.render_now()

    results: dict[str, object] = {"vertices": model.n_vertices, "load_default_head_ms": 1e3 * load_s,
                                  "first_open_of_the_panel_ms": 1e3 * first_open_s}
    drag(window, "sex", 5)                                # warm-up: caches, first VTK uploads
    for name in SLIDERS:
        preview, render, moved = drag(window, name, args.updates)
        total = [a + b for a, b in zip(preview, render, strict=True)]
        results[name] = {"preview": stats(preview), "render": stats(render), "update": stats(total),
                         "moved_vertices_median": int(np.median(moved))}
    engine_only, still = floors(window, args.updates)
    results["floor_identity_vertices"] = stats(engine_only)
    results["floor_render_unchanged"] = stats(still)
    results["peer_make_identity_head"] = stats(peer(window, args.releases))
    times, gaps, waiting_gaps = releases(window, app, args.releases)
    results["release_to_head_on_screen"] = stats(times)
    results["longest_gui_pause_during_a_release_ms"] = float(1e3 * max(gaps))
    results["longest_gui_pause_while_the_head_is_made_ms"] = float(1e3 * max(waiting_gaps))

    print(f"default head: {model.n_vertices} vertices, loaded in {results['load_default_head_ms']:.0f} ms; "
          f"first opening of the panel {results['first_open_of_the_panel_ms']:.0f} ms")
    for name in SLIDERS:
        r = results[name]
        print(f"drag {name:28s} update {r['update']['median_ms']:6.1f} ms median ({r['update']['p95_ms']:.1f} p95)"
              f" = preview {r['preview']['median_ms']:.1f} + render {r['render']['median_ms']:.1f}; "
              f"{r['moved_vertices_median']} vertices moved per step")
    print(f"floors: identity_vertices {results['floor_identity_vertices']['median_ms']:.1f} ms, "
          f"render of the unchanged view {results['floor_render_unchanged']['median_ms']:.1f} ms")
    print(f"peer (whole head with its rig per update): {results['peer_make_identity_head']['median_ms']:.0f} ms")
    print(f"release → new head on screen: {results['release_to_head_on_screen']['median_ms']:.0f} ms median; "
          f"longest GUI pause meanwhile {results['longest_gui_pause_during_a_release_ms']:.0f} ms "
          f"(while the worker made it: {results['longest_gui_pause_while_the_head_is_made_ms']:.0f} ms; the rest is "
          "the window taking and drawing the new head)")
    if args.json:
        args.json.write_text(json.dumps(results, indent=2))
    window.document.undo_stack.setClean()
    window.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
