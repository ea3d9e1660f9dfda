"""One stimulus of a design: speech, an expression overlay, the offset and the noise, into its files.

:func:`make_stimulus` is what a worker runs (a local process or a Dask worker);
it reads nothing but the design's levels and the files they name, and writes
the stimulus's files and then its record (``.records/ID.json``) atomically, so
a record on disk means every file it names is complete (``--resume`` trusts
a record only after checking the files' SHA-256).

>>> from engine.stimuli.design import parse_design
>>> design = parse_design('[factors]\\ntext = ["Moi."]\\n[output]\\nkinds = ["wav"]\\n', "d.toml")
>>> record = make_stimulus(design, design.stimuli[0], out)                         # doctest: +SKIP
>>> record["files"]["wav"]["name"], record["speech_onset_ms"]                       # doctest: +SKIP
('0001.wav', 30.0)
"""

from __future__ import annotations

import functools
import hashlib
import json
import math
from concurrent.futures import ThreadPoolExecutor
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from engine.commands import Library, load_library, translate
from engine.commands.command_files import HighLevelCommand
from engine.formats.atomic import atomic_files, atomic_write_text
from engine.model.model import Model
from engine.outputs.data_files import FrameData, write_data_file
from engine.outputs.png_file import write_png
from engine.outputs.video_tools import copy_without_audio
from engine.outputs.video_writer import check_video, encode_video
from engine.speech.say import Speech, speak
from engine.speech.synthesis import Utterance
from engine.stimuli.audio import (
    add_noise,
    clip_layout,
    measured_offset_ms,
    measured_snr_db,
    placed_audio,
    speech_mask,
)
from engine.stimuli.design import Design, DesignError, Stimulus
from engine.stimuli.heads import stimulus_head
from engine.timeline.timeline import Timeline

RECORDS = ".records"
PAUSES = frozenset({"#", "##", "pau", "h#", "brth", "_", "sil", "sp"})
EXPRESSION_ONSET_MS = 400.0
EXPRESSION_OFFSET_MS = 700.0
FILE_NAMES = {"mp4": "{id}.mp4", "silent-mp4": "{id}-silent.mp4", "wav": "{id}.wav", "png": "{id}.png",
              "phones": "{id}-phones.csv", "tracks": "{id}-tracks.csv"}


