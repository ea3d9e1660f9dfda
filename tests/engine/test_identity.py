"""The identity space (issue 18 §2): parameters, MakeHuman's weighting, the rig carried over, files and the CLI."""

from __future__ import annotations

import json
import shutil

import h5py
import numpy as np
import pytest

from engine import load_model, save_model
from engine.identity import (
    Identity,
    IdentityError,
    continuum,
    identity_parameters,
    identity_vertices,
    make_identity_head,
    morph,
)
from engine.identity.targets import IdentityTargets, identity_targets_path
from engine.identity.weights import target_weights
from tests.engine.cli_runner import assert_user_error, run

OLDER_MAN = {"sex": 1.0, "age": 60, "caucasian": 1.0, "african": 0.0, "asian": 0.0}


@pytest.fixture(scope="module")
def older_man():
    return make_identity_head(Identity(OLDER_MAN))


# -- parameters and weights --------------------------------------------------------------

def test_parameters_have_ranges_defaults_and_groups():
    params = identity_parameters()
    names = [p.name for p in params]
    assert names[:7] == ["sex", "age", "african", "asian", "caucasian", "muscle", "weight"]
    assert len(names) == len(set(names)) > 150
    groups = {p.group for p in params}
    assert {"macro", "head", "eyes", "nose", "mouth", "chin", "ears"} <= groups
    for p in params:
        assert p.minimum <= p.default <= p.maximum
    assert "eye-scale-decr-incr.left" in names and "nose-scale-horiz-decr-incr" in names


@pytest.mark.parametrize("values, words", [
    ({"age": 120}, "outside its range [1, 90]"), ({"sex": -0.1}, "outside its range"),
    ({"nose": 1}, "unknown identity parameter 'nose'"), ({"age": float("nan")}, "finite"),
    ({"african": 0, "asian": 0, "caucasian": 0}, "cannot all be 0"), ({"age": "old"}, "must be a number"),
])
def test_bad_values_are_refused_with_one_line(values, words):
    with pytest.raises(IdentityError, match=words.replace("[", r"\[").replace("]", r"\]")):
        Identity(values)


def test_macro_weights_follow_makehuman():
    """Sex, age and ancestry weight the race-gender-age targets by their product; each combination sums to 1."""
    w = target_weights(Identity({"sex": 0.25, "age": 57.5, "african": 1, "asian": 0.5, "caucasian": 0.5}))
    # age 57.5 is halfway between 25 (young) and 90 (old)
    assert w["macrodetails/african-male-young"] == pytest.approx(0.5 * 0.25 * 0.5)
    assert w["macrodetails/asian-female-old"] == pytest.approx(0.25 * 0.75 * 0.5)
    race = sum(v for k, v in w.items() if "universal" not in k and k.startswith("macrodetails/"))
    universal = sum(v for k, v in w.items() if "universal" in k)
    assert race == pytest.approx(1.0) and universal == pytest.approx(1.0)


def test_face_modifiers_pick_their_side_and_sign():
    w = target_weights(Identity({"nose-scale-horiz-decr-incr": -0.4, "eye-scale-decr-incr.left": 0.3}))
    assert w["nose/nose-scale-horiz-decr"] == pytest.approx(0.4) and "nose/nose-scale-horiz-incr" not in w
    assert w["eyes/l-eye-scale-incr"] == pytest.approx(0.3) and "eyes/r-eye-scale-incr" not in w


# -- the head -------------------------------------------------------------------------------

def test_the_default_identity_is_the_default_head(head):
    same = make_identity_head(Identity())
    np.testing.assert_allclose(same.vertices, head.vertices, atol=1e-9)
    for p in head.parameters:
        q = same.parameters[p.name]
        np.testing.assert_allclose(q.pivot, p.pivot, atol=1e-9)
        np.testing.assert_allclose(q.axis, p.axis, atol=1e-9)


