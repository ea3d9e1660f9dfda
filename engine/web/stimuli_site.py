"""The site of a whole stimulus set (``web-export --stimuli OUTDIR``): one page, every stimulus, every head.

A set made by ``artificial-person stimuli`` with the kinds ``tracks`` and ``wav`` (and, for word
events with their ends, ``phones``) holds every stimulus's performance on its own clip's clock —
the expression, the audio–visual offset, the noise already in. The site keeps them so:

=========================  =============================================================
``stimuli/ID.json``         the stimulus's animation (as ``animation.json`` of one sentence)
``stimuli/ID.wav``          its sound, copied unchanged from the set
``stimuli.json``            the list: each stimulus's id, its manifest row, its files
``head.glb``                the head, with every morph target any of its stimuli moves
``head-2.glb`` …            the other heads of a set with ``model`` or identity factors
=========================  =============================================================

``index.html?stimulus=ID`` plays one (``&t=MS``: paused at MS); ``index.html`` plays the first.
A set whose stimuli have heads of their own is written with the heads made again from its
design (``web-export --stimuli OUTDIR --design DESIGN.toml``: engine.stimuli.set_heads).
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from engine.errors import UserError
from engine.formats.text_files import read_bounded_text
from engine.speech.synthesis import Segment, read_phones_csv, read_wav
from engine.timeline.tracks import read_tracks_csv
from engine.web.site import (
    DEFAULT_SIZE,
    check_folder,
    json_bytes,
    shared_targets,
    site_animation,
    words_of,
    write_folder,
)
from engine.web.web_look import recorded_look
from engine.web.web_model import morph_parameters, web_glb

if TYPE_CHECKING:
    from engine.model import Model
    from engine.outputs.looks import Look

__all__ = ["HEAD_FACTORS", "STIMULI_FORMAT", "HeadsOf", "ListedStimulus", "read_set_listing", "write_stimuli_site"]

STIMULI_FORMAT = "artificial-person-web-stimuli"
#: Factors that give stimuli heads of their own (as engine.stimuli.heads.HEAD_FACTORS, which this layer
#: does not import): each head is made again from the design (``heads``).
HEAD_FACTORS = ("model", "identity", "identity_b", "identity_morph")
#: A stimulus id → (the key of its head, the head); stimuli with one key share one head.
HeadsOf = Callable[[str], "tuple[str, Model]"]
_ID = re.compile(r"^[A-Za-z0-9_-]+$")


@dataclass
class ListedStimulus:
    """One row of a set's manifest, checked: its id, its files (in the set's folder), its words from the manifest."""

    id: str
    line: int
    row: dict[str, str]
    tracks: Path
    audio: Path
    phones: Path | None
    manifest_words: list[Segment]


def read_set_listing(set_folder: str | Path) -> list[ListedStimulus]:
    """The stimuli of the set in ``set_folder`` as its ``manifest.csv`` lists them, every row checked before
    anything is read or written; a mistake raises :class:`UserError` naming the manifest and the row."""
    set_folder = Path(set_folder)
    manifest = set_folder / "manifest.csv"
    listed = []
    for line, row in _manifest_rows(manifest):
        tracks, audio = (_inside(set_folder, row[f"file_{kind}"], manifest, line) for kind in ("tracks", "wav"))
        phones = _inside(set_folder, row["file_phones"], manifest, line) if row.get("file_phones") else None
        listed.append(ListedStimulus(row["id"], line, row, tracks, audio, phones,
                                     _manifest_words(row, manifest, line)))
    return listed


def write_stimuli_site(model: Model | None, set_folder: str | Path, out: str | Path,
                       size: tuple[int, int] = DEFAULT_SIZE, heads: HeadsOf | None = None,
                       look: str | Look | None = None) -> dict[str, int]:
    """Write the site of the stimulus set in ``set_folder`` (its ``manifest.csv``) into ``out``.

    Every stimulus wears ``model``, unless ``heads`` (stimulus id → (key, model); one key, one head) gives
    each its own (``model`` may then be None): every head is in the site, the first as ``head.glb``, the
    next ``head-2.glb`` … A set whose manifest has head factors needs ``heads``. The head is lit and shaded
    in ``look``, by default the one the set was made with (its ``provenance.json``)."""
    if heads is None and model is None:
        raise ValueError("a model for every stimulus, or heads for each")
    set_folder, out = Path(set_folder), Path(out)
    listing = read_set_listing(set_folder)
    if heads is None:
        _refuse_heads_of_their_own(listing, set_folder / "manifest.csv")
    check_folder(out)
    if look is None:
        look = recorded_look(set_folder)
    groups: dict[str, tuple[Model, list[dict[str, Any]]]] = {}
    files, listed = {}, []
    for stimulus in listing:
        key, head = heads(stimulus.id) if heads is not None else ("", model)
        assert head is not None
        group = groups.setdefault(key, (head, []))
        number = list(groups).index(key) + 1
        glb_name = "head.glb" if number == 1 else f"head-{number}.glb"
        animation = _stimulus_animation(group[0], stimulus, size, look)
        animation.update(model=f"../{glb_name}", audio=f"{stimulus.id}.wav", stimulus=stimulus.id)
        group[1].append(animation)
        files[f"stimuli/{stimulus.id}.wav"] = stimulus.audio.read_bytes()
        listed.append({"id": stimulus.id, "animation": f"stimuli/{stimulus.id}.json",
                       "audio": f"stimuli/{stimulus.id}.wav", "model": glb_name,
                       "duration_ms": animation["duration_ms"], "manifest": stimulus.row})
    glbs = [web_glb(head, morph_parameters(head, shared_targets(animations)), look)
            for head, animations in groups.values()]
    for number, glb in enumerate(glbs[1:], start=2):
        files[f"head-{number}.glb"] = glb
    for _, animations in groups.values():
        for animation in animations:
            files[f"stimuli/{animation['stimulus']}.json"] = json_bytes(animation)
    files["stimuli.json"] = json_bytes({"format": STIMULI_FORMAT, "version": 1, "set": str(set_folder.name),
                                        "heads": len(glbs), "stimuli": listed})
    return write_folder(out, glbs[0], files, listed[0]["animation"])


def _refuse_heads_of_their_own(listing: list[ListedStimulus], manifest: Path) -> None:
    for stimulus in listing:
        factors = [f for f in HEAD_FACTORS if stimulus.row.get(f)]
        if factors:
            raise UserError(f"stimuli with heads of their own (factor '{factors[0]}'): give --design with the design "
                            "the set was made from, so that each head can be made again", file=manifest,
                            line=stimulus.line)


def _manifest_rows(manifest: Path) -> list[tuple[int, dict[str, str]]]:
    """The manifest's rows with their line numbers, checked for what a site needs."""
    if not manifest.is_file():
        raise UserError("no manifest.csv here: give the folder a stimulus set was made in", file=manifest)
    try:
        text = read_bounded_text(manifest, error=UserError, what="manifest")
    except OSError as exc:
        raise UserError(f"cannot read the manifest: {exc.strerror or exc}", file=manifest) from None
    reader = csv.DictReader(io.StringIO(text))
    try:
        return _checked_rows(reader, manifest)
    except csv.Error as exc:
        raise UserError(f"not a CSV table: {exc}", file=manifest, line=reader.line_num) from None


