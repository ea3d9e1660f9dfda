"""Frame selection and multistage (guided) PCA of marker data → the articulation file (§3.1.2).

The paper selected frames for every vowel and consonant (*"coordinates of
point 2.1 reveal opening of a jaw on which basis we selected frames for vowel
'a' and closed consonants like 'm' or 'p'"*), then applied multistage PCA to
the lip-contour markers (8.x) and the jaw marker (2.1) and kept five
components. Here:

* :func:`select_frames` picks frames by phone labels — the middle of every
  vowel, consonant, chosen phone or phone in a chosen context (``"a/p_p"``:
  *a* between *p*'s) — and :func:`parse_frame_list` by explicit numbers.
* :func:`multistage_pca` runs the guided PCA. Stage 1 is a PCA of the jaw
  marker's coordinates; its first score is the jaw component, and its linear
  contribution (the regression of *every* analysed coordinate on that score)
  is removed from the data. Stage 2 is a PCA of the lip markers' residual,
  and so on. Every component is a displacement pattern over all analysed
  markers (M × 3, mm), scaled so that a value of 1 is one standard deviation
  of its score over the analysed frames.
* :func:`save_articulation_file` / :func:`load_articulation_file` write and
  read the articulation file of DESIGN.md; :meth:`Articulation.report` and
  :func:`plot_components` describe the result in words and in a picture.

Lengths are mm, times ms; frame ``i`` of a recording is at ``i · 1000 /
rate_hz`` ms. ``docs/mocap-pca.md`` gives the mathematics and the file layout.

>>> import numpy as np
>>> rng = np.random.default_rng(0)
>>> jaw, lips = rng.normal(size=(2, 200, 1))
>>> pos = np.zeros((200, 3, 3))
>>> pos[:, 0, 1] = -5 * jaw[:, 0]                               # 2.1 moves down with the jaw
>>> pos[:, 1, 1], pos[:, 2, 0] = -3 * jaw[:, 0], 2 * lips[:, 0]  # 8.2 rides on it; 8.3 widens
>>> art = multistage_pca(["2.1", "8.2", "8.3"], pos, stages=[Stage(("2.1",), 1), Stage(("8.*",), 1)])
>>> art.stages.tolist(), round(float(art.explained_variance_ratio.sum()), 6)
([1, 2], 1.0)
"""

from __future__ import annotations

import fnmatch
import json
import re
from dataclasses import dataclass, field
from pathlib import Path

import h5py
import numpy as np

from engine.outputs.raster import draw_box, draw_dot, draw_line, draw_text
from engine.formats.atomic import atomic_path
from engine.mocap.errors import MocapError
from engine.mocap.hdf5_files import open_versioned, text_attribute

ARTICULATION_FORMAT = "artificial-person-articulation"
ARTICULATION_VERSION = 1
VOWELS = frozenset("a e i o u y @ 7".split())          # Suopuhe's Finnish vowels (@ = ä, 7 = ö)
PAUSES = frozenset(["#", "##", "pau", "sil", "_"])
LIP_CONTOUR = ("8.4", "8.6", "8.1", "8.5", "8.3", "8.7", "8.2", "8.8", "8.4")   # around the mouth


class ArticulationFileError(MocapError):
    """An articulation file is unreadable, not one this program wrote, of an unknown version, or inconsistent."""


# ---------------------------------------------------------------------------
# Frame selection
# ---------------------------------------------------------------------------

@dataclass
class FrameSelection:
    """Frames chosen for analysis, each with the phone it stands for (``""`` for explicit frames)."""

    frames: np.ndarray
    labels: list[str]
    description: str
    outside: int = 0
    """Requested frames that fall outside the recording (dropped)."""

    def __len__(self) -> int:
        return len(self.frames)