def test_an_identity_changes_the_face_and_keeps_the_mesh(head, older_man):
    assert older_man.n_vertices == head.n_vertices
    np.testing.assert_array_equal(older_man.faces, head.faces)
    assert older_man.landmarks == head.landmarks
    assert [p.name for p in older_man.parameters] == [p.name for p in head.parameters]
    moved = np.linalg.norm(older_man.vertices - head.vertices, axis=1)
    assert moved.max() > 5.0, "a different person, not the default head"


def test_eyes_stay_spheres_around_their_moved_pivots(older_man):
    for side in ("left", "right"):
        pivot = older_man.parameters[f"eye_{side}_turn"].pivot
        r = np.linalg.norm(older_man.vertices[older_man.part_vertices(f"eye_{side}")] - pivot, axis=1)
        assert np.ptp(r) < 1e-6 and 10 < r.mean() < 16


def test_pivots_move_with_the_surface_around_them(head):
    """A head scaled as a whole carries every pivot to the scaled place (the local affine maps are exact)."""
    from engine.identity.carry_over import carry_rig_over

    scaled = carry_rig_over(head, head.vertices * 1.1)
    for p in head.parameters:
        if p.kind == "rotation":
            np.testing.assert_allclose(scaled.parameters[p.name].pivot, p.pivot * 1.1, atol=1e-3, err_msg=p.name)
            np.testing.assert_allclose(scaled.parameters[p.name].axis, p.axis, atol=1e-6, err_msg=p.name)
        elif p.field:
            np.testing.assert_allclose(scaled.regions[p.name].displacements,
                                       head.regions[p.name].displacements * 1.1, atol=1e-3, err_msg=p.name)


def test_the_preview_vertices_are_the_made_heads_rest_shape(older_man):
    """The slider preview is the made head but for the fits after the carry-over (eyeballs a hair smaller)."""
    preview = identity_vertices(Identity(OLDER_MAN))
    assert np.linalg.norm(preview - older_man.vertices, axis=1).max() < 0.5


def test_morphs_are_identities_and_end_at_their_ends():
    a, b = Identity({"sex": 0.0, "age": 30}), Identity({"sex": 1.0, "age": 70, "african": 1.0})
    steps = continuum(a, b, 5)
    assert steps[0] == a and steps[-1] == b
    assert steps[2].value("age") == pytest.approx(50.0)
    with pytest.raises(IdentityError):
        morph(a, b, 1.5)
    mid = make_identity_head(steps[2])
    ends = [make_identity_head(x).vertices for x in (a, b)]
    between = np.linalg.norm(mid.vertices - (ends[0] + ends[1]) / 2, axis=1).mean()
    apart = np.linalg.norm(ends[0] - ends[1], axis=1).mean()
    assert between < 0.25 * apart, "the middle of a continuum is near the middle (sex × age × ancestry is multilinear)"


def test_the_identity_is_saved_and_made_again_exactly(older_man, tmp_path):
    path = save_model(older_man, tmp_path / "person.xml")
    back = load_model(path)
    assert back.identity == older_man.identity and back.identity.source == "anny-0.6.2"
    again = make_identity_head(Identity(back.identity.values))
    np.testing.assert_array_equal(again.vertices, back.vertices)


def test_a_model_file_with_a_bad_identity_record_is_refused(older_man, tmp_path):
    path = save_model(older_man, tmp_path / "person.xml")
    text = path.read_text().replace('name="sex" value="1.0"', 'name="sex" value="lots"')
    path.write_text(text)
    from engine.errors import ModelFileError

    with pytest.raises(ModelFileError, match=r"person\.xml"):
        load_model(path)


def test_a_damaged_targets_file_is_refused_naming_it(tmp_path):
    bad = tmp_path / "identity-targets.h5"
    shutil.copy(identity_targets_path(), bad)
    with h5py.File(bad, "a") as f:
        offsets = f["target_offsets"][()]
        offsets[-1] += 7
        f["target_offsets"][...] = offsets
    with pytest.raises(IdentityError, match=r"identity-targets\.h5"):
        IdentityTargets(bad)


def test_identities_apply_only_to_the_default_heads_mesh():
    from engine.model import Model

    with pytest.raises(IdentityError, match="default head's mesh"):
        make_identity_head(Identity({"sex": 1.0}), Model(np.zeros((3, 3)), [3, 0, 1, 2]))


