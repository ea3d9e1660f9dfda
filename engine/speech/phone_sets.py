"""Phone sets of label files: which phone a label names, and its features.

A recorded voice comes with phone labels written in some phone set. Each set
here turns a label into the name the articulation table knows and the
phone's features (:class:`~engine.speech.phone_features.PhoneFeatures`), so
the face articulates any of them (targets from the features where no table
row exists, issue 16 §3):

============  ======================================================  =====================
name          labels                                                  articulation table
============  ======================================================  =====================
``finnish``   Festival's Suopuhe phones (``a e i o u y @ 7``, ``a:``)  finnish.phones
``radio``     Festival's US English phones (``aa ae … zh pau``)       english.phones
``arpabet``   ARPAbet as the Montreal Forced Aligner writes it          english.phones
              (``AA1 B IY0``, ``sil sp spn``)
``ipa``       IPA symbols, with ``ː`` for length (``pʰ``, ``t͡ʃ``)      from features
``x-sampa``   X-SAMPA (and SAMPA, its subset): ``{ 2 @ tS A:``          from features
============  ======================================================  =====================

Pauses (``sil``, ``sp``, ``spn``, ``pau``, ``#``, ``_``, ``<p:>``, an empty
label) become the set's pause. :func:`guess_phone_set` picks the set whose
symbols cover every label.

>>> ipa = PHONE_SETS["ipa"]
>>> ipa.phone("ˈaː"), str(ipa.features("aː"))
('aː', '+ l 3 1 - 0 0 0')
>>> PHONE_SETS["arpabet"].phone("AA1"), PHONE_SETS["x-sampa"].phone("tS")
('aa', 't͡ʃ')
>>> guess_phone_set(["sil", "HH", "AH0", "L", "OW1"]).name
'arpabet'
"""

from __future__ import annotations

import unicodedata
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from engine.speech.phone_features import PhoneFeatures

PAUSE_LABELS = frozenset({"", "sil", "sp", "spn", "pau", "#", "##", "_", "<p:>", "<sil>", "h#", "SIL", "SP", "<p>"})
"""Labels that mean silence in the phone sets and aligners we know."""

