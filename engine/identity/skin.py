"""Skin that belongs to the person: its colour from the identity's ancestry, age and sex, with fine detail.

Every head :func:`engine.identity.make_identity_head` makes (the default
head's own identity too, continua and a design's people) is given a skin
image on its texture coordinates (the ``skin`` image of ``model.texture``;
docs/skin.md), worked out here, deterministically: the same identity gives
the same bytes. A photo-fitted head replaces it with its photographs.

* **Tone** (:func:`skin_tone`) — melanin and blood volume fractions of
  :mod:`engine.identity.skin_optics`' two-chromophore model: melanin blended
  by the ancestry shares from :data:`MELANIN` (inside Jacques's published
  ranges for light, moderately and darkly pigmented skin), a man's 12 % more
  (within a population men are darker than women, and redder), blood less
  and yellowing more with age.
* **Regions** (:func:`skin_regions`, placed by the MPEG-4 feature points):
  lips (much more blood, thinner epidermis: less melanin), cheeks and nose
  tip (more blood), ears, the skin round the eyes (a little darker), and a
  man's beard shadow; the painted brows and the mouth's dark inside are
  kept from the head's vertex colours.
* **Detail** (:mod:`engine.identity.skin_detail`) — pores everywhere, a
  mottle of melanin that grows with age, and fine lines (forehead, crow's
  feet, under the eyes, the nasolabial fold) that deepen with age: a height
  field that darkens its pits in the image, and that the physically based
  looks' shader turns into a bumped normal (``skin_detail`` in the look).

>>> from engine.identity import Identity
>>> light, dark = (skin_tone(Identity({"caucasian": 1, "african": 0, "asian": 0})),
...                skin_tone(Identity({"african": 1, "caucasian": 0, "asian": 0})))
>>> light.melanin < 0.05 < 0.25 < dark.melanin
True
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from engine.identity.iris import apply_iris
from engine.identity.parameters import RACES, Identity
from engine.identity.skin_atlas import skin_atlas, skin_faces
from engine.identity.skin_cache import cached_skin_pixels, skin_key
from engine.identity.skin_detail import detail_heights
from engine.identity.skin_optics import linear_to_srgb, skin_albedo, skin_albedo_fast
from engine.model import Model
from engine.model.texture import ModelTexture, TextureImage

SKIN_IMAGE = "skin"
ATLAS_SIZE = 1536
#: Melanosome volume fraction and yellowing (carotene-like, 0 … 1) of each ancestry's typical skin. The
#: fractions lie in Jacques's (1998) ranges: light 1.3–6.3 %, moderate 11–16 %, dark 18–43 %.
MELANIN = {"caucasian": 0.022, "asian": 0.055, "african": 0.36}
YELLOW = {"caucasian": 0.2, "asian": 0.45, "african": 0.3}
BLOOD = 0.06                    # dermal blood volume fraction of a young woman's forehead
MALE_MELANIN, MALE_BLOOD = 1.12, 1.15
BROW_MELANIN = 0.9              # the painted brows: a dark brown hair colour, darker with the skin
BROW_COLOUR = np.array([92, 64, 46])


@dataclass(frozen=True)
class SkinTone:
    """An identity's skin, before its regions: melanin and blood fractions, yellowing, age (years), maleness 0 … 1."""

    melanin: float
    blood: float
    yellow: float
    age: float
    male: float


def skin_tone(identity: Identity) -> SkinTone:
    """The tone of ``identity``'s skin (see the module's docstring)."""
    shares = identity.ancestry()
    male = float(np.clip(identity.value("sex"), 0.0, 1.0))
    age = float(identity.value("age"))
    melanin = sum(shares[r] * MELANIN[r] for r in RACES) * (1 + (MALE_MELANIN - 1) * male)
    yellow = sum(shares[r] * YELLOW[r] for r in RACES) + 0.25 * float(np.clip((age - 30) / 50, 0, 1))
    old = float(np.clip((age - 25) / 55, 0, 1))
    blood = BLOOD * (1 + (MALE_BLOOD - 1) * male) * (1 - 0.25 * old)
    if age < 18:                                    # children: rosier, a little lighter
        blood *= 1 + 0.3 * (18 - age) / 17
        melanin *= 1 - 0.2 * (18 - age) / 17
    return SkinTone(round(melanin, 6), round(blood, 6), round(yellow, 6), age, male)


