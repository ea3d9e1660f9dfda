"""``mocap learn``: a phone table whose coarticulation is learned from phone-labelled capture (issue 22 §2).

The paper leaves coarticulation "to be a subject of future analysis of motion
capture data" (§5). Here the sessions are read as trajectories of the model's
articulatory parameters (:mod:`engine.mocap.captured_tracks`), the
Cohen–Massaro targets, dominances and rates of every phone seen are fitted to
them parameter by parameter, regularised toward the starting table
(:mod:`engine.mocap.coarticulation_fit`), and the result is an
:class:`~engine.speech.articulation.ArticulationTable` that ``say
--articulation`` reads once written (:mod:`engine.speech.articulation_writer`).

Cross-validation: the speech is cut into utterances at the pauses (the phones
``#``, ``##``, ``pau``, ``sil``, ``_``); ``holdout`` of them (a fraction,
spread evenly over the sessions in order) are kept out of the fit. On those
frames the tracks of the learned table, of the starting table and of plain
target interpolation (method ``none``) are put through the model and compared
with the recording's lip markers (8.x), in mm of the recording; the model's
own per-frame fit of the captured markers is given beside them as the floor
no table can beat. Frames inside pauses belong to no utterance and are
neither fitted nor measured. Lengths mm, times ms.

>>> from engine.mocap.session import load_session
>>> learned = learn_coarticulation([("take.h5", load_session("take.h5"))], art, model, holdout=0.2)  # doctest: +SKIP
>>> print(learned.report())                                                                   # doctest: +SKIP
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from engine.mocap.captured_tracks import CapturedTake, MarkerModel, capture_tracks
from engine.mocap.coarticulation_fit import PRIOR_OCCURRENCES, ParameterFit, TrainingTrack, fit_parameter
from engine.mocap.errors import MocapError
from engine.mocap.frame_selection import PAUSES
from engine.mocap.pca import Articulation
from engine.mocap.session import Session
from engine.model.model import Model
from engine.speech.articulation import ArticulationTable, load_articulation

MIN_FRAMES = 30
"""Fewer frames in a session than this (half a second at 60 fps) is too little speech to learn from."""
METHODS = ("learned", "shipped", "none", "capture")
METHOD_TITLES = {"learned": "learned table (Cohen–Massaro)", "shipped": "starting table (Cohen–Massaro)",
                 "none": "plain target interpolation", "capture": "per-frame fit of the markers (floor)"}


@dataclass
class LearnedCoarticulation:
    """The learned table, what each parameter's fit did, and the trajectory error of each method."""

    table: ArticulationTable
    starting_table: str
    fits: list[ParameterFit]
    sources: list[str]
    utterances: int
    held_out: int
    fit_frames: int
    measured_frames: int
    lip_rms_mm: dict[str, float]
    """Method (:data:`METHODS`) → RMS distance at the lip markers over the measured frames, mm of the recording."""

    def report(self) -> str:
        where = "held-out" if self.held_out else "training (nothing held out)"
        lines = [f"learned from {len(self.sources)} session(s): {self.utterances} utterances, "
                 f"{self.utterances - self.held_out} fitted ({self.fit_frames} frames), {self.held_out} held out",
                 "parameter         rows fitted  RMS on the fitted frames, starting → learned (parameter units)"]
        lines += [f"  {f.parameter:<16s} {len(f.phones):>5d}        {f.rms_shipped:.4f} → {f.rms_learned:.4f}"
                  for f in self.fits]
        lines.append(f"RMS trajectory error at the lip markers, {where} frames ({self.measured_frames}), mm:")
        lines += [f"  {METHOD_TITLES[m]:<38s} {self.lip_rms_mm[m]:6.3f}" for m in METHODS]
        return "\n".join(lines) + "\n"

    def header(self) -> str:
        """The comment the written table starts with: what it was learned from."""
        lines = ["Learned by 'artificial-person mocap learn' (docs/mocap-learn.md) from:"]
        lines += [f"  {s}" for s in self.sources]
        lines.append(f"starting from {self.starting_table}, prior weight {PRIOR_OCCURRENCES:g} occurrences;")
        lines.append(f"{self.utterances - self.held_out} utterances fitted, {self.held_out} held out; "
                     "RMS at the lip markers, mm: "
                     + ", ".join(f"{m} {self.lip_rms_mm[m]:.3f}" for m in METHODS))
        lines.append("Rows of phones the recordings did not show are the starting table's.")
        return "\n".join(lines)


def parse_holdout(text: str) -> float:
    """``"20%"`` → 0.2; a percentage from 0 to below 100.

    >>> parse_holdout("20%"), parse_holdout("0")
    (0.2, 0.0)
    """
    match = re.fullmatch(r"\s*(\d+(?:\.\d*)?|\.\d+)\s*%?\s*", text)
    value = float(match.group(1)) if match else -1.0
    if not 0.0 <= value < 100.0:
        raise MocapError(f"--holdout must be a percentage from 0 to below 100, such as 20%, not '{text}'")
    return value / 100.0


def utterance_spans(phones: Sequence[tuple[float, float, str]]) -> list[tuple[float, float]]:
    """(start_ms, end_ms) of each stretch of phones between pauses.

    >>> utterance_spans([(0, 10, "#"), (10, 50, "p"), (50, 90, "a"), (90, 99, "#"), (99, 130, "u")])
    [(10.0, 90.0), (99.0, 130.0)]
    """
    spans: list[tuple[float, float]] = []
    start: float | None = None
    end = 0.0
    for a, b, label in phones:
        if label in PAUSES:
            if start is not None:
                spans.append((start, end))
            start = None
        else:
            start = float(a) if start is None else start
            end = float(b)
    if start is not None:
        spans.append((start, end))
    return spans


