"""Cohen–Massaro dominance parameters fitted to captured trajectories (issue 22 §2, step 2).

For one articulatory parameter at a time, the model of
:mod:`engine.speech.coarticulation` is fitted to the trajectories
:mod:`engine.mocap.captured_tracks` read from the recordings::

    D_k(t) = α_k · exp(−θ_k |t − c_k|^c),   θ = θ−_k before the phone's middle c_k, θ+_k after
    F(t)   = Σ_k D_k(t) T_k / Σ_k D_k(t),   then enforced targets blended in over their phones

For every phone row of the table that the training frames see (a long phone
``a:`` is its short row ``a`` unless it has its own) and whose cell names a
target (a ``-`` cell, "leave it to the neighbours", stays as it is), the
unknowns are the target ``T``, ``log α``, ``log θ−`` and ``log θ+`` (logs
keep them positive); the exponent ``c`` is the table's. ``least_squares``
(trust region, analytic Jacobian, bounds) minimises

    Σ_frames (F(t) − y(t))²  +  n₀ · m · Σ_unknowns g² (x − x_shipped)²

where ``y`` is the captured trajectory on the training frames, ``m`` the mean
number of frames a phone occurrence spans, ``n₀`` (:data:`PRIOR_OCCURRENCES`,
3) how many occurrences the shipped value counts as, and ``g`` the rough
change of the track per unit of the unknown (1 for a target, 0.1 for a log
dominance or log rate, :data:`PRIOR_SENSITIVITY`). A phone seen once or twice
therefore stays near the shipped row; one seen dozens of times follows the
data. Phones never seen keep the shipped row; enforced cells stay enforced
(their targets are fitted too). The forward model is checked against
:func:`~engine.speech.coarticulation.articulation_tracks` in the tests.

>>> import numpy as np
>>> from engine.speech.articulation import load_articulation
>>> table = load_articulation()
>>> times = np.arange(0.0, 400.0, 1000 / 60)
>>> utterance = TrainingTrack(times, ["#", "p", "a", "#"], np.array([0, 100, 180, 300.]),
...                           np.array([100, 180, 300, 400.]), np.zeros(len(times)), np.ones(len(times), bool))
>>> fit = fit_parameter([utterance], table, "jaw_open")       # the jaw never opens in this "recording"
>>> round(fit.table.target("a", "jaw_open"), 2) < 0.42
True
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from engine.mocap.errors import MocapError
from engine.speech.articulation import ArticulationTable, Target
from engine.speech.coarticulation import closure_window

PRIOR_OCCURRENCES = 3.0
PRIOR_SENSITIVITY = {"target": 1.0, "dominance": 0.1, "anticipation": 0.1, "carryover": 0.1}
TARGET_BOUNDS = (-3.0, 3.0)
DOMINANCE_BOUNDS = (1e-3, 1e3)
RATE_BOUNDS = (1e-4, 0.5)
"""1/ms: from a phone felt for seconds to one gone within a few ms."""
KINDS = ("target", "dominance", "anticipation", "carryover")


@dataclass
class TrainingTrack:
    """One utterance for the fit: frame times (ms), its phones, one parameter's captured values."""

    times_ms: np.ndarray
    labels: list[str]
    starts_ms: np.ndarray
    ends_ms: np.ndarray
    values: np.ndarray
    """(F,) captured values of the parameter (NaN where not captured)."""
    used: np.ndarray
    """(F,) bool: frames the fit uses (captured, in the training part)."""


@dataclass
class ParameterFit:
    """The table with one parameter's cells learned, and what was learned."""

    table: ArticulationTable
    parameter: str
    phones: list[str]
    """Rows fitted (the table's row names)."""
    occurrences: dict[str, int]
    rms_shipped: float
    """RMS misfit over the training frames with the starting table, parameter units."""
    rms_learned: float
    frames: int
    changes: dict[str, tuple[Target, Target]] = field(default_factory=dict)
    """Row → (shipped cell, learned cell)."""


def row_name(table: ArticulationTable, phone: str) -> str:
    """The name of the row ``phone`` reads (a long phone its short form's, unless it has its own)."""
    if phone in table.rows:
        return phone
    table.row(phone)                                   # raises naming the phone if it has no row
    return phone[:-1]


