"""Looks (docs/looks.md): the presets, every setting written down and read back, and each part of a look seen
in the pictures — so that a look that loses a part (the occlusion, the anti-aliasing, the lights, the
highlights) or a ``legacy`` that is no longer the old renderer's picture fails here.

``tests/engine/data/looks/legacy-*.png`` were drawn by the renderer as it was before looks existed
(``git show 1fb890d:engine/outputs/render.py``), with the same Mesa llvmpipe the tests run on, of the
head kept beside them (``legacy-head.npz``: the default head of that time, at rest and posed, with its
parts and colours), so that the default head may change and the check still hold.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import pytest

from engine.errors import UserError
from engine.outputs.antialias import fxaa
from engine.outputs.look_shader import SHADING, look_uniforms, shading_source
from engine.outputs.looks import DEFAULT_LOOK, LOOKS, look_from, look_option, material_class
from engine.outputs.occlusion import forget_computed, model_occlusion
from engine.outputs.part_layout import PartLayout
from engine.outputs.render import FrameRenderer, render_model
from engine.web.site import project, site_camera
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, made_set, run
from tests.engine.test_festival import needs_festival

DATA = Path(__file__).parent / "data" / "looks"
POSE = {"jaw_open": 0.4, "head_turn": 0.15, "brow_raise": 0.5}
SIZE = (300, 400)
NO_OCCLUSION = {"occlusion": 0.0, "direct_occlusion": 0.0}


def legacy_head():
    """The head the legacy references were drawn of (no rig: the camera frames its rest, it is drawn posed),
    and its pose."""
    from engine.model import Model

    kept = np.load(DATA / "legacy-head.npz")
    model = Model(kept["rest"].astype(float), kept["faces"], [str(p) for p in kept["parts"]], kept["vertex_part"],
                  landmarks={"2.1": int(kept["chin"])}, vertex_colors=kept["vertex_colors"],
                  part_colors=dict(zip(map(str, kept["part_names"]), map(str, kept["part_values"]), strict=True)))
    return model, kept["posed"].astype(float)


def textured_head(model):
    """``model`` with a made-up image on its skin: u, v from the rest vertices seen from the front."""
    from engine.model.texture import ModelTexture, TextureImage

    corners = model.faces[np.flatnonzero(_index_mask(model.faces))]
    low, high = model.vertices.min(axis=0), model.vertices.max(axis=0)
    uv = (model.vertices[corners][:, :2] - low[:2]) / (high[:2] - low[:2])
    y, x = np.mgrid[0:64, 0:64]
    pixels = np.stack([120 + 100 * np.sin(x / 5.0), 150 + 80 * np.cos(y / 7.0), 110 + 0 * x], axis=-1)
    sizes = _cell_sizes(model.faces)
    starts = np.concatenate([[0], np.cumsum(sizes[:-1] + 1)])
    skin = model.parts.index("skin")
    face_image = np.where(model.vertex_part[model.faces[starts + 1]] == skin, 0, -1)
    copy = model.copy()
    copy.texture = ModelTexture(uv, [TextureImage("waves", pixels.astype(np.uint8))], face_image)
    return copy


def _index_mask(faces):
    from engine.model.cells import cell_sizes, index_mask

    return index_mask(faces, cell_sizes(faces))


def _cell_sizes(faces):
    from engine.model.cells import cell_sizes

    return cell_sizes(faces)


def _reference(name: str) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(DATA / name).convert("RGB"))


def _luma(image: np.ndarray) -> np.ndarray:
    return image.astype(float) @ [0.299, 0.587, 0.114]


def _regions(head) -> dict[str, tuple[slice, slice]]:
    """Boxes of a front picture at SIZE (rows, columns): both eyes with their lids, under the nose, both cheeks."""
    camera = site_camera(head, SIZE)
    points = head.landmark_positions({})

    def at(name: str) -> np.ndarray:
        return project(camera, np.array([points[name]]))[0]

    eye_y = round(float(at("3.11")[1]))
    nose, lip = at("9.15"), at("8.1")
    return {
        "eye right": (slice(eye_y - 8, eye_y + 8), slice(round(at("3.12")[0]), round(at("3.8")[0]))),
        "eye left": (slice(eye_y - 8, eye_y + 8), slice(round(at("3.11")[0]), round(at("3.7")[0]))),
        "under nose": (slice(round(nose[1]) + 1, round(lip[1]) - 3), slice(round(nose[0]) - 10, round(nose[0]) + 10)),
        "cheek right": (slice(eye_y + 25, eye_y + 45), slice(round(at("3.12")[0]) + 9, round(at("3.8")[0]) - 13)),
        "cheek left": (slice(eye_y + 25, eye_y + 45), slice(round(at("3.11")[0]) + 13, round(at("3.7")[0]) - 9)),
    }


def _relative(head, image: np.ndarray) -> dict[str, float]:
    """The eyes' and under the nose's mean brightness relative to the cheeks'."""
    luma = _luma(image)
    boxes = {name: luma[box].mean() for name, box in _regions(head).items()}
    cheek = (boxes["cheek left"] + boxes["cheek right"]) / 2
    return {"eyes": (boxes["eye left"] + boxes["eye right"]) / 2 / cheek, "under nose": boxes["under nose"] / cheek}