def make_stimulus(design: Design, stimulus: Stimulus, outdir: str | Path) -> dict[str, Any]:
    """Make every file of ``stimulus`` in ``outdir`` and return (and write) its record."""
    outdir = Path(outdir)
    levels = stimulus.levels
    model = stimulus_head(design, levels)
    name = f"{design.path.name}: stimulus {stimulus.id}"
    table_of = None
    if "viseme" in levels:              # a viseme continuum: one phone articulated part of the way to another
        from engine.speech.articulation import ArticulationTable, table_for

        def table_of(utterance: Utterance) -> ArticulationTable:
            return table_for(utterance).with_blended_row(str(levels["viseme"]), str(levels["viseme_b"]),
                                                         float(levels["viseme_morph"]) / 100.0)
    if "audio" in levels:               # a recorded voice: its audio unchanged, the face from its labels
        from engine.speech.recorded import speak_recording

        speech = speak_recording(design.extra_files[levels["audio"]], design.extra_files[levels["labels"]], model,
                                 text=levels.get("text"), library=_library(), name=name, table_of=table_of)
    else:                               # either way the animation is built once, with the continuum's table if any
        speech = speak(str(levels.get("text", "")), model, voice=levels.get("voice"), library=_library(),
                       name=name, table_of=table_of)
    timeline, apex_ms = _with_expression(speech, model, levels)
    utterance, alignment = speech.utterance, 0.0
    if "audio_text" in levels:          # incongruent (McGurk): heard one utterance, seen another
        heard = speak(str(levels["audio_text"]), model, voice=levels.get("voice"), library=_library(),
                      name=f"{design.path.name}: stimulus {stimulus.id} (audio_text)")
        phone = levels.get("align_phone")
        where = f"{design.path.name}: stimulus {stimulus.id}"
        alignment = _onset(speech.utterance, phone, where) - _onset(heard.utterance, phone, where)
        utterance = heard.utterance
    offset = float(levels.get("av_offset_ms", 0.0)) + alignment
    video_ms = max(speech.end_ms, timeline.end)
    layout = clip_layout(utterance.duration_ms, video_ms, offset)
    rate = utterance.sample_rate
    clean = placed_audio(utterance.samples, rate, layout.audio_start_ms, layout.length_ms)
    mask = speech_mask(_shifted(utterance.phones, layout.audio_start_ms), rate, len(clean), PAUSES)
    audio, snr, gain = clean, None, 1.0
    if "snr_db" in levels:
        noise = levels.get("noise", "white")
        noise_source = design.extra_files.get(noise, noise) if isinstance(noise, str) else "white"
        audio, gain = add_noise(clean, rate, float(levels["snr_db"]), noise_source, mask,
                                seed=design.seed * 100_003 + int(stimulus.id))
        snr = measured_snr_db(clean, audio, mask, gain)
    fps = design.output.fps
    count = max(1, math.ceil(layout.length_ms * fps / 1000.0 - 1e-9))
    frame_times = np.arange(count) * (1000.0 / fps)
    values = timeline.sample(frame_times - layout.video_start_ms)
    names = {kind: FILE_NAMES[kind].format(id=stimulus.id) for kind in design.output.kinds}
    paths = {kind: outdir / name for kind, name in names.items()}
    # one video drawn: with both kinds, the silent one is the sound one's video stream copied (same frames)
    drawn = "mp4" if "mp4" in paths else "silent-mp4" if "silent-mp4" in paths else None
    requests = {} if drawn is None else {drawn: check_video(
        paths[drawn], model, frame_times, values, timeline.parameters, fps,
        audio=audio if drawn == "mp4" else None, sample_rate=rate if drawn == "mp4" else None,
        size=design.output.size, view=design.output.view, look=design.output.look, encoding=design.output.encoding)}
    words = [w.start_ms + layout.audio_start_ms for w in utterance.words]
    onset = next((p.start_ms for p in utterance.phones if p.label not in PAUSES), 0.0) + layout.audio_start_ms
    still_ms = design.output.still_ms
    if still_ms is None:
        still_ms = (apex_ms + layout.video_start_ms) if apex_ms is not None else layout.video_start_ms + \
            0.5 * (speech.duration_ms)
    # the still is the video's frame when that frame shows the very same values, drawn the same way
    still_frame = min(count - 1, max(0, round(still_ms * fps / 1000.0)))
    kept: dict[int, np.ndarray] = {}
    reuse = ("png" in paths and drawn is not None and requests[drawn].antialias(None)
             and np.array_equal(values[still_frame], timeline.sample([still_ms - layout.video_start_ms])[0]))

    def keep_still(n: int, image: np.ndarray) -> None:
        if n == still_frame:
            kept[n] = np.array(image)

    # the files beside the video show its sound (placed, padded, with its noise) and the phones where they are heard
    files_sound = replace(utterance, samples=audio, sample_rate=rate, source_wav=None,
                          phones=_shifted(utterance.phones, layout.audio_start_ms))
    data = FrameData(timeline.parameters, frame_times, values, files_sound, model)
    # the motion check's face motion, from the very positions the video is drawn from
    motion = MotionMeter(count) if drawn is not None and count >= 25 else None
    with atomic_files(paths.values()) as temporary:
        for kind, path in sorted(paths.items(), key=lambda item: item[0] in ("silent-mp4", "png")):   # after the mp4
            destination = temporary[path]
            if kind in requests:
                encode_video(requests[kind], destination, on_frame=keep_still if reuse else None,
                             on_positions=motion)
            elif kind == "silent-mp4":                   # the mp4, written just before, without its sound
                copy_without_audio(temporary[paths["mp4"]], destination, path)
            elif kind == "png" and still_frame in kept:
                write_png(destination, kept[still_frame])
            elif kind == "png":
                _still(model, timeline, still_ms - layout.video_start_ms, design, destination)
            else:                                        # wav, phones, tracks: as say writes them
                write_data_file(kind, destination, data)
    # the audio's check decodes the file's sound while the video's decodes its frames: both at once
    with ThreadPoolExecutor(max_workers=1, thread_name_prefix="audio-check") as pool:
        audio_check = pool.submit(_check, paths, utterance.samples * gain, clean, mask, rate,
                                  layout.audio_start_ms, float(levels["snr_db"]) if "snr_db" in levels else None,
                                  gain)
        frames = _decoded_frames(paths, count)
        video_check = (_check_video(paths, motion.motion, fps, layout.video_start_ms,
                                    frames) if motion is not None else {})   # no video to check: no motion
        check = audio_check.result()
    check.update(video_check)
    if check.get("video_ok") is False:
        check["ok"] = False
        check["problem"] = "; ".join(filter(None, [check.get("problem", ""), "the video's frames move "
                                                   f"{check['measured_video_lag_frames']} frames off its face"]))
    verdicts = None
    if design.output.validate:
        from engine.stimuli.judging import judge_stimulus

        verdicts = judge_stimulus(stimulus.id, levels, paths, model, frame_times, values, fps, frames)
    records = outdir / RECORDS
    records.mkdir(exist_ok=True)
    thumbnail = records / f"{stimulus.id}.thumb.npy"
    if frames is not None:
        _thumbnail_of_frame(frames[min(len(frames) - 1, max(0, round(still_ms * fps / 1000.0)))], thumbnail)
    else:
        _thumbnail(model, timeline, still_ms - layout.video_start_ms, design, thumbnail)
    record = {
        "id": stimulus.id,
        "levels": levels,
        "files": {kind: {"name": names[kind], "sha256": sha256_of(paths[kind])} for kind in names},
        "duration_ms": layout.length_ms,
        "audio_start_ms": layout.audio_start_ms,
        "video_start_ms": layout.video_start_ms,
        "av_offset_ms": offset - alignment,
        "alignment_ms": alignment,
        "snr_db": snr,
        "speech_onset_ms": onset,
        "word_onsets_ms": words,
        "words": [w.label for w in utterance.words],
        "expression_apex_ms": None if apex_ms is None else apex_ms + layout.video_start_ms,
        "still_ms": still_ms if "png" in names else None,
        "voice": utterance.voice,
        "warnings": speech.warnings,
        "snr_spec_db": levels.get("snr_db"),
        "check": check,
    }
    if verdicts is not None:
        record["validation"] = verdicts
    atomic_write_text(records / f"{stimulus.id}.json", json.dumps(record, indent=1, ensure_ascii=False))
    return record


