"""The look of a web site (:mod:`engine.outputs.looks`): what the player needs to light and shade the head
as ``render`` does, written into each animation JSON.

A physically based look (``portrait``, ``flat``, a look of one's own) goes in as ``"look"``: its
settings, the shader's uniforms shared by every part (:func:`engine.outputs.look_shader.look_uniforms`)
and each part's material uniforms, by part; the player compiles the engine's own GLSL
(:data:`engine.outputs.look_shader.SHADING`, put into ``player.js`` when the site is written) and reads
each point's baked occlusion from the ``.glb`` (``_OCCLUSION``, :mod:`engine.web.web_model`). The
``legacy`` look goes in as before: ``"lights"`` (the three camera lights) and ``"parts"`` (ambient,
diffuse, specular and power), drawn with three.js's Phong material.

>>> from engine import load_model
>>> document = look_document(load_model(), "portrait")
>>> sorted(document), document["look"]["name"], sorted(document["look"]["materials"])[:2]
(['background', 'look'], 'portrait', ['eye_left', 'eye_right'])
>>> sorted(look_document(load_model(), "legacy"))
['background', 'lights', 'parts']
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

from engine.errors import UserError
from engine.outputs.look_shader import look_uniforms, material_uniforms
from engine.outputs.looks import Look, look_from

if TYPE_CHECKING:
    from engine.model import Model

__all__ = ["CAMERA_LIGHTS", "LEGACY_BACKGROUND", "look_document", "recorded_look"]

#: The legacy look's background (bottom, top) and camera lights, as engine.outputs.render draws them.
LEGACY_BACKGROUND = ("#cfd1d4", "#eef0f2")
CAMERA_LIGHTS = [((-1.0, 0.9, 1.2), 0.78), ((1.3, 0.1, 1.0), 0.42), ((0.4, 1.2, -1.4), 0.45)]


def look_document(model: Model, look: str | Look | None = None) -> dict[str, Any]:
    """The entries of an animation JSON that say how the head looks in ``look`` (default ``portrait``)."""
    from engine.outputs.part_layout import PartLayout

    look = look_from(look)
    parts = PartLayout(model).parts
    if look.shading == "legacy":
        from engine.outputs.part_materials import part_material

        shading = {}
        for part in parts:
            _, ambient, diffuse, specular, power = part_material(part, model.part_colors)
            shading[part] = {"ambient": ambient, "diffuse": diffuse, "specular": specular, "power": power}
        return {"background": {"bottom": LEGACY_BACKGROUND[0], "top": LEGACY_BACKGROUND[1]},
                "lights": [{"camera_position": list(p), "intensity": i} for p, i in CAMERA_LIGHTS],
                "parts": shading}
    return {"background": {"bottom": look.background[0], "top": look.background[1]},
            "look": {"name": look.name, "shading": look.shading, "antialias": look.antialias,
                     "uniforms": look_uniforms(look),
                     "materials": {part: material_uniforms(look, part) for part in dict.fromkeys(parts)},
                     "settings": look.settings()}}


def recorded_look(set_folder: str | Path) -> Look | None:
    """The look a stimulus set was made with, from its ``provenance.json`` (``None``: a set made before
    looks were recorded, or with no provenance)."""
    path = Path(set_folder) / "provenance.json"
    if not path.is_file():
        return None
    try:
        settings = json.loads(path.read_text(encoding="utf-8")).get("look")
    except (OSError, ValueError, AttributeError):
        raise UserError("cannot read the set's provenance (JSON)", file=path) from None
    return None if settings is None else look_from(settings, where=str(path))
