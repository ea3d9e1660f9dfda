"""kill -9 in the middle of an autosave: the orphaned copy is the previous autosave or the new one, whole.

A real process writes autosaves through :class:`workbench.window.recovery.RecoverySession`
and is killed (SIGKILL) at chosen steps of the model's save (the points of
tests/engine/save_kill_worker.py). Listing the orphans afterwards finishes the
save, removes what the killed process left, and offers a model that loads.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

import engine
from tests.engine.save_kill_worker import models
from tests.engine.test_save_kill import fingerprint
from workbench.window.recovery import orphaned_entries

ROOT = Path(__file__).resolve().parents[2]

AUTOSAVER = """
import sys
from pathlib import Path
from types import SimpleNamespace
import engine
from tests.engine.save_kill_worker import arm, models
from workbench.window.recovery import RecoverySession

folder, point = Path(sys.argv[1]), sys.argv[2]
a, b = models()
session = RecoverySession(folder)
def document(model):
    return SimpleNamespace(model=model, path=None, save_copy=lambda path: engine.save_model(model, path))
if point != "first":
    session.write(document(a))              # a complete autosave of A first
arm("rename-2" if point == "first" else point)
session.write(document(b))                  # killed half-way through this one
sys.exit(3)
"""


def autosave_and_die(folder: Path, point: str) -> None:
    env = dict(os.environ, PYTHONPATH=str(ROOT), QT_QPA_PLATFORM="offscreen")
    done = subprocess.run([sys.executable, "-c", AUTOSAVER, str(folder), point], cwd=ROOT, env=env, check=False)
    assert done.returncode == -signal.SIGKILL, "the autosave was not killed where it should be"


@pytest.mark.parametrize("point,offered", [("journal", "A"), ("rename-2", "B"), ("unjournal", "B")])
def test_an_autosave_killed_half_way_is_offered_whole(tmp_path, point, offered):
    autosave_and_die(tmp_path, point)
    assert any(p.name.startswith(".") for p in tmp_path.iterdir())        # the kill left temporaries
    entries = orphaned_entries(tmp_path)
    assert len(entries) == 1
    reference = tmp_path / "reference"
    expected = {fingerprint(engine.load_model(engine.save_model(model, reference / f"{name}.xml"))): name
                for name, model in zip("AB", models(), strict=True)}
    assert expected[fingerprint(entries[0].load())] == offered
    assert not [p.name for p in tmp_path.iterdir() if p.name.startswith(".")]
    entries[0].remove()
    assert not [p for p in tmp_path.iterdir() if p.suffix in (".xml", ".h5", ".json", ".tmp", ".journal")]


def test_a_first_autosave_killed_before_its_description_leaves_nothing(tmp_path):
    autosave_and_die(tmp_path, "first")
    assert orphaned_entries(tmp_path) == []
    assert not [p for p in tmp_path.iterdir() if p.suffix in (".xml", ".h5", ".tmp", ".journal")]
