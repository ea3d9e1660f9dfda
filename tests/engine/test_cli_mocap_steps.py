"""``mocap pca`` and ``mocap apply`` on the command line: a synthetic session → articulation file → face."""

from __future__ import annotations

import h5py
import numpy as np
import pytest

from engine import load_model
from engine.mocap.importer import build_session
from engine.mocap.recording import Recording
from engine.mocap.session import save_session
from engine.mocap.synthetic import synthesize_recording
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.mocap_samples import TRAINING_PHONES, parse_phones

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def session_file(tmp_path_factory):
    rec = synthesize_recording(phones=parse_phones(TRAINING_PHONES), model=load_model(), seed=21)
    recording = Recording(labels=list(rec.markers), positions=rec.positions, rate_hz=rec.rate_hz,
                          source="synthetic", format="synthetic")
    path = tmp_path_factory.mktemp("mocap") / "take.h5"
    save_session(build_session(recording, phones=rec.phones), path)
    return path


def test_pca_then_apply(session_file, tmp_path):
    art = tmp_path / "art.h5"
    plot = tmp_path / "pcs.png"
    result = run("mocap", "pca", session_file, "--select", "V", "C", "--plot", plot, "-o", art)
    assert result.returncode == 0, result.stderr
    assert "stage" in result.stdout.lower() and plot.stat().st_size > 1000
    with h5py.File(art) as f:
        assert {"markers", "mean", "components", "explained_variance_ratio", "stages"} <= set(f)
        assert f["components"].shape[0] == 5 and list(f["stages"][:]) == [1, 2, 2, 2, 2]
    out = tmp_path / "head-pca.xml"
    result = run("mocap", "apply", art, "--held-out", session_file, "-o", out)
    assert result.returncode == 0, result.stderr
    assert "mm" in result.stdout
    model = load_model(out)
    assert [f"pca{k}" for k in range(1, 6)] == [n for n in model.parameters.names if n.startswith("pca")]
    moved = model.deform({"pca1": 1.0}) - model.deform({})
    assert np.linalg.norm(moved, axis=1).max() > 1.0


def test_custom_stages_and_explicit_frames(session_file, tmp_path):
    art = tmp_path / "art3.h5"
    result = run("mocap", "pca", session_file, "--stage", "2.1:1", "--stage", "8.*:2", "--frames", "0-200:2",
                 "-o", art)
    assert result.returncode == 0, result.stderr
    with h5py.File(art) as f:
        assert f["components"].shape[0] == 3


@pytest.mark.parametrize("args, words", [
    (("pca", "{session}", "-o", "{tmp}/a.txt"), "unknown extension"),
    (("pca", "{tmp}/missing.h5", "-o", "{tmp}/a.h5"), "missing.h5"),
    (("pca", "{session}", "--components", "0", "-o", "{tmp}/a.h5"), "at least 1"),
    (("apply", "{tmp}/missing.h5", "-o", "{tmp}/m.xml"), "missing.h5"),
    (("apply", "{session}", "--range", "3,1", "-o", "{tmp}/m.xml"), "MIN must be less than MAX"),
])
def test_errors_are_one_line(session_file, tmp_path, args, words):
    args = [a.format(session=session_file, tmp=tmp_path) for a in args]
    assert words in assert_user_error(run_in_process("mocap", *args))
