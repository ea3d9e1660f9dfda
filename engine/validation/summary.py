"""A set of verdicts summed up: the emotion confusion matrix, the identity distances, the worst first.

Identities are the files' ``intended.identity`` labels (a set's identity levels, or the
``identity`` column of ``--intended``). Each identity's reference face is the mean descriptor
of its neutral files (intended emotion ``neutral``), or of all its files where it has no
neutral one. Every file gets its distance to its own identity's reference and to the nearest
other identity's; the identity matrix holds the distances between references (less than
:data:`~engine.validation.observers.SAME_PERSON`, 0.6: the same person to dlib). Files with no
identity label are compared with each other, one identity a file.

>>> import numpy as np
>>> from engine.validation.judge import Verdict
>>> from engine.validation.intended import Intended
>>> a = Verdict("a.png", "image", Intended("happy", identity="A"), emotions=np.eye(7)[3], descriptor=np.zeros(128))
>>> b = Verdict("b.png", "image", Intended("sad", identity="B"), emotions=np.eye(7)[2], descriptor=np.ones(128))
>>> s = summarise([a, b])
>>> s.read, s.scored, s.confusion["sad"]["fear"], round(s.identity_distances[0][1], 2)
(1, 2, 1, 11.31)
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from engine.validation.judge import Verdict
from engine.validation.observers import EMOTIONS, SAME_PERSON

NO_FACE = "no face"


@dataclass
class Summary:
    """The set's tables. ``confusion[intended][judged]`` counts files (judged may be "no face")."""

    verdicts: list[Verdict]
    confusion: dict[str, dict[str, int]] = field(default_factory=dict)
    read: int = 0
    scored: int = 0
    mean_intended_probability: float | None = None
    identities: list[str] = field(default_factory=list)
    identity_distances: list[list[float]] = field(default_factory=list)

    @property
    def same_person_pairs(self) -> list[tuple[str, str, float]]:
        """Pairs of different identities the recogniser takes for one person (distance < 0.6)."""
        out = []
        for i, a in enumerate(self.identities):
            for j in range(i + 1, len(self.identities)):
                d = self.identity_distances[i][j]
                if d < SAME_PERSON:
                    out.append((a, self.identities[j], d))
        return out

    def worst(self) -> list[Verdict]:
        """The verdicts, worst first: unreadable files, faces not found, emotions misread (least
        probable intended class first), identities nearer another, the rest."""
        return sorted(self.verdicts, key=_badness)


def summarise(verdicts: list[Verdict]) -> Summary:
    """The summary of ``verdicts``; fills in each verdict's identity distances."""
    summary = Summary(verdicts)
    _emotions(summary)
    _identities(summary)
    return summary


def _emotions(summary: Summary) -> None:
    columns = [*EMOTIONS, NO_FACE]
    summary.confusion = {row: dict.fromkeys(columns, 0) for row in EMOTIONS}
    probabilities = []
    for v in summary.verdicts:
        if v.intended.emotion not in EMOTIONS:
            continue
        summary.scored += 1
        judged = v.judged or NO_FACE
        summary.confusion[v.intended.emotion][judged] += 1
        summary.read += judged == v.intended.emotion
        if v.intended_probability is not None:
            probabilities.append(v.intended_probability)
    summary.mean_intended_probability = float(np.mean(probabilities)) if probabilities else None


def _identities(summary: Summary) -> None:
    described = [v for v in summary.verdicts if v.descriptor is not None]
    groups: dict[str, list[Verdict]] = {}
    for v in described:
        groups.setdefault(v.intended.identity or v.file, []).append(v)
    names = sorted(groups)
    references, kinds = {}, {}
    for name, members in groups.items():
        every = [v.descriptor for v in members if v.descriptor is not None]
        neutral = [v.descriptor for v in members if v.descriptor is not None and v.intended.emotion == "neutral"]
        references[name] = np.mean(neutral if neutral else every, axis=0)
        kinds[name] = "neutral" if neutral else "mean of its files"
    summary.identities = names
    summary.identity_distances = [[float(np.linalg.norm(references[a] - references[b])) for b in names]
                                  for a in names]
    for name, members in groups.items():
        for v in members:
            assert v.descriptor is not None
            v.identity_own = float(np.linalg.norm(v.descriptor - references[name]))
            v.identity_reference = kinds[name]
            others = [(float(np.linalg.norm(v.descriptor - references[o])), o) for o in names if o != name]
            if others:
                v.nearest_other_distance, v.nearest_other = min(others)


def _badness(v: Verdict) -> tuple[int, float, str]:
    if v.status != "ok" and v.emotions is None:
        return (0, 0.0, v.file)
    if v.read_as_intended is False:
        return (1, v.intended_probability or 0.0, v.file)
    if v.identity_own is not None and v.nearest_other_distance is not None and \
            v.nearest_other_distance <= v.identity_own:
        return (2, v.nearest_other_distance - v.identity_own, v.file)
    if v.status != "ok":
        return (3, 0.0, v.file)
    return (4, -(v.intended_probability or 0.0), v.file)
