"""The photograph's expression: the action units and the jaw that, on the fitted head, give its landmarks.

A portrait smiles, or talks: its mouth corners are up and back, its lips
apart, its cheeks and lower lids raised. Fitted as identity, that shape
becomes the person's neutral face (a wide mouth, teeth painted on closed
lips). Here the rig's own parameters (:data:`EXPRESSIONS`: the jaw, the lip
corner puller AU12, the cheek raiser AU6, the upper lip raiser, the brows
…) are fitted with the identity (:mod:`engine.photofit.identity_fit`), so
the head is the person at rest and the photograph is that head *posed*; the
texture is then read through the posed head
(:func:`engine.photofit.fit.fit_photos`), so the smile's skin lands where it
belongs on the neutral face.

The landmarks move nearly linearly with these parameters (leaf deformations
superpose; the jaw turns by a few degrees), so each one's effect is sampled
on the default head with :meth:`Model.deform` (well under a millisecond a
pose) and made again about the estimate. Each value has a prior pulling it
to rest (:data:`EXPRESSION_SPREAD`): an expression is used only where the
landmarks ask for it.

>>> from engine.formats.model_files import load_model
>>> head = load_model()
>>> basis = ExpressionBasis(head, head.landmarks["8.3"] * np.ones(1, dtype=int))
>>> moved = basis.positions(np.array([0.5 if n == "AU12_left" else 0.0 for n in basis.names]))
>>> bool(moved[0, 1] > head.vertices[head.landmarks["8.3"], 1] + 2)      # the left mouth corner goes up
True
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from engine.model import Model

#: The rig parameters fitted as the photograph's expression (those a model lacks are left out).
EXPRESSIONS = ("jaw_open", "AU12_left", "AU12_right", "upper_lip_raise", "mouth_widen", "AU20_left", "AU20_right",
               "AU15_left", "AU15_right")
"""The mouth's: what a portrait's smile or speech moves. The lids are not among them: how open a person's eyes are
at rest is theirs (fitted as identity and warp); a portrait's narrowed eyes fitted as a lid tightener (AU7)
opened to a stare at rest, which reads as surprise. Nor are the brows (their height is the person's,
``eyebrows-trans-down-up``) or the cheek raiser AU6, which only the jaw line's points see: on a neutral
synthetic face those took up the landmarks' noise.)"""
#: Ranges narrower than the rig's: an expression fitted to a portrait is one a portrait shows.
EXPRESSION_RANGES = {"jaw_open": (0.0, 0.8), "mouth_widen": (-0.3, 1.0)}
"""Name → (low, high); every other parameter is fitted within 0 … 1 (and its rig range)."""
#: The prior: one unit of cost at this value (0 is rest).
EXPRESSION_SPREAD = 0.3
STEP = 0.1                               # the finite difference each parameter's effect is sampled with


class ExpressionBasis:
    """The landmarks (vertex ``index``) of ``model`` posed by the expression parameters, linear about a centre."""

    def __init__(self, model: Model, index: np.ndarray):
        names = {p.name for p in model.parameters}
        self.names = [n for n in EXPRESSIONS if n in names]
        self.model, self.index = model, np.asarray(index)
        ranges = {p.name: (p.minimum, p.maximum) for p in model.parameters}
        wanted = {n: EXPRESSION_RANGES.get(n, (0.0, 1.0)) for n in self.names}
        self.low = np.array([max(wanted[n][0], ranges[n][0]) for n in self.names])
        self.high = np.array([min(wanted[n][1], ranges[n][1]) for n in self.names])
        self.rest = model.deform({})[self.index]
        self.linearise(np.zeros(len(self.names)))

    def linearise(self, values: np.ndarray) -> None:
        """Sample each parameter's effect about ``values`` (E,)."""
        self.centre = np.clip(np.asarray(values, dtype=float), self.low, self.high)
        pose = dict(zip(self.names, self.centre.tolist(), strict=True))
        self.at_centre = self.model.deform(pose)[self.index]
        columns = []
        for name, value, high in zip(self.names, self.centre, self.high, strict=True):
            step = STEP if value + STEP <= high else -STEP
            moved = self.model.deform({**pose, name: value + step})[self.index]
            columns.append((moved - self.at_centre) / step)
        self.basis = np.array(columns) if columns else np.zeros((0, len(self.index), 3))

    def offsets(self, values: np.ndarray) -> np.ndarray:
        """(L, 3) how far the expression ``values`` moves each landmark from rest, mm."""
        return self.at_centre - self.rest + np.einsum("e,eld->ld", np.asarray(values) - self.centre, self.basis)

    def positions(self, values: np.ndarray) -> np.ndarray:
        return self.rest + self.offsets(values)

    def prior(self, values: np.ndarray) -> np.ndarray:
        return np.asarray(values) / EXPRESSION_SPREAD

    def as_dict(self, values: np.ndarray, floor: float = 1e-3) -> dict[str, float]:
        """The fitted values worth keeping (at least ``floor`` away from rest)."""
        return {n: round(float(v), 4) for n, v in zip(self.names, values, strict=True) if abs(v) >= floor}


def posed(model: Model, expression: Mapping[str, float]) -> np.ndarray:
    """(N, 3) ``model``'s vertices in the photograph's expression (its rest vertices without one)."""
    known = {p.name for p in model.parameters}
    return model.deform({k: v for k, v in expression.items() if k in known}) if expression else model.vertices
