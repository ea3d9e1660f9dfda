"""Interpolation between the time/value keys of one activation (§2.3 ``$interp``).

Every kind is evaluated vectorised over an array of times, is right-continuous
at a jump (two keys at the same time: the later key's value holds from that
time on), passes exactly through every key, and is zero outside the keys'
span — an activation contributes nothing before its first key or after its
last (``docs/commands.md``, "The timeline").

* ``linear`` — straight lines between keys (the paper's method).
* ``step`` — each key's value holds until the next key.
* ``cosine`` — half a cosine between neighbouring keys: smooth ease in and out,
  flat at every key.
* ``cubic`` — monotone piecewise-cubic Hermite (Fritsch–Carlson slopes):
  smooth, flat at the first and last key, and never beyond the values of the
  two neighbouring keys.

>>> import numpy as np
>>> from engine.commands.interpolation import interpolate
>>> interpolate("linear", [0, 100], [0, 1], np.array([-10, 0, 25, 100, 110]))
array([0.  , 0.  , 0.25, 1.  , 0.  ])
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

INTERPOLATIONS = ("linear", "step", "cubic", "cosine")


def interpolate(kind: str, times: npt.ArrayLike, values: npt.ArrayLike, at: npt.ArrayLike) -> np.ndarray:
    """Values of the curve through ``(times, values)`` at the times ``at``.

    ``times`` must not decrease. Outside ``[times[0], times[-1]]`` the result is 0.
    """
    if kind not in INTERPOLATIONS:
        raise ValueError(f"unknown interpolation '{kind}' (known: {', '.join(INTERPOLATIONS)})")
    times = np.asarray(times, dtype=float)
    values = np.asarray(values, dtype=float)
    at = np.asarray(at, dtype=float)
    out = np.zeros(at.shape)
    if times.size == 0:
        return out
    inside = (at >= times[0]) & (at <= times[-1])
    t = at[inside]
    # Segment i holds times[i] <= t < times[i+1]; side="right" picks the last of
    # several equal times, which makes every jump right-continuous.
    i = np.searchsorted(times, t, side="right") - 1
    i = np.clip(i, 0, times.size - 1)
    last = i >= times.size - 1
    j = np.where(last, i, i + 1)
    span = times[j] - times[i]
    u = np.divide(t - times[i], span, out=np.zeros_like(t), where=span > 0)
    v0, v1 = values[i], values[j]
    if kind == "step":
        result = v0
    elif kind == "linear":
        result = v0 + u * (v1 - v0)
    elif kind == "cosine":
        result = v0 + 0.5 * (1.0 - np.cos(np.pi * u)) * (v1 - v0)
    else:
        slopes = monotone_slopes(times, values)
        h = span
        u2, u3 = u * u, u * u * u
        result = ((2 * u3 - 3 * u2 + 1) * v0 + (u3 - 2 * u2 + u) * h * slopes[i]
                  + (-2 * u3 + 3 * u2) * v1 + (u3 - u2) * h * slopes[j])
    out[inside] = result
    return out


def monotone_slopes(times: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Fritsch–Carlson slopes at the keys: the cubic through them never overshoots.

    Interior keys get the weighted harmonic mean of the neighbouring secants
    (Fritsch & Butland 1984), or 0 at a local extremum. End keys get slope 0,
    so a curve that starts and ends at 0 joins the zero outside its span
    smoothly. A jump (two keys at one time) splits the curve into pieces,
    each with flat ends.
    """
    n = times.size
    slopes = np.zeros(n)
    if n < 2:
        return slopes
    h = np.diff(times)
    dv = np.diff(values)
    secant = np.divide(dv, h, out=np.zeros_like(dv), where=h > 0)
    left, right = secant[:-1], secant[1:]               # around interior keys 1 … n-2
    h0, h1 = h[:-1], h[1:]
    same_sign = (left * right > 0) & (h0 > 0) & (h1 > 0)
    w1, w2 = 2 * h1 + h0, h1 + 2 * h0
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):   # tiny secants: mean → 0
        mean = (w1 + w2) / (w1 / left + w2 / right)
    slopes[1:-1] = np.where(same_sign & np.isfinite(mean), mean, 0.0)
    return slopes
