"""Autosave and crash recovery: unsaved changes survive a crash, a kill or a power cut.

While the workbench runs it owns one *recovery session* in the recovery
folder (``<AppLocalDataLocation>/recovery``, on Linux
``~/.local/share/Artificial Person/Artificial Person Workbench/recovery``):

* ``<id>.lock``: a :class:`QLockFile` held as long as the process lives;
* ``<id>.xml`` + ``<id>.h5``: the model, written by :func:`engine.save_model`
  (atomically) every ``autosave/interval_seconds`` while it is modified;
* ``<id>.json``: what the copy is (format ``artificial-person-recovery``,
  version 1): the file it belongs to and when it was written. Written last,
  so a session with a ``.json`` always has a complete model. An autosave
  killed half-way (``kill -9``, a power cut) leaves the previous copy or the
  new one, whole: the model pair's renames are journalled and finished when
  the orphans are listed (:func:`engine.formats.atomic.finish_interrupted_writes`),
  which also removes the dead process's temporary files; a model killed
  before its first ``.json`` is removed, as it was never offered.
* ``<id>.library.json``: the library editor's unsaved text (format
  ``artificial-person-library-recovery``, version 1): the text itself, the
  library file it belongs to (``null`` for a new file) and when it was
  written, in one atomic write.

When the model is saved (or undone back to its saved state) its copy is
deleted, and likewise the library text's when the library file is saved or
its edits discarded; a clean shutdown deletes the whole session. A session
whose lock nobody holds any more (the process died) is *orphaned*: at the
next start the workbench offers to recover its model and its library text,
each if it is newer than the file it belongs to; otherwise it is stale and
removed.
"""

from __future__ import annotations

import contextlib
import json
import os
import time
import uuid
from dataclasses import dataclass
from pathlib import Path

from PySide6.QtCore import QLockFile, QObject, QStandardPaths, QTimer, Signal

import engine
from engine.formats.atomic import atomic_write_text, finish_interrupted_writes

from ..document.model_document import ModelDocument

RECOVERY_FORMAT = "artificial-person-recovery"
RECOVERY_VERSION = 1
LIBRARY_RECOVERY_FORMAT = "artificial-person-library-recovery"
LIBRARY_RECOVERY_VERSION = 1
LIBRARY_SUFFIX = ".library.json"
MODEL_SUFFIXES = (".json", ".xml", ".h5")   # the description first: see _remove_session_files


def recovery_dir() -> Path:
    """The folder recovery sessions live in (not created here)."""
    base = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.AppLocalDataLocation)
    return Path(base) / "recovery"


@dataclass(frozen=True)
class _OrphanedCopy:
    """What a workbench that did not shut down cleanly left in its recovery session, and whose file it was."""

    folder: Path
    session: str
    original: Path | None      # the file the copy belongs to; None for one never saved
    saved_at: float            # seconds since the epoch

    def is_newer_than_original(self) -> bool:
        """True unless the original file was saved after this copy was made."""
        if self.original is None or not self.original.exists():
            return True
        return self.saved_at > self.original.stat().st_mtime


@dataclass(frozen=True)
class RecoveryEntry(_OrphanedCopy):
    """An orphaned autosave: the model left behind by a workbench that did not shut down cleanly."""

    model_name: str

    @property
    def model_path(self) -> Path:
        return self.folder / f"{self.session}.xml"

    def load(self) -> engine.Model:
        return engine.load_model(self.model_path)

    def remove(self) -> None:
        _remove_session_files(self.folder, self.session)


@dataclass(frozen=True)
class LibraryCopy(_OrphanedCopy):
    """An orphaned library-editor text: unsaved edits left by a workbench that did not shut down cleanly."""

    text: str

    @property
    def path(self) -> Path:
        return self.folder / f"{self.session}{LIBRARY_SUFFIX}"

    def display_name(self) -> str:
        return self.original.name if self.original is not None else "untitled.lib"

    def remove(self) -> None:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(self.path)