def fit_parameter(tracks: Sequence[TrainingTrack], table: ArticulationTable, parameter: str,
                  prior_occurrences: float = PRIOR_OCCURRENCES) -> ParameterFit:
    """Fit the cells of ``parameter`` for every seen phone row (see the module text)."""
    from scipy.optimize import least_squares

    column = table.parameters.index(parameter)
    dash = Target(0.0, table.settings["weak"], table.settings["anticipation"], table.settings["carryover"])
    names = sorted({row_name(table, label) for t in tracks for label in t.labels})
    occurrences, spans = _occurrences(tracks, table)
    free = [n for n in names if occurrences.get(n, 0) > 0 and table.rows[n][column] != dash]
    problem = _Problem(tracks, table, column, names)
    frames = int(sum(t.used.sum() for t in tracks))
    if frames == 0:
        raise MocapError(f"no captured frame to fit {parameter} to")
    start = problem.vector()
    start_rms = float(np.sqrt(np.mean(problem.residuals(start) ** 2)))
    if not free:
        return ParameterFit(table, parameter, [], occurrences, start_rms, start_rms, frames)
    index = np.array([names.index(n) for n in free])
    chosen = np.concatenate([index + k * len(names) for k in range(4)])
    per_frame = spans / max(sum(occurrences.values()), 1)
    weights = math.sqrt(prior_occurrences * per_frame) * np.repeat(
        [PRIOR_SENSITIVITY[k] for k in KINDS], len(free))
    x0 = start[chosen]
    lower, upper = _bounds(len(free))
    x_start = np.clip(x0, lower + 1e-12, upper - 1e-12)

    def residuals(x: np.ndarray) -> np.ndarray:
        full = start.copy()
        full[chosen] = x
        return np.concatenate([problem.residuals(full), weights * (x - x0)])

    def jacobian(x: np.ndarray) -> np.ndarray:
        full = start.copy()
        full[chosen] = x
        return np.vstack([problem.jacobian(full)[:, chosen], np.diag(weights)])

    solution = least_squares(residuals, x_start, jac=jacobian, bounds=(lower, upper), method="trf",
                             x_scale="jac", max_nfev=200)
    learned = start.copy()
    learned[chosen] = solution.x
    fitted_table, changes = problem.table_with(learned, free)
    return ParameterFit(fitted_table, parameter, free, occurrences,
                        start_rms, float(np.sqrt(np.mean(problem.residuals(learned) ** 2))), frames, changes)


def _bounds(n: int) -> tuple[np.ndarray, np.ndarray]:
    lows = [TARGET_BOUNDS[0], math.log(DOMINANCE_BOUNDS[0]), math.log(RATE_BOUNDS[0]), math.log(RATE_BOUNDS[0])]
    highs = [TARGET_BOUNDS[1], math.log(DOMINANCE_BOUNDS[1]), math.log(RATE_BOUNDS[1]), math.log(RATE_BOUNDS[1])]
    return np.repeat(lows, n), np.repeat(highs, n)


def _occurrences(tracks: Sequence[TrainingTrack], table: ArticulationTable) -> tuple[dict[str, int], float]:
    """Per row: how many of its phones overlap a used frame; and the used frames those phones span."""
    counts: dict[str, int] = {}
    spans = 0.0
    for t in tracks:
        used_times = t.times_ms[t.used]
        for label, start, end in zip(t.labels, t.starts_ms, t.ends_ms, strict=True):
            inside = int(np.count_nonzero((used_times >= start) & (used_times < end)))
            if inside:
                name = row_name(table, label)
                counts[name] = counts.get(name, 0) + 1
                spans += inside
    return counts, spans