OFFSET_TOLERANCE_SAMPLES = 1
SNR_TOLERANCE_DB = {"wav": 0.1, "mp4": 1.5}


def _check(paths: dict[str, Path], speech: np.ndarray, clean: np.ndarray, mask: np.ndarray, rate: int,
           audio_start_ms: float, snr_db: float | None, gain: float) -> dict[str, Any]:
    """Measure the written file's audio: where the speech starts in it (cross-correlation with the speech
    alone) and its SNR; compare both with the design."""
    source = "wav" if "wav" in paths else "mp4" if "mp4" in paths else None
    if source is None:
        return {"ok": True, "measured_from": ""}
    if source == "wav":
        from engine.speech.synthesis import read_wav

        written, _ = read_wav(paths["wav"])
    else:
        from engine.outputs.video_probe import read_audio

        written, _ = read_audio(paths["mp4"], rate)
    written = np.asarray(written[:len(clean)], dtype=np.float64)
    if len(written) < len(clean):
        written = np.pad(written, (0, len(clean) - len(written)))
    start = measured_offset_ms(speech, written, rate, search_ms=abs(audio_start_ms) + 200.0)
    problems = []
    if abs(start - audio_start_ms) > OFFSET_TOLERANCE_SAMPLES * 1000.0 / rate + 1e-9:
        problems.append(f"the speech starts at {start:.3f} ms in the {source}, not {audio_start_ms:.3f} ms")
    measured = measured_snr_db(clean, written, mask, gain) if snr_db is not None else None
    if measured is not None and snr_db is not None and abs(measured - snr_db) > SNR_TOLERANCE_DB[source]:
        problems.append(f"the SNR in the {source} is {measured:.2f} dB, not {snr_db:g} dB")
    return {"ok": not problems, "measured_from": source, "measured_audio_start_ms": start,
            "measured_snr_db": measured, "problem": "; ".join(problems)}


