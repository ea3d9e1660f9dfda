"""Motion-capture helpers the workbench used to keep to itself: gap statistics by the engine's own fill rule,
mapping files written and read back, and marker files of a made-up recording read back by the engine's readers.
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.mocap.errors import LabelFileError, MarkerFileError
from engine.mocap.gaps import fill_gaps, marker_gap_stats, marker_gaps
from engine.mocap.naming import marker_names, read_mapping, write_mapping
from engine.mocap.readers import read_marker_file
from engine.mocap.sample_files import (
    QTM_DECIMALS,
    TRC_DECIMALS,
    write_phone_segments_csv,
    write_qtm_tsv,
    write_sample_recording,
    write_trc,
)
from engine.speech.labels import read_labels

REPORT_KEYS = ("gaps", "filled_gaps", "filled_frames", "missing_gaps", "missing_frames")


def random_positions(rng: np.random.Generator, frames: int, markers: int, gap_rate: float) -> np.ndarray:
    """Smooth trajectories (mm) with gaps of random lengths, some at the ends."""
    t = np.arange(frames)[:, None, None]
    positions = 10 * np.sin(t / 7.0 + rng.uniform(0, 6, (1, markers, 3))) + rng.normal(0, 50, (1, markers, 3))
    absent = rng.random((frames, markers)) < gap_rate
    for _ in range(rng.integers(0, 4)):                       # a few long runs
        m, start = rng.integers(markers), rng.integers(frames)
        absent[start:start + rng.integers(1, 25), m] = True
    positions[absent] = np.nan
    return positions


@pytest.mark.parametrize("seed", range(12))
def test_gap_statistics_equal_what_fill_gaps_reports(seed):
    rng = np.random.default_rng(seed)
    frames, markers = int(rng.integers(1, 120)), int(rng.integers(1, 6))
    positions = random_positions(rng, frames, markers, gap_rate=rng.choice([0.0, 0.05, 0.3, 0.9]))
    for max_gap in (0, 1, 3, int(rng.integers(0, 40))):
        stats = marker_gap_stats(positions, max_gap)
        _, was_filled, missing, report = fill_gaps(positions, max_gap)
        absent = np.isnan(positions).any(axis=2)
        for m in range(markers):
            assert {k: stats[m][k] for k in REPORT_KEYS} == report[m]
            assert stats[m]["filled_frames"] == int(was_filled[:, m].sum())
            assert stats[m]["missing_frames"] == int(missing[:, m].sum())
            assert stats[m]["absent_frames"] == int(absent[:, m].sum())
            rule = marker_gaps(absent[:, m], max_gap)
            assert stats[m]["longest_gap"] == max((b - a for a, b in rule.gaps), default=0)


def test_the_rule_fills_short_inner_gaps_only():
    absent = np.array([1, 0, 1, 1, 0, 1, 1, 1, 0, 1], bool)
    rule = marker_gaps(absent, max_gap_frames=2)
    assert rule.gaps == [(0, 1), (2, 4), (5, 8), (9, 10)]
    assert rule.fillable == [(2, 4)] and rule.filled_frames == 2 and rule.absent_frames == 7


def test_gap_statistics_refuse_a_wrong_shape():
    with pytest.raises(ValueError, match="frames, markers, 3"):
        marker_gap_stats(np.zeros((4, 2)), 3)


# -- mapping files -----------------------------------------------------------------------------------

def test_a_written_mapping_reads_back_and_names_the_markers(tmp_path):
    mapping = {"LipCornerL": "8.3", "Lip Corner R": "8.4", "Marker17": "-", "FP2_1": "2.1"}
    path = write_mapping(tmp_path / "face.map", mapping)
    assert read_mapping(path) == mapping
    names, changes = marker_names(["LipCornerL", "Marker17", "Cheek"], read_mapping(path))
    assert names == ["8.3", None, "Cheek"] and changes["dropped"] == ["Marker17"]


@pytest.mark.parametrize("mapping", [{"A#1": "8.3"}, {"A": "8#3"}, {"": "8.3"}, {"A\nB": "8.3"}, {"A": "8=3"}])
def test_a_mapping_that_would_not_read_back_is_refused(tmp_path, mapping):
    with pytest.raises(LabelFileError, match="cannot write the mapping"):
        write_mapping(tmp_path / "face.map", mapping)
    assert list(tmp_path.iterdir()) == []


# -- marker files --------------------------------------------------------------------------------------

@pytest.mark.parametrize("writer, decimals, fmt", [(write_qtm_tsv, QTM_DECIMALS, "tsv"),
                                                   (write_trc, TRC_DECIMALS, "trc")])
def test_written_marker_files_read_back_to_the_same_numbers(tmp_path, writer, decimals, fmt):
    rng = np.random.default_rng(7)
    positions = rng.normal(0, 40, (30, 4, 3))
    positions[3:6, 1] = np.nan
    positions[0, 3] = np.nan
    labels = ["FP8_3", "Lip Corner R", "2.1", "nose"]
    path = writer(tmp_path / f"take.{fmt}", labels, positions, 60.0)
    recording = read_marker_file(path)
    assert recording.format == fmt and recording.labels == labels and recording.rate_hz == 60.0
    np.testing.assert_array_equal(np.isnan(recording.positions), np.isnan(positions))
    present = ~np.isnan(positions)
    np.testing.assert_allclose(recording.positions[present], positions[present], atol=0.5 * 10.0 ** -decimals)


def test_marker_writers_check_their_input(tmp_path):
    with pytest.raises(ValueError, match="2 labels for 3 markers"):
        write_trc(tmp_path / "x.trc", ["a", "b"], np.zeros((4, 3, 3)), 60.0)
    with pytest.raises(ValueError, match="frames, markers, 3"):
        write_qtm_tsv(tmp_path / "x.tsv", ["a"], np.zeros((4, 3)), 60.0)
    with pytest.raises(ValueError, match="frame rate"):
        write_qtm_tsv(tmp_path / "x.tsv", ["a"], np.zeros((4, 1, 3)), 0.0)
    with pytest.raises(MarkerFileError, match="folder does not exist"):
        write_trc(tmp_path / "missing" / "x.trc", ["a"], np.zeros((4, 1, 3)), 60.0)


def test_phone_segments_read_back_as_labels(tmp_path):
    phones = [(0.0, 100.0, "#"), (100.0, 180.5, "m"), (180.5, 400.25, "a:")]
    path = write_phone_segments_csv(tmp_path / "take.phones.csv", phones)
    assert read_labels(path) == phones


def test_a_sample_recording_reads_back_as_it_was_made(head, tmp_path):
    phones = [(0.0, 150.0, "#"), (150.0, 250.0, "p"), (250.0, 450.0, "a"), (450.0, 600.0, "#")]
    files = write_sample_recording(tmp_path / "take1", fmt="trc", seed=2, labels={"2.1": "Chin"},
                                   phones=phones, model=head)
    recording = files["recording"]
    assert files["markers"] == tmp_path / "take1.trc" and files["labels"] == tmp_path / "take1.phones.csv"
    read = read_marker_file(files["markers"])
    assert read.labels == [("Chin" if m == "2.1" else m) for m in recording.markers]
    np.testing.assert_allclose(read.positions, recording.positions, atol=1e-4, equal_nan=True)
    assert read_labels(files["labels"]) == [(a, b, label) for a, b, label in recording.phones]
    with pytest.raises(MarkerFileError, match="unknown sample format"):
        write_sample_recording(tmp_path / "take2", fmt="c3d", phones=phones, model=head)
