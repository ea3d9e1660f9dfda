"""A study's data summed up: recognition, confusions, Wagner's Hu and chance, ratings, contrasts.

Only test trials count (practice does not; attention checks decide who is kept: a participant who
fails more of them than ``min_attention`` allows is left out, and listed). Conditions are the source
(synthetic, human) × the presentation (static, dynamic). Per condition and emotion:

* the **recognition rate**, hits over trials pooled over participants, with Wilson's 95 % interval
  (trials taken as independent), and the mean of the participants' own rates;
* the **confusion matrix** (intended × response: counts and shares of the row);
* **Hu** and **pc** (engine.study.measures) per participant from that participant's matrix of the
  condition, their means, and Wagner's test of Hu against pc (paired t of the arcsine-square-root
  values, across participants; two or more needed), and Hu and pc of the pooled matrix;
* each **rating**'s mean with its t interval (over trials);
* **contrasts**: dynamic − static within each source, synthetic − human within each presentation, for
  the hit rate (pooled: Newcombe's interval; paired over participants: t), Hu and each rating.
"""

from __future__ import annotations

import math
import statistics
from collections import defaultdict
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

from engine.study.design import CANONICAL_EMOTIONS
from engine.study.measures import (
    arcsine,
    confusion_counts,
    hu_table,
    mean_interval,
    newcombe,
    paired_t,
    wilson,
)
from engine.study.results import Results, Trial

__all__ = ["Analysis", "analyse", "categories_of"]

ALL = "all"
CONDITION_ORDER = (("synthetic", "static"), ("synthetic", "dynamic"), ("human", "static"), ("human", "dynamic"))