# -- the command line --------------------------------------------------------------------------

def test_cli_lists_the_parameters_as_json():
    result = run("identity", "--list", "--json")
    assert result.returncode == 0, result.stderr
    listed = json.loads(result.stdout)
    assert listed[1] == {"name": "age", "min": 1.0, "max": 90.0, "default": 25.0, "group": "macro"}
    assert len(listed) == len(identity_parameters())


def test_cli_makes_and_morphs_identities(tmp_path):
    a, b, m = tmp_path / "a.xml", tmp_path / "b.xml", tmp_path / "m.xml"
    assert run("identity", "--set", "sex=1", "--set", "age=60", "-o", a).returncode == 0
    assert run("identity", "--set", "sex=0", "--set", "asian=1", "-o", b).returncode == 0
    result = run("identity", "--from", a, "--to", b, "--at", "0.25", "-o", m)
    assert result.returncode == 0, result.stderr
    made = load_model(m)
    assert made.identity.values["sex"] == pytest.approx(0.75)
    assert made.identity.values["age"] == pytest.approx(0.75 * 60 + 0.25 * 25)


@pytest.mark.parametrize("args, words", [
    (["--set", "age=120", "-o", "x.xml"], "outside its range"),
    (["--set", "nose=1", "-o", "x.xml"], "unknown identity parameter 'nose'"),
    (["--set", "sex", "-o", "x.xml"], "NAME=VALUE"),
    (["--from", "a.xml", "-o", "x.xml"], "--from A.xml, --to B.xml and --at T"),
    (["--set", "sex=1"], "-o PERSON.xml"),
    (["--from", "missing.xml", "--to", "missing.xml", "--at", "0.5", "-o", "x.xml"], "missing.xml"),
])
def test_cli_refuses_bad_input_with_one_line(tmp_path, args, words):
    line = assert_user_error(run("identity", *args, cwd=tmp_path))
    assert words in line


@pytest.mark.slow
def test_an_identity_from_the_cli_speaks_with_closed_bilabials_and_open_vowels(tmp_path):
    """`identity -o` then `say -m` (real Festival): the lips meet at p, b, m and part at a, as on the default head."""
    import csv

    person = tmp_path / "person.xml"
    assert run("identity", "--set", "sex=0", "--set", "age=35", "--set", "african=1", "--set", "asian=0",
               "--set", "caucasian=0", "-o", person).returncode == 0
    tracks, phones = tmp_path / "tracks.csv", tmp_path / "phones.csv"
    result = run("say", "-m", person, "Pappa osti mummolle paljon omenoita ja marjapuuroa.",
                 "--tracks", tracks, "--phones", phones, "--fps", "200", "--quiet")   # 5 ms rows: short phones too
    assert result.returncode == 0, result.stderr
    head = load_model(person)
    with open(tracks, newline="") as f:
        rows = list(csv.DictReader(f))
    times = np.array([float(r["time_ms"]) for r in rows])
    names = [n for n in rows[0] if n != "time_ms"]
    values = np.array([[float(r[n]) for n in names] for r in rows])
    with open(phones, newline="") as f:
        labelled = [(r["phone"], (float(r["start_ms"]) + float(r["end_ms"])) / 2) for r in csv.DictReader(f)]

    def gap(at_ms):
        row = np.array([np.interp(at_ms, times, values[:, k]) for k in range(len(names))])
        lm = head.landmark_positions(dict(zip(names, row, strict=True)))
        return float(np.linalg.norm(lm["2.2"] - lm["2.3"]))

    closed = [gap(t) for p, t in labelled if p in ("p", "b", "m")]
    opened = [gap(t) for p, t in labelled if p.rstrip(":") == "a"]
    assert len(closed) >= 5 and len(opened) >= 4
    assert max(closed) <= 1.0, f"lip gap at a bilabial: {max(closed):.2f} mm"
    assert np.mean(opened) >= 6.0, f"mean lip gap at a: {np.mean(opened):.2f} mm"