def select_frames(phones, n_frames: int, rate_hz: float, selectors=("V", "C"),
                  position: float = 0.5) -> FrameSelection:
    """The frames at the middle of the phones that match any of ``selectors``.

    Parameters
    ----------
    phones : list of ``(start_ms, end_ms, label)`` or segments (``.start_ms``, ``.end_ms``, ``.label``)
        On the recording's clock: frame ``i`` is at ``i · 1000 / rate_hz`` ms.
    n_frames, rate_hz : the recording's length in frames and its frame rate (Hz).
    selectors : str or sequence of str
        Each ``PHONES`` or ``PHONES/LEFT_RIGHT``; each part is a comma list of
        phone labels, classes ``V`` (vowels), ``C`` (consonants), ``#``
        (pauses) or ``*`` (anything); an empty ``LEFT`` or ``RIGHT`` means
        any neighbour. ``"V"``: all vowels; ``"m,p,b"``; ``"a/p_p"``: *a*
        between two *p*'s; ``"V/_#"``: vowels before a pause. A short label
        also matches its long form (``a`` matches ``a:``; write ``a:`` for the
        long one only).
    position : float
        Where in the phone, 0 (start) … 1 (end); 0.5 is the middle.

    >>> phones = [(0, 100, "#"), (100, 180, "p"), (180, 330, "a"), (330, 400, "p"), (400, 500, "a:")]
    >>> sel = select_frames(phones, 31, 60.0, "a/p_p")
    >>> sel.frames.tolist(), sel.labels
    ([15], ['a'])
    >>> select_frames(phones, 31, 60.0, "V").labels
    ['a', 'a:']
    """
    if isinstance(selectors, str):
        selectors = [selectors]
    if not 0 <= position <= 1:
        raise MocapError(f"the position within a phone must be between 0 and 1, not {position}")
    rules = [_parse_selector(s) for s in selectors]
    segments = _phone_triples(phones)
    labels = [s[2] for s in segments]
    chosen: dict[int, str] = {}
    outside = 0
    for i, (start, end, label) in enumerate(segments):
        left = labels[i - 1] if i > 0 else "#"
        right = labels[i + 1] if i + 1 < len(labels) else "#"
        if not any(_matches(label, t) and _matches(left, lft) and _matches(right, rgt) for t, lft, rgt in rules):
            continue
        frame = int(round((start + position * (end - start)) * rate_hz / 1000.0))
        if not 0 <= frame < n_frames:
            outside += 1
            continue
        chosen.setdefault(frame, label)
    frames = np.array(sorted(chosen), dtype=np.int64)
    description = "phones " + " ".join(selectors) + (f" position={position:g}" if position != 0.5 else "")
    return FrameSelection(frames, [chosen[f] for f in frames], description, outside)


def reselect_frames(selection: str, phones, n_frames: int, rate_hz: float) -> np.ndarray:
    """The frames an :attr:`Articulation.selection` text describes, chosen again in the same recording.

    ``""`` → every frame; ``"phones V C"`` (optionally ``position=0.3``) →
    :func:`select_frames`; ``"frames 0-99,120"`` → :func:`parse_frame_list`.
    Frames later left out for missing markers are included. Use it to find
    the frames a PCA did *not* analyse (held-out frames of the same session).

    >>> reselect_frames("frames 3,10-12", [], 100, 60.0).tolist()
    [3, 10, 11, 12]
    """
    text = str(selection).strip()
    if not text:
        return np.arange(n_frames)
    kind, _, rest = text.partition(" ")
    if kind == "frames":
        return parse_frame_list(rest, n_frames).frames
    if kind == "phones":
        words = rest.split()
        position = 0.5
        if words and words[-1].startswith("position="):
            position = float(words.pop()[len("position="):])
        return select_frames(phones, n_frames, rate_hz, words, position).frames
    raise MocapError(f"cannot tell which frames were analysed from the selection {text!r}")


def parse_frame_list(text: str, n_frames: int | None = None) -> FrameSelection:
    """Explicit frames from ``"0-99,120,200-300:5"`` (ranges inclusive, ``:step`` optional).

    >>> parse_frame_list("3,10-14:2").frames.tolist()
    [3, 10, 12, 14]
    """
    frames: set[int] = set()
    for item in str(text).replace(" ", "").split(","):
        if not item:
            continue
        m = re.fullmatch(r"(\d+)(?:-(\d+)(?::(\d+))?)?", item)
        if not m:
            raise MocapError(f"frame list item {item!r} is not a frame number or a range like 10-20 or 10-20:2")
        lo = int(m.group(1))
        hi = int(m.group(2)) if m.group(2) else lo
        step = int(m.group(3)) if m.group(3) else 1
        if hi < lo or step < 1:
            raise MocapError(f"frame range {item!r} is empty")
        frames.update(range(lo, hi + 1, step))
    outside = 0
    if n_frames is not None:
        outside = sum(1 for f in frames if f >= n_frames)
        frames = {f for f in frames if f < n_frames}
    ordered = np.array(sorted(frames), dtype=np.int64)
    return FrameSelection(ordered, [""] * len(ordered), f"frames {text}", outside)


def _frame_ranges(frames, limit: int = 30000) -> str:
    """``"frames 0-4,7,10-20"`` for a frame list (``parse_frame_list`` reads it back); a count if too long."""
    f = np.unique(np.asarray(frames, dtype=np.int64).reshape(-1))
    if not len(f):
        return "frames (none)"
    breaks = np.flatnonzero(np.diff(f) != 1)
    starts, ends = f[np.r_[0, breaks + 1]], f[np.r_[breaks, len(f) - 1]]
    text = "frames " + ",".join(str(a) if a == b else f"{a}-{b}" for a, b in zip(starts, ends))
    return text if len(text) <= limit else f"{len(f)} listed frames"    # HDF5 attributes stay under 64 kB


