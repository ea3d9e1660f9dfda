"""The built study as the browser runs it (``study.json``), and each participant's trial order.

The order is drawn in the participant's browser, from a seed recorded in every row of the data:
``participant_seed = fnv1a32(f"{seed}:{participant}")`` drives mulberry32, a 32-bit generator whose
every step is integer arithmetic, so :func:`participant_sequence` (here) and ``sequenceFor`` (in
``engine/web/study/study.js``) give the same order, trial for trial (tested in Chromium). The draws,
in this order:

1. practice: the first ``practice`` of the test specs shuffled (Fisher–Yates, drawing from the top);
2. each block of the participant's block order (``orders[order]``), its specs (× ``repetitions``)
   shuffled;
3. each attention check: a spec (a draw), the answer asked for (a draw among the choices but
   "other", or a point of the first scale when there is no identification), and where it goes
   (a draw among the places after the first test trial).

The block order is ``orders[k]`` for participant number ``n`` with ``k = (n − 1) mod len(orders)`` (an id
that is not a number: ``k = fnv1a32(id) mod len(orders)``).

>>> fnv1a32("2003:7"), [round(x, 6) for x in mulberry32(1)(3)]
(1383847941, [0.627074, 0.002736, 0.527447])
"""

from __future__ import annotations

import hashlib
import itertools
import json
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from engine.errors import UserError
from engine.study.design import CANONICAL_EMOTIONS, DEFAULT_LABELS, StudyDesign
from engine.study.stimuli_list import TrialSpec

__all__ = ["FORMAT", "VERSION", "Choice", "SequenceItem", "block_orders", "choices_for", "fnv1a32", "mulberry32",
           "order_index", "participant_sequence", "study_document"]

FORMAT = "artificial-person-study"
VERSION = 1
DIGIT_KEYS = tuple("1234567890") + tuple("qwertyuiopasdfghjklzxcvbnm")


@dataclass(frozen=True)
class Choice:
    value: str
    label: str
    key: str


@dataclass(frozen=True)
class SequenceItem:
    phase: str
    """``practice``, ``test`` or ``attention``."""
    spec: int
    """Index into the study's ``trials``."""
    block: str
    expected: str | None = None


def fnv1a32(text: str) -> int:
    """FNV-1a, 32 bits, of the UTF-8 bytes of ``text``."""
    value = 0x811C9DC5
    for byte in text.encode("utf-8"):
        value = ((value ^ byte) * 0x01000193) & 0xFFFFFFFF
    return value


def mulberry32(seed: int) -> Callable[[int], list[float]]:
    """``draw(n)``: the next ``n`` numbers in [0, 1) of mulberry32 from ``seed`` (as the browser's Math.imul code)."""
    state = [seed & 0xFFFFFFFF]

    def one() -> float:
        state[0] = (state[0] + 0x6D2B79F5) & 0xFFFFFFFF
        a = state[0]
        t = ((a ^ (a >> 15)) * (1 | a)) & 0xFFFFFFFF
        t = ((t + (((t ^ (t >> 7)) * (61 | t)) & 0xFFFFFFFF)) & 0xFFFFFFFF) ^ t
        return ((t ^ (t >> 14)) & 0xFFFFFFFF) / 4294967296.0

    def draw(n: int) -> list[float]:
        return [one() for _ in range(n)]

    return draw


def _shuffle(items: list[Any], draw: Callable[[int], list[float]]) -> list[Any]:
    out = list(items)
    for i in range(len(out) - 1, 0, -1):
        j = int(draw(1)[0] * (i + 1))
        out[i], out[j] = out[j], out[i]
    return out


def choices_for(design: StudyDesign, specs: Sequence[TrialSpec]) -> list[Choice]:
    """The identification task's options: the design's, or the stimuli's emotions (in the usual order), then
    neutral and other; every stimulus's emotion must be among them."""
    given = design.choices
    if given.values is not None:
        values = list(given.values)
    else:
        found = {s.intended for s in specs} - {"neutral", "other"}
        values = [e for e in CANONICAL_EMOTIONS if e in found] + sorted(found - set(CANONICAL_EMOTIONS))
        if given.neutral or any(s.intended == "neutral" for s in specs):
            values.append("neutral")
        if given.other:
            values.append("other")
    missing = sorted({s.intended for s in specs} - set(values))
    if missing and "identification" in design.procedure.tasks:
        raise UserError(f"stimuli show {', '.join(missing)}, which [identification] choices does not offer",
                        file=design.path)
    if len(values) > len(DIGIT_KEYS):
        raise UserError(f"at most {len(DIGIT_KEYS)} choices", file=design.path)
    keys = list(given.keys) or list(DIGIT_KEYS[:len(values)])
    if len(keys) != len(values):
        raise UserError(f"[identification] keys lists {len(keys)} keys for {len(values)} choices "
                        f"({', '.join(values)})", file=design.path)
    return [Choice(v, given.labels.get(v, DEFAULT_LABELS.get(v, v.replace("_", " ").capitalize())), k)
            for v, k in zip(values, keys, strict=True)]


