"""A population model of the identity space: plausible people drawn at random, the same person from the same seed.

:func:`draw_identity` draws one adult from population model
:data:`POPULATION` (version 2; docs/population.md says the same in words,
with the spread measured; model 1, drawable still, spread faces less: :data:`SPREADS`):

* **sex** — a woman or a man with probability ½ each (or the one asked
  for); a woman's ``sex`` is ``|N(0, 0.1)|`` (at most 0.3), a man's 1 minus
  that: two modes with a little spread, as MakeHuman's sex target is a
  continuum;
* **age** — uniform in years over the chosen range (18 … 75 by default);
* **ancestry** — a point on the simplex: one of the three ancestries chosen
  with probability ⅓ each holds ``1 − m`` of the mix, where ``m`` is 0 for
  60 % of people and uniform in 0 … 0.5 for the rest, split between the other
  two by a uniform share;
* **muscle**, **weight** — ``N(0.5, 0.12)`` and ``N(0.5, 0.15)``, within
  0.2 … 0.8 and 0.15 … 0.85;
* **face modifiers** — jointly Gaussian around the default (0): each
  modifier's spread ``σ`` moves its target's furthest vertex by
  :data:`SPREAD_MM` at 1 σ (at most ``σ`` = :data:`MAX_SIGMA`, 0.4; a detail modifier — a bump,
  a fold, one part of the nose's width, :data:`DETAIL_WORDS` — half that), and two modifiers are
  correlated by :data:`COHERENCE` × the cosine between their targets'
  displacement fields (modifiers that move the same skin the same way vary
  together: a wide nose is wide at the bridge, the wings and the tip); each
  is cut at ±2.5 σ; the shapes around the mouth that the rig's lip fits
  follow (:data:`LIP_WORDS`) at a quarter of that spread; the single-target
  head and chin shapes (``head-oval`` …) are ``|N(0, σ)|``;
* **not drawn** — the modifiers that place or turn the whole head, and the
  neck's (pose, not face); the lips' own shape (:data:`LIP_SHAPE`: their
  heights, widths, volumes, bow and philtrum); and everything one-sided:
  faces are drawn symmetric (no per-side offsets, no sideways shift of the
  nose or mouth, no one-eye fold), as the rig's checks expect;
* **bounded** — the face modifiers together move no vertex more than
  :data:`MAX_FACE_MM` from where the macro parameters put it: a draw that
  would is scaled down to that.

Values given (``fixed``) are kept exactly; the face modifiers not given are
drawn from their distribution *given* the fixed ones (the Gaussian's
conditional), so fixing a wide nose also widens its wings. Every value is
rounded (4 decimals; age 0.1 year), so the same seed gives the same
identity, and the same ``<identity>`` in the model file byte for byte, on any
machine (the rig fitted to it can differ in the tenth digit). The random
numbers come from :class:`random.Random`'s ``random()`` alone, whose
sequence for a seed Python guarantees across versions, through one stream
per part of the draw (fixing the sex does not change the face drawn).

>>> a, b = draw_identity(7), draw_identity(7)
>>> a == b, a.drawn["seed"], a.drawn["population"]
(True, '7', '2')
>>> draw_identity(7, sex="female").value("sex") < 0.5
True
"""

from __future__ import annotations

import hashlib
import math
import random
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from functools import cache
from typing import Any

import numpy as np

from engine.identity.errors import IdentityError
from engine.identity.parameters import (
    MACRO,
    RACES,
    Identity,
    face_modifiers,
    identity_parameter,
    identity_parameters,
)

