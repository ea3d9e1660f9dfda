"""The one-page HTML report of a validation: figures and tables, every picture inside the file.

It opens offline in any browser (no script, no link to anything outside it): the headline
figures, the confusion matrix of intended × judged emotion as a heat map, the identity distance
matrix, the lip-aperture traces of the videos against the engine's intended lip gap, the worst
files first with a thumbnail of each still, and what each observer is and may be used for.
Figures are drawn with matplotlib's Agg canvas (no window, no global pyplot state).
"""

from __future__ import annotations

import base64
import html
import io
from pathlib import Path
from typing import Any

import numpy as np

from engine.formats.atomic import atomic_write_text
from engine.validation.judge import Verdict
from engine.validation.observers import EMOTIONS, SAME_PERSON, model_facts
from engine.validation.summary import NO_FACE, Summary
from engine.validation.table import verdict_row

WORST_SHOWN = 24
TRACES_SHOWN = 6
THUMBNAIL = 96

STYLE = """
body { font: 14px/1.45 system-ui, sans-serif; margin: 24px auto; max-width: 1100px; color: #222; }
h1 { font-size: 22px; } h2 { font-size: 17px; margin-top: 28px; border-bottom: 1px solid #ddd; }
table { border-collapse: collapse; font-size: 12px; } td, th { border: 1px solid #ddd; padding: 3px 6px; }
th { background: #f4f4f4; } .bad { color: #b00; } .ok { color: #070; }
.figs img { max-width: 49%; vertical-align: top; }
.note { color: #555; font-size: 12px; }
"""


def write_report(summary: Summary, path: str | Path, title: str = "Validation") -> None:
    """The report of ``summary`` in ``path`` (written atomically)."""
    atomic_write_text(path, report_html(summary, title))


def report_html(summary: Summary, title: str = "Validation") -> str:
    """The report as one HTML text."""
    parts = [f"<!doctype html><html lang='en'><meta charset='utf-8'><title>{html.escape(title)}</title>",
             f"<style>{STYLE}</style><body><h1>{html.escape(title)}</h1>", _headline(summary)]
    figures = []
    if summary.scored:
        figures.append(_image(_confusion_figure(summary), "confusion matrix of intended and judged emotion"))
    if len(summary.identities) > 1:
        figures.append(_image(_identity_figure(summary), "identity distance matrix"))
    if figures:
        parts.append(f"<h2>Figures</h2><div class='figs'>{''.join(figures)}</div>")
    traces = [v for v in summary.verdicts if v.aperture_trace is not None][:TRACES_SHOWN]
    if traces:
        parts.append("<h2>Lips: aperture seen in each frame against the lip gap the engine meant</h2>")
        parts.append(_image(_traces_figure(traces), "lip aperture traces"))
    parts.append(_worst_table(summary))
    parts.append(_observers_table())
    parts.append("</body></html>")
    return "\n".join(parts)


def _headline(summary: Summary) -> str:
    n = len(summary.verdicts)
    unreadable = sum(1 for v in summary.verdicts if v.emotions is None)
    lines = [f"{n} file{'s' if n != 1 else ''} judged; {n - unreadable} with a face"
             + (f", {unreadable} without (see the table)" if unreadable else "") + "."]
    if summary.scored:
        share = 100 * summary.read / summary.scored
        mean = summary.mean_intended_probability
        lines.append(f"Emotion read as intended: <b>{summary.read} of {summary.scored} ({share:.0f} %)</b>"
                     + (f"; mean probability of the intended class {mean:.2f}." if mean is not None else "."))
    if len(summary.identities) > 1:
        pairs = len(summary.identities) * (len(summary.identities) - 1) // 2
        same = len(summary.same_person_pairs)
        lines.append(f"Identities: {len(summary.identities)}; <b>{pairs - same} of {pairs} pairs are different "
                     f"people</b> to the face recogniser (distance ≥ {SAME_PERSON}).")
        own = [v for v in summary.verdicts if v.identity_own is not None and v.nearest_other_distance is not None]
        if own:
            nearest = sum(1 for v in own if (v.identity_own or 0.0) < (v.nearest_other_distance or 0.0))
            lines.append(f"Files nearest their own identity: {nearest} of {len(own)}.")
    lips = [v.lips for v in summary.verdicts if v.lips is not None and v.lips.r is not None]
    if lips:
        rs = [c.r for c in lips if c.r is not None]
        closures = sum(c.closures_intended for c in lips)
        seen = sum(c.closures_seen for c in lips)
        lines.append(f"Lips: aperture against the engine's lip gap r = {min(rs):.2f}–{max(rs):.2f} over "
                     f"{len(rs)} video{'s' if len(rs) != 1 else ''}; bilabial closures seen {seen} of {closures}.")
    return "".join(f"<p>{line}</p>" for line in lines)


def _confusion_figure(summary: Summary) -> bytes:
    rows = [e for e in EMOTIONS if any(summary.confusion[e].values())]
    columns = [*EMOTIONS, NO_FACE]
    counts = np.array([[summary.confusion[r][c] for c in columns] for r in rows], dtype=float)
    shares = counts / np.maximum(counts.sum(axis=1, keepdims=True), 1)
    fig, ax = _figure(6.4, max(2.6, 1.4 + 0.45 * len(rows)))
    ax.imshow(shares, cmap="Blues", vmin=0, vmax=1, aspect="auto")
    ax.set_xticks(range(len(columns)), columns, rotation=40, ha="right")
    ax.set_yticks(range(len(rows)), rows)
    ax.set_xlabel("judged")
    ax.set_ylabel("intended")
    for i in range(len(rows)):
        for j in range(len(columns)):
            if counts[i, j]:
                ax.text(j, i, f"{int(counts[i, j])}", ha="center", va="center",
                        color="white" if shares[i, j] > 0.5 else "black", fontsize=9)
    ax.set_title("Intended × judged emotion (counts; shade: share of the row)")
    return _png(fig)


