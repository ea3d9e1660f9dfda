#!/usr/bin/env python3
"""Time from launching the workbench to a window showing the head (goal: under 3 s).

Run from the project root under a display (Xvfb is enough)::

    xvfb-run -a .venv/bin/python benchmarks/bench_launch.py [--runs 5] [--json out.json]

Each run starts ``python -m workbench`` (the default head) as a fresh
process with ``AP_LAUNCH_MARKER`` and ``AP_LAUNCH_QUIT`` set
(:mod:`workbench.painting.launch_probe`): the workbench writes the wall-clock
time of the viewport's first finished paint to the marker file and closes.
Launch time = that time − the time just before the process was started, so
it includes the interpreter, every import (Qt, VTK, pyvista, numpy, scipy,
the engine), loading the model, building the window with every installed
tool, and the first render. Beside it, the floor: a bare ``python -c "pass"``,
and the imports no window with a pyvistaqt view can do without (Qt, VTK,
pyvista, pyvistaqt), once plain and once with ``matplotlib.pyplot``
deferred as the workbench defers it (:mod:`workbench.deferred_imports`).

Python writes and reuses its bytecode cache here, as on a user's machine,
even where ``PYTHONDONTWRITEBYTECODE`` is set in the calling shell: without
the cache every run would compile the whole workbench again (about 0.5 s).

Settings and recovery files go to temporary folders. No assertions.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PYTHON = str(ROOT / ".venv" / "bin" / "python") if (ROOT / ".venv" / "bin" / "python").exists() else sys.executable


def launch_once(timeout: float = 60.0) -> float:
    with tempfile.TemporaryDirectory(prefix="ap-launch-") as tmp:
        marker = Path(tmp) / "shown"
        env = dict(_environment(), AP_LAUNCH_MARKER=str(marker), AP_LAUNCH_QUIT="1",
                   XDG_CONFIG_HOME=str(Path(tmp) / "config"), XDG_DATA_HOME=str(Path(tmp) / "data"))
        start = time.time()
        process = subprocess.run([PYTHON, "-m", "workbench"], cwd=ROOT, env=env, timeout=timeout,
                                 stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, check=False)
        if not marker.exists():
            raise RuntimeError(f"the workbench never showed the head (exit {process.returncode}):\n{process.stderr}")
        return float(marker.read_text()) - start


def _environment() -> dict[str, str]:
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


def floor_once(code: str) -> float:
    start = time.time()
    subprocess.run([PYTHON, "-c", code], cwd=ROOT, check=True, env=_environment())
    return time.time() - start


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args(argv)
    launch_once()                              # warm the file cache (first run after a build is slower)
    runs = [launch_once() for _ in range(args.runs)]
    bare = [floor_once("pass") for _ in range(3)]
    imports = [floor_once("import PySide6.QtWidgets, pyvista, pyvistaqt") for _ in range(3)]
    deferred = [floor_once("import workbench.deferred_imports as d; d.install(); "
                           "import PySide6.QtWidgets, pyvista, pyvistaqt") for _ in range(3)]
    result = {"launch_s": runs, "python_s": bare, "imports_s": imports, "imports_deferred_s": deferred}
    fmt = ", ".join
    print(f"launch → head shown: median {sorted(runs)[len(runs) // 2]:.2f} s  "
          f"(runs: {fmt(f'{t:.2f}' for t in runs)})  goal < 3 s")
    print(f"floor: python alone {min(bare):.2f} s; python + Qt/VTK/pyvista/pyvistaqt imports "
          f"{min(imports):.2f} s, with pyplot deferred {min(deferred):.2f} s")
    if args.json:
        args.json.write_text(json.dumps(result, indent=2) + "\n")


if __name__ == "__main__":
    main()