# IPA vowels: symbol → (height 1 high … 3 low, frontness 1 front … 3 back, rounded)
_IPA_VOWELS = {
    "i": ("1", "1", "-"), "y": ("1", "1", "+"), "ɨ": ("1", "2", "-"), "ʉ": ("1", "2", "+"),
    "ɯ": ("1", "3", "-"), "u": ("1", "3", "+"), "ɪ": ("1", "1", "-"), "ʏ": ("1", "1", "+"),
    "ʊ": ("1", "3", "+"), "e": ("2", "1", "-"), "ø": ("2", "1", "+"), "ɘ": ("2", "2", "-"),
    "ɵ": ("2", "2", "+"), "ɤ": ("2", "3", "-"), "o": ("2", "3", "+"), "ə": ("2", "2", "-"),
    "ɛ": ("2", "1", "-"), "œ": ("2", "1", "+"), "ɜ": ("2", "2", "-"), "ɞ": ("2", "2", "+"),
    "ʌ": ("2", "3", "-"), "ɔ": ("2", "3", "+"), "æ": ("3", "1", "-"), "ɐ": ("3", "2", "-"),
    "a": ("3", "1", "-"), "ɶ": ("3", "1", "+"), "ɑ": ("3", "3", "-"), "ɒ": ("3", "3", "+"),
    "ɚ": ("2", "2", "-"), "ɝ": ("2", "2", "-"),
}
# IPA consonants: symbol → (type: s stop, f fricative, a affricate, n nasal, l lateral, r approximant/trill;
#                           place: l labial, b labio-dental, d dental, a alveolar, p palatal/postalveolar,
#                           v velar/uvular, g glottal/pharyngeal; voiced)
_IPA_CONSONANTS = {
    "p": ("s", "l", "-"), "b": ("s", "l", "+"), "t": ("s", "a", "-"), "d": ("s", "a", "+"),
    "ʈ": ("s", "a", "-"), "ɖ": ("s", "a", "+"), "c": ("s", "p", "-"), "ɟ": ("s", "p", "+"),
    "k": ("s", "v", "-"), "g": ("s", "v", "+"), "ɡ": ("s", "v", "+"), "q": ("s", "v", "-"),
    "ɢ": ("s", "v", "+"), "ʔ": ("s", "g", "-"),
    "m": ("n", "l", "+"), "ɱ": ("n", "b", "+"), "n": ("n", "a", "+"), "ɳ": ("n", "a", "+"),
    "ɲ": ("n", "p", "+"), "ŋ": ("n", "v", "+"), "ɴ": ("n", "v", "+"),
    "ʙ": ("r", "l", "+"), "r": ("r", "a", "+"), "ʀ": ("r", "v", "+"), "ɾ": ("s", "a", "+"),
    "ɽ": ("s", "a", "+"),
    "ɸ": ("f", "l", "-"), "β": ("f", "l", "+"), "f": ("f", "b", "-"), "v": ("f", "b", "+"),
    "θ": ("f", "d", "-"), "ð": ("f", "d", "+"), "s": ("f", "a", "-"), "z": ("f", "a", "+"),
    "ʃ": ("f", "p", "-"), "ʒ": ("f", "p", "+"), "ʂ": ("f", "p", "-"), "ʐ": ("f", "p", "+"),
    "ç": ("f", "p", "-"), "ʝ": ("f", "p", "+"), "x": ("f", "v", "-"), "ɣ": ("f", "v", "+"),
    "χ": ("f", "v", "-"), "ʁ": ("f", "v", "+"), "ħ": ("f", "g", "-"), "ʕ": ("f", "g", "+"),
    "h": ("f", "g", "-"), "ɦ": ("f", "g", "+"),
    "ʋ": ("r", "b", "+"), "ɹ": ("r", "a", "+"), "ɻ": ("r", "a", "+"), "j": ("r", "p", "+"),
    "ɰ": ("r", "v", "+"), "w": ("r", "l", "+"), "ɥ": ("r", "p", "+"),
    "l": ("l", "a", "+"), "ɭ": ("l", "a", "+"), "ʎ": ("l", "p", "+"), "ʟ": ("l", "v", "+"), "ɫ": ("l", "a", "+"),
    "t͡ʃ": ("a", "p", "-"), "d͡ʒ": ("a", "p", "+"), "t͡s": ("a", "a", "-"), "d͡z": ("a", "a", "+"),
    "t͡ɕ": ("a", "p", "-"), "d͡ʑ": ("a", "p", "+"), "ɕ": ("f", "p", "-"), "ʑ": ("f", "p", "+"),
}
_IPA_AFFRICATES = {"tʃ": "t͡ʃ", "dʒ": "d͡ʒ", "ts": "t͡s", "dz": "d͡z", "tɕ": "t͡ɕ", "dʑ": "d͡ʑ",
                   "ʧ": "t͡ʃ", "ʤ": "d͡ʒ", "ʦ": "t͡s", "ʣ": "d͡z"}
_IPA_LONG = "ː"
_DIPHTHONG_ENDS = set("jwɪʊʏ")
_IPA_IGNORED = set("ˈˌˑ.ʰʷʲˠˤⁿˡ̥̬̩̯̃̚˞ʼ") | {"\u0361", "\u035c"}
"""Stress, syllable marks and diacritics that do not change which articulators move (the tie bar is
put back where an affricate needs it)."""