def _parse_selector(text: str):
    text = str(text).strip()
    if not text:
        raise MocapError("an empty phone selector (write e.g. V, C, a or a/p_p)")
    target, left, right = text, "", ""
    if "/" in text:
        target, context = text.split("/", 1)
        if "_" not in context:
            raise MocapError(f"phone selector {text!r}: the context after '/' must be LEFT_RIGHT, e.g. a/p_p")
        left, right = context.split("_", 1)
    if not target:
        raise MocapError(f"phone selector {text!r} names no phone before '/'")
    return tuple(frozenset(x for x in part.split(",") if x) or frozenset("*") for part in (target, left, right))


def _matches(label: str, items) -> bool:
    base = label[:-1] if label.endswith(":") else label
    for item in items:
        if item == "*" or item == label or item == base:
            return True
        if item == "V" and base in VOWELS:
            return True
        if item == "C" and base not in VOWELS and label not in PAUSES:
            return True
        if item == "#" and label in PAUSES:
            return True
    return False


def _phone_triples(phones) -> list[tuple[float, float, str]]:
    out = []
    for p in phones or []:
        if hasattr(p, "label"):
            out.append((float(p.start_ms), float(p.end_ms), str(p.label)))
        else:
            start, end, label = p[:3]
            out.append((float(start), float(end), str(label)))
    return out


# ---------------------------------------------------------------------------
# Multistage PCA
# ---------------------------------------------------------------------------

@dataclass(frozen=True)
class Stage:
    """One stage: which markers guide it (names or glob patterns such as ``8.*``) and how many components."""

    markers: tuple[str, ...]
    components: int = 1

    def __post_init__(self):
        markers = (self.markers,) if isinstance(self.markers, str) else tuple(self.markers)
        object.__setattr__(self, "markers", tuple(str(m) for m in markers))
        if not self.markers:
            raise MocapError("a PCA stage needs at least one marker")
        if int(self.components) != self.components or self.components < 1:
            raise MocapError(f"a PCA stage needs a whole number of components ≥ 1, not {self.components}")
        object.__setattr__(self, "components", int(self.components))


#: The paper's choice: the jaw (2.1) first, then four components of the lip contour (8.x): five in all.
DEFAULT_STAGES = (Stage(("2.1",), 1), Stage(("8.*",), 4))


def default_stages(n_components: int = 5) -> tuple[Stage, ...]:
    """The paper's stages for ``n_components`` in all: one jaw component (2.1), the rest from the lips (8.x).

    >>> [(s.markers, s.components) for s in default_stages(3)]
    [(('2.1',), 1), (('8.*',), 2)]
    """
    if int(n_components) != n_components or n_components < 1:
        raise MocapError(f"the number of components must be a whole number ≥ 1, not {n_components}")
    jaw = Stage(("2.1",), 1)
    return (jaw,) if n_components == 1 else (jaw, Stage(("8.*",), int(n_components) - 1))


def parse_stage(text: str) -> Stage:
    """A stage from ``"MARKERS:COMPONENTS"``, markers comma-separated, globs allowed.

    >>> parse_stage("8.*:4"), parse_stage("2.1")
    (Stage(markers=('8.*',), components=4), Stage(markers=('2.1',), components=1))
    """
    markers, _, count = str(text).partition(":")
    try:
        n = int(count) if count else 1
    except ValueError:
        raise MocapError(f"stage {text!r}: the number of components after ':' must be a whole number") from None
    return Stage(tuple(m for m in markers.replace(" ", "").split(",") if m), n)


