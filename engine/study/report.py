"""``study-analyse``'s folder: ``report.html`` (one page, every figure inside it), ``figures/*.png`` and the tables
as CSV for R or pandas — all written together (engine.formats.atomic).

============================  ===========================================================================
``trials.csv``                every trial read (practice and attention checks too), ``included`` 1/0
``participants.csv``          each participant: trials, attention checks passed, kept or not, hit rate
``recognition.csv``           per condition and emotion: trials, hits, rate and its Wilson interval, the
                              participants' mean rate, Hu and pc (means and pooled), Hu against pc (t, p)
``confusion.csv``             per condition: intended × response, count and share of the row (long)
``hu.csv``                    per participant, condition and emotion: stimuli, responses, hits, Hu, pc
``ratings.csv``               per scale, condition and emotion: trials, mean, sd, 95 % interval
``contrasts.csv``             dynamic − static, synthetic − human: pooled and paired differences
``validate-vs-people.csv``    with ``--set``: each stimulus's ``validate`` verdict beside the answers to it
============================  ===========================================================================
"""

from __future__ import annotations

import base64
import csv
import html
import io
import math
from pathlib import Path
from typing import Any

from engine.formats.atomic import atomic_files
from engine.study.analysis import ALL, Analysis
from engine.study.figures import figures

__all__ = ["report_html", "tables", "write_report"]

STYLE = """
body { font: 14px/1.45 system-ui, sans-serif; margin: 24px auto; max-width: 1150px; color: #222;
       padding: 0 12px; }
h1 { font-size: 22px; } h2 { font-size: 17px; margin-top: 28px; border-bottom: 1px solid #ddd; }
table { border-collapse: collapse; font-size: 12px; margin: 6px 0; }
td, th { border: 1px solid #ddd; padding: 3px 6px; }
th { background: #f4f4f4; } td.n { text-align: right; font-variant-numeric: tabular-nums; }
figure { margin: 10px 0; } figure img { max-width: 100%; } figcaption { color: #555; font-size: 12px; }
.note { color: #555; font-size: 12px; } .warn { color: #a40; }
"""


def _text(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.6g}"
    return str(value)


def _csv(rows: list[dict[str, Any]], columns: list[str] | None = None) -> str:
    columns = columns or (list(rows[0]) if rows else [])
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(columns)
    for row in rows:
        writer.writerow([_text(row.get(c)) for c in columns])
    return out.getvalue()


def tables(analysis: Analysis) -> dict[str, str]:
    """Every table as CSV text, by file name."""
    kept = {id(t) for t in analysis.included}
    trial_rows = []
    for t in analysis.results.trials:
        row: dict[str, Any] = {"participant": t.participant, "trial": t.trial, "phase": t.phase, "stimulus": t.stimulus,
                               "source": t.source, "presentation": t.presentation, "intended": t.intended,
                               "response": t.response, "correct": t.correct, "rt": t.rt, "expected": t.expected,
                               "included": id(t) in kept}
        row.update({f"rating_{s}": t.ratings.get(s) for s in analysis.results.scales})
        row.update(t.levels)
        row["file"] = t.file
        trial_rows.append(row)
    columns = list(dict.fromkeys(c for r in trial_rows for c in r))
    out = {"trials.csv": _csv(trial_rows, columns), "participants.csv": _csv(analysis.participants)}
    if analysis.recognition:
        out["recognition.csv"] = _csv(analysis.recognition)
        confusion = []
        for (source, presentation), (rows, matrix) in analysis.confusion.items():
            for intended, counts in zip(rows, matrix, strict=True):
                total = sum(counts)
                for response, count in zip(analysis.responses, counts, strict=True):
                    confusion.append({"source": source, "presentation": presentation, "intended": intended,
                                      "response": response, "count": count, "share": count / total if total else 0.0})
        out["confusion.csv"] = _csv(confusion)
        out["hu.csv"] = _csv(analysis.hu)
    if analysis.ratings:
        out["ratings.csv"] = _csv(analysis.ratings)
    if analysis.contrasts:
        out["contrasts.csv"] = _csv(analysis.contrasts)
    if analysis.validation:
        out["validate-vs-people.csv"] = _csv(analysis.validation)
        out["validate-vs-people-summary.csv"] = _csv(analysis.validation_summary)
    return out


def write_report(analysis: Analysis, folder: str | Path, title: str | None = None) -> list[Path]:
    """The report, the figures and the tables into ``folder`` (made if missing); the files written."""
    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        from engine.errors import UserError

        raise UserError("the report must be a folder, and this is a file", file=folder)
    (folder / "figures").mkdir(parents=True, exist_ok=True)
    pictures = figures(analysis)
    texts = tables(analysis)
    texts["report.html"] = report_html(analysis, pictures, title)
    targets = {folder / name: text.encode("utf-8") for name, text in texts.items()}
    targets.update({folder / "figures" / name: png for name, png in pictures.items()})
    with atomic_files(targets) as temporary:
        for target, data in targets.items():
            temporary[target].write_bytes(data)
    return list(targets)