def _checked_rows(reader: csv.DictReader[str], manifest: Path) -> list[tuple[int, dict[str, str]]]:
    header = reader.fieldnames or []
    if "id" not in header:
        raise UserError("not a stimulus set's manifest (no 'id' column)", file=manifest, line=1)
    missing = [kind for kind in ("tracks", "wav") if f"file_{kind}" not in header]
    if missing:
        raise UserError(f"the set has no {' and no '.join(missing)} files: make it with \"tracks\" and \"wav\" "
                        "among [output] kinds", file=manifest, line=1)
    rows = []
    for row in reader:
        line = reader.line_num
        if None in row or any(value is None for value in row.values()):
            raise UserError("a row with more or fewer cells than the header", file=manifest, line=line)
        if not _ID.match(row["id"]):
            raise UserError(f"stimulus id {row['id']!r} is not letters, digits, '-' or '_'", file=manifest, line=line)
        rows.append((line, row))
    if not rows:
        raise UserError("the manifest lists no stimulus", file=manifest, line=1)
    if len({row["id"] for _, row in rows}) != len(rows):
        raise UserError("two stimuli have the same id", file=manifest)
    return rows


def _stimulus_animation(model: Model, stimulus: ListedStimulus, size: tuple[int, int],
                        look: str | Look | None) -> dict[str, Any]:
    table = read_tracks_csv(stimulus.tracks, model)
    samples, rate = read_wav(stimulus.audio)
    phones = read_phones_csv(stimulus.phones) if stimulus.phones is not None else []
    words = words_of(phones) if phones else stimulus.manifest_words
    end_ms = max(table.end, 1000.0 * len(samples) / rate, phones[-1].end_ms if phones else 0.0)
    frame_ms = 1000.0 / table.fps
    times = np.arange(max(1, int(np.ceil(end_ms / frame_ms - 1e-9)) + 1)) * frame_ms
    return site_animation(model, table.parameters, table.sample(times), frame_ms, phones, words, end_ms, size, look)


def _inside(set_folder: Path, name: str, manifest: Path, line: int) -> Path:
    """A file the manifest names, which must be in the set's folder."""
    path = set_folder / name
    try:
        inside = bool(name) and not Path(name).is_absolute() and ".." not in Path(name).parts and path.is_file()
    except (OSError, ValueError):                 # a name too long for the system, or with a NUL in it
        inside = False
    if not inside:
        raise UserError(f"the file {name[:200]!r} is not in the set's folder", file=manifest, line=line)
    return path


def _manifest_words(row: dict[str, str], manifest: Path, line: int) -> list[Segment]:
    """Words from the manifest's ``words`` and ``word_onsets_ms`` (each ending where the next starts)."""
    words = [w for w in row.get("words", "").split(";") if w]
    try:
        onsets = [float(t) for t in row.get("word_onsets_ms", "").split(";") if t]
    except ValueError:
        raise UserError("word_onsets_ms: not numbers", file=manifest, line=line) from None
    if len(words) != len(onsets):
        raise UserError("words and word_onsets_ms do not pair up", file=manifest, line=line)
    ends = [*onsets[1:], onsets[-1]] if onsets else []
    return [Segment(w, s, e) for w, s, e in zip(words, onsets, ends, strict=True)]
