"""Phone labels for a session: Praat TextGrids, label files, or Festival's timing of the spoken text.

Every reader returns ``(start_ms, end_ms, label)`` triples on the recording's
clock (0 ms = the first frame).

* **Praat TextGrid** (text or short text format, UTF-8 or UTF-16): one
  interval tier; by default the one named ``phones``, ``phone``,
  ``phonemes``, ``segments`` or ``segment`` (any case), else the first
  interval tier. Empty intervals (silence) are left out.
* **Label file**: one segment per line, ``start end label`` separated by
  spaces or tabs (Audacity's label export reads as is). Times are seconds
  unless the file has a line ``# units: ms``. ``#`` starts a comment; lines
  starting with ``\\`` (Audacity's frequency lines) are skipped.
* **Phones CSV**, the table ``say --phones`` writes (``start_ms,end_ms,phone,word``); a row with
  no phone is silence and left out.
* **Festival**: synthesise the text that was spoken and take the phone
  timings, either as they are or stretched to a given duration.

>>> parse_label_lines(["0.00 0.12 h", "0.12 0.20 e"], "x.lab")
[(0.0, 120.0, 'h'), (120.0, 200.0, 'e')]
>>> parse_label_lines(["# units: ms", "0 120 h"], "x.lab")
[(0.0, 120.0, 'h')]
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import TYPE_CHECKING

from engine.commands.limits import MAX_TIME_MS
from engine.errors import UserError
from engine.formats.text_files import read_bounded_bytes

if TYPE_CHECKING:
    from engine.speech.synthesis import Synthesizer

class LabelFileError(UserError):
    """A phone label file (Praat TextGrid, label lines, phones CSV) or a marker mapping file is malformed,
    or its labels cannot drive the face (a missing tier, unknown phones, labels past the audio)."""


PHONE_TIER_NAMES = ("phones", "phone", "phonemes", "segments", "segment")
_UNITS = re.compile(r"#\s*units?\s*[:=]?\s*(ms|s)\s*$", re.IGNORECASE)
# Each alternative consumes what it scans, so tokenizing is linear: a quoted text with no closing quote runs
# to the end of the file (and is refused), a bracket comment with no ']' to the end of its line.
_TOKEN = re.compile(r'"(?:[^"]|"")*(?:"|\Z)|\[[^\]"\n]*(?:\]|$)|<exists>|<absent>'
                    r'|[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?', re.MULTILINE)
_UNTERMINATED = re.compile(r'(?:[^"]|"")*\Z')



def read_labels(path: str | Path, tier: str | None = None) -> list[tuple[float, float, str]]:
    """Phone labels from a TextGrid, a phones CSV or a label file (recognised by content)."""
    path = Path(path)
    text = _read_text(path)
    head = text.lstrip()[:200]
    if head.startswith("File type") and "ooTextFile" in head:
        return parse_textgrid(text, path, tier)
    if tier is not None:
        raise LabelFileError("--tier applies to Praat TextGrids only", file=path)
    first = head.split("\n", 1)[0].replace(" ", "").lower()
    if first.startswith("start_ms,end_ms,"):
        return _phones_csv(text, path)
    return parse_label_lines(text.splitlines(), path)


def _read_text(path: Path) -> str:
    data = read_bounded_bytes(path, error=LabelFileError, what="label file")
    if data[:2] in (b"\xff\xfe", b"\xfe\xff"):
        try:
            return data.decode("utf-16")
        except UnicodeDecodeError as exc:
            raise LabelFileError(f"not valid UTF-16 text at byte {exc.start + 1} ({exc.reason})", file=path,
                                 line=data[:exc.start].count("\n".encode("utf-16-le")) + 1) from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def parse_label_lines(lines: list[str], path: str | Path) -> list[tuple[float, float, str]]:
    """``start end label`` lines (seconds, or ms after ``# units: ms``) as ms triples."""
    scale = 1000.0
    out = []
    for number, raw in enumerate(lines, start=1):
        unit = _UNITS.match(raw.strip())
        if unit:
            scale = 1.0 if unit.group(1).lower() == "ms" else 1000.0
            continue
        line = raw.split("#", 1)[0].strip()
        if not line or line.startswith("\\"):
            continue
        parts = line.split(None, 2)
        if len(parts) < 3:
            raise LabelFileError(f"expected 'start end label', got '{line}'", file=path, line=number)
        try:
            start, end = float(parts[0]) * scale, float(parts[1]) * scale
        except ValueError:
            raise LabelFileError(f"'{parts[0]} {parts[1]}' are not two times", file=path, line=number) from None
        if not (end >= start >= 0):
            raise LabelFileError(f"segment ends ({parts[1]}) before it starts ({parts[0]}) or starts before 0",
                                 file=path, line=number)
        _check_segment_end(end, path, number)
        out.append((start, end, parts[2].strip()))
    return out


def _phones_csv(text: str, path: Path) -> list[tuple[float, float, str]]:
    lines = text.splitlines()
    out = []
    for number, line in enumerate(lines[1:], start=2):
        if not line.strip():
            continue
        cells = [c.strip() for c in line.split(",")]
        if len(cells) < 3:
            raise LabelFileError("expected start_ms,end_ms,phone[,word]", file=path, line=number)
        try:
            start, end = float(cells[0]), float(cells[1])
        except ValueError:
            raise LabelFileError(f"'{cells[0]}', '{cells[1]}' are not times in ms", file=path, line=number) from None
        if not end >= start >= 0:
            raise LabelFileError("segment ends before it starts, or starts before 0", file=path, line=number)
        _check_segment_end(end, path, number)
        if cells[2]:                              # an empty phone is silence, as an empty TextGrid interval
            out.append((start, end, cells[2]))
    return out


def parse_textgrid(text: str, path: str | Path, tier: str | None = None) -> list[tuple[float, float, str]]:
    """The intervals of one interval tier of a Praat TextGrid (text or short text format), in ms."""
    tokens = [(m.group(0), m.start()) for m in _TOKEN.finditer(text) if not m.group(0).startswith("[")]
    pos = 0

    def line_of(offset: int) -> int:
        return text.count("\n", 0, offset) + 1

    def take(kind: str) -> tuple[str, int]:
        """The next token (a ``string`` unquoted, a ``flag``, a ``number`` as written) and its offset."""
        nonlocal pos
        if pos >= len(tokens):
            raise LabelFileError(f"the TextGrid ends early (expected {kind})", file=path,
                                 line=text.count("\n") + 1)
        token, offset = tokens[pos]
        pos += 1
        if kind == "string":
            if not token.startswith('"'):
                raise LabelFileError(f"expected a quoted text, found '{token}'", file=path, line=line_of(offset))
            if len(token) < 2 or _UNTERMINATED.fullmatch(token, 1):
                raise LabelFileError("a quoted text has no closing quote", file=path, line=line_of(offset))
            return token[1:-1].replace('""', '"'), offset
        if kind == "number" and token.startswith(('"', "<")):
            raise LabelFileError(f"expected a number, found {token}", file=path, line=line_of(offset))
        return token, offset

    def take_number() -> tuple[float, int]:
        token, offset = take("number")
        value = float(token)
        if not math.isfinite(value):
            raise LabelFileError(f"the number {token} is too large", file=path, line=line_of(offset))
        return value, offset

    def take_count(what: str) -> int:
        """A count of tiers or intervals: whole, not negative, and no more than the tokens left."""
        value, offset = take_number()
        if value != int(value) or value < 0 or value > len(tokens) - pos:
            raise LabelFileError(f"{what} {value:g} is not a whole number the file can hold", file=path,
                                 line=line_of(offset))
        return int(value)

    file_type, _ = take("string")
    object_class, offset = take("string")
    if file_type != "ooTextFile" or object_class != "TextGrid":
        raise LabelFileError(f"not a Praat TextGrid (object class '{object_class}')", file=path, line=line_of(offset))
    take_number()
    take_number()
    flag, offset = take("flag")
    if flag != "<exists>":
        raise LabelFileError("the TextGrid has no tiers", file=path, line=line_of(offset))
    n_tiers = take_count("the number of tiers")
    tiers = []
    for _ in range(n_tiers):
        kind, offset = take("string")
        name, _ = take("string")
        take_number()
        take_number()
        n = take_count("the number of intervals")
        items = []
        for _ in range(n):
            if kind == "IntervalTier":
                start, _ = take_number()
                end, at = take_number()
                label, _ = take("string")
                items.append((start, end, label, at))
            elif kind == "TextTier":
                take_number()
                take("string")
            else:
                raise LabelFileError(f"unknown tier class '{kind}'", file=path, line=line_of(offset))
        tiers.append((kind, name, items, offset))
    intervals = [t for t in tiers if t[0] == "IntervalTier"]
    if not intervals:
        raise LabelFileError("the TextGrid has no interval tier", file=path)
    if tier is not None:
        chosen = [t for t in intervals if t[1] == tier]
        if not chosen:
            names = ", ".join(f"'{t[1]}'" for t in intervals)
            raise LabelFileError(f"no interval tier named '{tier}' (there are {names})", file=path)
    else:
        chosen = [t for t in intervals if t[1].strip().lower() in PHONE_TIER_NAMES] or intervals
    out = []
    for start, end, label, at in chosen[0][2]:
        if end < start:
            raise LabelFileError("an interval ends before it starts", file=path, line=line_of(at))
        _check_segment_end(end * 1000.0, path, line_of(at))
        if label.strip():
            out.append((start * 1000.0, end * 1000.0, label.strip()))
    return out


def _check_segment_end(end_ms: float, path: str | Path, line: int) -> None:
    if not end_ms <= MAX_TIME_MS:
        raise LabelFileError(f"a segment ends at {end_ms:g} ms, beyond {MAX_TIME_MS:.0f} ms (24 hours)",
                             file=path, line=line)


def festival_phones(text: str, voice: str | None = None, duration_ms: float | None = None,
                    synthesizer: Synthesizer | None = None) -> list[tuple[float, float, str]]:
    """Phone labels from Festival's synthesis of ``text`` (Suopuhe phone names, pauses ``#``).

    With ``duration_ms`` the timings are stretched linearly so the utterance
    spans that long; otherwise they are Festival's own, starting at 0 ms.
    ``synthesizer`` defaults to :class:`engine.speech.festival.FestivalSynthesizer`.
    """
    if synthesizer is None:
        from engine.speech.festival import FestivalSynthesizer

        synthesizer = FestivalSynthesizer()
    phones = synthesizer.synthesize(text, voice=voice).phones
    if not phones:
        return []
    end = max(p.end_ms for p in phones)
    factor = duration_ms / end if duration_ms and end > 0 else 1.0
    return [(p.start_ms * factor, p.end_ms * factor, p.label) for p in phones]
