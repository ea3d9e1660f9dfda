"""The report's figures, drawn with matplotlib's Agg canvas (no window, no pyplot state): PNG bytes each.

* recognition: hit rate per emotion and condition, Wilson 95 % intervals, the chance of a guess (1/k);
* confusion: intended × response per condition, shade the share of the row, the counts written in;
* hu: Wagner's Hu (mean over participants) per emotion and condition, with its chance pc marked;
* ratings: each scale's mean per emotion and condition with its 95 % interval;
* machine: the ``validate`` observers' rate read as intended beside the participants' hit rate.
"""

from __future__ import annotations

import io
import math
from typing import Any

import numpy as np

from engine.study.analysis import ALL, Analysis, categories_of

__all__ = ["confusion_figure", "figures", "hu_figure", "machine_figure", "ratings_figure", "recognition_figure"]

COLOURS = {("synthetic", "static"): "#7fa7d6", ("synthetic", "dynamic"): "#1f5fa8", ("human", "static"): "#f2a672",
           ("human", "dynamic"): "#c1521b"}


def figures(analysis: Analysis) -> dict[str, bytes]:
    """Every figure that has something to show, by file name."""
    out: dict[str, bytes] = {}
    if analysis.recognition:
        out["recognition.png"] = recognition_figure(analysis)
        out["confusion.png"] = confusion_figure(analysis)
        out["hu.png"] = hu_figure(analysis)
    if analysis.ratings:
        out["ratings.png"] = ratings_figure(analysis)
    if analysis.validation_summary:
        out["validate-vs-people.png"] = machine_figure(analysis)
    return out


def _figure(width: float, height: float, columns: int = 1) -> tuple[Any, Any]:
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), dpi=100, layout="constrained")
    axes = fig.subplots(1, columns, squeeze=False)[0]
    return fig, axes


def _png(fig: Any) -> bytes:
    out = io.BytesIO()
    fig.savefig(out, format="png")
    return out.getvalue()


def _legend(ax: Any) -> None:
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)


def _label(condition: tuple[str, str]) -> str:
    return f"{condition[0]}, {condition[1]}"


def _grouped(ax: Any, emotions: list[str], conditions: list[tuple[str, str]],
             value: Any, interval: Any = None) -> None:
    width = 0.8 / max(1, len(conditions))
    for k, condition in enumerate(conditions):
        xs, ys, lows, highs = [], [], [], []
        for i, emotion in enumerate(emotions):
            found = value(condition, emotion)
            if found is None or (isinstance(found, float) and math.isnan(found)):
                continue
            xs.append(i - 0.4 + width * (k + 0.5))
            ys.append(found)
            if interval is not None:
                low, high = interval(condition, emotion)
                lows.append(max(0.0, found - low) if not math.isnan(low) else 0.0)
                highs.append(max(0.0, high - found) if not math.isnan(high) else 0.0)
        if not xs:
            continue
        ax.bar(xs, ys, width * 0.92, color=COLOURS.get(condition, "#888"), label=_label(condition))
        if interval is not None:
            ax.errorbar(xs, ys, yerr=[lows, highs], fmt="none", ecolor="#222", elinewidth=1, capsize=2)
    ax.set_xticks(range(len(emotions)), emotions, rotation=30, ha="right")


def recognition_figure(analysis: Analysis) -> bytes:
    rows = {(r["source"], r["presentation"], r["emotion"]): r for r in analysis.recognition}
    emotions = [*categories_of([r["emotion"] for r in analysis.recognition if r["emotion"] != ALL]), ALL]
    fig, (ax,) = _figure(max(6.0, 1.0 + 0.9 * len(emotions)), 3.8)
    _grouped(ax, emotions, analysis.conditions,
             lambda c, e: rows[(*c, e)]["rate"] if (*c, e) in rows else None,
             lambda c, e: (rows[(*c, e)]["ci_low"], rows[(*c, e)]["ci_high"]))
    chance = 1 / max(1, len(analysis.responses))
    ax.axhline(chance, color="#999", linestyle="--", linewidth=1, label=f"a guess (1/{len(analysis.responses)})")
    ax.set_ylim(0, 1.05)
    ax.set_ylabel("recognition rate")
    ax.set_title("Recognition per emotion (pooled; 95 % Wilson intervals)", fontsize=10)
    _legend(ax)
    return _png(fig)


