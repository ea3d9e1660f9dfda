"""The colour of a person's irises: from the identity's ancestry shares, drawn per person (issue 32 item 1).

The default head paints each eyeball with three vertex colours (sclera, iris,
pupil; engine/data/default-head/head_colors.py). :func:`apply_iris` repaints
the iris — the middle of the three by brightness, as
:func:`engine.photofit.eyes.recolour_irises` does with a photograph's — with
:func:`iris_colour_for`'s colour. The colour is one of :data:`IRIS_COLOURS`,
chosen with the chances of :data:`IRIS_CHANCES` blended by the ancestry
shares (brown eyes nearly always for wholly African and Asian people; blue,
grey, green, hazel and brown for Europeans, in about the proportions reported
for northern and central Europe), and varied a little in shade, from a seed
derived from the identity's values: the same person always has the same eyes,
two people usually not. The default head (no identity values) keeps its own
blue-grey iris.

>>> from engine.identity import Identity
>>> iris_colour_for(Identity({"african": 1.0, "caucasian": 0.0, "asian": 0.0, "age": 30})) is not None
True
>>> iris_colour_for(Identity()) is None
True
"""

from __future__ import annotations

import hashlib

import numpy as np

from engine.identity.parameters import RACES, Identity
from engine.model import Model

EYEBALLS = ("eye_left", "eye_right")
#: sRGB of each iris colour (the shade varies a little around it per person).
IRIS_COLOURS = {
    "dark-brown": (58, 36, 22),
    "brown": (96, 62, 34),
    "hazel": (118, 92, 52),
    "green": (92, 112, 74),
    "grey": (112, 122, 128),
    "blue": (78, 110, 150),
}
#: Chances of each colour (in IRIS_COLOURS' order) for a wholly African, Asian and Caucasian person.
IRIS_CHANCES = {
    "african": (0.90, 0.09, 0.01, 0.00, 0.00, 0.00),
    "asian": (0.80, 0.18, 0.02, 0.00, 0.00, 0.00),
    "caucasian": (0.06, 0.22, 0.14, 0.10, 0.13, 0.35),
}
SHADE = 0.12             # the per-person shade: each channel × (1 ± up to this)


def iris_name_and_colour(identity: Identity) -> tuple[str, np.ndarray] | None:
    """The iris colour's name and sRGB (3,) uint8 of ``identity``; None for the default head (no values)."""
    if not identity.values:
        return None
    digest = hashlib.sha256(("iris/" + repr(sorted(identity.values.items()))).encode()).digest()
    rng = np.random.default_rng(int.from_bytes(digest[:8], "little"))
    shares = np.array([identity.value(r) for r in RACES], float)
    shares = shares / shares.sum() if shares.sum() > 0 else np.full(len(RACES), 1 / len(RACES))
    chance = shares @ np.array([IRIS_CHANCES[r] for r in RACES])
    names = list(IRIS_COLOURS)
    name = names[int(rng.choice(len(names), p=chance / chance.sum()))]
    shade = 1.0 + SHADE * (2.0 * rng.random() - 1.0)
    tint = 1.0 + 0.04 * (2.0 * rng.random(3) - 1.0)
    rgb = np.clip(np.rint(np.array(IRIS_COLOURS[name], float) * shade * tint), 0, 255).astype(np.uint8)
    return name, rgb


def iris_colour_for(identity: Identity) -> np.ndarray | None:
    """sRGB (3,) uint8 of ``identity``'s irises (see the module's text); None for the default head."""
    chosen = iris_name_and_colour(identity)
    return None if chosen is None else chosen[1]


def apply_iris(model: Model, identity: Identity) -> None:
    """Repaint ``model``'s irises (the middle of each eyeball's three colours) for ``identity``, in place.

    A model without vertex colours or eyeballs painted in three colours is left as it is.
    """
    colour = iris_colour_for(identity)
    if colour is None or model.vertex_colors is None:
        return
    painted = model.vertex_colors.copy()          # not in place: the array may be the default head's own
    for part in EYEBALLS:
        if part not in model.parts:
            continue
        inside = np.flatnonzero(model.vertex_part == model.parts.index(part))
        colours, which = np.unique(painted[inside], axis=0, return_inverse=True)
        if len(colours) != 3:
            continue
        middle = int(np.argsort(colours.astype(float).sum(axis=1))[1])
        painted[inside[which.reshape(-1) == middle]] = colour
    model.vertex_colors = painted
    model.changed()


def iris_colour_of(model: Model, part: str = "eye_left") -> np.ndarray | None:
    """The iris colour (sRGB) painted on ``model``'s eyeball ``part``, or None if it has no three-colour eye."""
    if model.vertex_colors is None or part not in model.parts:
        return None
    inside = np.flatnonzero(model.vertex_part == model.parts.index(part))
    colours = np.unique(model.vertex_colors[inside], axis=0)
    if len(colours) != 3:
        return None
    return colours[int(np.argsort(colours.astype(float).sum(axis=1))[1])]