def vertex_motion(model: Model, values: np.ndarray) -> np.ndarray:
    """How far the face moves into each frame (``values``: frames × the model's parameters, in tree order):
    the mean distance its vertices travel from the frame before (mm; 0 for the first frame). What a camera
    sees move, unlike a parameter's value (the tongue behind closed lips moves no pixel)."""
    deformer = model.deformer()
    meter = MotionMeter(len(values))
    for n, row in enumerate(values):
        meter(n, deformer.deform(row))
    return meter.motion


class MotionMeter:
    """:func:`vertex_motion` gathered frame by frame from positions already deformed (the video's own:
    :func:`~engine.outputs.video_writer.encode_video`'s ``on_positions``), so no frame is deformed again."""

    def __init__(self, frames: int) -> None:
        self.motion = np.zeros(frames)
        self.seen = 0
        self._previous: np.ndarray | None = None

    def __call__(self, n: int, positions: np.ndarray) -> None:
        if n != self.seen:
            raise ValueError(f"frame {n} came after frame {self.seen - 1}: the frames must come in order")
        if self._previous is not None:
            self.motion[n] = float(np.linalg.norm(positions - self._previous, axis=1).mean())
        self._previous = positions
        self.seen += 1


def _decoded_frames(paths: dict[str, Path], count: int) -> np.ndarray | None:
    """The frames of the video just written, as its file holds them (None: no video, or too short to check)."""
    kind = "mp4" if "mp4" in paths else "silent-mp4" if "silent-mp4" in paths else None
    if kind is None or count < 25:
        return None
    from engine.outputs.video_probe import read_frames

    return read_frames(paths[kind])


def _check_video(paths: dict[str, Path], motion: np.ndarray, fps: float, video_start_ms: float,
                 frames: np.ndarray | None = None) -> dict[str, Any]:
    """Measure the written video: where its frames move against where the face moves.

    The motion of the frames (mean absolute change of the pixels from one frame to the next) is
    cross-correlated with the motion of the face (``motion``: how far its vertices travel into each
    frame); they must coincide to the frame, so the face starts where the clip says
    (``video_start_ms``) in the file as written. Clips shorter than 25 frames are too short to tell.
    """
    kind = "mp4" if "mp4" in paths else "silent-mp4" if "silent-mp4" in paths else None
    if kind is None or len(motion) < 25:
        return {}
    from engine.outputs.video_probe import read_frames

    if frames is None:
        frames = read_frames(paths[kind])
    # every other row and column is enough to see where the picture moves, at a quarter of the cost
    sampled = frames[:, ::2, ::2].astype(np.int16)
    moving_pixels = np.abs(sampled[1:] - sampled[:-1]).mean(axis=(1, 2, 3))
    moving_values = motion[1:]
    count = min(len(moving_pixels), len(moving_values))
    if count < 3 or not moving_values[:count].any() or not moving_pixels[:count].any():
        return {"measured_video_lag_frames": None}
    a = (moving_pixels[:count] - moving_pixels[:count].mean()) / (moving_pixels[:count].std() or 1.0)
    b = (moving_values[:count] - moving_values[:count].mean()) / (moving_values[:count].std() or 1.0)
    reach = min(count - 1, round((video_start_ms + 500.0) * fps / 1000.0))
    lags = list(range(-reach, reach + 1))
    scores = [float(np.dot(a[max(0, k):count + min(0, k)], b[max(0, -k):count - max(0, k)])) for k in lags]
    lag = lags[int(np.argmax(scores))]
    return {"measured_video_lag_frames": lag, "video_ok": lag == 0}


