"""Phones → articulatory parameter tracks, with or without coarticulation.

``cohen-massaro`` (default): every phone ``s`` exerts, on every parameter
``p``, a dominance that peaks at the phone's middle ``c_s`` and falls off
exponentially before it (anticipation) and after it (carry-over)::

    D_sp(t) = α_sp · exp(−θ_sp |t − c_s|^c),   θ = θ−_sp before c_s, θ+_sp after
    F_p(t)  = Σ_s D_sp(t) T_sp / Σ_s D_sp(t)

(Cohen & Massaro 1993). Targets marked as enforced in the table (bilabial
and labiodental closure) are then imposed around their phone's middle: the
track is blended into the target by a window that is 1 over the middle half
of the phone and falls to 0 at its edges, so the lips close at every p, b, m
however fast the speech.

``none``: the paper's plain target interpolation (§2.1) — each phone's
targets at its middle, straight lines between.

The result is one low-level activation per parameter, sampled every
``step_ms`` (and at every phone middle), ready for the timeline, where it
adds to whatever inline commands do.

>>> from engine.speech.synthesis import Segment
>>> from engine.speech.articulation import load_articulation
>>> phones = [Segment("#", 0, 100), Segment("p", 100, 180), Segment("a", 180, 300), Segment("#", 300, 400)]
>>> jaw = articulate(phones, load_articulation())[0]
>>> jaw.parameter, float(jaw.values[jaw.times.tolist().index(140.0)])   # closed at the middle of p
('jaw_open', 0.0)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import ArrayLike

from engine.commands.command_files import Activation
from engine.errors import UserError

if TYPE_CHECKING:
    from engine.speech.synthesis import Segment

METHODS = ("cohen-massaro", "none")
STEP_MS = 5.0


class TargetTable(Protocol):
    """What coarticulation reads from an articulation table: an
    :class:`~engine.speech.articulation.ArticulationTable`, or a view of one restricted to some parameters."""

    @property
    def parameters(self) -> Sequence[str]: ...

    @property
    def exponent(self) -> float: ...

    def arrays(self, phones: list[str], /) -> tuple[np.ndarray, ...]:
        """``(value, dominance, anticipation, carryover, enforced)``, each phones × parameters."""
        ...


def articulate(phones: Sequence[Segment], table: TargetTable, method: str = "cohen-massaro",
               step_ms: float = STEP_MS) -> list[Activation]:
    """One activation (linear keys) per table parameter for a list of phone segments."""
    times = key_times(phones, step_ms)
    tracks = articulation_tracks(phones, table, times, method)
    return [Activation(name, times, tracks[:, j], "linear", command="speech", line=method)
            for j, name in enumerate(table.parameters)]


def key_times(phones: Sequence[Segment], step_ms: float = STEP_MS) -> np.ndarray:
    """A regular grid over the utterance plus every phone's middle and the end."""
    if not phones:
        return np.zeros(0)
    start, end = phones[0].start_ms, phones[-1].end_ms
    grid = np.arange(start, end, step_ms)
    middles = [(p.start_ms + p.end_ms) / 2 for p in phones]
    return np.unique(np.concatenate([grid, middles, [end]]))


def articulation_tracks(phones: Sequence[Segment], table: TargetTable, times: ArrayLike,
                        method: str = "cohen-massaro") -> np.ndarray:
    """Parameter values (len(times) × table parameters) at the given times."""
    if method not in METHODS:
        raise UserError(f"unknown coarticulation '{method}' (known: {', '.join(METHODS)})")
    times = np.asarray(times, dtype=float)
    if not phones:
        return np.zeros((times.size, len(table.parameters)))
    labels = [p.label for p in phones]
    starts = np.array([p.start_ms for p in phones], dtype=float)
    ends = np.array([p.end_ms for p in phones], dtype=float)
    middles = (starts + ends) / 2
    value, dominance, anticipation, carryover, enforced = table.arrays(labels)
    if method == "none":
        tracks = np.column_stack([np.interp(times, middles, value[:, j]) for j in range(value.shape[1])])
    else:
        tracks = _dominance_blend(times, middles, value, dominance, anticipation, carryover, table.exponent)
    _enforce(tracks, times, starts, ends, value, enforced)
    return tracks


