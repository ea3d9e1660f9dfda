"""The web page fits its window: the head framed as ``render --view front`` frames a picture of the window's
size, in headless Chromium (DevTools) and headless Firefox ESR (WebDriver BiDi), at 600×800, 640×480 and
1366×768, and again when the window is resized (the player's ResizeObserver).

For each, measured in the screenshot against the engine's own render at that size: the face's bounding
box (every pixel that is not the background, row by row) inside the picture with the margin render
keeps, centred, its edges within 3 px of the render's; the dark features within 3 px of the render's
(browser to engine); no console error;
no request outside the site, and none for a ``three/`` folder (three.js is in the bundle: no import
map). ``AP_SCREENSHOT_DIR=DIR`` writes the screenshots there.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from engine.outputs.render import render_model
from engine.speech.synthesis import wav_bytes
from engine.web.site import write_site
from tests.web_browser import CHROMIUM, Browser, outside, served
from tests.web_firefox import FIREFOX, Firefox
from tests.web_pictures import feature_distance_px

pytestmark = pytest.mark.slow
SIZES = [(600, 800), (640, 480), (1366, 768)]
POSE = {"jaw_open": 0.25}
EDGE_PX = 3            # the face's box, browser against engine, each edge
FEATURES_PX = 3.0      # the dark features' 95th-percentile distance
BROWSERS = {
    "chromium": pytest.param("chromium", marks=pytest.mark.skipif(
        CHROMIUM is None, reason="no chromium (AP_CHROMIUM or on the PATH; ./bootstrap installs it)")),
    "firefox": pytest.param("firefox", marks=pytest.mark.skipif(
        FIREFOX is None, reason="no firefox-esr (AP_FIREFOX or on the PATH; ./bootstrap installs it)")),
}


@pytest.fixture(scope="module")
def site(head, tmp_path_factory):
    folder = tmp_path_factory.mktemp("fit")
    values = np.array([[POSE["jaw_open"]], [POSE["jaw_open"]]])
    write_site(head, list(POSE), values, 50.0, wav_bytes(np.zeros(1600, np.float32), 16000), folder)
    return folder


@pytest.fixture(scope="module")
def renders(head):
    return {size: render_model(head, POSE, size=size) for size in [*SIZES, (1200, 300), (300, 900)]}


@pytest.fixture(scope="module", params=list(BROWSERS.values()))
def browser(request, site):
    with served(site) as base, (Browser() if request.param == "chromium" else Firefox()) as running:
        yield request.param, running, base


def face_box(picture: np.ndarray) -> tuple[int, int, int, int]:
    """(left, top, right, bottom) of what is not background: each row's background is its own leftmost
    pixels (the gradient runs top to bottom, and the framing keeps a margin at the sides)."""
    rgb = picture.astype(int)
    background = np.median(rgb[:, :4], axis=1, keepdims=True)
    face = np.abs(rgb - background).max(axis=2) > 12
    rows, columns = np.flatnonzero(face.sum(axis=1) >= 2), np.flatnonzero(face.sum(axis=0) >= 2)
    return int(columns[0]), int(rows[0]), int(columns[-1]), int(rows[-1])


def _keep(name: str, picture: np.ndarray) -> None:
    folder = os.environ.get("AP_SCREENSHOT_DIR")
    if folder:
        from PIL import Image

        Path(folder).mkdir(parents=True, exist_ok=True)
        Image.fromarray(picture).save(Path(folder) / name, quality=90)


def _shown(page, size: tuple[int, int]) -> np.ndarray:
    """The screenshot once the player is framed for ``size`` and has drawn two frames since."""
    page.wait_for(f"window.ArtificialPerson && ArtificialPerson.ready && ArtificialPerson.size.width === {size[0]}"
                  f" && ArtificialPerson.size.height === {size[1]}")
    page.evaluate("ArtificialPerson.nextFrame().then(() => ArtificialPerson.nextFrame())")
    return page.screenshot(size)


def check_framed(name: str, picture: np.ndarray, render: np.ndarray, size: tuple[int, int]) -> None:
    width, height = size
    shot, engine = face_box(picture), face_box(render)
    # the browser's dark features to the engine's (eyes, lashes, nostrils, the open mouth); not back: the engine
    # draws the brows darker than the player since the brows became hair (issue 32), which is not framing
    features = feature_distance_px(picture, render)[0]
    print(f"\n{name}: face box {shot} (engine {engine}); dark features {features:.1f} px")
    assert max(abs(a - b) for a, b in zip(shot, engine, strict=True)) <= EDGE_PX, (shot, engine)
    left, top, right, _ = shot
    margin = 0.05 * min(width, height * 0.75)
    assert left > margin and width - 1 - right > margin and top > 0.03 * height, "the head is cut or at an edge"
    assert abs((left + right) / 2 - (width - 1) / 2) <= 0.02 * width, "the head is not centred"
    assert features <= FEATURES_PX


@pytest.mark.parametrize("size", SIZES, ids=lambda s: f"{s[0]}x{s[1]}")
def test_the_head_is_framed_as_render_frames_a_picture_of_the_window_s_size(browser, renders, size):
    name, running, base = browser
    page = running.open(f"{base}/index.html?t=0", size)
    picture = _shown(page, size)
    _keep(f"fit-{name}-{size[0]}x{size[1]}.jpg", picture)
    assert picture.shape == (size[1], size[0], 3)
    check_framed(f"{name} {size[0]}x{size[1]}", picture, renders[size], size)
    assert page.evaluate("[document.getElementById('view').width, document.getElementById('view').height]") == \
        list(size)                                          # the drawing buffer is the canvas's size, not 600×800
    requested = page.requested()
    assert page.problems() == []
    assert f"{base}/player.js" in requested and not [url for url in requested if "/three/" in url]
    assert outside(requested, base) == []


def test_a_resized_window_is_framed_again(browser, renders):
    name, running, base = browser
    page = running.open(f"{base}/index.html?t=0", (600, 800))
    _shown(page, (600, 800))
    for size in [(1366, 768), (1200, 300), (300, 900)]:          # and a very wide and a very tall one
        page.resize(size)
        picture = _shown(page, size)
        _keep(f"fit-{name}-resized-{size[0]}x{size[1]}.jpg", picture)
        check_framed(f"{name} resized to {size[0]}x{size[1]}", picture, renders[size], size)
    assert page.problems() == []


def test_the_check_sees_a_head_framed_for_another_size(renders):
    """The measure can fail: the 600×800 framing squeezed into 640×480, or the head moved, is caught."""
    from PIL import Image

    squeezed = np.asarray(Image.fromarray(renders[(600, 800)]).resize((640, 480)))
    with pytest.raises(AssertionError):
        check_framed("600x800 squeezed into 640x480", squeezed, renders[(640, 480)], (640, 480))
    moved = np.roll(renders[(1366, 768)], 8, axis=1)
    with pytest.raises(AssertionError):
        check_framed("moved 8 px", moved, renders[(1366, 768)], (1366, 768))
