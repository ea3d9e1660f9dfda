"""Writing Praat TextGrids (long text format) for tests: tiers of (start_ms, end_ms, label)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path


def textgrid_text(tiers: dict[str, Sequence[tuple[float, float, str]]], end_ms: float) -> str:
    """A TextGrid with one interval tier per entry; gaps become empty intervals, as Praat writes them."""
    out = ['File type = "ooTextFile"', 'Object class = "TextGrid"', "", "xmin = 0", f"xmax = {end_ms / 1000!r}",
           "tiers? <exists>", f"size = {len(tiers)}", "item []:"]
    for number, (name, raw) in enumerate(tiers.items(), start=1):
        intervals, at = [], 0.0
        for start, end, label in raw:
            if start > at:
                intervals.append((at, start, ""))
            intervals.append((start, end, label))
            at = end
        if end_ms > at:
            intervals.append((at, end_ms, ""))
        out += [f"    item [{number}]:", '        class = "IntervalTier"', f'        name = "{name}"',
                "        xmin = 0", f"        xmax = {end_ms / 1000!r}",
                f"        intervals: size = {len(intervals)}"]
        for index, (start, end, label) in enumerate(intervals, start=1):
            escaped = label.replace('"', '""')
            out += [f"        intervals [{index}]:", f"            xmin = {start / 1000!r}",
                    f"            xmax = {end / 1000!r}", f'            text = "{escaped}"']
    return "\n".join(out) + "\n"


def write_textgrid(path: Path, tiers: dict[str, Sequence[tuple[float, float, str]]], end_ms: float) -> Path:
    path.write_text(textgrid_text(tiers, end_ms), encoding="utf-8")
    return path
