"""The shading of a look, as GLSL: one text that both VTK (the renderer, the workbench viewport) and
three.js (the web player) compile, so the engine's pictures and the browser's agree by construction.

:data:`SHADING` (compiled with ``LOOK_LIGHTS`` defined as the look's number of lights:
:func:`shading_source`) defines ``vec3 lookShade(vec3 albedo, vec3 N, vec3 V, float occlusion)`` (and
:data:`UNIFORMS` declares its uniforms, for three.js: VTK declares the uniforms it is given itself):
``albedo`` the surface's linear colour (the part colour × vertex colour × texture, each made linear as
VTK's physically based shading does), ``N`` the unit normal and ``V`` the unit direction to the eye,
both in the camera's frame (x right, y up, z towards the viewer), ``occlusion`` the baked open sky
(:mod:`engine.outputs.occlusion`). It returns the pixel's colour with gamma 2.2, as VTK's physically
based shading writes it:

* each directional light adds a GGX microfacet highlight (Trowbridge–Reitz distribution, the
  height-correlated Smith visibility, Schlick's Fresnel with the material's reflectance at normal
  incidence) and the Lambert diffuse that the Fresnel leaves, the diffuse cosine wrapped per colour
  channel by the material's ``wrap`` (light reaching a little past the shadow's edge, redder: skin);
* a hemisphere ambient (``sky`` from the camera's up, ``ground`` from below) lights the albedo;
* the occlusion takes ``occlusion`` of the ambient and ``direct_occlusion`` of the direct diffuse light
  away (not of the highlights, which are the mirror image of the light: a catchlight in an eye next to
  the lid stays);
* times the exposure, clipped, back to gamma 2.2;
* on the skin, with ``LOOK_VIEW_POSITION`` defined (VTK: :func:`shading_source`), the normal is first
  bumped by the albedo's fine relief (``lookDetail``: the look's ``skin_detail``; 0 elsewhere).

:func:`look_uniforms` and :func:`material_uniforms` give the values, by uniform name, for a look and a
part: the renderer hands them to VTK, the site writes them into the animation JSON for the player.

>>> from engine.outputs.looks import look_from
>>> values = look_uniforms(look_from("portrait"))
>>> sorted(values)[:3], len(values["lookLightDirection0"])
(['lookAmbientOcclusion', 'lookDirectOcclusion', 'lookExposure'], 3)
>>> material_uniforms(look_from("portrait"), "eye_left")["lookRoughness"]
0.2
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from engine.outputs.looks import Look

__all__ = ["SHADING", "UNIFORMS", "look_uniforms", "material_uniforms", "shading_source", "web_shading_source"]

LIGHTS = 4

UNIFORMS = """
// Artificial Person: the uniforms of a look (engine/outputs/look_shader.py; VTK declares its own).
uniform vec3 lookLightDirection0;
uniform vec3 lookLightDirection1;
uniform vec3 lookLightDirection2;
uniform vec3 lookLightDirection3;
uniform vec3 lookLightRadiance0;
uniform vec3 lookLightRadiance1;
uniform vec3 lookLightRadiance2;
uniform vec3 lookLightRadiance3;
uniform vec3 lookSky;
uniform vec3 lookGround;
uniform float lookAmbientOcclusion;
uniform float lookDirectOcclusion;
uniform float lookExposure;
uniform float lookRoughness;
uniform float lookReflectance;
uniform float lookSpecular;
uniform vec3 lookWrap;
uniform float lookDetail;
"""

SHADING = """
// Artificial Person: the shading of a look (engine/outputs/look_shader.py; docs/looks.md).
float lookDistribution(float NdH, float alpha) {
  float a2 = alpha * alpha;
  float d = (NdH * a2 - NdH) * NdH + 1.0;
  return a2 / max(3.14159265 * d * d, 1e-8);
}

float lookVisibility(float NdV, float NdL, float alpha) {
  float a2 = alpha * alpha;
  float v = NdL * sqrt(NdV * NdV * (1.0 - a2) + a2);
  float l = NdV * sqrt(NdL * NdL * (1.0 - a2) + a2);
  return 0.5 / max(v + l, 1e-8);
}

// one directional light's diffuse and highlight reflected towards the eye, added to the sums
void lookLight(vec3 N, vec3 V, vec3 L, vec3 radiance, vec3 albedo, float alpha, inout vec3 diffuseSum,
               inout vec3 highlightSum) {
  float cosine = dot(N, L);
  vec3 H = normalize(V + L);
  float NdL = clamp(cosine, 0.0, 1.0);
  float NdV = clamp(dot(N, V), 1e-4, 1.0);
  float NdH = clamp(dot(N, H), 0.0, 1.0);
  float HdL = clamp(dot(H, L), 0.0, 1.0);
  float grazing = 1.0 - HdL;
  float grazing2 = grazing * grazing;
  float F = lookReflectance + (1.0 - lookReflectance) * grazing2 * grazing2 * grazing;
  vec3 wrapped = clamp((vec3(cosine) + lookWrap) / (vec3(1.0) + lookWrap), 0.0, 1.0);
  vec3 diffuse = (1.0 - F) * albedo * 0.31830989 * wrapped;
  float highlight = lookSpecular * F * lookDistribution(NdH, alpha) * lookVisibility(NdV, NdL, alpha) * NdL;
  diffuseSum += radiance * diffuse;
  highlightSum += radiance * highlight;
}

