"""The hair of a person drawn from the population model (engine.identity.population): scalp style,
beard and brows from the person's seed, by sex and age; the colour from age and ancestry (docs/hair.md
has the chances)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from engine.identity.hair_style import HairChoice
from engine.identity.parameters import Identity
from engine.identity.population import _Stream

__all__ = ["BEARD_CHANCES", "BROWS_CHANCES", "SCALP_CHANCES", "bald_share", "drawn_hair"]


#: Scalp styles (hair_style.STYLES' names) and their chances for a woman and a man; a man's chance of a bald
#: scalp grows with age (BALD_BY_AGE), taken from his other styles' chances in proportion.
SCALP_CHANCES = {"female": {"long": 0.5, "tied": 0.33, "short": 0.17},
                 "male": {"short": 0.8, "long": 0.08, "tied": 0.04, "none": 0.08}}
#: Facial hair of a man (a woman has none) and the brows' thickness of each sex.
BEARD_CHANCES = {"none": 0.5, "stubble": 0.22, "moustache": 0.1, "beard": 0.18}
BROWS_CHANCES = {"female": {"thin": 0.45, "medium": 0.5, "thick": 0.05},
                 "male": {"thin": 0.05, "medium": 0.55, "thick": 0.4}}


def bald_share(age: float) -> float:
    """How likely a man of ``age`` years is bald on top (the ``none`` scalp): 8 % young, about 40 % by 70."""
    return float(np.clip(0.08 + (age - 30.0) * 0.008, 0.08, 0.45))


def drawn_hair(identity: Identity) -> HairChoice | None:
    """The hair of a person drawn from the population model: scalp style, beard and brows from the seed, by sex and
    age; the colour from age and ancestry (:func:`~engine.identity.hair_style.colour_for`). None for an identity
    not drawn.

    >>> from engine.identity.population import draw_identity
    >>> drawn_hair(draw_identity(7)) == drawn_hair(draw_identity(7))
    True
    """
    if identity.drawn is None:
        return None
    stream = _Stream(int(identity.drawn["seed"]), "hair")
    man = identity.value("sex") >= 0.5
    age = identity.value("age")
    scalp = dict(SCALP_CHANCES["male" if man else "female"])
    if man:
        bald = bald_share(age)
        rest = 1.0 - scalp.pop("none")
        scalp = {k: v * (1.0 - bald) / rest for k, v in scalp.items()} | {"none": bald}
    style, beard, brows = (_pick(stream, table) for table in
                           (scalp, BEARD_CHANCES, BROWS_CHANCES["male" if man else "female"]))
    from engine.identity.hair_style import colour_for

    return HairChoice(style=style, beard=beard if man else "none", brows=brows, colour=colour_for(identity))


def _pick(stream: _Stream, chances: Mapping[str, float]) -> str:
    """One of ``chances``' names, with its chance (one uniform number drawn, always)."""
    u, total = stream.uniform(), 0.0
    for name, chance in chances.items():
        total += chance
        if u < total:
            return name
    return next(reversed(list(chances)))
