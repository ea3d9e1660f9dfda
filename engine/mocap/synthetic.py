"""Synthetic motion capture with a known answer: virtual markers on the default head (§3.1.1).

No openly licensed lip and jaw speech recordings exist that we could ship, so
the tests (and anyone trying the pipeline) use recordings made up from the
default head itself:

1. phones (from Festival, or given) → articulatory tracks of the head's own
   parameters (``jaw_open``, ``mouth_widen``, ``lip_protrude``,
   ``upper_lip_raise``, ``lower_lip_raise``) through the phone → target table
   ``engine/library/articulation/finnish.phones`` with Cohen–Massaro coarticulation
   (:func:`engine.speech.coarticulation.articulation_tracks`), sampled at the
   capture rate (60 fps, as the paper's MacReflex);
2. the head deformed by those values (exactly, through the model's own
   deformation) and read at its landmark vertices: one virtual marker per
   MPEG-4 feature point — the lip contour 8.1–8.8, the chin 2.1 and 2.10, the
   eye corners (3.x) and head-fixed reference points on the nose bridge (9.12)
   and the forehead (11.1–11.3), placed on the skin where the head has no
   landmark for them (:func:`marker_vertices`);
3. smooth random rigid head motion, Gaussian marker noise, single-frame
   dropouts and gaps (NaN), as an optical tracker gives them.

What comes back (:class:`SyntheticRecording`) holds the observed markers and
the ground truth: the clean articulation-only markers, the generating tracks,
the per-marker displacement basis (the derivative of every marker position
with respect to every parameter at rest, mm per unit) and the head motion.
With ``linear=True`` the markers are exactly ``rest + tracks · basis``, so the
motion lies in a known 5-dimensional subspace; by default they are the head's
real deformation, in which ``jaw_open`` is a rotation (a slightly curved
path) and the lower lip rides on the jaw.

Lengths are mm, times ms; frame ``i`` is at ``i · 1000 / rate_hz`` ms.

>>> from engine.speech.synthesis import Segment
>>> phones = [Segment("#", 0, 100), Segment("p", 100, 180), Segment("a", 180, 330), Segment("#", 330, 430)]
>>> rec = synthesize_recording(phones=phones, noise_mm=0, head_motion=False, gaps=False)
>>> rec.positions.shape == (rec.n_frames, len(rec.markers), 3), rec.parameters[0]
(True, 'jaw_open')
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from engine.errors import UserError
from engine.mocap.frame_selection import Phones
from engine.model.vertex_subset import model_at_vertices
from engine.script.timed_labels import TimedLabel

if TYPE_CHECKING:
    from engine.model.model import Model
    from engine.speech.articulation import ArticulationTable
    from engine.speech.synthesis import Segment, Synthesizer

#: Markers of the lip contour and the jaw: what the paper analysed (§3.1.1, "8.x and 2.1").
ARTICULATION_MARKERS = ("2.1", "8.1", "8.2", "8.3", "8.4", "8.5", "8.6", "8.7", "8.8")
#: Head-fixed markers for removing head motion: nose bridge and forehead (on the default head the
#: nostril and nose-base points 9.1–9.5 and 9.15 move with the lips, so they would not do).
REFERENCE_MARKERS = ("9.12", "11.1", "11.2", "11.3")
#: Eye corners: still during speech, captured like the paper's other markers.
EYE_MARKERS = ("3.7", "3.8", "3.11", "3.12")
#: The default marker set: articulation markers, the chin boss, eye corners and the reference markers.
DEFAULT_MARKERS = (*ARTICULATION_MARKERS, "2.10", *EYE_MARKERS, *REFERENCE_MARKERS)
#: Sentences with every Finnish vowel and most consonants, bilabial closures and rounding.
DEFAULT_TEXT = "Papu ja kala. Hyvää päivää, mitä kuuluu? Öljyä ja syötävää."


@dataclass
class SyntheticRecording:
    """A made-up capture session and the truth behind it (mm, ms)."""

    markers: list[str]
    positions: np.ndarray
    """(F, M, 3) observed: articulation + head motion + noise, NaN where missing."""
    rate_hz: float
    phones: list[tuple[float, float, str]]
    """(start_ms, end_ms, label) on the recording's clock (frame 0 at 0 ms)."""
    missing: np.ndarray
    """(F, M) bool, True where a marker dropped out."""
    clean: np.ndarray
    """(F, M, 3) articulation only: no head motion, no noise, no gaps."""
    rest: np.ndarray
    """(M, 3) marker positions on the head at rest."""
    parameters: list[str]
    """The articulatory parameters driven (those that move a marker)."""
    tracks: np.ndarray
    """(F, P) the generating parameter values."""
    basis: np.ndarray
    """(P, M, 3) marker displacement per unit of each parameter at rest, mm (the true subspace)."""
    head_rotation: np.ndarray
    """(F, 3, 3) head rotation; observed = pivot + R (x − pivot) + t, column vectors."""
    head_translation: np.ndarray
    """(F, 3) head translation, mm."""
    head_pivot: np.ndarray
    """(3,) centre of the head rotation, mm."""
    reference: list[str] = field(default_factory=list)
    """The head-fixed markers among :attr:`markers` (for head-motion removal)."""
    text: str = ""

    @property
    def n_frames(self) -> int:
        return int(self.positions.shape[0])

    @property
    def times_ms(self) -> np.ndarray:
        return np.arange(self.n_frames) * (1000.0 / self.rate_hz)

    def marker_index(self, names: Iterable[str]) -> np.ndarray:
        """Columns of the named markers."""
        return np.array([self.markers.index(n) for n in names], dtype=np.int64)


