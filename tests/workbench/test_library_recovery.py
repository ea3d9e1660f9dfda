"""Autosave and crash recovery of the library editor's unsaved text: in this process, and for real
with a workbench that is killed with SIGKILL while the text is unsaved."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
import weakref
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QMessageBox, QWidget

import engine
from tests.workbench.test_library_editor import GOOD, forget_library_edits, type_text
from tests.workbench.test_recovery import PROJECT_ROOT, _files, _orphan, _wait_for
from workbench import settings
from workbench.window.recovery import RecoverySession, orphaned_entries, orphaned_library_copies

Button = QMessageBox.StandardButton
TYPED = "# typed before the crash\n$command = Shrug\n$mandatory = at\nbrow_raise = 0,0; 100,1; 300,0\n$proc = once"


@pytest.fixture
def window(qtbot, make_window, synthetic_model_path):
    """The main window on the synthetic head; its library edits are forgotten before pytest-qt closes it."""
    windows = []
    sentinel = QWidget()
    qtbot.addWidget(sentinel, before_close_func=lambda _w: [forget_library_edits(w()) for w in windows])
    window = make_window(synthetic_model_path)
    windows.append(weakref.ref(window))
    window.library_test_sentinel = sentinel
    return window


@pytest.fixture
def editor(window):
    window.library_editor_dock.show()
    return window.library_editor


@pytest.fixture
def library_file(tmp_path) -> Path:
    """A library file saved an hour ago, before any crash."""
    path = tmp_path / "library" / "BrowSwing.lib"
    path.parent.mkdir()
    path.write_text(GOOD, encoding="utf-8")
    old = time.time() - 3600
    os.utime(path, (old, old))
    return path


@pytest.fixture
def copy_of_head(tmp_path, synthetic_model_path) -> Path:
    """The synthetic head saved an hour ago, before any crash."""
    path = engine.save_model(engine.load_model(synthetic_model_path), tmp_path / "head.xml")
    old = time.time() - 3600
    for p in (path, path.with_suffix(".h5")):
        os.utime(p, (old, old))
    return path


def _copy(session: RecoverySession) -> dict:
    return json.loads(session.library_path.read_text(encoding="utf-8"))


def _orphan_text(folder: Path, text: str, original: Path | None) -> RecoverySession:
    """A library text left by a process that is gone: written, then its lock dropped without cleaning up."""
    session = RecoverySession(folder)
    session.write_library_text(text, original)
    session._lock.unlock()                # what the kernel does for a process killed with -9
    return session


# ---------------------------------------------------------------------------
# in this process
# ---------------------------------------------------------------------------

def test_unsaved_text_is_autosaved_and_a_clean_save_leaves_nothing(window, editor, qtbot, tmp_path):
    autosaver, session = editor.autosaver, window.autosaver.session
    assert not autosaver.timer.isActive() and not autosaver.autosave_now()      # nothing unsaved
    editor.text.setFocus()
    type_text(qtbot, editor.text, "$command = Wave")
    assert editor.is_modified
    assert autosaver.timer.isActive() and autosaver.timer.interval() == window.autosaver.timer.interval()

    assert autosaver.autosave_now()
    copy = _copy(session)
    assert copy["format"] == "artificial-person-library-recovery" and copy["version"] == 1
    assert copy["original"] is None and copy["text"] == "$command = Wave"       # a new file
    assert not autosaver.autosave_now()                                          # unchanged since
    type_text(qtbot, editor.text, "\nbrow_raise = 1")
    assert autosaver.autosave_now() and _copy(session)["text"] == "$command = Wave\nbrow_raise = 1"
    assert not session.has_copy()                  # the model's own copy is another file, not written

    target = tmp_path / "Wave.lib"
    assert editor.save_as(target)
    assert not session.has_library_copy() and not autosaver.timer.isActive()
    assert [n for n in _files(session.folder) if n.startswith(session.id)] == [f"{session.id}.lock"]
    assert target.read_text() == "$command = Wave\nbrow_raise = 1"

    type_text(qtbot, editor.text, "\n# more")       # edits to a saved file name the file
    assert autosaver.autosave_now() and _copy(session)["original"] == str(target)


def test_closing_the_window_cleanly_removes_the_copy(window, editor, qtbot, monkeypatch):
    session = window.autosaver.session
    editor.set_text(GOOD, modified=True)
    assert editor.autosaver.autosave_now() and session.has_library_copy()
    monkeypatch.setattr(editor, "ask_unsaved", lambda reason: Button.Discard)
    assert window.close()
    assert not any(name.startswith(session.id) for name in _files(session.folder))


def test_discarding_the_edits_drops_the_copy_and_new_edits_are_kept(window, editor, qtbot, monkeypatch):
    session = window.autosaver.session
    editor.set_text(GOOD, modified=True)
    assert editor.autosaver.autosave_now()
    monkeypatch.setattr(editor, "ask_unsaved", lambda reason: Button.Discard)
    assert editor.maybe_save("opening another file")
    assert not session.has_library_copy() and not editor.autosaver.autosave_now()

    editor.text.setFocus()
    type_text(qtbot, editor.text, "# typed after Discard")    # new edits: worth keeping, and asked about
    assert not editor.edits_discarded and editor.autosaver.autosave_now()
    asked = []
    monkeypatch.setattr(editor, "ask_unsaved", lambda reason: asked.append(reason) or Button.Cancel)
    assert not editor.maybe_save("closing") and asked == ["closing"]


def test_a_failed_autosave_is_said_and_tried_again(window, editor, monkeypatch):
    session = window.autosaver.session
    editor.set_text(GOOD, modified=True)

    def full_disk(text, original):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(session, "write_library_text", full_disk)
    assert not editor.autosaver.autosave_now()
    assert "Autosave of the library file failed" in window.statusBar().currentMessage()
    monkeypatch.delattr(session, "write_library_text")          # the disk has room again
    assert editor.autosaver.autosave_now() and session.has_library_copy()


def test_the_autosave_runs_on_the_model_s_interval(make_window, synthetic_model_path, qtbot):
    QSettings().setValue(settings.AUTOSAVE_INTERVAL, 0.05)
    window = make_window(synthetic_model_path)
    editor = window.library_editor
    try:
        editor.set_text(GOOD, modified=True)
        assert editor.autosaver.timer.interval() == 50
        qtbot.waitUntil(window.autosaver.session.has_library_copy, timeout=5000)
    finally:
        forget_library_edits(window)              # marked saved: the copy goes, and closing asks nothing
    assert not window.autosaver.session.has_library_copy()


def test_an_orphaned_text_is_offered_and_recovered_without_touching_the_file(window, editor, library_file,
                                                                             monkeypatch):
    folder = window.autosaver.session.folder
    edited = GOOD.replace("count=2", "count=5")
    orphan = _orphan_text(folder, edited, library_file)
    asked = []
    monkeypatch.setattr(editor, "ask_recover", lambda copy: asked.append(copy) or Button.Yes)
    window.library_editor_dock.hide()

    assert editor.offer_recovery()
    assert [c.session for c in asked] == [orphan.id] and asked[0].original == library_file
    assert editor.text.toPlainText() == edited and editor.path == library_file
    assert editor.is_modified and editor.title() == "Library editor — BrowSwing.lib*"
    assert editor.form.spin_boxes["count"].value() == 5          # checked and bound like typed text
    assert window.library_editor_dock.isVisible()
    assert library_file.read_text() == GOOD                       # the file itself is not written
    assert not orphan.library_path.exists()                       # the orphan is gone …
    assert _copy(window.autosaver.session)["text"] == edited      # … our own copy replaces it
    assert orphaned_library_copies(folder) == []


def test_model_and_library_copies_of_one_session_are_offered_each(window, editor, copy_of_head, monkeypatch):
    folder = window.autosaver.session.folder
    model_orphan, _ = _orphan(folder, copy_of_head)
    model_orphan.write_library_text("# recovered text", None)      # the same dead session
    assert [c.session for c in orphaned_library_copies(folder)] == [model_orphan.id]
    monkeypatch.setattr(window.files, "ask_recover", lambda entry: Button.Yes)
    assert window.files.offer_recovery()
    assert model_orphan.library_path.exists()                      # recovering the model keeps the text
    monkeypatch.setattr(editor, "ask_recover", lambda copy: Button.Yes)
    assert editor.offer_recovery()
    assert editor.path is None and editor.title() == "Library editor — untitled.lib*"
    assert editor.text.toPlainText() == "# recovered text"
    assert orphaned_entries(folder) == [] and orphaned_library_copies(folder) == []


def test_later_keeps_the_copy_and_discard_deletes_it(window, editor, library_file, monkeypatch):
    folder = window.autosaver.session.folder
    orphan = _orphan_text(folder, "# edited", library_file)
    monkeypatch.setattr(editor, "ask_recover", lambda copy: Button.Ignore)
    assert not editor.offer_recovery()
    assert orphan.library_path.exists() and editor.is_blank and not editor.is_modified
    monkeypatch.setattr(editor, "ask_recover", lambda copy: Button.Discard)
    assert not editor.offer_recovery()
    assert not orphan.library_path.exists() and orphaned_library_copies(folder) == []
    assert editor.is_blank and not editor.is_modified and library_file.read_text() == GOOD


def test_a_copy_older_than_its_file_and_an_unreadable_one_are_dropped_unasked(window, editor, library_file,
                                                                             monkeypatch):
    folder = window.autosaver.session.folder
    stale = _orphan_text(folder, "# edited", library_file)
    library_file.write_text(GOOD + "# saved again after the crash\n")
    broken = RecoverySession(folder)
    broken.library_path.write_text('{"format": "artificial-person-library-recovery", "version": 1}')
    broken._lock.unlock()
    monkeypatch.setattr(editor, "ask_recover", lambda copy: pytest.fail("asked about a stale copy"))
    assert not editor.offer_recovery()
    assert not stale.library_path.exists() and not broken.library_path.exists()


def test_a_running_workbench_keeps_its_text(window, make_window, synthetic_model_path):
    other = make_window(synthetic_model_path)
    other.library_editor.set_text(GOOD, modified=True)
    assert other.library_editor.autosaver.autosave_now()
    assert orphaned_library_copies(window.autosaver.session.folder) == []      # its lock is held
    forget_library_edits(other)


# ---------------------------------------------------------------------------
# for real: a workbench process killed with SIGKILL, then started again
# ---------------------------------------------------------------------------

def _process(home: Path, *args: str) -> subprocess.Popen:
    """The workbench with a scripted library editor (``tests/workbench/library_editor_process.py``)."""
    env = dict(os.environ, XDG_CONFIG_HOME=str(home / "config"), XDG_DATA_HOME=str(home / "data"))
    return subprocess.Popen([sys.executable, "-m", "tests.workbench.library_editor_process", *map(str, args)],
                            cwd=PROJECT_ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


@pytest.mark.slow
@pytest.mark.parametrize("answer", ["recover", "discard"])
def test_a_killed_workbench_s_library_text_is_offered_at_the_next_start(answer, library_file, synthetic_model_path,
                                                                         tmp_path):
    home = tmp_path / "home"
    conf = home / "config" / "Artificial Person" / "Artificial Person Workbench.conf"
    conf.parent.mkdir(parents=True)
    conf.write_text("[autosave]\ninterval_seconds=0.3\n")
    recovery = home / "data" / "Artificial Person" / "Artificial Person Workbench" / "recovery"

    # 1. Start, open the library file in the library editor, type, wait for the autosave, kill -9.
    first = _process(home, "edit", synthetic_model_path, library_file, TYPED)

    def autosaved() -> bool:
        return any("$proc = once" in p.read_text(encoding="utf-8") for p in recovery.glob("*.library.json"))

    _wait_for(autosaved, 60, first)
    os.kill(first.pid, signal.SIGKILL)
    assert first.wait(10) == -signal.SIGKILL
    first.stdout.close()
    left = _files(recovery)
    assert len(left) == 2 and left[0].endswith(".library.json") and left[1].endswith(".lock")
    assert library_file.read_text() == GOOD                       # never saved: the file is as it was

    # 2. Start again: the offer is answered; the process reports the editor and closes.
    report = tmp_path / "report.json"
    second = _process(home, answer, synthetic_model_path, report)
    try:
        output, _ = second.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        second.kill()
        pytest.fail(f"the second workbench did not finish:\n{second.communicate()[0]}")
    assert second.returncode == 0, output
    state = json.loads(report.read_text())
    assert len(state["asked"]) == 1 and state["asked"][0]["original"] == str(library_file)
    if answer == "recover":
        assert state["text"] == GOOD + TYPED
        assert state["path"] == str(library_file) and state["modified"] is True
        assert state["title"] == "Library editor — BrowSwing.lib*" and state["dock_visible"]
        assert state["own_copy"]                                  # autosaved again, in the new session
    else:
        assert state["text"] == "" and state["path"] is None and state["modified"] is False
        assert not state["own_copy"]
    assert library_file.read_text() == GOOD                       # recovering never writes the file
    assert _files(recovery) == []                                 # clean shutdown: no copies, no locks
