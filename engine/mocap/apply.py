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

:func:`reconstruct_held_out` fits the new parameters to held-out frames,
deforms the model and measures the error at the landmark vertices, in mm of
the recording.

Geodesic distances are shortest paths along mesh edges (Dijkstra), slightly
longer than true surface distances on a coarse mesh. Lengths are mm.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from engine.errors import ParameterError, UserError
from engine.model.parameters import NAME_PATTERN, Parameter
from engine.mocap.errors import MocapError
from engine.mocap.pca import Articulation, describe_component

if TYPE_CHECKING:
    from scipy import sparse

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

    def to_model(self, positions) -> np.ndarray:
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
        return "\n".join(lines) + "\n"


def component_names(art: Articulation, names=None, prefix: str | None = None) -> list[str]:
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
        out, seen = [], {}
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


def apply_articulation(model, art: Articulation, *, names=None, prefix: str | None = None, parent: str | None = "auto",
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
    off = [m for m, v in zip(used, vertices) if model.vertex_part[v] != part_index]
    if off:
        raise MocapError(f"landmarks {', '.join(off)} are not on the part '{part}'")

    mean = art.mean[columns]
    comps = art.components[:, columns]
    target = model.vertices[vertices]
    scale, rotation, translation, rest_values, rms = _align(mean, comps, target, rest_offset)
    marker_disp = scale * np.einsum("ij,cmj->cmi", rotation, comps)          # (C, used, 3) model mm

    graph = surface_graph(model, part)
    region, weights = articulation_region(graph, vertices, inner_mm, outer_mm, neighbour_ratio)
    fields = _surface_rbf(graph, vertices, region, marker_disp)

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
                               region, weights, parent_name, marker_disp)


# -- held-out frames ---------------------------------------------------------------------

@dataclass
class HeldOutError:
    """Reconstruction error at the markers, mm of the recording (model mm ÷ the alignment scale)."""

    markers: list[str]
    rms_mm: float
    """Over all markers and frames."""
    max_mm: float
    per_marker_rms_mm: np.ndarray
    per_frame_rms_mm: np.ndarray
    n_frames: int
    rest_rms_mm: float
    """The same error with every new parameter at 0 (the model at rest): the baseline."""
    pca_rms_mm: float
    """The PCA model's own least-squares error at the markers, without the face."""
    values: np.ndarray
    """(F, C) fitted parameter values on the face."""

    def report(self) -> str:
        worst = int(np.argmax(self.per_marker_rms_mm))
        return (f"held-out reconstruction through the face: {self.n_frames} frames, {len(self.markers)} markers: "
                f"RMS {self.rms_mm:.3f} mm, max {self.max_mm:.3f} mm (worst marker {self.markers[worst]}: "
                f"{self.per_marker_rms_mm[worst]:.3f} mm RMS); PCA alone {self.pca_rms_mm:.3f} mm; "
                f"face at rest {self.rest_rms_mm:.3f} mm\n")


