"""Autosave and crash recovery: in this process, and for real with a workbench killed by SIGKILL."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QMessageBox

import engine
from tests.workbench.synthetic_workbench_model import build_synthetic_model
from tests.workbench.workbench_model_state import model_state
from workbench import settings
from workbench.document.model_document import ModelDocument
from workbench.document.undo_commands import WeightsChangedCommand
from workbench.window.recovery import RecoverySession, orphaned_entries

Button = QMessageBox.StandardButton
PROJECT_ROOT = Path(__file__).resolve().parents[2]


def _paint(document, weight=0.5, name="brow_raise"):
    indices = document.model.regions[name].indices
    document.push(WeightsChangedCommand(document, name, indices, np.full(len(indices), weight)))


def _files(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir()) if folder.exists() else []


# ---------------------------------------------------------------------------
# in this process
# ---------------------------------------------------------------------------

def test_autosave_writes_a_copy_only_while_modified(window):
    autosaver, session = window.autosaver, window.autosaver.session
    assert autosaver.timer.isActive() and autosaver.timer.interval() == 60_000     # the default, 60 s
    assert not autosaver.autosave_now() and not session.has_copy()                  # nothing to save

    _paint(window.document)
    assert autosaver.autosave_now()
    info = json.loads(session.info_path.read_text())
    assert info["format"] == "artificial-person-recovery" and info["version"] == 1
    assert info["original"] == str(window.document.path)
    assert model_state(engine.load_model(session.model_path)) == model_state(window.document.model)
    assert not autosaver.autosave_now()                  # unchanged since the last copy

    window.undo()                                        # back at the saved state: nothing to recover
    assert not session.has_copy() and not session.model_path.exists()
    window.redo()
    assert autosaver.autosave_now()
    assert window.files.save_model(session.folder.parent / "saved.xml")
    assert not session.has_copy()


def test_a_clean_shutdown_leaves_no_recovery_files(window, monkeypatch):
    session = window.autosaver.session
    _paint(window.document)
    window.autosaver.autosave_now()
    assert f"{session.id}.lock" in _files(session.folder) and session.has_copy()
    monkeypatch.setattr(window.files, "ask_unsaved", lambda doing: Button.Discard)
    assert window.close()
    assert not any(name.startswith(session.id) for name in _files(session.folder))


def test_the_autosave_interval_setting_is_used(make_window, synthetic_model_path, qtbot):
    QSettings().setValue(settings.AUTOSAVE_INTERVAL, 0.05)
    window = make_window(synthetic_model_path)
    assert window.autosaver.timer.interval() == 50
    _paint(window.document)
    qtbot.waitUntil(window.autosaver.session.has_copy, timeout=5000)


def _orphan(folder: Path, original: Path | None, weight: float = 0.25) -> tuple[RecoverySession, dict]:
    """A recovery copy whose process is gone: written, then its lock dropped without cleaning up."""
    document = ModelDocument(engine.load_model(original) if original else build_synthetic_model(), original)
    _paint(document, weight)
    session = RecoverySession(folder)
    session.write(document)
    session._lock.unlock()                    # what the kernel does for a process killed with -9
    return session, model_state(document.model)


@pytest.fixture
def copy_of_head(tmp_path, synthetic_model_path) -> Path:
    path = engine.save_model(engine.load_model(synthetic_model_path), tmp_path / "head.xml")
    old = time.time() - 3600                  # saved an hour ago, before the crash
    for p in (path, path.with_suffix(".h5")):
        os.utime(p, (old, old))
    return path


def test_an_orphaned_copy_is_offered_and_recovered(window, copy_of_head, monkeypatch):
    folder = window.autosaver.session.folder
    orphan, painted = _orphan(folder, copy_of_head)
    asked = []
    monkeypatch.setattr(window.files, "ask_recover", lambda entry: asked.append(entry) or Button.Yes)

    assert window.files.offer_recovery()
    assert [e.session for e in asked] == [orphan.id] and asked[0].original == copy_of_head
    assert model_state(window.document.model) == painted
    assert window.document.path == copy_of_head
    assert window.isWindowModified() and window.windowTitle() == "head.xml[*] — Artificial Person"
    assert not orphan.info_path.exists()                          # the orphan is gone …
    assert window.autosaver.session.has_copy()                    # … our own copy replaces it
    assert window.document.undo_stack.count() == 0


def test_discard_deletes_the_copy_and_later_keeps_it(window, copy_of_head, monkeypatch):
    folder = window.autosaver.session.folder
    orphan, _ = _orphan(folder, copy_of_head)
    before = model_state(window.document.model)
    monkeypatch.setattr(window.files, "ask_recover", lambda entry: Button.Ignore)
    assert not window.files.offer_recovery()
    assert orphan.info_path.exists() and model_state(window.document.model) == before
    monkeypatch.setattr(window.files, "ask_recover", lambda entry: Button.Discard)
    assert not window.files.offer_recovery()
    assert not orphan.info_path.exists() and not orphan.model_path.exists()
    assert orphaned_entries(folder) == []


def test_a_copy_older_than_its_saved_file_is_dropped_unasked(window, copy_of_head, monkeypatch):
    folder = window.autosaver.session.folder
    orphan, _ = _orphan(folder, copy_of_head)
    engine.save_model(engine.load_model(copy_of_head), copy_of_head)    # saved again after the copy
    monkeypatch.setattr(window.files, "ask_recover", lambda entry: pytest.fail("asked about a stale copy"))
    assert not window.files.offer_recovery()
    assert not orphan.info_path.exists()


def test_a_running_workbench_keeps_its_copy(window, make_window, synthetic_model_path):
    other = make_window(synthetic_model_path)
    _paint(other.document)
    other.autosaver.autosave_now()
    assert orphaned_entries(window.autosaver.session.folder) == []      # its lock is held: not an orphan


def test_never_saved_models_are_recovered_untitled(window, monkeypatch):
    _orphan_entry, painted = _orphan(window.autosaver.session.folder, None)
    monkeypatch.setattr(window.files, "ask_recover", lambda entry: Button.Yes)
    assert window.files.offer_recovery()
    assert window.document.path is None and window.windowTitle() == "untitled[*] — Artificial Person"
    assert model_state(window.document.model) == painted


# ---------------------------------------------------------------------------
# for real: a workbench process killed with SIGKILL, then started again
# ---------------------------------------------------------------------------

def _workbench(model: Path, home: Path, **hooks) -> subprocess.Popen:
    """``python -m workbench MODEL`` on this test's display, with its own settings and data folders."""
    env = dict(os.environ, XDG_CONFIG_HOME=str(home / "config"), XDG_DATA_HOME=str(home / "data"),
               **{f"AP_WORKBENCH_TEST_{k.upper()}": v for k, v in hooks.items()})
    return subprocess.Popen([sys.executable, "-m", "workbench", str(model)], cwd=PROJECT_ROOT, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def _wait_for(condition, timeout: float, process: subprocess.Popen) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        if process.poll() is not None:
            pytest.fail(f"the workbench exited early ({process.returncode}):\n{process.stdout.read()}")
        if time.monotonic() > deadline:
            process.kill()
            pytest.fail(f"timed out; workbench output:\n{process.communicate()[0]}")
        time.sleep(0.1)


@pytest.mark.slow
def test_a_killed_workbench_s_changes_are_recovered_at_the_next_start(copy_of_head, tmp_path):
    home = tmp_path / "home"
    # The real setting, in the real settings file: autosave every 0.3 s.
    conf = home / "config" / "Artificial Person" / "Artificial Person Workbench.conf"
    conf.parent.mkdir(parents=True)
    conf.write_text("[autosave]\ninterval_seconds=0.3\n")
    recovery = home / "data" / "Artificial Person" / "Artificial Person Workbench" / "recovery"
    original = model_state(engine.load_model(copy_of_head))

    # 1. Start, paint brow_raise's region to 0.5, wait for the autosave, kill -9.
    first = _workbench(copy_of_head, home, edit="weights brow_raise 0.5")
    _wait_for(lambda: any(recovery.glob("*.json")), 60, first)
    os.kill(first.pid, signal.SIGKILL)
    assert first.wait(10) == -signal.SIGKILL
    first.stdout.close()
    left = _files(recovery)
    assert any(n.endswith(".lock") for n in left) and any(n.endswith(".h5") for n in left)

    # 2. Start again: the recovery offer is accepted; the hook reports the window and quits cleanly.
    report = tmp_path / "report.json"
    second = _workbench(copy_of_head, home, recovery="recover", report=str(report))
    try:
        output, _ = second.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        second.kill()
        pytest.fail(f"the second workbench did not finish:\n{second.communicate()[0]}")
    assert second.returncode == 0, output
    state = json.loads(report.read_text())
    assert state["modified"] is True
    assert state["title"] == "head.xml[*] — Artificial Person"
    assert state["document_path"] == str(copy_of_head)

    recovered = engine.load_model(state["model_copy"])
    weights = recovered.regions["brow_raise"].weights
    assert len(weights) > 0 and np.all(weights == 0.5)
    painted = engine.load_model(copy_of_head)
    region = painted.regions["brow_raise"]
    painted.set_region("brow_raise", engine.InfluenceRegion(region.indices, np.full(len(region.indices), 0.5)))
    expected = model_state(painted)
    assert model_state(recovered) == expected                 # the edit, and nothing else, came back
    assert model_state(engine.load_model(copy_of_head)) == original     # the file itself was never touched
    assert _files(recovery) == []                             # clean shutdown: no copies, no locks
