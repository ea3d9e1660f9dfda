"""Skin colour from two chromophores: melanin in the epidermis, haemoglobin in the dermis, as linear RGB albedo.

A small spectral model (synthesised for this toolkit; the constants are the
published ones cited below). For each wavelength 400 … 700 nm in 10 nm steps:

* the **epidermis** lets through ``T = exp(−f_mel · μ_mel(λ) · d_epi)`` one way, with eumelanin's
  absorption ``μ_mel = 6.6·10¹¹ · λ^−3.33`` cm⁻¹ (λ in nm) and ``f_mel`` the melanosomes' volume
  fraction (Jacques 1998, "Skin optics", Oregon Medical Laser Center News: 1.3–6.3 % in light-skinned
  adults, 11–16 % moderately pigmented, 18–43 % darkly pigmented), ``d_epi`` 80 µm;
* the **dermis** reflects the Kubelka–Munk diffuse albedo ``R = 1 + k − √(k² + 2k)``, ``k = μa/μs'``, of
  its absorption — blood at volume fraction ``f_blood`` (haemoglobin 150 g/l, 75 % oxygenated; molar
  extinction after Prahl's compiled tables, sampled at 50 nm and interpolated) over the bloodless
  dermis's baseline ``μa = 0.244 + 85.3 · exp(−(λ − 154)/66.2)`` cm⁻¹ — and its reduced scattering
  ``μs' = 2·10⁵ · λ^−1.5 + 2·10¹² · λ^−4`` cm⁻¹ (both Jacques 1998), with a carotene-like yellowing
  ``yellow`` (0 … 1, a carotene-like absorption about 470 nm in the epidermis) on the blue end;
* the skin's albedo is ``0.85 · T² · R`` (in and out through the epidermis; the 0.85 and the 80 µm
  epidermis calibrated so that typical European, East Asian and African skin tones fall at melanin
  fractions inside Jacques's ranges) plus the 4 % the surface reflects diffusely.

The spectrum is turned into CIE XYZ with Wyman, Sloan & Shirley's (2013) analytic fit of the CIE 1931
colour-matching functions under an equal-energy light, then into linear sRGB, white-balanced so that a
perfect white reflector gives (1, 1, 1).

>>> import numpy as np
>>> light, dark = skin_albedo(np.array([0.03, 0.35]), np.array([0.02, 0.02]))
>>> bool(light.sum() > 2 * dark.sum()), bool(light[0] > light[1] > light[2])
(True, True)
"""

from __future__ import annotations

from functools import cache

import numpy as np

WAVELENGTHS = np.arange(400.0, 701.0, 10.0)
EPIDERMIS_CM = 0.008
SURFACE_DIFFUSE = 0.04
#: What the dermis's Kubelka–Munk albedo is scaled by: light lost to the depth and to the sides (calibrated,
#: with the epidermis's thickness, against typical photographed skin tones; docs/skin.md).
DERMIS_SCALE = 0.85
#: Haemoglobin molar extinction (cm⁻¹/M) at 400 … 700 nm every 50 nm: oxygenated, deoxygenated (Prahl).
_HB_NM = np.array([400.0, 450.0, 500.0, 550.0, 600.0, 650.0, 700.0])
_HBO2 = np.array([266232.0, 62816.0, 20932.0, 43016.0, 3200.0, 368.0, 290.0])
_HB = np.array([223296.0, 103292.0, 20862.0, 53412.0, 14677.0, 3750.0, 1794.0])
_HB_GRAMS_PER_LITRE, _HB_MOLAR_MASS, _OXYGENATED = 150.0, 64500.0, 0.75
_XYZ_TO_RGB = np.array([[3.2406, -1.5372, -0.4986], [-0.9689, 1.8758, 0.0415], [0.0557, -0.2040, 1.0570]])


def _lobe(lam: np.ndarray, mu: float, below: float, above: float) -> np.ndarray:
    sigma = np.where(lam < mu, below, above)
    return np.asarray(np.exp(-0.5 * ((lam - mu) / sigma) ** 2))


@cache
def _spectrum_to_rgb() -> np.ndarray:
    """(W, 3): a reflectance spectrum (per wavelength) @ this = white-balanced linear sRGB."""
    lam = WAVELENGTHS
    x = 1.056 * _lobe(lam, 599.8, 37.9, 31.0) + 0.362 * _lobe(lam, 442.0, 16.0, 26.7) \
        - 0.065 * _lobe(lam, 501.1, 20.4, 26.2)
    y = 0.821 * _lobe(lam, 568.8, 46.9, 40.5) + 0.286 * _lobe(lam, 530.9, 16.3, 31.1)
    z = 1.217 * _lobe(lam, 437.0, 11.8, 36.0) + 0.681 * _lobe(lam, 459.0, 26.0, 13.8)
    to_rgb = np.stack([x, y, z], axis=1) @ _XYZ_TO_RGB.T          # (W, 3)
    white = to_rgb.sum(axis=0)
    return np.asarray(to_rgb / white)


