"""The validation tables: one row a file (``validation.csv``), the confusion matrix and the identity
distances beside it (``validation-confusion.csv``, ``validation-identities.csv``), written together.

Columns of the main table (empty where a value does not apply):

``file``, ``stimulus``, ``kind`` (image, video, or ? for a file that could not be read),
``status`` (ok, or what went wrong: no face, 2 faces, cut short …), ``faces``, ``face_score``,
``detector``; ``intended_emotion``, ``intended_expression``, ``judged_emotion``,
``judged_probability``, ``intended_probability``, ``read_as_intended`` (yes/no), ``p_<class>`` for
each of the seven classes; ``identity``, ``identity_distance_own``, ``identity_reference``,
``nearest_other_identity``, ``nearest_other_distance``; ``lip_aperture``, ``eye_opening``,
``brow_height`` (inter-ocular distances); for videos ``frames``, ``frames_face_lost``,
``lip_r`` (pixels against the engine's lip gap), ``closures_intended``, ``closures_seen``,
``lip_aperture_min``, ``lip_aperture_max``; ``notes``.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path
from typing import Any

from engine.formats.atomic import atomic_files
from engine.validation.judge import Verdict
from engine.validation.observers import EMOTIONS
from engine.validation.summary import NO_FACE, Summary

COLUMNS = ["file", "stimulus", "kind", "status", "faces", "face_score", "detector", "intended_emotion",
           "intended_expression", "judged_emotion", "judged_probability", "intended_probability", "read_as_intended",
           *(f"p_{e}" for e in EMOTIONS), "identity", "identity_distance_own", "identity_reference",
           "nearest_other_identity", "nearest_other_distance", "lip_aperture", "eye_opening", "brow_height",
           "frames", "frames_face_lost", "lip_r", "closures_intended", "closures_seen", "lip_aperture_min",
           "lip_aperture_max", "notes"]


def verdict_row(v: Verdict) -> dict[str, Any]:
    """The main table's row for one verdict (numbers as text, 4 decimals)."""
    row: dict[str, Any] = dict.fromkeys(COLUMNS, "")
    row.update({
        "file": v.file, "stimulus": v.intended.stimulus, "kind": v.kind, "status": v.status, "faces": v.faces,
        "face_score": _n(v.face_score), "detector": v.detector, "intended_emotion": v.intended.emotion or "",
        "intended_expression": v.intended.expression, "judged_emotion": v.judged or "",
        "judged_probability": _n(v.judged_probability), "intended_probability": _n(v.intended_probability),
        "read_as_intended": {True: "yes", False: "no", None: ""}[v.read_as_intended],
        "identity": v.intended.identity, "identity_distance_own": _n(v.identity_own),
        "identity_reference": v.identity_reference, "nearest_other_identity": v.nearest_other,
        "nearest_other_distance": _n(v.nearest_other_distance), "lip_aperture": _n(v.lip_aperture),
        "eye_opening": _n(v.eye_opening), "brow_height": _n(v.brow_height),
        "frames": v.frames if v.kind == "video" else "", "frames_face_lost": v.frames_lost if v.kind == "video" else "",
        "notes": "; ".join(v.notes),
    })
    for k, e in enumerate(EMOTIONS):
        row[f"p_{e}"] = "" if v.emotions is None else _n(float(v.emotions[k]))
    if v.lips is not None:
        row.update(lip_r=_n(v.lips.r), closures_intended=v.lips.closures_intended,
                   closures_seen=v.lips.closures_seen, lip_aperture_min=_n(v.lips.aperture_min),
                   lip_aperture_max=_n(v.lips.aperture_max))
    return row


def write_tables(summary: Summary, path: str | Path) -> list[Path]:
    """``path`` and its two companions, written together (atomically); returns the three paths."""
    path = Path(path)
    texts = {path.with_name(name): text for name, text in table_texts(summary, path.name).items()}
    with atomic_files(texts) as temporary:
        for target, temp in temporary.items():
            temp.write_text(texts[target], encoding="utf-8")
    return list(texts)


def table_texts(summary: Summary, name: str) -> dict[str, str]:
    """The three tables' texts by file name: ``name`` (``validation.csv``) and its two companions."""
    stem = name.removesuffix(".csv")
    return {name: _csv(COLUMNS, [verdict_row(v) for v in summary.verdicts]),
            f"{stem}-confusion.csv": _confusion_text(summary), f"{stem}-identities.csv": _identities_text(summary)}


def _confusion_text(summary: Summary) -> str:
    columns = ["intended", *EMOTIONS, NO_FACE]
    rows = [{"intended": e, **summary.confusion[e]} for e in EMOTIONS if any(summary.confusion[e].values())]
    return _csv(columns, rows)


def _identities_text(summary: Summary) -> str:
    columns = ["identity", *summary.identities]
    rows = [{"identity": a, **{b: _n(d) for b, d in zip(summary.identities, line, strict=True)}}
            for a, line in zip(summary.identities, summary.identity_distances, strict=True)]
    return _csv(columns, rows)


def _csv(columns: list[str], rows: list[dict[str, Any]]) -> str:
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=columns, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    return out.getvalue()


def _n(value: float | None) -> str:
    return "" if value is None else f"{value:.4f}"
