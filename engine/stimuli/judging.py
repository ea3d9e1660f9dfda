"""A stimulus judged as it is made (``[output] validate = true``), and the set's verdicts summed up.

Each worker judges its stimulus's still and video with the observers of :mod:`engine.validation`
(loaded once a worker): the emotion against the one its levels mean, the face found, the lips of
the video against the lip gap of the very timeline that drew it. The verdicts go into the
stimulus's record; :func:`check_columns` adds them to ``check.csv``, and :func:`set_tables` gives
the set's ``validation.csv``, its confusion and identity tables and ``validation-report.html``.

>>> from engine.stimuli.design import parse_design
>>> design = parse_design('[factors]\\ntext = ["Moi."]\\n[output]\\nkinds = ["png"]\\nvalidate = true\\n')
>>> design.output.validate
True
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from engine.model.model import Model

VALIDATION_TABLE = "validation.csv"
VALIDATION_REPORT = "validation-report.html"
CHECK_COLUMNS = ("validation_status", "face_found", "intended_emotion", "judged_emotion", "judged_probability",
                 "intended_probability", "read_as_intended", "identity_distance_own", "nearest_other_distance",
                 "lip_r", "closures_intended", "closures_seen", "frames_face_lost")


def judge_stimulus(stimulus_id: str, levels: dict[str, Any], paths: dict[str, Path], model: Model,
                   frame_times: np.ndarray, values: np.ndarray, fps: float,
                   frames: np.ndarray | None) -> list[dict[str, Any]]:
    """The verdicts (as records) on the stimulus's still and its video, the video's lips against the gap
    the engine drew (``values`` at ``frame_times``, frames × parameters)."""
    from engine.stimuli.design import level_text
    from engine.validation import judge_file, lip_track, stimulus_intended
    from engine.validation.judge import judge_frames
    from engine.validation.records import verdict_record

    intended = stimulus_intended({"id": stimulus_id, **{k: str(level_text(v)) for k, v in levels.items()}})
    verdicts = []
    if "png" in paths:
        verdicts.append(judge_file(paths["png"], intended))
    video = next((kind for kind in ("mp4", "silent-mp4") if kind in paths), None)
    if video is not None:
        lips = lip_track(model, frame_times, values)
        if frames is not None:
            verdicts.append(judge_frames(frames, fps, str(paths[video]), intended, lips))
        else:
            verdicts.append(judge_file(paths[video], intended, lips))
    for verdict in verdicts:
        verdict.file = Path(verdict.file).name
    return [verdict_record(v) for v in verdicts]


def set_verdicts(records: list[dict[str, Any]]) -> list[Any]:
    """Every verdict of the set's records, summed up (identity distances filled in), or [] when the set
    was made without validation."""
    from engine.validation import summarise
    from engine.validation.records import verdict_from_record

    verdicts = [verdict_from_record(v) for r in records for v in r.get("validation", [])]
    return summarise(verdicts).verdicts if verdicts else []


def check_columns(record: dict[str, Any], verdicts: list[Any]) -> dict[str, str]:
    """The validation columns of one stimulus's ``check.csv`` row: the emotion of its still (or, with no
    still, its video), the lips and lost frames of its video."""
    from engine.validation.table import verdict_row

    mine = [v for v in verdicts if v.intended.stimulus == record["id"]]
    row = dict.fromkeys(CHECK_COLUMNS, "")
    if not mine:
        return row
    still = next((v for v in mine if v.kind == "image"), mine[0])
    video = next((v for v in mine if v.kind == "video"), None)
    cells = verdict_row(still)
    row.update({name: cells[name] for name in ("intended_emotion", "judged_emotion", "judged_probability",
                                               "intended_probability", "read_as_intended",
                                               "nearest_other_distance")})
    row["identity_distance_own"] = cells["identity_distance_own"]
    row["validation_status"] = "; ".join(f"{v.kind}: {v.status}" for v in mine if v.status != "ok") or "ok"
    row["face_found"] = "yes" if all(v.faces > 0 for v in mine) else "NO"
    if video is not None:
        video_cells = verdict_row(video)
        row.update({name: video_cells[name] for name in ("lip_r", "closures_intended", "closures_seen",
                                                         "frames_face_lost")})
    return row


def set_tables(verdicts: list[Any], title: str) -> dict[str, str]:
    """The set's validation files by name: the three tables and the report."""
    from engine.validation import report_html, summarise
    from engine.validation.table import table_texts

    summary = summarise(verdicts)
    texts = table_texts(summary, VALIDATION_TABLE)
    texts[VALIDATION_REPORT] = report_html(summary, title)
    return texts
