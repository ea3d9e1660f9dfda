"""A look put onto VTK objects made elsewhere: an actor's shading, a renderer's anti-aliasing.

Nothing here imports VTK: the offscreen renderer (:mod:`engine.outputs.render`) and the workbench
viewport make the actors, meshes and arrays, and these functions only call their methods, so both
draw a look with the same settings and the same shader (:mod:`engine.outputs.look_shader`).

An actor in a physically based look is drawn with VTK's PBR interpolation, whose fragment shader
gives the surface's colour (``albedo``: the part colour, vertex colour or base-colour texture), the
normal ``N`` and the eye direction ``V`` in the camera's frame; :data:`FRAGMENT_REPLACEMENTS` then
has :func:`~engine.outputs.look_shader.SHADING`'s ``lookShade`` write the pixel, and the point array
:data:`OCCLUSION_ARRAY` (the baked occlusion) reaches it as a vertex attribute.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from engine.outputs.look_shader import look_uniforms, material_uniforms, shading_source

if TYPE_CHECKING:
    from engine.outputs.looks import Look

__all__ = ["OCCLUSION_ARRAY", "dress_actor", "set_antialias", "set_uniforms"]

OCCLUSION_ARRAY = "LookOcclusion"
_POINTS = 0                                    # vtkDataObject.FIELD_ASSOCIATION_POINTS
# (tag, before VTK's own substitutions?, replacement)
VERTEX_REPLACEMENTS = [
    ("//VTK::Normal::Dec", True, "//VTK::Normal::Dec\nin float lookOcclusionMC;\nout float lookOcclusionVSOutput;\n"),
    ("//VTK::Normal::Impl", True, "//VTK::Normal::Impl\n  lookOcclusionVSOutput = lookOcclusionMC;\n"),
]
FRAGMENT_REPLACEMENTS = [
    # ``{shading}``: look_shader.shading_source(look)
    ("//VTK::Normal::Dec", True, "//VTK::Normal::Dec\nin float lookOcclusionVSOutput;\n{shading}"),
    # after VTK's own lighting code (which stays, unused): our shading writes the pixel
    ("//VTK::Light::Impl", False,
     "//VTK::Light::Impl\n  fragOutput0 = vec4(lookShade(albedo, N, V, lookOcclusionVSOutput), opacity);\n"),
]


def dress_actor(actor: Any, look: Look, part: str, texture: Any | None = None) -> None:
    """Shade ``actor`` (its mapper's mesh holding the point array :data:`OCCLUSION_ARRAY`) as ``part`` in ``look``.

    ``texture``, if given, is the part's colour image (a ``vtkTexture``), drawn as the PBR base colour.
    """
    prop = actor.GetProperty()
    material = look.material(part)
    prop.SetInterpolationToPBR()
    prop.SetAmbient(0.0)
    prop.SetDiffuse(1.0)
    prop.SetSpecular(0.0)
    prop.SetRoughness(material.roughness)
    prop.SetMetallic(0.0)
    prop.SetBaseIOR(material.ior)
    if texture is not None:
        prop.SetBaseColorTexture(texture)
    mapper = actor.GetMapper()
    mapper.MapDataArrayToVertexAttribute("lookOcclusionMC", OCCLUSION_ARRAY, _POINTS, -1)
    shaders = actor.GetShaderProperty()
    shaders.ClearAllShaderReplacements()
    for tag, first, code in VERTEX_REPLACEMENTS:
        shaders.AddVertexShaderReplacement(tag, first, code, False)
    for tag, first, code in FRAGMENT_REPLACEMENTS:
        shaders.AddFragmentShaderReplacement(tag, first, code.replace("{shading}", shading_source(look)), False)
    set_uniforms(shaders.GetFragmentCustomUniforms(), {**look_uniforms(look), **material_uniforms(look, part)})


def set_uniforms(uniforms: Any, values: Mapping[str, float | Sequence[float]]) -> None:
    """Set floats and vec3s on a ``vtkUniforms``."""
    for name, value in values.items():
        if isinstance(value, int | float):
            uniforms.SetUniformf(name, float(value))
        else:
            uniforms.SetUniform3f(name, [float(v) for v in value])


def set_antialias(window: Any, renderer: Any, look: Look, on: bool, on_screen: bool = False) -> None:
    """Smooth the edges as ``look`` says while ``on``: 8× multisampling on the window for ``msaa``; for
    ``fxaa``, VTK's FXAA pass on a window on the screen (``on_screen``), while an offscreen frame is
    smoothed after it is read back (:func:`engine.outputs.antialias.fxaa`, the same algorithm at a
    sixth of the cost on a software OpenGL)."""
    method = look.antialias if on else "none"
    window.SetMultiSamples(8 if method == "msaa" else 0)
    if (method == "fxaa" and on_screen) or renderer.GetUseFXAA():
        renderer.SetUseFXAA(method == "fxaa" and on_screen)