def orphaned_entries(folder: str | Path | None = None) -> list[RecoveryEntry]:
    """Model copies no running workbench owns, newest first.

    Sessions still locked by a live process are left alone; unreadable
    session descriptions are skipped (and removed with their files).
    """
    folder = Path(folder) if folder is not None else recovery_dir()
    if folder.is_dir():
        finish_interrupted_writes(folder)   # an autosave killed half-way: its renames done, its temporaries gone
    entries = []
    for folder_, session in _orphaned_sessions(folder, ".json"):
        entry = _read_entry(folder_ / f"{session}.json")
        if entry is None:
            _remove_session_files(folder_, session)
        else:
            entries.append(entry)
    for folder_, session in _orphaned_sessions(folder, ".xml"):
        if not (folder_ / f"{session}.json").exists():
            _remove_session_files(folder_, session)     # killed before its description was written: never offered
    return sorted(entries, key=lambda e: e.saved_at, reverse=True)


def orphaned_library_copies(folder: str | Path | None = None) -> list[LibraryCopy]:
    """Library-editor texts no running workbench owns, newest first (unreadable ones are removed)."""
    copies = []
    for folder_, session in _orphaned_sessions(folder, LIBRARY_SUFFIX):
        copy = _read_library_copy(folder_, session)
        if copy is None:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(folder_ / f"{session}{LIBRARY_SUFFIX}")
        else:
            copies.append(copy)
    return sorted(copies, key=lambda c: c.saved_at, reverse=True)


def _orphaned_sessions(folder: str | Path | None, suffix: str) -> list[tuple[Path, str]]:
    """``(folder, session)`` for each file ``<session><suffix>`` whose session lock nobody holds."""
    folder = Path(folder) if folder is not None else recovery_dir()
    if not folder.is_dir():
        return []
    sessions = []
    for path in folder.glob(f"*{suffix}"):
        session = path.name[:-len(suffix)]
        if "." in session:
            continue                    # another kind of file (``<id>.library.json`` for ``.json``)
        lock = QLockFile(str(folder / f"{session}.lock"))
        lock.setStaleLockTime(0)        # stale only when its process is gone, never by age
        if not lock.tryLock(0):
            continue                    # a running workbench owns it
        lock.unlock()
        sessions.append((folder, session))
    return sessions


def _read_library_copy(folder: Path, session: str) -> LibraryCopy | None:
    try:
        data = json.loads((folder / f"{session}{LIBRARY_SUFFIX}").read_text(encoding="utf-8"))
        if (data.get("format") != LIBRARY_RECOVERY_FORMAT
                or int(data.get("version", 0)) != LIBRARY_RECOVERY_VERSION):
            return None
        original = data.get("original")
        text = data["text"]
        if not isinstance(text, str):
            return None
        return LibraryCopy(folder, session, Path(original) if original else None, float(data["saved_at"]), text)
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return None


def _read_entry(info: Path) -> RecoveryEntry | None:
    try:
        data = json.loads(info.read_text(encoding="utf-8"))
        if data.get("format") != RECOVERY_FORMAT or int(data.get("version", 0)) != RECOVERY_VERSION:
            return None
        original = data.get("original")
        entry = RecoveryEntry(info.parent, info.stem, Path(original) if original else None,
                              float(data["saved_at"]), str(data.get("model_name", "")))
    except (OSError, ValueError, KeyError, TypeError):
        return None
    return entry if entry.model_path.exists() else None


def _remove_session_files(folder: Path, session: str) -> None:
    # The description first: without it nobody will try to read a half-removed model.
    for suffix in MODEL_SUFFIXES:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(folder / f"{session}{suffix}")