POPULATION = 2
"""The population model's version: recorded with every identity drawn, so a set can be drawn again."""
POPULATIONS = (1, 2)
"""The versions this program draws from."""
MAX_SEED = 2**32 - 1
MAX_COUNT = 1000         # random identities asked for at once
APART_POOL = 4           # "apart": the people are chosen from this many times as many draws
ADULT_AGES = (18.0, 75.0)
SPREAD_MM = 4.5          # a face modifier's 1 σ moves its target's furthest vertex this far (model 1: 3.0)
MAX_SIGMA = 0.4
DETAIL = 0.5             # the spread of a detail modifier (a bump, a fold, a lip's volume) × that of a proportion
#: Detail modifiers: local shapes (a bump, a fold, a dimple, one part of the nose's width), drawn at
#: DETAIL × the spread; every other drawn modifier sets a proportion (size, place, angle of a feature).
DETAIL_WORDS = ("width1", "width2", "width3", "compression", "greek", "hump", "cupidsbow", "dimples",
                "laugh-lines", "philtrum", "cleft", "eyefold", "bag", "flaring", "volume", "-ext-", "point-width",
                "septumangle", "nubian", "temple", "push1", "push2", "height1", "height2", "height3",
                "corner1", "corner2", "nostrils-angle", "jaw-drop", "head-age", "head-fat", "middle")
#: Around the mouth, the shapes the rig's lip fits (closure, protrusion; docs/identity.md) hold on only
#: near the default head's: drawn at LIPS × the spread. The lips' own shape (LIP_SHAPE) is not drawn.
LIP_WORDS = ("mouth-angles-", "mouth-scale-vert-", "mouth-scale-depth-", "mouth-trans-backward-", "chin-prognathism-",
             "chin-jaw-drop-")
LIPS = 0.25
CUT = 2.5                # a face modifier is cut at ±CUT σ
COHERENCE = 0.8          # the correlation of two modifiers: this × the cosine of their displacement fields
MAX_FACE_MM = 22.0       # the face modifiers together move no vertex further than this (model 1: 15.0)
#: Each population model's (SPREAD_MM, MAX_FACE_MM). Model 1's bound held half its draws back (docs/population.md);
#: model 2 spreads faces wider. Both draw the same random numbers for a seed: the same person, spread more.
SPREADS = {1: (3.0, 15.0), 2: (SPREAD_MM, MAX_FACE_MM)}
#: Modifiers not drawn: they place or turn the whole head, or shape the neck (pose and body, not face).
#: The lips' own shape: their heights, widths, volumes and bow (on random faces the rig's lip fits let the lips
#: cross near the corners with these, even at a quarter of the spread; see docs/identity.md).
LIP_SHAPE = ("mouth-lowerlip-", "mouth-upperlip-", "mouth-cupidsbow", "mouth-philtrum-")
#: Faces are drawn symmetric (the rig's checks hold a face's two halves to be mirror images): the
#: modifiers that move the nose or mouth sideways, or shape one eye only, are not drawn either.
NOT_DRAWN_PREFIXES = ("head-angle-", "head-trans-", "head-back-", "measure-neck-", "neck-",
                      "nose-trans-in-out", "mouth-trans-in-out", "eye-eyefold-concave-convex",
                      *LIP_SHAPE)
SEXES = ("female", "male")


@dataclass(frozen=True)
class DrawRequest:
    """What is asked of a draw: the ``seed``, and optionally the sex, an age range and fixed values."""

    seed: int
    sex: str | None = None
    ages: tuple[float, float] | None = None
    fixed: Mapping[str, float] = field(default_factory=dict)
    population: int = POPULATION

    def given(self) -> str:
        """What was asked besides the seed, as one line (``sex=female;age=20-40;nose-…=0.3``), '' for nothing."""
        parts = [f"sex={self.sex}"] if self.sex else []
        if self.ages is not None:
            parts.append(f"age={self.ages[0]:g}-{self.ages[1]:g}")
        parts += [f"{k}={v:g}" for k, v in self.fixed.items()]
        return ";".join(parts)


def draw_identity(seed: int, sex: str | None = None, ages: tuple[float, float] | None = None,
                  fixed: Mapping[str, float] | None = None, population: int = POPULATION) -> Identity:
    """A person drawn from population model ``population`` with ``seed`` (see the module's text).

    ``sex`` "female" or "male" draws from that mode only; ``ages`` (years, low, high) replaces the
    adult range; ``fixed`` values are kept exactly. The identity's ``drawn`` says how it was drawn.
    Bad input (a seed outside 0 … 2³²−1, a fixed value that contradicts the sex or the age range
    asked for, an unknown parameter) is an :class:`IdentityError`.
    """
    return _identity(check_request(DrawRequest(seed, sex, ages, dict(fixed or {}), population)))