def learn_coarticulation(sessions: Sequence[tuple[str, Session]], art: Articulation, model: Model,
                         table: ArticulationTable | None = None, holdout: float = 0.0,
                         prior_occurrences: float = PRIOR_OCCURRENCES) -> LearnedCoarticulation:
    """Learn the coarticulation of ``table`` (default: the shipped Finnish one) from ``sessions`` (see above)."""
    from engine.speech.coarticulation import articulation_tracks
    from engine.speech.synthesis import Segment

    table = load_articulation() if table is None else table
    if not sessions:
        raise MocapError("no session to learn from")
    for source, session in sessions:
        if not session.phones:
            raise MocapError("the session has no phone labels: import it with --labels or --text", file=source)
        if session.n_frames < MIN_FRAMES:
            raise MocapError(f"the session has {session.n_frames} frames: too few to learn from "
                             f"(at least {MIN_FRAMES})", file=source)
        unknown = sorted({label for _, _, label in session.phones if not _has_row(table, label)})
        if unknown:
            raise MocapError(f"the phone table {table.file} has no row for the session's phones "
                             f"{' '.join(unknown)}: give --table with rows for them", file=source)
    parameters = _moving_parameters(model, art, table)
    captured = [capture_tracks(session, art, model, parameters, source) for source, session in sessions]
    takes = [take for take, _ in captured]
    spans = [utterance_spans(take.phones) for take in takes]
    train, test, count, held = _split(takes, spans, holdout)
    fits = []
    learned = table
    for j, name in enumerate(parameters):
        tracks = [TrainingTrack(take.times_ms, [p[2] for p in take.phones], np.array([p[0] for p in take.phones]),
                                np.array([p[1] for p in take.phones]), take.values[:, j],
                                mask & np.isfinite(take.values[:, j]))
                  for take, mask in zip(takes, train, strict=True)]
        fit = fit_parameter(tracks, learned, name, prior_occurrences)
        fits.append(fit)
        learned = fit.table

    measured = test if held else train
    errors: dict[str, list[np.ndarray]] = {m: [] for m in METHODS}
    for (take, marker_model), mask in zip(captured, measured, strict=True):
        segments = [Segment(label, a, b) for a, b, label in take.phones]
        lips = [k for k, m in enumerate(take.markers) if m.startswith("8.")]
        candidates = {"learned": articulation_tracks(segments, _Columns(learned, parameters), take.times_ms),
                      "shipped": articulation_tracks(segments, _Columns(table, parameters), take.times_ms),
                      "none": articulation_tracks(segments, _Columns(table, parameters), take.times_ms, "none"),
                      "capture": np.nan_to_num(take.values)}
        for method, tracks in candidates.items():
            distance = take.marker_error_mm(marker_model, tracks, mask)[:, lips]
            errors[method].append(distance[np.isfinite(distance)])
    rms = {m: float(np.sqrt(np.mean(np.concatenate(e) ** 2))) if sum(map(len, e)) else float("nan")
           for m, e in errors.items()}
    return LearnedCoarticulation(
        table=learned, starting_table=table.file, fits=fits, sources=[s for s, _ in sessions], utterances=count,
        held_out=held, fit_frames=int(sum(m.sum() for m in train)), measured_frames=int(sum(m.sum() for m in measured)),
        lip_rms_mm=rms)


def _has_row(table: ArticulationTable, phone: str) -> bool:
    return phone in table.rows or (phone.endswith(":") and phone[:-1] in table.rows)


class _Columns:
    """A table seen through some of its parameters (what coarticulation reads)."""

    def __init__(self, table: ArticulationTable, names: Sequence[str]) -> None:
        self._table, self.parameters, self.exponent = table, list(names), table.exponent
        self._columns = [table.parameters.index(n) for n in names]

    def arrays(self, labels: list[str], /) -> tuple[np.ndarray, ...]:
        return tuple(a[:, self._columns] for a in self._table.arrays(labels))


def _moving_parameters(model: Model, art: Articulation, table: ArticulationTable) -> list[str]:
    """The table's parameters the model has that move an articulation marker."""
    lips = [m for m in art.markers if m in model.landmarks]
    names = [p for p in table.parameters if p in model.parameters]
    if not lips or not names:
        raise MocapError("none of the table's parameters can be seen at the articulation's markers on this model")
    jacobian = MarkerModel(model, lips, names).jacobian(np.zeros(len(names)))
    moving = [n for k, n in enumerate(names) if np.abs(jacobian[:, k]).max() > 1e-6]
    if not moving:
        raise MocapError(f"none of the table's parameters ({', '.join(table.parameters)}) moves the markers")
    return moving


def _split(takes: Sequence[CapturedTake], spans: Sequence[list[tuple[float, float]]],
           holdout: float) -> tuple[list[np.ndarray], list[np.ndarray], int, int]:
    """Per take, frames fitted and frames held out; the number of utterances and of held-out ones."""
    everything = [(i, span) for i, take_spans in enumerate(spans) for span in take_spans]
    count = len(everything)
    held = 0 if holdout == 0 else max(1, round(holdout * count))
    if count == 0:
        raise MocapError("the sessions' phone labels hold no speech between the pauses")
    if held >= count:
        raise MocapError(f"cannot hold out {100 * holdout:g}% of {count} utterance(s) and still fit: "
                         "give more sessions or a smaller --holdout")
    chosen = {int((k + 0.5) * count / held) for k in range(held)} if held else set()
    train = [np.zeros(take.n_frames, bool) for take in takes]
    test = [np.zeros(take.n_frames, bool) for take in takes]
    for n, (i, (start, end)) in enumerate(everything):
        inside = (takes[i].times_ms >= start) & (takes[i].times_ms < end)
        (test if n in chosen else train)[i][inside] = True
    return train, test, count, held
