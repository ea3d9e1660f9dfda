"""The ``validate`` verdicts beside the participants': each synthetic stimulus judged by the observers and by people.

:func:`check_set` makes sure the set given is the one the study was built from (the SHA-256 of its
``manifest.csv`` is in every row of the data); :func:`beside_people` runs ``engine.validation.validate``
on the set and joins each still (static) and video (dynamic) with the participants' answers to it.
"""

from __future__ import annotations

import math
from collections import Counter
from pathlib import Path
from typing import Any

from engine.study.analysis import ALL, Analysis, categories_of
from engine.study.results import Results, ResultsError
from engine.study.stimuli_list import sha256_file

__all__ = ["beside_people", "check_set"]


def check_set(results: Results, set_folder: Path) -> None:
    """Refuse a set whose manifest is not the one the study was built from."""
    manifest = set_folder / "manifest.csv"
    if not manifest.is_file():
        raise ResultsError("no manifest.csv here: give --set the folder of the study's stimulus set", file=manifest)
    if not results.set_manifest_sha256:
        raise ResultsError("the results do not record the set they were built from (no set_manifest_sha256)",
                           file=results.first_file)
    digest = sha256_file(manifest)
    if digest != results.set_manifest_sha256:
        raise ResultsError(f"the set's manifest has changed since the study was built (SHA-256 {digest[:12]}…, the "
                           f"results record {results.set_manifest_sha256[:12]}…): give the set the study was built "
                           "from", file=manifest)


def beside_people(analysis: Analysis, set_folder: Path, detector: str = "auto") -> None:
    """Fill ``analysis.validation`` (one row a stimulus and presentation) and ``validation_summary``."""
    from engine.validation import ObserversMissing, validate

    try:
        summary = validate([set_folder], detector=detector)
    except ObserversMissing as exc:
        analysis.notes.append(f"no validate verdicts: {exc.message}")
        return
    people: dict[tuple[str, str], list[str]] = {}
    for trial in analysis.included:
        if trial.source == "synthetic" and trial.response:
            people.setdefault((trial.stimulus, trial.presentation), []).append(trial.response)
    for verdict in summary.verdicts:
        presentation = "static" if verdict.kind == "image" else "dynamic"
        stimulus = verdict.intended.stimulus
        answers = people.get((stimulus, presentation), [])
        intended = verdict.intended.emotion or ""
        modal, modal_count = Counter(answers).most_common(1)[0] if answers else ("", 0)
        hits = sum(a == intended for a in answers)
        judged = verdict.judged or ""
        analysis.validation.append({
            "stimulus": stimulus, "presentation": presentation, "file": Path(verdict.file).name,
            "intended": intended, "machine_status": verdict.status, "machine_judged": judged,
            "machine_p_judged": verdict.judged_probability, "machine_p_intended": verdict.intended_probability,
            "machine_read_as_intended": judged == intended if judged and intended else None,
            "people_answers": len(answers), "people_hits": hits,
            "people_hit_rate": hits / len(answers) if answers else math.nan,
            "people_modal": modal, "people_modal_share": modal_count / len(answers) if answers else math.nan,
            "agree": (judged == modal) if judged and modal else None})
    _summary(analysis)


def _summary(analysis: Analysis) -> None:
    rows = [r for r in analysis.validation if r["intended"]]
    for presentation in ("static", "dynamic"):
        mine = [r for r in rows if r["presentation"] == presentation]
        for emotion in [*categories_of([r["intended"] for r in mine]), ALL]:
            chosen = [r for r in mine if emotion in (ALL, r["intended"])]
            judged = [r for r in chosen if r["machine_read_as_intended"] is not None]
            answered = [r for r in chosen if r["people_answers"]]
            agreed = [r for r in chosen if r["agree"] is not None]
            if not chosen:
                continue
            row: dict[str, Any] = {
                "presentation": presentation, "emotion": emotion, "stimuli": len(chosen),
                "machine_read": sum(bool(r["machine_read_as_intended"]) for r in judged),
                "machine_rate": (sum(bool(r["machine_read_as_intended"]) for r in judged) / len(judged)
                                 if judged else math.nan),
                "people_rate": (sum(r["people_hits"] for r in answered) / sum(r["people_answers"] for r in answered)
                                if answered else math.nan),
                "agreement": sum(bool(r["agree"]) for r in agreed) / len(agreed) if agreed else math.nan}
            analysis.validation_summary.append(row)