# -- the presets and their settings ----------------------------------------------------------------------

def test_the_presets_and_the_default():
    assert list(LOOKS) == ["portrait", "flat", "legacy"] and DEFAULT_LOOK in LOOKS
    assert look_from(None) is LOOKS[DEFAULT_LOOK]
    portrait, flat = LOOKS["portrait"], LOOKS["flat"]
    assert len(portrait.lights) == 3 and portrait.antialias == flat.antialias == "fxaa"
    key, fill, rim = portrait.lights
    assert key.intensity > 3 * fill.intensity and key.direction[0] < 0 < fill.direction[0] and rim.direction[2] < 0
    # flat: the two halves of the face lit alike, much of it by the ambient light
    left, right = flat.lights
    assert left.intensity == right.intensity and left.direction[0] == -right.direction[0]
    assert sum(flat.sky) > 2 * sum(portrait.sky)
    # the lights come from high enough that the upper lip's underside is in shade and the opening of the
    # mouth reads to a face-landmark model (from near the eye line: r 0.886 and 0.802, docs/looks.md)
    for light in (key, left, right):
        x, y, z = light.unit_direction()
        assert y > 0.5 * math.hypot(x, z), light
    assert LOOKS["legacy"].shading == "legacy" and LOOKS["legacy"].antialias == "msaa"
    assert material_class("eye_left") == "eye" and portrait.material("eye_left").roughness <= 0.2
    assert portrait.material("skin").wrap[0] > portrait.material("skin").wrap[2]     # light wraps redder


def test_every_setting_reads_back_and_bad_ones_are_refused(tmp_path):
    for look in LOOKS.values():
        settings = look.settings()
        assert look_from(json.loads(json.dumps(settings))) == look
    changed = look_from({"preset": "portrait", "name": "mine", "exposure": 1.1,
                         "materials": {"skin": {"roughness": 0.6}},
                         "lights": [{"direction": [0, 0, 1], "intensity": 0.5}]})
    assert (changed.name, changed.exposure, changed.material("skin").roughness) == ("mine", 1.1, 0.6)
    assert look_from(changed.settings()) == changed and len(changed.lights) == 1
    for bad, message in [({"exposure": "bright"}, "exposure must be a number"),
                         ({"shine": 1}, "unknown setting 'shine'"),
                         ({"preset": "studio"}, "unknown preset"),
                         ({"lights": [{"direction": [0, 0, 0]}]}, "must not be zero"),
                         ({"materials": {"cape": {}}}, "unknown part kind 'cape'"),
                         ({"background": "grey"}, "background must be"),
                         ({"antialias": "ssaa"}, "antialias must be one of")]:
        with pytest.raises(UserError, match=message):
            look_from(bad)
    path = tmp_path / "look.json"
    path.write_text(json.dumps(LOOKS["flat"].settings()))
    assert look_option(str(path)) == LOOKS["flat"] and look_option("legacy") is LOOKS["legacy"]
    path.write_text("{not json")
    with pytest.raises(UserError, match="not a look's settings"):
        look_option(str(path))