def draw_identities(count: int, seed: int, sex: str | None = None, ages: tuple[float, float] | None = None,
                    fixed: Mapping[str, float] | None = None, apart: bool = False,
                    population: int = POPULATION) -> list[Identity]:
    """``count`` people: those of seeds ``seed`` … ``seed + count − 1``, or with ``apart`` the ``count`` of
    seeds ``seed`` … ``seed + APART_POOL × count − 1`` that are furthest apart in shape.

    ``apart`` chooses greedily: the first seed's person, then each time the candidate whose nearest
    chosen face is furthest (:func:`shape_distance`). Each person is the one :func:`draw_identity`
    draws with its own seed (recorded in its ``drawn``), so any one can be drawn again alone.
    """
    if isinstance(count, bool) or not isinstance(count, int) or not 1 <= count <= MAX_COUNT:
        raise IdentityError(f"the number of random identities must be a whole number from 1 to {MAX_COUNT}, "
                            f"not {count!r}")
    pool = count * APART_POOL if apart and count > 1 else count
    first = check_request(DrawRequest(seed, sex, ages, dict(fixed or {}), population))
    if first.seed + pool - 1 > MAX_SEED:
        raise IdentityError(f"seeds {first.seed} … {first.seed + pool - 1} go past {MAX_SEED}: choose a smaller seed")
    people = [_identity(replace(first, seed=first.seed + k)) for k in range(pool)]
    if pool == count:
        return people
    shapes = [shape_signature(p) for p in people]
    chosen = [0]
    nearest = np.array([_distance(shapes[0], s) for s in shapes])
    while len(chosen) < count:
        nearest[chosen] = -1.0
        best = int(np.argmax(nearest))
        chosen.append(best)
        nearest = np.minimum(nearest, [_distance(shapes[best], s) for s in shapes])
    return [people[k] for k in chosen]


def random_levels(table: Mapping[str, Any]) -> list[dict[str, Any]]:
    """A stimulus design's random people, ``{random = N, seed = S}`` (docs/stimuli.md), as N levels of one person
    each, ``{random = 1, seed = s, population = 1, …}``; what else the table gives is kept in every level.

    The table may give ``apart = true`` (the N furthest apart of APART_POOL × N draws), ``sex = "female"``
    or ``"male"``, ``age`` (years, or ``[LOW, HIGH]``), ``population`` (1) and any identity parameter's
    value. A mistake is an :class:`IdentityError` saying what is wrong.
    """
    count = table.get("random")
    apart = table.get("apart", False)
    if not isinstance(apart, bool):
        raise IdentityError("apart must be true or false")
    request = level_request(table)
    people = draw_identities(count, request.seed, request.sex, request.ages, request.fixed, apart,
                             request.population) if isinstance(count, int) else []
    if not people:
        raise IdentityError(f"random must be the number of people, 1 to {MAX_COUNT}, not {_shown(count)}")
    given = {k: v for k, v in table.items() if k not in ("random", "seed", "apart", "population")}
    return [{"random": 1, "seed": int(p.drawn["seed"]) if p.drawn else 0, "population": request.population,
             **given} for p in people]


def level_request(level: Mapping[str, Any]) -> DrawRequest:
    """The draw a random-identity level or table asks for (its ``random`` count aside), checked."""
    known = {"random", "seed", "apart", "population", "sex", "age"}
    fixed: dict[str, float] = {}
    for name, value in level.items():
        if name in known - {"age"}:
            continue
        if name == "age" and isinstance(value, list):
            continue
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise IdentityError(f"{name} must be a number, not {_shown(value)}")
        fixed[name] = float(value)
    age = level.get("age")
    ages = None
    if isinstance(age, list):
        if len(age) != 2 or not all(isinstance(a, int | float) and not isinstance(a, bool) for a in age):
            raise IdentityError(f"an age range is two numbers of years, [LOW, HIGH], not {_shown(age)}")
        ages = (float(age[0]), float(age[1]))
    sex = level.get("sex")
    if isinstance(sex, int | float) and not isinstance(sex, bool):
        fixed["sex"], sex = float(sex), None
    return check_request(DrawRequest(level.get("seed"), sex, ages, fixed,   # type: ignore[arg-type]
                                     level.get("population", POPULATION)))