def reconstruct_held_out(model, applied: AppliedArticulation, art: Articulation, markers, positions,
                         register: bool = False) -> HeldOutError:
    """Fit the new parameters to held-out frames, deform the model, measure at the landmarks.

    ``markers`` names the columns of ``positions`` ((F, M, 3), mm, head
    motion removed, NaN where missing; the frames should not be among those
    the PCA analysed). Each frame is taken into model space with the
    alignment, the parameters :attr:`AppliedArticulation.names` are fitted
    by least squares to the markers present, the model is deformed with
    those values and the landmark vertices are compared with the markers.

    Frames from the recording the PCA analysed share its coordinates. A
    *different* recording has had its head motion removed relative to its
    own reference frame: pass ``register=True`` to first move it rigidly into
    the analysed recording's coordinates (:func:`register_recording`).
    """
    from engine.mocap.synthetic import model_at_landmarks

    markers = [str(m) for m in markers]
    absent = [m for m in applied.markers if m not in markers]
    if absent:
        raise MocapError(f"the held-out data lack markers {', '.join(absent)}")
    x = np.asarray(positions, dtype=float)
    if x.ndim != 3 or x.shape[1:] != (len(markers), 3):
        raise MocapError(f"marker positions have shape {x.shape}, expected (frames, {len(markers)}, 3)")
    if register:
        rotation, translation = register_recording(art, markers, x)
        x = x @ rotation.T + translation
    x = x[:, [markers.index(m) for m in applied.markers]]
    target = applied.to_model(x)                                            # (F, m, 3) model mm
    sub = model_at_landmarks(model, applied.markers)                        # exact at these vertices, fast
    rest = sub.vertices
    basis = np.stack([sub.deform({n: 1.0}) - rest for n in applied.names])  # (C, m, 3): linear leaves
    deformer = sub.deformer()
    order = {n: i for i, n in enumerate(sub.parameters.names)}
    base = sub.values_array()
    errors = np.full(x.shape[:2], np.nan)
    rest_err = np.full(x.shape[:2], np.nan)
    fitted = np.full((len(x), len(applied.names)), np.nan)
    A = basis.reshape(len(applied.names), -1).T
    for f in range(len(x)):
        ok = np.isfinite(target[f]).all(axis=1)
        if not ok.any():
            continue
        rows = np.repeat(ok, 3)
        v = np.linalg.lstsq(A[rows], (target[f] - rest).reshape(-1)[rows], rcond=None)[0]
        fitted[f] = v
        values = base.copy()
        for name, value in zip(applied.names, v):
            values[order[name]] = value
        moved = deformer.deform(values)
        errors[f, ok] = np.linalg.norm(moved[ok] - target[f, ok], axis=1)
        rest_err[f, ok] = np.linalg.norm(rest[ok] - target[f, ok], axis=1)
    errors /= applied.scale
    rest_err /= applied.scale
    frames = np.isfinite(errors).any(axis=1)
    if not frames.any():
        raise MocapError("no held-out frame has any of the markers")
    cols = [art.markers.index(m) for m in applied.markers]
    pca_fit = art.reconstruct(art.values(x, applied.markers))[:, cols]
    pca_err = np.linalg.norm(pca_fit - x, axis=2)
    return HeldOutError(
        markers=list(applied.markers), rms_mm=float(np.sqrt(np.nanmean(errors ** 2))),
        max_mm=float(np.nanmax(errors)),
        per_marker_rms_mm=np.sqrt(np.nanmean(np.where(np.isfinite(errors), errors ** 2, np.nan), axis=0)),
        per_frame_rms_mm=np.sqrt(np.nanmean(errors[frames] ** 2, axis=1)), n_frames=int(frames.sum()),
        rest_rms_mm=float(np.sqrt(np.nanmean(rest_err ** 2))), pca_rms_mm=float(np.sqrt(np.nanmean(pca_err ** 2))),
        values=fitted)


def register_recording(art: Articulation, markers, positions, iterations: int = 30):
    """The rigid motion (R, t) that takes another recording into the coordinates ``art`` was computed in.

    Minimises ``Σ_f |R x_f + t − (mean + Σ_k v_fk C_k)|²`` over one rotation
    and translation for the whole recording and free component values per
    frame (alternating Procrustes and least squares), on the frames where
    every analysed marker is present. ``positions`` (F, M, 3) mm, columns
    named by ``markers``. Returns ``R`` (3, 3) and ``t`` (3,): ``x ↦ x Rᵀ + t``.
    """
    x = art._take(positions, markers)
    complete = np.isfinite(x).all(axis=(1, 2))
    if not complete.any():
        raise MocapError("no frame has every analysed marker: cannot register the recording")
    x = x[complete]
    flat = x.reshape(-1, 3)
    _, rotation, translation = similarity_fit(x.mean(axis=0), art.mean, scale=False)
    for _ in range(iterations):
        moved = x @ rotation.T + translation
        target = art.reconstruct(art.values(moved))
        _, new_rotation, new_translation = similarity_fit(flat, target.reshape(-1, 3), scale=False)
        step = np.abs(new_rotation - rotation).max() + np.abs(new_translation - translation).max()
        rotation, translation = new_rotation, new_translation
        if step < 1e-10:
            break
    return rotation, translation