@dataclass
class Articulation:
    """The result of multistage PCA: a linear model of the markers (mm).

    ``positions ≈ mean + Σ_k value_k · components[k]``, with ``value_k`` in
    standard deviations of component ``k``'s score over the analysed frames.
    """

    markers: list[str]
    mean: np.ndarray
    """(M, 3) mean marker positions over the analysed frames, mm."""
    components: np.ndarray
    """(C, M, 3) displacement of every marker for value 1 (= one standard deviation), mm."""
    explained_variance_ratio: np.ndarray
    """(C,) share of the total variance of all analysed coordinates each component removes."""
    stages: np.ndarray
    """(C,) 1-based stage that produced each component."""
    stage_markers: list[list[str]]
    """For each stage, the markers that guided it."""
    score_std: np.ndarray
    """(C,) standard deviation of each raw score (projection onto the stage markers' unit direction), mm."""
    n_frames: int = 0
    """Frames analysed."""
    excluded_missing: int = 0
    """Selected frames left out because an analysed marker was missing."""
    selection: str = ""
    rate_hz: float = float("nan")
    source: str = ""
    frames: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    """The frames analysed (indices into the recording)."""

    @property
    def n_components(self) -> int:
        return int(self.components.shape[0])

    def values(self, positions, markers=None) -> np.ndarray:
        """Least-squares component values (F, C) for marker positions (F, M, 3) or (M, 3), mm.

        ``markers`` names the columns of ``positions`` (default: this model's
        markers, in order). Missing coordinates (NaN) are left out of each
        frame's fit; a frame with none left gets NaN values.
        """
        x = self._take(positions, markers)
        single = x.ndim == 2
        x = x.reshape(-1, x.shape[-2] * 3) - self.mean.reshape(1, -1)
        basis = self.components.reshape(self.n_components, -1).T
        out = np.full((len(x), self.n_components), np.nan)
        ok = np.isfinite(x)
        complete = ok.all(axis=1)
        if complete.any():
            out[complete] = np.linalg.lstsq(basis, x[complete].T, rcond=None)[0].T
        for f in np.flatnonzero(~complete & ok.any(axis=1)):
            out[f] = np.linalg.lstsq(basis[ok[f]], x[f, ok[f]], rcond=None)[0]
        return out[0] if single else out

    def reconstruct(self, values) -> np.ndarray:
        """Marker positions (F, M, 3) mm for component values (F, C) (or (M, 3) for one (C,))."""
        v = np.asarray(values, dtype=float)
        return self.mean + np.tensordot(v, self.components, axes=(-1, 0))

    def _take(self, positions, markers) -> np.ndarray:
        x = np.asarray(positions, dtype=float)
        if markers is not None:
            markers = [str(m) for m in markers]
            absent = [m for m in self.markers if m not in markers]
            if absent:
                raise MocapError(f"the data lack the analysed markers {', '.join(absent)}")
            x = x[..., [markers.index(m) for m in self.markers], :]
        if x.shape[-2:] != (len(self.markers), 3):
            raise MocapError(f"marker positions have shape {x.shape}, expected (…, {len(self.markers)}, 3)")
        return x

    def report(self) -> str:
        """Explained variance per component and per stage, and what each component does, as text."""
        lines = [f"Multistage PCA of {len(self.markers)} markers ({', '.join(self.markers)})",
                 f"frames analysed: {self.n_frames}"
                 + (f" ({self.excluded_missing} more excluded: analysed markers missing)"
                    if self.excluded_missing else "")
                 + (f"; selection: {self.selection}" if self.selection else "")]
        for s, names in enumerate(self.stage_markers, start=1):
            mine = self.stages == s
            lines.append(f"stage {s} on {', '.join(names)}: {int(mine.sum())} component(s), "
                         f"{100 * self.explained_variance_ratio[mine].sum():.1f} % of the variance")
        lines.append(f"total: {100 * self.explained_variance_ratio.sum():.1f} % of the variance "
                     f"in {self.n_components} components")
        lines.append("")
        lines.append(" PC  stage  explained  cumulative  largest marker motion at +1 SD          looks like")
        cumulative = np.cumsum(self.explained_variance_ratio)
        for k in range(self.n_components):
            lines.append(f"{k + 1:3d}  {self.stages[k]:5d}  {100 * self.explained_variance_ratio[k]:7.1f} %"
                         f"  {100 * cumulative[k]:8.1f} %  {_largest_motion(self, k):<38s}  {describe_component(self, k)}")
        return "\n".join(lines) + "\n"