def block_orders(design: StudyDesign, specs: Sequence[TrialSpec]) -> tuple[str, list[list[str]]]:
    """The blocking factor and its counterbalanced orders (every permutation, or a Latin square's rows)."""
    blocking = design.procedure.blocks
    if blocking == "none":
        return blocking, [["all"]]
    levels = list(design.presentations) if blocking == "presentation" else ["synthetic", "human"]
    present = {getattr(s, blocking) for s in specs}
    levels = [level for level in levels if level in present]
    if len(levels) < 2:
        raise UserError(f"procedure.blocks = \"{blocking}\" needs two levels of it, and the study has "
                        f"{', '.join(levels) or 'none'}", file=design.path)
    if design.procedure.counterbalance == "latin":
        return blocking, [levels[k:] + levels[:k] for k in range(len(levels))]
    return blocking, [list(p) for p in itertools.permutations(levels)]


def study_document(design: StudyDesign, specs: list[TrialSpec], choices: list[Choice], manifest_sha256: str,
                   set_name: str, pages: dict[str, str], live: bool) -> dict[str, Any]:
    """What the browser runs (``study.json`` and ``study-data.js``), with its ``study_id`` (a hash of the rest)."""
    blocking, orders = block_orders(design, specs)
    procedure = design.procedure
    document: dict[str, Any] = {
        "format": FORMAT, "version": VERSION, "name": design.name, "title": design.title, "seed": design.seed,
        "set": set_name, "set_manifest_sha256": manifest_sha256, "design_sha256": design.sha256,
        "tasks": list(procedure.tasks),
        "choices": [{"value": c.value, "label": c.label, "key": c.key} for c in choices],
        "question": design.choices.question, "buttons": design.choices.buttons,
        "scales": [{"name": s.name, "question": s.question, "min": s.low, "max": s.high, "anchors": list(s.anchors),
                    "keys": list(s.keys)} for s in design.scales],
        "procedure": {"blocks": blocking, "orders": orders, "repetitions": procedure.repetitions,
                      "practice": procedure.practice, "attention_checks": procedure.attention_checks,
                      "static_ms": procedure.static_ms, "fixation_ms": procedure.fixation_ms,
                      "gap_ms": procedure.gap_ms},
        "pages": pages, "width": design.width, "live": live,
        "factors": list(dict.fromkeys(name for s in specs for name in s.levels)),
        "trials": [s.document() for s in specs],
    }
    text = json.dumps(document, sort_keys=True, ensure_ascii=False)
    document["study_id"] = hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]
    return document


def order_index(participant: str, orders: int) -> int:
    """Which block order a participant gets: ``(n − 1) mod orders`` for a number ``n``, else by the id's hash."""
    text = participant.strip()
    if text.isdigit() and text.isascii() and len(text) < 16:
        return (int(text) - 1) % orders
    return fnv1a32(text) % orders


def participant_sequence(document: dict[str, Any], participant: str) -> tuple[int, int, list[SequenceItem]]:
    """(participant seed, block order, trials in order) as the browser draws them (the module notes)."""
    seed = fnv1a32(f"{document['seed']}:{participant}")
    draw = mulberry32(seed)
    procedure = document["procedure"]
    trials = document["trials"]
    blocking = procedure["blocks"]
    order = order_index(participant, len(procedure["orders"]))
    indices = list(range(len(trials)))
    practice: list[SequenceItem] = []
    count = procedure["practice"]
    while len(practice) < count:
        practice += [SequenceItem("practice", i, _block_of(trials[i], blocking))
                     for i in _shuffle(indices, draw)[:count - len(practice)]]
    test: list[SequenceItem] = []
    for block in procedure["orders"][order]:
        members = [i for i in indices if _block_of(trials[i], blocking) == block] * procedure["repetitions"]
        test += [SequenceItem("test", i, block) for i in _shuffle(members, draw)]
    answers = _attention_answers(document)
    for _ in range(procedure["attention_checks"]):
        i = int(draw(1)[0] * len(trials))
        expected = answers[int(draw(1)[0] * len(answers))]
        position = 1 + int(draw(1)[0] * len(test)) if test else 0
        test.insert(position, SequenceItem("attention", i, _block_of(trials[i], blocking), expected))
    return seed, order, practice + test


def _block_of(trial: dict[str, Any], blocking: str) -> str:
    return "all" if blocking == "none" else str(trial[blocking])


def _attention_answers(document: dict[str, Any]) -> list[str]:
    if "identification" in document["tasks"]:
        return [c["value"] for c in document["choices"] if c["value"] != "other"] or ["other"]
    scale = document["scales"][0]
    return [str(v) for v in range(scale["min"], scale["max"] + 1)]
