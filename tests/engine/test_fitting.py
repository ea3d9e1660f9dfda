"""Fitting a parameter to an example pose (engine/fitting/, §2.2.2).

Synthetic poses are made with the engine's own transforms on a small curved
sheet of quads (a chin-like piece of cylinder, mm), so the true axis, pivot,
angle, direction and weights are known. "Exactly" means 1e-6 in weights and
degrees (the solver's tolerance is far below that); the noisy cases add
Gaussian noise of a stated σ per coordinate and check the tolerances given
in ``docs/fitting.md``. The last section fits a shipped reference pose
(ARKit jawOpen) on the default head, with bounds measured there.
"""

from __future__ import annotations

import doctest
from pathlib import Path

import numpy as np
import pytest

from engine import InfluenceRegion, Model, Parameter, ParameterTree, UserError
from engine.deform.transforms import apply, rotation_about_axis
from engine.errors import ParameterError
from engine.fitting import FittingError, fit_parameter, fit_pose, mesh_edges, reference_pose, reference_pose_names

AXIS = np.array([0.96, 0.1, -0.26]) / np.linalg.norm([0.96, 0.1, -0.26])
PIVOT = np.array([0.0, 70.0, 0.0])
ANGLE = 20.0                                   # degrees
DIRECTION = np.array([3.0, 8.0, 5.0])          # mm


def sheet(nx: int = 16, ny: int = 14):
    """Vertices (mm) and quad faces of a curved sheet, 60 × 50 mm."""
    x, y = np.meshgrid(np.linspace(-30, 30, nx), np.linspace(0, 50, ny))
    V = np.column_stack([x.ravel(), y.ravel(), (40 - 0.01 * x ** 2).ravel()])
    faces = []
    for j in range(ny - 1):
        for i in range(nx - 1):
            a = j * nx + i
            faces += [4, a, a + 1, a + nx + 1, a + nx]
    return V, np.array(faces)


V, FACES = sheet()
EDGES = mesh_edges(FACES)
# 1 on the lower part (farthest from the pivot: it moves most), fading to 0 at y = 35 mm; no weight in
# [0.8, 1), so the vertices moving at least 0.9 of the most (the fit's core, held at 1) are truly at 1
W_TRUE = np.clip((35 - V[:, 1]) / 20, 0, 1)
W_TRUE = np.where(W_TRUE < 1, 0.8 * W_TRUE, 1.0)


def rotation_pose(weights=W_TRUE, angle=ANGLE):
    return weights[:, None] * (apply(rotation_about_axis(AXIS, PIVOT, angle), V) - V)


def translation_pose(weights=W_TRUE):
    return weights[:, None] * DIRECTION


def distance_to_true_axis(point):
    d = point - PIVOT
    return float(np.linalg.norm(d - (d @ AXIS) * AXIS))


def axis_error_degrees(axis, reference=AXIS):
    """Angle between two directions (arctan2 of cross and dot: accurate near 0, unlike arccos)."""
    reference = np.asarray(reference, float) / np.linalg.norm(reference)
    return float(np.degrees(np.arctan2(np.linalg.norm(np.cross(axis, reference)), axis @ reference)))


def roughness(w):
    return float(np.sum((w[EDGES[:, 0]] - w[EDGES[:, 1]]) ** 2))


def sheet_model(**parameters):
    """The sheet as a model with two parts (lower and upper half) and a static root parent."""
    part = (V[:, 1] > 25).astype(int)
    tree = ParameterTree([Parameter("root", "rotation"), Parameter("leaf", "translation", parent="root",
                                                                    direction=(1, 0, 0))])
    return Model(V, FACES, parts=["lower", "upper"], vertex_part=part, parameters=tree,
                 regions={"root": InfluenceRegion(np.arange(len(V)), np.ones(len(V))),
                          "leaf": InfluenceRegion([0], [1.0])})


# -- recovery of known transforms ---------------------------------------------------

def test_rotation_is_recovered_exactly_without_noise():
    fit = fit_pose(V, rotation_pose(), "rotation", edges=EDGES, smoothness=0.0)
    p = fit.parameter
    assert p.kind == "rotation"
    assert axis_error_degrees(p.axis) < 1e-6
    assert abs(p.degrees_per_unit - ANGLE) < 1e-6
    assert distance_to_true_axis(p.pivot) < 1e-6
    np.testing.assert_allclose(fit.weights, W_TRUE, atol=1e-6)
    assert fit.residual_max_mm < 1e-6


def test_rotation_pivot_is_the_axis_point_nearest_the_moving_part():
    fit = fit_pose(V, rotation_pose(), "rotation", smoothness=0.0)
    w = fit.weights
    centroid = w @ V / w.sum()
    assert abs((centroid - fit.parameter.pivot) @ fit.parameter.axis) < 1e-9