def synthesize_recording(text: str | None = None, *, phones: Phones | None = None, model: Model | None = None,
                         table: ArticulationTable | None = None, markers: Iterable[str] = DEFAULT_MARKERS,
                         rate_hz: float = 60.0, linear: bool = False, head_motion: bool = True,
                         head_rotation_deg: float = 3.0, head_translation_mm: float = 4.0, noise_mm: float = 0.2,
                         gaps: bool = True, dropout_probability: float = 0.002,
                         gaps_per_minute: float = 4.0, gap_frames: tuple[int, int] = (2, 30),
                         long_gap_frames: int = 90, seed: int = 0, voice: str | None = None,
                         synthesizer: Synthesizer | None = None) -> SyntheticRecording:
    """Make up a marker recording of ``text`` spoken by the default head.

    Parameters
    ----------
    text : str, optional
        Finnish text for Festival (default :data:`DEFAULT_TEXT` when ``phones``
        is not given). Needs Festival with the Suopuhe voices.
    phones : list of segments or ``(start_ms, end_ms, label)``, optional
        Phone timings to use instead of running Festival (e.g. recorded from
        an earlier run), ms.
    model : engine.Model, optional
        The head (default: the shipped default head). Markers sit on its
        landmark vertices.
    table : ArticulationTable, optional
        Phone → target table (default ``engine/library/articulation/finnish.phones``).
    markers : sequence of ids
        Virtual markers, in this order (default :data:`DEFAULT_MARKERS`):
        the model's landmarks, or the reference points :func:`marker_vertices` places.
    rate_hz : float
        Frames per second (60, like the paper's MacReflex).
    linear : bool
        True: markers are exactly ``rest + Σ tracks_k · basis_k`` (a known
        linear subspace). False (default): the head's real deformation.
    head_motion : bool
        Add smooth random rigid motion of the whole head: rotations of about
        ``head_rotation_deg`` degrees and translations of about
        ``head_translation_mm`` mm, a few tenths of a hertz.
    noise_mm : float
        Standard deviation of Gaussian marker noise per coordinate, mm.
    gaps : bool
        Add missing samples (NaN): isolated dropouts with probability
        ``dropout_probability`` per marker and frame, gaps of ``gap_frames``
        (min, max) frames at ``gaps_per_minute`` per marker, and one long gap
        of ``long_gap_frames`` frames on one lip marker (too long to fill).
    seed : int
        One seed, one recording.

    Raises :class:`UserError` for markers the model lacks or phones that are
    empty, and :class:`~engine.speech.synthesis.SynthesisError` when Festival
    is needed but missing.
    """
    from engine.formats.model_files import load_model
    from engine.speech.articulation import load_articulation
    from engine.speech.coarticulation import articulation_tracks

    model = load_model() if model is None else model
    table = load_articulation() if table is None else table
    if not (np.isfinite(rate_hz) and rate_hz > 0):
        raise UserError(f"the frame rate must be a positive number of frames per second, not {rate_hz}")
    markers = [str(m) for m in markers]
    places = marker_vertices(model, markers)
    if phones is None:
        text = DEFAULT_TEXT if text is None else text
        if synthesizer is None:
            from engine.speech.festival import FestivalSynthesizer
            synthesizer = FestivalSynthesizer()
        phones = synthesizer.synthesize(text, voice).phones
    segments = _segments(phones)
    if not segments:
        raise UserError("no phones to articulate")

    rng = np.random.default_rng(seed)
    end_ms = segments[-1].end_ms
    n_frames = int(np.floor(end_ms * rate_hz / 1000.0)) + 1
    times = np.arange(n_frames) * (1000.0 / rate_hz)

    sub = model_at_vertices(model, [places[m] for m in markers], landmarks={m: i for i, m in enumerate(markers)})
    names = [p for p in table.parameters if p in model.parameters]
    all_tracks = articulation_tracks(segments, _Subtable(table, names), times)
    basis_all = _jacobian(sub, names)
    moving = [k for k in range(len(names)) if np.abs(basis_all[k]).max() > 1e-9]
    parameters = [names[k] for k in moving]
    tracks = all_tracks[:, moving]
    basis = basis_all[moving]
    rest = sub.vertices.copy()

    if linear:
        clean = rest[None] + np.einsum("fp,pmc->fmc", tracks, basis)
    else:
        deformer = sub.deformer()
        order = {n: i for i, n in enumerate(sub.parameters.names)}
        values = np.zeros((n_frames, len(order)))
        for j, name in enumerate(parameters):
            values[:, order[name]] = tracks[:, j]
        clean = np.stack([deformer.deform(v) for v in values])

    pivot = _head_pivot(model)
    rotation = np.tile(np.eye(3), (n_frames, 1, 1))
    translation = np.zeros((n_frames, 3))
    if head_motion:
        angles = _smooth_noise(rng, times, 3, head_rotation_deg)
        rotation = _rotations(np.radians(angles))
        translation = _smooth_noise(rng, times, 3, head_translation_mm)
    observed = pivot + np.einsum("fij,fmj->fmi", rotation, clean - pivot) + translation[:, None, :]
    if noise_mm > 0:
        observed = observed + rng.normal(0.0, noise_mm, observed.shape)
    missing = np.zeros(observed.shape[:2], dtype=bool)
    if gaps:
        missing = _dropouts(rng, n_frames, markers, rate_hz, dropout_probability, gaps_per_minute,
                            gap_frames, long_gap_frames)
    observed[missing] = np.nan

    return SyntheticRecording(
        markers=markers, positions=observed, rate_hz=float(rate_hz),
        phones=[(s.start_ms, s.end_ms, s.label) for s in segments], missing=missing, clean=clean,
        rest=rest, parameters=parameters, tracks=tracks, basis=basis, head_rotation=rotation,
        head_translation=translation, head_pivot=pivot,
        reference=[m for m in markers if m in REFERENCE_MARKERS], text=text or "")