def confusion_figure(analysis: Analysis) -> bytes:
    conditions = [c for c in analysis.conditions if c in analysis.confusion]
    columns = analysis.responses
    rows_most = max(len(analysis.confusion[c][0]) for c in conditions)
    across = min(2, len(conditions))
    down = -(-len(conditions) // across)
    from matplotlib.figure import Figure

    cell = 0.5 + 0.5 * len(columns)
    fig = Figure(figsize=(1.4 + across * cell, down * (1.4 + 0.42 * rows_most + 0.1 * len(columns))), dpi=100,
                 layout="constrained")
    axes = fig.subplots(down, across, squeeze=False).ravel()
    for ax in axes[len(conditions):]:
        ax.set_visible(False)
    for ax, condition in zip(axes, conditions, strict=False):
        rows, matrix = analysis.confusion[condition]
        counts = np.array(matrix, dtype=float)
        shares = counts / np.maximum(counts.sum(axis=1, keepdims=True), 1)
        ax.imshow(shares, cmap="Blues", vmin=0, vmax=1, aspect="auto")
        ax.set_xticks(range(len(columns)), columns, rotation=45, ha="right", fontsize=8)
        ax.set_yticks(range(len(rows)), rows, fontsize=8)
        for i in range(len(rows)):
            for j in range(len(columns)):
                if counts[i, j]:
                    ax.text(j, i, f"{int(counts[i, j])}", ha="center", va="center", fontsize=8,
                            color="white" if shares[i, j] > 0.5 else "black")
        ax.set_title(_label(condition), fontsize=10)
        ax.set_xlabel("response", fontsize=9)
        ax.set_ylabel("intended", fontsize=9)
    return _png(fig)


def hu_figure(analysis: Analysis) -> bytes:
    rows = {(r["source"], r["presentation"], r["emotion"]): r for r in analysis.recognition if r["emotion"] != ALL}
    emotions = categories_of([e for (_, _, e) in rows])
    fig, (ax,) = _figure(max(6.0, 1.0 + 0.9 * len(emotions)), 3.6)
    _grouped(ax, emotions, analysis.conditions, lambda c, e: rows[(*c, e)]["hu_mean"] if (*c, e) in rows else None)
    width = 0.8 / max(1, len(analysis.conditions))
    for k, condition in enumerate(analysis.conditions):
        xs = [i - 0.4 + width * (k + 0.5) for i, e in enumerate(emotions) if (*condition, e) in rows]
        ys = [rows[(*condition, e)]["pc_mean"] for e in emotions if (*condition, e) in rows]
        ax.scatter(xs, ys, marker="_", s=160, color="#111", linewidths=2,
                   label="chance pc" if k == 0 else None, zorder=3)
    ax.set_ylim(0, 1.05)
    ax.set_ylabel("unbiased hit rate Hu")
    ax.set_title("Unbiased hit rate Hu (mean over participants), chance pc marked", fontsize=10)
    _legend(ax)
    return _png(fig)


def ratings_figure(analysis: Analysis) -> bytes:
    scales = list(dict.fromkeys(r["scale"] for r in analysis.ratings))
    fig, axes = _figure(min(6.5 * len(scales), 16.0), 3.8, len(scales))
    for ax, scale in zip(axes, scales, strict=True):
        rows = {(r["source"], r["presentation"], r["emotion"]): r for r in analysis.ratings if r["scale"] == scale}
        emotions = [*categories_of([e for (_, _, e) in rows if e != ALL]), ALL]
        _grouped(ax, emotions, analysis.conditions,
                 lambda c, e, rows=rows: rows[(*c, e)]["mean"] if (*c, e) in rows else None,
                 lambda c, e, rows=rows: (rows[(*c, e)]["ci_low"], rows[(*c, e)]["ci_high"]))
        ax.set_title(f"{scale} (mean, 95 % interval)", fontsize=10)
        ax.set_ylabel(scale)
    _legend(axes[-1])
    return _png(fig)


def machine_figure(analysis: Analysis) -> bytes:
    presentations = list(dict.fromkeys(r["presentation"] for r in analysis.validation_summary))
    fig, axes = _figure(min(6.0 * len(presentations), 14.0), 3.6, len(presentations))
    for ax, presentation in zip(axes, presentations, strict=True):
        rows = [r for r in analysis.validation_summary if r["presentation"] == presentation]
        x = np.arange(len(rows))
        ax.bar(x - 0.2, [r["machine_rate"] for r in rows], 0.38, color="#6c757d", label="validate (stimuli)")
        ax.bar(x + 0.2, [r["people_rate"] for r in rows], 0.38, color=COLOURS[("synthetic", presentation)],
               label="participants (answers)")
        for bars in ax.containers:
            ax.bar_label(bars, fmt="%.2f", fontsize=7, padding=1)
        ax.set_xticks(x, [r["emotion"] for r in rows], rotation=30, ha="right")
        ax.set_ylim(0, 1.15)
        ax.set_ylabel("read as intended")
        ax.set_title(f"synthetic, {presentation}", fontsize=10)
    _legend(axes[-1])
    return _png(fig)
