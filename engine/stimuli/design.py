"""Design files: factors and their levels in, the list of stimuli to make out (docs/stimuli.md).

A design is a TOML file (read with the standard library's ``tomllib``)::

    seed = 7                              # optional: visual prosody, noise (default 0)

    [factors]
    text = ["Pappa ampui pallon.", "Maija meni kotiin."]
    av_offset_ms = [-200, 0, 200]

    [output]
    kinds = ["mp4"]                       # mp4, wav, png, silent-mp4
    size = "320x240"
    fps = 30
    look = "portrait"                     # portrait, flat, legacy, or a table (docs/looks.md)

Factors with fixed meanings: ``text`` (with inline commands), ``voice``,
``model`` (a model file, relative to the design), ``expression`` and
``intensity`` (0–100 %), ``av_offset_ms`` (positive: the audio later than the
video), ``snr_db`` and ``noise`` (``white``, ``speech-shaped`` or a WAV file).
``audio_text`` makes an incongruent (McGurk) stimulus: its audio is heard
while the face articulates ``text``, the two aligned at the onset of
``align_phone`` (default: the first vowel). Any other factor is a free label
copied into the manifest. ``expression_b`` and ``morph`` (0–100 %) make an
expression continuum: ``expression`` at (100 − morph) % and ``expression_b``
at morph %, both scaled by ``intensity``. ``audio`` and ``labels`` (a WAV and
its phone labels) replace Festival with a recorded voice. Which combinations
are made: every one (the default, ``combine = "cross"``), a listed subset
(``combine = "list"`` with ``[[rows]]`` tables), or blocks (``[[blocks]]``,
each crossed on its own, one after the other). Every error names the file,
the line and the key, and nothing is made.

>>> design = parse_design('[factors]\\ntext = ["Moi.", "Hei."]\\nav_offset_ms = [0, 100]\\n', "d.toml")
>>> [(s.id, s.levels["text"], s.levels["av_offset_ms"]) for s in design.stimuli]
[('0001', 'Moi.', 0), ('0002', 'Moi.', 100), ('0003', 'Hei.', 0), ('0004', 'Hei.', 100)]
"""

from __future__ import annotations

import hashlib
import itertools
import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from engine.commands.limits import MAX_TIME_MS
from engine.errors import UserError
from engine.formats.text_files import read_bounded_text
from engine.outputs.looks import Look, look_from
from engine.outputs.video_encoding import Encoding, encoding_from
from engine.stimuli.design_toml import DesignError, Locator, read_design_toml

FIXED_FACTORS = ("text", "voice", "model", "expression", "intensity", "av_offset_ms", "snr_db", "noise",
                 "audio_text", "align_phone", "expression_b", "morph", "audio", "labels", "identity", "identity_b",
                 "identity_morph", "viseme", "viseme_b", "viseme_morph")
KINDS = ("mp4", "wav", "png", "silent-mp4", "phones", "tracks")
NOISES = ("white", "speech-shaped")
MAX_STIMULI = 100_000
MAX_OFFSET_MS = 10_000.0
VIEWS = ("front", "side", "three-quarter")
_TOP_KEYS = {"seed", "factors", "output", "combine", "rows", "blocks", "name"}
_OUTPUT_KEYS = {"kinds", "size", "fps", "view", "still_ms", "validate", "look", "encoding"}
RANGES: dict[str, tuple[float, float, str]] = {
    **dict.fromkeys(("intensity", "morph", "identity_morph", "viseme_morph"),
                    (0.0, 100.0, "must be a number from 0 to 100 (%)")),
    "av_offset_ms": (-MAX_OFFSET_MS, MAX_OFFSET_MS, f"must be a number of ms within ±{MAX_OFFSET_MS:g}"),
    "snr_db": (-60.0, 60.0, "must be a number of dB from -60 to 60"),
    "fps": (1.0, 240.0, "fps must be a number from 1 to 240"),
    "still_ms": (0.0, MAX_TIME_MS, f"still_ms must be a time in ms from the start of the clip, 0 to "
                                   f"{MAX_TIME_MS:.0f} (24 hours)"),
}
"""The range of every number with a meaning (factor levels and [output] options); any other number in a
design (a free label, an identity value) is finite and within ±10¹⁵ (``design_toml.check_values``)."""