def test_rotation_with_noise_is_within_tolerance():
    sigma = 0.05                                               # mm per coordinate; displacements up to 17 mm
    noisy = rotation_pose() + np.random.default_rng(1).normal(0, sigma, V.shape)
    fit = fit_pose(V, noisy, "rotation", edges=EDGES, smoothness=0.0)
    p = fit.parameter
    assert axis_error_degrees(p.axis) < 0.5
    assert abs(p.degrees_per_unit - ANGLE) < 0.2
    assert distance_to_true_axis(p.pivot) < 1.0
    moving = np.linalg.norm(rotation_pose(np.ones(len(V))), axis=1) > 5     # weights are well determined there
    assert np.abs(fit.weights - W_TRUE)[moving].max() < 0.03
    assert fit.residual_rms_mm < 1.1 * sigma * np.sqrt(3)                 # no worse than the noise itself


def test_translation_is_recovered_exactly_without_noise():
    fit = fit_pose(V, translation_pose(), "translation", edges=EDGES, smoothness=0.0)
    assert fit.parameter.kind == "translation" and not fit.parameter.field
    np.testing.assert_allclose(fit.parameter.direction, DIRECTION, atol=1e-9)
    np.testing.assert_allclose(fit.weights, W_TRUE, atol=1e-9)
    assert fit.residual_max_mm < 1e-9


def test_translation_with_noise_is_within_tolerance():
    sigma = 0.05
    noisy = translation_pose() + np.random.default_rng(2).normal(0, sigma, V.shape)
    fit = fit_pose(V, noisy, "translation", edges=EDGES, smoothness=0.0)
    assert np.linalg.norm(fit.parameter.direction - DIRECTION) < 0.1
    assert np.abs(fit.weights - W_TRUE).max() < 0.03
    assert fit.residual_rms_mm < 1.1 * sigma * np.sqrt(3)


def test_a_translation_fitted_as_a_rotation_turns_about_a_distant_axis():
    """§2.2.1: "translation can be in practice approximated by a rotation with large radius"."""
    fit = fit_pose(V, translation_pose(), "rotation", edges=EDGES, smoothness=0.0)
    p = fit.parameter
    d = V.mean(axis=0) - p.pivot
    assert np.linalg.norm(d - (d @ p.axis) * p.axis) > 1e4              # mm from the axis
    assert abs(p.axis @ DIRECTION) < 1e-3 * np.linalg.norm(DIRECTION)   # the axis lies across the motion
    assert fit.residual_max_mm < 0.01


def test_field_translation_reproduces_the_pose_exactly_in_the_region():
    pose = rotation_pose()
    fit = fit_pose(V, pose, "field")
    assert fit.parameter.field and fit.mesh_residual_max_mm == 0.0
    region = np.flatnonzero(V[:, 1] < 10)
    fit = fit_pose(V, pose, "field", region=region)
    assert fit.residual_max_mm == 0.0
    np.testing.assert_array_equal(fit.region.indices, region)
    assert fit.mesh_residual_max_mm == pytest.approx(np.linalg.norm(pose, axis=1)[V[:, 1] >= 10].max())


# -- weights: region, bounds, smoothness --------------------------------------------

@pytest.mark.parametrize("kind", ["rotation", "translation"])
def test_weights_outside_the_region_are_zero(kind):
    pose = rotation_pose() if kind == "rotation" else translation_pose()
    region = np.flatnonzero(V[:, 0] < 0)                        # the left half only
    fit = fit_pose(V, pose, kind, edges=EDGES, region=region, smoothness=0.05)
    assert np.isin(fit.region.indices, region).all()
    assert np.all(fit.weights[V[:, 0] >= 0] == 0)
    np.testing.assert_array_equal(fit.allowed, region)
    assert fit.residual_rms_mm < 0.5                            # the left half is fitted ...
    assert fit.mesh_residual_max_mm > 5                         # ... the right half's motion is not


def test_region_given_as_part_names_or_mask():
    model = sheet_model()
    lower = model.part_vertices("lower")
    by_name = fit_parameter(model, rotation_pose(), "rotation", region="lower", smoothness=0.0)
    by_list = fit_parameter(model, rotation_pose(), "rotation", region=["lower"], smoothness=0.0)
    mask = np.zeros(len(V), dtype=bool)
    mask[lower] = True
    by_mask = fit_parameter(model, rotation_pose(), "rotation", region=mask, smoothness=0.0)
    for fit in (by_name, by_list, by_mask):
        np.testing.assert_array_equal(fit.allowed, lower)
        assert np.isin(fit.region.indices, lower).all()


