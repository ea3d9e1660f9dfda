"""Fuzzing the marker-file readers with damaged real files (hypothesis).

Each example takes a real file from tests/engine/data/capture, changes some bytes (or cuts it), and
reads it: the only way out other than a Recording is a MarkerFileError whose message names the file.
CI runs ``AP_FUZZ_EXAMPLES`` examples per test (default 200); the release check runs 10000:

    AP_FUZZ_EXAMPLES=10000 .venv/bin/python -m pytest tests/engine/test_capture_fuzz.py -q
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from engine.mocap.errors import MarkerFileError
from engine.mocap.readers import read_marker_file

DATA = Path(__file__).parent / "data" / "capture"
EXAMPLES = int(os.environ.get("AP_FUZZ_EXAMPLES", "200"))
C3D_FILES = ["FP_Type3.c3d", "read_NOTworking2.c3d", "Optotrak.c3d", "Kistler-parameters.c3d"]
TRC_FILES = ["opensim-exampleFormat.trc", "opensim-dataWithNaNsOfDifferentCases.trc"]
FUZZ = settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])


def _read_or_refuse(path: Path) -> None:
    try:
        rec = read_marker_file(path)
    except MarkerFileError as exc:
        message = str(exc)
        assert path.name in message
        return
    assert rec.positions.ndim == 3 and rec.positions.shape[1:] == (len(rec.labels), 3)
    assert np.isfinite(rec.rate_hz) and rec.rate_hz > 0


def _mutations(size: int, near: int):
    """(offset, new bytes) changes, weighted to the header and parameter section where the structure lives."""
    offset = st.one_of(st.integers(0, min(size, near) - 1), st.integers(0, size - 1))
    return st.lists(st.tuples(offset, st.binary(min_size=1, max_size=4)), min_size=1, max_size=8)


def _damaged(original: bytes, changes, cut) -> bytes:
    data = bytearray(original)
    for at, new in changes:
        data[at:at + len(new)] = new
    return bytes(data[:cut] if cut is not None else data)


TEXT_TOKENS = [b"\t", b"\n", b",", b" ", b"nan", b"inf", b"-1", b"1e308", b"1e-300", b"0", b"", b"\r\n", b"\x00",
               b"\xff"]


@pytest.mark.parametrize("name", C3D_FILES)
@FUZZ
@given(draw=st.data())
def test_damaged_c3d_files_read_or_are_refused_naming_the_file(name, tmp_path, draw):
    original = (DATA / name).read_bytes()
    changes = draw.draw(_mutations(len(original), 3072), label="changes")
    cut = draw.draw(st.one_of(st.none(), st.integers(0, len(original))), label="cut")
    path = tmp_path / name
    path.write_bytes(_damaged(original, changes, cut))
    _read_or_refuse(path)


@pytest.mark.parametrize("name", TRC_FILES)
@FUZZ
@given(draw=st.data())
def test_damaged_trc_files_read_or_are_refused_naming_the_file(name, tmp_path, draw):
    original = (DATA / name).read_bytes()
    tokens = st.sampled_from([*TEXT_TOKENS, b"PathFileType", b"NumFrames"])
    changes = draw.draw(st.lists(st.tuples(st.integers(0, len(original) - 1), tokens), min_size=1, max_size=8),
                        label="changes")
    cut = draw.draw(st.one_of(st.none(), st.integers(0, len(original))), label="cut")
    path = tmp_path / name
    path.write_bytes(_damaged(original, [(at, new) for at, new in changes], cut))
    _read_or_refuse(path)


@pytest.mark.parametrize("value", [float("nan"), float("inf"), -1.0, 1e30, 2.5])
def test_counts_given_as_floats_that_are_no_counts(value):
    """POINT:USED, POINT:FRAMES or ANALOG:USED written as a float (type 4) holding NaN, inf, −1 …: the header's."""
    import struct

    from engine.mocap import c3d_file
    from engine.mocap.c3d_parameters import C3dHeader, C3dParameter, C3dParameters

    header = C3dHeader(parameter_block=2, point_count=3, analog_per_frame=0, first_frame=1, last_frame=10,
                       scale=-1.0, data_block=3, rate=60.0)
    weird = C3dParameter(4, (), struct.pack("<f", value), "INTEL")
    params = C3dParameters("INTEL", {"POINT:USED": weird, "POINT:FRAMES": weird, "ANALOG:USED": weird,
                                     "ANALOG:RATE": C3dParameter(4, (), struct.pack("<f", 600.0), "INTEL")})
    notes: list[str] = []
    assert c3d_file._point_count(header, params, notes) == 3
    assert c3d_file._analog_words(header, params, 60.0, 3, 4, 10 * 48, notes) == 0
    assert c3d_file._frame_count(header, params, 10, notes, Path("x.c3d")) == 10