def _table(rows: list[dict[str, Any]], columns: list[str], names: list[str] | None = None) -> str:
    head = "".join(f"<th>{html.escape(n)}</th>" for n in (names or columns))
    body = []
    for row in rows:
        cells = []
        for c in columns:
            value = row.get(c)
            numeric = isinstance(value, int | float) and not isinstance(value, bool)
            shown = _text(round(value, 3) if isinstance(value, float) and not math.isnan(value) else value)
            cells.append(f"<td class='n'>{shown}</td>" if numeric else f"<td>{html.escape(shown)}</td>")
        body.append(f"<tr>{''.join(cells)}</tr>")
    return f"<table><tr>{head}</tr>{''.join(body)}</table>"


def _figure(pictures: dict[str, bytes], name: str, caption: str) -> str:
    if name not in pictures:
        return ""
    data = base64.b64encode(pictures[name]).decode()
    return (f"<figure><img alt='{html.escape(caption)}' src='data:image/png;base64,{data}'>"
            f"<figcaption>{html.escape(caption)} (figures/{name})</figcaption></figure>")


def report_html(analysis: Analysis, pictures: dict[str, bytes], title: str | None = None) -> str:
    results = analysis.results
    kept = [p for p in analysis.participants if p["included"]]
    title = title or f"Study '{results.study}': the participants' answers"
    parts = [f"<!doctype html><html lang='en'><meta charset='utf-8'><title>{html.escape(title)}</title>",
             f"<style>{STYLE}</style><body><h1>{html.escape(title)}</h1>",
             f"<p>study_id {html.escape(results.study_id)}; {len(kept)} of {len(analysis.participants)} participants "
             f"analysed, {len(analysis.included)} test trials; from {len(results.files)} file"
             f"{'s' if len(results.files) != 1 else ''}"
             + (f" ({results.duplicates} trials given twice, counted once)" if results.duplicates else "") + ".</p>"]
    parts += [f"<p class='warn'>{html.escape(n)}</p>" for n in analysis.notes]
    if analysis.recognition:
        overall = [r for r in analysis.recognition if r["emotion"] == ALL]
        parts.append("<h2>Recognition</h2>")
        parts.append(_table(overall, ["source", "presentation", "trials", "hits", "rate", "ci_low", "ci_high",
                                      "hu_mean", "pc_mean"],
                            ["source", "presentation", "trials", "hits", "rate", "95 % low", "95 % high",
                             "mean Hu", "mean pc"]))
        parts.append(_figure(pictures, "recognition.png", "Recognition rate per emotion and condition"))
        parts.append(_figure(pictures, "confusion.png", "Confusion matrices (intended × response)"))
        parts.append("<h2>Unbiased hit rate (Wagner 1993)</h2>")
        parts.append(_figure(pictures, "hu.png", "Hu per emotion and condition, with the chance proportion pc"))
        parts.append(_table([r for r in analysis.recognition if r["emotion"] != ALL],
                            ["source", "presentation", "emotion", "trials", "rate", "ci_low", "ci_high", "hu_mean",
                             "pc_mean", "hu_pooled", "pc_pooled", "hu_vs_pc_t", "hu_vs_pc_p"],
                            ["source", "presentation", "emotion", "trials", "rate", "95 % low", "95 % high",
                             "mean Hu", "mean pc", "pooled Hu", "pooled pc", "t (Hu vs pc)", "p"]))
    if analysis.ratings:
        parts.append("<h2>Ratings</h2>")
        parts.append(_figure(pictures, "ratings.png", "Mean ratings per emotion and condition"))
        parts.append(_table(analysis.ratings, ["scale", "source", "presentation", "emotion", "trials", "mean", "sd",
                                               "ci_low", "ci_high"]))
    if analysis.contrasts:
        parts.append("<h2>Contrasts</h2><p class='note'>difference = b − a; pooled interval: Newcombe's for rates, "
                     "Welch's for ratings (trials as independent); paired: over the participants who saw both.</p>")
        parts.append(_table(analysis.contrasts, ["contrast", "within", "emotion", "measure", "a_value", "b_value",
                                                 "difference", "pooled_ci_low", "pooled_ci_high", "participants",
                                                 "paired_ci_low", "paired_ci_high", "t", "p"]))
    if analysis.validation_summary:
        parts.append("<h2>The validate observers beside the participants</h2>")
        parts.append(_figure(pictures, "validate-vs-people.png", "Read as intended: observers and participants"))
        parts.append(_table(analysis.validation_summary, ["presentation", "emotion", "stimuli", "machine_rate",
                                                          "people_rate", "agreement"],
                            ["presentation", "emotion", "stimuli", "observers: read as intended",
                             "participants: hit rate", "observers' emotion = participants' commonest"]))
    parts.append("<h2>Participants</h2>")
    parts.append(_table(analysis.participants, ["participant", "order", "trials", "practice", "attention_checks",
                                                "attention_passed", "included", "hit_rate", "median_rt"]))
    parts.append("<h2>Measures</h2><p class='note'>Recognition rate: hits / trials, pooled over participants, with "
                 "Wilson's 95 % score interval. Hu (Wagner 1993) of emotion i: a²/(b·c), a the hits, b the stimuli "
                 "of i, c the responses i; pc = (b/N)(c/N), N all judgments; computed per participant and condition, "
                 "then averaged; Hu is tested against pc by a paired t test of asin(√·) across participants. Times "
                 "are on the player's clock (docs/study.md). Tables: the CSV files beside this page.</p>")
    parts.append("</body></html>")
    return "\n".join(parts)
