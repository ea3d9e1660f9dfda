"""Running ``artificial-person`` as users run it: a fresh interpreter, no display."""

from __future__ import annotations

import os
import subprocess
import sys


def run(*args, cwd=None, command=None) -> subprocess.CompletedProcess:
    """``python -m engine ARGS`` in a fresh interpreter with no display."""
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    command = command or [sys.executable, "-m", "engine"]
    return subprocess.run([*command, *map(str, args)], capture_output=True, text=True, env=env, cwd=cwd,
                          timeout=120, check=False)


def assert_user_error(result: subprocess.CompletedProcess) -> str:
    """Status 2, one ``error:`` line on stderr, no traceback; returns that line."""
    assert result.returncode == 2, (result.returncode, result.stderr)
    assert "Traceback" not in result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith("error: ")
    return lines[0]


def made_set(folder, design: str):
    """The stimulus set of the design text ``design``, made by the CLI in ``folder`` (one worker): the
    folder, holding ``design.toml`` and the set in ``set/``."""
    (folder / "design.toml").write_text(design)
    made = run("stimuli", folder / "design.toml", "-o", folder / "set", "--workers", "1")
    assert made.returncode == 0, made.stderr
    return folder