@dataclass(frozen=True)
class Output:
    """What each stimulus becomes."""

    kinds: tuple[str, ...] = ("mp4",)
    size: tuple[int, int] = (320, 240)
    fps: float = 30.0
    view: str = "front"
    still_ms: float | None = None
    """When a ``png`` still is taken (ms from the start of the clip); default: the expression's apex, or the
    middle of the speech."""
    validate: bool = False
    """Judge every stimulus's still and video with the observers of ``validate`` (docs/validation.md) as it
    is made: the verdicts go into ``check.csv``, ``validation.csv`` and ``validation-report.html``."""
    look: Look = field(default_factory=look_from)
    """How the head is lit and shaded (:mod:`engine.outputs.looks`): ``look = "NAME"`` or an ``[output.look]``
    table of settings; recorded whole in ``provenance.json``."""
    encoding: Encoding = field(default_factory=Encoding)
    """How the videos are compressed (:mod:`engine.outputs.video_encoding`): ``encoding = "lossless"`` or an
    ``[output.encoding]`` table of ``preset`` and ``crf``; in ``provenance.json`` and each manifest row."""


@dataclass(frozen=True)
class Stimulus:
    """One stimulus: its id (its place in the design, ``0001`` …) and the level of every factor."""

    id: str
    levels: dict[str, Any]


@dataclass
class Design:
    path: Path
    factors: dict[str, list[Any]]
    stimuli: list[Stimulus]
    output: Output
    seed: int = 0
    name: str = ""
    sha256: str = ""
    extra_files: dict[str, Path] = field(default_factory=dict)
    """Model and noise files the design names, by the name written in it (resolved against its folder)."""

    @property
    def folder(self) -> Path:
        return self.path.parent


def load_design(path: str | Path) -> Design:
    """Read and check a design file (:class:`DesignError` naming file, line and key)."""
    path = Path(path)
    try:
        text = read_bounded_text(path, limit=4 * 1024 * 1024, error=DesignError, what="design file")
    except OSError as exc:
        raise DesignError(f"cannot read the design: {exc.strerror or exc}", file=path) from None
    return parse_design(text, path)


def parse_design(text: str, path: str | Path = "<design>") -> Design:
    """Check a design's text and list its stimuli."""
    path = Path(path)
    data, where = read_design_toml(text, path)
    for key in data:
        if key not in _TOP_KEYS:
            raise where.error(key, f"unknown key '{key}' (known: {', '.join(sorted(_TOP_KEYS))})")
    factors = data.get("factors")
    if not isinstance(factors, dict) or not factors:
        raise DesignError("the design has no [factors] table with at least one factor", file=path, line=1)
    checked = {name: _levels(name, values, where, path.parent) for name, values in factors.items()}
    combine = data.get("combine", "blocks" if "blocks" in data else "list" if "rows" in data else "cross")
    if combine not in ("cross", "list", "blocks"):
        raise where.error("combine", f"combine must be cross, list or blocks, not {combine!r}")
    rows = _combinations(combine, checked, data, where, path.parent)
    if not rows:
        raise where.error("factors", "the design makes no stimulus")
    width = max(4, len(str(len(rows))))
    stimuli = [Stimulus(f"{i:0{width}d}", row) for i, row in enumerate(rows, start=1)]
    seed = data.get("seed", 0)
    if not isinstance(seed, int) or isinstance(seed, bool) or not 0 <= seed < 2**32:
        raise where.error("seed", "seed must be a whole number from 0 to 4294967295")
    name = data.get("name", path.stem)
    if not isinstance(name, str):
        raise where.error("name", "name must be a string")
    extra: dict[str, Path] = {}
    for row in rows:
        if ("audio" in row) != ("labels" in row):
            raise where.error("audio" if "audio" not in row else "labels",
                              "a recorded voice needs both factors: audio (the WAV) and labels")
        if "audio" in row and ("voice" in row or "audio_text" in row):
            raise where.error("audio", "a recorded voice cannot also have a Festival voice or audio_text")
        visemes = [k for k in ("viseme", "viseme_b", "viseme_morph") if k in row]
        if visemes and len(visemes) != 3:
            missing = next(k for k in ("viseme", "viseme_b", "viseme_morph") if k not in row)
            raise where.error(visemes[0], f"a viseme continuum needs viseme, viseme_b and viseme_morph ({missing} "
                                          "is missing)")
        if "identity_b" in row and "identity_morph" not in row:
            raise where.error("identity_b", "an identity continuum needs identity_morph (0–100 %) with identity_b")
        if "identity_morph" in row and "identity_b" not in row:
            raise where.error("identity_morph", "identity_morph needs identity_b (the identity at 100 %)")
        for factor in ("model", "noise", "audio", "labels", "identity", "identity_b"):
            value = row.get(factor)
            if isinstance(value, str) and (factor != "noise" or value not in NOISES) and value not in extra:
                extra[value] = (path.parent / value).resolve()
    return Design(path, checked, stimuli, _output(data.get("output", {}), where), seed, name,
                  hashlib.sha256(text.encode("utf-8")).hexdigest(), extra)


