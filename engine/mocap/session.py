"""A motion-capture session: imported markers ready for analysis (§3.1.1), and its HDF5 file.

A :class:`Session` is what ``mocap import`` produces and what frame
selection and multistage PCA read: marker trajectories in millimetres with
the head motion removed, the raw trajectories as the file had them, which
samples were missing or gap-filled, the per-frame head alignment, and any
phone labels. Lengths are mm, times ms.

The session file (HDF5) is written atomically and carries
``format = "artificial-person-mocap-session"`` and ``version = 1``; reading
refuses anything else with a :class:`~engine.mocap.errors.SessionFileError`
naming the file. Layout, version 1::

    attrs      format, version, rate_hz (frames per second), source, units = "mm"
    markers    (M,) str      marker names: MPEG-4 feature point ids ("8.3") or the file's own labels
    positions  (F, M, 3) f8  mm, head motion removed, NaN where missing
    raw        (F, M, 3) f8  mm, as read from the file (no filling, no alignment), NaN where missing
    missing    (F, M) bool   still missing after gap filling (excluded from analysis)
    filled     (F, M) bool   missing in the file, filled by the spline
    alignment  (F, 4, 4) f8  per-frame rigid transform, row-vector convention: [raw, 1] · A = [positions, 1];
                             NaN for frames that could not be aligned
    reference  (R,) str      the head-fixed markers the alignment used
    report     str           JSON: the gap report and import settings (see engine.mocap.gaps)
    phones/start_ms, phones/end_ms (P,) f8 and phones/label (P,) str   optional phone labels

>>> import numpy as np
>>> s = Session(markers=["2.1", "8.1"], positions=np.zeros((3, 2, 3)), raw=np.zeros((3, 2, 3)), rate_hz=60.0,
...             missing=np.zeros((3, 2), bool), alignment=np.tile(np.eye(4), (3, 1, 1)))
>>> s.times_ms
array([ 0.        , 16.66666667, 33.33333333])
>>> s.n_frames, s.n_markers
(3, 2)
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import h5py
import numpy as np

from engine.formats.atomic import atomic_path
from engine.mocap.errors import MocapError, SessionFileError
from engine.mocap.hdf5_files import open_versioned, text_attribute

SESSION_FORMAT = "artificial-person-mocap-session"
SESSION_VERSION = 1


@dataclass
class Session:
    """Imported marker data (mm, ms). Arrays are validated on construction.

    ``phones`` are ``(start_ms, end_ms, label)`` triples on the session's
    clock, which starts at 0 ms on the first frame (:attr:`times_ms`).
    """

    markers: list[str]
    positions: np.ndarray
    """(F, M, 3) mm, head motion removed, NaN where missing."""
    raw: np.ndarray
    """(F, M, 3) mm as read from the file: no filling, no alignment; NaN where the file had a gap."""
    rate_hz: float
    missing: np.ndarray
    """(F, M) bool, True where a marker is still missing after gap filling."""
    alignment: np.ndarray
    """(F, 4, 4) row-vector transforms, ``[raw, 1] · alignment[f] = [positions, 1]``; NaN where unaligned."""
    phones: list[tuple[float, float, str]] = field(default_factory=list)
    source: str = ""
    report: dict[str, Any] = field(default_factory=dict)
    filled: np.ndarray | None = None
    """(F, M) bool, True where the file had a gap that the spline filled (None: nothing filled)."""
    reference: list[str] = field(default_factory=list)
    """The head-fixed markers the alignment used."""

    def __post_init__(self) -> None:
        self.markers = [str(m) for m in self.markers]
        self.positions = np.asarray(self.positions, dtype=float)
        self.raw = np.asarray(self.raw, dtype=float)
        self.missing = np.asarray(self.missing, dtype=bool)
        self.alignment = np.asarray(self.alignment, dtype=float)
        self.rate_hz = float(self.rate_hz)
        self.reference = [str(m) for m in self.reference]
        self.phones = [(float(a), float(b), str(c)) for a, b, c in self.phones]
        n_markers = len(self.markers)
        if self.positions.ndim != 3 or self.positions.shape[1:] != (n_markers, 3):
            raise MocapError(f"positions have shape {self.positions.shape}, expected (frames, {n_markers}, 3)")
        n_frames = self.positions.shape[0]
        if self.raw.shape != self.positions.shape:
            raise MocapError(f"raw positions have shape {self.raw.shape}, expected {self.positions.shape}")
        if self.missing.shape != (n_frames, n_markers):
            raise MocapError(f"the missing mask has shape {self.missing.shape}, expected {(n_frames, n_markers)}")
        if self.filled is None:
            self.filled = np.zeros((n_frames, n_markers), bool)
        self.filled = np.asarray(self.filled, dtype=bool)
        if self.filled.shape != (n_frames, n_markers):
            raise MocapError(f"the filled mask has shape {self.filled.shape}, expected {(n_frames, n_markers)}")
        if self.alignment.shape != (n_frames, 4, 4):
            raise MocapError(f"the alignment has shape {self.alignment.shape}, expected {(n_frames, 4, 4)}")
        if not (np.isfinite(self.rate_hz) and self.rate_hz > 0):
            raise MocapError(f"the frame rate must be a positive number of frames per second, not {self.rate_hz}")
        if len(set(self.markers)) != n_markers:
            raise MocapError("marker names must be unique")
        unknown = [m for m in self.reference if m not in self.markers]
        if unknown:
            raise MocapError(f"reference markers {', '.join(unknown)} are not among the session's markers")

    @property
    def n_frames(self) -> int:
        return int(self.positions.shape[0])

    @property
    def n_markers(self) -> int:
        return len(self.markers)

    @property
    def times_ms(self) -> np.ndarray:
        """(F,) time of every frame in ms; the first frame is at 0 ms."""
        return np.arange(self.n_frames) * (1000.0 / self.rate_hz)

    def marker_index(self, name: str) -> int:
        """Column of marker ``name`` in the arrays; a :class:`MocapError` if the session lacks it."""
        try:
            return self.markers.index(name)
        except ValueError:
            raise MocapError(f"the session has no marker '{name}' (it has {', '.join(self.markers)})") from None


# -- the file ----------------------------------------------------------------------

def save_session(session: Session, path: str | Path) -> None:
    """Write ``session`` to an HDF5 file atomically (temporary file beside ``path``, then rename)."""
    with atomic_path(path, SessionFileError) as tmp:
        _write(session, tmp)


def _write(s: Session, tmp: str) -> None:
    text = h5py.string_dtype()
    with h5py.File(tmp, "w", track_order=True) as f:
        f.attrs["format"] = SESSION_FORMAT
        f.attrs["version"] = SESSION_VERSION
        f.attrs["rate_hz"] = s.rate_hz
        f.attrs["source"] = s.source
        f.attrs["units"] = "mm"
        f.create_dataset("markers", data=np.array(s.markers, dtype=object), dtype=text)
        big = {"compression": "gzip", "shuffle": True} if s.positions.size > 4096 else {}
        f.create_dataset("positions", data=s.positions, **big)
        f.create_dataset("raw", data=s.raw, **big)
        f.create_dataset("missing", data=s.missing, **big)
        f.create_dataset("filled", data=s.filled, **big)
        f.create_dataset("alignment", data=s.alignment, **big)
        f.create_dataset("reference", data=np.array(s.reference, dtype=object), dtype=text)
        f.create_dataset("report", data=json.dumps(s.report, sort_keys=True), dtype=text)
        g = f.create_group("phones")
        g.create_dataset("start_ms", data=np.array([p[0] for p in s.phones], float))
        g.create_dataset("end_ms", data=np.array([p[1] for p in s.phones], float))
        g.create_dataset("label", data=np.array([p[2] for p in s.phones], dtype=object), dtype=text)


def load_session(path: str | Path) -> Session:
    """Read a session file, checking its format, version and every array's kind, shape and size.

    NaN (a missing sample) is allowed in ``positions``, ``raw`` and
    ``alignment``; infinities nowhere. Anything else wrong, or any damage the
    HDF5 library reports, is a :class:`SessionFileError` naming the file.
    """
    path = Path(path)
    with open_versioned(path, SESSION_FORMAT, SESSION_VERSION, SessionFileError, "a motion-capture session",
                        "mocap import") as f:
        markers = f.strings("markers")
        positions = f.array("positions", "f", ndim=3, allow_nan=True).astype(float)
        n_frames, n_markers = positions.shape[0], len(markers)
        shape = (n_frames, n_markers)
        try:
            rate = float(f.attribute("rate_hz"))  # type: ignore[arg-type]
        except (TypeError, ValueError):
            raise SessionFileError("the session has no valid 'rate_hz' attribute", file=path) from None
        try:
            report = json.loads(f.text("report") or "{}")
        except json.JSONDecodeError as exc:
            raise SessionFileError(f"the '/report' dataset is not valid JSON ({exc.msg})", file=path) from None
        if not isinstance(report, dict):
            raise SessionFileError("the '/report' dataset is not a JSON object", file=path)
        phones = []
        if f.has("phones"):
            starts = f.array("phones/start_ms", "f").astype(float)
            ends = f.array("phones/end_ms", "f").astype(float)
            labels = f.strings("phones/label")
            if not (len(starts) == len(ends) == len(labels)):
                raise SessionFileError("the phones/start_ms, phones/end_ms and phones/label datasets differ "
                                       "in length", file=path)
            phones = list(zip(starts.tolist(), ends.tolist(), labels, strict=True))
        try:
            return Session(
                markers=markers, positions=positions,
                raw=f.array("raw", "f", shape=positions.shape, allow_nan=True),
                rate_hz=rate,
                missing=f.array("missing", "b", shape=shape).astype(bool),
                alignment=f.array("alignment", "f", shape=(n_frames, 4, 4), allow_nan=True),
                phones=phones, source=text_attribute(f.attribute("source")) or "", report=report,
                filled=f.array("filled", "b", shape=shape).astype(bool) if f.has("filled") else None,
                reference=f.strings("reference") if f.has("reference") else [],
            )
        except SessionFileError:
            raise
        except MocapError as exc:
            raise SessionFileError(f"inconsistent session: {exc.message}", file=path) from None
