"""Reading a study's data back: the CSVs participants' browsers wrote, from any host, checked.

A results file is one participant's CSV (a folder, a lab computer, Pavlovia, a JATOS result file),
several CSVs one after another (JATOS's *Export results → Data only* joins every run's), or a table of
every jsPsych trial with our columns among others (Cognition.run's export: rows that are not trials —
consent, instructions — are passed over). Every file must come from one study (its ``study_id``), and
hold the columns the analysis needs (:data:`engine.study.columns.REQUIRED`). A mistake is one
:class:`ResultsError` naming the file and the line.

>>> table = read_results_text("study,study_id,participant,trial,phase,stimulus,source,presentation,intended,"
...                           "response,rt\\ns,ab12,1,1,test,0001,synthetic,static,happy,happy,512\\n", "r.csv")
>>> [(t.participant, t.stimulus, t.response, t.rt) for t in table.trials]
[('1', '0001', 'happy', 512.0)]
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from engine.errors import UserError
from engine.formats.text_files import read_bounded_text
from engine.study.columns import REQUIRED

__all__ = ["MAX_RESULTS_BYTES", "PHASES", "Results", "ResultsError", "Trial", "read_results", "read_results_text"]

MAX_RESULTS_BYTES = 200_000_000
PHASES = ("practice", "test", "attention")
MAX_RT_MS = 86_400_000.0


class ResultsError(UserError):
    """A results file that cannot be analysed: its file and line are named."""


@dataclass(frozen=True)
class Trial:
    participant: str
    trial: int
    phase: str
    stimulus: str
    source: str
    presentation: str
    intended: str
    response: str
    rt: float | None
    expected: str
    ratings: dict[str, float]
    levels: dict[str, str]
    order: str
    file: str
    line: int

    @property
    def condition(self) -> str:
        return f"{self.source} {self.presentation}"

    @property
    def correct(self) -> bool:
        return self.response == (self.expected if self.phase == "attention" else self.intended)


@dataclass
class Results:
    study: str = ""
    study_id: str = ""
    set_manifest_sha256: str = ""
    trials: list[Trial] = field(default_factory=list)
    scales: list[str] = field(default_factory=list)
    files: list[str] = field(default_factory=list)
    duplicates: int = 0
    first_file: str = ""
    index: dict[tuple[str, int], Trial] = field(default_factory=dict, repr=False)


def read_results(paths: Sequence[str | Path]) -> Results:
    """Every trial of every file, from one study; a participant's trial given twice (the same row) counts once."""
    if not paths:
        raise ResultsError("give the results files (one CSV per participant, or a host's export)")
    results = Results()
    for path in paths:
        text = read_bounded_text(path, limit=MAX_RESULTS_BYTES, error=ResultsError, what="results file")
        _read_into(results, text, str(path))
    if not any(t.phase == "test" for t in results.trials):
        raise ResultsError("the results hold no test trial (only practice, attention checks or pages)",
                           file=results.first_file or str(paths[0]))
    return results


def read_results_text(text: str, name: str) -> Results:
    """:func:`read_results` of one file's text (``name`` is the file named in errors)."""
    results = Results()
    _read_into(results, text, name)
    return results


def _read_into(results: Results, text: str, name: str) -> None:
    text = text.lstrip("\ufeff")
    reader = csv.reader(io.StringIO(text, newline=""))
    header: list[str] | None = None
    header_line = 0
    found = False
    try:
        for cells in reader:
            line = reader.line_num
            if not any(cell.strip() for cell in cells):
                continue
            if _is_header(cells):
                header, header_line = [c.strip() for c in cells], line
                _check_header(header, name, line, results)
                continue
            if header is None:
                raise ResultsError("not the results of an Artificial Person study: no header with 'study_id' and "
                                   "'participant' before the first row", file=name, line=line)
            row = dict(zip(header, cells + [""] * (len(header) - len(cells)), strict=False))
            if len(cells) > len(header) and any(c.strip() for c in cells[len(header):]):
                raise ResultsError(f"a row of {len(cells)} cells under a header of {len(header)}", file=name,
                                   line=line)
            if row.get("phase", "") not in PHASES:
                continue                          # a page, the preloading, a host's own row
            trial = _trial(row, header, results, name, line)
            key = (trial.participant, trial.trial)
            earlier = results.index.get(key)
            if earlier is not None:
                if _answers(earlier) != _answers(trial):
                    raise ResultsError(f"participant {trial.participant}'s trial {trial.trial} is given twice, "
                                       f"differently (also {earlier.file}:{earlier.line}: two sessions of one "
                                       "participant?)", file=name, line=line)
                results.duplicates += 1
                continue
            results.index[key] = trial
            results.trials.append(trial)
            found = True
    except csv.Error as exc:
        raise ResultsError(f"malformed CSV: {exc}", file=name, line=reader.line_num) from None
    if header is None:
        raise ResultsError("not the results of an Artificial Person study (no header with 'study_id' and "
                           "'participant')", file=name, line=1)
    if not found and not results.trials:
        raise ResultsError("no trials in this file", file=name, line=header_line)
    if name not in results.files:
        results.files.append(name)
    if not results.first_file:
        results.first_file = name


