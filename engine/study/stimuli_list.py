"""What a study shows: the trials of a stimulus set (each stimulus as a still and as a video) and of a human table.

A set made by ``artificial-person stimuli`` says, in its ``manifest.csv``, every stimulus's factor levels
and files with their SHA-256; its emotion comes from the ``expression`` factor (at ``intensity`` 0 it is
neutral; engine.validation.intended) or from the factor the design names. A human comparison table
(``[human] table``) lists a lab's photographs and videos::

    file,emotion,presentation,actor
    actors/a1-happy.jpg,happy,static,a1
    actors/a1-happy.mp4,happy,dynamic,a1

(``presentation`` may be left out: pictures are static, videos dynamic; every other column is a level
copied into the data). Every mistake names the table and the line.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from engine.errors import UserError
from engine.formats.csv_tables import read_table
from engine.validation.intended import EXPRESSION_CLASSES, stimulus_intended

__all__ = ["IMAGE_SUFFIXES", "VIDEO_SUFFIXES", "SetListing", "TrialSpec", "human_specs", "read_set", "set_specs",
           "sha256_file"]

IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg", ".webp", ".gif")
VIDEO_SUFFIXES = (".mp4", ".webm")
MAX_HUMAN_FILE = 2 * 1024**3
CLOCK_COLUMNS = ("duration_ms", "audio_start_ms", "video_start_ms", "speech_onset_ms", "expression_apex_ms",
                 "still_ms")
_ID = re.compile(r"^[A-Za-z0-9_-]{1,64}$")
_LEVEL_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]{0,63}$")


@dataclass
class TrialSpec:
    """One thing a participant is shown: a stimulus in one presentation."""

    stimulus: str
    source: str
    """``synthetic`` (from the set) or ``human`` (from the human table)."""
    presentation: str
    """``static`` or ``dynamic``."""
    media: str
    """``image``, ``video`` or ``live`` (the web player)."""
    file: str
    """Where the file is in the study's folder (``stimuli/0001.png``); for ``live``, the stimulus id."""
    source_path: Path | None
    sha256: str
    intended: str
    levels: dict[str, str] = field(default_factory=dict)
    clock: dict[str, float | None] = field(default_factory=dict)
    words: list[dict[str, Any]] = field(default_factory=list)
    """Each word and its onset on the clip's clock (ms), from the manifest."""

    def document(self) -> dict[str, Any]:
        return {"stimulus": self.stimulus, "source": self.source, "presentation": self.presentation,
                "media": self.media, "file": self.file, "intended": self.intended, "levels": self.levels,
                "clock": self.clock, "words": self.words}


@dataclass
class SetListing:
    folder: Path
    manifest: Path
    manifest_sha256: str
    factors: list[str]
    rows: list[tuple[int, dict[str, str]]]