class _Problem:
    """The Cohen–Massaro tracks of one parameter and their derivatives, for a vector of row unknowns.

    The vector is ``[T…, log α…, log θ−…, log θ+…]`` over :attr:`names`.
    """

    def __init__(self, tracks: Sequence[TrainingTrack], table: ArticulationTable, column: int,
                 names: list[str]) -> None:
        self.tracks, self.table, self.column, self.names = list(tracks), table, column, names
        self.exponent = table.exponent
        rows = [table.rows[n][column] for n in names]
        self.enforced = np.array([r.enforced for r in rows])
        self.rows = [np.array([names.index(row_name(table, label)) for label in t.labels]) for t in self.tracks]

    def vector(self) -> np.ndarray:
        cells = [self.table.rows[n][self.column] for n in self.names]
        return np.concatenate([[c.value for c in cells], np.log([c.dominance for c in cells]),
                               np.log([c.anticipation for c in cells]), np.log([c.carryover for c in cells])])

    def residuals(self, x: np.ndarray) -> np.ndarray:
        return np.concatenate([(self._track(t, r, x, False)[0] - t.values)[t.used]
                               for t, r in zip(self.tracks, self.rows, strict=True)])

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        return np.vstack([self._track(t, r, x, True)[1][t.used] for t, r in zip(self.tracks, self.rows, strict=True)])

    def tracks_for(self, x: np.ndarray) -> list[np.ndarray]:
        return [self._track(t, r, x, False)[0] for t, r in zip(self.tracks, self.rows, strict=True)]

    def _track(self, t: TrainingTrack, rows: np.ndarray, x: np.ndarray,
               derivatives: bool) -> tuple[np.ndarray, np.ndarray]:
        n = len(self.names)
        target, log_alpha = x[:n][rows], x[n:2 * n][rows]
        ahead, after = np.exp(x[2 * n:3 * n][rows]), np.exp(x[3 * n:][rows])
        middles = (t.starts_ms + t.ends_ms) / 2
        tau = t.times_ms[:, None] - middles[None, :]
        distance = np.abs(tau) ** self.exponent
        before = tau < 0
        rate = np.where(before, ahead[None, :], after[None, :])
        log_w = log_alpha[None, :] - rate * distance
        w = np.exp(log_w - log_w.max(axis=1, keepdims=True))      # a common factor per frame cancels
        share = w / w.sum(axis=1, keepdims=True)
        track = share @ target
        jac = np.zeros((len(track), 4 * n))
        if derivatives:
            onehot = np.zeros((len(rows), n))
            onehot[np.arange(len(rows)), rows] = 1.0
            pull = share * (target[None, :] - track[:, None])    # ∂F/∂log α_k
            jac[:, :n] = share @ onehot
            jac[:, n:2 * n] = pull @ onehot
            jac[:, 2 * n:3 * n] = (pull * np.where(before, -rate * distance, 0.0)) @ onehot
            jac[:, 3 * n:] = (pull * np.where(before, 0.0, -rate * distance)) @ onehot
        order = np.argsort(t.times_ms, kind="stable")
        sorted_times = t.times_ms[order]
        for k in np.flatnonzero(self.enforced[rows]):
            lo = np.searchsorted(sorted_times, t.starts_ms[k], "left")
            hi = np.searchsorted(sorted_times, t.ends_ms[k], "right")
            inside = order[lo:hi]
            window = closure_window(t.times_ms[inside], t.starts_ms[k], t.ends_ms[k])
            track[inside] = track[inside] * (1 - window) + target[k] * window
            if derivatives:
                jac[inside] *= (1 - window)[:, None]
                jac[inside, rows[k]] += window
        return track, jac

    def table_with(self, x: np.ndarray, free: list[str]) -> tuple[ArticulationTable, dict[str, tuple[Target, Target]]]:
        n = len(self.names)
        rows = {phone: list(targets) for phone, targets in self.table.rows.items()}
        changes = {}
        for name in free:
            i = self.names.index(name)
            old = self.table.rows[name][self.column]
            new = Target(float(x[i]), float(math.exp(x[n + i])), float(math.exp(x[2 * n + i])),
                         float(math.exp(x[3 * n + i])), old.enforced)
            rows[name][self.column] = new
            changes[name] = (old, new)
        t = self.table
        return ArticulationTable(list(t.parameters), rows, t.exponent, t.file, dict(t.lines), t.phoneset,
                                 dict(t.settings), t.derived), changes
