"""What ``fit-photos`` reads: only regular files, within a bound; camera MPO files; no decompression bomb.

Each test here failed before the reader was bounded (issue 30): ``--landmarks
/dev/zero`` ran out of memory, a named pipe blocked for ever, an MPO file was
refused, a picture claiming 95 megapixels printed Pillow's warning before the
error line.
"""

from __future__ import annotations

import os
import struct
import sys
import zlib

import numpy as np
import pytest
from PIL import Image

from engine.formats.model_files import load_model
from engine.photofit import PhotoFitError, read_photo, read_points
from engine.photofit import photos as photos_module
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.fuzz_support import no_hang
from tests.engine.test_photofit import good_front, write_points

# The command with its address space capped, so that a reader that does read /dev/zero fails in seconds
# with a MemoryError instead of taking the machine's memory.
CAPPED = [sys.executable, "-c", "import resource, runpy; resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30)); "
          "runpy.run_module('engine', run_name='__main__', alter_sys=True)"]
WAIT = 20
"""Seconds a read of a named pipe may block before the test calls it a hang (a bound, not a timing check)."""


@pytest.fixture
def inputs(tmp_path):
    photo = tmp_path / "front.png"
    Image.fromarray(np.zeros((400, 300, 3), dtype=np.uint8)).save(photo)
    return photo, write_points(tmp_path / "points.json", {"front": good_front()})


@pytest.mark.parametrize("which", ["--landmarks", "--front", "--side"])
def test_a_device_as_input_is_refused_before_it_is_read(inputs, tmp_path, which):
    photo, points = inputs
    given = {"--front": photo, "--landmarks": points}
    given[which] = "/dev/zero"
    args = [a for option, value in given.items() for a in (option, value)]
    line = assert_user_error(run("fit-photos", *args, "-o", tmp_path / "p.xml", command=CAPPED))
    assert line.startswith("error: /dev/zero: ") and "not a regular file" in line, line


def test_a_folder_as_landmarks_or_photograph_is_refused(inputs, tmp_path):
    photo, points = inputs
    for args in (("--front", photo, "--landmarks", tmp_path), ("--front", tmp_path, "--landmarks", points)):
        line = assert_user_error(run("fit-photos", *args, "-o", tmp_path / "p.xml"))
        assert f"error: {tmp_path}: " in line and "not a regular file" in line, line


@pytest.mark.parametrize("what", ["landmarks", "photograph"])
def test_a_named_pipe_is_refused_without_blocking(tmp_path, what):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    known = set(load_model().landmarks)
    read = (lambda: read_points(fifo, known)) if what == "landmarks" else (lambda: read_photo(fifo))
    with no_hang(WAIT), pytest.raises(PhotoFitError) as caught:
        read()
    assert str(caught.value).startswith(f"{fifo}: ") and "not a regular file" in str(caught.value)


def test_a_named_pipe_on_the_command_line_ends_with_status_2(inputs, tmp_path):
    _, points = inputs
    fifo = tmp_path / "pipe.jpg"
    os.mkfifo(fifo)
    line = assert_user_error(run("fit-photos", "--front", fifo, "--landmarks", points, "-o", tmp_path / "p.xml"))
    assert "not a regular file" in line


def test_a_photograph_larger_than_the_byte_bound_is_refused_unread(tmp_path, monkeypatch):
    path = tmp_path / "big.png"
    Image.fromarray((np.random.default_rng(0).random((60, 60, 3)) * 255).astype(np.uint8)).save(path)
    monkeypatch.setattr(photos_module, "MAX_PHOTO_BYTES", path.stat().st_size - 1)
    with pytest.raises(PhotoFitError, match="file too large"):
        read_photo(path)


def png_claiming(width: int, height: int) -> bytes:
    """A PNG header that claims ``width`` × ``height`` RGB pixels, with one row of data: a bomb's shape."""
    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(b"\0" * (3 * width + 1)))
            + chunk(b"IEND", b""))


@pytest.mark.parametrize(("width", "height"), [
    (9_000, 9_000),          # 81 MP: above our bound, below Pillow's
    (10_000, 9_500),         # 95 MP: Pillow's DecompressionBombWarning
    (20_000, 20_000),        # 400 MP: Pillow's DecompressionBombError
])
def test_a_picture_claiming_too_many_pixels_is_one_clear_error(tmp_path, width, height):
    path = tmp_path / "bomb.png"
    path.write_bytes(png_claiming(width, height))
    with pytest.raises(PhotoFitError) as caught:
        read_photo(path)
    assert f"more than the {photos_module.MAX_PIXELS:,} pixels" in str(caught.value)


def test_the_decompression_bomb_warning_does_not_reach_stderr(inputs, tmp_path):
    _, points = inputs
    bomb = tmp_path / "bomb.png"
    bomb.write_bytes(png_claiming(10_000, 9_500))
    line = assert_user_error(run("fit-photos", "--front", bomb, "--landmarks", points, "-o", tmp_path / "p.xml"))
    assert "more than the 80,000,000 pixels" in line, line


def test_a_camera_mpo_file_is_read_as_its_first_picture(tmp_path):
    first = np.zeros((20, 60, 3), dtype=np.uint8)
    first[:, :10] = 255                                     # a white band on the stored picture's left
    second = np.full((20, 60, 3), 128, dtype=np.uint8)      # the other eye's picture (or a depth map)
    exif = Image.Exif()
    exif[0x0112] = 6                                        # "rotate 90° clockwise to view", as a phone writes
    path = tmp_path / "camera.jpg"
    Image.fromarray(first).save(path, format="MPO", save_all=True, append_images=[Image.fromarray(second)],
                                exif=exif.tobytes(), quality=95)
    with Image.open(path) as written:
        assert written.format == "MPO" and written.n_frames == 2
    upright = read_photo(path)
    assert upright.shape == (60, 20, 3)                     # the first picture, turned upright
    assert upright[:10].mean() > 200 and upright[-10:].mean() < 50
