"""From a marker file to a :class:`~engine.mocap.session.Session` (what ``mocap import`` does).

The steps, each its own engine function: read the file (:mod:`.readers`),
name the markers (:mod:`.naming`), turn them to the toolkit's axes
(:mod:`.capture_axes`: +Y up, +Z facing), fill short gaps (:mod:`.gaps`), remove
head motion (:mod:`.head_motion`), attach phone labels (:mod:`engine.speech.labels`).
:func:`build_session` does all but the reading, for arrays that come from
elsewhere (a generator, another tool).

>>> session = import_marker_file("take1.tsv", mapping="face.map", max_gap_ms=100,
...                              labels="take1.TextGrid")        # doctest: +SKIP
>>> print(format_report(session))                                # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from engine.mocap.capture_axes import detect_axes
from engine.mocap.errors import MocapError
from engine.mocap.gaps import fill_gaps, max_gap_frames
from engine.mocap.head_motion import MIN_REFERENCE, remove_head_motion
from engine.mocap.marker_assignment import unmapped_labels
from engine.mocap.naming import default_reference, marker_names, read_mapping
from engine.mocap.readers import FORMAT_NAMES, read_marker_file
from engine.mocap.recording import Recording
from engine.mocap.session import Session
from engine.model.landmarks import landmark_sort_key

if TYPE_CHECKING:
    from engine.mocap.csv_table import CsvLayout
    from engine.speech.synthesis import Synthesizer

DEFAULT_MAX_GAP_MS = 100.0


def import_marker_file(path: str | Path, *, format: str = "auto", mapping: str | Path | dict[str, str] | None = None,
                       max_gap_ms: float = DEFAULT_MAX_GAP_MS, reference: list[str] | None = None,
                       reference_frame: str | int = "first", labels: str | Path | None = None,
                       tier: str | None = None, text: str | None = None, voice: str | None = None,
                       stretch_text: bool = False, csv_layout: CsvLayout | None = None,
                       synthesizer: Synthesizer | None = None, up: str = "auto") -> Session:
    """Read a marker file and prepare it for analysis.

    ``mapping`` is a mapping file or a ``{label: id}`` dict; ``max_gap_ms``
    the longest gap to fill (ms); ``reference`` the head-fixed markers by
    session name (default :func:`~engine.mocap.naming.default_reference`;
    ``[]`` leaves head motion in); ``labels`` a TextGrid, label file or
    phones CSV, or ``text`` the spoken text for Festival's timings
    (``stretch_text`` stretches them over the whole recording); ``up`` the
    file's up axis (``"Z"``, ``"-Y"`` …) or ``"auto"`` to find it from the
    markers (:func:`~engine.mocap.capture_axes.detect_axes`).
    """
    recording = read_marker_file(path, format=format, csv_layout=csv_layout)
    if isinstance(mapping, (str, Path)):
        mapping = read_mapping(mapping)
    phones, phone_source = [], None
    if labels is not None and text is not None:
        raise MocapError("give phone labels either from a file or from the spoken text, not both")
    if labels is not None:
        from engine.speech.labels import read_labels

        phones, phone_source = read_labels(labels, tier=tier), Path(labels).name
    elif text is not None:
        from engine.speech.labels import festival_phones

        duration = recording.n_frames * 1000.0 / recording.rate_hz if stretch_text else None
        phones = festival_phones(text, voice=voice, duration_ms=duration, synthesizer=synthesizer)
        phone_source = "Festival" + (" (stretched over the recording)" if stretch_text else "")
    session = build_session(recording, mapping=mapping, max_gap_ms=max_gap_ms, reference=reference,
                            reference_frame=reference_frame, phones=phones, up=up)
    if phone_source:
        session.report["phones"] = {"source": phone_source, "count": len(phones)}
    return session


def build_session(recording: Recording, *, mapping: dict[str, str] | None = None,
                  max_gap_ms: float = DEFAULT_MAX_GAP_MS, reference: list[str] | None = None,
                  reference_frame: str | int = "first",
                  phones: list[tuple[float, float, str]] | None = None, up: str = "auto") -> Session:
    """Name, turn to +Y up, gap-fill and head-align a :class:`~engine.mocap.recording.Recording` (positions in mm).

    ``up`` is the file's up axis (``"Z"``, ``"-Y"`` …), or ``"auto"``: found
    from the MPEG-4-named markers, kept as it is when they cannot tell.
    """
    if not (np.isfinite(max_gap_ms) and max_gap_ms >= 0):
        raise MocapError(f"the longest gap to fill must be 0 ms or more, not {max_gap_ms}")
    names, naming = marker_names(recording.labels, mapping)
    naming["not_feature_points"] = unmapped_labels(recording.labels, names)
    kept = [(k, n) for k, n in enumerate(names) if n is not None]
    keep = [k for k, _ in kept]
    markers = [n for _, n in kept]
    if not markers:
        raise MocapError(f"{recording.source}: the file has no markers" if not recording.labels
                         else "no markers left to import (the mapping drops them all)")
    raw = np.asarray(recording.positions, dtype=float)
    if len(keep) < raw.shape[1]:
        raw = raw[:, keep]
    axes = detect_axes(markers, raw, up=None if up == "auto" else up, file_up=recording.up_hint)
    raw = axes.apply(raw)
    if raw.shape[0] == 0:
        raise MocapError(f"{recording.source}: the file has no frames")
    if not np.isfinite(raw).any():
        raise MocapError(f"{recording.source}: every sample of the {len(markers)} markers imported is missing "
                         f"in all {raw.shape[0]} frames: nothing to import")
    gap_frames = max_gap_frames(max_gap_ms, recording.rate_hz)
    filled, was_filled, missing, gap_report = fill_gaps(raw, gap_frames)

    if reference is None:
        reference = default_reference(markers)
        if len(reference) < MIN_REFERENCE:
            raise MocapError(f"{recording.source}: cannot remove head motion: it needs at least {MIN_REFERENCE} "
                             f"head-fixed reference markers (9.x, 10.x, 11.x, 20.x) and the file has "
                             f"{len(reference)}{' (' + ', '.join(reference) + ')' if reference else ''}; "
                             "name them with --map, pick them with --reference, or give --reference none")
    unknown = [r for r in reference if r not in markers]
    if unknown:
        raise MocapError(f"reference marker(s) {', '.join(unknown)} are not in the file "
                         f"(markers: {', '.join(sorted(markers, key=landmark_sort_key))})")
    report = {
        "source": recording.source, "format": recording.format, "units_in_file": recording.units,
        "rate_hz": recording.rate_hz, "frames": int(raw.shape[0]), "markers": len(markers),
        "file_start_ms": recording.start_ms, "max_gap_ms": float(max_gap_ms), "max_gap_frames": gap_frames,
        "gaps": {markers[m]: r for m, r in gap_report.items()},
        "naming": naming, "events": [[name, t] for name, t in recording.events],
        "file_notes": list(recording.notes),
        "axes": {"up": axes.up, "facing": axes.facing, "source": axes.source, "rotation": axes.rotation.tolist(),
                 "text": axes.describe()},
    }
    if reference:
        index = [markers.index(r) for r in reference]
        positions, alignment, info = remove_head_motion(filled, missing, index, reference_frame, filled=was_filled)
        unaligned = ~np.isfinite(alignment[:, 0, 0])
        missing = missing | unaligned[:, None]
        positions[missing] = np.nan
        residual = info["residual_rms_mm"]
        finite = residual[np.isfinite(residual)]
        report["head_motion"] = {
            "reference": list(reference), "reference_frame": info["reference_frame"],
            "unaligned_frames": info["unaligned_frames"],
            "residual_rms_mm": {"median": float(np.median(finite)) if len(finite) else None,
                                "max": float(finite.max()) if len(finite) else None},
        }
    else:
        positions = filled.copy()
        positions[missing] = np.nan
        alignment = np.tile(np.eye(4), (raw.shape[0], 1, 1))
        report["head_motion"] = None
    report["complete_frames"] = int((~missing).all(axis=1).sum())
    return Session(markers=markers, positions=positions, raw=raw, rate_hz=recording.rate_hz, missing=missing,
                   alignment=alignment, phones=list(phones or []), source=recording.source, report=report,
                   filled=was_filled, reference=list(reference))


def format_report(session: Session) -> str:
    """The import report as text: the recording, gaps per marker, head motion, phones."""
    r = session.report
    fmt = str(r.get("format"))
    lines = [f"{session.source}: {FORMAT_NAMES.get(fmt, fmt)}, {session.n_frames} frames "
             f"at {session.rate_hz:g} Hz, {session.n_markers} markers (file units {r.get('units_in_file', 'mm')})"]
    lines += [f"note: {note}" for note in r.get("file_notes", [])]
    if r.get("axes"):
        lines.append(r["axes"]["text"])
    naming = r.get("naming") or {}
    if naming.get("renamed"):
        lines.append("renamed: " + ", ".join(f"{a} → {b}" for a, b in naming["renamed"].items()))
    if naming.get("dropped"):
        lines.append("dropped: " + ", ".join(naming["dropped"]))
    if naming.get("unused_mapping"):
        lines.append("mapping entries not in the file: " + ", ".join(naming["unused_mapping"]))
    if naming.get("not_feature_points"):
        kept = naming["not_feature_points"]
        lines.append(f"warning: {len(kept)} of {session.n_markers} markers name no MPEG-4 feature point and keep "
                     f"their file labels (name them with --map): {', '.join(kept)}")
    gaps = r.get("gaps", {})
    with_gaps = [m for m in session.markers if gaps.get(m, {}).get("gaps")]
    lines.append(f"gaps (filled up to {r.get('max_gap_ms', 0):g} ms = {r.get('max_gap_frames', 0)} frames): "
                 + ("none" if not with_gaps else f"{len(with_gaps)} of {session.n_markers} markers"))
    if with_gaps:
        rows = [("marker", "gaps", "filled gaps", "filled frames", "missing gaps", "missing frames")]
        for m in with_gaps:
            g = gaps[m]
            rows.append((m, str(g["gaps"]), str(g["filled_gaps"]), str(g["filled_frames"]), str(g["missing_gaps"]),
                         str(g["missing_frames"])))
        widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
        lines += ["  " + "  ".join(c.rjust(w) if i else c.ljust(w)
                                   for i, (c, w) in enumerate(zip(row, widths, strict=True)))
                  for row in rows]
    hm = r.get("head_motion")
    if hm:
        res = hm["residual_rms_mm"]
        detail = (f"; reference residual RMS median {res['median']:.3g} mm, max {res['max']:.3g} mm"
                  if res.get("median") is not None else "")
        lines.append(f"head motion removed: reference {', '.join(hm['reference'])}, frame {hm['reference_frame']}"
                     f"{detail}; {hm['unaligned_frames']} frames could not be aligned")
    else:
        lines.append("head motion left in (no reference markers)")
    lines.append(f"complete frames (every marker present): {r.get('complete_frames', 0)} of {session.n_frames}")
    if session.phones:
        src = (r.get("phones") or {}).get("source", "labels")
        end = max(p[1] for p in session.phones)
        note = " — longer than the recording" if end > session.n_frames * 1000.0 / session.rate_hz + 1e-6 else ""
        lines.append(f"phones: {len(session.phones)} from {src}, up to {end:.0f} ms{note}")
    return "\n".join(lines)