def marker_vertices(model: Model, markers: Iterable[str]) -> dict[str, int]:
    """Vertex of every marker: the model's landmark of that id, else a head-fixed point placed on the skin.

    Placed points (where the model has no landmark): ``9.12`` nose bridge
    (midline, at the height of the inner eye corners 3.8/3.11, frontmost),
    ``11.1`` forehead middle (midline, 45 mm above the brow tops 4.3/4.4),
    ``11.3`` / ``11.2`` forehead left / right (x = ±35 mm, 40 mm above the
    brows). Each is the frontmost skin vertex within 6 mm of that spot in
    x and y. Other ids the model lacks raise :class:`UserError`.
    """
    out = {}
    for m in markers:
        if m in model.landmarks:
            out[m] = int(model.landmarks[m])
        elif m in _PLACED:
            out[m] = _place(model, *_PLACED[m], marker=m)
        else:
            raise UserError(f"the model has no landmark for marker {m} (it has "
                            f"{', '.join(sorted(model.landmarks))}; placed points: {', '.join(_PLACED)})")
    return out


# id → (x mm or None for the midline, landmark pair whose mean y is the base, mm above it)
_PLACED = {"9.12": (0.0, ("3.8", "3.11"), 0.0), "11.1": (0.0, ("4.3", "4.4"), 45.0),
           "11.2": (-35.0, ("4.3", "4.4"), 40.0), "11.3": (35.0, ("4.3", "4.4"), 40.0)}


def _place(model: Model, x: float, base: tuple[str, ...], above: float, marker: str) -> int:
    if not all(b in model.landmarks for b in base) or "skin" not in model.parts:
        raise UserError(f"cannot place marker {marker}: the model needs landmarks {' and '.join(base)} and a skin part")
    y = np.mean([model.vertices[model.landmarks[b], 1] for b in base]) + above
    v = model.vertices
    near = np.flatnonzero((model.vertex_part == model.parts.index("skin"))
                          & (np.abs(v[:, 0] - x) <= 6.0) & (np.abs(v[:, 1] - y) <= 6.0))
    if not len(near):
        raise UserError(f"cannot place marker {marker}: no skin near x = {x:g}, y = {y:.0f} mm")
    return int(near[np.argmax(v[near, 2])])