class RecoverySession:
    """This process's slot in the recovery folder, locked while the process lives."""

    def __init__(self, folder: str | Path | None = None):
        self.folder = Path(folder) if folder is not None else recovery_dir()
        self.folder.mkdir(parents=True, exist_ok=True)
        self.id = f"{time.strftime('%Y%m%d-%H%M%S')}-{os.getpid()}-{uuid.uuid4().hex[:8]}"
        self._lock = QLockFile(str(self.folder / f"{self.id}.lock"))
        self._lock.setStaleLockTime(0)
        self._lock.tryLock(0)           # a fresh unique name: nobody else can hold it

    @property
    def model_path(self) -> Path:
        return self.folder / f"{self.id}.xml"

    @property
    def info_path(self) -> Path:
        return self.folder / f"{self.id}.json"

    def write(self, document: ModelDocument) -> None:
        """Save the document's model as this session's recovery copy (model first, then its description)."""
        document.save_copy(self.model_path)
        info = {"format": RECOVERY_FORMAT, "version": RECOVERY_VERSION,
                "original": str(document.path) if document.path is not None else None,
                "saved_at": time.time(), "model_name": document.model.name, "pid": os.getpid()}
        atomic_write_text(self.info_path, json.dumps(info, indent=2) + "\n")

    def has_copy(self) -> bool:
        return self.info_path.exists()

    def clear(self) -> None:
        """Forget the model's recovery copy (the model was saved, or went back to its saved state)."""
        _remove_session_files(self.folder, self.id)

    @property
    def library_path(self) -> Path:
        return self.folder / f"{self.id}{LIBRARY_SUFFIX}"

    def write_library_text(self, text: str, original: Path | None) -> None:
        """Keep the library editor's unsaved ``text`` (of file ``original``; ``None``: a new file), atomically."""
        info = {"format": LIBRARY_RECOVERY_FORMAT, "version": LIBRARY_RECOVERY_VERSION,
                "original": str(original) if original is not None else None,
                "saved_at": time.time(), "pid": os.getpid(), "text": text}
        atomic_write_text(self.library_path, json.dumps(info, indent=2, ensure_ascii=False) + "\n")

    def has_library_copy(self) -> bool:
        return self.library_path.exists()

    def clear_library(self) -> None:
        """Forget the library text's copy (the file was saved, or its edits discarded)."""
        with contextlib.suppress(FileNotFoundError):
            os.unlink(self.library_path)

    def close(self) -> None:
        """Clean shutdown: remove every copy and release the lock (which deletes the lock file)."""
        self.clear()
        self.clear_library()
        if self._lock.isLocked():
            self._lock.unlock()


class Autosaver(QObject):
    """Every ``interval_seconds``, writes the document to its recovery session if it changed.

    Signals
    -------
    autosaved(str)
        The recovery copy was written to this path.
    failed(str)
        Writing it failed; the message says why.
    """

    autosaved = Signal(str)
    failed = Signal(str)

    def __init__(self, document: ModelDocument, session: RecoverySession, interval_seconds: float,
                 parent: QObject | None = None):
        super().__init__(parent)
        self._document = document
        self.session = session
        self._saved_generation: int | None = None
        self.timer = QTimer(self)
        self.timer.setInterval(max(1, round(interval_seconds * 1000)))
        self.timer.timeout.connect(self.autosave_now)
        document.modified_changed.connect(self._on_modified_changed)
        self.timer.start()

    def autosave_now(self) -> bool:
        """Write the recovery copy now if the model is modified and changed since the last one."""
        document = self._document
        if not document.is_modified:
            return False
        if document.generation == self._saved_generation and self.session.has_copy():
            return False
        try:
            self.session.write(document)
        except (engine.UserError, OSError) as exc:
            self.failed.emit(str(exc))
            return False
        self._saved_generation = document.generation
        self.autosaved.emit(str(self.session.model_path))
        return True

    def stop(self) -> None:
        self.timer.stop()

    def _on_modified_changed(self, modified: bool) -> None:
        if not modified:
            self.session.clear()
            self._saved_generation = None
