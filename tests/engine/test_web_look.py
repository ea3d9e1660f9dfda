"""The look of a ``web-export`` site in a real browser (headless Chromium): the page lights and shades the head
as ``render`` does, preset by preset, within a stated tolerance (docs/web-export.md, docs/looks.md).

A site of a short jaw movement is written in each look and opened paused where the jaw is half open; the
screenshot is compared with the engine's render of the same pose in the same look. Controls that must
fall outside the tolerance: the other look's render, and the page of a site whose occlusion is switched
off. Without a browser: the site carries the look (its settings and uniforms in the animation JSON, the
engine's shader in ``player.js``, each point's baked occlusion in the ``.glb``, the same numbers the
renderer draws with). ``AP_SCREENSHOT_DIR=DIR`` also writes the screenshots and renders there.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest

from engine.outputs.look_shader import SHADING, UNIFORMS, web_shading_source
from engine.outputs.looks import LOOKS
from engine.outputs.occlusion import model_occlusion
from engine.outputs.render import render_model
from engine.speech.synthesis import wav_bytes
from engine.web.site import write_site
from engine.web.web_model import OCCLUSION
from tests.web_browser import CHROMIUM, Browser, served
from tests.web_pictures import feature_distance_px

SIZE = (300, 400)
AT_MS = 500.0                   # the jaw at 0.5, halfway between the two frames
PIXEL_TOLERANCE = 1.5           # mean |browser − engine| over the picture, of 255 (as tests/engine/test_web_browser.py)
FACE_TOLERANCE = 3.0            # the same over the face (eyes, nose, mouth)
FEATURES_PX = 3.0
NO_OCCLUSION = {"preset": "portrait", "occlusion": 0.0, "direct_occlusion": 0.0}
browser_needed = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (./bootstrap installs it)")


def _site(head, folder: Path, look) -> Path:
    values = np.array([[0.0], [1.0]])                   # jaw_open 0 at 0 ms, 1 at 1000 ms
    wav = wav_bytes(np.zeros(16000, dtype=np.float32), 16000)
    write_site(head, ["jaw_open"], values, 1000.0, wav, folder, duration_ms=1000.0, size=SIZE, look=look)
    return folder


def _face(difference: np.ndarray) -> np.ndarray:
    height, width = difference.shape[:2]
    return difference[int(0.38 * height):int(0.75 * height), int(0.3 * width):int(0.7 * width)]


def _keep(name: str, picture: np.ndarray) -> None:
    folder = os.environ.get("AP_SCREENSHOT_DIR")
    if folder:
        from engine.outputs.png_file import write_png

        Path(folder).mkdir(parents=True, exist_ok=True)
        write_png(Path(folder) / name, picture)


@pytest.fixture(scope="module")
def screenshots(head, tmp_path_factory):
    """The page of each look (and of portrait without occlusion), paused at AT_MS."""
    shots = {}
    for name in ("portrait", "flat", "legacy", "no occlusion"):
        folder = _site(head, tmp_path_factory.mktemp(name.replace(" ", "-")), NO_OCCLUSION if name == "no occlusion"
                       else name)
        with served(folder) as base, Browser() as chromium:
            page = chromium.open(f"{base}/index.html?t={AT_MS:g}", SIZE)
            page.ready()
            assert page.evaluate("ArtificialPerson.position") == pytest.approx(AT_MS, abs=1e-3)
            shots[name] = {"picture": page.screenshot(SIZE)[..., :3], "problems": page.problems()}
        _keep(f"web-look-{name.replace(' ', '-')}.png", shots[name]["picture"])
    return shots


# -- without a browser -------------------------------------------------------------------------------------

def test_the_site_carries_the_look(head, tmp_path):
    folder = _site(head, tmp_path / "site", "flat")
    animation = json.loads((folder / "animation.json").read_text())
    look = animation["look"]
    assert look["settings"] == LOOKS["flat"].settings() and look["name"] == "flat"
    assert animation["background"] == {"bottom": "#c8c8c8", "top": "#c8c8c8"} and "lights" not in animation
    assert look["uniforms"]["lookSky"] == list(LOOKS["flat"].sky)
    assert set(look["materials"]) == set(head.parts)
    assert json.dumps(web_shading_source()) in (folder / "player.js").read_text()      # the engine's own GLSL
    assert web_shading_source().endswith(UNIFORMS + SHADING)                          # with the relief's defines
    glb = (folder / "head.glb").read_bytes()
    length = int.from_bytes(glb[12:16], "little")
    document = json.loads(glb[20:20 + length])
    data = glb[20 + length + 8:]
    expected = model_occlusion(head, LOOKS["flat"].occlusion_radius_mm).astype(np.float32)
    start, found = 0, []
    for primitive in document["meshes"][0]["primitives"]:
        accessor = document["accessors"][primitive["attributes"][OCCLUSION]]
        view = document["bufferViews"][accessor["bufferView"]]
        found.append(np.frombuffer(data, "<f4", accessor["count"], view["byteOffset"]))
        start += accessor["count"]
    assert start == len(expected) and np.array_equal(np.concatenate(found), expected)


def test_a_legacy_site_is_drawn_as_before(head, tmp_path):
    animation = json.loads((_site(head, tmp_path / "site", "legacy") / "animation.json").read_text())
    assert "look" not in animation and len(animation["lights"]) == 3 and set(animation["parts"]) == set(head.parts)
    glb = (tmp_path / "site" / "head.glb").read_bytes()
    assert OCCLUSION.encode() not in glb


# -- in the browser ------------------------------------------------------------------------------------------

@pytest.mark.slow
@browser_needed
@pytest.mark.parametrize("name", ["portrait", "flat", "legacy"])
def test_the_page_shows_the_engines_look(head, screenshots, name):
    shot = screenshots[name]
    assert shot["problems"] == []
    render = render_model(head, {"jaw_open": 0.5}, size=SIZE, look=name)
    _keep(f"web-look-{name}-engine.png", render)
    difference = np.abs(shot["picture"].astype(int) - render.astype(int))
    features = feature_distance_px(shot["picture"], render)
    others = [other for other in ("portrait", "flat") if other != name]
    control = np.abs(shot["picture"].astype(int) - render_model(head, {"jaw_open": 0.5}, size=SIZE,
                                                                   look=others[0]).astype(int)).mean()
    print(f"{name}: browser against engine {difference.mean():.2f} grey levels ({_face(difference).mean():.2f} over "
          f"the face), features {features[0]:.1f}/{features[1]:.1f} px; against {others[0]} {control:.2f}")
    assert difference.mean() < PIXEL_TOLERANCE and _face(difference).mean() < FACE_TOLERANCE
    assert max(features) <= FEATURES_PX
    assert control > 3 * PIXEL_TOLERANCE


@pytest.mark.slow
@browser_needed
def test_a_page_without_the_occlusion_is_outside_the_tolerance(head, screenshots):
    render = render_model(head, {"jaw_open": 0.5}, size=SIZE, look="portrait")
    without = _face(np.abs(screenshots["no occlusion"]["picture"].astype(int) - render.astype(int))).mean()
    print(f"the page without occlusion against the engine's portrait: {without:.2f} grey levels over the face")
    assert without > FACE_TOLERANCE
