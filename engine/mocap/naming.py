"""Marker names: file labels → MPEG-4 feature point ids, and the head-fixed reference set (§3.1.1).

The paper's 32 markers were "a subset of MPEG4 points and some additional
locations to capture head motion"; "some of them (9.x, 20.x) are used as
reference points". Sessions name markers by feature point id (``2.1``,
``8.1``…``8.8``, ``9.3`` …, see :data:`engine.model.landmarks.FEATURE_POINTS`) and
the head-fixed points by the ids in :data:`REFERENCE_POINTS`.

A label becomes an id by, in order:

1. the mapping file, lines ``label = id`` (``#`` starts a comment; the label
   is everything before the last ``=``, so labels may hold spaces; an id of
   ``-`` drops the marker), read by :func:`read_mapping` and written by
   :func:`write_mapping`;
2. a label that already spells an id, optionally prefixed: ``8.3``, ``FP8.3``,
   ``fp8_3``, ``FP_8_3``, ``MPEG4_8.3`` all become ``8.3``;
3. otherwise the label is kept as it is.

>>> normalise_label("FP8_3"), normalise_label("08.03"), normalise_label("LeftCheek")
('8.3', '8.3', None)
>>> default_reference(["2.1", "8.3", "9.3", "11.1", "20.1", "20.2"])
['9.3', '11.1', '20.1', '20.2']
>>> default_reference(["2.1", "8.3", "9.1", "9.2", "9.3"])
['9.1', '9.2', '9.3']
"""

from __future__ import annotations

import re
from pathlib import Path

from engine.formats.atomic import atomic_write_text
from engine.formats.text_files import read_bounded_bytes
from engine.mocap.errors import LabelFileError, MocapError
from engine.model.landmarks import landmark_sort_key

DROP = "-"

#: Head-fixed points: they move with the skull, not with the jaw, lips or brows.
RIGID_REFERENCE_POINTS = {
    "9.3": "nose tip",
    "9.6": "left upper edge of the nose bone",
    "9.7": "right upper edge of the nose bone",
    "9.12": "middle lower edge of the nose bone (nose bridge)",
    "9.13": "left lower edge of the nose bone",
    "9.14": "right lower edge of the nose bone",
    "10.1": "top of the left ear",
    "10.2": "top of the right ear",
    "10.3": "back of the left ear",
    "10.4": "back of the right ear",
    "10.5": "bottom of the left ear lobe",
    "10.6": "bottom of the right ear lobe",
    "10.7": "lower contact point between the left ear lobe and the face",
    "10.8": "lower contact point between the right ear lobe and the face",
    "10.9": "upper contact point between the left ear and the face",
    "10.10": "upper contact point between the right ear and the face",
    "11.1": "middle of the border between hair and forehead",
    "11.2": "right end of the border between hair and forehead",
    "11.3": "left end of the border between hair and forehead",
    "11.4": "top of the skull",
    "11.5": "over the left ear",
    "11.6": "over the right ear",
    **{f"20.{k}": "additional head-fixed marker (the paper's 20.x: headband, glasses frame, forehead)"
       for k in range(1, 10)},
}
#: The paper's other 9.x reference points: on the nose wings and below the nose, steady enough to fall back
#: on when fewer than three of the rigid points were captured, though they move a little with the upper lip.
NOSE_REFERENCE_POINTS = {
    "9.1": "left nostril border",
    "9.2": "right nostril border",
    "9.4": "bottom right edge of the nose",
    "9.5": "bottom left edge of the nose",
    "9.15": "bottom middle edge of the nose (subnasale)",
}
REFERENCE_POINTS = {**RIGID_REFERENCE_POINTS, **NOSE_REFERENCE_POINTS}

_ID = re.compile(r"(?:fp|mpeg-?4?|mpeg)?[ _\-.]?0*(\d{1,2})[._]0*(\d{1,2})", re.IGNORECASE)


def normalise_label(label: str) -> str | None:
    """The feature point id a label spells (``FP8_3`` → ``8.3``), or None."""
    m = _ID.fullmatch(label.strip())
    if not m:
        return None
    return f"{int(m.group(1))}.{int(m.group(2))}"