def sha256_file(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as stream:
        while chunk := stream.read(1 << 20):
            digest.update(chunk)
    return digest.hexdigest()


def read_set(folder: Path) -> SetListing:
    """The set's manifest: its rows, its factors (the columns between ``id`` and the first file), its SHA-256."""
    manifest = folder / "manifest.csv"
    if not manifest.is_file():
        raise UserError("no manifest.csv here: name the folder a stimulus set was made in", file=manifest)
    header, rows = read_table(manifest, what="stimulus manifest")
    if not header or header[0] != "id":
        raise UserError("not a stimulus set's manifest (its first column is not 'id')", file=manifest, line=1)
    first_file = next((i for i, name in enumerate(header) if name.startswith("file_")), None)
    if first_file is None:
        raise UserError("the manifest names no stimulus files", file=manifest, line=1)
    if not rows:
        raise UserError("the manifest lists no stimulus", file=manifest, line=1)
    seen: set[str] = set()
    for line, row in rows:
        if not _ID.match(row["id"]):
            raise UserError(f"stimulus id {row['id'][:40]!r} is not letters, digits, '-' or '_'", file=manifest,
                            line=line)
        if row["id"] in seen:
            raise UserError(f"stimulus {row['id']} is listed twice", file=manifest, line=line)
        seen.add(row["id"])
    return SetListing(folder, manifest, sha256_file(manifest), header[1:first_file], rows)


def set_specs(listing: SetListing, presentations: tuple[str, ...], dynamic: str, emotion_factor: str,
              check_files: bool = True) -> list[TrialSpec]:
    """Every stimulus of the set in every presentation, its files checked against the manifest's SHA-256."""
    header = set(listing.rows[0][1]) if listing.rows else set()
    needs = {"static": ["png"], "dynamic": ["tracks", "wav"] if dynamic == "live" else []}
    for presentation in presentations:
        for kind in needs[presentation]:
            if f"file_{kind}" not in header:
                raise UserError(f"the {presentation} condition needs each stimulus's {kind}: make the set with "
                                f"\"{kind}\" among [output] kinds", file=listing.manifest, line=1)
    if "dynamic" in presentations and dynamic == "video" and not {"file_mp4", "file_silent-mp4"} & header:
        raise UserError("the dynamic condition needs each stimulus's video: make the set with \"mp4\" among "
                        "[output] kinds (or dynamic = \"live\" with tracks and wav)", file=listing.manifest, line=1)
    if emotion_factor != "expression" and emotion_factor not in listing.factors:
        raise UserError(f"the set has no factor '{emotion_factor}' (its factors: {', '.join(listing.factors)})",
                        file=listing.manifest, line=1)
    specs = []
    for line, row in listing.rows:
        intended = _set_emotion(row, emotion_factor, listing.manifest, line)
        levels = {name: row.get(name, "") for name in listing.factors}
        clock = {name: _number(row.get(name, ""), listing.manifest, line, name) for name in CLOCK_COLUMNS}
        words = _words(row, listing.manifest, line)
        for presentation in presentations:
            if presentation == "static":
                kind, media = "png", "image"
            elif dynamic == "live":
                kind, media = "wav", "live"
            else:
                kind, media = ("mp4" if row.get("file_mp4") else "silent-mp4"), "video"
            path, digest = _set_file(listing, row, kind, line, check_files)
            file = row["id"] if media == "live" else f"stimuli/{Path(row[f'file_{kind}']).name}"
            specs.append(TrialSpec(row["id"], "synthetic", presentation, media, file, None if media == "live" else path,
                                   digest, intended, levels, clock, words))
    return specs


def _words(row: dict[str, str], manifest: Path, line: int) -> list[dict[str, Any]]:
    words = [w for w in (row.get("words") or "").split(";") if w]
    onsets = [_number(t, manifest, line, "word_onsets_ms") for t in (row.get("word_onsets_ms") or "").split(";") if t]
    if len(words) != len(onsets):
        raise UserError("words and word_onsets_ms do not pair up", file=manifest, line=line)
    return [{"word": w, "start_ms": t} for w, t in zip(words, onsets, strict=True)]


def _set_emotion(row: dict[str, str], factor: str, manifest: Path, line: int) -> str:
    if factor == "expression":
        emotion = stimulus_intended(row, manifest=manifest, line=line).emotion
        if emotion is not None:
            return emotion
        text = (row.get("expression") or "").strip().lower()
    else:
        text = (row.get(factor) or "").strip().lower()
        text = EXPRESSION_CLASSES.get(text, text)
    value = re.sub(r"[^a-z0-9_]+", "_", text).strip("_")
    if not value or not value[0].isalpha():
        raise UserError(f"stimulus {row['id']}: its {factor} {text[:40]!r} names no emotion", file=manifest, line=line)
    return value[:40]


def _set_file(listing: SetListing, row: dict[str, str], kind: str, line: int, check: bool) -> tuple[Path, str]:
    name = row.get(f"file_{kind}", "")
    path = listing.folder / name
    try:
        inside = bool(name) and not Path(name).is_absolute() and ".." not in Path(name).parts and path.is_file()
    except (OSError, ValueError):
        inside = False
    if not inside:
        raise UserError(f"stimulus {row['id']}: its {kind} file {name[:200]!r} is not in the set's folder",
                        file=listing.manifest, line=line)
    recorded = row.get(f"sha256_{kind}", "")
    if check:
        digest = sha256_file(path)
        if recorded and digest != recorded:
            raise UserError(f"stimulus {row['id']}: {name} has changed since the set was made (its SHA-256 is not "
                            "the manifest's)", file=listing.manifest, line=line)
        return path, digest
    return path, recorded


def _number(text: str, manifest: Path, line: int, name: str) -> float | None:
    if not text.strip():
        return None
    try:
        value = float(text)
    except ValueError:
        raise UserError(f"{name}: {text[:40]!r} is not a number", file=manifest, line=line) from None
    if value != value or abs(value) > 1e12:
        raise UserError(f"{name}: {text[:40]!r} is not a time in ms", file=manifest, line=line)
    return value


def human_specs(table: Path, presentations: tuple[str, ...]) -> list[TrialSpec]:
    """The human comparison's photographs and videos, each checked (a regular file of a known type)."""
    header, rows = read_table(table, what="human comparison table")
    for column in ("file", "emotion"):
        if column not in header:
            raise UserError(f"the human table needs a '{column}' column (file,emotion[,presentation,id,…])",
                            file=table, line=1)
    extra = [name for name in header if name not in ("file", "emotion", "presentation", "id")]
    for name in extra:
        if not _LEVEL_NAME.match(name):
            raise UserError(f"column {name[:40]!r}: a column is a name (letters, digits, '_')", file=table, line=1)
    specs: list[TrialSpec] = []
    used: set[str] = set()
    for line, row in rows:
        specs.append(_human_spec(table, line, row, extra, presentations, used))
    if not specs:
        raise UserError("the human table lists no file", file=table, line=1)
    return specs


def _human_spec(table: Path, line: int, row: dict[str, str], extra: list[str], presentations: tuple[str, ...],
                used: set[str]) -> TrialSpec:
    def fail(message: str) -> UserError:
        return UserError(message, file=table, line=line)

    name = row["file"].strip()
    path = table.parent / name
    try:
        ok = bool(name) and "\x00" not in name and path.is_file()
        size = path.stat().st_size if ok else 0
    except (OSError, ValueError):
        ok, size = False, 0
    if not ok:
        raise fail(f"{name[:200]!r} is not a file (names are relative to the table)")
    if size > MAX_HUMAN_FILE:
        raise fail(f"{name[:200]!r} is larger than 2 GiB")
    suffix = path.suffix.lower()
    if suffix not in IMAGE_SUFFIXES + VIDEO_SUFFIXES:
        raise fail(f"{name[:200]!r}: a picture ({', '.join(IMAGE_SUFFIXES)}) or a video "
                   f"({', '.join(VIDEO_SUFFIXES)}) is needed")
    presentation = (row.get("presentation") or "").strip() or ("static" if suffix in IMAGE_SUFFIXES else "dynamic")
    if presentation not in ("static", "dynamic"):
        raise fail(f"presentation {presentation[:40]!r} is not static or dynamic")
    if (presentation == "static") != (suffix in IMAGE_SUFFIXES):
        raise fail(f"a {presentation} stimulus must be a {'picture' if presentation == 'static' else 'video'}")
    text = row["emotion"].strip().lower()
    if not re.match(r"^[a-z][a-z0-9 _-]{0,39}$", text):
        raise fail(f"emotion {row['emotion'][:40]!r} names no emotion (a word such as happy, or a library "
                   "expression such as Happy)")
    emotion = re.sub(r"[^a-z0-9_]+", "_", EXPRESSION_CLASSES.get(text, text)).strip("_")
    ident = (row.get("id") or "").strip() or f"human-{len(used) + 1:03d}"
    if not _ID.match(ident):
        raise fail(f"id {ident[:40]!r} is not letters, digits, '-' or '_'")
    key = f"{ident}:{presentation}"
    if key in used:
        raise fail(f"{ident} is listed twice as {presentation}")
    used.add(key)
    if presentation not in presentations:
        raise fail(f"the study has no {presentation} condition ([conditions] presentation)")
    file = f"human/{ident}-{presentation}{suffix}"
    return TrialSpec(ident, "human", presentation, "image" if presentation == "static" else "video", file, path,
                     sha256_file(path), emotion, {name: row.get(name, "") for name in extra}, {})
