"""Visual prosody (optional): the face moving with the speech, beyond articulation (§5).

Three behaviours, each expressed as high-level commands of the shipped
library (so a user's own ``Blink``, ``BrowRaise`` or ``HeadNod`` takes over):

* **blinking** — spontaneous blinks at random intervals (gamma-distributed,
  mean 3.5 s, never closer than 1.2 s), as adults blink in conversation;
* **brows on accented words** — a brief ``BrowRaise`` (40 %) on the first word
  of every phrase that has two or more syllables: Finnish stress falls on a
  word's first syllable and the phrase accent usually on its first content
  word;
* **nods at phrase ends** — a small ``HeadNod`` (30 %) as the last word of a
  phrase ends.

A *phrase* is a run of words between pauses (Festival's ``#``/``##`` phones,
or a silence between words longer than 120 ms). Everything random comes
from one seed, so the same text and seed give the same face.

>>> from engine.speech.synthesis import Segment
>>> words = [Segment("hyvää", 100, 400), Segment("päivää", 400, 800)]
>>> [c.name for c in prosody_commands(words, [], duration_ms=1000, seed=1)]
['BrowRaise', 'Blink', 'HeadNod']
"""

from __future__ import annotations

import random
from collections.abc import Sequence
from typing import TYPE_CHECKING

from engine.commands.command_files import HighLevelCommand

if TYPE_CHECKING:
    from engine.speech.synthesis import Segment

PAUSES = ("#", "##")
PHRASE_GAP_MS = 120.0
BLINK_MEAN_MS = 3500.0
BLINK_MIN_MS = 1200.0
VOWELS = set("aeiouyäöå@7")


def prosody_commands(words: Sequence[Segment], phones: Sequence[Segment], duration_ms: float, seed: int = 0,
                     blinks: bool = True, brows: bool = True, nods: bool = True) -> list[HighLevelCommand]:
    """High-level commands for visual prosody over an utterance."""
    rng = random.Random(seed)
    out: list[HighLevelCommand] = []
    phrases = split_phrases(words, phones)
    for phrase in phrases:
        first, last = phrase[0], phrase[-1]
        if brows and syllables(first.label) >= 2:
            apex = max(50.0, first.end_ms - first.start_ms - 150.0)
            out.append(_command("BrowRaise", at=first.start_ms, amplitude=40, onset=150, apex=apex, offset=250))
        if nods:
            out.append(_command("HeadNod", at=max(0.0, last.end_ms - 150.0), amplitude=30, count=1))
    if blinks:
        t = rng.uniform(300.0, 1500.0)
        while t < duration_ms:
            out.append(_command("Blink", at=round(t, 1)))
            t += max(BLINK_MIN_MS, rng.gammavariate(4.0, BLINK_MEAN_MS / 4.0))
    return sorted(out, key=lambda c: c.arguments["at"])


def split_phrases(words: Sequence[Segment], phones: Sequence[Segment]) -> list[list[Segment]]:
    """Words grouped into phrases at pauses."""
    pauses = [(p.start_ms, p.end_ms) for p in phones if p.label in PAUSES]
    phrases: list[list[Segment]] = []
    previous: Segment | None = None
    for word in words:
        gap = previous is not None and word.start_ms - previous.end_ms > PHRASE_GAP_MS
        paused = previous is not None and any(previous.end_ms - 1 <= s and e <= word.start_ms + 1 and e > s
                                              for s, e in pauses)
        if previous is None or gap or paused:
            phrases.append([])
        phrases[-1].append(word)
        previous = word
    return phrases


def syllables(word: str) -> int:
    """Vowel groups in a word (Finnish: one per syllable nucleus, diphthongs and long vowels once)."""
    count, in_vowel = 0, False
    for ch in word.lower():
        vowel = ch in VOWELS
        if vowel and not in_vowel:
            count += 1
        in_vowel = vowel
    return count


def _command(name: str, **arguments: float) -> HighLevelCommand:
    return HighLevelCommand(name, {k: float(v) for k, v in arguments.items()}, file="<prosody>")
