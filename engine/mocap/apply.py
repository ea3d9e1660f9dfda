"""Onto the face: one translation parameter per PCA component (§3.1.2, ``mocap apply``).

*"One translation parameter per principal component was defined, thus the
superposition of deformations produced by each parameter separately
(Equation 2) provide a linear estimation of visual articulation from PCA
parameters. The region affected by articulatory parameters spans jaw, lips,
and close surrounding of lips. Cheeks, for example, are outside this
region."*

:func:`apply_articulation` adds to a model, for every component of an
:class:`~engine.mocap.pca.Articulation`, a field translation (a per-vertex
displacement, value 1 = one standard deviation of the component):

1. **Correspondence.** Each analysed marker is the model's landmark of the
   same id (``model.landmarks``: ``"8.3"`` → vertex). Markers the model has
   no landmark for are left out and reported.
2. **Alignment.** Marker coordinates are not model coordinates. A similarity
   transform (scale, rotation, translation; Umeyama) takes the marker shape
   onto the model's rest landmarks. Because the recording's mean shape is a
   half-open mouth while the model rests closed, the fit also finds the
   component values ``rest_values`` at which the markers look most like the
   model at rest (alternating Procrustes and least squares, lightly
   regularised). Component displacements then turn with the rotation and
   grow with the scale.
3. **Region.** The skin around the markers: the markers are joined by
   shortest paths along the mesh (each to the markers no more than
   ``neighbour_ratio`` times as far as its nearest one), and a vertex's
   weight is 1 within ``inner_mm`` of those paths (measured along the
   surface), falling smoothly (smoothstep) to 0 at ``outer_mm``. With the
   lip-contour and chin markers that covers the lips (inside and out), the
   chin and the skin between; cheeks, nose and eyes stay outside.
4. **Interpolation.** The displacement of every region vertex is a radial
   basis function interpolation of the marker displacements with *surface*
   (geodesic) distances — a thin-plate kernel ``r² log r`` plus a constant —
   so that the upper and lower lips, a few millimetres apart through the
   mouth but far apart along the skin, move independently.
   (``scipy.interpolate.RBFInterpolator`` measures straight-line distances,
   which would drag the upper lip along with the lower one.) At the marker
   vertices the weight is 1 and the interpolation exact, so the face
   reproduces the PCA model at the markers.

Each parameter is a leaf under the rigid parameter that carries the upper
lip (on the default head ``head_tilt``), so head motion carries the lips.
Parameter value ``v`` on the face means component value ``v + rest_values``
in the PCA model: 0 is the model's rest pose.

The alignment is :mod:`engine.mocap.marker_alignment`, the region and the
interpolation :mod:`engine.mocap.surface_interpolation`;
:func:`~engine.mocap.held_out.reconstruct_held_out` fits the new parameters
to held-out frames, deforms the model and measures the error at the landmark
vertices, in mm of the recording.

Geodesic distances are shortest paths along mesh edges (Dijkstra), slightly
longer than true surface distances on a coarse mesh. Lengths are mm.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from engine.errors import ParameterError, UserError
from engine.mocap.errors import MocapError
from engine.mocap.marker_alignment import align_to_landmarks
from engine.mocap.pca import Articulation, describe_component
from engine.mocap.surface_interpolation import articulation_region, surface_graph, surface_rbf
from engine.model.parameters import NAME_PATTERN, Parameter

if TYPE_CHECKING:
    from engine.model.model import Model

DEFAULT_PREFIX = "pca"
_ARTICULATORY = {"lowering": "lips_lower", "raising": "lips_raise", "protrusion": "lip_protrude",
                 "retraction": "lip_retract", "widening": "mouth_widen", "narrowing (rounding)": "lip_round"}


@dataclass
class AppliedArticulation:
    """What :func:`apply_articulation` did to a model."""

    names: list[str]
    """The new parameters, one per component, in component order."""
    markers: list[str]
    """Markers matched to landmarks (used)."""
    ignored: list[str]
    """Analysed markers the model has no landmark for."""
    scale: float
    rotation: np.ndarray
    """(3, 3): model = scale · rotation @ marker + translation (column vectors)."""
    translation: np.ndarray
    rest_values: np.ndarray
    """(C,) component values (standard deviations) at which the markers best match the model at rest."""
    alignment_rms_mm: float
    """RMS distance, model mm, between the aligned marker shape at ``rest_values`` and the rest landmarks."""
    region: np.ndarray
    """Vertex indices of the influence region (shared by all the new parameters)."""
    weights: np.ndarray
    parent: str | None
    marker_displacements: np.ndarray = field(default_factory=lambda: np.zeros((0, 0, 3)))
    """(C, used markers, 3) model-space displacement of the marker vertices for value 1, mm."""
    warnings: list[str] = field(default_factory=list)
    """What looks wrong and should be checked (a rest pose far outside the value range)."""

    def to_model(self, positions: npt.ArrayLike) -> np.ndarray:
        """Marker-space positions (…, 3) → model space, mm."""
        return self.scale * np.asarray(positions, dtype=float) @ self.rotation.T + self.translation

    def report(self) -> str:
        lines = [f"added {len(self.names)} field translation parameters: {', '.join(self.names)}"
                 + (f" (under '{self.parent}')" if self.parent else " (roots)"),
                 f"markers matched to landmarks: {', '.join(self.markers)}"]
        if self.ignored:
            lines.append(f"markers without a landmark on the model (left out): {', '.join(self.ignored)}")
        angle = np.degrees(np.arccos(np.clip((np.trace(self.rotation) - 1) / 2, -1, 1)))
        lines.append(f"alignment marker → model: scale {self.scale:.4f}, rotation {angle:.2f}°, "
                     f"translation ({', '.join(f'{t:.1f}' for t in self.translation)}) mm; "
                     f"residual at rest {self.alignment_rms_mm:.2f} mm RMS")
        lines.append("the model's rest pose in component values (SD): "
                     + ", ".join(f"{v:+.2f}" for v in self.rest_values))
        lines.append(f"influence region: {len(self.region)} vertices, {int(np.sum(self.weights >= 1))} "
                     f"with weight 1")
        lines += [f"warning: {w}" for w in self.warnings]
        return "\n".join(lines) + "\n"


def component_names(art: Articulation, names: str | Sequence[str] | None = None,
                    prefix: str | None = None) -> list[str]:
    """The parameter names for the components of ``art``.

    ``names=None``: ``pca1`` … ``pcaN`` (``prefix`` replaces ``pca``).
    ``names="articulatory"``: after what each component does (``jaw_open``
    for the jaw stage, then ``lip_protrude``, ``mouth_widen``, ``lip_round``,
    ``lips_raise`` …, repeats numbered), with ``prefix`` in front if given —
    note that the default head already has ``jaw_open``, ``mouth_widen`` and
    ``lip_protrude``. A list: those names.
    """
    n = art.n_components
    if names is None:
        out = [f"{DEFAULT_PREFIX if prefix is None else prefix}{k + 1}" for k in range(n)]
    elif isinstance(names, str) and names == "articulatory":
        out = []
        seen: dict[str, int] = {}
        for k in range(n):
            word = describe_component(art, k)
            base = "jaw_open" if word.startswith("jaw opening") else _ARTICULATORY.get(word, "articulation")
            seen[base] = seen.get(base, 0) + 1
            out.append((prefix or "") + base + (f"_{seen[base]}" if seen[base] > 1 else ""))
    else:
        out = [str(x) for x in ([names] if isinstance(names, str) else names)]
        if len(out) != n:
            raise MocapError(f"{len(out)} parameter names given for {n} components")
    for name in out:
        if not NAME_PATTERN.fullmatch(name):
            raise MocapError(f"parameter name {name!r} is not allowed: use letters, digits, '_', '.' and '-', "
                             "starting with a letter or '_'")
    if len(set(out)) != len(out):
        raise MocapError(f"parameter names must differ: {', '.join(out)}")
    return out


def apply_articulation(model: Model, art: Articulation, *, names: str | Sequence[str] | None = None,
                       prefix: str | None = None, parent: str | None = "auto",
                       value_range: tuple[float, float] = (-3.0, 3.0), inner_mm: float = 8.0,
                       outer_mm: float = 20.0, neighbour_ratio: float = 1.3, part: str = "skin",
                       rest_offset: bool = True) -> AppliedArticulation:
    """Add one field translation parameter per component of ``art`` to ``model`` (in place).

    Parameters
    ----------
    model : engine.Model
    art : Articulation
        From :func:`~engine.mocap.pca.multistage_pca` or the articulation file.
    names, prefix : see :func:`component_names`. Names the model already has
        are refused (nothing is added).
    parent : ``"auto"`` (the rigid parameter with the most weight at the
        upper-lip marker), a parameter name, or None (roots).
    value_range : (min, max)
        Range of each parameter in standard deviations around the recording's
        mean; shifted by the rest offset and widened to include 0.
    inner_mm, outer_mm : float
        Surface distance from the marker paths where the weight starts to fall, and where it is 0.
    neighbour_ratio : float
        Which markers are joined by paths (see the module docstring).
    part : str
        The part the region lies on (``skin``).
    rest_offset : bool
        Fit the component values of the model's rest pose while aligning (see module docstring).

    Returns an :class:`AppliedArticulation`; raises :class:`MocapError` or
    :class:`~engine.errors.ParameterError` (clashing names) before changing
    anything.
    """
    chosen = component_names(art, names, prefix)
    clashes = [n for n in chosen if n in model.parameters]
    if clashes:
        existing = ", ".join(f"'{n}' ({model.parameters[n].kind}{' field' if model.parameters[n].field else ''})"
                             for n in clashes)
        raise ParameterError(f"the model already has parameters named {existing}: choose other names "
                             f"(another prefix, or explicit names) or remove those parameters first")
    if not outer_mm > inner_mm >= 0:
        raise MocapError(f"the region needs 0 ≤ inner ({inner_mm:g} mm) < outer ({outer_mm:g} mm) distance")
    lo, hi = float(value_range[0]), float(value_range[1])
    if not lo < hi:
        raise MocapError(f"the value range ({lo:g}, {hi:g}) is empty")

    used = [m for m in art.markers if m in model.landmarks]
    ignored = [m for m in art.markers if m not in model.landmarks]
    if len(used) < 3:
        raise MocapError(f"only {len(used)} of the analysed markers ({', '.join(art.markers)}) are landmarks "
                         f"of the model (it has {', '.join(sorted(model.landmarks))}); the alignment needs 3")
    if part not in model.parts:
        raise MocapError(f"the model has no part '{part}' (parts: {', '.join(model.parts)})")
    columns = [art.markers.index(m) for m in used]
    vertices = np.array([model.landmarks[m] for m in used], dtype=np.int64)
    part_index = model.parts.index(part)
    off = [m for m, v in zip(used, vertices, strict=True) if model.vertex_part[v] != part_index]
    if off:
        raise MocapError(f"landmarks {', '.join(off)} are not on the part '{part}'")

    mean = art.mean[columns]
    comps = art.components[:, columns]
    target = model.vertices[vertices]
    scale, rotation, translation, rest_values, rms = align_to_landmarks(mean, comps, target, rest_offset)
    marker_disp = scale * np.einsum("ij,cmj->cmi", rotation, comps)          # (C, used, 3) model mm

    graph = surface_graph(model, part)
    region, weights = articulation_region(graph, vertices, inner_mm, outer_mm, neighbour_ratio)
    fields = surface_rbf(graph, vertices, region, marker_disp)

    parent_name = _parent(model, used, vertices) if parent == "auto" else parent
    if parent_name is not None:
        model.parameters[parent_name]            # an unknown name raises with a suggestion
    from engine.model.model import InfluenceRegion

    added = []
    try:
        for k, name in enumerate(chosen):
            low, high = min(lo - rest_values[k], 0.0), max(hi - rest_values[k], 0.0)
            stage = int(art.stages[k])
            guide = ", ".join(art.stage_markers[stage - 1]) if stage <= len(art.stage_markers) else "?"
            description = (f"PCA component {k + 1} (stage {stage}, guided by {guide}): "
                           f"{100 * art.explained_variance_ratio[k]:.1f} % of the variance, "
                           f"{describe_component(art, k)}; value 1 = one standard deviation, 0 = rest"
                           + (f"; from {art.source}" if art.source else ""))
            model.add_parameter(Parameter(name, "translation", parent=parent_name, minimum=low, maximum=high,
                                          field=True, description=description),
                                InfluenceRegion(region, weights, fields[k]))
            added.append(name)
    except UserError:
        for name in added:
            model.remove_parameter(name)
        raise
    return AppliedArticulation(chosen, used, ignored, scale, rotation, translation, rest_values, rms,
                               region, weights, parent_name, marker_disp,
                               rest_pose_warnings(chosen, rest_values, (lo, hi)))


def rest_pose_warnings(names: Sequence[str], rest_values: np.ndarray, value_range: tuple[float, float]) -> list[str]:
    """Warnings for components whose rest value lies far outside ``value_range`` (SD).

    The model's rest shape should look like some frame of the recording. A
    closed mouth at rest is often an extreme of speech, a few SD out (3.3 SD
    on the synthetic takes of the tests), so only a rest value beyond the
    range by more than half its width warns (outside −6..+6 for −3..+3): then
    the markers and the model do not match (wrong mapping, units or axes).

    >>> rest_pose_warnings(["pca1", "pca2"], np.array([19.2, -3.4]), (-3.0, 3.0))  # doctest: +ELLIPSIS
    ["the model's rest pose is at +19.2 SD on pca1, far outside the range -3..+3: ..."]
    """
    lo, hi = value_range
    margin = (hi - lo) / 2
    return [f"the model's rest pose is at {v:+.1f} SD on {name}, far outside the range {lo:g}..{hi:+g}: the "
            "recording's mean mouth shape is unlike the model's rest shape — check the marker mapping, "
            "the units and the up axis (mocap import --up)"
            for name, v in zip(names, rest_values, strict=True) if not lo - margin <= v <= hi + margin]


def _parent(model: Model, markers: list[str], vertices: np.ndarray) -> str | None:
    """The group-1 parameter with the most weight at the upper-lip marker (8.1, else the first marker)."""
    vertex = vertices[markers.index("8.1")] if "8.1" in markers else vertices[0]
    tree = model.parameters
    best, best_weight = None, 0.0
    for p in tree:
        if tree.is_leaf(p.name):
            continue
        region = model.regions[p.name]
        hit = np.searchsorted(region.indices, vertex)
        if hit < len(region.indices) and region.indices[hit] == vertex and region.weights[hit] > best_weight:
            best, best_weight = p.name, float(region.weights[hit])
    return best
