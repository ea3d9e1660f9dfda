"""The articulation file: the result of the multistage PCA, in HDF5 (§3.1.2).

:func:`save_articulation_file` writes an :class:`~engine.mocap.pca.Articulation`
atomically; :func:`load_articulation_file` reads and checks one, refusing
files of another format or an unknown version with
:class:`ArticulationFileError` naming the file. Lengths are mm.
``docs/mocap-pca.md`` gives the file layout.

>>> import tempfile, numpy as np
>>> from pathlib import Path
>>> from engine.mocap.pca import Stage, multistage_pca
>>> rng = np.random.default_rng(0)
>>> pos = rng.normal(size=(50, 3, 3))
>>> art = multistage_pca(["2.1", "8.2", "8.3"], pos, stages=[Stage(("2.1",), 1), Stage(("8.*",), 1)])
>>> with tempfile.TemporaryDirectory() as folder:
...     again = load_articulation_file(save_articulation_file(art, Path(folder) / "art.h5"))
>>> again.markers, np.allclose(again.components, art.components)
(['2.1', '8.2', '8.3'], True)
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import NoReturn

import h5py
import numpy as np

from engine.formats.atomic import atomic_path
from engine.mocap.errors import MocapError
from engine.mocap.hdf5_files import open_versioned, text_attribute
from engine.mocap.pca import Articulation

ARTICULATION_FORMAT = "artificial-person-articulation"
ARTICULATION_VERSION = 1


class ArticulationFileError(MocapError):
    """An articulation file is unreadable, not one this program wrote, of an unknown version, or inconsistent."""


def save_articulation_file(art: Articulation, path: str | Path) -> Path:
    """Write the articulation file atomically (temporary file beside ``path``, then rename).

    Datasets (a fixed layout other tools rely on): ``markers`` (M names), ``mean`` (M × 3,
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
        for name in ("markers", "mean", "components", "explained_variance_ratio", "stages"):
            if not f.has(name):
                raise ArticulationFileError(f"missing dataset '/{name}'", file=path)
        markers = f.strings("markers")
        mean = f.array("mean", "f", tail=(3,)).astype(float)
        components = f.array("components", "f", ndim=3).astype(float)
        ratio = f.array("explained_variance_ratio", "f").astype(float)
        stages = f.array("stages", "f").astype(float)      # whole numbers: checked below
        n_comp = components.shape[0]
        try:
            score_std = np.asarray(f.attribute("score_std_mm") if f.attribute("score_std_mm") is not None
                                   else np.full(n_comp, np.nan), dtype=float).reshape(-1)
            stage_markers = json.loads(text_attribute(f.attribute("stage_markers")) or "[]")
            counts = {key: int(f.attribute(key) or 0)  # type: ignore[call-overload]
                      for key in ("n_frames", "excluded_missing")}
            rate = f.attribute("rate_hz")
            rate_hz = float(rate) if rate is not None else np.nan  # type: ignore[arg-type]
        except (TypeError, ValueError):
            raise ArticulationFileError("the attributes 'score_std_mm', 'stage_markers', 'n_frames', "
                                        "'excluded_missing' or 'rate_hz' are damaged", file=path) from None
        if not isinstance(stage_markers, list) or score_std.size > n_comp:
            raise ArticulationFileError("the attributes 'score_std_mm' or 'stage_markers' are damaged", file=path)
        art = Articulation(
            markers=markers, mean=mean, components=components, explained_variance_ratio=ratio, stages=stages,
            stage_markers=stage_markers, score_std=score_std, n_frames=counts["n_frames"],
            excluded_missing=counts["excluded_missing"], selection=text_attribute(f.attribute("selection")) or "",
            rate_hz=rate_hz, source=text_attribute(f.attribute("source")) or "")
    _check_arrays(art, path)
    art.stages = art.stages.astype(np.int64)
    return art


def _check_arrays(art: Articulation, path: str | Path) -> None:
    def fail(message: str) -> NoReturn:
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
