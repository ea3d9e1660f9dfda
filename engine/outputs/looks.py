"""Looks: how the head is lit and shaded, as named presets whose every setting is written down (docs/looks.md).

A :class:`Look` is everything that changes the picture apart from the model
and the pose: the lights, the ambient light, the soft occlusion in creases,
each kind of part's material, the anti-aliasing and the background. Three
presets ship:

``portrait`` (the default)
    a three-point portrait light — a key light 45° above the camera's left, a
    fill from the right at a sixth of its strength, a rim light from behind
    — over a dim sky-and-ground ambient, physically based shading (GGX
    highlights, Fresnel, skin that lets light wrap a little past the edge of
    the shadow, redder there), baked ambient occlusion in the creases, the skin image's fine detail
    (pores, lines) as relief (``skin_detail``), FXAA.
``flat``
    even light for psychophysics: a bright ambient and two weak lights from
    above, either side, so neither half of the face is darker, faint
    highlights, a little occlusion, FXAA, a uniform grey background.
``legacy``
    the look of every picture before looks existed, to the pixel: VTK's
    Phong shading with the renderer's three camera lights and 8×
    multisampling (:mod:`engine.outputs.render`'s own path, unchanged).

Every look rides with the camera (its lights are given in the camera's
frame: x right, y up, z towards the viewer), so a turned view keeps its
light. :meth:`Look.settings` gives every setting as plain data (what a
stimulus set's provenance records) and :func:`look_from` makes a look again
from a name, or from such settings with a ``preset`` to start from::

    look_from("portrait")
    look_from({"preset": "portrait", "occlusion": 0.5, "exposure": 1.1})
    look_from(recorded_settings)                  # provenance.json's "look": the same pictures again

>>> look = look_from("portrait")
>>> look.name, look.antialias, len(look.lights)
('portrait', 'fxaa', 3)
>>> look_from(look.settings()) == look
True
>>> look_from({"preset": "flat", "exposure": 1.2}).exposure
1.2
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, replace
from typing import Any

from engine.errors import UserError

__all__ = ["ANTIALIAS", "DEFAULT_LOOK", "LOOKS", "MATERIAL_CLASSES", "Light", "Look", "Material", "look_from",
           "look_option", "material_class"]

DEFAULT_LOOK = "portrait"
ANTIALIAS = ("fxaa", "msaa", "none")
#: The kinds of part a material is chosen for, by the start of the part's name (else ``skin``).
MATERIAL_CLASSES = ("eyelash", "eyebrow", "brow", "hair", "eye", "teeth", "tooth", "tongue", "gum", "mouth", "skin")
MAX_LIGHTS = 4


@dataclass(frozen=True)
class Light:
    """A directional light riding with the camera: ``direction`` towards the light in the camera's frame
    (x right, y up, z towards the viewer; need not be unit length), ``colour`` linear RGB, ``intensity``
    (1: a white surface facing it is lit to white)."""

    direction: tuple[float, float, float]
    colour: tuple[float, float, float] = (1.0, 1.0, 1.0)
    intensity: float = 1.0

    def unit_direction(self) -> tuple[float, float, float]:
        length = math.sqrt(sum(c * c for c in self.direction))
        return (self.direction[0] / length, self.direction[1] / length, self.direction[2] / length)

    def radiance(self) -> tuple[float, float, float]:
        """The colour times the intensity times π: what the shader multiplies the BRDF by."""
        return (self.colour[0] * self.intensity * math.pi, self.colour[1] * self.intensity * math.pi,
                self.colour[2] * self.intensity * math.pi)


@dataclass(frozen=True)
class Material:
    """How one kind of part reflects light: GGX ``roughness`` (0 mirror … 1 matte), refractive index
    ``ior`` (sets the reflectance at normal incidence, ((n − 1)/(n + 1))², 2.8 % for skin), ``specular``
    (a scale on the highlight; 1 is physical) and ``wrap`` (per RGB channel: how far light reaches past
    the shadow's edge, a cheap stand-in for light scattered under the skin; 0 is Lambert)."""

    roughness: float = 0.5
    ior: float = 1.4
    specular: float = 1.0
    wrap: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def reflectance(self) -> float:
        return ((self.ior - 1.0) / (self.ior + 1.0)) ** 2


@dataclass(frozen=True)
class Look:
    """One way of lighting and shading the head. ``shading`` is ``"pbr"`` (the shader of
    :mod:`engine.outputs.look_shader`, the same in VTK and in the web player) or ``"legacy"`` (VTK's
    Phong and the old camera lights; every other setting is then only a record)."""

    name: str
    shading: str = "pbr"
    lights: tuple[Light, ...] = ()
    sky: tuple[float, float, float] = (0.2, 0.2, 0.2)
    """Ambient light from above (the camera's up), linear RGB: a white surface facing up shows this much."""
    ground: tuple[float, float, float] = (0.1, 0.1, 0.1)
    """Ambient light from below."""
    occlusion: float = 1.0
    """How much of the ambient light the baked occlusion takes away in creases (0: none, 1: all it finds)."""
    direct_occlusion: float = 0.5
    """How much of the direct light it takes away there (soft shadow without shadow maps)."""
    occlusion_radius_mm: float = 30.0
    exposure: float = 1.0
    materials: Mapping[str, Material] = field(default_factory=dict)
    antialias: str = "fxaa"
    """How edges are smoothed when anti-aliasing is on: ``fxaa`` (a post-process: cheap on a software
    OpenGL), ``msaa`` (8× multisampling) or ``none``."""
    background: tuple[str, str] = ("#cfd1d4", "#eef0f2")
    """Bottom and top of the picture's vertical gradient (the same twice: one colour)."""
    skin_detail: float = 1.0
    """How strongly the skin image's fine detail (pores, lines: :mod:`engine.identity.skin_detail`) bumps the
    skin's normal in the physically based shader (0: off, 1: as made, up to 4); the image's colours stay."""
    version: int = 1

    def material(self, part: str) -> Material:
        """The material of a part, by its name (as :func:`material_class` sorts it)."""
        return self.materials.get(material_class(part), self.materials.get("skin", Material()))

    def settings(self) -> dict[str, Any]:
        """Every setting as plain JSON data; :func:`look_from` makes the same look of it."""
        return {
            "name": self.name, "version": self.version, "shading": self.shading,
            "lights": [{"direction": list(light.direction), "colour": list(light.colour),
                        "intensity": light.intensity} for light in self.lights],
            "sky": list(self.sky), "ground": list(self.ground), "occlusion": self.occlusion,
            "direct_occlusion": self.direct_occlusion, "occlusion_radius_mm": self.occlusion_radius_mm,
            "exposure": self.exposure,
            "materials": {name: {"roughness": m.roughness, "ior": m.ior, "specular": m.specular,
                                 "wrap": list(m.wrap)} for name, m in sorted(self.materials.items())},
            "antialias": self.antialias, "background": list(self.background), "skin_detail": self.skin_detail,
        }


def material_class(part: str) -> str:
    """The kind of part a name is, for its material: ``eyelashes_left`` → ``eyelash``, ``eye_left`` → ``eye``.

    >>> [material_class(p) for p in ("skin", "eye_left", "eyelashes_right", "teeth_upper", "Tongue", "cap")]
    ['skin', 'eye', 'eyelash', 'teeth', 'tongue', 'skin']
    """
    lowered = part.lower()
    for prefix in MATERIAL_CLASSES[:-1]:
        if lowered.startswith(prefix):
            return prefix
    return "skin"


_SKIN = Material(roughness=0.52, ior=1.4, specular=0.9, wrap=(0.16, 0.12, 0.1))
_MATERIALS = {
    "skin": _SKIN,
    # the cornea: a catchlight. With the key light 45° up its highlight sits at the top of the iris, half
    # under the upper lid; a little broader and brighter than physical (0.14, 1.0) it still shows there
    "eye": Material(roughness=0.2, ior=1.376, specular=1.3),
    "eyelash": Material(roughness=0.7, ior=1.55, specular=0.3),
    "eyebrow": Material(roughness=0.7, ior=1.55, specular=0.3),
    "brow": Material(roughness=0.7, ior=1.55, specular=0.3),
    "hair": Material(roughness=0.55, ior=1.55, specular=0.6),
    "teeth": Material(roughness=0.3, ior=1.6, specular=0.8),
    "tooth": Material(roughness=0.3, ior=1.6, specular=0.8),
    "tongue": Material(roughness=0.35, ior=1.35, specular=1.0, wrap=(0.3, 0.12, 0.1)),
    "gum": Material(roughness=0.35, ior=1.35, specular=1.0, wrap=(0.3, 0.12, 0.1)),
    "mouth": Material(roughness=0.4, ior=1.35, specular=0.8, wrap=(0.3, 0.12, 0.1)),
}

LOOKS: dict[str, Look] = {
    "portrait": Look(
        "portrait",
        # key: 45° above and 45° to the camera's left. Lower (0.6 up, as at first) the upper lip's
        # underside and the upper teeth took the same light as the lip's front, and dlib's lip
        # landmarks put the inner upper lip below the teeth: r 0.886 against the engine's lip gap
        lights=(Light((-1.0, 1.4, 1.0), (1.0, 0.96, 0.92), 1.0),
                Light((1.0, -0.1, 0.65), (0.92, 0.95, 1.0), 0.15),       # fill: the right, 1/6 as strong
                Light((0.7, 0.8, -1.0), (1.0, 1.0, 1.0), 0.4)),          # rim: behind, above
        sky=(0.07, 0.07, 0.073), ground=(0.06, 0.057, 0.054), occlusion=1.0, direct_occlusion=0.75,
        materials=_MATERIALS),
    "flat": Look(
        "flat",
        # from above the eyes, as even left and right as before: lit from the front (0.25 up, with more
        # ambient: sky 0.45, ground 0.38) the lips had no shading to set them off, r 0.802 (docs/looks.md)
        lights=(Light((-0.6, 1.2, 1.0), (1.0, 1.0, 1.0), 0.4), Light((0.6, 1.2, 1.0), (1.0, 1.0, 1.0), 0.4)),
        sky=(0.35, 0.35, 0.35), ground=(0.22, 0.22, 0.22), occlusion=0.6, direct_occlusion=0.3,
        materials={name: replace(m, specular=m.specular * 0.4) for name, m in _MATERIALS.items()},
        background=("#c8c8c8", "#c8c8c8")),
    # the old renderer's settings, recorded (engine.outputs.render draws this look with its own code)
    "legacy": Look(
        "legacy", shading="legacy",
        lights=(Light((-1.0, 0.9, 1.2), intensity=0.78), Light((1.3, 0.1, 1.0), intensity=0.42),
                Light((0.4, 1.2, -1.4), intensity=0.45)),
        sky=(0.0, 0.0, 0.0), ground=(0.0, 0.0, 0.0), occlusion=0.0, direct_occlusion=0.0, antialias="msaa",
        skin_detail=0.0),
}


def look_from(spec: str | Look | Mapping[str, Any] | None = None, where: str | None = None) -> Look:
    """A look from a preset's name, a :class:`Look`, or settings (a ``preset`` or ``name`` to start from,
    any setting of :meth:`Look.settings` to change); ``None``: the default. Bad settings raise
    :class:`UserError` (naming ``where``, a file, if given).

    >>> look_from("flat").name
    'flat'
    >>> look_from("studio")
    Traceback (most recent call last):
    ...
    engine.errors.UserError: unknown look 'studio' (looks: portrait, flat, legacy)
    """
    if spec is None:
        return LOOKS[DEFAULT_LOOK]
    if isinstance(spec, Look):
        return spec
    if isinstance(spec, str):
        if spec not in LOOKS:
            raise UserError(f"unknown look '{spec}' (looks: {', '.join(LOOKS)})", file=where)
        return LOOKS[spec]
    if not isinstance(spec, Mapping):
        raise UserError(f"a look is a preset's name or a table of settings, not {spec!r}", file=where)
    return _from_settings(dict(spec), where)


def look_option(text: str) -> Look:
    """The look a command line names: a preset's name, or a JSON file of settings (as a stimulus set's
    ``provenance.json`` records its ``"look"``)."""
    if text in LOOKS or not text.lower().endswith(".json"):
        return look_from(text)
    import json

    from engine.formats.text_files import read_bounded_text

    try:
        settings = json.loads(read_bounded_text(text, 1 << 20))
    except json.JSONDecodeError as exc:
        raise UserError(f"not a look's settings (JSON): {exc.msg}", file=text, line=exc.lineno) from None
    return look_from(settings, where=text)


_KEYS = {"preset", "name", "version", "shading", "lights", "sky", "ground", "occlusion", "direct_occlusion",
         "occlusion_radius_mm", "exposure", "materials", "antialias", "background", "skin_detail"}


def _from_settings(table: dict[str, Any], where: str | None) -> Look:
    def fail(message: str) -> UserError:
        return UserError(f"look: {message}", file=where)

    unknown = sorted(set(table) - _KEYS)
    if unknown:
        raise fail(f"unknown setting '{unknown[0]}' (settings: {', '.join(sorted(_KEYS - {'preset'}))})")
    start = table.get("preset", table["name"] if isinstance(table.get("name"), str) and table["name"] in LOOKS
                      else DEFAULT_LOOK)
    if not isinstance(start, str) or start not in LOOKS:
        raise fail(f"unknown preset {start!r} (looks: {', '.join(LOOKS)})")
    base = LOOKS[start]
    changes: dict[str, Any] = {}
    if "name" in table:
        changes["name"] = _text(table["name"], "name", fail)
    for key in ("occlusion", "direct_occlusion"):
        if key in table:
            changes[key] = _number(table[key], key, 0.0, 1.0, fail)
    if "occlusion_radius_mm" in table:
        changes["occlusion_radius_mm"] = _number(table["occlusion_radius_mm"], "occlusion_radius_mm", 1.0, 200.0,
                                                 fail)
    if "exposure" in table:
        changes["exposure"] = _number(table["exposure"], "exposure", 0.05, 20.0, fail)
    if "skin_detail" in table:
        changes["skin_detail"] = _number(table["skin_detail"], "skin_detail", 0.0, 4.0, fail)
    if "version" in table:
        changes["version"] = int(_number(table["version"], "version", 1, 1_000_000, fail))
    for key in ("sky", "ground"):
        if key in table:
            changes[key] = _rgb(table[key], key, 0.0, 20.0, fail)
    if "shading" in table:
        if table["shading"] not in ("pbr", "legacy"):
            raise fail("shading must be 'pbr' or 'legacy'")
        changes["shading"] = table["shading"]
    if "antialias" in table:
        if table["antialias"] not in ANTIALIAS:
            raise fail(f"antialias must be one of {', '.join(ANTIALIAS)}")
        changes["antialias"] = table["antialias"]
    if "background" in table:
        changes["background"] = _background(table["background"], fail)
    if "lights" in table:
        changes["lights"] = _lights(table["lights"], fail)
    if "materials" in table:
        changes["materials"] = _materials(table["materials"], base.materials, fail)
    return replace(base, **changes)


def _lights(value: Any, fail: Any) -> tuple[Light, ...]:
    if not isinstance(value, list) or len(value) > MAX_LIGHTS:
        raise fail(f"lights must be a list of up to {MAX_LIGHTS} lights")
    lights = []
    for k, entry in enumerate(value):
        if not isinstance(entry, Mapping) or not set(entry) <= {"direction", "colour", "intensity"} \
                or "direction" not in entry:
            raise fail(f"light {k + 1} must be a table with direction, and colour and intensity if wanted")
        direction = _rgb(entry["direction"], f"light {k + 1} direction", -1e3, 1e3, fail)
        if sum(c * c for c in direction) < 1e-12:
            raise fail(f"light {k + 1} direction must not be zero")
        lights.append(Light(direction, _rgb(entry.get("colour", [1, 1, 1]), f"light {k + 1} colour", 0.0, 20.0, fail),
                            _number(entry.get("intensity", 1.0), f"light {k + 1} intensity", 0.0, 20.0, fail)))
    return tuple(lights)


def _materials(value: Any, base: Mapping[str, Material], fail: Any) -> dict[str, Material]:
    if not isinstance(value, Mapping):
        raise fail("materials must be a table of part kinds")
    out = dict(base)
    names = {f.name for f in fields(Material)}
    for kind, entry in value.items():
        if kind not in MATERIAL_CLASSES:
            raise fail(f"unknown part kind '{kind}' in materials (kinds: {', '.join(MATERIAL_CLASSES)})")
        if not isinstance(entry, Mapping) or not set(entry) <= names:
            raise fail(f"materials.{kind} must be a table of {', '.join(sorted(names))}")
        material = out.get(kind, Material())
        changes: dict[str, Any] = {}
        if "roughness" in entry:
            changes["roughness"] = _number(entry["roughness"], f"materials.{kind}.roughness", 0.02, 1.0, fail)
        if "ior" in entry:
            changes["ior"] = _number(entry["ior"], f"materials.{kind}.ior", 1.0, 3.0, fail)
        if "specular" in entry:
            changes["specular"] = _number(entry["specular"], f"materials.{kind}.specular", 0.0, 10.0, fail)
        if "wrap" in entry:
            changes["wrap"] = _rgb(entry["wrap"], f"materials.{kind}.wrap", 0.0, 1.0, fail)
        out[kind] = replace(material, **changes)
    return out


def _number(value: Any, what: str, low: float, high: float, fail: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value) \
            or not low <= value <= high:
        raise fail(f"{what} must be a number from {low:g} to {high:g}")
    return float(value)


def _rgb(value: Any, what: str, low: float, high: float, fail: Any) -> tuple[float, float, float]:
    if not isinstance(value, list | tuple) or len(value) != 3:
        raise fail(f"{what} must be three numbers")
    r, g, b = (_number(v, what, low, high, fail) for v in value)
    return (r, g, b)


def _text(value: Any, what: str, fail: Any) -> str:
    if not isinstance(value, str) or not 0 < len(value) <= 64:
        raise fail(f"{what} must be a short text")
    return value


def _background(value: Any, fail: Any) -> tuple[str, str]:
    import re

    if isinstance(value, str):
        value = [value, value]
    if not isinstance(value, list | tuple) or len(value) != 2 or \
            not all(isinstance(v, str) and re.fullmatch(r"#[0-9a-fA-F]{6}", v) for v in value):
        raise fail("background must be a colour '#rrggbb' or two (bottom, top)")
    return (value[0].lower(), value[1].lower())