# -- geometry -----------------------------------------------------------------------------

def surface_graph(model, part: str = "skin") -> sparse.csr_matrix:
    """The edges of ``part``'s polygons as a sparse (N × N) graph weighted by length, mm."""
    from scipy import sparse      # here, not at import: scipy.sparse costs the workbench 0.15 s at start

    tris = model.triangles()
    on = model.vertex_part == model.parts.index(part)
    edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    edges = edges[on[edges[:, 0]] & on[edges[:, 1]]]
    length = np.linalg.norm(model.vertices[edges[:, 0]] - model.vertices[edges[:, 1]], axis=1)
    n = model.n_vertices
    graph = sparse.coo_matrix((length, (edges[:, 0], edges[:, 1])), shape=(n, n)).tocsr()
    return graph.maximum(graph.T).tocsr()


def articulation_region(graph, vertices, inner_mm: float, outer_mm: float, neighbour_ratio: float = 1.3):
    """The influence region: vertex indices and weights (1 near the markers, 0 beyond ``outer_mm``).

    The markers are joined by shortest paths along ``graph`` (each to every
    marker no farther than ``neighbour_ratio`` × its nearest one); weights
    fall with the surface distance ``d`` from those paths: 1 for ``d ≤
    inner_mm``, smoothstep down to 0 at ``outer_mm``.
    """
    from scipy.sparse.csgraph import dijkstra      # here, not at import: it pulls in scipy.linalg (0.1–0.2 s)

    vertices = np.asarray(vertices, dtype=np.int64)
    dist, pred = dijkstra(graph, directed=False, indices=vertices, return_predecessors=True)
    between = dist[:, vertices]
    if not np.all(np.isfinite(between)):
        i, j = np.argwhere(~np.isfinite(between))[0]
        raise MocapError(f"marker vertices {vertices[i]} and {vertices[j]} are not connected on the surface")
    nearest = np.where(np.eye(len(vertices), dtype=bool), np.inf, between).min(axis=1)
    skeleton = set(vertices.tolist())
    for i in range(len(vertices)):
        for j in range(len(vertices)):
            if i != j and between[i, j] <= neighbour_ratio * nearest[i]:
                v = vertices[j]
                while v != vertices[i] and v >= 0:
                    skeleton.add(int(v))
                    v = pred[i, v]
    to_skeleton = dijkstra(graph, directed=False, indices=sorted(skeleton), min_only=True, limit=outer_mm)
    t = np.clip((to_skeleton - inner_mm) / (outer_mm - inner_mm), 0.0, 1.0)
    weight = 1.0 - t * t * (3.0 - 2.0 * t)                                  # smoothstep 1 → 0
    weight[~np.isfinite(to_skeleton)] = 0.0
    indices = np.flatnonzero(weight > 0)
    return indices, weight[indices]


def surface_coordinates(graph, region, dims: int = 3) -> np.ndarray:
    """(len(region), dims) coordinates whose straight-line distances approximate surface distances.

    Classical multidimensional scaling of the shortest-path distances
    between the region's vertices (Isomap): upper and lower lip, 2–3 mm apart
    through the mouth but some 60 mm apart along the skin, come out far
    apart. Paths stay inside the region where it is connected.
    """
    from scipy.sparse.csgraph import dijkstra

    region = np.asarray(region, dtype=np.int64)
    inside = graph[region][:, region]
    dist = dijkstra(inside, directed=False)
    if not np.all(np.isfinite(dist)):
        dist = dijkstra(graph, directed=False, indices=region)[:, region]
    if not np.all(np.isfinite(dist)):
        raise MocapError("part of the region is not connected to the rest along the surface")
    sq = dist ** 2
    centred = sq - sq.mean(axis=0) - sq.mean(axis=1)[:, None] + sq.mean()
    from scipy.linalg import eigh

    n = len(region)
    dims = min(dims, n)
    eigenvalues, eigenvectors = eigh(-0.5 * centred, subset_by_index=[n - dims, n - 1])   # the largest only
    top = np.argsort(eigenvalues)[::-1]
    return eigenvectors[:, top] * np.sqrt(np.maximum(eigenvalues[top], 0.0))


