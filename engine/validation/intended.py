"""What each file was meant to show: from a stimulus set's manifest, or a table the user gives.

A stimulus set's ``manifest.csv`` says it for every stimulus we made: the ``expression`` at its
``intensity`` (an ``expression_b`` continuum by ``morph``), the person (``model``, ``identity``,
``identity_b``, ``identity_morph``). For files we did not make (a lab's recordings of actors),
``--intended CSV`` says it: a header with ``file`` and any of ``emotion``, ``identity`` and
``landmarks`` (the engine's landmarks table for a video, ``say --landmarks``)::

    file,emotion,identity
    actor1-happy.jpg,happy,actor1
    actor1-neutral.jpg,neutral,actor1

An emotion is one of the classifier's seven classes (:data:`EMOTIONS`) or a library expression
(``Happy``, ``Anger`` …); ``Contempt`` and blends have no class and are not scored.

>>> intended_emotion("Happy", 100), intended_emotion("Sad", 0), intended_emotion("Contempt", 100)
('happy', 'neutral', None)
>>> intended_emotion("Fear", 100, expression_b="Surprise", morph=70)
'surprise'
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from engine.errors import UserError
from engine.formats.csv_tables import read_table
from engine.validation.observers import EMOTIONS

EXPRESSION_CLASSES = {
    "happy": "happy", "happiness": "happy", "joy": "happy",
    "sad": "sad", "sadness": "sad",
    "surprise": "surprise", "surprised": "surprise",
    "fear": "fear", "afraid": "fear", "fearful": "fear",
    "anger": "angry", "angry": "angry",
    "disgust": "disgust", "disgusted": "disgust",
    "neutral": "neutral", "none": "neutral", "": "neutral",
}
"""Expression names (any case) → the classifier's class. Names not here (Contempt, HappySurprise,
a user's own command) have no class."""
IDENTITY_COLUMNS = ("model", "identity", "identity_b", "identity_morph")
VIDEO_KINDS = ("mp4", "silent-mp4")


@dataclass(frozen=True)
class Intended:
    """What one file was meant to show. ``emotion`` None: not scored; ``identity`` "": not grouped."""

    emotion: str | None = None
    expression: str = ""
    identity: str = ""
    stimulus: str = ""
    landmarks: Path | None = None
    tracks: Path | None = None


@dataclass(frozen=True)
class SetFile:
    """One file of a stimulus set to judge, with what it was meant to show."""

    path: Path
    kind: str
    intended: Intended


def intended_emotion(expression: str, intensity: float = 100.0, expression_b: str = "",
                     morph: float = 0.0) -> str | None:
    """The class an expression at an intensity (a continuum ``morph`` % toward ``expression_b``) means."""
    if intensity <= 0:
        return "neutral"
    if expression_b:
        if morph == 50:
            return None
        expression = expression_b if morph > 50 else expression
    return EXPRESSION_CLASSES.get(expression.strip().lower())


def read_intended(path: str | Path) -> dict[Path, Intended]:
    """The ``--intended`` table: resolved file path → what it was meant to show."""
    path = Path(path)
    header, rows = read_table(path, what="intended table")
    if "file" not in header or not {"emotion", "identity", "landmarks"} & set(header):
        raise UserError("the intended table needs a 'file' column and one of 'emotion', 'identity', 'landmarks'",
                        file=path, line=1)
    out: dict[Path, Intended] = {}
    for line, row in rows:
        name = (row.get("file") or "").strip()
        if not name:
            raise UserError("a row with no file", file=path, line=line)
        emotion_text = (row.get("emotion") or "").strip()
        emotion: str | None = None
        if emotion_text:
            emotion = emotion_text.lower() if emotion_text.lower() in EMOTIONS else intended_emotion(emotion_text)
            if emotion is None and emotion_text.lower() not in ("contempt", "other"):
                raise UserError(f"'{emotion_text}' is no emotion: use one of {', '.join(EMOTIONS)} "
                                "or a library expression (Happy, Anger …)", file=path, line=line)
        landmarks = (row.get("landmarks") or "").strip()
        out[_named_file(path, name, line)] = Intended(
            emotion=emotion, expression=emotion_text, identity=(row.get("identity") or "").strip(),
            landmarks=_named_file(path, landmarks, line) if landmarks else None)
    return out


def _named_file(table: Path, name: str, line: int) -> Path:
    """A file the table names, relative to the table's folder (a NUL byte or an unusable name refused)."""
    try:
        return (table.parent / name).resolve()
    except (ValueError, OSError) as exc:
        raise UserError(f"'{name[:60]}' is no usable file name ({exc})", file=table, line=line) from None


def read_set(folder: str | Path) -> list[SetFile]:
    """The stills and videos of the stimulus set in ``folder`` (its ``manifest.csv``), each with
    what it was meant to show. One video a stimulus is judged (``mp4`` before ``silent-mp4``)."""
    folder = Path(folder)
    manifest = folder / "manifest.csv"
    header, rows = read_table(manifest, what="stimulus manifest")
    if "id" not in header:
        raise UserError("not a stimulus manifest: it has no 'id' column", file=manifest, line=1)
    files: list[SetFile] = []
    for line, row in rows:
        intended = stimulus_intended(row, folder, manifest, line)
        if row.get("file_png"):
            files.append(SetFile(folder / row["file_png"], "png", intended))
        video = next((kind for kind in VIDEO_KINDS if row.get(f"file_{kind}")), None)
        if video is not None:
            files.append(SetFile(folder / row[f"file_{video}"], video, intended))
    if not files:
        raise UserError("the set holds no stills (png) or videos (mp4, silent-mp4) to judge", file=manifest)
    return files


def stimulus_intended(row: Mapping[str, str], folder: Path | None = None, manifest: Path | None = None,
                      line: int | None = None) -> Intended:
    """What a stimulus was meant to show, from its levels as the manifest writes them (every cell text)."""
    expression = (row.get("expression") or "").strip()
    expression_b = (row.get("expression_b") or "").strip()
    try:
        intensity = float(row.get("intensity") or 100)
        morph = float(row.get("morph") or 0)
    except ValueError:
        raise UserError("intensity and morph must be numbers", file=manifest, line=line) from None
    identity = "; ".join(f"{name}={row[name]}" for name in IDENTITY_COLUMNS if (row.get(name) or "").strip())
    label = expression or "none"
    if expression_b:
        label = f"{expression}→{expression_b} {morph:g} %"
    elif intensity != 100:
        label = f"{label} {intensity:g} %"
    tracks = folder / row["file_tracks"] if folder is not None and row.get("file_tracks") else None
    landmarks = folder / row["file_landmarks"] if folder is not None and row.get("file_landmarks") else None
    return Intended(emotion=intended_emotion(expression, intensity, expression_b, morph), expression=label,
                    identity=identity or "default head", stimulus=row.get("id", ""), landmarks=landmarks,
                    tracks=tracks)