_X_SAMPA = {
    "1": "ɨ", "}": "ʉ", "M": "ɯ", "I": "ɪ", "Y": "ʏ", "U": "ʊ", "2": "ø", "@\\": "ɘ", "8": "ɵ", "7": "ɤ",
    "@": "ə", "E": "ɛ", "9": "œ", "3": "ɜ", "3\\": "ɞ", "V": "ʌ", "O": "ɔ", "{": "æ", "6": "ɐ", "&": "ɶ",
    "A": "ɑ", "Q": "ɒ", "@`": "ɚ", "3`": "ɝ",
    "t`": "ʈ", "d`": "ɖ", "J\\": "ɟ", "G\\": "ɢ", "?": "ʔ", "F": "ɱ", "n`": "ɳ", "J": "ɲ", "N": "ŋ",
    "N\\": "ɴ", "B\\": "ʙ", "R\\": "ʀ", "4": "ɾ", "r`": "ɽ", "p\\": "ɸ", "B": "β", "T": "θ", "D": "ð",
    "S": "ʃ", "Z": "ʒ", "s`": "ʂ", "z`": "ʐ", "C": "ç", "j\\": "ʝ", "G": "ɣ", "X": "χ", "R": "ʁ",
    "X\\": "ħ", "?\\": "ʕ", "h\\": "ɦ", "P": "ʋ", "v\\": "ʋ", "r\\": "ɹ", "r\\`": "ɻ", "M\\": "ɰ",
    "l`": "ɭ", "L": "ʎ", "L\\": "ʟ", "H": "ɥ", "5": "ɫ", "s\\": "ɕ", "z\\": "ʑ",
    "tS": "t͡ʃ", "dZ": "d͡ʒ", "ts": "t͡s", "dz": "d͡z", "ts\\": "t͡ɕ", "dz\\": "d͡ʑ",
    ":": "ː",
}
_X_SAMPA_IGNORED = set('"%.=~\'`')
"""Stress, syllable and syllabic marks, nasalisation, palatalisation, rhoticity: not which articulators move."""
_X_SAMPA_PLAIN = set("ieaouyptdkgbmnfvszjlrwhxcq")

_ARPABET = {"AA", "AE", "AH", "AO", "AW", "AY", "B", "CH", "D", "DH", "EH", "ER", "EY", "F", "G", "HH", "IH",
            "IY", "JH", "K", "L", "M", "N", "NG", "OW", "OY", "P", "R", "S", "SH", "T", "TH", "UH", "UW", "V",
            "W", "Y", "Z", "ZH", "AX", "AXR", "DX", "EL", "EM", "EN", "NX", "HV"}


@dataclass(frozen=True)
class PhoneSet:
    """Labels → the phone names an articulation table knows, and their features.

    ``festival_phoneset`` picks the shipped table (``$phoneset``); ``pause``
    is the name silences get; ``_name_of`` returns ``None`` for a label the set
    does not know.
    """

    name: str
    festival_phoneset: str
    pause: str
    _name_of: Callable[[str], str | None]
    _features_of: Callable[[str], PhoneFeatures | None]

    def phone(self, label: str) -> str | None:
        """The phone ``label`` names (the set's pause for a silence), ``None`` if the set does not know it."""
        stripped = label.strip()
        if stripped in PAUSE_LABELS:
            return self.pause
        return self._name_of(stripped)

    def features(self, phone: str) -> PhoneFeatures | None:
        """Features of a phone name :meth:`phone` returned (``None`` where the table's own row is used)."""
        if phone == self.pause:
            return PhoneFeatures("-", "0", "0", "0", "0", "0", "0", "-")
        return self._features_of(phone)


def ipa_phone(label: str) -> str | None:
    """The IPA label without stress or diacritics, affricates tied (``t͡ʃ``), length kept (``aː``); ``None``
    if what remains is not one vowel or consonant we know."""
    text = unicodedata.normalize("NFD", label)
    long = _IPA_LONG in text or text.endswith(":")
    kept = "".join(c for c in text if c not in _IPA_IGNORED and c not in (_IPA_LONG, ":"))
    kept = unicodedata.normalize("NFC", _IPA_AFFRICATES.get(kept, kept))
    if len(kept) == 2 and kept[0] == kept[1]:                   # a geminate or long vowel written twice
        kept, long = kept[0], True
    if kept in _IPA_VOWELS or kept in _IPA_CONSONANTS:
        return kept + (_IPA_LONG if long else "")
    if len(kept) == 2 and kept[0] in _IPA_VOWELS and (kept[1] in _IPA_VOWELS or kept[1] in _DIPHTHONG_ENDS):
        return kept                                              # a diphthong: aɪ, aj, ɔʏ, ow
    return None


def ipa_features(phone: str) -> PhoneFeatures | None:
    """Festival-style features of an :func:`ipa_phone` name; a diphthong has its first part's, length ``d``."""
    if len(phone) == 2 and phone[0] in _IPA_VOWELS and phone[1] != _IPA_LONG:
        height, front, rounded = _IPA_VOWELS[phone[0]]
        return PhoneFeatures("+", "d", height, front, rounded, "0", "0", "0")
    base = phone.removesuffix(_IPA_LONG)
    if base in _IPA_VOWELS:
        height, front, rounded = _IPA_VOWELS[base]
        length = "l" if phone.endswith(_IPA_LONG) else ("a" if base == "ə" else "s")
        return PhoneFeatures("+", length, height, front, rounded, "r" if base in "ɚɝ" else "0", "0", "0")
    if base in _IPA_CONSONANTS:
        kind, place, voiced = _IPA_CONSONANTS[base]
        return PhoneFeatures("-", "0", "0", "0", "0", kind, place, voiced)
    return None