def _surface_rbf(graph, vertices, region, displacements) -> np.ndarray:
    """(C, len(region), 3) thin-plate RBF of marker displacements in surface coordinates."""
    from scipy.interpolate import RBFInterpolator

    coords = surface_coordinates(graph, region)
    at = np.searchsorted(region, vertices)
    c = displacements.shape[0]
    values = displacements.transpose(1, 0, 2).reshape(len(vertices), 3 * c)
    try:
        fit = RBFInterpolator(coords[at], values, kernel="thin_plate_spline", degree=1)
    except (ValueError, np.linalg.LinAlgError) as exc:
        raise MocapError(f"cannot interpolate the marker displacements over the surface ({exc})") from None
    return fit(coords).reshape(len(region), c, 3).transpose(1, 0, 2)


def _align(mean, comps, target, rest_offset: bool, ridge: float = 1e-6):
    """Similarity transform marker → model, and the component values of the model's rest pose.

    Starts from the Procrustes fit of the mean shape, then (``rest_offset``)
    minimises ``Σ |s R (mean + Σ v_k C_k) + t − L|² + ridge · |B|² |v|²``
    over scale, rotation, translation and ``v`` jointly (Levenberg–Marquardt);
    the tiny ridge only matters where a component could imitate a similarity.
    """
    from scipy.optimize import least_squares
    from scipy.spatial.transform import Rotation

    c = comps.shape[0]
    scale, rotation, translation = similarity_fit(mean, target)
    values = np.zeros(c)
    if rest_offset:
        flat = comps.reshape(c, -1)
        weight = np.sqrt(ridge * np.sum(flat ** 2) / c)

        def residuals(p):
            rot = Rotation.from_rotvec(p[:3]).as_matrix()
            shape = mean + np.tensordot(p[7:], comps, axes=1)
            fit = np.exp(p[3]) * shape @ rot.T + p[4:7] - target
            return np.concatenate([fit.reshape(-1), weight * p[7:]])

        start = np.concatenate([Rotation.from_matrix(rotation).as_rotvec(), [np.log(scale)], translation, values])
        solution = least_squares(residuals, start, method="lm", xtol=1e-12, ftol=1e-12, gtol=1e-12)
        values = solution.x[7:]
        scale, rotation, translation = similarity_fit(mean + np.tensordot(values, comps, axes=1), target)
    shape = mean + np.tensordot(values, comps, axes=1)
    rms = float(np.sqrt(np.mean(np.sum((scale * shape @ rotation.T + translation - target) ** 2, axis=1))))
    return scale, rotation, translation, values, rms


def similarity_fit(source, target, scale: bool = True):
    """Scale s, rotation R, translation t minimising Σ |s R x + t − y|² (Umeyama 1991); s = 1 if not ``scale``.

    ``source`` and ``target`` are (K, 3) corresponding points (column-vector
    convention: y ≈ s R x + t). Used to place markers on the model's landmarks.

    >>> x = np.array([[0., 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    >>> s, R, t = similarity_fit(x, 2 * x + [5, 0, 0])
    >>> round(s, 9), np.allclose(R, np.eye(3)), t.round(9).tolist()
    (2.0, True, [5.0, 0.0, 0.0])
    """
    mx, my = source.mean(axis=0), target.mean(axis=0)
    x, y = source - mx, target - my
    u, d, vt = np.linalg.svd(y.T @ x / len(x))
    s = np.ones(3)
    if np.linalg.det(u) * np.linalg.det(vt) < 0:
        s[2] = -1.0
    rotation = u @ np.diag(s) @ vt
    var = np.sum(x ** 2) / len(x)
    if var <= 0:
        raise MocapError("the markers all sit at one point: cannot align them to the model")
    factor = float(np.sum(d * s) / var) if scale else 1.0
    return factor, rotation, my - factor * rotation @ mx


def _parent(model, markers, vertices) -> str | None:
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