THUMBNAIL_WIDTH = 128


def _thumbnail(model: Model, timeline: Timeline, at_ms: float, design: Design, path: Path) -> None:
    """A small picture of the stimulus at its still's time, for the set's contact sheet."""
    from engine.outputs.render import FrameRenderer

    width, height = design.output.size
    size = (THUMBNAIL_WIDTH, max(2, round(THUMBNAIL_WIDTH * height / width / 2) * 2))
    with FrameRenderer(model, size=size, view=design.output.view, look=design.output.look) as renderer:
        image = renderer.render(model.deform(timeline.values_at(at_ms)))
    with path.open("wb") as stream:
        np.save(stream, np.ascontiguousarray(image, dtype=np.uint8), allow_pickle=False)


def _thumbnail_of_frame(frame: np.ndarray, path: Path) -> None:
    """The thumbnail of a stimulus with a video: its frame at the still's time, as the file shows it, made
    small (no second drawing of the face)."""
    from PIL import Image

    height, width = frame.shape[:2]
    size = (THUMBNAIL_WIDTH, max(2, round(THUMBNAIL_WIDTH * height / width / 2) * 2))
    image = np.asarray(Image.fromarray(np.ascontiguousarray(frame[..., :3])).resize(size, Image.Resampling.BOX))
    with path.open("wb") as stream:
        np.save(stream, np.ascontiguousarray(image, dtype=np.uint8), allow_pickle=False)


def sha256_of(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as stream:
        for block in iter(lambda: stream.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _with_expression(speech: Speech, model: Model, levels: dict[str, Any]) -> tuple[Timeline, float | None]:
    """The speech's timeline with the expression held over it at ``intensity`` %; and when it is at full."""
    intensity = float(levels.get("intensity", 100.0))
    morph = float(levels.get("morph", 0.0)) / 100.0                  # 0: all expression, 1: all expression_b
    weights = [(levels.get("expression"), intensity * (1.0 - morph)), (levels.get("expression_b"), intensity * morph)]
    hold = max(0.0, speech.end_ms - EXPRESSION_ONSET_MS)
    commands = [HighLevelCommand(str(name), {"at": 0.0, "amplitude": amplitude, "onset": EXPRESSION_ONSET_MS,
                                             "apex": hold, "offset": EXPRESSION_OFFSET_MS}, file="design", line=None)
                for name, amplitude in weights
                if name is not None and str(name).lower() not in ("none", "neutral") and amplitude > 0]
    if not commands:
        return speech.timeline, None
    activations = speech.activations + translate(commands, _library(), model)
    return Timeline(activations, model), EXPRESSION_ONSET_MS


def _onset(utterance: Utterance, phone: str | None, where: str) -> float:
    """Where ``phone`` (its first occurrence; a long form counts) or, with no phone given, the first vowel
    begins in ``utterance``."""
    for segment in utterance.phones:
        label = segment.label
        if phone is None:
            features = utterance.phone_features.get(label)
            if features is not None and features.is_vowel:
                return segment.start_ms
        elif label == phone or label.rstrip(":") == phone:
            return segment.start_ms
    raise DesignError(f"{where}: '{utterance.text}' has no {'vowel' if phone is None else repr(phone)} to "
                      "align the audio and the video at (align_phone)")


def _shifted(phones: list, by_ms: float) -> list:
    return [replace(p, start_ms=p.start_ms + by_ms, end_ms=p.end_ms + by_ms) for p in phones] if by_ms else phones


def _still(model: Model, timeline: Timeline, at_ms: float, design: Design, destination: Path) -> None:
    from engine.outputs.render import FrameRenderer

    values = timeline.values_at(at_ms)
    with FrameRenderer(model, size=design.output.size, view=design.output.view, look=design.output.look) as renderer:
        image = renderer.render(model.deform(values))
    write_png(destination, image)


@functools.lru_cache(maxsize=1)
def _library() -> Library:
    return load_library()
