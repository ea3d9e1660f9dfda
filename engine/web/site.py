"""A web site that plays the head: ``index.html``, the player, three.js, the model, the animation, the audio.

The folder works offline from any static web server (nothing is fetched from elsewhere):

=====================  ==================================================================
``index.html``         the page: the head fills the window, framed as ``render`` frames it
``player.js``          the player and three.js |three| in one ES module (:mod:`.player_bundle`;
                       its API is ``window.ArtificialPerson``): the page needs no import map
``three-LICENSE.txt``  three.js's MIT licence, beside the bundle
``head.glb``           the model: skeleton + the morph targets the animation uses (:mod:`.web_model`)
``animation.json``     frame table, phones, words, camera, lights (:mod:`.animation`)
``speech.wav``         the audio (16-bit PCM, as ``say -o x.wav`` writes it)
=====================  ==================================================================

>>> from engine import load_model
>>> from engine.speech.say import speak
>>> head = load_model()                                                     # doctest: +SKIP
>>> speech = speak("Pappa osti omenoita.", head)                            # doctest: +SKIP
>>> write_speech_site(speech, head, "site")                                 # doctest: +SKIP
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from engine.errors import UserError
from engine.formats.atomic import atomic_files, finish_interrupted_writes
from engine.outputs.camera import VIEW_ANGLE, VIEWS, camera_pose, framed_points
from engine.outputs.gltf_skeleton import skeleton_parameters
from engine.outputs.look_shader import web_shading_source
from engine.outputs.looks import Look, look_from
from engine.speech.synthesis import Segment
from engine.web.animation import animation_document
from engine.web.player_bundle import SHADER_MARK, bundle_text, licence_text
from engine.web.web_camera import web_framing
from engine.web.web_look import look_document
from engine.web.web_model import morph_parameters, web_glb

if TYPE_CHECKING:
    from engine.model import Model
    from engine.speech.say import Speech

__all__ = ["DEFAULT_FPS", "DEFAULT_SIZE", "MARKER", "SITE_FILES", "project", "site_camera", "words_of", "write_site",
           "write_speech_site", "write_tracks_site"]

DEFAULT_FPS = 60.0
DEFAULT_SIZE = (600, 800)
MARKER = "artificial-person-web-site"
THREE_VERSION = "0.170.0"
#: The files a site of one utterance holds.
SITE_FILES = ("index.html", "player.js", "three-LICENSE.txt", "head.glb", "animation.json", "speech.wav")


def site_camera(model: Model, size: tuple[int, int] = DEFAULT_SIZE, view: str = "front") -> dict[str, Any]:
    """The camera of ``render --view VIEW --size WxH`` (rest-pose framing), in metres, as the player takes it,
    with the ``framing`` (:mod:`engine.web.web_camera`) by which the player frames the head so at the size of
    its canvas, whatever that is.

    >>> from engine import load_model
    >>> camera = site_camera(load_model())
    >>> camera["fov_degrees"], camera["width"], camera["height"], camera["up"]
    (20.0, 600, 800, [0.0, 1.0, 0.0])
    """
    width, height = size
    focal, position, up, (near, far) = camera_pose(framed_points(model), VIEWS[view], width, height)
    return {"view": view, "fov_degrees": VIEW_ANGLE, "width": width, "height": height,
            "position": [round(float(c) / 1000.0, 7) for c in position],
            "target": [round(float(c) / 1000.0, 7) for c in focal],
            "up": [float(c) for c in up], "near": near / 1000.0, "far": far / 1000.0,
            "framing": web_framing(model, view)}


def project(camera: dict[str, Any], points_mm: np.ndarray) -> np.ndarray:
    """Pixel positions (x right, y down, from the picture's top-left corner) of points (mm) seen by ``camera``.

    >>> from engine import load_model
    >>> head = load_model()
    >>> camera = site_camera(head)
    >>> project(camera, np.array(camera["target"])[None] * 1000).round(3).tolist()
    [[300.0, 400.0]]
    """
    position, target = np.array(camera["position"]) * 1000, np.array(camera["target"]) * 1000
    back = position - target
    back /= np.linalg.norm(back)
    right = np.cross(camera["up"], back)
    right /= np.linalg.norm(right)
    up = np.cross(back, right)
    relative = np.asarray(points_mm, dtype=float) - position
    depth = -(relative @ back)
    focal_px = camera["height"] / 2 / np.tan(np.radians(camera["fov_degrees"]) / 2)
    x = camera["width"] / 2 + focal_px * (relative @ right) / depth
    y = camera["height"] / 2 - focal_px * (relative @ up) / depth
    return np.column_stack([x, y])


def write_speech_site(speech: Speech, model: Model, out: str | Path, fps: float = DEFAULT_FPS,
                      size: tuple[int, int] = DEFAULT_SIZE, look: str | Look | None = None) -> dict[str, int]:
    """The site of one utterance (``say``'s pipeline): its timeline sampled at ``fps``, its audio, in ``look``."""
    from engine.speech.synthesis import wav_bytes

    times = speech.frame_times(fps)
    values = speech.timeline.sample(times)
    names = list(speech.timeline.parameters)
    utterance = speech.utterance
    wav = wav_bytes(utterance.samples, utterance.sample_rate)
    return write_site(model, names, values, 1000.0 / fps, wav, out, phones=utterance.phones, words=utterance.words,
                      duration_ms=speech.end_ms, size=size, look=look)


def write_site(model: Model, names: Sequence[str], values: np.ndarray, frame_ms: float, wav: bytes,
               out: str | Path, phones: Sequence[Segment] = (), words: Sequence[Segment] = (),
               duration_ms: float | None = None, size: tuple[int, int] = DEFAULT_SIZE,
               look: str | Look | None = None) -> dict[str, int]:
    """Write the site into the folder ``out`` (made if missing; a folder that is not empty must be an
    earlier site, whose files are replaced). ``values``: frames × ``names``, frame ``n`` at ``n × frame_ms``;
    ``look`` how the head is lit and shaded (:mod:`engine.outputs.looks`, default ``portrait``).
    Returns each file's size in bytes."""
    out = Path(out)
    check_folder(out)
    look = look_from(look)
    animation = site_animation(model, names, values, frame_ms, phones, words, duration_ms, size, look)
    animation.update(model="head.glb", audio="speech.wav")
    glb = web_glb(model, morph_parameters(model, shared_targets([animation])), look)
    files = {"animation.json": json_bytes(animation), "speech.wav": wav}
    return write_folder(out, glb, files, "animation.json")


def site_animation(model: Model, names: Sequence[str], values: np.ndarray, frame_ms: float,
                   phones: Sequence[Segment] = (), words: Sequence[Segment] = (), duration_ms: float | None = None,
                   size: tuple[int, int] = DEFAULT_SIZE, look: str | Look | None = None) -> dict[str, Any]:
    """One animation JSON (without the ``model`` and ``audio`` it names): the frame table with the
    camera, and the lights and shading of ``render`` in ``look`` (:mod:`engine.web.web_look`)."""
    tree = model.parameters
    defaults = [tree[name].default for name in names]
    animation = animation_document(names, values, defaults, frame_ms, skeleton_parameters(model), phones, words,
                                   duration_ms)
    animation.update(camera=site_camera(model, size), **look_document(model, look), generator=MARKER)
    return animation


def shared_targets(animations: Sequence[dict[str, Any]]) -> dict[str, float]:
    """The morph targets one model needs for all ``animations``: each morph parameter at the value farthest
    from its default that any of them reaches; every animation's channels are set to that target value."""
    peaks: dict[str, float] = {}
    for animation in animations:
        for channel in animation["channels"]:
            if channel["kind"] == "morph":
                name, value = channel["parameter"], channel["target_value"]
                if name not in peaks or abs(value - channel["default"]) > abs(peaks[name] - channel["default"]):
                    peaks[name] = value
    for animation in animations:
        for channel in animation["channels"]:
            if channel["kind"] == "morph":
                channel["target_value"] = peaks[channel["parameter"]]
    return peaks


def json_bytes(document: dict[str, Any]) -> bytes:
    return json.dumps(document, separators=(",", ":"), ensure_ascii=False).encode("utf-8")


def write_folder(out: Path, glb: bytes, files: dict[str, bytes], first_animation: str) -> dict[str, int]:
    """The page, the player (bundled with three.js) and the model, with ``files`` (path in the site → bytes),
    into ``out``; the page opens ``first_animation`` unless its address names a stimulus. Returns each
    file's size.

    Every file is written by :func:`engine.formats.atomic.atomic_files`, all under one journal: each goes
    to a new temporary file of a random name beside its target (so a link planted at some fixed name is
    never followed) and is renamed over it once all are written; an export killed half-way is finished by
    the next one into the folder (:func:`check_folder`), or, killed before its first rename, undone. A
    link in place of a file is replaced, not followed; a folder of the site that is a link is refused."""
    out.mkdir(parents=True, exist_ok=True)
    page = _player_file("index.html").replace("{{ANIMATION}}", first_animation)
    player = bundle_text().replace(SHADER_MARK, json.dumps(web_shading_source()))   # the skin's relief as rendered
    contents = {"index.html": page.encode("utf-8"), "player.js": player.encode("utf-8"),
                "three-LICENSE.txt": licence_text().encode("utf-8"), "head.glb": glb, **files}
    targets = {name: _site_path(out, name) for name in contents}
    with atomic_files(targets.values()) as temporary:
        for name, target in targets.items():
            temporary[target].write_bytes(contents[name])
    return {name: len(blob) for name, blob in contents.items()}


def _site_path(out: Path, name: str) -> Path:
    """The path of the site's file ``name`` (``stimuli/x.wav``), its folders made inside ``out``; a folder
    on the way that is a symbolic link (which would take the file out of the site) or a file is refused."""
    folder = out
    for part in Path(name).parts[:-1]:
        folder = folder / part
        if folder.is_symlink():
            raise UserError("is a symbolic link: the site's folders must be its own (remove the link)", file=folder)
        if not folder.exists():
            folder.mkdir()
        elif not folder.is_dir():
            raise UserError("is a file where the site needs a folder", file=folder)
    return folder / Path(name).name


def write_tracks_site(model: Model, tracks: str | Path, audio: str | Path, out: str | Path,
                      phones: str | Path | None = None, size: tuple[int, int] = DEFAULT_SIZE,
                      look: str | Look | None = None) -> dict[str, int]:
    """The site of a tracks CSV and its audio (a WAV, copied unchanged), with the words of a phones CSV if given.

    The tracks are resampled at their own frame rate from 0 ms (held before their first row and after
    their last) until the later of their end and the audio's."""
    from engine.speech.synthesis import read_phones_csv, read_wav_bytes, wav_layout
    from engine.timeline.tracks import read_tracks_csv

    table = read_tracks_csv(tracks, model)
    wav = read_wav_bytes(audio)             # read once, bounded; checked as every WAV is, then copied unchanged
    layout = wav_layout(wav, audio)
    segments = read_phones_csv(phones) if phones is not None else []
    audio_ms = 1000.0 * layout.frames / layout.rate
    end_ms = max(table.end, audio_ms, segments[-1].end_ms if segments else 0.0)
    frame_ms = 1000.0 / table.fps
    count = max(1, int(np.ceil(end_ms / frame_ms - 1e-9)) + 1)
    times = np.arange(count) * frame_ms
    return write_site(model, table.parameters, table.sample(times), frame_ms, wav, out,
                      phones=segments, words=words_of(segments), duration_ms=end_ms, size=size, look=look)


def words_of(phones: Sequence[Segment]) -> list[Segment]:
    """The words of a phone sequence: each run of phones of one word (pauses, word "", end a run).

    >>> words_of([Segment("p", 0, 10, "Pappa"), Segment("a", 10, 20, "Pappa"), Segment("#", 20, 30, "")])
    [Segment(label='Pappa', start_ms=0, end_ms=20, word='')]
    """
    words: list[Segment] = []
    previous = ""
    for phone in phones:
        if phone.word and phone.word == previous:
            last = words[-1]
            words[-1] = Segment(last.label, last.start_ms, phone.end_ms)
        elif phone.word:
            words.append(Segment(phone.word, phone.start_ms, phone.end_ms))
        previous = phone.word
    return words


def _player_file(name: str) -> str:
    return (resources.files("engine.web") / "player" / name).read_text(encoding="utf-8")


def check_folder(out: Path) -> None:
    """Refuse a file, or a folder that holds anything but an earlier site.

    An earlier export killed half-way is finished first, or undone if it was killed before its first
    rename (:func:`engine.formats.atomic.finish_interrupted_writes` on the site's folders), so that its
    leftovers never make the folder look like someone else's."""
    if out.exists() and not out.is_dir():
        raise UserError("the site must be a folder, and this is a file", file=out)
    if not out.is_dir():
        return
    for folder in _site_folders(out):
        finish_interrupted_writes(folder)
    if _holds_files(out):
        index = out / "index.html"
        if not (index.is_file() and MARKER in _head_of(index)):
            raise UserError("the folder is not empty and holds no earlier site: choose a new or empty folder",
                            file=out)


#: The folders a site has of its own (a stimulus set's files; ``three/``, which sites before the bundle
#: held), besides the site's own folder.
_SUBFOLDERS = ("three", "stimuli")


def _site_folders(out: Path) -> list[Path]:
    """``out`` and every folder of the site under it (links not followed)."""
    folders = [out]
    for name in _SUBFOLDERS:
        top = out / name
        if top.is_dir() and not top.is_symlink():
            folders += [top, *(p for p in top.rglob("*") if p.is_dir() and not p.is_symlink())]
    return folders


def _holds_files(out: Path) -> bool:
    """True if ``out`` holds anything but the site's own folders empty of files (what a new export
    killed before its first rename leaves once its temporary files are gone)."""
    for entry in out.iterdir():
        if entry.name not in _SUBFOLDERS or entry.is_symlink() or not entry.is_dir():
            return True
        if any(not p.is_dir() or p.is_symlink() for p in entry.rglob("*")):
            return True
    return False


def _head_of(index: Path) -> str:
    """The first 64 kB of a page (the marker is in its head): a huge file named index.html is not read whole."""
    with index.open("rb") as stream:
        return stream.read(65536).decode("utf-8", errors="replace")
