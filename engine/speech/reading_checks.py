"""What Festival will read oddly: numbers, dates and abbreviations to write out in words.

Festival's text front end expands some tokens on its own, and the Finnish
Suopuhe voices less than the English ones: ``674 500`` is read as two
numbers, ``12.6.`` digit by digit as a word, ``3,5`` as "kolme pilkku viisi"
at best, ``mm.`` letter by letter ("äm äm"). The face articulates whatever
Festival says, so a stimulus with such a token silently says something other
than the text. :func:`reading_warnings` names each token with its line and
column, so the user can write it out ("kuusisataaseitsemänkymmentäneljätuhatta
viisisataa", "kahdestoista kesäkuuta", "muun muassa").

>>> for warning in reading_warnings("Hinta on 674 500 euroa, mm. 12.6. alkaen", "suo_fi_lj_diphone"):
...     print(warning.located("text").split(": Festival")[0])
text:1: column 10: '674 500'
text:1: column 25: 'mm.'
text:1: column 29: '12.6.'
>>> reading_warnings("Pappa ampui pallon.", "suo_fi_lj_diphone")
[]
"""

from __future__ import annotations

import re
from dataclasses import dataclass

FINNISH_ABBREVIATIONS = {
    "mm.": "muun muassa", "esim.": "esimerkiksi", "jne.": "ja niin edelleen", "ym.": "ynnä muuta",
    "yms.": "ynnä muuta sellaista", "tms.": "tai muuta sellaista", "ks.": "katso", "n.": "noin",
    "s.": "sivu", "v.": "vuonna", "vrt.": "vertaa", "ns.": "niin sanottu", "eKr.": "ennen Kristusta",
    "jKr.": "jälkeen Kristuksen", "ts.": "toisin sanoen", "mm": "millimetriä", "cm": "senttimetriä",
    "km": "kilometriä", "kg": "kilogrammaa", "klo": "kello", "nro": "numero", "puh.": "puhelin",
}
"""Finnish abbreviations Suopuhe spells out letter by letter, with what to write instead."""

_DATE = re.compile(r"(?<![\w.])\d{1,2}\.\d{1,2}\.(?:\d{2,4}\b)?")
_GROUPED_NUMBER = re.compile(r"(?<![\w.,])\d{1,3}(?:[ \u00a0]\d{3})+(?![\w,.]\d)")
_DECIMAL = re.compile(r"(?<![\w.,])\d+[.,]\d+(?![\w.,]*\d)")
_ORDINAL = re.compile(r"(?<![\w.,])\d{1,3}\.(?=\s+\w)")
_INLINE_COMMAND = re.compile(r"<[^<>]*>")
_TOKEN = re.compile(r"(?<!\w)[A-Za-zÅÄÖåäö]{1,4}\.?(?!\w)")


@dataclass(frozen=True)
class ReadingWarning:
    """A token Festival will read oddly, where it stands in the text (from 1), and what to do."""

    line: int
    column: int
    token: str
    advice: str

    def located(self, name: str) -> str:
        """``NAME:LINE: column C: 'token': advice`` (the form of the toolkit's errors)."""
        return f"{name}:{self.line}: column {self.column}: '{self.token}': {self.advice}"


def reading_warnings(text: str, voice: str | None = None) -> list[ReadingWarning]:
    """Every token Festival will read oddly, in text order.

    Numbers and dates are checked for every voice; abbreviations for the
    Finnish voices (a voice name with ``_fi_`` in it, or no voice: the default
    is Finnish). Inline commands (``<HeadNod at="1.5"/>``) are not read, so not checked.
    """
    finnish = voice is None or "_fi_" in voice
    text = _INLINE_COMMAND.sub(lambda m: " " * len(m.group(0)), text)   # same columns, commands not read
    found: list[tuple[int, str, str]] = []
    taken: list[tuple[int, int]] = []

    def add(match: re.Match[str], advice: str) -> None:
        start, end = match.span()
        if any(start < e and s < end for s, e in taken):
            return
        taken.append((start, end))
        found.append((start, match.group(0), advice))

    for match in _DATE.finditer(text):
        add(match, "Festival reads a date written in digits oddly; write it out in words"
                   + (" (e.g. kahdestoista kesäkuuta)" if finnish else ""))
    for match in _GROUPED_NUMBER.finditer(text):
        add(match, "Festival reads digits separated by spaces as separate numbers; write the number out in words")
    for match in _DECIMAL.finditer(text):
        add(match, "Festival reads a decimal number digit by digit or as separate numbers; write it out in words")
    if finnish:
        for match in _ORDINAL.finditer(text):
            add(match, "Festival reads an ordinal number (a number with a full stop) as a cardinal; "
                       "write it out in words")
        for match in _TOKEN.finditer(text):
            expansion = FINNISH_ABBREVIATIONS.get(match.group(0))
            if expansion is not None:
                add(match, f"Festival reads this abbreviation letter by letter; write it out ({expansion})")
    found.sort()
    return [ReadingWarning(*_line_column(text, start), token, advice) for start, token, advice in found]


def _line_column(text: str, offset: int) -> tuple[int, int]:
    line = text.count("\n", 0, offset) + 1
    return line, offset - (text.rfind("\n", 0, offset) + 1) + 1