@cache
def _absorption() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Per wavelength (cm⁻¹): melanin at fraction 1, whole blood, bloodless dermis; dermal reduced scattering."""
    lam = WAVELENGTHS
    melanin = 6.6e11 * lam ** -3.33
    eps = _OXYGENATED * np.exp(np.interp(lam, _HB_NM, np.log(_HBO2))) \
        + (1 - _OXYGENATED) * np.exp(np.interp(lam, _HB_NM, np.log(_HB)))
    blood = 2.303 * eps * _HB_GRAMS_PER_LITRE / _HB_MOLAR_MASS
    baseline = 0.244 + 85.3 * np.exp(-(lam - 154.0) / 66.2)
    scattering = 2e5 * lam ** -1.5 + 2e12 * lam ** -4.0
    return melanin, blood, baseline, scattering


def skin_spectrum(melanin: np.ndarray, blood: np.ndarray, yellow: np.ndarray | float = 0.0) -> np.ndarray:
    """(N, W) diffuse reflectance at :data:`WAVELENGTHS` for N pairs of volume fractions (0 … 1)."""
    mel_abs, blood_abs, base_abs, scatter = _absorption()
    melanin = np.asarray(melanin, dtype=float).reshape(-1, 1)
    blood = np.asarray(blood, dtype=float).reshape(-1, 1)
    yellow = np.broadcast_to(np.asarray(yellow, dtype=float).reshape(-1, 1), melanin.shape)
    carotene = yellow * 40.0 * np.exp(-(((WAVELENGTHS - 470.0) / 45.0) ** 2))     # cm⁻¹ in the epidermis
    transmit = np.exp(-(melanin * mel_abs + carotene) * EPIDERMIS_CM)
    k = (blood * blood_abs + (1 - blood) * base_abs) / scatter
    dermis = 1 + k - np.sqrt(k * k + 2 * k)
    return np.asarray(SURFACE_DIFFUSE + (1 - SURFACE_DIFFUSE) * DERMIS_SCALE * transmit ** 2 * dermis)


def skin_albedo(melanin: np.ndarray, blood: np.ndarray, yellow: np.ndarray | float = 0.0) -> np.ndarray:
    """(N, 3) linear sRGB albedo (0 … 1) for N melanin and blood volume fractions (and yellowing 0 … 1)."""
    rgb = skin_spectrum(melanin, blood, yellow) @ _spectrum_to_rgb()
    return np.asarray(np.clip(rgb, 0.0, 1.0))


_LOG_RANGE = (np.log(0.002), np.log(0.9))
_LUT_STEPS = (56, 56, 13)
_YELLOW_MAX = 1.2


@cache
def _albedo_table() -> tuple[tuple[np.ndarray, ...], np.ndarray]:
    """:func:`skin_albedo` on a grid of log melanin × log blood × yellowing (computed once)."""
    logs = np.linspace(*_LOG_RANGE, _LUT_STEPS[0])
    yellows = np.linspace(0.0, _YELLOW_MAX, _LUT_STEPS[2])
    M, B, Y = np.meshgrid(np.exp(logs), np.exp(logs), yellows, indexing="ij")
    table = skin_albedo(M.reshape(-1), B.reshape(-1), Y.reshape(-1)).reshape(*M.shape, 3)
    return (logs, logs, yellows), table


def skin_albedo_fast(melanin: np.ndarray, blood: np.ndarray, yellow: np.ndarray) -> np.ndarray:
    """:func:`skin_albedo` read from a table (trilinear; within 0.2 % of it), for the many texels of an image."""
    from scipy.interpolate import RegularGridInterpolator

    axes, table = _albedo_table()
    points = np.stack([np.clip(np.log(np.maximum(melanin, 1e-9)), *_LOG_RANGE),
                       np.clip(np.log(np.maximum(blood, 1e-9)), *_LOG_RANGE),
                       np.clip(yellow, 0.0, _YELLOW_MAX)], axis=-1)
    return np.asarray(RegularGridInterpolator(axes, table)(points))


def linear_to_srgb(linear: np.ndarray) -> np.ndarray:
    """Linear RGB 0 … 1 → sRGB bytes (the standard's piecewise curve)."""
    c = np.clip(np.asarray(linear, dtype=float), 0.0, 1.0)
    s = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
    return np.asarray(np.clip(np.rint(s * 255), 0, 255).astype(np.uint8))