def read_mapping(path: str | Path) -> dict[str, str]:
    """Read a mapping file: ``label = id`` lines; ``-`` as the id drops the marker."""
    path = Path(path)
    try:
        data = read_bounded_bytes(path, error=LabelFileError, what="mapping file")
    except OSError as exc:
        raise LabelFileError(f"cannot read: {exc.strerror or exc}", file=path) from None
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = data.decode("latin-1")
    mapping: dict[str, str] = {}
    targets: dict[str, int] = {}
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        label, sep, target = line.rpartition("=")
        label, target = label.strip().strip('"'), target.strip()
        if not sep or not label or not target:
            raise LabelFileError(f"expected 'label = id', got '{raw.strip()}'", file=path, line=number)
        if label in mapping:
            raise LabelFileError(f"label '{label}' is mapped twice", file=path, line=number)
        if target != DROP:
            if target in targets:
                raise LabelFileError(f"id '{target}' is already given to another label on line {targets[target]}",
                                     file=path, line=number)
            targets[target] = number
        mapping[label] = target
    return mapping


def write_mapping(path: str | Path, mapping: dict[str, str]) -> Path:
    """Write ``{label: id}`` (``-`` drops the marker) as a mapping file, one ``label = id`` a line, atomically.

    What :func:`read_mapping` reads back. A label holding ``#`` (a comment)
    or a line break, or an empty label or id, cannot be written:
    :class:`LabelFileError`.

    >>> import tempfile
    >>> path = write_mapping(f"{tempfile.mkdtemp()}/face.map", {"Lip Corner L": "8.3", "Marker17": "-"})
    >>> read_mapping(path)
    {'Lip Corner L': '8.3', 'Marker17': '-'}
    """
    path = Path(path)
    for label, target in mapping.items():
        for text in (label, target):
            if not text.strip() or "#" in text or "\n" in text or "\r" in text or text != text.strip():
                raise LabelFileError(f"cannot write the mapping '{label} = {target}': labels and ids must be "
                                     "non-empty, without '#', line breaks or spaces at either end", file=path)
        if "=" in target:
            raise LabelFileError(f"cannot write the mapping '{label} = {target}': an id holds no '='", file=path)
    width = max((len(label) for label in mapping), default=0)
    lines = ["# marker label = MPEG-4 feature point id ('-' drops the marker)"]
    lines += [f"{label:<{width}} = {target}" for label, target in mapping.items()]
    atomic_write_text(path, "\n".join(lines) + "\n", LabelFileError)
    return path


def marker_names(labels: list[str], mapping: dict[str, str] | None = None) -> tuple[list[str | None], dict]:
    """The session name of every file label (None: dropped), and what was renamed and dropped.

    >>> marker_names(["LM", "FP2_1", "Cheek"], {"LM": "8.3"})[0]
    ['8.3', '2.1', 'Cheek']
    """
    mapping = mapping or {}
    names: list[str | None] = []
    renamed, dropped = {}, []
    for label in labels:
        if label in mapping:
            name = None if mapping[label] == DROP else mapping[label]
        else:
            name = normalise_label(label) or label
        if name is None:
            dropped.append(label)
        elif name != label:
            renamed[label] = name
        names.append(name)
    taken: dict[str, str] = {}
    for label, name in zip(labels, names, strict=True):
        if name is None:
            continue
        if name in taken:
            raise MocapError(f"markers '{taken[name]}' and '{label}' would both be named '{name}' "
                             "(fix the mapping file)")
        taken[name] = label
    unused = sorted(set(mapping) - set(labels))
    return names, {"renamed": renamed, "dropped": dropped, "unused_mapping": unused}


def default_reference(markers: list[str]) -> list[str]:
    """The head-fixed markers to align on: the rigid points present, or with the nose points if under three."""
    rigid = [m for m in markers if m in RIGID_REFERENCE_POINTS]
    if len(rigid) >= 3:
        return sorted(rigid, key=landmark_sort_key)
    return sorted([m for m in markers if m in REFERENCE_POINTS], key=landmark_sort_key)
