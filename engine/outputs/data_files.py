"""The files beside a video, one writer per kind: what ``say``, the workbench's Export speech… and a
stimulus of a design (``stimuli``) all write, written the same way by each.

A video is drawn by :mod:`engine.outputs.video_writer`; every other kind is written here from one
:class:`FrameData`: the parameters' values at the video's frames (so the tracks and the landmarks show
the very samples the video shows), the utterance as the files show it (its phones, its sound) and,
where asked for, the low-level commands.

>>> import numpy as np
>>> from engine.speech.synthesis import Segment, Utterance
>>> spoken = Utterance("Moi.", "test", np.zeros(160, np.float32), 16000, [Segment("m", 0.0, 10.0, "moi")], [])
>>> data = FrameData(["jaw"], np.array([0.0, 33.333]), np.array([[0.0], [0.5]]), spoken)
>>> print(data_file_text("tracks", data), end="")
time_ms,jaw
0,0
33.333,0.5
>>> sorted(DATA_FILE_KINDS)
['landmarks', 'phones', 'tracks', 'wav', 'xml']
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from engine.commands.command_files import format_number, low_level_xml
from engine.model.landmarks import landmark_sort_key
from engine.model.vertex_subset import model_at_landmarks
from engine.speech.synthesis import Utterance, phones_csv, read_wav_bytes, wav_bytes
from engine.timeline.tracks import tracks_csv_text

if TYPE_CHECKING:
    from engine.commands.command_files import Activation
    from engine.model.model import Model

__all__ = ["DATA_FILE_KINDS", "FrameData", "data_file_bytes", "data_file_text", "landmarks_csv",
           "write_data_file"]


@dataclass(frozen=True)
class FrameData:
    """What the files beside a video show.

    ``values`` (frames × ``parameters``, in the model's tree order) at ``times`` (ms), as
    :meth:`engine.timeline.Timeline.sample` gives them; ``utterance`` with its phones and its samples
    as the files hold them (a stimulus shifts the phones and pads and mixes the sound first); ``model``
    for the landmarks and ``activations`` for the low-level commands, when those are written.
    """

    parameters: Sequence[str]
    times: np.ndarray
    values: np.ndarray
    utterance: Utterance
    model: Model | None = None
    activations: Sequence[Activation] | None = None


def _wav(data: FrameData) -> bytes:
    """The sound as 16-bit PCM; a recorded utterance's own WAV file byte for byte."""
    spoken = data.utterance
    if spoken.source_wav is not None:
        return read_wav_bytes(spoken.source_wav, "recording")
    return wav_bytes(spoken.samples, spoken.sample_rate)


def _xml(data: FrameData) -> str:
    if data.activations is None:
        raise ValueError("the low-level commands need the activations")
    return low_level_xml(list(data.activations))


def _landmarks(data: FrameData) -> str:
    if data.model is None:
        raise ValueError("the landmarks need the model")
    return landmarks_csv(data.model, data.times, data.values)


#: Every kind written here → how its contents are made (text kinds are UTF-8).
_WRITERS: dict[str, Callable[[FrameData], bytes | str]] = {
    "wav": _wav,
    "xml": _xml,
    "phones": lambda data: phones_csv(data.utterance),
    "tracks": lambda data: tracks_csv_text(data.parameters, data.times, data.values),
    "landmarks": _landmarks,
}
DATA_FILE_KINDS = frozenset(_WRITERS)


def data_file_bytes(kind: str, data: FrameData) -> bytes:
    """The contents of the ``kind`` file (one of :data:`DATA_FILE_KINDS`) for ``data``."""
    contents = _WRITERS[kind](data)
    return contents.encode("utf-8") if isinstance(contents, str) else contents


def data_file_text(kind: str, data: FrameData) -> str:
    """A text kind's contents (everything but ``wav``)."""
    if kind == "wav":
        raise ValueError("a WAV file is not text")
    return data_file_bytes(kind, data).decode("utf-8")


def write_data_file(kind: str, destination: str | Path, data: FrameData) -> None:
    """Write the ``kind`` file for ``data`` to ``destination`` as it is (the callers' temporary file of
    :func:`engine.formats.atomic.atomic_files`, which makes the set of files atomic)."""
    Path(destination).write_bytes(data_file_bytes(kind, data))


def landmarks_csv(model: Model, times: np.ndarray, values: np.ndarray) -> str:
    """The landmarks table: ``frame,time_ms,<id>_x,<id>_y,<id>_z,…`` (mm), one row per frame.

    ``values`` (frames × parameters, in the model's tree order) at ``times``
    (ms), as :meth:`engine.timeline.Timeline.sample` gives them.

    >>> from engine import load_model
    >>> head = load_model()
    >>> table = landmarks_csv(head, np.array([0.0]), head.values_array()[None])
    >>> table.splitlines()[0].split(",")[:5]
    ['frame', 'time_ms', '2.1_x', '2.1_y', '2.1_z']
    """
    times, values = np.asarray(times, dtype=float), np.asarray(values, dtype=float)
    if values.shape != (len(times), len(model.parameters)):
        raise ValueError(f"expected {len(times)} frames × {len(model.parameters)} parameters of values, "
                         f"got shape {values.shape}")
    ids = sorted(model.landmarks, key=landmark_sort_key)
    header = ["frame", "time_ms"] + [f"{i}_{axis}" for i in ids for axis in "xyz"]
    lines = [",".join(header)]
    # the landmarks' own vertices, moved as the whole mesh would move them (the same numbers): the mesh
    # itself is deformed once per frame, by the video that shows it, not again for this table
    deformer = model_at_landmarks(model, ids).deformer()
    for n, (t, row) in enumerate(zip(times, values, strict=True)):
        points = deformer.deform(row)
        lines.append(",".join([str(n), format_number(t)] + [format_number(c) for c in points.ravel()]))
    return "\n".join(lines) + "\n"
