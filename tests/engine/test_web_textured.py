"""A textured head's web site (issue 23: "the model as glTF … textured when the model is"), in real Chromium.

The default head gets an image on its MakeHuman atlas whose colour waves along both texture
axes (red across, green down), so a site that dropped the image, or flipped or
swapped its coordinates, shows other colours on the face. The site's still at rest is compared
with the engine's render of the same textured head: the face's mean colour and the mean pixel
difference; a control renders the head with its image flipped upside down and must differ.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest

from engine.model.texture import ModelTexture, TextureImage
from engine.outputs.render import render_model
from engine.speech.say import speak
from engine.web.site import write_speech_site
from tests.engine.test_photofit import skin_face_image
from tests.web_browser import CHROMIUM, Browser, served

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (./bootstrap installs it)")]

SIZE = 128


def ramp_image(flipped: bool = False) -> np.ndarray:
    """(SIZE, SIZE, 3): red waves across the image, green waves down it (upside down when ``flipped``), six of
    each, so a coordinate flipped or swapped anywhere on the face shows other colours there."""
    wave = 135 + 90 * np.sin(np.linspace(0, 12 * np.pi, SIZE) + 0.5)
    pixels = np.empty((SIZE, SIZE, 3), dtype=np.uint8)
    pixels[..., 0] = wave[None, :]
    pixels[..., 1] = (wave[::-1] if flipped else wave)[:, None]
    pixels[..., 2] = 90
    return pixels


def textured(head, pixels: np.ndarray):
    model = head.copy()
    model.texture = ModelTexture(model.texture.corner_uv.copy(), [TextureImage("ramp", pixels)],
                                 skin_face_image(model))
    return model


@pytest.fixture(scope="module")
def pictures(head, tmp_path_factory):
    model = textured(head, ramp_image())
    folder = tmp_path_factory.mktemp("textured-site")
    write_speech_site(speak("Moi.", model), model, folder)
    camera = json.loads((folder / "animation.json").read_text())["camera"]
    size = (camera["width"], camera["height"])
    with served(folder) as base, Browser() as chromium:
        page = chromium.open(f"{base}/index.html?t=0", size)
        page.ready()
        screenshot = page.screenshot(size)
        problems = page.problems()
    rest: dict[str, float] = {}
    engine = render_model(model, rest, size=size)
    flipped = render_model(textured(head, ramp_image(flipped=True)), rest, size=size)
    plain = render_model(head, rest, size=size)
    if os.environ.get("AP_SCREENSHOT_DIR"):                  # the pictures, to look at
        from engine.outputs.png_file import write_png

        for name, picture in (("browser", screenshot), ("engine", engine)):
            write_png(Path(os.environ["AP_SCREENSHOT_DIR"]) / f"web-textured-{name}.png", picture)
    return {"browser": screenshot, "engine": engine, "flipped": flipped, "plain": plain, "problems": problems,
            "glb": (folder / "head.glb").read_bytes()}


def face(picture: np.ndarray) -> np.ndarray:
    """The middle of the picture (the face: forehead to chin, cheek to cheek), as ints."""
    height, width = picture.shape[:2]
    return picture[height // 4: 3 * height // 4, width // 3: 2 * width // 3].astype(int)


def face_difference(a: np.ndarray, b: np.ndarray) -> float:
    """Mean |a − b| over the face, of 255."""
    return float(np.abs(face(a) - face(b)).mean())


def test_the_site_carries_the_image_in_its_glb(pictures):
    glb = pictures["glb"]
    chunk = json.loads(glb[20:20 + int.from_bytes(glb[12:16], "little")])
    assert len(chunk.get("images", [])) == 1 and chunk["textures"]
    assert any("baseColorTexture" in m.get("pbrMetallicRoughness", {}) for m in chunk["materials"])
    assert any("TEXCOORD_0" in p["attributes"] for mesh in chunk["meshes"] for p in mesh["primitives"])


def test_the_browser_draws_the_texture_as_the_engine_does(pictures):
    assert pictures["problems"] == []
    differences = {name: face_difference(pictures["browser"], pictures[name])
                   for name in ("engine", "flipped", "plain")}
    print(f"\nmean |browser − render| over the face, of 255: {differences}")
    assert differences["engine"] < 3.0
    # the measure sees an image turned upside down and an image left out
    assert differences["flipped"] > 3 * differences["engine"] and differences["flipped"] > 6.0
    assert differences["plain"] > 3 * differences["engine"] and differences["plain"] > 6.0
