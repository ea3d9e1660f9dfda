"""The tables of a stimulus set: manifest, PsychoPy conditions, checks, provenance — written together.

* ``manifest.csv``: one row per stimulus: its id, every factor's level, each
  file with its SHA-256, the clip's duration, where the audio and the video
  start in it, the audio–visual offset, the SNR measured back, and the times a
  researcher aligns to (speech onset, each word's onset, the expression's
  apex, the still's time), ms from the start of the file.
* ``conditions.csv``: PsychoPy's loop format (a header of variable names, one
  row per trial, paths relative to the table): ``stimulus`` (the main file),
  every factor, and every file by kind.
* ``check.csv``: each stimulus's own measurements from the files it wrote
  (audio offset by cross-correlation with the clean speech, SNR), and
  whether they meet the design.
* ``provenance.json``: the toolkit's version and git commit, the hashes of
  the design, model, noise and library files, Festival's version and voices,
  the numeric libraries' versions, the seed, and which OpenGL drew the pictures
  (``render_backend``: GPU or Mesa's software rasteriser,
  :func:`engine.outputs.render_backend.probe`). Its ``format_version`` is
  :data:`PROVENANCE_VERSION`; files written before it had one are version 1
  (no ``render_backend``), and :func:`read_provenance` reads both.
"""

from __future__ import annotations

import csv
import hashlib
import importlib.metadata
import io
import json
import platform
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np

from engine.errors import UserError
from engine.formats.atomic import atomic_files
from engine.outputs.png_file import png_bytes
from engine.paths import LIBRARY_DIR
from engine.processes import with_parent_death_signal
from engine.stimuli.design import FIXED_FACTORS, Design, level_text
from engine.stimuli.judging import check_columns, set_tables, set_verdicts
from engine.stimuli.make import RECORDS

MANIFEST = "manifest.csv"
CONDITIONS = "conditions.csv"
CHECKS = "check.csv"
PROVENANCE = "provenance.json"
#: 2: ``format_version`` and ``render_backend`` added; 1: the files before (no ``format_version``).
PROVENANCE_VERSION = 2
DRAWN_KINDS = frozenset({"mp4", "silent-mp4", "png"})
CONTACT_SHEET = "contact-sheet.png"
SHEET_COLUMNS = 8
SHEET_LIMIT = 400
MAIN_KINDS = ("mp4", "silent-mp4", "wav", "png", "tracks", "phones")
VIDEO_KINDS = frozenset({"mp4", "silent-mp4"})


def write_set_files(design: Design, outdir: Path, records: list[dict[str, Any]]) -> None:
    """The four tables of the set, from the records of every stimulus (all replaced together)."""
    factors = list(design.factors)
    kinds = list(design.output.kinds)
    verdicts = set_verdicts(records)
    texts = {
        MANIFEST: _csv(_manifest_rows(records, factors, kinds, design.output.look.name,
                                      design.output.encoding.name if VIDEO_KINDS & set(kinds) else "")),
        CONDITIONS: _csv(_condition_rows(records, factors, kinds)),
        CHECKS: _csv(_check_rows(records, verdicts if design.output.validate else None)),
        PROVENANCE: json.dumps(provenance(design, records), indent=2, ensure_ascii=False) + "\n",
    }
    if design.output.validate:
        texts.update(set_tables(verdicts, f"Validation of {design.name or design.path.name}"))
    sheet = contact_sheet(outdir, records)
    targets = [outdir / name for name in texts] + ([outdir / CONTACT_SHEET] if sheet is not None else [])
    with atomic_files(targets) as temporary:
        for name, text in texts.items():
            temporary[outdir / name].write_text(text, encoding="utf-8")
        if sheet is not None:
            temporary[outdir / CONTACT_SHEET].write_bytes(png_bytes(sheet))