def test_the_shader_is_compiled_for_the_looks_lights():
    assert shading_source(LOOKS["portrait"]).startswith("#define LOOK_LIGHTS 3\n") and SHADING in \
        shading_source(LOOKS["portrait"])
    uniforms = look_uniforms(LOOKS["flat"])
    assert uniforms["lookLightRadiance2"] == [0.0, 0.0, 0.0] and uniforms["lookSky"] == list(LOOKS["flat"].sky)


# -- legacy: the old renderer's pictures ---------------------------------------------------------------------

@pytest.mark.parametrize("view", ["front", "three-quarter"])
def test_legacy_is_the_old_renderers_picture_to_the_pixel(view):
    model, pose = legacy_head()
    with FrameRenderer(model, size=(150, 200), view=view, look="legacy") as renderer:
        assert np.array_equal(renderer.render(pose), _reference(f"legacy-{view}.png"))


def test_a_legacy_video_frame_and_a_textured_legacy_head_are_the_old_ones_to_the_pixel():
    model, pose = legacy_head()
    with FrameRenderer(model, size=(160, 120), antialias=False, look="legacy") as renderer:
        assert np.array_equal(renderer.render(pose), _reference("legacy-video-frame.png"))
    with FrameRenderer(textured_head(model), size=(150, 200), view="three-quarter", look="legacy") as renderer:
        assert np.array_equal(renderer.render(pose), _reference("legacy-textured.png"))
    with FrameRenderer(model, size=(150, 200), look="portrait") as renderer:        # the control
        assert np.abs(renderer.render(pose).astype(int) - _reference("legacy-front.png")).mean() > 5


# -- the parts of a physically based look, seen in the picture -----------------------------------------------

def test_the_occlusion_darkens_the_eyes_and_under_the_nose(head):
    with_occlusion = _relative(head, render_model(head, {}, size=SIZE, look="portrait"))
    without = _relative(head, render_model(head, {}, size=SIZE, look={"preset": "portrait", **NO_OCCLUSION}))
    print(f"eyes / cheeks {with_occlusion['eyes']:.3f} (without occlusion {without['eyes']:.3f}); under the nose "
          f"{with_occlusion['under nose']:.3f} ({without['under nose']:.3f})")
    assert with_occlusion["eyes"] < without["eyes"] - 0.05
    assert with_occlusion["under nose"] < without["under nose"] - 0.02


def test_the_baked_occlusion_is_lower_in_creases_and_the_same_every_time(head):
    layout = PartLayout(head)
    values = model_occlusion(head)
    forget_computed()
    again = model_occlusion(head.copy())                     # computed afresh for another model object
    assert np.array_equal(values, again)
    skin = layout.parts.index("skin")
    start, stop = layout.slices[skin]
    at = dict(zip(layout.used(skin).tolist(), values[start:stop], strict=True))
    creases = [at[head.landmarks[name]] for name in ("8.3", "8.4", "3.8", "3.11")]   # lip and eye corners
    forehead = head.vertices[layout.used(skin)][:, 1] > head.vertices[head.landmarks["4.1"], 1] + 15
    front = head.vertices[layout.used(skin)][:, 2] > head.vertices[head.landmarks["4.1"], 2] - 10
    assert max(creases) < np.median(values[start:stop][forehead & front]) - 0.2


def test_the_look_is_lit_from_the_camera_left_and_flat_is_even(head):
    halves = {}
    for name in ("portrait", "flat"):
        luma = _luma(render_model(head, {}, size=SIZE, look=name))
        boxes = _regions(head)
        halves[name] = luma[boxes["cheek right"]].mean() / luma[boxes["cheek left"]].mean()
    print(f"the picture's left cheek / its right: portrait {halves['portrait']:.2f}, flat {halves['flat']:.2f}")
    assert halves["portrait"] > 1.1 and abs(halves["flat"] - 1) < 0.06


