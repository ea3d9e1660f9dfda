"""Naming a session's markers after import (engine.mocap.marker_assignment), on a real NaturalPoint facial take.

``Facial-Sing-200-frames.c3d`` is c3d.org sample 29 cut after 200 frames: 38
markers labelled ``root-1`` … ``root-6`` (head), ``section1-1`` …
``section14-3`` (face) and ``Unlabeled1``, none an MPEG-4 id. Looking at
where they sit (Z up, the face towards −Y, the subject's left +X),
``section14-2`` is the chin's midpoint (the lowest marker on the midline),
``section10-2`` / ``section13-2`` the middle of the upper / lower lip and
``section11-1`` / ``section12-1`` the lip corners.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from engine.mocap.errors import MocapError
from engine.mocap.importer import format_report, import_marker_file
from engine.mocap.marker_assignment import (
    assign_marker,
    feature_point_choices,
    is_feature_point,
    marker_labels,
    marker_map_renames,
    rename_markers,
    session_mapping,
    unmapped_labels,
)
from engine.mocap.naming import marker_names, read_mapping, write_mapping
from engine.mocap.readers import read_marker_file
from engine.mocap.session import load_session, save_session

FACIAL_SING = Path(__file__).parent / "data" / "capture" / "Facial-Sing-200-frames.c3d"
LIPS_AND_CHIN = {"section14-2": "2.1", "section10-2": "8.1", "section13-2": "8.2", "section11-1": "8.3",
                 "section12-1": "8.4"}
HEAD = ["root-1", "root-2", "root-3", "root-4", "root-5", "root-6"]


@pytest.fixture
def session():
    return import_marker_file(FACIAL_SING, reference=HEAD)


def test_the_cut_file_reads_as_the_take_it_was_cut_from():
    recording = read_marker_file(FACIAL_SING)
    assert recording.n_frames == 200 and recording.rate_hz == 100.0 and len(recording.labels) == 38
    assert recording.labels[:7] == [*HEAD, "section1-1"] and recording.labels[-2:] == ["section14-3", "Unlabeled1"]
    assert any("cut short" in note and "200 of the 3000" in note for note in recording.notes)
    assert np.isnan(recording.positions[:, -1]).all()            # Unlabeled1: never seen in these frames
    assert np.isfinite(recording.positions[:, :-1]).all()


def test_every_label_of_the_take_names_no_feature_point():
    recording = read_marker_file(FACIAL_SING)
    names, _ = marker_names(recording.labels)
    assert unmapped_labels(recording.labels, names) == recording.labels          # all 38, kept as they are
    names, _ = marker_names(recording.labels, {**LIPS_AND_CHIN, "Unlabeled1": "-"})
    unmapped = unmapped_labels(recording.labels, names)
    assert len(unmapped) == 32 and "section14-2" not in unmapped and "Unlabeled1" not in unmapped


@pytest.mark.parametrize(("name", "expected"), [("2.1", True), ("8.8", True), ("11.3", True), ("20.9", True),
                                                ("FP2_1", False), ("02.1", False), ("1.1", False), ("12.1", False),
                                                ("root-1", False), ("", False)])
def test_which_names_are_feature_point_ids(name, expected):
    assert is_feature_point(name) is expected


def test_the_import_report_warns_of_them(session):
    assert session.report["naming"]["not_feature_points"] == marker_labels(session)
    assert ("warning: 38 of 38 markers name no MPEG-4 feature point and keep their file labels (name them with "
            "--map): root-1, root-2, ") in format_report(session)
    assign_marker(session, "section14-2", "2.1")
    assert "warning: 37 of 38 markers" in format_report(session)
    assert "section14-2" not in session.report["naming"]["not_feature_points"]


def test_assigning_the_chin_renames_the_marker_and_is_saved_with_the_session(session, tmp_path):
    before = session.positions.copy()
    assert assign_marker(session, "section14-2", "2.1") == {"section14-2": "2.1"}
    assert session.markers[session.marker_index("2.1")] == "2.1" and "section14-2" not in session.markers
    assert marker_labels(session)[session.marker_index("2.1")] == "section14-2"
    np.testing.assert_array_equal(session.positions, before)                  # only the name changes
    assert session.report["naming"]["renamed"] == {"section14-2": "2.1"}
    assert "2.1" in session.report["gaps"] and "section14-2" not in session.report["gaps"]
    assert "renamed: section14-2 → 2.1" in format_report(session)
    save_session(session, tmp_path / "take.h5")
    again = load_session(tmp_path / "take.h5")
    assert again.markers == session.markers and marker_labels(again) == marker_labels(session)
    assert session_mapping(again) == {"section14-2": "2.1"}


def test_an_id_given_to_a_second_marker_leaves_the_first_with_its_label(session):
    assign_marker(session, "section14-2", "2.1")
    renames = assign_marker(session, "section14-1", "2.1")
    assert renames == {"section14-1": "2.1", "2.1": "section14-2"}
    assert session.markers.count("2.1") == 1 and "section14-2" in session.markers
    assert marker_labels(session)[session.marker_index("2.1")] == "section14-1"
    rename_markers(session, {new: old for old, new in renames.items()})           # undo
    assert marker_labels(session)[session.marker_index("2.1")] == "section14-2"
    assert "section14-1" in session.markers


def test_unassigning_gives_the_file_label_back(session):
    assign_marker(session, "section14-2", "2.1")
    assert assign_marker(session, "2.1", None) == {"2.1": "section14-2"}
    assert "section14-2" in session.markers and session.report["naming"]["renamed"] == {}
    assert session_mapping(session) == {}


def test_the_rename_undoes_exactly(session):
    markers, report = list(session.markers), repr(session.report)
    undo = rename_markers(session, {"section14-2": "2.1", "root-1": "20.1"})
    assert session.reference[0] == "20.1" and session.report["head_motion"]["reference"][0] == "20.1"
    rename_markers(session, undo)
    assert session.markers == markers and repr(session.report) == report


@pytest.mark.parametrize("point", ["FP2_1", "chin", "1.1", "2.1 # chin"])
def test_an_id_that_is_no_feature_point_is_refused_and_nothing_changes(session, point):
    markers = list(session.markers)
    with pytest.raises(MocapError, match="no MPEG-4 feature point id"):
        assign_marker(session, "section14-2", point)
    assert session.markers == markers


def test_names_that_clash_or_cannot_be_written_are_refused(session):
    markers = list(session.markers)
    with pytest.raises(MocapError, match="would both be named 'root-2'"):
        rename_markers(session, {"root-1": "root-2"})
    with pytest.raises(MocapError, match="holds no '#'"):
        rename_markers(session, {"root-1": "a = b"})
    with pytest.raises(MocapError, match="has no marker 'nose'"):
        assign_marker(session, "nose", "9.3")
    assert session.markers == markers


def test_the_session_mapping_names_the_next_import_the_same_way(session, tmp_path):
    for label, point in LIPS_AND_CHIN.items():
        assign_marker(session, label, point)
    path = write_mapping(tmp_path / "facial-sing.map", session_mapping(session))
    assert read_mapping(path) == LIPS_AND_CHIN
    again = import_marker_file(FACIAL_SING, mapping=path, reference=HEAD)
    assert again.markers == session.markers


def test_a_marker_map_put_onto_a_session(session):
    assign_marker(session, "section14-1", "2.1")                  # a wrong guess, then the lab's map
    mapping = {**LIPS_AND_CHIN, "Unlabeled1": "-", "NotInThisTake": "9.3"}
    renames = marker_map_renames(session, mapping)
    assert renames == {"section14-2": "2.1", "2.1": "section14-1", "section10-2": "8.1", "section13-2": "8.2",
                       "section11-1": "8.3", "section12-1": "8.4"}
    rename_markers(session, renames)
    assert {session.markers[i]: label for i, label in enumerate(marker_labels(session))
            if label in LIPS_AND_CHIN} == {p: label for label, p in LIPS_AND_CHIN.items()}
    assert "Unlabeled1" in session.markers                        # dropping is for the import


def test_the_points_to_choose_from(head):
    choices = feature_point_choices(head)
    ids = [c.id for c in choices]
    assert ids[:len(head.landmarks)] == sorted(head.landmarks, key=lambda p: tuple(int(t) for t in p.split(".")))
    chin = choices[ids.index("2.1")]
    assert chin.description == "bottom of the chin" and chin.on_model
    assert choices[ids.index("9.12")].on_model                    # placed on the skin by the engine
    assert not choices[ids.index("20.1")].on_model and "head-fixed" in choices[ids.index("20.1")].description
    assert len(ids) == len(set(ids)) and all(is_feature_point(i) for i in ids)
