"""Articulation targets derived from a phone's features, for any Festival voice.

Every Festival phone set describes each phone by the same eight features
(``radio_phones.scm``, Suopuhe's ``finnish_phones.scm``, …):

=========  ==================================================================
``vc``     vowel ``+`` or consonant ``-``
``vlng``   vowel length: short ``s``, long ``l``, diphthong ``d``, schwa ``a``
``vheight`` vowel height: high ``1``, mid ``2``, low ``3``
``vfront`` vowel frontness: front ``1``, central ``2``, back ``3``
``vrnd``   lip rounding ``+`` / ``-``
``ctype``  consonant type: stop ``s``, fricative ``f``, affricate ``a``, nasal ``n``,
           lateral ``l``, approximant ``r``
``cplace`` place: labial ``l``, alveolar ``a``, palatal ``p``, labio-dental ``b``,
           dental ``d``, velar ``v``, glottal ``g``
``cvox``   voicing ``+`` / ``-``
=========  ==================================================================

(``0`` is "does not apply".) :func:`derived_cells` turns them into a row of
an articulation table (``engine/library/articulation/*.phones`` syntax) for the
default head's six articulatory parameters. The values are the Finnish hand-made
table's, generalised: the jaw opens by vowel height, the lips spread for
unrounded front vowels and round for rounded ones, bilabial stops and nasals
close the lips (enforced), labio-dentals bring the lower lip to the upper
teeth, coronals raise the tongue, and pauses return to rest. A hand-made
row always takes precedence (:func:`engine.speech.articulation.table_for`).

>>> open_a = PhoneFeatures.parse("+ s 3 3 - 0 0 0")
>>> derived_cells(open_a, ["jaw_open", "mouth_widen", "lip_protrude"])
['0.4', '0.25', '0']
>>> derived_cells(PhoneFeatures.parse("- 0 0 0 0 s l -"), ["jaw_open", "lower_lip_raise"])   # p
['0!/2', '1!/2']
>>> PhoneFeatures.parse("- 0 0 0 0 0 0 -").is_pause
True
"""

from __future__ import annotations

from dataclasses import dataclass, fields

FEATURE_NAMES = ("vc", "vlng", "vheight", "vfront", "vrnd", "ctype", "cplace", "cvox")
"""Festival's phone features, in the order :func:`PhoneFeatures.parse` reads them."""

_JAW_BY_HEIGHT = {"1": 0.13, "2": 0.26, "3": 0.4}
_ROUNDING = {  # (frontness, height) → lip_protrude of a rounded vowel: back vowels round more
    ("1", "1"): 0.95, ("1", "2"): 0.6, ("1", "3"): 0.5,
    ("2", "1"): 0.95, ("2", "2"): 0.7, ("2", "3"): 0.55,
    ("3", "1"): 1.0, ("3", "2"): 0.75, ("3", "3"): 0.55,
}
_SPREAD = {  # (frontness, height) → mouth_widen of an unrounded vowel
    ("1", "1"): 0.9, ("1", "2"): 0.65, ("1", "3"): 0.45,
    ("2", "1"): 0.55, ("2", "2"): 0.45, ("2", "3"): 0.35,
    ("3", "1"): 0.5, ("3", "2"): 0.35, ("3", "3"): 0.25,
}
_TONGUE_BY_VOWEL = {("1", "1"): 0.2, ("1", "2"): 0.1}  # (frontness, height): front close/mid vowels

_REST = "0/0.6"
_FREE = "-"