def _identity_figure(summary: Summary) -> bytes:
    d = np.array(summary.identity_distances)
    names = [n if len(n) <= 28 else n[:27] + "…" for n in summary.identities]
    size = 1.6 + 0.45 * len(names)
    fig, ax = _figure(size + 1.2, size)
    image = ax.imshow(d, cmap="viridis_r", vmin=0, vmax=max(1.0, float(d.max())))
    ax.set_xticks(range(len(names)), names, rotation=40, ha="right", fontsize=8)
    ax.set_yticks(range(len(names)), names, fontsize=8)
    for i in range(len(names)):
        for j in range(len(names)):
            light = d[i, j] < 0.45 * max(1.0, float(d.max()))
            ax.text(j, i, f"{d[i, j]:.2f}", ha="center", va="center", fontsize=7,
                    color="red" if i != j and d[i, j] < SAME_PERSON else ("black" if light else "white"),
                    fontweight="bold" if i != j and d[i, j] < SAME_PERSON else "normal")
    fig.colorbar(image, ax=ax, label="distance (< 0.6: same person)")
    ax.set_title("Distances between identities")
    return _png(fig)


def _traces_figure(verdicts: list[Verdict]) -> bytes:
    fig, axes = _figure(9.6, 1.9 * len(verdicts), rows=len(verdicts))
    for ax, v in zip(np.atleast_1d(axes), verdicts, strict=True):
        assert v.aperture_trace is not None
        times, aperture, gaps = v.aperture_trace
        ax.plot(times, aperture, color="tab:blue", lw=1.2, label="seen (inter-ocular distances)")
        ax.set_ylabel("seen")
        if gaps is not None:
            twin = ax.twinx()
            twin.plot(times, gaps, color="tab:orange", lw=1.0, label="engine (mm)")
            twin.set_ylabel("engine, mm")
        r = "" if v.lips is None or v.lips.r is None else f"  r = {v.lips.r:.2f}"
        ax.set_title(f"{Path(v.file).name}{r}", fontsize=9, loc="left")
    np.atleast_1d(axes)[-1].set_xlabel("time, ms")
    return _png(fig)


def _worst_table(summary: Summary) -> str:
    shown = ["file", "status", "intended_expression", "intended_emotion", "judged_emotion", "judged_probability",
             "intended_probability", "identity", "identity_distance_own", "nearest_other_distance", "lip_r"]
    head = "".join(f"<th>{html.escape(c.replace('_', ' '))}</th>" for c in ["", *shown])
    lines = []
    for v in summary.worst()[:WORST_SHOWN]:
        row = verdict_row(v)
        row["file"] = Path(v.file).name
        good = v.read_as_intended
        mark = "bad" if good is False or v.emotions is None else "ok"
        cells = "".join(f"<td class='{mark if c == 'judged_emotion' else ''}'>{html.escape(str(row[c]))}</td>"
                        for c in shown)
        lines.append(f"<tr><td>{_thumbnail(v)}</td>{cells}</tr>")
    more = len(summary.verdicts) - WORST_SHOWN
    tail = f"<p class='note'>{more} more in the CSV table.</p>" if more > 0 else ""
    return f"<h2>The worst first</h2><table><tr>{head}</tr>{''.join(lines)}</table>{tail}"


def _observers_table() -> str:
    rows = "".join(f"<tr><td>{html.escape(m.role)}</td><td>{html.escape(m.name)}</td><td>{html.escape(m.file)}</td>"
                   f"<td>{html.escape(m.trained_on)}</td><td>{html.escape(m.licence)}</td></tr>"
                   for m in model_facts())
    return ("<h2>The observers</h2><table><tr><th>judges</th><th>model</th><th>from</th><th>trained on</th>"
            f"<th>licence</th></tr>{rows}</table><p class='note'>Models trained on photographs of real people "
            "give a first, reproducible verdict; they do not replace a rating study with people. The 68-point "
            "landmark model may be used for research only.</p>")


def _thumbnail(v: Verdict) -> str:
    if v.kind != "image":
        return ""
    from PIL import Image

    try:
        with Image.open(v.file) as image:
            image.thumbnail((THUMBNAIL, THUMBNAIL))
            out = io.BytesIO()
            image.convert("RGB").save(out, format="JPEG", quality=80)
    except (OSError, ValueError):
        return ""
    return f"<img alt='' src='data:image/jpeg;base64,{base64.b64encode(out.getvalue()).decode()}'>"


def _figure(width: float, height: float, rows: int = 1) -> tuple[Any, Any]:
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), dpi=100, layout="constrained")
    axes = fig.subplots(rows, 1) if rows > 1 else fig.subplots()
    return fig, axes


def _png(fig: Any) -> bytes:
    out = io.BytesIO()
    fig.savefig(out, format="png")
    return out.getvalue()


def _image(png: bytes, alt: str) -> str:
    return f"<img alt='{html.escape(alt)}' src='data:image/png;base64,{base64.b64encode(png).decode()}'>"