def test_weights_stay_in_the_unit_interval():
    """A pose that overshoots (1.6 × the motion) in one place and moves backwards in another."""
    factor = np.ones(len(V))
    overshoot = (V[:, 0] > 10) & (V[:, 1] < 20)
    backwards = (V[:, 0] < -10) & (V[:, 1] < 20)
    factor[overshoot], factor[backwards] = 1.6, -1.0
    for kind, pose in (("rotation", rotation_pose(W_TRUE * factor)),
                       ("translation", translation_pose(W_TRUE * factor))):
        for smoothness in (0.0, 0.05):
            fit = fit_pose(V, pose, kind, edges=EDGES, smoothness=smoothness)
            w = fit.weights
            assert w.min() >= 0.0 and w.max() == 1.0, (kind, smoothness)
    fit = fit_pose(V, translation_pose(W_TRUE * factor), "translation", smoothness=0.0)
    assert np.all(fit.weights[backwards] == 0)                  # moving against the direction: weight 0
    # the part moving most sets the direction (weight 1); the rest of the block moves 1/1.6 of it
    np.testing.assert_allclose(fit.parameter.direction, 1.6 * DIRECTION, atol=1e-9)
    np.testing.assert_allclose(fit.weights[(W_TRUE == 1) & ~overshoot & ~backwards], 1 / 1.6, atol=1e-9)


def test_smoothness_reduces_weight_roughness():
    """Large noise (σ = 0.3 mm) on a 5° rotation makes per-vertex weights ragged; the edge term evens them
    out and brings them closer to the truth (measured: roughness 4.3 → 2.7, the truth's 2.6; worst
    weight error 0.25 → 0.12)."""
    noisy = rotation_pose(angle=5.0) + np.random.default_rng(3).normal(0, 0.3, V.shape)
    fits = {s: fit_pose(V, noisy, "rotation", edges=EDGES, smoothness=s) for s in (0.0, 0.02, 0.1)}
    rough = {s: roughness(fit.weights) for s, fit in fits.items()}
    error = {s: np.abs(fit.weights - W_TRUE).max() for s, fit in fits.items()}
    assert rough[0.1] < rough[0.02] < rough[0.0]
    assert rough[0.1] < 0.7 * rough[0.0]
    assert error[0.1] < 0.7 * error[0.0]


def test_smoothness_without_edges_is_per_vertex():
    pose = rotation_pose()
    a = fit_pose(V, pose, "rotation", smoothness=1.0)           # no edges: nothing to smooth over
    b = fit_pose(V, pose, "rotation", smoothness=0.0)
    np.testing.assert_array_equal(a.weights, b.weights)


# -- the result as engine objects ---------------------------------------------------

@pytest.mark.parametrize("kind", ["rotation", "translation", "field"])
def test_apply_adds_a_leaf_that_reproduces_the_fit_at_value_1(kind):
    model = sheet_model()
    pose = rotation_pose() if kind != "translation" else translation_pose()
    fit = fit_parameter(model, pose, kind, name="fitted_pose", parent="root", smoothness=0.01)
    fit.apply(model)
    assert model.parameters.group("fitted_pose") == 2 and model.parameters["fitted_pose"].parent == "root"
    np.testing.assert_allclose(model.deform(fitted_pose=1.0) - V, fit.fitted, atol=1e-9)
    assert np.array_equal(model.deform(fitted_pose=0.0), V)
    assert fit.residual_rms_mm < 0.05 and fit.explained > 0.999
    with pytest.raises(ParameterError, match="already exists"):
        fit.apply(model)


def test_summary_and_residual_figures():
    fit = fit_pose(V, rotation_pose() + 0.1, "rotation", smoothness=0.0)
    assert fit.residual_rms_mm <= fit.residual_max_mm
    assert fit.pose_rms_mm > fit.residual_rms_mm
    assert 0.9 < fit.explained < 1.0
    text = fit.summary()
    assert text.startswith("fitted: rotation") and "residual RMS" in text and "mm" in text


def test_apply_refuses_a_leaf_parent_that_has_a_region():
    model = sheet_model()
    fit = fit_parameter(model, translation_pose(), "translation", parent="leaf")
    with pytest.raises(FittingError, match="parent 'leaf' is a leaf"):
        fit.apply(model)
    assert "fitted" not in model.parameters


def test_apply_refuses_a_model_with_another_vertex_count():
    fit = fit_pose(V, translation_pose(), "translation")
    other = Model(V[:-1], [], parts=["surface"])
    with pytest.raises(FittingError, match="vertices"):
        fit.apply(other)


# -- bad input ----------------------------------------------------------------------

def _nan_pose():
    pose = rotation_pose()
    pose[7, 1] = np.nan
    return pose


