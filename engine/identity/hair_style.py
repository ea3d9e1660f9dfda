"""The hair a person has: scalp style, facial hair, brows and their colour (named in the model file).

A :class:`HairChoice` names a scalp ``style`` (``none`` is bald), a ``beard``,
the ``brows``' thickness and the hair ``colour``; the brows and the beard take
the hair's colour. Every style is made here, procedurally (no outside assets).
A colour not given is chosen from the person (:func:`colour_for`): grey/white
the more likely the older, black and dark brown the more likely the larger the
African and Asian shares, from a seed derived from the identity's values, so
the same person always gets the same colour.

>>> from engine.identity import Identity
>>> round(grey_share(25), 2), round(grey_share(55), 2), round(grey_share(80), 2)
(0.0, 0.51, 0.92)
>>> colour_for(Identity({"sex": 1, "age": 60})) == colour_for(Identity({"sex": 1, "age": 60}))
True
"""

from __future__ import annotations

import hashlib
from typing import Any

import numpy as np

from engine.formats.hair_element import BEARDS, BROWS, COLOURS, PIGMENTS, SEED, STYLES, HairChoice
from engine.model.identity_record import IdentityRecord

__all__ = ["BEARDS", "BROWS", "COLOURS", "HAIR_KEYS", "PIGMENTS", "SEED", "STYLES", "HairChoice", "colour_for",
           "grey_share", "hair_from_level", "hair_of", "without_hair_keys"]


def grey_share(age: float) -> float:
    """How likely a person of ``age`` years has grey or white hair (about half by 55, most by 70)."""
    return float(np.clip((age - 32.0) / 45.0, 0.0, 0.92))


def colour_for(identity: IdentityRecord | None) -> str:
    """The hair colour of a person whose colour was not chosen: drawn from age and ancestry, seeded by the values.

    >>> from engine.identity import Identity
    >>> colour_for(Identity({"age": 30, "african": 1.0})) in COLOURS
    True
    """
    values = dict(identity.values) if identity is not None else {}
    digest = hashlib.sha256(repr(sorted(values.items())).encode()).digest()
    rng = np.random.default_rng(int.from_bytes(digest[:8], "little"))
    age = float(values.get("age", 25.0))
    if rng.random() < grey_share(age):
        return "white" if age > 70 and rng.random() < 0.5 else "grey"
    shares = np.array([values.get(r, 1 / 3) for r in ("african", "asian", "caucasian")], float)
    shares = shares / shares.sum() if shares.sum() > 0 else np.full(3, 1 / 3)
    # chances of black, dark brown, brown, blond, red for wholly African, Asian and Caucasian people
    table = np.array([[0.80, 0.18, 0.02, 0.00, 0.00],
                      [0.75, 0.23, 0.02, 0.00, 0.00],
                      [0.10, 0.35, 0.30, 0.19, 0.06]])
    chance = shares @ table
    return PIGMENTS[int(rng.choice(len(PIGMENTS), p=chance / chance.sum()))]


def hair_of(record: IdentityRecord | None) -> HairChoice | None:
    """The hair an identity record carries (``record.hair``), if any."""
    hair = getattr(record, "hair", None)
    return hair if isinstance(hair, HairChoice) else None


#: The keys of a stimulus design's identity table that choose hair, not the shape (docs/stimuli.md).
HAIR_KEYS = {"hair": "style", "hair_colour": "colour", "hair_color": "colour", "beard": "beard", "brows": "brows"}


def hair_from_level(level: object) -> HairChoice | None:
    """The hair an identity level of a design asks for (``{sex = 1, hair = "short", beard = "stubble"}``), if any.

    >>> hair_from_level({"sex": 1, "hair": "long", "hair_colour": "red"}).describe()
    'long red hair, no beard, medium brows'
    """
    if not isinstance(level, dict) or not any(k in level for k in HAIR_KEYS):
        return None
    asked = {HAIR_KEYS[k]: str(v) for k, v in level.items() if k in HAIR_KEYS}
    return HairChoice.parse(**asked)


def without_hair_keys(level: dict[str, Any]) -> dict[str, Any]:
    """An identity table with its hair keys taken out (what :class:`~engine.identity.Identity` is made from)."""
    return {k: v for k, v in level.items() if k not in HAIR_KEYS}