@dataclass
class Analysis:
    results: Results
    included: list[Trial]
    responses: list[str]
    conditions: list[tuple[str, str]]
    participants: list[dict[str, Any]] = field(default_factory=list)
    recognition: list[dict[str, Any]] = field(default_factory=list)
    confusion: dict[tuple[str, str], tuple[list[str], list[list[int]]]] = field(default_factory=dict)
    hu: list[dict[str, Any]] = field(default_factory=list)
    ratings: list[dict[str, Any]] = field(default_factory=list)
    contrasts: list[dict[str, Any]] = field(default_factory=list)
    validation: list[dict[str, Any]] = field(default_factory=list)
    validation_summary: list[dict[str, Any]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    @property
    def identification(self) -> bool:
        return any(t.response for t in self.included)


def categories_of(values: Iterable[str]) -> list[str]:
    """Emotion names in the report's order: the usual emotions, others alphabetically, neutral, other."""
    found = set(values)
    ordered = [e for e in CANONICAL_EMOTIONS if e in found]
    ordered += sorted(found - set(CANONICAL_EMOTIONS) - {"neutral", "other", ""})
    return ordered + [e for e in ("neutral", "other") if e in found]


def analyse(results: Results, min_attention: float = 1.0) -> Analysis:
    """The analysis of ``results``; ``min_attention``: the share of attention checks a participant must pass."""
    by_participant: dict[str, list[Trial]] = defaultdict(list)
    for trial in results.trials:
        by_participant[trial.participant].append(trial)
    participants, kept = [], set()
    for name in sorted(by_participant, key=_natural):
        row = _participant_row(name, by_participant[name], min_attention)
        participants.append(row)
        if row["included"]:
            kept.add(name)
    included = [t for t in results.trials if t.phase == "test" and t.participant in kept]
    present = {(t.source, t.presentation) for t in included}
    conditions = [c for c in CONDITION_ORDER if c in present]
    responses = categories_of([t.response for t in included] + [t.intended for t in included])
    analysis = Analysis(results, included, responses, conditions, participants)
    dropped = [p["participant"] for p in participants if not p["included"]]
    if dropped:
        analysis.notes.append(f"left out for failing attention checks: {', '.join(dropped)}")
    if not included:
        analysis.notes.append("no participant is left to analyse")
        return analysis
    if analysis.identification:
        _identification(analysis)
    _ratings(analysis)
    _contrasts(analysis)
    return analysis


def _mean(values: list[float]) -> float:
    return statistics.fmean(values) if values else math.nan


def _natural(name: str) -> tuple[int, int | str]:
    return (0, int(name)) if name.isdigit() else (1, name)


def _participant_row(name: str, trials: list[Trial], min_attention: float) -> dict[str, Any]:
    test = [t for t in trials if t.phase == "test"]
    checks = [t for t in trials if t.phase == "attention"]
    passed = sum(t.correct for t in checks)
    rts = [t.rt for t in test if t.rt is not None]
    answered = [t for t in test if t.response]
    share = passed / len(checks) if checks else 1.0
    return {"participant": name, "files": ";".join(sorted({t.file for t in trials})), "order": test[0].order if test
            else "", "trials": len(test), "practice": sum(t.phase == "practice" for t in trials),
            "attention_checks": len(checks), "attention_passed": passed,
            "included": bool(test) and share >= min_attention - 1e-9,
            "hit_rate": sum(t.correct for t in answered) / len(answered) if answered else math.nan,
            "median_rt": statistics.median(rts) if rts else math.nan}


def _by_condition(trials: Iterable[Trial]) -> dict[tuple[str, str], list[Trial]]:
    out: dict[tuple[str, str], list[Trial]] = defaultdict(list)
    for t in trials:
        out[(t.source, t.presentation)].append(t)
    return out


def _identification(analysis: Analysis) -> None:
    columns = analysis.responses
    for condition, trials in _by_condition(t for t in analysis.included if t.response).items():
        rows = categories_of([t.intended for t in trials])
        pooled = confusion_counts([(t.intended, t.response) for t in trials], rows, columns)
        analysis.confusion[condition] = (rows, pooled)
        pooled_hu = hu_table(pooled, rows, columns)
        per_participant: dict[str, dict[str, dict[str, float]]] = {}
        for name in sorted({t.participant for t in trials}, key=_natural):
            own = [t for t in trials if t.participant == name]
            table = hu_table(confusion_counts([(t.intended, t.response) for t in own], rows, columns), rows, columns)
            per_participant[name] = table
            for emotion, values in table.items():
                if values["stimuli"]:
                    analysis.hu.append({"participant": name, "source": condition[0], "presentation": condition[1],
                                        "emotion": emotion, **values})
        for emotion in [*rows, ALL]:
            analysis.recognition.append(_recognition_row(condition, emotion, trials, pooled_hu, per_participant))
    analysis.conditions = [c for c in CONDITION_ORDER if c in analysis.confusion]
    rank = {c: k for k, c in enumerate(CONDITION_ORDER)}
    analysis.recognition.sort(key=lambda r: rank[(r["source"], r["presentation"])])
    analysis.hu.sort(key=lambda r: (_natural(r["participant"]), rank[(r["source"], r["presentation"])]))


def _recognition_row(condition: tuple[str, str], emotion: str, trials: list[Trial],
                     pooled_hu: dict[str, dict[str, float]],
                     per_participant: dict[str, dict[str, dict[str, float]]]) -> dict[str, Any]:
    chosen = [t for t in trials if emotion == ALL or t.intended == emotion]
    hits = sum(t.response == t.intended for t in chosen)
    low, high = wilson(hits, len(chosen))
    rates = []
    for name in per_participant:
        own = [t for t in chosen if t.participant == name]
        if own:
            rates.append(sum(t.response == t.intended for t in own) / len(own))
    row: dict[str, Any] = {"source": condition[0], "presentation": condition[1], "emotion": emotion,
                           "trials": len(chosen), "hits": hits, "rate": hits / len(chosen) if chosen else math.nan,
                           "ci_low": low, "ci_high": high, "participants": len(rates),
                           "participant_mean": statistics.fmean(rates) if rates else math.nan,
                           "participant_sd": statistics.stdev(rates) if len(rates) > 1 else math.nan}
    if emotion == ALL:
        hus = [_mean([v["hu"] for v in table.values() if v["stimuli"]]) for table in per_participant.values()]
        pcs = [_mean([v["pc"] for v in table.values() if v["stimuli"]]) for table in per_participant.values()]
        hus, pcs = [x for x in hus if not math.isnan(x)], [x for x in pcs if not math.isnan(x)]
        pooled = [v for v in pooled_hu.values() if v["stimuli"]]
        pooled_values = (_mean([v["hu"] for v in pooled]), _mean([v["pc"] for v in pooled]))
    else:
        hus = [table[emotion]["hu"] for table in per_participant.values() if table[emotion]["stimuli"]]
        pcs = [table[emotion]["pc"] for table in per_participant.values() if table[emotion]["stimuli"]]
        pooled_values = (pooled_hu[emotion]["hu"], pooled_hu[emotion]["pc"])
    t, p, _ = paired_t([arcsine(x) for x in pcs], [arcsine(x) for x in hus])
    row.update({"hu_mean": statistics.fmean(hus) if hus else math.nan,
                "hu_sd": statistics.stdev(hus) if len(hus) > 1 else math.nan,
                "pc_mean": statistics.fmean(pcs) if pcs else math.nan,
                "hu_pooled": pooled_values[0], "pc_pooled": pooled_values[1], "hu_vs_pc_t": t, "hu_vs_pc_p": p})
    return row


def _ratings(analysis: Analysis) -> None:
    for scale in analysis.results.scales:
        for condition, trials in _by_condition(analysis.included).items():
            for emotion in [*categories_of([t.intended for t in trials]), ALL]:
                values = [t.ratings[scale] for t in trials if scale in t.ratings and emotion in (ALL, t.intended)]
                if not values:
                    continue
                mean, sd, n, low, high = mean_interval(values)
                analysis.ratings.append({"scale": scale, "source": condition[0], "presentation": condition[1],
                                         "emotion": emotion, "trials": n, "mean": mean, "sd": sd, "ci_low": low,
                                         "ci_high": high})
    rank = {c: k for k, c in enumerate(CONDITION_ORDER)}
    scales = analysis.results.scales
    analysis.ratings.sort(key=lambda r: (scales.index(r["scale"]), rank[(r["source"], r["presentation"])]))


def _contrasts(analysis: Analysis) -> None:
    have = set(analysis.conditions)
    pairs = [("dynamic − static", source, (source, "static"), (source, "dynamic"))
             for source in ("synthetic", "human") if {(source, "static"), (source, "dynamic")} <= have]
    pairs += [("synthetic − human", presentation, ("human", presentation), ("synthetic", presentation))
              for presentation in ("static", "dynamic")
              if {("human", presentation), ("synthetic", presentation)} <= have]
    grouped = _by_condition(analysis.included)
    for name, within, a, b in pairs:
        emotions = [e for e in categories_of([t.intended for t in grouped[a]])
                    if e in {t.intended for t in grouped[b]}] + [ALL]
        for emotion in emotions:
            ta = [t for t in grouped[a] if emotion in (ALL, t.intended)]
            tb = [t for t in grouped[b] if emotion in (ALL, t.intended)]
            measures: list[str] = (["hit_rate", "hu"] if analysis.identification else [])
            measures += [f"rating_{s}" for s in analysis.results.scales]
            for measure in measures:
                row = _contrast_row(measure, ta, tb, analysis, a, b, emotion)
                if row is not None:
                    analysis.contrasts.append({"contrast": name, "within": within, "emotion": emotion, **row})


def _contrast_row(measure: str, ta: list[Trial], tb: list[Trial], analysis: Analysis, a: tuple[str, str],
                  b: tuple[str, str], emotion: str) -> dict[str, Any] | None:
    if measure == "hit_rate":                   # the answered trials (a trial with no answer is in no matrix)
        ta, tb = [t for t in ta if t.response], [t for t in tb if t.response]

    def value(trials: list[Trial]) -> float:
        if measure == "hit_rate":
            return sum(t.response == t.intended for t in trials) / len(trials) if trials else math.nan
        scale = measure[len("rating_"):]
        values = [t.ratings[scale] for t in trials if scale in t.ratings]
        return statistics.fmean(values) if values else math.nan

    pooled_low = pooled_high = math.nan
    if measure == "hu":
        per = _hu_by_participant(analysis, emotion)
        va = {p: v for (p, c), v in per.items() if c == a}
        vb = {p: v for (p, c), v in per.items() if c == b}
        a_value = statistics.fmean(va.values()) if va else math.nan
        b_value = statistics.fmean(vb.values()) if vb else math.nan
    else:
        a_value, b_value = value(ta), value(tb)
        people = sorted({t.participant for t in ta} & {t.participant for t in tb}, key=_natural)
        va = {p: value([t for t in ta if t.participant == p]) for p in people}
        vb = {p: value([t for t in tb if t.participant == p]) for p in people}
        if measure == "hit_rate":
            _, pooled_low, pooled_high = newcombe(sum(t.response == t.intended for t in ta), len(ta),
                                                  sum(t.response == t.intended for t in tb), len(tb))
        else:
            pooled_low, pooled_high = _welch([t.ratings[measure[7:]] for t in ta if measure[7:] in t.ratings],
                                             [t.ratings[measure[7:]] for t in tb if measure[7:] in t.ratings])
    if math.isnan(a_value) or math.isnan(b_value):
        return None
    both = [p for p in va if p in vb and not (math.isnan(va[p]) or math.isnan(vb[p]))]
    differences = [vb[p] - va[p] for p in both]
    mean, _, _, low, high = mean_interval(differences)
    if measure in ("hit_rate", "hu"):            # a difference of proportions lies within ±1
        low, high = max(-1.0, low), min(1.0, high)
    t, p, _ = paired_t([va[q] for q in both], [vb[q] for q in both])
    return {"measure": measure, "a": " ".join(a), "b": " ".join(b), "a_value": a_value, "b_value": b_value,
            "difference": b_value - a_value, "pooled_ci_low": pooled_low, "pooled_ci_high": pooled_high,
            "participants": len(both), "paired_mean": mean, "paired_ci_low": low, "paired_ci_high": high,
            "t": t, "p": p}


def _hu_by_participant(analysis: Analysis, emotion: str) -> dict[tuple[str, tuple[str, str]], float]:
    values: dict[tuple[str, tuple[str, str]], list[float]] = defaultdict(list)
    for row in analysis.hu:
        if emotion in (ALL, row["emotion"]):
            values[(row["participant"], (row["source"], row["presentation"]))].append(row["hu"])
    return {key: statistics.fmean(v) for key, v in values.items()}


def _welch(a: list[float], b: list[float]) -> tuple[float, float]:
    """Welch's 95 % interval of mean(b) − mean(a) (nan where either has fewer than 2 values)."""
    if len(a) < 2 or len(b) < 2:
        return math.nan, math.nan
    va, vb = statistics.variance(a) / len(a), statistics.variance(b) / len(b)
    difference = statistics.fmean(b) - statistics.fmean(a)
    if va + vb == 0:
        return difference, difference
    df = (va + vb) ** 2 / (va * va / (len(a) - 1) + vb * vb / (len(b) - 1))
    from scipy.stats import t

    half = float(t.ppf(0.975, df)) * math.sqrt(va + vb)
    return difference - half, difference + half
