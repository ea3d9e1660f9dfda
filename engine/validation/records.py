"""A verdict as plain data (JSON) and back: how a worker hands its verdicts to the set that sums them up.

>>> import numpy as np
>>> from engine.validation.judge import Verdict
>>> from engine.validation.intended import Intended
>>> v = Verdict("a.png", "image", Intended("happy", "Happy", "anna", "0001"), faces=1, emotions=np.eye(7)[3])
>>> back = verdict_from_record(verdict_record(v))
>>> back.judged, back.intended.identity, back.faces
('happy', 'anna', 1)
"""

from __future__ import annotations

from dataclasses import asdict
from typing import Any

import numpy as np

from engine.validation.intended import Intended
from engine.validation.judge import Verdict
from engine.validation.lips import LipCheck


def verdict_record(v: Verdict) -> dict[str, Any]:
    """The verdict as JSON-ready data (the per-frame traces are left out)."""
    return {
        "file": v.file, "kind": v.kind, "status": v.status, "faces": v.faces, "face_score": v.face_score,
        "detector": v.detector,
        "intended": {"emotion": v.intended.emotion, "expression": v.intended.expression,
                     "identity": v.intended.identity, "stimulus": v.intended.stimulus},
        "emotions": None if v.emotions is None else [float(p) for p in v.emotions],
        "descriptor": None if v.descriptor is None else [float(d) for d in v.descriptor],
        "lip_aperture": v.lip_aperture, "eye_opening": v.eye_opening, "brow_height": v.brow_height,
        "frames": v.frames, "frames_lost": v.frames_lost,
        "lips": None if v.lips is None else asdict(v.lips), "notes": list(v.notes),
    }


def verdict_from_record(record: dict[str, Any]) -> Verdict:
    """The verdict :func:`verdict_record` wrote."""
    meant = record.get("intended") or {}
    lips = record.get("lips")
    return Verdict(
        file=str(record["file"]), kind=str(record["kind"]),
        intended=Intended(emotion=meant.get("emotion"), expression=meant.get("expression", ""),
                          identity=meant.get("identity", ""), stimulus=meant.get("stimulus", "")),
        status=str(record.get("status", "ok")), faces=int(record.get("faces", 0)),
        face_score=record.get("face_score"), detector=str(record.get("detector", "")),
        emotions=None if record.get("emotions") is None else np.array(record["emotions"], dtype=float),
        descriptor=None if record.get("descriptor") is None else np.array(record["descriptor"], dtype=float),
        lip_aperture=record.get("lip_aperture"), eye_opening=record.get("eye_opening"),
        brow_height=record.get("brow_height"), frames=int(record.get("frames", 0)),
        frames_lost=int(record.get("frames_lost", 0)), lips=None if lips is None else LipCheck(**lips),
        notes=list(record.get("notes", [])))