def _dominance_blend(times: np.ndarray, middles: np.ndarray, value: np.ndarray, dominance: np.ndarray,
                     anticipation: np.ndarray, carryover: np.ndarray, exponent: float) -> np.ndarray:
    """Σ D·T / Σ D at every time, block by block over the phones within :func:`_reach_ms` of the block.

    Phones farther away weigh less than 1e-18 of the nearest phone's dominance, so leaving them out
    changes no result beyond rounding, and the cost grows with the length of the speech, not its square.
    """
    order = np.argsort(times, kind="stable")
    sorted_times = times[order]
    reach = _reach_ms(sorted_times, middles, dominance, anticipation, carryover, exponent)
    tracks = np.empty((times.size, value.shape[1]))
    for first in range(0, sorted_times.size, _BLOCK):
        block = sorted_times[first:first + _BLOCK]
        lo = int(np.searchsorted(middles, block[0] - reach, "left"))
        hi = int(np.searchsorted(middles, block[-1] + reach, "right"))
        lo = min(lo, max(int(np.searchsorted(middles, block[0])) - 1, 0))     # the nearest phone always counts
        hi = max(hi, min(int(np.searchsorted(middles, block[-1])) + 1, middles.size))
        phones = slice(lo, hi)
        tracks[order[first:first + _BLOCK]] = _blend(block, middles[phones], value[phones], dominance[phones],
                                                     anticipation[phones], carryover[phones], exponent)
    return tracks


_BLOCK = 1024
_NEGLIGIBLE = 1e-18


def _reach_ms(times: np.ndarray, middles: np.ndarray, dominance: np.ndarray, anticipation: np.ndarray,
              carryover: np.ndarray, exponent: float) -> float:
    """How far from a time a phone's middle may be and still matter (relative weight ≥ 1e-18).

    The nearest phone is at most ``near`` away and weighs at least α_min·exp(−θ_max·near^c); each of the
    N phones farther than ``reach`` weighs at most α_max·exp(−θ_min·reach^c): their sum stays below
    1e-18 of the nearest one's weight.
    """
    index = np.clip(np.searchsorted(middles, times), 1, middles.size - 1) if middles.size > 1 else None
    if index is None:
        return float("inf")
    near = float(np.max(np.minimum(np.abs(times - middles[index - 1]), np.abs(times - middles[index]))))
    rates = np.concatenate([anticipation.ravel(), carryover.ravel()])
    slowest, fastest = float(rates.min()), float(rates.max())
    spread = math.log(float(dominance.max()) / float(dominance.min()))
    needed = (spread + fastest * near ** exponent + math.log(middles.size / _NEGLIGIBLE)) / slowest
    return float(needed ** (1.0 / exponent)) + near


def _blend(times: np.ndarray, middles: np.ndarray, value: np.ndarray, dominance: np.ndarray,
           anticipation: np.ndarray, carryover: np.ndarray, exponent: float) -> np.ndarray:
    tau = times[:, None] - middles[None, :]                       # T × N
    distance = np.abs(tau) ** exponent
    before = tau < 0
    tracks = np.empty((times.size, value.shape[1]))
    nearest_phone = np.argmin(np.abs(tau), axis=1)
    for j in range(value.shape[1]):
        rate = np.where(before, anticipation[None, :, j], carryover[None, :, j])
        weight = dominance[None, :, j] * np.exp(-rate * distance)
        total = weight.sum(axis=1)
        blended = (weight * value[None, :, j]).sum(axis=1)
        # Far from every phone all dominances underflow: fall back to the nearest phone's target.
        nearest = value[nearest_phone, j]
        tracks[:, j] = np.divide(blended, total, out=nearest.copy(), where=total > 1e-300)
    return tracks


def closure_window(times: np.ndarray, start: float, end: float) -> np.ndarray:
    """1 over the middle half of [start, end], a half cosine down to 0 at the edges, 0 outside."""
    middle, half = (start + end) / 2, (end - start) / 2
    if half <= 0:
        return (times == middle).astype(float)
    d = np.abs(times - middle) / half                             # 0 at the middle, 1 at the edges
    w = np.where(d <= 0.5, 1.0, 0.5 * (1 + np.cos(np.pi * (d - 0.5) / 0.5)))
    return np.where(d <= 1.0, w, 0.0)


def _enforce(tracks: np.ndarray, times: np.ndarray, starts: np.ndarray, ends: np.ndarray, value: np.ndarray,
             enforced: np.ndarray) -> None:
    """Blend enforced targets in around their phones' middles; only the times inside each phone change."""
    order = np.argsort(times, kind="stable")
    sorted_times = times[order]
    for s, j in zip(*np.nonzero(enforced), strict=True):
        inside = order[np.searchsorted(sorted_times, starts[s], "left"):np.searchsorted(sorted_times, ends[s], "right")]
        w = closure_window(times[inside], starts[s], ends[s])
        tracks[inside, j] = tracks[inside, j] * (1 - w) + value[s, j] * w