# ---------------------------------------------------------------------------

def _combinations(combine: str, factors: dict[str, list[Any]], data: dict[str, Any], where: Locator,
                  folder: Path) -> list[dict[str, Any]]:
    """The stimuli's levels, counted before any is made: a design of more than :data:`MAX_STIMULI` is refused
    at once, however many blocks or rows it writes."""
    if combine == "cross":
        _refuse_too_many(math.prod(len(v) for v in factors.values()), "factors", where)
        return _cross(factors)
    index = {name: {_key(level) for level in levels} for name, levels in factors.items()}
    if combine == "list":
        rows = data.get("rows")
        if not isinstance(rows, list) or not rows or not all(isinstance(r, dict) for r in rows):
            raise where.error("rows", "combine = \"list\" needs [[rows]] tables, one per stimulus")
        _refuse_too_many(len(rows), "rows", where)
        out = []
        for number, row in enumerate(rows):
            for name, value in row.items():
                _known_level(name, value, factors, index, where, folder, "rows", number)
            missing = [n for n in factors if n not in row]
            if missing:
                raise where.error("rows", f"a row gives no level for {', '.join(missing)}",
                                  where.line_in_table("rows", number))
            out.append({name: row[name] for name in factors})
        return out
    blocks = data.get("blocks")
    if not isinstance(blocks, list) or not blocks or not all(isinstance(b, dict) for b in blocks):
        raise where.error("blocks", "combine = \"blocks\" needs [[blocks]] tables of factor levels")
    chosen = []
    for number, block in enumerate(blocks):
        levels = dict(factors)
        for name, values in block.items():
            if name in factors and (not isinstance(values, list) or not values):
                raise where.error(name, f"factor '{name}' must be a list of its levels, e.g. {name} = [...]",
                                  where.line_in_table("blocks", number, name))
            for value in values if isinstance(values, list) else [values]:
                _known_level(name, value, factors, index, where, folder, "blocks", number)
            levels[name] = _levels(name, values, where, folder)
        chosen.append(levels)
    _refuse_too_many(sum(math.prod(len(v) for v in levels.values()) for levels in chosen), "blocks", where)
    return [row for levels in chosen for row in _cross(levels)]


def _refuse_too_many(count: int, key: str, where: Locator) -> None:
    if count > MAX_STIMULI:
        raise where.error(key, f"the design makes {count} stimuli, more than {MAX_STIMULI}")


def _known_level(name: str, value: Any, factors: dict[str, list[Any]], index: dict[str, set[Any]],
                 where: Locator, folder: Path, tables: str, number: int) -> None:
    """Refuse ``value`` of factor ``name`` in the ``number``-th of the ``[[tables]]`` (rows or blocks) unless
    it is one of the factor's levels: looked up in ``index``, so a design of many rows takes time in
    proportion to its length. The error names the line in that table."""
    if name in factors and _key(_one_person(name, value)) in index[name]:
        return
    line = where.line_in_table(tables, number, name)
    if name not in factors:
        raise where.error(name, f"{tables[:-1]} names '{name}', which is not a factor", line)
    try:
        _level(name, value, where, folder)
    except DesignError as exc:
        raise DesignError(exc.message, file=where.path, line=line) from None
    raise where.error(name, f"{value!r} is not a level of '{name}'", line)