def level_identity(level: Mapping[str, Any]) -> Identity:
    """The person of one random-identity level ``{random = 1, seed = s, …}``."""
    if level.get("random") != 1 or isinstance(level.get("random"), bool):
        raise IdentityError("a level of one random person has random = 1")
    return _identity(level_request(level))


def is_random_level(level: object) -> bool:
    """Whether a design's identity level (or table) asks for random people (``random = …``)."""
    return isinstance(level, Mapping) and "random" in level


def check_request(request: DrawRequest) -> DrawRequest:
    """``request`` with its fixed values checked and ordered, or :class:`IdentityError` saying what is wrong."""
    seed = request.seed
    if isinstance(seed, bool) or not isinstance(seed, int | np.integer) or not 0 <= int(seed) <= MAX_SEED:
        raise IdentityError(f"a random identity's seed must be a whole number from 0 to {MAX_SEED}, not "
                            f"{_shown(seed)}")
    if isinstance(request.population, bool) or request.population not in POPULATIONS:
        raise IdentityError(f"population model {_shown(request.population)} is not one this program draws from "
                            f"({', '.join(map(str, POPULATIONS))})")
    if request.sex is not None and request.sex not in SEXES:
        raise IdentityError(f"sex must be female or male, not {_shown(request.sex)}")
    fixed = dict(Identity(request.fixed).values)            # names and ranges checked, in the parameters' order
    fixed.update({name: float(v) for name, v in request.fixed.items() if name not in fixed})   # defaults given
    order = {p.name: k for k, p in enumerate(identity_parameters())}
    fixed = dict(sorted(fixed.items(), key=lambda kv: order[kv[0]]))
    if request.sex is not None and "sex" in fixed and (fixed["sex"] < 0.5) != (request.sex == "female"):
        raise IdentityError(f"sex={fixed['sex']:g} contradicts the sex asked for, {request.sex} (a woman is "
                            "below 0.5, a man 0.5 and above)")
    ages = request.ages
    if ages is not None:
        low, high = (float(a) for a in ages)
        age = identity_parameter("age")
        if not (math.isfinite(low) and math.isfinite(high) and age.minimum <= low <= high <= age.maximum):
            raise IdentityError(f"an age range must be LOW-HIGH years within {age.minimum:g} … {age.maximum:g}, "
                                f"the lower first, not {low:g}-{high:g}")
        if "age" in fixed and not low <= fixed["age"] <= high:
            raise IdentityError(f"age={fixed['age']:g} is outside the age range asked for, {low:g}-{high:g}")
        ages = (low, high)
    return DrawRequest(int(seed), request.sex, ages, fixed, int(request.population))


def shape_signature(identity: Identity) -> np.ndarray:
    """The front of ``identity``'s face as points (mm), centred and scaled to the default face's size.

    The recogniser looks at a face aligned and scaled to a standard size; so does this signature.
    """
    from engine.identity.targets import shipped_targets
    from engine.identity.weights import identity_displacement

    targets = shipped_targets()
    front = _front(targets.rest)
    rest = targets.rest[front] - targets.rest[front].mean(axis=0)
    face = targets.rest[front] + identity_displacement(identity, targets)[front]
    face -= face.mean(axis=0)
    return face * float(np.linalg.norm(rest) / np.linalg.norm(face)) - rest


def shape_distance(a: Identity, b: Identity) -> float:
    """How far apart two faces are in shape: the RMS distance (mm) of their scaled front points."""
    return _distance(shape_signature(a), shape_signature(b))


def _distance(a: np.ndarray, b: np.ndarray) -> float:
    return round(float(np.sqrt(np.mean(np.sum((a - b) ** 2, axis=1)))), 3)     # rounded: the same on any machine