def contact_sheet(outdir: Path, records: list[dict[str, Any]]) -> np.ndarray | None:
    """Every stimulus's thumbnail (at its still's time) labelled with its id, in design order, 8 a row; the
    first 400 of a larger set. ``None`` when no thumbnail is there."""
    from engine.outputs.raster import draw_text

    thumbs = []
    for record in records[:SHEET_LIMIT]:
        path = outdir / RECORDS / f"{record['id']}.thumb.npy"
        try:
            image = np.load(path, allow_pickle=False)
        except (OSError, ValueError):
            continue
        if image.ndim == 3 and image.shape[2] == 3 and image.dtype == np.uint8:
            marked = not record.get("check", {}).get("ok", True)
            thumbs.append((record["id"] + (" NO" if marked else ""), image))
    if not thumbs:
        return None
    height, width = thumbs[0][1].shape[:2]
    gap, label = 4, 14
    columns = min(SHEET_COLUMNS, len(thumbs))
    rows = -(-len(thumbs) // columns)
    sheet = np.full((gap + rows * (height + label + gap), gap + columns * (width + gap), 3), 255, np.uint8)
    for k, (name, image) in enumerate(thumbs):
        r, c = divmod(k, columns)
        y, x = gap + r * (height + label + gap), gap + c * (width + gap)
        if image.shape[:2] == (height, width):
            sheet[y:y + height, x:x + width] = image
        draw_text(sheet, name, x, y + height + 3, (40, 40, 40), scale=1)
    return sheet


def _manifest_rows(records: list[dict[str, Any]], factors: list[str], kinds: list[str],
                   look: str = "", encoding: str = "") -> list[dict[str, Any]]:
    rows = []
    for record in records:
        row: dict[str, Any] = {"id": record["id"]}
        row.update({name: level_text(record["levels"].get(name, "")) for name in factors})
        for kind in kinds:
            row[f"file_{kind}"] = record["files"][kind]["name"]
            row[f"sha256_{kind}"] = record["files"][kind]["sha256"]
        row.update({
            "duration_ms": _ms(record["duration_ms"]), "audio_start_ms": _ms(record["audio_start_ms"]),
            "video_start_ms": _ms(record["video_start_ms"]), "av_offset_ms": _ms(record["av_offset_ms"]),
            "alignment_ms": _ms(record.get("alignment_ms", 0.0)),
            "snr_db": "" if record["snr_db"] is None else f"{record['snr_db']:.3f}",
            "speech_onset_ms": _ms(record["speech_onset_ms"]),
            "word_onsets_ms": ";".join(_ms(t) for t in record["word_onsets_ms"]),
            "words": ";".join(record["words"]),
            "expression_apex_ms": "" if record["expression_apex_ms"] is None else _ms(record["expression_apex_ms"]),
            "still_ms": "" if record["still_ms"] is None else _ms(record["still_ms"]),
            "look": look,                                       # its settings: provenance.json
            "encoding": encoding,                               # the videos' (empty with none): provenance.json
        })
        rows.append(row)
    return rows


def _condition_rows(records: list[dict[str, Any]], factors: list[str], kinds: list[str]) -> list[dict[str, Any]]:
    main = next(kind for kind in MAIN_KINDS if kind in kinds)
    rows = []
    for record in records:
        row: dict[str, Any] = {"stimulus": record["files"][main]["name"], "id": record["id"]}
        row.update({name: level_text(record["levels"].get(name, "")) for name in factors})
        row.update({f"file_{kind.replace('-', '_')}": record["files"][kind]["name"] for kind in kinds})
        row["speech_onset_ms"] = _ms(record["speech_onset_ms"])
        rows.append(row)
    return rows


def _check_rows(records: list[dict[str, Any]], verdicts: list[Any] | None) -> list[dict[str, Any]]:
    rows = []
    for record in records:
        check = record.get("check", {})
        rows.append({"id": record["id"], "av_offset_ms": _ms(record["av_offset_ms"]),
                     "audio_start_ms": _ms(record["audio_start_ms"]),
                     "measured_audio_start_ms": _optional(check.get("measured_audio_start_ms")),
                     "measured_from": check.get("measured_from", ""),
                     "snr_db": _optional(record.get("snr_spec_db")),
                     "measured_snr_db": _optional(check.get("measured_snr_db")),
                     "measured_video_lag_frames": "" if check.get("measured_video_lag_frames") is None
                     else str(check["measured_video_lag_frames"]),
                     "ok": "yes" if check.get("ok", True) else "NO", "problem": check.get("problem", "")})
        if verdicts is not None:
            rows[-1].update(check_columns(record, verdicts))
    return rows


def provenance(design: Design, records: list[dict[str, Any]]) -> dict[str, Any]:
    """What made the set, so it can be made the same way again."""
    names = ["numpy", "scipy", "vtk", "h5py", "lxml"]
    if design.output.validate:
        names += ["dlib-bin", "face_recognition_models", "ai-edge-litert", "pillow"]
    libraries: dict[str, str | None] = {}
    for name in names:
        try:
            libraries[name] = importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            libraries[name] = None
    made = {
        "format_version": PROVENANCE_VERSION,
        "toolkit": {"version": _toolkit_version(), "git_commit": git_commit()},
        "design": {"file": design.path.name, "sha256": design.sha256, "seed": design.seed,
                   "stimuli": len(records)},
        "files": {name: _file_hash(path) for name, path in sorted(design.extra_files.items())},
        "library_sha256": _tree_hash(LIBRARY_DIR),
        "default_model_sha256": _default_model_hash(),
        "festival": {"version": _festival_version(), "voices": sorted({r["voice"] for r in records})},
        "python": sys.version.split()[0], "platform": platform.platform(), "libraries": libraries,
        "look": design.output.look.settings(), "look_methods": look_methods(),
        "encoding": design.output.encoding.settings(),
        "render_backend": _render_backend() if DRAWN_KINDS & set(design.output.kinds) else None,
    }
    if design.output.validate:
        from dataclasses import asdict

        from engine.validation.observers import EMOTION_MODEL_SHA256, model_facts

        made["validation"] = {"observers": [asdict(m) for m in model_facts()],
                              "emotion_model_sha256": EMOTION_MODEL_SHA256}
    return made


def read_provenance(path: str | Path) -> dict[str, Any]:
    """A set's ``provenance.json`` as a dict whose ``format_version`` and ``render_backend`` are always
    there (1 and ``None`` for a file written before they were), or a :class:`UserError` naming the file."""
    path = Path(path)
    try:
        made = json.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise UserError(f"cannot read the set's provenance: {exc.strerror or exc}", file=path) from None
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise UserError(f"the set's provenance is not JSON ({exc})", file=path) from None
    if not isinstance(made, dict):
        raise UserError("the set's provenance must be a JSON object", file=path)
    version = made.get("format_version", 1)
    if isinstance(version, bool) or not isinstance(version, int) or version < 1:
        raise UserError(f"format_version must be a whole number from 1, not {version!r}", file=path)
    if version > PROVENANCE_VERSION:
        raise UserError(f"format_version {version} is newer than this toolkit reads ({PROVENANCE_VERSION}): "
                        "update the toolkit", file=path)
    backend = made.get("render_backend")
    if backend is not None and not isinstance(backend, dict):
        raise UserError("render_backend must be an object or null", file=path)
    return {**made, "format_version": version, "render_backend": backend}


def _render_backend() -> dict[str, str]:
    """Which OpenGL draws here (the set's workers open theirs the same way), as ``render --info`` prints it."""
    from engine.outputs.render_backend import probe

    return probe()


def look_methods() -> dict[str, Any]:
    """How the look's parts are computed, with the settings of each (beside the look's own, so a set can be
    drawn the same way again): the shader's text, the anti-aliasing, the baked occlusion."""
    from engine.outputs import antialias, occlusion
    from engine.outputs.look_shader import SHADING

    return {"shader_sha256": hashlib.sha256(SHADING.encode("utf-8")).hexdigest(), "fxaa": antialias.settings(),
            "occlusion": occlusion.settings()}


def _csv(rows: list[dict[str, Any]]) -> str:
    buffer = io.StringIO()
    if rows:
        writer = csv.DictWriter(buffer, fieldnames=list(rows[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    return buffer.getvalue()


def _ms(value: float) -> str:
    return f"{float(value):.3f}".rstrip("0").rstrip(".") or "0"


def _optional(value: float | None) -> str:
    return "" if value is None else f"{float(value):.3f}"


def _file_hash(path: Path) -> str | None:
    try:
        return hashlib.sha256(Path(path).read_bytes()).hexdigest()
    except OSError:
        return None


def _tree_hash(folder: Path) -> str:
    digest = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file() and "__pycache__" not in p.parts):
        digest.update(str(path.relative_to(folder)).encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()


def _default_model_hash() -> dict[str, str | None]:
    from engine.paths import default_model_path

    xml = default_model_path()
    return {xml.name: _file_hash(xml), xml.with_suffix(".h5").name: _file_hash(xml.with_suffix(".h5"))}


def _toolkit_version() -> str | None:
    for name in ("artificial-person", "artificial_person"):
        try:
            return importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            continue
    return None


def git_commit(top: Path | None = None) -> str | None:
    """The commit of the toolkit's own checkout (``top``: the folder holding ``engine/``), or ``None``.

    ``None`` too when the toolkit is installed as a package: a venv's ``site-packages`` inside a lab's
    own repository would otherwise give that repository's commit, which says nothing of the toolkit. So
    the checkout counts only when its top level is ``top`` itself.
    """
    top = (top or Path(__file__).resolve().parents[2]).resolve()
    try:
        done = subprocess.run(with_parent_death_signal(["git", "-C", str(top), "rev-parse", "--show-toplevel",
                                                        "HEAD"]),
                              capture_output=True, text=True, timeout=10, check=False)
    except (OSError, subprocess.TimeoutExpired):
        return None
    lines = done.stdout.split()
    if done.returncode != 0 or len(lines) != 2 or Path(lines[0]).resolve() != top:
        return None
    return lines[1]


def _festival_version() -> str | None:
    from engine.programs import find_program

    festival = find_program("festival")
    if festival is None:
        return None
    try:
        done = subprocess.run(with_parent_death_signal([festival, "--version"]), capture_output=True, text=True,
                              timeout=30, check=False)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return (done.stdout or done.stderr).strip().splitlines()[0] if (done.stdout or done.stderr).strip() else None


__all__ = ["CHECKS", "CONDITIONS", "FIXED_FACTORS", "MANIFEST", "PROVENANCE", "PROVENANCE_VERSION", "level_text",
           "provenance", "read_provenance", "write_set_files"]