def _smooth(t: np.ndarray) -> np.ndarray:
    t = np.clip(t, 0.0, 1.0)
    return np.asarray(t * t * (3 - 2 * t))


def _blob(points: np.ndarray, centre: np.ndarray, radius: float) -> np.ndarray:
    d = np.linalg.norm(points - centre, axis=1) / radius
    return np.asarray(np.exp(-0.5 * d * d * 4))


def skin_regions(model: Model) -> dict[str, np.ndarray]:
    """Per-vertex weights 0 … 1 of the face's regions, placed by the MPEG-4 feature points of ``model``."""
    P = model.vertices
    lm = {k: P[v] for k, v in model.landmarks.items()}
    front = _smooth((P[:, 2] - (lm["8.3"][2] - 25)) / 15)
    # lips: inside the outer lip contour (corners 8.3/8.4, top 8.1, bottom 8.2), in the front plane
    centre = (lm["8.3"] + lm["8.4"]) / 2
    half_width = abs(lm["8.3"][0] - lm["8.4"][0]) / 2 + 1.0
    x = (P[:, 0] - centre[0]) / half_width
    above = P[:, 1] > centre[1]
    height = np.where(above, lm["8.1"][1] - centre[1] + 0.6, centre[1] - lm["8.2"][1] + 0.6)
    y = (P[:, 1] - centre[1]) / np.maximum(height, 1e-6)
    # the upper lip's outline dips to the corners faster than an ellipse (its bow)
    r = np.sqrt(x * x + (y / np.where(above, 1 - 0.35 * x * x, 1.0)) ** 2)
    lips = _smooth((1.08 - r) / 0.16) * _smooth((P[:, 2] - (lm["8.3"][2] - 8)) / 4)
    eye_l, eye_r = (lm["3.7"] + lm["3.11"]) / 2, (lm["3.12"] + lm["3.8"]) / 2
    cheek = np.zeros(len(P))
    for eye, corner in ((eye_l, lm["8.3"]), (eye_r, lm["8.4"])):
        apple = np.array([eye[0] * 1.15, 0.45 * eye[1] + 0.55 * corner[1] + 4, eye[2] + 6])
        cheek = np.maximum(cheek, _blob(P * [1, 1, 0.4], apple * [1, 1, 0.4], 30.0))
    nose = np.maximum(_blob(P, lm["9.3"], 14.0), 0.7 * np.maximum(_blob(P, lm["9.1"], 9.0), _blob(P, lm["9.2"], 9.0)))
    eyes = np.maximum(_blob(P, eye_l, 26.0), _blob(P, eye_r, 26.0)) * front
    ears = _smooth((np.abs(P[:, 0]) - 62) / 8) * _smooth((P[:, 1] - 95) / 10) * _smooth((175 - P[:, 1]) / 10)
    beard = (_smooth((lm["9.15"][1] - 3 - P[:, 1]) / 6) * _smooth((P[:, 1] - (lm["8.2"][1] - 32)) / 8)
             * _smooth((P[:, 2] - (lm["8.3"][2] - 60)) / 20) * _smooth((70 - np.abs(P[:, 0])) / 12))
    beard *= 1 - lips
    forehead = _smooth((P[:, 1] - lm["4.3"][1] - 4) / 10) * front
    return {"lips": lips * front, "cheeks": cheek * front * (1 - lips), "nose": nose * (1 - lips),
            "eyes": eyes, "ears": ears, "beard": beard, "forehead": forehead}


def _painted(model: Model) -> tuple[np.ndarray, np.ndarray]:
    """Per vertex: how much it shows the painted brow (0 … 1), and whether it keeps its own colour (the
    mouth's inside): both read from the head's vertex colours against its skin colour."""
    n = model.n_vertices
    if model.vertex_colors is None:
        return np.zeros(n), np.zeros(n, dtype=bool)
    skin_hex = model.part_colors.get("skin", "#e3b49c")
    plain = np.array([int(skin_hex[i:i + 2], 16) for i in (1, 3, 5)], dtype=float)
    colours = model.vertex_colors.astype(float)
    towards = BROW_COLOUR - plain
    k = np.clip((colours - plain) @ towards / (towards @ towards), 0, 1)
    off_line = np.linalg.norm(colours - plain - k[:, None] * towards, axis=1)
    lm_y = model.vertices[model.landmarks["3.7"], 1] if "3.7" in model.landmarks else 0.0
    brow = np.where((off_line < 6) & (model.vertices[:, 1] > lm_y), k, 0.0)
    own = (np.linalg.norm(colours - plain, axis=1) > 3) & (brow == 0)
    return brow, own