def _answers(trial: Trial) -> tuple[object, ...]:
    return (trial.phase, trial.stimulus, trial.presentation, trial.response, trial.rt, sorted(trial.ratings.items()))


def _is_header(cells: list[str]) -> bool:
    names = {c.strip() for c in cells}
    return "study_id" in names and "participant" in names


def _check_header(header: list[str], name: str, line: int, results: Results) -> None:
    missing = [column for column in REQUIRED if column not in header]
    if missing:
        raise ResultsError(f"missing columns: {', '.join(missing)} (not the data of `artificial-person study`, or "
                           "cut by a spreadsheet)", file=name, line=line)
    if len(set(header)) != len(header):
        twice = sorted({c for c in header if header.count(c) > 1})
        raise ResultsError(f"columns named twice: {', '.join(twice)[:200]}", file=name, line=line)
    scales = [c[len("rating_"):] for c in header if c.startswith("rating_") and not c.endswith(("_rt", "_method"))]
    for scale in scales:
        if scale not in results.scales:
            results.scales.append(scale)


def _trial(row: dict[str, str], header: list[str], results: Results, name: str, line: int) -> Trial:
    def fail(message: str) -> ResultsError:
        return ResultsError(message, file=name, line=line)

    study_id = row["study_id"].strip()
    if not results.study_id:
        results.study_id, results.study = study_id, row["study"].strip()
        results.set_manifest_sha256 = row.get("set_manifest_sha256", "").strip()
        results.first_file = results.first_file or name
    elif study_id != results.study_id:
        raise fail(f"from another study: study '{row['study'][:40]}' (study_id {study_id[:20]}), while "
                   f"{results.first_file} is from '{results.study[:40]}' (study_id {results.study_id})")
    participant = row["participant"].strip()
    if not participant or len(participant) > 64:
        raise fail("a trial with no participant (or one of more than 64 characters)")
    try:
        number = int(row["trial"])
    except ValueError:
        raise fail(f"trial {row['trial'][:20]!r} is not a whole number") from None
    if not 0 < number < 10**7:
        raise fail(f"trial {number} is not a trial number")
    for column in ("stimulus", "source", "presentation", "intended"):
        if not row[column].strip():
            raise fail(f"a trial with no {column}")
        if len(row[column]) > 200:
            raise fail(f"{column}: more than 200 characters")
    if row["presentation"] not in ("static", "dynamic"):
        raise fail(f"presentation {row['presentation'][:40]!r} is not static or dynamic")
    if row["source"] not in ("synthetic", "human"):
        raise fail(f"source {row['source'][:40]!r} is not synthetic or human")
    ratings = {}
    for scale in results.scales:
        text = row.get(f"rating_{scale}", "").strip()
        if text:
            ratings[scale] = _number(text, f"rating_{scale}", fail, 1e6)
    known = set(REQUIRED) | {"expected", "order", "block_order"}
    levels = {c: row[c] for c in header if c not in known and not c.startswith(("rating_", "ap_"))
              and c not in _NOT_LEVELS}
    rt_text = row["rt"].strip()
    return Trial(participant, number, row["phase"], row["stimulus"].strip(), row["source"],
                 row["presentation"], row["intended"].strip(), row["response"].strip(),
                 _number(rt_text, "rt", fail, MAX_RT_MS) if rt_text else None, row.get("expected", "").strip(),
                 ratings, levels, row.get("block_order", "").strip(), name, line)


def _number(text: str, column: str, fail: object, limit: float) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or abs(value) > limit:
        assert callable(fail)
        raise fail(f"{column}: {text[:40]!r} is not a number within ±{limit:g}")
    return value


_NOT_LEVELS = frozenset({
    "set_manifest_sha256", "participant_source", "participant_seed", "host", "block", "media", "file",
    "response_key", "response_method", "correct", "onset_t", "offset_t", "play_t", "clip_start_t", "first_frame_t",
    "audio_start_t", "face_start_t", "speech_onset_t", "ended_t", "response_t", "frames", "dropped_frames", "sound",
    "clock_spread_ms", "duration_ms", "audio_start_ms", "video_start_ms", "speech_onset_ms", "word_onsets",
    "trial_type", "trial_index", "time_elapsed", "internal_node_id", "plugin_version", "page", "rt_page", "error",
    "preloaded", "saved"})