@pytest.mark.parametrize(("fmt", "key", "value", "message"), [
    ("trc", "NumFrames", "inf", r"x\.trc:3: NumFrames 'inf' is not a whole number"),
    ("trc", "DataRate", "1e300", r"x\.trc:3: DataRate must be a frame rate from 0\.001 to 1e\+06"),
    ("trc", "DataRate", "1e-300", r"x\.trc:3: DataRate must be a frame rate"),
    ("tsv", "FREQUENCY", "1e300", r"x\.tsv:\d+: FREQUENCY must be a frame rate from 0\.001 to 1e\+06"),
    ("tsv", "FREQUENCY", "1e-300", r"x\.tsv:\d+: FREQUENCY must be a frame rate"),
])
def test_header_numbers_out_of_any_range(tmp_path, fmt, key, value, message):
    import re

    from engine.mocap.sample_files import write_qtm_tsv, write_trc

    positions = np.arange(18.0).reshape(2, 3, 3)
    if fmt == "trc":
        path = write_trc(tmp_path / "x.trc", ["a", "b", "c"], positions, rate_hz=60)
        lines = Path(path).read_text().splitlines()
        cells = lines[2].split("\t")
        cells[lines[1].split("\t").index(key)] = value
        lines[2] = "\t".join(cells)
        Path(path).write_text("\n".join(lines) + "\n")
    else:
        path = write_qtm_tsv(tmp_path / "x.tsv", ["a", "b", "c"], positions, rate_hz=60)
        Path(path).write_text(re.sub(rf"{key}\t\S+", f"{key}\t{value}", Path(path).read_text()))
    with pytest.raises(MarkerFileError, match=message):
        read_marker_file(path)


@FUZZ
@given(draw=st.data())
def test_damaged_qtm_tsv_files_read_or_are_refused_naming_the_file(tmp_path, draw):
    """No public QTM export was found: the file is one engine.mocap.sample_files writes."""
    from engine.mocap.sample_files import write_qtm_tsv

    positions = np.random.default_rng(0).normal(0, 50, (6, 4, 3))
    positions[2, 1] = 0.0
    source = write_qtm_tsv(tmp_path / "source.tsv", ["8.3", "8.4", "2.1", "9.3"], positions, rate_hz=60)
    original = Path(source).read_bytes()
    tokens = st.sampled_from([*TEXT_TOKENS, b"EXT", b"NO_OF_FRAMES", b"MARKER_NAMES", b"EVENT\tx\t1e308\t1"])
    changes = draw.draw(st.lists(st.tuples(st.integers(0, len(original) - 1), tokens), min_size=1, max_size=8),
                        label="changes")
    cut = draw.draw(st.one_of(st.none(), st.integers(0, len(original))), label="cut")
    path = tmp_path / "take.tsv"
    path.write_bytes(_damaged(original, changes, cut))
    _read_or_refuse(path)


@pytest.mark.parametrize("pattern", [b"\x00\x81\x7f", b"\x00\x00\x80\x7f", b"\x01\x00\x80\xff"])
def test_signalling_nan_and_infinite_header_floats(tmp_path, pattern):
    """Found by the release fuzz run: a header scale or rate whose bits are a signalling NaN (numpy warned)."""
    for name in ("Kistler-parameters.c3d", "FP_Type3.c3d", "read_NOTworking2.c3d"):
        data = bytearray((DATA / name).read_bytes())
        data[13:13 + len(pattern)] = pattern
        path = tmp_path / name
        path.write_bytes(bytes(data))
        _read_or_refuse(path)