def test_fxaa_smooths_the_outline_and_is_on_by_default(head):
    with FrameRenderer(head, size=SIZE, look="portrait") as smooth, \
            FrameRenderer(head, size=SIZE, look="portrait", antialias=False) as rough:
        pose = head.deform(POSE)
        smoothed, stepped = smooth.render(pose), rough.render(pose)
    assert np.array_equal(smoothed, fxaa(stepped))
    changed = np.abs(smoothed.astype(int) - stepped.astype(int)).max(axis=2) > 8
    assert 200 < changed.sum() < 0.05 * changed.size           # edges only


def test_a_catchlight_in_the_eyes(head):
    """The cornea's highlight of the key light: pixels of the eyes far brighter than with no highlights."""
    boxes = _regions(head)
    lit = _luma(render_model(head, {}, size=SIZE, look="portrait"))
    dull = _luma(render_model(head, {}, size=SIZE, look={"preset": "portrait",
                                                         "materials": {"eye": {"specular": 0.0}}}))
    for eye in ("eye left", "eye right"):
        assert (lit[boxes[eye]] - dull[boxes[eye]]).max() > 40


# -- through the command line ----------------------------------------------------------------------------------

def test_render_takes_a_look(head, tmp_path):
    from PIL import Image

    out = tmp_path / "flat.png"
    result = run("render", "--look", "flat", "--size", "120x160", "-o", out)
    assert result.returncode == 0, result.stderr
    assert np.array_equal(np.asarray(Image.open(out).convert("RGB")), render_model(head, {}, size=(120, 160),
                                                                                  look="flat"))
    assert "unknown look 'studio'" in assert_user_error(run_in_process("render", "--look", "studio", "-o",
                                                                       tmp_path / "x.png"))


# -- videos and stimulus sets -------------------------------------------------------------------------------

def test_a_video_is_drawn_in_its_look_by_both_processes(head, tmp_path, monkeypatch):
    """Every frame of a flat-look video (the render helper drawing every other one) is the flat still."""
    from engine.outputs.video_probe import read_frames
    from engine.outputs.video_writer import write_video

    monkeypatch.setenv("AP_RENDER_PROCESSES", "2")                 # the second process, however short
    times = np.arange(4) * (1000 / 25)
    out = tmp_path / "flat.mp4"
    write_video(out, head, times, np.full((4, 1), 0.4), ["jaw_open"], fps=25, size=(160, 120), look="flat")
    frames = read_frames(out)
    still = render_model(head, {"jaw_open": 0.4}, size=(160, 120), look="flat").astype(int)
    legacy = render_model(head, {"jaw_open": 0.4}, size=(160, 120), look="legacy").astype(int)
    for frame in frames:
        assert np.abs(frame.astype(int) - still).mean() < 2.5 < np.abs(frame.astype(int) - legacy).mean()


@needs_festival
def test_a_stimulus_set_records_its_look_and_is_drawn_in_it(tmp_path):
    from PIL import Image

    design = '[factors]\ntext = ["Moi."]\n[output]\nkinds = ["png"]\nsize = "96x72"\nlook = "{}"\n'
    pictures = {}
    for name in ("flat", "legacy"):
        (tmp_path / name).mkdir()
        folder = made_set(tmp_path / name, design.format(name)) / "set"
        provenance = json.loads((folder / "provenance.json").read_text())
        assert provenance["look"] == LOOKS[name].settings()
        assert set(provenance["look_methods"]) == {"shader_sha256", "fxaa", "occlusion"}
        with (folder / "manifest.csv").open(encoding="utf-8") as stream:
            (row,) = list(csv.DictReader(stream))
        assert row["look"] == name
        pictures[name] = np.asarray(Image.open(folder / row["file_png"]).convert("RGB")).astype(int)
    assert np.abs(pictures["flat"] - pictures["legacy"]).mean() > 5