def multistage_pca(source, positions=None, *, stages=DEFAULT_STAGES, frames=None, analysed=None,
                   rate_hz: float | None = None, source_name: str = "") -> Articulation:
    """Multistage (guided) PCA of marker positions (§3.1.2).

    Parameters
    ----------
    source : list of marker names, or a session
        Marker names (MPEG-4 ids such as ``"8.1"``) for the columns of
        ``positions``; or an object with ``.markers``, ``.positions`` (and
        optionally ``.rate_hz``, ``.missing``, ``.source``), such as
        :class:`~engine.mocap.session.Session`.
    positions : (F, M, 3) array, mm
        Head motion already removed; NaN where a marker is missing.
    stages : sequence of :class:`Stage`
        Default :data:`DEFAULT_STAGES`: one jaw component from 2.1, then four
        lip components from 8.x.
    frames : None, int sequence or :class:`FrameSelection`
        The frames to analyse (default: all). Frames in which any analysed
        marker is missing are left out and counted.
    analysed : marker names, optional
        The markers whose motion the components describe (default: every
        marker any stage names, in the data's order). Extra markers (e.g.
        2.10) get displacement patterns without guiding a stage.

    Each stage takes the top principal components of its own markers'
    coordinates in the current residual. Their scores ``s`` (orthogonal to
    each other and to every earlier score) are regressed out of *every*
    analysed coordinate: the component is ``Rᵀs / sᵀs`` and the residual
    becomes ``R − s · componentᵀ``. The share of the total variance a
    component removes is ``|s|² |component|² / |X|²``; the shares add up to
    at most 1. Within a stage components are sorted by that share; the sign
    makes the dominant motion (down, outward or forward, see
    :func:`describe_component`) positive. Components are scaled to one
    standard deviation of their score.
    """
    names, positions, rate, missing, src = _unpack(source, positions, rate_hz)
    stage_list = [s if isinstance(s, Stage) else parse_stage(s) for s in (stages or ())]
    if not stage_list:
        raise MocapError("multistage PCA needs at least one stage")
    stage_names = [_expand(s.markers, names) for s in stage_list]
    if analysed is None:
        wanted = {m for group in stage_names for m in group}
        analysed = [m for m in names if m in wanted]
    else:
        analysed = _expand(analysed, names)
        for group in stage_names:
            lost = [m for m in group if m not in analysed]
            if lost:
                raise MocapError(f"stage markers {', '.join(lost)} are not among the analysed markers")
    columns = np.array([names.index(m) for m in analysed], dtype=np.int64)

    if isinstance(frames, FrameSelection):
        selection, frames = frames.description, frames.frames
    else:
        selection = "" if frames is None else _frame_ranges(frames)
    n_total = positions.shape[0]
    frames = np.arange(n_total) if frames is None else np.unique(np.asarray(frames, dtype=np.int64).reshape(-1))
    bad = frames[(frames < 0) | (frames >= n_total)]
    if len(bad):
        raise MocapError(f"frames {', '.join(map(str, bad[:5]))} are outside the recording (0–{n_total - 1})")
    x = positions[frames][:, columns]
    ok = np.isfinite(x).all(axis=(1, 2))
    if missing is not None:
        ok &= ~missing[frames][:, columns].any(axis=1)
    used = frames[ok]
    x = x[ok]
    n_comp = sum(s.components for s in stage_list)
    if len(used) < n_comp + 1:
        raise MocapError(f"only {len(used)} frames are usable ({int((~ok).sum())} of {len(frames)} selected "
                         f"have missing markers); {n_comp} components need at least {n_comp + 1}")

    mean = x.mean(axis=0)
    residual = (x - mean).reshape(len(used), -1)
    total = float(np.sum(residual ** 2))
    if total <= 0:
        raise MocapError("the analysed markers do not move in the selected frames")
    marker_pos = {m: i for i, m in enumerate(analysed)}
    comps, ratios, stage_of, stds = [], [], [], []
    for number, (stage, group) in enumerate(zip(stage_list, stage_names), start=1):
        cols = np.concatenate([np.arange(3) + 3 * marker_pos[m] for m in group])
        block = residual[:, cols]
        if stage.components > len(cols):
            raise MocapError(f"stage {number} asks for {stage.components} components but its markers "
                             f"({', '.join(group)}) have only {len(cols)} coordinates")
        _, sv, vt = np.linalg.svd(block, full_matrices=False)
        k = stage.components
        if len(sv) < k or sv[k - 1] ** 2 <= 1e-12 * total:
            have = int(np.sum(sv ** 2 > 1e-12 * total))
            raise MocapError(f"stage {number} ({', '.join(group)}) has variance left for only {have} "
                             f"component(s), not {k}")
        scores = block @ vt[:k].T                                 # (F, k), orthogonal columns
        norms = np.sum(scores ** 2, axis=0)
        patterns = (scores.T @ residual) / norms[:, None]         # (k, 3M): regression on each score
        explained = norms * np.sum(patterns ** 2, axis=1) / total
        residual = residual - scores @ patterns
        order = np.argsort(-explained, kind="stable")
        for j in order:
            std = np.sqrt(norms[j] / len(used))
            pattern = patterns[j].reshape(-1, 3) * std
            pattern *= _sign(pattern, mean)
            comps.append(pattern)
            ratios.append(explained[j])
            stage_of.append(number)
            stds.append(std)
    return Articulation(
        markers=list(analysed), mean=mean, components=np.array(comps), explained_variance_ratio=np.array(ratios),
        stages=np.array(stage_of, dtype=np.int64), stage_markers=[list(g) for g in stage_names],
        score_std=np.array(stds), n_frames=int(len(used)), excluded_missing=int((~ok).sum()),
        selection=selection, rate_hz=float(rate) if rate is not None else float("nan"),
        source=source_name or src, frames=used)


def _unpack(source, positions, rate_hz):
    missing = None
    src = ""
    if hasattr(source, "markers") and hasattr(source, "positions"):
        names = list(source.markers)
        positions = source.positions if positions is None else positions
        rate_hz = getattr(source, "rate_hz", None) if rate_hz is None else rate_hz
        missing = getattr(source, "missing", None)
        src = str(getattr(source, "source", "") or "")
    else:
        names = list(source)
        if positions is None:
            raise MocapError("marker positions are needed with a list of marker names")
    names = [str(m) for m in names]
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 3 or positions.shape[1:] != (len(names), 3):
        raise MocapError(f"marker positions have shape {positions.shape}, expected (frames, {len(names)}, 3)")
    if len(set(names)) != len(names):
        raise MocapError("marker names must be unique")
    if missing is not None:
        missing = np.asarray(missing, dtype=bool)
        if missing.shape != positions.shape[:2]:
            missing = None
    return names, positions, rate_hz, missing, src


