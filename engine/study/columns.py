"""The columns of a study's data: one row per trial, in the long format (docs/study.md, *The data*).

>>> columns_for(["intensity"], ["expression", "trial"])[0][-3:]
['word_onsets', 'expression', 'factor_trial']
"""

from __future__ import annotations

__all__ = ["IDENTITY_COLUMNS", "REQUIRED", "TIME_COLUMNS", "TRIAL_COLUMNS", "columns_for", "rating_columns"]

IDENTITY_COLUMNS = ("study", "study_id", "set_manifest_sha256", "participant", "participant_source",
                    "participant_seed", "order", "block_order", "host")
TRIAL_COLUMNS = ("trial", "phase", "block", "stimulus", "source", "presentation", "media", "file", "intended",
                 "expected", "response", "response_key", "response_method", "correct", "rt")
TIME_COLUMNS = ("onset_t", "offset_t", "play_t", "clip_start_t", "first_frame_t", "audio_start_t", "face_start_t",
                "speech_onset_t", "ended_t", "response_t", "frames", "dropped_frames", "sound", "clock_spread_ms",
                "duration_ms", "audio_start_ms", "video_start_ms", "speech_onset_ms", "word_onsets")
REQUIRED = ("study", "study_id", "participant", "trial", "phase", "stimulus", "source", "presentation", "intended",
            "response", "rt")
"""What ``study-analyse`` needs of every results file (and a ``rating_NAME`` column per scale it sums up)."""


def rating_columns(name: str) -> list[str]:
    return [f"rating_{name}", f"rating_{name}_rt", f"rating_{name}_method"]


def columns_for(scales: list[str], factors: list[str]) -> tuple[list[str], dict[str, str]]:
    """Every column in order, and the column of each factor level (``factor_NAME`` where NAME is taken)."""
    fixed = [*IDENTITY_COLUMNS, *TRIAL_COLUMNS]
    for name in scales:
        fixed += rating_columns(name)
    fixed += TIME_COLUMNS
    taken = set(fixed)
    levels = {name: f"factor_{name}" if name in taken else name for name in factors}
    return fixed + list(levels.values()), levels
