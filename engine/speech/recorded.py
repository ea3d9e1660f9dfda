"""A recorded voice drives the lips: a WAV and its phone labels instead of Festival (issue 24).

The audio is the speaker's, unchanged; the face articulates the labelled
phones with the same articulation and coarticulation as synthetic speech
(§2.1), so a natural /ba/ or a sentence of a standard corpus gets a face whose
every movement is known. Labels come from a Praat TextGrid (a phone tier and,
when there is one, a word tier for anchoring inline commands), a label file or
a phones CSV, in any phone set of :mod:`engine.speech.phone_sets`.

Gaps between labels (Praat's empty intervals) and the stretches before the
first and after the last label become pauses, so the phones cover the audio
from 0 to its end.

>>> from engine.speech.recorded import recorded_utterance
>>> utterance = recorded_utterance("take.wav", "take.TextGrid")     # doctest: +SKIP
>>> utterance.phoneset, utterance.phones[1].label                   # doctest: +SKIP
('radio', 'hh')
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

from engine.formats.text_files import read_bounded_bytes, read_bounded_text
from engine.speech.labels import LabelFileError, read_labels
from engine.speech.phone_features import PhoneFeatures
from engine.speech.phone_sets import PAUSE_LABELS, PHONE_SETS, PhoneSet, closest_phone_set, guess_phone_set
from engine.speech.synthesis import Segment, SynthesisError, Utterance, read_wav

if TYPE_CHECKING:
    from engine.commands import Library
    from engine.model.model import Model
    from engine.speech.articulation import ArticulationTable
    from engine.speech.say import Speech

WORD_TIER_NAMES = ("words", "word", "orthography", "ort", "text")
"""TextGrid tiers read as the words, in this order (any case), when ``word_tier`` is not given."""


def recorded_utterance(audio: str | Path, labels: str | Path, phone_set: str = "auto", tier: str | None = None,
                       word_tier: str | None = None, phone_map: str | Path | None = None) -> Utterance:
    """The recording as an :class:`~engine.speech.synthesis.Utterance`: its samples, its labelled phones
    (named as ``phone_set`` names them, with their features) and its words (from the word tier, if any)."""
    audio, labels = Path(audio), Path(labels)
    samples, rate = read_wav(audio)
    duration_ms = 1000.0 * len(samples) / rate
    if len(samples) == 0:
        raise SynthesisError("the recording has no samples", file=audio)
    raw = _sorted_checked(read_labels(labels, tier), labels, duration_ms, rate)
    mapping = read_phone_map(phone_map) if phone_map is not None else {}
    chosen = _phone_set(phone_set, [mapping.get(label, label) for _, _, label in raw], labels)
    phones, features = _phones(raw, chosen, mapping, labels, duration_ms)
    words = _words(labels, word_tier, duration_ms, rate)
    phones = [replace(p, word=_word_at(words, p)) if p.label != chosen.pause else p for p in phones]
    return Utterance(text=" ".join(w.label for w in words), voice=f"recording {audio.name}", samples=samples,
                     sample_rate=rate, phones=phones, words=words, phoneset=chosen.festival_phoneset,
                     phone_features=features, source_wav=audio)


def speak_recording(audio: str | Path, labels: str | Path, model: Model, text: str | None = None,
                    phone_set: str = "auto", tier: str | None = None, word_tier: str | None = None,
                    phone_map: str | Path | None = None, library: Library | None = None,
                    table: ArticulationTable | None = None, coarticulation: str = "cohen-massaro",
                    prosody_seed: int | None = None, name: str = "<text>",
                    table_of: Callable[[Utterance], ArticulationTable] | None = None) -> Speech:
    """The recording with a face: :func:`recorded_utterance` animated as :func:`engine.speech.say.speak`
    animates synthetic speech (``table_of`` as there: the table chosen from the utterance).

    ``text`` (optional) holds the inline commands; its words are matched to
    the label file's word tier, which it therefore needs when it has commands.
    """
    from engine.commands import load_library
    from engine.script.inline_commands import Script, parse_script
    from engine.speech.say import animate, check_commands

    library = load_library() if library is None else library
    script = parse_script(text, name) if text is not None else None
    if script is not None:
        check_commands(script, library, model)
    utterance = recorded_utterance(audio, labels, phone_set, tier, word_tier, phone_map)
    if script is None:
        script = Script(utterance.text, [w.label for w in utterance.words], [], name)
    elif script.commands and not utterance.words:
        raise LabelFileError("the text has inline commands, but the labels have no word tier to anchor them to "
                         f"(tiers named {', '.join(WORD_TIER_NAMES)}, or --word-tier NAME)", file=labels)
    if table_of is not None:
        table = table_of(utterance)
    return animate(script, utterance, model, library, table, coarticulation, prosody_seed)


def read_phone_map(path: str | Path) -> dict[str, str]:
    """A user's label table: ``LABEL PHONE`` per line (white space between; ``#`` starts a comment), mapping
    the labels of a file to phones of the chosen phone set."""
    path = Path(path)
    try:
        text = read_bounded_text(path, error=LabelFileError, what="phone map")
    except OSError as exc:
        raise LabelFileError(f"cannot read the phone map: {exc.strerror or exc}", file=path) from None
    except UnicodeDecodeError:
        raise LabelFileError("the phone map is not UTF-8 text", file=path) from None
    mapping: dict[str, str] = {}
    for number, line in enumerate(text.splitlines(), start=1):
        content = re.split(r"(?:^|\s)#", line, maxsplit=1)[0].split()
        if not content:
            continue
        if len(content) != 2:
            raise LabelFileError(f"expected 'LABEL PHONE', got {line.strip()!r}", file=path, line=number)
        mapping[content[0]] = content[1]
    return mapping


def _sorted_checked(raw: Sequence[tuple[float, float, str]], path: Path, duration_ms: float,
                    rate: int) -> list[tuple[float, float, str]]:
    if not raw:
        raise LabelFileError("the label file has no phone labels", file=path)
    ordered = sorted(raw)
    slack = 1000.0 / rate                                       # a label may end up to a sample late
    for (_, end, label), (next_start, _, next_label) in itertools.pairwise(ordered):
        if next_start < end - 1e-6:
            raise LabelFileError(f"phone '{next_label}' at {next_start:g} ms starts before '{label}' ends "
                             f"({end:g} ms): labels overlap", file=path, line=_line_of(path, next_label))
    _, last_end, last = ordered[-1]
    if last_end > duration_ms + slack:
        raise LabelFileError(f"phone '{last}' ends at {last_end:g} ms, past the end of the audio ({duration_ms:g} ms): "
                         "are these the labels of this recording?", file=path, line=_line_of(path, last))
    return ordered


def _phone_set(name: str, labels: list[str], path: Path) -> PhoneSet:
    if name == "auto":   # no set knows them all: the closest names what it does not know, with lines
        return guess_phone_set(labels) if _every_label_known(labels) else closest_phone_set(labels)
    if name not in PHONE_SETS:
        raise LabelFileError(f"unknown phone set '{name}' (known: auto, {', '.join(sorted(PHONE_SETS))})")
    return PHONE_SETS[name]


def _every_label_known(labels: list[str]) -> bool:
    try:
        guess_phone_set(labels)
    except ValueError:
        return False
    return True


def _phones(raw: list[tuple[float, float, str]], chosen: PhoneSet, mapping: dict[str, str], path: Path,
            duration_ms: float) -> tuple[list[Segment], dict[str, PhoneFeatures]]:
    phones: list[Segment] = []
    features: dict[str, PhoneFeatures] = {}
    unknown: dict[str, int | None] = {}
    at = 0.0
    for start, end, label in raw:
        name = chosen.phone(mapping.get(label, label))
        if name is None:
            unknown.setdefault(label, _line_of(path, label))
            continue
        if start > at:
            phones.append(Segment(chosen.pause, at, start))
        phones.append(Segment(name, start, end))
        known = chosen.features(name)
        if known is not None:
            features.setdefault(name, known)
        at = end
    if unknown:
        first_line = next((line for line in unknown.values() if line is not None), None)
        listed = ", ".join(f"'{label}'" + (f" (line {line})" if line and len(unknown) > 1 else "")
                           for label, line in list(unknown.items())[:8]) + (" …" if len(unknown) > 8 else "")
        raise LabelFileError(f"the {chosen.name} phone set does not know {listed}; map them with --phone-map "
                         f"(LABEL PHONE per line) or choose another --phone-set ({', '.join(sorted(PHONE_SETS))})",
                         file=path, line=first_line)
    if duration_ms > at:
        phones.append(Segment(chosen.pause, at, duration_ms))
    if phones and phones[-1].end_ms > duration_ms:                 # a label a fraction of a sample late
        phones[-1] = replace(phones[-1], end_ms=duration_ms)
    features.setdefault(chosen.pause, chosen.features(chosen.pause) or PhoneFeatures())
    return phones, features


def _words(path: Path, word_tier: str | None, duration_ms: float, rate: int) -> list[Segment]:
    if not _is_textgrid(path):
        if word_tier is not None:
            raise LabelFileError("--word-tier applies to Praat TextGrids only", file=path)
        return []
    names = [word_tier] if word_tier is not None else list(WORD_TIER_NAMES)
    for name in names:
        try:
            raw = read_labels(path, name)
        except LabelFileError:
            if word_tier is not None:
                raise
            continue
        ordered = _sorted_checked(raw, path, duration_ms, rate) if raw else []
        return [Segment(label, start, end) for start, end, label in ordered if label.strip() not in PAUSE_LABELS]
    return []


def _word_at(words: list[Segment], phone: Segment) -> str:
    middle = phone.mid_ms
    for word in words:
        if word.start_ms <= middle < word.end_ms:
            return word.label
    return ""


def _is_textgrid(path: Path) -> bool:
    try:
        with path.open("rb") as stream:
            head = stream.read(200)
    except OSError:
        return False
    for encoding in ("utf-8", "utf-16"):
        try:
            if "ooTextFile" in head.decode(encoding, errors="ignore"):
                return True
        except LookupError:
            continue
    return False


def _line_of(path: Path, label: str) -> int | None:
    """The first line of the label file that holds ``label`` as a label (for an error message)."""
    try:
        data = read_bounded_bytes(path, error=LabelFileError, what="labels")
    except (OSError, LabelFileError):
        return None
    text = data.decode("utf-16" if data[:2] in (b"\xff\xfe", b"\xfe\xff") else "utf-8", errors="replace")
    quoted = f'"{label}"'
    for number, line in enumerate(text.splitlines(), start=1):
        if quoted in line or (label and line.split()[-1:] == [label]) or line.split(",")[2:3] == [label]:
            return number
    return None