def _front(rest: np.ndarray) -> np.ndarray:
    """The targets' vertices of the front of the face: the 40 % furthest forward."""
    return rest[:, 2] > np.percentile(rest[:, 2], 60)


def _identity(request: DrawRequest) -> Identity:
    identity = Identity(_draw(request))
    identity.drawn = {"population": str(request.population), "seed": str(request.seed), "given": request.given()}
    return identity


def _shown(value: object) -> str:
    text = repr(value)
    return text if len(text) <= 30 else f"{text[:25]}… ({len(text)} characters)"


# --------------------------------------------------------------------------- the draw

class _Stream:
    """Uniform and normal numbers from :meth:`random.Random.random` only (a sequence Python keeps)."""

    def __init__(self, seed: int, name: str) -> None:
        # "population-1" for every model: models 1 and 2 differ in their spreads, not their random numbers
        digest = hashlib.sha256(f"artificial-person-population-1/{seed}/{name}".encode()).digest()
        self._random = random.Random(int.from_bytes(digest[:8], "big"))

    def uniform(self, low: float = 0.0, high: float = 1.0) -> float:
        return low + (high - low) * self._random.random()

    def normal(self) -> float:
        """A standard normal number (Box–Muller)."""
        u = 1.0 - self._random.random()                   # (0, 1]
        return math.sqrt(-2.0 * math.log(u)) * math.cos(2.0 * math.pi * self._random.random())


def _draw(request: DrawRequest) -> dict[str, float]:
    seed, fixed = request.seed, request.fixed
    values: dict[str, float] = {}
    body = _Stream(seed, "macro")
    coin = body.uniform()                            # drawn always, so asking for a sex changes nothing else
    woman = coin < 0.5 if request.sex is None else request.sex == "female"
    spread = min(0.3, abs(0.1 * body.normal()))
    values["sex"] = spread if woman else 1.0 - spread
    low, high = request.ages or ADULT_AGES
    values["age"] = round(body.uniform(low, high), 1)
    values.update(_ancestry(_Stream(seed, "ancestry"), fixed))
    values["muscle"] = _clip(0.5 + 0.12 * body.normal(), 0.2, 0.8)
    values["weight"] = _clip(0.5 + 0.15 * body.normal(), 0.15, 0.85)
    values = {k: round(v, 4) if k != "age" else v for k, v in values.items()}
    values.update({k: v for k, v in fixed.items() if k in {p.name for p in MACRO}})
    face = _face(_Stream(seed, "face"), values, fixed, request.population)
    values.update(face)
    values.update(fixed)
    return values


def _ancestry(stream: _Stream, fixed: Mapping[str, float]) -> dict[str, float]:
    """A point on the simplex: one ancestry mostly, sometimes a mix (see the module's text)."""
    first = min(2, int(stream.uniform() * 3))
    mixed = stream.uniform() >= 0.6
    m = stream.uniform(0.0, 0.5) if mixed else 0.0
    split = stream.uniform()
    others = [r for k, r in enumerate(RACES) if k != first]
    shares = {RACES[first]: 1.0 - m, others[0]: m * split, others[1]: m * (1.0 - split)}
    given = {r: fixed[r] for r in RACES if r in fixed}
    if given:                 # the shares not given keep their proportions, filling what the given ones leave
        rest = [r for r in RACES if r not in given]
        left = max(0.0, 1.0 - sum(given.values()))
        total = sum(shares[r] for r in rest)
        for r in rest:
            shares[r] = left * (shares[r] / total if total > 0 else 1.0 / len(rest))
        shares.update(given)
    return shares


def _clip(value: float, low: float, high: float) -> float:
    return min(high, max(low, value))


@dataclass(frozen=True)
class FaceModel:
    """The face modifiers' joint distribution: their names, spreads ``sigma`` and correlation ``correlation``."""

    names: tuple[str, ...]
    sigma: np.ndarray
    correlation: np.ndarray
    one_sided: np.ndarray          # True for single-target modifiers (0 … 1): drawn as |N(0, σ)|