#ifdef LOOK_VIEW_POSITION
// the skin's fine detail as relief: the albedo's log luminance (the skin image darkens its pores and lines,
// engine/identity/skin_detail.py) taken as a height, LOOK_DETAIL_MM per unit, times lookDetail, bumping the
// normal by the surface gradient of its screen-space derivatives (Mikkelsen 2010, "Bump mapping
// unparametrized surfaces on the GPU"); the position is the fragment's in the camera's frame, mm
vec3 lookDetailNormal(vec3 albedo, vec3 N) {
  vec3 p = LOOK_VIEW_POSITION;
  float h = LOOK_DETAIL_MM * lookDetail * log(max(dot(albedo, vec3(0.2126, 0.7152, 0.0722)), 1e-4));
  vec3 sx = dFdx(p);
  vec3 sy = dFdy(p);
  vec3 r1 = cross(sy, N);
  vec3 r2 = cross(N, sx);
  float det = dot(sx, r1);
  vec3 gradient = sign(det) * (dFdx(h) * r1 + dFdy(h) * r2);
  vec3 bumped = abs(det) * N - gradient;
  return lookDetail > 0.0 && dot(bumped, bumped) > 1e-20 ? normalize(bumped) : N;
}
#endif

vec3 lookShade(vec3 albedo, vec3 N, vec3 V, float occlusion) {
#ifdef LOOK_VIEW_POSITION
  N = lookDetailNormal(albedo, N);
#endif
  float alpha = max(lookRoughness * lookRoughness, 0.002);
  vec3 diffuse = vec3(0.0);
  vec3 highlight = vec3(0.0);
#if LOOK_LIGHTS > 0
  lookLight(N, V, lookLightDirection0, lookLightRadiance0, albedo, alpha, diffuse, highlight);
#endif
#if LOOK_LIGHTS > 1
  lookLight(N, V, lookLightDirection1, lookLightRadiance1, albedo, alpha, diffuse, highlight);
#endif
#if LOOK_LIGHTS > 2
  lookLight(N, V, lookLightDirection2, lookLightRadiance2, albedo, alpha, diffuse, highlight);
#endif
#if LOOK_LIGHTS > 3
  lookLight(N, V, lookLightDirection3, lookLightRadiance3, albedo, alpha, diffuse, highlight);
#endif
  vec3 ambient = albedo * mix(lookGround, lookSky, 0.5 + 0.5 * N.y);
  float open = clamp(occlusion, 0.0, 1.0);
  vec3 colour = diffuse * mix(1.0, open, lookDirectOcclusion) + highlight
              + ambient * mix(1.0, open, lookAmbientOcclusion);
  return pow(clamp(colour * lookExposure, 0.0, 1.0), vec3(1.0 / 2.2));
}
"""


#: The skin's relief: millimetres of height per unit of the albedo's log luminance (a line
#: the skin image darkens by a quarter is 0.2 mm deep).
DETAIL_MM = 0.7
#: Where VTK's fragment shader keeps the fragment's position in the camera's frame (declared before the
#: look's shading is put in).
VTK_VIEW_POSITION = "vertexVCVSOutput.xyz"
#: Where three.js keeps it, negated (``vViewPosition``, declared before the web player puts the shading in).
WEB_VIEW_POSITION = "(-vViewPosition)"


def shading_source(look: Look) -> str:
    """:data:`SHADING` for ``look`` in VTK: compiled for as many lights as it has (``LOOK_LIGHTS``), with
    the skin's relief (``LOOK_VIEW_POSITION``: VTK's fragment position)."""
    return (f"#define LOOK_LIGHTS {len(look.lights)}\n#define LOOK_VIEW_POSITION {VTK_VIEW_POSITION}\n"
            f"#define LOOK_DETAIL_MM {DETAIL_MM:.6f}\n{SHADING}")


def web_shading_source() -> str:
    """:data:`UNIFORMS` and :data:`SHADING` as the web player compiles them: with the skin's relief from
    three.js's fragment position, in metres as the glTF is (the player defines ``LOOK_LIGHTS`` itself).

    >>> "#define LOOK_VIEW_POSITION (-vViewPosition)" in web_shading_source()
    True
    """
    return (f"#define LOOK_VIEW_POSITION {WEB_VIEW_POSITION}\n#define LOOK_DETAIL_MM {DETAIL_MM / 1000:.9f}\n"
            f"{UNIFORMS}{SHADING}")


def look_uniforms(look: Look) -> dict[str, float | list[float]]:
    """The uniforms of ``look`` shared by every part: lights (unused ones black), ambient, occlusion, exposure."""
    values: dict[str, float | list[float]] = {}
    for k in range(LIGHTS):
        if k < len(look.lights):
            light = look.lights[k]
            values[f"lookLightDirection{k}"] = [round(c, 9) for c in light.unit_direction()]
            values[f"lookLightRadiance{k}"] = [round(c, 9) for c in light.radiance()]
        else:
            values[f"lookLightDirection{k}"] = [0.0, 0.0, 1.0]
            values[f"lookLightRadiance{k}"] = [0.0, 0.0, 0.0]
    values.update(lookSky=list(look.sky), lookGround=list(look.ground), lookAmbientOcclusion=look.occlusion,
                  lookDirectOcclusion=look.direct_occlusion, lookExposure=look.exposure)
    return values


def material_uniforms(look: Look, part: str) -> dict[str, float | list[float]]:
    """The uniforms of one part's material in ``look``."""
    from engine.outputs.looks import material_class

    material = look.material(part)
    detail = look.skin_detail if material_class(part) == "skin" and look.shading == "pbr" else 0.0
    return {"lookRoughness": material.roughness, "lookReflectance": round(material.reflectance(), 9),
            "lookSpecular": material.specular, "lookWrap": list(material.wrap), "lookDetail": detail}