def _key(value: Any) -> Any:
    """``value`` as a set member: equal values (``1`` and ``1.0``, tables in any key order) give equal keys."""
    if isinstance(value, dict):
        return ("table", tuple(sorted(((k, _key(v)) for k, v in value.items()), key=lambda item: item[0])))
    if isinstance(value, list):
        return ("array", tuple(_key(v) for v in value))
    return value


def _cross(factors: dict[str, list[Any]]) -> list[dict[str, Any]]:
    names = list(factors)
    return [dict(zip(names, combo, strict=True)) for combo in itertools.product(*factors.values())]


def _levels(name: str, values: Any, where: Locator, folder: Path) -> list[Any]:
    if _random_people(name, values):
        values = [values]                          # identity = {random = 10, seed = 7}: ten random people
    if not isinstance(values, list) or not values:
        raise where.error(name, f"factor '{name}' must be a list of its levels, e.g. {name} = [...]")
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
        raise where.error(name, f"factor name '{name}': letters, digits and _ only")
    checked = [level for value in values for level in (_people(name, value, where) if _random_people(name, value)
                                                       else [_level(name, value, where, folder)])]
    if len({repr(v) for v in checked}) != len(checked):
        raise where.error(name, f"factor '{name}' lists a level twice")
    return checked


def _random_people(name: str, value: Any) -> bool:
    """Whether ``value`` of factor ``name`` asks for random people (``{random = 10, seed = 7}``, docs/stimuli.md)."""
    return name in ("identity", "identity_b") and isinstance(value, dict) and "random" in value


def _people(name: str, table: dict[str, Any], where: Locator) -> list[dict[str, Any]]:
    """A random-people table as its levels, one person each (``{random = 1, seed = 8, population = 1}``)."""
    from engine.identity import IdentityError
    from engine.identity.population import random_levels

    try:
        return random_levels(table)
    except IdentityError as exc:
        raise where.error(name, f"'{name}' random people: {exc.message}") from None


def _one_person(name: str, value: Any) -> Any:
    """A row's or block's level as the factor's levels hold it (a random person with its population model)."""
    if _random_people(name, value) and "population" not in value:
        from engine.identity.population import POPULATION

        return {**value, "population": POPULATION}
    return value


def _level(name: str, value: Any, where: Locator, folder: Path) -> Any:
    def need(ok: bool, what: str) -> None:
        if not ok:
            raise where.error(name, f"'{name}' level {value!r}: {what}")

    if name in ("text", "voice", "expression", "audio_text", "align_phone", "expression_b", "viseme", "viseme_b"):
        need(isinstance(value, str) and value.strip() != "", "must be a non-empty string")
    elif name == "model":
        need(isinstance(value, str), "must be a model file name (relative to the design)")
        need((folder / value).is_file(), f"no such model file ({(folder / value)})")
    elif name in ("identity", "identity_b"):
        need(isinstance(value, dict | str), "must be a table of identity parameters ({sex = 1, age = 60}) or a "
                                            "model file with an identity (relative to the design)")
        if isinstance(value, str):
            need((folder / value).is_file(), f"no such model file ({folder / value})")
        else:
            from engine.identity import Identity, IdentityError
            from engine.identity.hair_style import hair_from_level, without_hair_keys

            try:
                Identity(without_hair_keys(value))
                hair_from_level(value)                 # hair = "short", beard = "stubble" … (docs/hair.md)
            except IdentityError as exc:
                need(False, exc.message)
            except UserError as exc:
                need(False, exc.message)
    elif name in RANGES:
        need(_in_range(name, value), RANGES[name][2])
    elif name in ("audio", "labels"):
        need(isinstance(value, str), f"must be a file name (relative to the design): the recording's "
                                     f"{'WAV' if name == 'audio' else 'phone labels'}")
        need((folder / value).is_file(), f"no such file ({folder / value})")
        if name == "audio":
            _need_wav(folder / value, need)
    elif name == "noise":
        need(isinstance(value, str), f"must be {' or '.join(NOISES)} or a WAV file")
        need(value in NOISES or (folder / value).is_file(), f"no such noise file ({folder / value})")
        if value not in NOISES:
            _need_wav(folder / value, need)
    else:
        need(isinstance(value, str | int | float | bool), "a free label must be a string, number or boolean")
    return value