@pytest.mark.parametrize("args, message", [
    (dict(displacements=np.zeros((len(V), 2))), r"\(N, 3\) array"),
    (dict(displacements=np.zeros((len(V) - 1, 3))), "displacement vectors"),
    (dict(displacements="up"), "array of numbers"),
    (dict(displacements=_nan_pose()), "1 vertices have non-finite coordinates.*vertex 7"),
    (dict(region=[]), "region is empty"),
    (dict(region=[0, len(V)]), "outside"),
    (dict(region=np.zeros(3, dtype=bool)), "one entry per vertex"),
    (dict(region="chin"), "unknown part 'chin'"),
    (dict(region=["lower", "uper"]), "did you mean 'upper'"),
    (dict(region=[0.5, 1.5]), "vertex indices"),
    (dict(kind="scale"), "unknown fit kind 'scale'"),
    (dict(smoothness=-1.0), "smoothness"),
    (dict(smoothness=float("nan")), "smoothness"),
    (dict(core=0.0), "core"),
    (dict(core=1.5), "core"),
    (dict(displacements=np.zeros((len(V), 3))), "moves none"),
    (dict(region=[3, 4], kind="rotation"), "at least 3 moving vertices"),
    (dict(name="no spaces"), "name"),
])
def test_bad_input_raises_a_user_error(args, message):
    args = {"displacements": rotation_pose(), "kind": "rotation", **args}
    with pytest.raises(UserError, match=message):
        fit_parameter(sheet_model(), args.pop("displacements"), **args)


def test_bad_input_errors_are_fitting_errors():
    with pytest.raises(FittingError):
        fit_parameter(sheet_model(), np.full((len(V), 3), np.nan))
    assert issubclass(FittingError, UserError)
    with pytest.raises(ParameterError, match="unknown parameter 'jaw'"):
        fit_parameter(sheet_model(), rotation_pose(), parent="jaw")
    with pytest.raises(FittingError, match="edges"):
        fit_pose(V, rotation_pose(), edges=[[0, len(V)]])


def test_mesh_edges_are_unique_and_sorted():
    edges = mesh_edges(np.array([3, 0, 1, 2, 4, 0, 2, 3, 4]))
    assert edges.tolist() == [[0, 1], [0, 2], [0, 4], [1, 2], [2, 3], [3, 4]]
    assert len(EDGES) == 16 * 13 + 15 * 14


# -- the shipped reference poses on the default head --------------------------------


def test_reference_poses_load_by_name():
    names = reference_pose_names()
    assert len(names) == 86 and "arkit/jawOpen" in names and "expression_units/mouth-open" in names
    np.testing.assert_array_equal(reference_pose("jawOpen"), reference_pose("arkit/jawOpen"))
    with pytest.raises(FittingError, match="did you mean 'arkit/jawOpen'"):
        reference_pose("arkit/jawOpne")


def test_jaw_open_fits_as_a_rotation(head):
    """Bounds measured on the shipped head (docs/fitting.md): RMS 0.978 mm, max 4.43 mm, 20.8° about +x."""
    fit = fit_parameter(head, reference_pose("arkit/jawOpen"), "rotation", name="jaw_drop", parent="head_tilt",
                        smoothness=0.0)
    p = fit.parameter
    assert fit.residual_rms_mm < 1.1 and fit.residual_max_mm < 4.6 and fit.explained > 0.98
    assert min(axis_error_degrees(p.axis, [1, 0, 0]), axis_error_degrees(p.axis, [-1, 0, 0])) < 1.0
    assert 20 < p.degrees_per_unit < 25
    assert abs(p.pivot[0]) < 1.0                                 # on the midline, behind and above the chin
    teeth = fit.weights[head.part_vertices("teeth_lower")]
    assert teeth.min() > 0.75                                    # carried (almost) rigidly
    model = head.copy()
    fit.apply(model)
    np.testing.assert_allclose(model.deform(jaw_drop=1.0) - head.vertices, fit.fitted, atol=1e-9)


# -- the documented examples run ----------------------------------------------------

def test_module_docstring_example():
    import engine.fitting

    result = doctest.testmod(engine.fitting, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0 and result.failed == 0


def test_docs_example():
    """The ``>>>`` examples of docs/fitting.md, read as one doctest (code fences end an example's output)."""
    path = Path(__file__).resolve().parents[2] / "docs" / "fitting.md"
    text = "\n".join("" if line.startswith("```") else line for line in path.read_text().splitlines())
    test = doctest.DocTestParser().get_doctest(text, {}, "fitting.md", str(path), 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    result = runner.run(test)
    assert result.attempted > 0 and result.failed == 0