def _expand(patterns, names) -> list[str]:
    """Marker names matching the patterns, in the data's order; an error for patterns matching none."""
    patterns = [patterns] if isinstance(patterns, str) else list(patterns)
    out = []
    for p in patterns:
        hits = [m for m in names if m == p or fnmatch.fnmatchcase(m, p)]
        if not hits:
            raise MocapError(f"no marker matches '{p}' (markers: {', '.join(names)})")
        out.extend(h for h in hits if h not in out)
    return [m for m in names if m in out]


def _measures(pattern: np.ndarray, mean: np.ndarray) -> dict[str, float]:
    """Mean downward, outward (away from the midline) and forward motion of the markers, mm."""
    centre_x = np.median(mean[:, 0])
    side = np.sign(mean[:, 0] - centre_x)
    return {"down": float(-pattern[:, 1].mean()), "out": float((pattern[:, 0] * side).mean()),
            "forward": float(pattern[:, 2].mean())}


def _dominant(pattern: np.ndarray, mean: np.ndarray) -> tuple[str, float]:
    """The measure that names a component: down, else forward, else out — the first at least half the largest."""
    m = _measures(pattern, mean)
    top = max(abs(v) for v in m.values())
    for key in ("down", "forward", "out"):
        if abs(m[key]) >= 0.5 * top:
            return key, m[key]
    raise AssertionError("unreachable")      # the largest measure passes its own test


def _sign(pattern: np.ndarray, mean: np.ndarray) -> float:
    return -1.0 if _dominant(pattern, mean)[1] < 0 else 1.0


_WORDS = {("down", 1): "lowering", ("down", -1): "raising",
          ("out", 1): "widening", ("out", -1): "narrowing (rounding)",
          ("forward", 1): "protrusion", ("forward", -1): "retraction"}


def describe_component(art: Articulation, k: int) -> str:
    """A word for what component ``k`` does at +1: the dominant mean motion of its markers.

    The measures are the markers' mean downward (−y), forward (+z) and
    outward (away from the midline in x) displacement, in mm; the first of
    them, in that order, that is at least half the largest in size names the
    component (the default head faces +Z with +Y up). The same measure fixes
    the sign in :func:`multistage_pca`, so it is always positive there.
    """
    key, value = _dominant(art.components[k], art.mean)
    word = _WORDS[(key, 1 if value >= 0 else -1)]
    stage = int(art.stages[k])
    guided_by_jaw = 0 < stage <= len(art.stage_markers) and "2.1" in art.stage_markers[stage - 1]
    return f"jaw opening ({word})" if guided_by_jaw and key == "down" else word


def _largest_motion(art: Articulation, k: int) -> str:
    d = art.components[k]
    i = int(np.argmax(np.linalg.norm(d, axis=1)))
    side = art.mean[i, 0] - np.median(art.mean[:, 0])
    if abs(side) > 1.0:                          # off the midline: in or out
        lateral = "out" if d[i, 0] * side > 0 else "in"
    else:                                        # on it: the subject's own left (+x) or right
        lateral = "left" if d[i, 0] > 0 else "right"
    axes = [(lateral, abs(d[i, 0])), ("down" if d[i, 1] < 0 else "up", abs(d[i, 1])),
            ("back" if d[i, 2] < 0 else "forward", abs(d[i, 2]))]
    words = ", ".join(f"{w} {v:.1f}" for w, v in axes if v >= 0.05) or "still"
    return f"{art.markers[i]}: {words} mm"


# ---------------------------------------------------------------------------
# The articulation file (DESIGN.md)
# ---------------------------------------------------------------------------

def save_articulation_file(art: Articulation, path: str | Path) -> Path:
    """Write the articulation file atomically (temporary file beside ``path``, then rename).

    Datasets exactly as DESIGN.md: ``markers`` (M names), ``mean`` (M × 3,
    mm), ``components`` (C × M × 3, mm at value 1 = one standard deviation),
    ``explained_variance_ratio`` (C), ``stages`` (C, 1-based). Attributes:
    ``format``, ``version``, ``units``, ``component_scale``, ``score_std_mm``
    (C), ``stage_markers`` (JSON), ``n_frames``, ``excluded_missing``,
    ``selection``, ``rate_hz``, ``source``.
    """
    path = Path(path)
    _check_arrays(art, path)
    text = h5py.string_dtype()
    with atomic_path(path, ArticulationFileError) as tmp, h5py.File(tmp, "w", track_order=True) as f:
        f.attrs["format"] = ARTICULATION_FORMAT
        f.attrs["version"] = ARTICULATION_VERSION
        f.attrs["units"] = "mm"
        f.attrs["component_scale"] = "value 1 = one standard deviation of the component's score"
        f.attrs["score_std_mm"] = np.asarray(art.score_std, dtype=float)
        f.attrs["stage_markers"] = json.dumps(art.stage_markers)
        f.attrs["n_frames"] = int(art.n_frames)
        f.attrs["excluded_missing"] = int(art.excluded_missing)
        f.attrs["selection"] = str(art.selection)
        f.attrs["rate_hz"] = float(art.rate_hz)
        f.attrs["source"] = str(art.source)
        f.create_dataset("markers", data=np.array(art.markers, dtype=object), dtype=text)
        f.create_dataset("mean", data=np.asarray(art.mean, dtype=float))
        f.create_dataset("components", data=np.asarray(art.components, dtype=float))
        f.create_dataset("explained_variance_ratio", data=np.asarray(art.explained_variance_ratio, dtype=float))
        f.create_dataset("stages", data=np.asarray(art.stages, dtype=np.int64))
    return path


