"""Multistage (guided) PCA of marker data (§3.1.2): the linear articulation model.

The paper selected frames for every vowel and consonant (*"coordinates of
point 2.1 reveal opening of a jaw on which basis we selected frames for vowel
'a' and closed consonants like 'm' or 'p'"*), then applied multistage PCA to
the lip-contour markers (8.x) and the jaw marker (2.1) and kept five
components. The frames come from :mod:`engine.mocap.frame_selection`.
Here:

* :func:`multistage_pca` runs the guided PCA. Stage 1 is a PCA of the jaw
  marker's coordinates; its first score is the jaw component, and its linear
  contribution (the regression of *every* analysed coordinate on that score)
  is removed from the data. Stage 2 is a PCA of the lip markers' residual,
  and so on. Every component is a displacement pattern over all analysed
  markers (M × 3, mm), scaled so that a value of 1 is one standard deviation
  of its score over the analysed frames.
* :meth:`Articulation.report` and :func:`describe_component` describe the
  result in words; :mod:`engine.mocap.component_plot` draws it and
  :mod:`engine.mocap.articulation_file` writes and reads the articulation
  file.

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
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np
import numpy.typing as npt

from engine.mocap.errors import MocapError
from engine.mocap.frame_selection import FrameSelection, frame_list_text


@dataclass(frozen=True)
class Stage:
    """One stage: which markers guide it (names or glob patterns such as ``8.*``) and how many components."""

    markers: tuple[str, ...]
    components: int = 1

    def __post_init__(self) -> None:
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

    def values(self, positions: npt.ArrayLike, markers: Sequence[str] | None = None) -> np.ndarray:
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

    def reconstruct(self, values: npt.ArrayLike) -> np.ndarray:
        """Marker positions (F, M, 3) mm for component values (F, C) (or (M, 3) for one (C,))."""
        v = np.asarray(values, dtype=float)
        return self.mean + np.tensordot(v, self.components, axes=(-1, 0))

    def _take(self, positions: npt.ArrayLike, markers: Sequence[str] | None) -> np.ndarray:
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
        lines.extend(f"{k + 1:3d}  {self.stages[k]:5d}  {100 * self.explained_variance_ratio[k]:7.1f} %"
                     f"  {100 * cumulative[k]:8.1f} %  {_largest_motion(self, k):<38s}  {describe_component(self, k)}"
                     for k in range(self.n_components))
        return "\n".join(lines) + "\n"


@runtime_checkable
class MarkerData(Protocol):
    """Named marker trajectories, such as a :class:`~engine.mocap.session.Session`: (F, M, 3) positions, mm."""

    @property
    def markers(self) -> Sequence[str]: ...
    @property
    def positions(self) -> np.ndarray: ...


def multistage_pca(source: Sequence[str] | MarkerData, positions: npt.ArrayLike | None = None, *,
                   stages: Sequence[Stage | str] | None = DEFAULT_STAGES,
                   frames: FrameSelection | npt.ArrayLike | None = None, analysed: str | Sequence[str] | None = None,
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
    frames : None, int sequence or :class:`~engine.mocap.frame_selection.FrameSelection`
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
        selection = "" if frames is None else frame_list_text(frames)
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
    for number, (stage, group) in enumerate(zip(stage_list, stage_names, strict=True), start=1):
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
        score_std=np.array(stds), n_frames=len(used), excluded_missing=int((~ok).sum()),
        selection=selection, rate_hz=float(rate) if rate is not None else float("nan"),
        source=source_name or src, frames=used)


def _unpack(source: Sequence[str] | MarkerData, positions: npt.ArrayLike | None, rate_hz: float | None,
            ) -> tuple[list[str], np.ndarray, float | None, np.ndarray | None, str]:
    missing = None
    src = ""
    if isinstance(source, MarkerData):
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


def _expand(patterns: str | Sequence[str], names: list[str]) -> list[str]:
    """Marker names matching the patterns, in the data's order; an error for patterns matching none."""
    patterns = [patterns] if isinstance(patterns, str) else list(patterns)
    out: list[str] = []
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