def _not_drawn() -> set[str]:
    return {m.name for m in face_modifiers() if m.name.startswith(NOT_DRAWN_PREFIXES)}


@cache
def face_model(population: int = POPULATION) -> FaceModel:
    """The joint distribution of the drawn face modifiers of population model ``population``, from the shipped
    targets."""
    from engine.identity.targets import shipped_targets

    spread_mm, coherence = SPREADS[population][0], COHERENCE

    targets = shipped_targets()
    n = len(targets.hm08_vertex)
    names, sigma, fields, one_sided = [], [], [], []
    for m in face_modifiers():
        if m.name in _not_drawn():
            continue
        full = np.zeros((n, 3))
        for negative, positive in m.sides.values():
            for key, sign in ((negative, -1.0), (positive, 1.0)):
                if key:
                    index, delta, _ = targets.targets[f"{m.group}/{key}"]
                    full[index] += sign * delta
        size = max(float(np.linalg.norm(targets.targets[f"{m.group}/{k}"][1], axis=1).max())
                   for pair in m.sides.values() for k in pair if k)
        names.append(m.name)
        factor = LIPS if m.name.startswith(LIP_WORDS) else DETAIL if any(w in m.name for w in DETAIL_WORDS) else 1.0
        sigma.append(min(MAX_SIGMA, spread_mm / size) * factor)
        fields.append(full.ravel() / max(float(np.linalg.norm(full)), 1e-12))
        one_sided.append(m.minimum >= 0.0)
    F = np.array(fields)
    cosine = np.round(F @ F.T, 2)                          # rounded: the same on every machine
    np.fill_diagonal(cosine, 1.0)
    correlation = coherence * cosine + (1.0 - coherence) * np.eye(len(names))
    return FaceModel(tuple(names), np.array(sigma), correlation, np.array(one_sided))


def _face(stream: _Stream, macro: Mapping[str, float], fixed: Mapping[str, float],
          population: int = POPULATION) -> dict[str, float]:
    """The face modifiers: jointly Gaussian, conditioned on the fixed ones, cut and bounded."""
    model = face_model(population)
    k = len(model.names)
    z = np.array([stream.normal() for _ in range(k)])
    cov = model.correlation * np.outer(model.sigma, model.sigma)
    given = np.array([n in fixed for n in model.names])
    L = np.linalg.cholesky(model.correlation)
    x = model.sigma * (L @ z)
    if given.any():
        # conditional Gaussian: x_free | x_given = a  ~  μ + the free part of the unconditioned draw's residual
        a = np.array([fixed[n] for n in np.array(model.names)[given]])
        S_gg, S_fg = cov[np.ix_(given, given)], cov[np.ix_(~given, given)]
        x_free = x[~given] + S_fg @ np.linalg.solve(S_gg, a - x[given])
        x = np.zeros(k)
        x[~given], x[given] = x_free, a
    x = np.clip(x, -CUT * model.sigma, CUT * model.sigma)
    x = np.where(model.one_sided & ~given, np.abs(x), x)
    values = {n: float(v) for n, v, g in zip(model.names, x, given, strict=True) if not g}
    for name, value in values.items():
        p = identity_parameter(name)
        values[name] = _clip(value, p.minimum, p.maximum)
    bound = SPREADS[population][1]
    return {name: round(value, 4) for name, value in _bounded(values, macro, fixed, bound).items()}


def _bounded(values: dict[str, float], macro: Mapping[str, float], fixed: Mapping[str, float],
             bound: float = MAX_FACE_MM) -> dict[str, float]:
    """``values`` scaled down so that with the fixed ones they move no vertex more than ``bound`` mm."""
    from engine.identity.weights import identity_displacement

    base = Identity(dict(macro))
    macro_only = identity_displacement(base)
    fixed_face = {k: v for k, v in fixed.items() if k not in macro}
    moved = identity_displacement(base.with_values({**fixed_face, **values})) - macro_only
    furthest = float(np.linalg.norm(moved, axis=1).max())
    if furthest <= bound:
        return values
    scale = bound / furthest
    return {k: v * scale for k, v in values.items()}