def load_articulation_file(path: str | Path) -> Articulation:
    """Read and check an articulation file; :class:`ArticulationFileError` naming the file otherwise."""
    path = Path(path)
    with open_versioned(path, ARTICULATION_FORMAT, ARTICULATION_VERSION, ArticulationFileError,
                        "an articulation file", "mocap pca") as f:
        def dataset(name):
            if name not in f or not isinstance(f[name], h5py.Dataset):
                raise ArticulationFileError(f"missing dataset '/{name}'", file=path)
            return np.asarray(f[name][()])

        markers = [text_attribute(m) for m in np.atleast_1d(dataset("markers")).tolist()]
        numbers = {}
        for name in ("mean", "components", "explained_variance_ratio", "stages"):
            try:
                numbers[name] = dataset(name).astype(float)
            except (TypeError, ValueError):
                raise ArticulationFileError(f"dataset '/{name}' does not hold numbers", file=path) from None
        n_comp = numbers["components"].shape[0] if numbers["components"].ndim else 0
        try:
            score_std = np.asarray(f.attrs.get("score_std_mm", np.full(n_comp, np.nan)), dtype=float).reshape(-1)
            stage_markers = json.loads(text_attribute(f.attrs.get("stage_markers")) or "[]")
        except (TypeError, ValueError):
            raise ArticulationFileError("the attributes 'score_std_mm' or 'stage_markers' are damaged",
                                        file=path) from None
        art = Articulation(
            markers=markers, mean=numbers["mean"], components=numbers["components"],
            explained_variance_ratio=numbers["explained_variance_ratio"], stages=numbers["stages"],
            stage_markers=stage_markers, score_std=score_std,
            n_frames=int(f.attrs.get("n_frames", 0)), excluded_missing=int(f.attrs.get("excluded_missing", 0)),
            selection=text_attribute(f.attrs.get("selection")) or "", rate_hz=float(f.attrs.get("rate_hz", np.nan)),
            source=text_attribute(f.attrs.get("source")) or "")
    _check_arrays(art, path)
    art.stages = art.stages.astype(np.int64)
    return art


def _check_arrays(art: Articulation, path) -> None:
    def fail(message):
        raise ArticulationFileError(message, file=path)

    m = len(art.markers)
    if m == 0:
        fail("the articulation has no markers")
    if any(not isinstance(n, str) or not n for n in art.markers) or len(set(art.markers)) != m:
        fail("marker names must be unique, non-empty text")
    mean = np.asarray(art.mean)
    comps = np.asarray(art.components)
    if mean.shape != (m, 3):
        fail(f"'mean' has shape {mean.shape}, expected ({m}, 3) for {m} markers")
    if comps.ndim != 3 or comps.shape[1:] != (m, 3):
        fail(f"'components' has shape {comps.shape}, expected (components, {m}, 3)")
    c = comps.shape[0]
    if c == 0:
        fail("the articulation has no components")
    ratio = np.asarray(art.explained_variance_ratio)
    stages = np.asarray(art.stages)
    if ratio.shape != (c,):
        fail(f"'explained_variance_ratio' has shape {ratio.shape}, expected ({c},) for {c} components")
    if stages.shape != (c,):
        fail(f"'stages' has shape {stages.shape}, expected ({c},) for {c} components")
    if not (np.all(np.isfinite(mean)) and np.all(np.isfinite(comps)) and np.all(np.isfinite(ratio))):
        fail("'mean', 'components' and 'explained_variance_ratio' must be finite numbers")
    if np.any(ratio < 0) or np.any(ratio > 1) or ratio.sum() > 1 + 1e-9:
        fail(f"explained variance ratios must lie in [0, 1] and sum to at most 1 (they sum to {ratio.sum():.6g})")
    if not np.all(np.isfinite(stages)) or np.any(stages != np.round(stages)) or np.any(stages < 1) \
            or np.any(np.diff(stages) < 0):
        fail("'stages' must be whole numbers ≥ 1 in non-decreasing order")
    if np.asarray(art.score_std).shape != (c,):
        fail(f"the attribute 'score_std_mm' must hold {c} numbers")