def _need_wav(path: Path, need: Callable[[bool, str], None]) -> None:
    """A design's WAV (a recording, a noise) is read as :func:`~engine.speech.synthesis.read_wav` reads it,
    so a file it refuses is an error at the design's line, before anything is made."""
    from engine.speech.synthesis import read_wav_layout

    try:
        read_wav_layout(path)
    except UserError as exc:
        need(False, exc.message)


def _in_range(name: str, value: Any) -> bool:
    """Whether ``value`` is a number (not a boolean) within :data:`RANGES` ``[name]``."""
    low, high, _ = RANGES[name]
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value) and \
        low <= value <= high


def _output(table: Any, where: Locator) -> Output:
    if not isinstance(table, dict):
        raise where.error("output", "[output] must be a table")
    for key in table:
        if key not in _OUTPUT_KEYS:
            raise where.error(key, f"unknown output key '{key}' (known: {', '.join(sorted(_OUTPUT_KEYS))})")
    kinds = table.get("kinds", ["mp4"])
    if not isinstance(kinds, list) or not kinds or any(k not in KINDS for k in kinds):
        raise where.error("kinds", f"kinds must list some of {', '.join(KINDS)}")
    size = table.get("size", "320x240")
    match = re.fullmatch(r"(\d{2,4})x(\d{2,4})", str(size))
    if not match or any(int(v) % 2 or int(v) < 16 for v in match.groups()):
        raise where.error("size", f"size must be WIDTHxHEIGHT, even numbers from 16 (got {size!r})")
    fps = table.get("fps", 30)
    if not _in_range("fps", fps):
        raise where.error("fps", RANGES["fps"][2])
    view = table.get("view", "front")
    if view not in VIEWS:
        raise where.error("view", f"view must be one of {', '.join(VIEWS)}")
    still = table.get("still_ms")
    if still is not None and not _in_range("still_ms", still):
        raise where.error("still_ms", RANGES["still_ms"][2])
    validate = table.get("validate", False)
    if not isinstance(validate, bool):
        raise where.error("validate", "validate must be true or false")
    if validate and not {"png", "mp4", "silent-mp4"} & set(kinds):
        raise where.error("validate", "validate needs a picture to judge: kinds must hold png, mp4 or silent-mp4")
    try:
        look = look_from(table.get("look"))
    except UserError as exc:
        message = exc.message.removeprefix("look: ")
        setting = re.match(r"[\w.]+", message)                 # the setting named first: its line
        line = where.line_of(setting.group().split(".")[-1]) if setting and isinstance(table.get("look"), dict) \
            else None
        raise where.error("look", message, line) from None
    try:
        encoding = encoding_from(table.get("encoding"))
    except UserError as exc:
        message = exc.message.removeprefix("encoding: ")
        setting = re.match(r"\w+", message)
        line = where.line_of(setting.group()) if setting and isinstance(table.get("encoding"), dict) else None
        raise where.error("encoding", message, line) from None
    return Output(tuple(dict.fromkeys(kinds)), (int(match.group(1)), int(match.group(2))), float(fps), view,
                  None if still is None else float(still), validate, look, encoding)


def level_text(level: Any) -> str | Any:
    """A level as a table cell: an identity table as ``sex=1;age=60`` (readable in R, pandas and PsychoPy)."""
    if isinstance(level, dict):
        return ";".join(f"{k}={v:g}" if isinstance(v, int | float) else f"{k}={v}" for k, v in level.items())
    return level
