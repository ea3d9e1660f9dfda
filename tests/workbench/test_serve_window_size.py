"""``serve --window`` fits the screen (issue 30, section 4): 600 × 800 on a 768-pixel laptop screen was cut at the chin.

The real ``serve --window`` on an X server of the test's own of a laptop's
and a desktop's size (Xvfb writing its screen to a file, as in
``test_serve_window.py``, whose helpers start the server and read the
screen): the window, found on the screen as the pixels that are not the bare
(black) root, must lie inside the screen with the shape asked for, and the
head inside the window with room around it, chin included. A size that
does not fit is made smaller with a note on stderr.
"""

from __future__ import annotations

import signal
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QRect

from engine.live.client import LiveClient
from tests.workbench.test_serve_window import Screen, applied, needs_xvfb, screen_of, screen_when, start_window_server
from workbench.live_window import fitted_size, place_on_screen

SCREENSHOTS = Path("/tmp")


def box(mask: np.ndarray) -> tuple[int, int, int, int]:
    """(left, top, right, bottom) of the True pixels, right and bottom exclusive."""
    rows, columns = np.nonzero(mask.any(axis=1))[0], np.nonzero(mask.any(axis=0))[0]
    return int(columns[0]), int(rows[0]), int(columns[-1]) + 1, int(rows[-1]) + 1


def window_on_screen(screen: Screen, folder: Path, *options: str) -> tuple[np.ndarray, str]:
    """``serve --window`` with ``options`` on ``screen``: what the screen shows once a pose is presented, and
    the server's stderr."""
    served = start_window_server(screen, folder, *options)
    try:
        with LiveClient(served.url) as head:
            applied(head, {"jaw_open": 0.0})
        picture = screen_when(screen, lambda picture: (picture.sum(axis=2) > 0).sum() > 1000)
    finally:
        served.process.send_signal(signal.SIGTERM)
        assert served.process.wait(timeout=30) == 0, served.stderr()
        assert served.process.stdout is not None
        served.process.stdout.close()
    assert "Traceback" not in served.stderr(), served.stderr()
    return picture, served.stderr()


def head_inside(picture: np.ndarray, window: tuple[int, int, int, int]) -> tuple[int, int, int, int]:
    """The head's box inside ``window``: the pixels that differ from the window's background (the renderer's
    gradient, the same across each row: its colour at the row's left edge)."""
    left, top, right, bottom = window
    inside = picture[top:bottom, left:right].astype(int)
    background = inside[:, :1, :]
    head = np.abs(inside - background).max(axis=2) > 30
    return box(head)


@needs_xvfb
@pytest.mark.slow
@pytest.mark.parametrize("width, height, fits", [(1366, 768, False), (1920, 1080, True)])
def test_the_default_window_fits_the_screen_with_the_whole_head(width, height, fits, tmp_path):
    # 600x800 is --size's default: passing it is what leaving it out does (start_window_server passes a small one)
    with screen_of(width, height, tmp_path) as screen:
        picture, stderr = window_on_screen(screen, tmp_path, "--size", "600x800")
    from engine.outputs.png_file import write_png

    write_png(SCREENSHOTS / f"serve-window-{width}x{height}.png", picture)
    window = box(picture.sum(axis=2) > 0)
    left, top, right, bottom = window
    shown = (right - left, bottom - top)
    assert right <= width and bottom <= height
    if fits:
        assert shown == (600, 800) and "note:" not in stderr
    else:
        assert shown == fitted_size((600, 800), (width, height)) and shown[1] < 768 - 40
        assert abs(shown[0] / shown[1] - 600 / 800) < 0.01, "the shape asked for"
        assert f"note: the window is {shown[0]}x{shown[1]}, not 600x800" in stderr
    head_left, head_top, head_right, head_bottom = head_inside(picture, window)
    # framed as `render --view front`: the neck's cut edge just above the bottom, background all round
    assert head_top > 0.03 * shown[1] and head_bottom <= shown[1] - 3, "the head whole, chin included"
    assert head_left > 0.05 * shown[0] and head_right < 0.95 * shown[0]


@needs_xvfb
@pytest.mark.slow
def test_an_explicit_size_larger_than_the_screen_is_made_smaller_with_a_note(tmp_path):
    with screen_of(1366, 768, tmp_path) as screen:
        picture, stderr = window_on_screen(screen, tmp_path, "--size", "1600x900")
    left, top, right, bottom = box(picture.sum(axis=2) > 0)
    assert (right - left, bottom - top) == fitted_size((1600, 900), (1366, 768)) == (1265, 712)
    assert "note: the window is 1265x712, not 1600x900: that does not fit the screen (1366x768 free)" in stderr


def test_a_size_that_fits_is_kept_and_one_that_does_not_keeps_its_shape():
    assert fitted_size((240, 320), (1366, 768)) == (240, 320)
    assert fitted_size((600, 800), (1920, 1080)) == (600, 800)
    w, h = fitted_size((600, 800), (1366, 768))
    assert h == 768 - 56 and abs(w / h - 0.75) < 0.005
    w, h = fitted_size((3000, 1000), (1366, 768))
    assert w == 1366 - 24 and abs(w / h - 3.0) < 0.01


def test_the_window_is_placed_inside_the_free_area(qtbot, capsys):
    from workbench.live_window import LiveWindow, close_window

    window = LiveWindow((600, 800))
    try:
        free = QRect(0, 27, 1366, 741)                  # a panel across the top of a laptop screen
        assert place_on_screen(window, (600, 800), free) == fitted_size((600, 800), (1366, 741))
        geometry = window.geometry()
        assert free.contains(geometry) and geometry.size().toTuple() == fitted_size((600, 800), (1366, 741))
        assert "note: the window is" in capsys.readouterr().err
    finally:
        close_window(window)
