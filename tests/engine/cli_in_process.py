"""``artificial-person ARGS`` run in this interpreter through :func:`engine.cli.main` (issue 35 item 5).

For the argument and error tests: the same parser, verbs and error handling as ``python -m engine``
(``engine/__main__.py`` only passes ``main()``'s status to ``sys.exit``), without starting a fresh
interpreter (about 0.6 s each). What only a real process shows — the console script, the exit status as the
shell sees it, imports at start-up, memory limits, signals — stays in :mod:`tests.engine.cli_runner`.
"""

from __future__ import annotations

import contextlib
import io
import os
import subprocess
from pathlib import Path

from engine.cli import main


def run_in_process(*args, cwd: str | Path | None = None) -> subprocess.CompletedProcess:
    """``main([ARGS])`` with stdout and stderr captured (and ``cwd`` as the working folder meanwhile): its
    status, stdout and stderr, as :func:`tests.engine.cli_runner.run` returns them."""
    argv = [str(a) for a in args]
    out, err = io.StringIO(), io.StringIO()
    before = Path.cwd()
    try:
        if cwd is not None:
            os.chdir(cwd)
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            status = main(argv)
    finally:
        os.chdir(before)
    return subprocess.CompletedProcess(["artificial-person", *argv], status, out.getvalue(), err.getvalue())