# Consonant rows by place (and type), in the order jaw, widen, protrude, upper lip, lower lip, tongue.
_BILABIAL_CLOSURE = ("0!/2", _FREE, _FREE, "0/2", "1!/2", _FREE)
_LABIAL_GLIDE = ("0.12/0.5", _FREE, "0.8", _FREE, _FREE, _FREE)
_LABIODENTAL = ("0.06/3", _FREE, "0/2", "0.35/2", "0.7!/2", _FREE)
_DENTAL = ("0.14/0.6", _FREE, _FREE, _FREE, _FREE, "0.8/2")
_ALVEOLAR = ("0.14/0.6", _FREE, _FREE, _FREE, _FREE, "0.7/2")
_POSTALVEOLAR = ("0.14/0.6", _FREE, "0.35", _FREE, _FREE, "0.6/2")
_PALATAL_GLIDE = ("0.12/0.5", "0.5/0.5", _FREE, _FREE, _FREE, "0.3")
_VELAR = ("0.16/0.5", _FREE, _FREE, _FREE, _FREE, _FREE)
_UNCONSTRAINED = (_FREE,) * 6

DERIVED_PARAMETERS = ("jaw_open", "mouth_widen", "lip_protrude", "upper_lip_raise", "lower_lip_raise",
                      "tongue_raise")
"""The parameters :func:`derived_cells` knows; any other parameter gets ``-`` (left to its neighbours)."""


@dataclass(frozen=True)
class PhoneFeatures:
    """One phone's features as its Festival phone set gives them (``0``: does not apply)."""

    vc: str = "0"
    vlng: str = "0"
    vheight: str = "0"
    vfront: str = "0"
    vrnd: str = "0"
    ctype: str = "0"
    cplace: str = "0"
    cvox: str = "0"

    @classmethod
    def parse(cls, text: str) -> PhoneFeatures:
        """From the eight features separated by white space (missing ones are ``0``)."""
        values = text.split()[: len(FEATURE_NAMES)]
        return cls(*values)

    def __str__(self) -> str:
        return " ".join(getattr(self, f.name) for f in fields(self))

    @property
    def is_vowel(self) -> bool:
        """A vowel proper (syllabic consonants such as English ``em`` count as consonants)."""
        return self.vc == "+" and self.ctype in ("0", "r") and self.vheight != "0"

    @property
    def is_pause(self) -> bool:
        """Silence: neither a vowel nor a consonant with a type or a place (``pau``, ``#``, ``h#``)."""
        return self.vc != "+" and self.ctype == "0" and self.cplace == "0"


def derived_cells(features: PhoneFeatures, parameters: list[str] | tuple[str, ...]) -> list[str]:
    """The cells (table syntax, ``target[!][/dominance]`` or ``-``) of ``parameters`` for a phone."""
    row = dict(zip(DERIVED_PARAMETERS, _default_head_row(features), strict=True))
    return [row.get(name, _FREE) for name in parameters]


def _default_head_row(features: PhoneFeatures) -> tuple[str, ...]:
    if features.is_pause:
        return (_REST,) * 6
    if features.is_vowel:
        return _vowel_row(features)
    return _consonant_row(features)


def _vowel_row(f: PhoneFeatures) -> tuple[str, ...]:
    height = f.vheight if f.vheight in _JAW_BY_HEIGHT else "2"
    front = f.vfront if f.vfront in ("1", "2", "3") else "2"
    jaw = _JAW_BY_HEIGHT[height]
    tongue = _TONGUE_BY_VOWEL.get((front, height), 0.0)
    if f.vrnd == "+":
        return (_number(jaw), "0", _number(_ROUNDING[front, height]), "0", "0",
                _number(tongue / 2 if tongue else 0.0))
    upper_lip = 0.15 if height == "3" else 0.1
    return (_number(jaw), _number(_SPREAD[front, height]), "0", _number(upper_lip), "0", _number(tongue))


def _consonant_row(f: PhoneFeatures) -> tuple[str, ...]:
    place, kind = f.cplace, f.ctype
    if place == "l":
        return _LABIAL_GLIDE if kind == "r" else _BILABIAL_CLOSURE
    if place == "b":
        return _LABIODENTAL
    if place == "d":
        return _DENTAL
    if place == "a":
        return _ALVEOLAR
    if place == "p":
        return _PALATAL_GLIDE if kind == "r" else _POSTALVEOLAR
    if place == "v":
        return _VELAR
    return _UNCONSTRAINED


def _number(value: float) -> str:
    return f"{value:g}"