# -- the pieces -----------------------------------------------------------------------

class _Subtable:
    """The articulation table restricted to the parameters the model has."""

    def __init__(self, table: ArticulationTable, names: Iterable[str]) -> None:
        self._table, self.parameters, self.exponent = table, list(names), table.exponent
        self._columns = [table.parameters.index(n) for n in names]

    def arrays(self, labels: list[str]) -> tuple[np.ndarray, ...]:
        return tuple(a[:, self._columns] for a in self._table.arrays(labels))


def _segments(phones: Phones) -> list[Segment]:
    from engine.speech.synthesis import Segment

    out = []
    for p in phones:
        if isinstance(p, Segment):
            out.append(p)
        elif isinstance(p, TimedLabel):
            out.append(Segment(str(p.label), float(p.start_ms), float(p.end_ms)))
        else:
            start, end, label = p[:3]
            out.append(Segment(str(label), float(start), float(end)))
    return out


def _jacobian(sub: Model, names: Iterable[str], step: float = 1e-4) -> np.ndarray:
    """(P, M, 3) derivative of the marker positions with respect to each parameter at rest (central)."""
    out = []
    for name in names:
        plus = sub.deform({name: step})
        minus = sub.deform({name: -step})
        out.append((plus - minus) / (2 * step))
    return np.array(out)


def _head_pivot(model: Model) -> np.ndarray:
    """Where the head turns: the pivot of the head nod if the model has one, else the mesh centre."""
    for name in ("head_nod", "head_turn", "head_tilt"):
        if name in model.parameters and model.parameters[name].kind == "rotation":
            return model.parameters[name].pivot.copy()
    return model.vertices.mean(axis=0)


def _smooth_noise(rng: np.random.Generator, times_ms: np.ndarray, n: int, amplitude: float) -> np.ndarray:
    """(F, n) smooth random signals: three sines per channel, 0.1–0.7 Hz, RMS ≈ ``amplitude``/√2."""
    t = times_ms / 1000.0
    out = np.zeros((len(t), n))
    for j in range(n):
        for _ in range(3):
            f = rng.uniform(0.1, 0.7)
            out[:, j] += rng.uniform(0.3, 1.0) * np.sin(2 * np.pi * f * t + rng.uniform(0, 2 * np.pi))
    return amplitude * out / 1.5


def _rotations(angles: np.ndarray) -> np.ndarray:
    """(F, 3, 3) rotations R = Rz · Ry · Rx from (F, 3) angles in radians."""
    cx, cy, cz = np.cos(angles).T
    sx, sy, sz = np.sin(angles).T
    zero, one = np.zeros_like(cx), np.ones_like(cx)
    rx = np.stack([np.stack([one, zero, zero], -1), np.stack([zero, cx, -sx], -1), np.stack([zero, sx, cx], -1)], 1)
    ry = np.stack([np.stack([cy, zero, sy], -1), np.stack([zero, one, zero], -1), np.stack([-sy, zero, cy], -1)], 1)
    rz = np.stack([np.stack([cz, -sz, zero], -1), np.stack([sz, cz, zero], -1), np.stack([zero, zero, one], -1)], 1)
    return rz @ ry @ rx


def _dropouts(rng: np.random.Generator, n_frames: int, markers: Sequence[str], rate_hz: float, probability: float,
              per_minute: float, gap_frames: tuple[int, int], long_gap: int) -> np.ndarray:
    missing = rng.random((n_frames, len(markers))) < probability
    minutes = n_frames / rate_hz / 60.0
    lo, hi = gap_frames
    for m in range(len(markers)):
        for _ in range(rng.poisson(per_minute * minutes)):
            length = int(rng.integers(lo, hi + 1))
            start = int(rng.integers(0, max(1, n_frames - length)))
            missing[start:start + length, m] = True
    lips = [i for i, name in enumerate(markers) if name.startswith("8.")]
    if long_gap > 0 and lips and n_frames > long_gap + 2:
        m = int(rng.choice(lips))
        start = int(rng.integers(1, n_frames - long_gap))
        missing[start:start + long_gap, m] = True
    return missing
