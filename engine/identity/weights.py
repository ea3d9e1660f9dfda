"""How an identity's values weight the shape targets, by MakeHuman's own rules.

:func:`target_weights` turns an :class:`~engine.identity.parameters.Identity`
into a weight per target: the macro targets ``{race}-{gender}-{age}`` are
weighted by the product of the ancestry share, the sex weight and the age
weight; ``universal-{gender}-{age}-{muscle}-{weight}`` by the product of the
sex, age, muscle and weight weights; a face modifier by its value on its
negative or positive target.

>>> from engine.identity.parameters import Identity
>>> w = target_weights(Identity({"sex": 1.0, "age": 25, "caucasian": 1, "african": 0, "asian": 0}))
>>> round(w["macrodetails/caucasian-male-young"], 6), "macrodetails/african-male-young" in w
(1.0, False)
"""

from __future__ import annotations

import numpy as np

from engine.identity.parameters import SIDES, Identity, age_value, face_modifiers
from engine.identity.targets import IdentityTargets, shipped_targets


def _age_weights(value: float) -> dict[str, float]:
    """MakeHuman's baby/child/young/old weights for an age value 0 … 1."""
    if value < 0.5:
        young = max(0.0, (value - 0.1875) / (0.5 - 0.1875))
        baby = max(0.0, 1.0 - value / 0.1875)
        return {"baby": baby, "child": max(0.0, min(1.0, value / 0.1875) - young), "young": young, "old": 0.0}
    old = max(0.0, value * 2.0 - 1.0)
    return {"baby": 0.0, "child": 0.0, "young": 1.0 - old, "old": old}


def _level_weights(value: float, what: str) -> dict[str, float]:
    """min/average/max weights of a 0 … 1 value (average at 0.5)."""
    if value < 0.5:
        return {f"min{what}": 1.0 - 2.0 * value, f"average{what}": 2.0 * value, f"max{what}": 0.0}
    return {f"min{what}": 0.0, f"average{what}": 2.0 - 2.0 * value, f"max{what}": 2.0 * value - 1.0}


def target_weights(identity: Identity) -> dict[str, float]:
    """The weight of every target the identity uses (targets of weight 0 left out)."""
    weights: dict[str, float] = {}

    def add(key: str, w: float) -> None:
        if w != 0.0:
            weights[key] = weights.get(key, 0.0) + w

    sex = identity.value("sex")
    gender = {"female": 1.0 - sex, "male": sex}
    age = _age_weights(age_value(identity.value("age")))
    muscle = _level_weights(identity.value("muscle"), "muscle")
    weight = _level_weights(identity.value("weight"), "weight")
    for race, share in identity.ancestry().items():
        for g, wg in gender.items():
            for a, wa in age.items():
                add(f"macrodetails/{race}-{g}-{a}", share * wg * wa)
    for g, wg in gender.items():
        for a, wa in age.items():
            for m, wm in muscle.items():
                for k, ww in weight.items():
                    add(f"macrodetails/universal-{g}-{a}-{m}-{k}", wg * wa * wm * ww)
    for modifier in face_modifiers():
        both = identity.value(modifier.name)
        for side, (negative, positive) in modifier.sides.items():
            value = both + (identity.value(f"{modifier.name}.{side}") if side in SIDES else 0.0)
            value = max(modifier.minimum, min(1.0, value))
            if value > 0 and positive:
                add(f"{modifier.group}/{positive}", value)
            elif value < 0 and negative:
                add(f"{modifier.group}/{negative}", -value)
    return weights


def identity_displacement(identity: Identity, targets: IdentityTargets | None = None) -> np.ndarray:
    """The identity's shape minus the default head's, (n, 3) mm on the targets file's vertices."""
    targets = targets or shipped_targets()
    D = targets.displacement(target_weights(identity)) - targets.displacement(target_weights(Identity()))
    return D
