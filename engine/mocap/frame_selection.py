"""Frame selection for the multistage PCA (§3.1.2): by phone labels or by explicit frame numbers.

The paper selected frames for every vowel and consonant (*"coordinates of
point 2.1 reveal opening of a jaw on which basis we selected frames for vowel
'a' and closed consonants like 'm' or 'p'"*). Here :func:`select_frames`
picks frames by phone labels — the middle of every vowel, consonant, chosen
phone or phone in a chosen context (``"a/p_p"``: *a* between *p*'s) — and
:func:`parse_frame_list` by explicit numbers; :func:`reselect_frames` chooses
again the frames an :attr:`~engine.mocap.pca.Articulation.selection` text
describes.

Times are ms; frame ``i`` of a recording is at ``i · 1000 / rate_hz`` ms.

>>> frame_list_text([0, 1, 2, 3, 4, 7, 10, 11])
'frames 0-4,7,10-11'
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TypeAlias

import numpy as np
import numpy.typing as npt

from engine.mocap.errors import MocapError
from engine.script.timed_labels import TimedLabel

VOWELS = frozenset(["a", "e", "i", "o", "u", "y", "@", "7"])          # Suopuhe's Finnish vowels (@ = ä, 7 = ö)
PAUSES = frozenset(["#", "##", "pau", "sil", "_"])


#: Phones as ``(start_ms, end_ms, label)`` triples or timed labels (:class:`~engine.speech.synthesis.Segment`).
Phones: TypeAlias = Iterable[tuple[float, float, str] | TimedLabel]


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


def select_frames(phones: Phones | None, n_frames: int, rate_hz: float,
                  selectors: str | Sequence[str] = ("V", "C"), position: float = 0.5) -> FrameSelection:
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
        frame = round((start + position * (end - start)) * rate_hz / 1000.0)
        if not 0 <= frame < n_frames:
            outside += 1
            continue
        chosen.setdefault(frame, label)
    frames = np.array(sorted(chosen), dtype=np.int64)
    description = "phones " + " ".join(selectors) + (f" position={position:g}" if position != 0.5 else "")
    return FrameSelection(frames, [chosen[f] for f in frames], description, outside)


def reselect_frames(selection: str, phones: Phones | None, n_frames: int, rate_hz: float) -> np.ndarray:
    """The frames an :attr:`~engine.mocap.pca.Articulation.selection` text describes, chosen again.

    The phones and frames are those of the recording the PCA analysed.
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


def frame_list_text(frames: npt.ArrayLike, limit: int = 30000) -> str:
    """``"frames 0-4,7,10-20"`` for a frame list (``parse_frame_list`` reads it back); a count if too long.

    ``limit`` is the longest text in characters; a longer list becomes ``"N listed frames"``.
    """
    f = np.unique(np.asarray(frames, dtype=np.int64).reshape(-1))
    if not len(f):
        return "frames (none)"
    breaks = np.flatnonzero(np.diff(f) != 1)
    starts, ends = f[np.r_[0, breaks + 1]], f[np.r_[breaks, len(f) - 1]]
    text = "frames " + ",".join(str(a) if a == b else f"{a}-{b}" for a, b in zip(starts, ends, strict=True))
    return text if len(text) <= limit else f"{len(f)} listed frames"    # HDF5 attributes stay under 64 kB


def _parse_selector(text: str) -> tuple[frozenset[str], ...]:
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


def _matches(label: str, items: Iterable[str]) -> bool:
    base = label[:-1] if label.endswith(":") else label
    for item in items:
        if item in ("*", label, base):
            return True
        if item == "V" and base in VOWELS:
            return True
        if item == "C" and base not in VOWELS and label not in PAUSES:
            return True
        if item == "#" and label in PAUSES:
            return True
    return False


def _phone_triples(phones: Phones | None) -> list[tuple[float, float, str]]:
    out = []
    for p in phones or []:
        if isinstance(p, TimedLabel):
            out.append((float(p.start_ms), float(p.end_ms), str(p.label)))
        else:
            start, end, label = p[:3]
            out.append((float(start), float(end), str(label)))
    return out
