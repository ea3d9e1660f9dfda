"""The measures of a category-judgment study: hit rates with intervals, Wagner's unbiased hit rate, means.

**Unbiased hit rate** (Wagner 1993, "On measuring performance in category judgment studies of
nonverbal behavior", J. Nonverbal Behav. 17: 3–28). In a confusion matrix of stimulus category (rows)
by response category (columns), with ``a`` the hits of category *i* (the diagonal cell), ``b`` the
stimuli of category *i* (the row's total) and ``c`` the uses of response *i* (the column's total),

    Hu_i = a² / (b · c) = (a / b) · (a / c)

— the hit rate times the proportion of *i* responses that were right; 0 where ``c`` is 0. Its chance
value, the joint probability of stimulus *i* and response *i* if the two were independent, is

    pc_i = (b / N) · (c / N)

with N all judgments. Wagner tests Hu against pc per category across judges (paired t on the arcsine of
the square root of each; :func:`arcsine`).

>>> round(unbiased_hit_rate(3, 4, 4), 4), round(chance_proportion(4, 4, 12), 4)
(0.5625, 0.1111)
>>> [round(x, 4) for x in wilson(7, 10)]
[0.3968, 0.8922]
"""

from __future__ import annotations

import math
from collections.abc import Sequence

__all__ = ["Z95", "arcsine", "chance_proportion", "confusion_counts", "hu_table", "mean_interval", "newcombe",
           "paired_t", "unbiased_hit_rate", "wilson"]

Z95 = 1.959963984540054
"""The normal quantile of a two-sided 95 % interval."""


def unbiased_hit_rate(hits: int, stimuli: int, responses: int) -> float:
    """Wagner's Hu of one category: ``hits² / (stimuli · responses)`` (0 where either total is 0)."""
    if stimuli <= 0 or responses <= 0:
        return 0.0
    return hits * hits / (stimuli * responses)


def chance_proportion(stimuli: int, responses: int, total: int) -> float:
    """Wagner's pc of one category: ``(stimuli / N) · (responses / N)``."""
    if total <= 0:
        return 0.0
    return (stimuli / total) * (responses / total)


def confusion_counts(pairs: Sequence[tuple[str, str]], rows: Sequence[str], columns: Sequence[str]
                     ) -> list[list[int]]:
    """Counts of (intended, response) pairs as a ``rows`` × ``columns`` matrix (pairs outside them left out)."""
    where_row = {r: i for i, r in enumerate(rows)}
    where_column = {c: j for j, c in enumerate(columns)}
    matrix = [[0] * len(columns) for _ in rows]
    for intended, response in pairs:
        if intended in where_row and response in where_column:
            matrix[where_row[intended]][where_column[response]] += 1
    return matrix


def hu_table(matrix: Sequence[Sequence[int]], rows: Sequence[str], columns: Sequence[str]
             ) -> dict[str, dict[str, float]]:
    """Per stimulus category: stimuli, responses, hits, hit rate, Hu and pc of one confusion matrix."""
    total = sum(sum(r) for r in matrix)
    column_totals = [sum(matrix[i][j] for i in range(len(rows))) for j in range(len(columns))]
    out = {}
    for i, category in enumerate(rows):
        stimuli = sum(matrix[i])
        j = list(columns).index(category) if category in columns else None
        hits = matrix[i][j] if j is not None else 0
        responses = column_totals[j] if j is not None else 0
        out[category] = {"stimuli": stimuli, "responses": responses, "hits": hits,
                         "hit_rate": hits / stimuli if stimuli else math.nan,
                         "hu": unbiased_hit_rate(hits, stimuli, responses),
                         "pc": chance_proportion(stimuli, responses, total)}
    return out


def wilson(successes: int, trials: int, z: float = Z95) -> tuple[float, float]:
    """Wilson's score interval of a proportion (nan, nan for no trials)."""
    if trials <= 0:
        return math.nan, math.nan
    p = successes / trials
    denominator = 1 + z * z / trials
    centre = (p + z * z / (2 * trials)) / denominator
    half = z * math.sqrt(p * (1 - p) / trials + z * z / (4 * trials * trials)) / denominator
    return max(0.0, centre - half), min(1.0, centre + half)


def newcombe(k1: int, n1: int, k2: int, n2: int, z: float = Z95) -> tuple[float, float, float]:
    """The difference ``k2/n2 − k1/n1`` of two independent proportions and its interval (Newcombe 1998,
    method 10: from the two Wilson intervals)."""
    if n1 <= 0 or n2 <= 0:
        return math.nan, math.nan, math.nan
    p1, p2 = k1 / n1, k2 / n2
    l1, u1 = wilson(k1, n1, z)
    l2, u2 = wilson(k2, n2, z)
    d = p2 - p1
    low = d - math.sqrt((p2 - l2) ** 2 + (u1 - p1) ** 2)
    high = d + math.sqrt((u2 - p2) ** 2 + (p1 - l1) ** 2)
    return d, low, high


def mean_interval(values: Sequence[float]) -> tuple[float, float, int, float, float]:
    """(mean, sd, n, low, high): the mean with Student's t interval (nan where n < 2)."""
    n = len(values)
    if n == 0:
        return math.nan, math.nan, 0, math.nan, math.nan
    mean = sum(values) / n
    if n < 2:
        return mean, math.nan, 1, math.nan, math.nan
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1))
    from scipy.stats import t

    half = float(t.ppf(0.975, n - 1)) * sd / math.sqrt(n)
    return mean, sd, n, mean - half, mean + half


def paired_t(a: Sequence[float], b: Sequence[float]) -> tuple[float, float, int]:
    """Paired t test of ``b − a``: (t, two-sided p, pairs); nan where fewer than 2 pairs or no variance."""
    n = len(a)
    if n < 2 or len(b) != n:
        return math.nan, math.nan, n
    differences = [y - x for x, y in zip(a, b, strict=True)]
    mean = sum(differences) / n
    sd = math.sqrt(sum((d - mean) ** 2 for d in differences) / (n - 1))
    if sd == 0:
        return math.nan, math.nan, n
    from scipy.stats import t

    statistic = mean / (sd / math.sqrt(n))
    return statistic, float(2 * t.sf(abs(statistic), n - 1)), n


def arcsine(p: float) -> float:
    """``asin(√p)``, the variance-stabilising transform Wagner applies to Hu and pc before testing them."""
    return math.asin(math.sqrt(min(1.0, max(0.0, p))))