# ---------------------------------------------------------------------------
# The picture
# ---------------------------------------------------------------------------

PANEL = 300            # pixels per panel side
HEADER = 22            # pixels of text above each row


def plot_components(art: Articulation, path: str | Path | None = None, amplitude: float = 2.0) -> np.ndarray:
    """A picture of every component as marker displacements: one row per component, front and side views.

    Grey: the mean markers (the lip contour 8.x joined in order); red: the
    shape at ``+amplitude`` standard deviations, blue at ``−amplitude``, with
    a line from each mean marker to its ``+`` position. Both views use one
    scale (true mm), the front view with the subject's left on the right,
    the side view with the face to the right. A component whose largest
    motion would be too small to see is magnified, and its row says by how
    much (``X5``). Returns the (H, W, 3) uint8
    image and, with ``path``, writes it as PNG.
    """
    from engine.outputs.render import write_png

    views = (("FRONT", 0, 1), ("SIDE", 2, 1))
    # Small components are drawn magnified (×2, ×5, ×10 …, shown in the row's title) so that
    # their largest marker motion is at least 4 % of the picture's span.
    span = max(float(np.ptp(art.mean, axis=0).max()), 1e-6)
    gains = [_gain(amplitude * np.abs(c).max(), 0.04 * span) for c in art.components]
    shapes = [art.mean] + [art.mean + s * g * amplitude * c for c, g in zip(art.components, gains) for s in (1, -1)]
    pts = np.concatenate(shapes)
    n_rows = art.n_components
    width, height = 2 * PANEL, n_rows * (PANEL + HEADER) + 2 * HEADER
    image = np.full((height, width, 3), 255, dtype=np.uint8)
    extent = max(float(np.ptp(pts, axis=0).max()), 1e-6)
    scale = 0.8 * PANEL / extent
    grey, red, blue = (150, 150, 150), (210, 30, 30), (30, 60, 210)
    draw_text(image, "GREY MEAN", 8, 4, grey)
    draw_text(image, f"RED +{amplitude:g} SD", 140, 4, red)
    draw_text(image, f"BLUE -{amplitude:g} SD", 290, 4, blue)
    for col, (title, ax, ay) in enumerate(views):
        draw_text(image, title, col * PANEL + PANEL // 2 - 6 * len(title) // 2, HEADER + 4, (0, 0, 0))
    contour = [art.markers.index(m) for m in LIP_CONTOUR if m in art.markers]
    for k in range(n_rows):
        top = 2 * HEADER + k * (PANEL + HEADER)
        label = f"PC{k + 1}  STAGE {art.stages[k]}  {100 * art.explained_variance_ratio[k]:.1f}%"
        if gains[k] != 1:
            label += f"  X{gains[k]:g}"
        draw_text(image, label, 8, top + 6, (0, 0, 0))
        shown = gains[k] * amplitude * art.components[k]
        for col, (_, ax, ay) in enumerate(views):
            left = col * PANEL
            centre = np.array([pts[:, ax].min() + pts[:, ax].max(), pts[:, ay].min() + pts[:, ay].max()]) / 2

            def to_px(p, left=left, ax=ax, ay=ay, centre=centre):
                return np.column_stack([left + PANEL / 2 + (p[:, ax] - centre[0]) * scale,
                                        top + HEADER + PANEL / 2 - (p[:, ay] - centre[1]) * scale])

            draw_box(image, left, top + HEADER, PANEL, PANEL - 2, (225, 225, 225))
            mean_px = to_px(art.mean)
            plus_px = to_px(art.mean + shown)
            minus_px = to_px(art.mean - shown)
            for shape, colour in ((mean_px, grey), (minus_px, blue), (plus_px, red)):
                if len(contour) > 1:
                    for a, b in zip(contour[:-1], contour[1:]):
                        draw_line(image, shape[a], shape[b], colour)
            for i in range(len(art.markers)):
                draw_line(image, mean_px[i], plus_px[i], red)
                draw_dot(image, minus_px[i], blue, 2)
                draw_dot(image, plus_px[i], red, 2)
                draw_dot(image, mean_px[i], (60, 60, 60), 2)
    if path is not None:
        write_png(path, image)
    return image


def _gain(largest: float, wanted: float) -> float:
    """1, or the smallest of 2, 5, 10, 20, 50 … that makes ``largest`` at least ``wanted``."""
    if largest <= 0 or largest >= wanted:
        return 1.0
    for exponent in range(0, 7):
        for step in (1, 2, 5):
            gain = step * 10.0 ** exponent
            if gain > 1 and largest * gain >= wanted:
                return gain
    return 1e6