def x_sampa_to_ipa(label: str) -> str | None:
    """X-SAMPA (longest symbol first) as IPA, or ``None`` for a character X-SAMPA does not have."""
    out, i = [], 0
    while i < len(label):
        for size in (3, 2, 1):
            piece = label[i:i + size]
            if len(piece) == size and piece in _X_SAMPA:
                out.append(_X_SAMPA[piece])
                i += size
                break
        else:
            char = label[i]
            if char == "_":                     # a diacritic: _h aspirated, _w labialised, _0 voiceless …
                i += 2
                continue
            if char in _X_SAMPA_IGNORED:
                i += 1
                continue
            if char not in _X_SAMPA_PLAIN:
                return None
            out.append("ɡ" if char == "g" else char)
            i += 1
    return "".join(out)


def _x_sampa_phone(label: str) -> str | None:
    ipa = x_sampa_to_ipa(label)
    return ipa_phone(ipa) if ipa else None


def _arpabet_phone(label: str) -> str | None:
    base = label.rstrip("012").upper()
    return base.lower() if base in _ARPABET else None


def _table_phone(known: frozenset[str]) -> Callable[[str], str | None]:
    def name(label: str) -> str | None:
        return label if label in known or label.rstrip(":") in known else None
    return name


def _no_features(_phone: str) -> PhoneFeatures | None:
    return None


_SUOPUHE = frozenset({"a", "e", "i", "o", "u", "y", "@", "7", "p", "b", "t", "d", "k", "g", "m", "n", "N", "f", "v",
                       "s", "S", "h", "j", "l", "r", "T", "z"})
_RADIO = frozenset(name.lower() for name in _ARPABET)

PHONE_SETS: dict[str, PhoneSet] = {
    "finnish": PhoneSet("finnish", "finnish", "#", _table_phone(_SUOPUHE), _no_features),
    "radio": PhoneSet("radio", "radio", "pau", _table_phone(_RADIO), _no_features),
    "arpabet": PhoneSet("arpabet", "radio", "pau", _arpabet_phone, _no_features),
    "ipa": PhoneSet("ipa", "ipa", "_", ipa_phone, ipa_features),
    "x-sampa": PhoneSet("x-sampa", "ipa", "_", _x_sampa_phone, ipa_features),
}
PHONE_SETS["sampa"] = PHONE_SETS["x-sampa"]
PHONE_SETS["festival"] = PHONE_SETS["finnish"]

GUESS_ORDER = ("arpabet", "finnish", "radio", "ipa", "x-sampa")
"""Which set :func:`guess_phone_set` tries first: the more specific sets before the more general."""


def guess_phone_set(labels: Iterable[str]) -> PhoneSet:
    """The first set of :data:`GUESS_ORDER` that knows every label; :class:`ValueError` naming the labels
    no set knows otherwise."""
    distinct = sorted({label.strip() for label in labels} - PAUSE_LABELS)
    for name in GUESS_ORDER:
        candidate = PHONE_SETS[name]
        if all(candidate.phone(label) is not None for label in distinct):
            return candidate
    best = closest_phone_set(distinct).name
    unknown = [label for label in distinct if PHONE_SETS[best].phone(label) is None]
    raise ValueError(f"no phone set knows every label (closest: {best}, which does not know "
                     f"{', '.join(repr(u) for u in unknown[:8])}{' …' if len(unknown) > 8 else ''})")


def closest_phone_set(labels: Iterable[str]) -> PhoneSet:
    """The set of :data:`GUESS_ORDER` that knows the most of ``labels`` (the first of equals)."""
    distinct = {label.strip() for label in labels} - PAUSE_LABELS
    return PHONE_SETS[min(GUESS_ORDER, key=lambda n: sum(PHONE_SETS[n].phone(label) is None for label in distinct))]