def skin_texture(model: Model, identity: Identity, size: int = ATLAS_SIZE) -> TextureImage:
    """The skin image of ``identity`` on ``model``'s texture coordinates (``model`` its head)."""
    atlas = skin_atlas(model, size)
    tone = skin_tone(identity)
    regions = skin_regions(model)
    brow, own = _painted(model)
    old = float(np.clip((tone.age - 25) / 50, 0, 1))
    melanin = tone.melanin * (1 - 0.45 * regions["lips"]) * (1 + 0.18 * regions["eyes"]) \
        * (1 + 0.1 * regions["beard"] * tone.male)
    blood = tone.blood * (1 + 8.0 * regions["lips"] + 0.9 * regions["cheeks"] * (1 + 0.3 * tone.male)
                          + 0.5 * regions["nose"] + 0.6 * regions["ears"] - 0.1 * regions["eyes"])
    yellow = tone.yellow * (1 - 0.6 * regions["lips"])
    beard = regions["beard"] * float(np.clip((tone.male - 0.5) * 2, 0, 1)) * float(np.clip((tone.age - 15) / 8, 0, 1))
    fields = np.stack([np.log(melanin), np.log(blood), yellow, beard, brow, own.astype(float)], axis=1)
    texel = atlas.interpolate(fields)
    positions = atlas.interpolate(model.vertices)
    heights, mottle, redness = detail_heights(atlas, positions, regions, model, tone.age)
    mel_t = np.exp(texel[:, 0] + mottle * (0.05 + 0.2 * old))
    blood_t = np.exp(texel[:, 1] + redness * 0.12)
    linear = skin_albedo_fast(mel_t, blood_t, texel[:, 2])
    # a beard shadow: stubble under the skin, darker and bluish-grey where a man shaves
    linear *= 1 - texel[:, 3:4] * np.array([0.22, 0.20, 0.14])
    brow_linear = skin_albedo(np.array([max(BROW_MELANIN * 0.12, 4 * tone.melanin)]), np.array([0.02]))[0] * 0.2
    linear = linear * (1 - texel[:, 4:5]) + brow_linear * texel[:, 4:5]
    linear *= (1 + heights)[:, None]                   # pits and lines hold a little shadow of their own
    srgb = linear_to_srgb(linear).astype(float)
    if model.vertex_colors is not None:           # the mouth's inside keeps the head's own colours
        kept = atlas.interpolate(model.vertex_colors.astype(float))
        w = np.clip(texel[:, 5:6] * 1.5 - 0.25, 0, 1)
        srgb = srgb * (1 - w) + kept * w
    fill = srgb.mean(axis=0) if len(srgb) else np.array([200.0, 160.0, 140.0])
    pixels = atlas.image(srgb, fill)
    return TextureImage(SKIN_IMAGE, np.clip(np.rint(pixels), 0, 255).astype(np.uint8))


def apply_skin(model: Model, identity: Identity, size: int = ATLAS_SIZE) -> None:
    """Give ``model`` (a head on the default head's texture coordinates) the skin of ``identity``, in place.

    A head whose texture already shows images (photographs) keeps them; a model without texture
    coordinates, a skin part or the feature points the regions need is left as it is. The image is
    taken from the disk cache when it was worked out before (:mod:`engine.identity.skin_cache`).
    """
    texture = model.texture
    needed = ("3.7", "3.8", "3.11", "3.12", "8.1", "8.2", "8.3", "8.4", "9.1", "9.2", "9.3", "9.15", "4.3")
    if texture is None or "skin" not in model.parts or any(k not in model.landmarks for k in needed):
        return
    if any(image.name != SKIN_IMAGE for image in texture.images):
        return
    pixels = cached_skin_pixels(skin_key(model, identity, size), lambda: skin_texture(model, identity, size).pixels)
    image = TextureImage(SKIN_IMAGE, pixels)
    face_image = np.full(len(texture.face_image), -1, dtype=np.int64)
    face_image[skin_faces(model)] = 0
    model.texture = ModelTexture(texture.corner_uv.copy(), [image], face_image)
    model.changed()
    apply_iris(model, identity)                    # the eyes' colour too (engine.identity.iris)
