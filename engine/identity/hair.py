"""Hair where people have it: brows, scalp hair and facial hair as parts of the head that move with its skin.

:func:`add_hair` gives a head (the default head or any identity made on its
mesh) the hair of a :class:`~engine.identity.hair_style.HairChoice`, as new
parts:

* ``eyebrow_left``, ``eyebrow_right`` — a few hundred short hairs each,
  rooted in the painted brow's band (landmarks 4.1–4.6), standing up at the
  head of the brow and lying outwards along it (``thin``, ``medium``, ``thick``);
* ``hair`` — the scalp: ``short`` (cropped, combed from the crown),
  ``long`` (parted, falling past the ears to the jaw), ``tied`` (combed
  back into a knot); ``none`` is bald;
* ``hair_beard`` — a ``moustache`` or a full ``beard``; ``beard_stubble`` — ``stubble``, the skin
  under it darkened (shaded as skin, being skin more than hair).

The hair is grown on the default head (:mod:`engine.identity.hair_geometry`)
and held by its skin (:mod:`engine.identity.hair_surface`): on an identity it
sits on that person's skin, and in the rig every hair vertex takes the
weights (and field displacements) of the skin point it hangs from, so the
brows follow AU1, AU2 and AU4 and all hair follows the head (§2.2). Colours
are per vertex, the hair's colour varied strand by strand; grey hair is
white strands among a few dark ones. The choice is recorded on the head's
identity record (``<hair>`` in the model file).

>>> from engine.identity import Identity, make_identity_head
>>> from engine.identity.hair_style import HairChoice
>>> head = add_hair(make_identity_head(Identity()), HairChoice.parse(style="short", colour="brown"))
>>> [p for p in head.parts if p.startswith(("hair", "eyebrow"))]
['eyebrow_left', 'eyebrow_right', 'hair']
"""

from __future__ import annotations

from dataclasses import replace
from functools import cache

import numpy as np

from engine.errors import UserError
from engine.identity.errors import IdentityError
from engine.identity.hair_geometry import HairPiece, brow_hairs, bun, curtain, ribbons, sample_roots, shell, tangent
from engine.identity.hair_regions import HairRegions, default_regions
from engine.identity.hair_style import COLOURS, HairChoice, colour_for
from engine.identity.hair_surface import SkinSurface, place, rig_for_anchors
from engine.model import Model
from engine.model.identity_record import IdentityRecord
from engine.model.texture import ModelTexture

HAIR_PARTS = ("eyebrow_left", "eyebrow_right", "hair", "hair_beard", "beard_stubble")
#: Hairs per brow and the band's half-widths (inner, top, outer; mm) for each brow thickness.
BROW_HAIRS = {"thin": (160, (2.6, 2.0, 1.1)), "medium": (260, (3.6, 2.9, 1.6)), "thick": (380, (4.6, 3.7, 2.1))}
CROWN = np.array([0.0, 248.0, 10.0])          # short hair is combed out from here (default head, mm)
TIE = np.array([0.0, 190.0, -52.0])           # tied hair is pulled to here


@cache
def _default_surface() -> tuple[np.ndarray, HairRegions, SkinSurface]:
    from engine.formats.model_files import load_model

    head = load_model()
    regions = default_regions()
    return head.vertices, regions, SkinSurface(head.vertices, regions.triangles)


@cache
def grown(part: str, kind: str, seed: int) -> HairPiece:
    """The hair of one part in one kind (``short``, ``stubble``, ``thick`` …) on the default head."""
    vertices, regions, surface = _default_surface()
    rng = np.random.default_rng([seed, HAIR_PARTS.index(part), len(kind)])
    if part.startswith("eyebrow"):
        count, widths = BROW_HAIRS[kind]
        ends = regions.brow_left if part == "eyebrow_left" else regions.brow_right
        return brow_hairs(surface, ends, count, widths, rng)
    if part == "hair":
        return _scalp(kind, vertices, regions, surface, rng)
    return _beard(kind, vertices, regions, surface, rng)


def _scalp(kind: str, vertices: np.ndarray, regions: HairRegions, surface: SkinSurface,
           rng: np.random.Generator) -> HairPiece:
    thickness = {"short": 4.0, "long": 6.5, "tied": 2.6}[kind]
    body = shell(vertices, regions, regions.scalp, thickness, surface, shade=0.62)
    dense = np.zeros(len(vertices))
    dense[regions.skin] = regions.scalp
    near_scalp = SkinSurface(vertices, regions.triangles[(dense[regions.triangles] > 0).any(axis=1)])

    def inside(points: np.ndarray) -> np.ndarray:
        anchors = near_scalp.closest(points)
        return np.einsum("mk,mk->m", anchors.bary, dense[anchors.corners]) > 0.05

    def field(points: np.ndarray, normals: np.ndarray) -> np.ndarray:
        if kind == "short":
            out = points - CROWN
            out[:, 1] = np.minimum(out[:, 1], 0.0) - 8.0        # out from the crown, and down
        elif kind == "tied":
            out = TIE - points
        else:                                                   # parted in the middle, falling down the sides
            side = np.where(points[:, 0] >= 0, 1.0, -1.0)
            out = np.stack([side * 0.9, np.full(len(points), -1.0), np.full(len(points), -0.35)], axis=1)
        return tangent(out, normals)

    count = {"short": 2200, "long": 1800, "tied": 1700}[kind]
    roots = sample_roots(vertices, regions, regions.scalp, count, rng)
    anchors = surface.closest(roots)
    strength = np.einsum("mk,mk->m", anchors.bary, dense[anchors.corners])
    length = {"short": 15.0, "long": 34.0, "tied": 30.0}[kind] * rng.uniform(0.7, 1.2, count)
    height = 0.35 + (thickness - 0.25) * strength + rng.uniform(0.0, 0.6, count)
    strands = ribbons(surface, roots, field, length, rng.uniform(0.7, 1.2, count), height,
                      4, rng.uniform(0.78, 1.18, count), lift_tip=0.3 if kind == "short" else 0.0,
                      keep=inside if kind == "short" else None)
    pieces = [body, strands]
    skin = regions.skin
    if kind == "long":
        pieces.append(curtain(vertices, skin, near_scalp, 182.0, 52.0, 66.0, 260, 9, 2.5, rng))
    elif kind == "tied":
        pieces.append(bun(TIE + np.array([0.0, 0.0, -6.0]), 20.0, near_scalp, rng))
    return HairPiece.join(pieces)


def _beard(kind: str, vertices: np.ndarray, regions: HairRegions, surface: SkinSurface,
           rng: np.random.Generator) -> HairPiece:
    if kind == "stubble":
        stubble = shell(vertices, regions, regions.beard, 0.35, surface, least=0.3)
        dense = np.zeros(len(vertices))
        dense[regions.skin] = regions.beard
        stubble.shade = -np.einsum("mk,mk->m", stubble.anchors.bary, dense[stubble.anchors.corners])
        return stubble
    strength = regions.moustache if kind == "moustache" else regions.beard
    thickness = 2.2 if kind == "moustache" else 5.0
    body = shell(vertices, regions, strength, thickness, surface, shade=0.6)
    count = 600 if kind == "moustache" else 1700
    roots = sample_roots(vertices, regions, strength, count, rng)
    dense = np.zeros(len(vertices))
    dense[regions.skin] = strength
    anchors = surface.closest(roots)
    s = np.einsum("mk,mk->m", anchors.bary, dense[anchors.corners])

    def down(points: np.ndarray, normals: np.ndarray) -> np.ndarray:
        out = np.zeros_like(points)
        out[:, 1] = -1.0
        out[:, 0] = 0.25 * np.sign(points[:, 0])
        return tangent(out, normals)

    length = (6.0 if kind == "moustache" else 9.0) * rng.uniform(0.6, 1.2, count)
    strands = ribbons(surface, roots, down, length, rng.uniform(0.45, 0.8, count),
                      0.3 + (thickness - 0.25) * s + rng.uniform(0, 0.4, count), 3,
                      rng.uniform(0.78, 1.18, count))
    return HairPiece.join([body, strands])


def pieces_for(choice: HairChoice) -> dict[str, HairPiece]:
    """The parts a choice grows (default head), by part name."""
    out: dict[str, HairPiece] = {}
    if choice.brows != "none":
        for part in ("eyebrow_left", "eyebrow_right"):
            out[part] = grown(part, choice.brows, choice.seed)
    if choice.style != "none":
        out["hair"] = grown("hair", choice.style, choice.seed)
    if choice.beard == "stubble":                  # shaded as skin (the material of a part named beard…)
        out["beard_stubble"] = grown("beard_stubble", choice.beard, choice.seed)
    elif choice.beard != "none":
        out["hair_beard"] = grown("hair_beard", choice.beard, choice.seed)
    return out


def strand_colours(piece: HairPiece, colour: str, seed: int, skin_rgb: np.ndarray) -> np.ndarray:
    """sRGB per vertex: the hair's colour times each vertex's shade; grey and white hair mixes in dark
    strands; stubble (shade < 0) is the skin under it darkened towards the hair's colour."""
    rgb = np.array(COLOURS[colour], float)
    rng = np.random.default_rng([seed, 7])
    strands = int(piece.strand.max()) + 1 if len(piece.strand) else 0
    own = np.tile(rgb, (strands, 1))
    if colour in ("grey", "white"):
        dark = rng.random(strands) < (0.3 if colour == "grey" else 0.1)
        own[dark] = COLOURS["dark-brown"]
    # light hair lets light through: its shadowed under-layer is less dark than dark hair's
    depth = 0.5 if colour in ("grey", "white", "blond") else 1.0
    out = own[piece.strand] * (1.0 - depth * (1.0 - np.abs(piece.shade)))[:, None]
    stubble = piece.shade < 0
    if stubble.any():
        k = 0.5 * -piece.shade[stubble, None]                  # thinning out at the beard's edge
        out[stubble] = (1 - k) * skin_rgb[stubble] + k * rgb * 0.8
    return np.clip(np.rint(out), 0, 255).astype(np.uint8)


def add_hair(model: Model, choice: HairChoice) -> Model:
    """A copy of ``model`` with ``choice``'s hair as parts (any hair it had is replaced), rigged with its skin.

    ``model`` must have the default head's skin mesh (the default head, or an identity made on it).
    A choice without a colour takes the one :func:`~engine.identity.hair_style.colour_for` gives the person.
    """
    base = without_hair(model)
    _, regions, _ = _default_surface()
    skin_tri = base.triangles()
    if base.n_vertices < int(regions.triangles.max()) + 1 or "skin" not in base.parts:
        raise IdentityError("hair grows on the default head's skin: this model's mesh is not the default head's")
    same = {tuple(t) for t in regions.triangles[:50].tolist()} <= {tuple(t) for t in skin_tri.tolist()}
    if not same:
        raise IdentityError("hair grows on the default head's skin: this model's mesh is not the default head's")
    if not choice.colour:
        choice = choice.with_colour(colour_for(base.identity))
    pieces = pieces_for(choice)
    vertices, faces, vertex_part = [base.vertices], [base.faces], [base.vertex_part]
    parts = list(base.parts)
    colours = [base.vertex_colors if base.vertex_colors is not None else _part_rgb(base)]
    anchors_all = []
    skin_colours = skin_vertex_colours(base)
    n = base.n_vertices
    for name, piece in pieces.items():
        parts.append(name)
        points = place(base.vertices, piece.anchors)
        vertices.append(points)
        tri = piece.triangles + n
        faces.append(np.column_stack([np.full(len(tri), 3), tri]).ravel())
        vertex_part.append(np.full(len(points), len(parts) - 1))
        skin_rgb = np.einsum("mk,mkd->md", piece.anchors.bary, skin_colours[piece.anchors.corners])
        colours.append(strand_colours(piece, choice.colour, choice.seed + len(parts), skin_rgb))
        anchors_all.append(piece.anchors)
        n += len(points)
    from engine.identity.hair_surface import Anchors

    regions_out = rig_for_anchors(base, Anchors.concatenate(anchors_all), base.n_vertices)
    texture = base.texture
    all_faces = np.concatenate(faces)
    if texture is not None:
        added = sum(len(p.triangles) for p in pieces.values())
        texture = ModelTexture(np.concatenate([texture.corner_uv, np.zeros((3 * added, 2))]), texture.images,
                               np.concatenate([texture.face_image, np.full(added, -1, np.int64)]))
    try:
        out = Model(np.concatenate(vertices), all_faces, parts, np.concatenate(vertex_part), base.parameters.copy(),
                    regions_out, dict(base.landmarks), base.name, base.description, dict(base.part_colors),
                    np.concatenate(colours), texture)
    except UserError as exc:                                      # a mistake here, not the user's
        raise IdentityError(f"the hair could not be added: {exc.message}") from None
    out.identity = _with_hair(base.identity, choice)
    return out


def without_hair(model: Model) -> Model:
    """``model`` without the parts :func:`add_hair` makes (the model itself when it has none).

    The hair's vertices are the last ones (as :func:`add_hair` appends them), so the rest keep their numbers.
    """
    hair = [k for k, p in enumerate(model.parts) if p in HAIR_PARTS]
    if not hair:
        return model
    is_hair = np.isin(model.vertex_part, hair)
    keep = int(np.argmax(is_hair)) if is_hair.any() else model.n_vertices
    if is_hair[keep:].sum() != model.n_vertices - keep:
        raise IdentityError("this model's hair parts are not its last vertices: they were not made by add_hair")
    from engine.model.cells import cell_sizes, cell_starts

    sizes = cell_sizes(model.faces)
    starts = cell_starts(sizes)
    kept_cells = model.faces[starts + 1] < keep
    cells = np.repeat(kept_cells, sizes + 1)
    parts = [p for p in model.parts if p not in HAIR_PARTS]
    remap = {k: parts.index(p) for k, p in enumerate(model.parts) if p in parts}
    regions = {}
    for name, r in model.regions.items():
        sel = r.indices < keep
        regions[name] = type(r)(r.indices[sel], r.weights[sel], None if r.displacements is None
                                else r.displacements[sel])
    texture = model.texture
    if texture is not None:
        corners = int(sizes[kept_cells].sum())
        texture = ModelTexture(texture.corner_uv[:corners], texture.images, texture.face_image[kept_cells])
    out = Model(model.vertices[:keep], model.faces[cells], parts,
                np.array([remap[int(k)] for k in model.vertex_part[:keep]]), model.parameters.copy(), regions,
                dict(model.landmarks), model.name, model.description,
                {k: v for k, v in model.part_colors.items() if k in parts},
                None if model.vertex_colors is None else model.vertex_colors[:keep], texture)
    out.identity = model.identity
    return out


def skin_vertex_colours(model: Model) -> np.ndarray:
    """(n, 3) sRGB floats of the skin at every vertex: its texture's colour there where the skin is textured
    (the person's own skin, engine.identity.skin), else the vertex colour."""
    out = (model.vertex_colors if model.vertex_colors is not None else _part_rgb(model)).astype(float)
    texture = model.texture
    if texture is None or not texture.images or not (texture.face_image >= 0).any():
        return out
    from engine.model.cells import cell_sizes, index_mask

    sizes = cell_sizes(model.faces)
    corner_vertex = model.faces[index_mask(model.faces, sizes)]
    corner_image = np.repeat(texture.face_image, sizes)
    for image_index, image in enumerate(texture.images):
        pick = corner_image == image_index
        if not pick.any():
            continue
        vertex, first = np.unique(corner_vertex[pick], return_index=True)
        uv = texture.corner_uv[pick][first] % 1.0
        h, w = image.pixels.shape[:2]
        col = np.clip((uv[:, 0] * w).astype(int), 0, w - 1)
        row = np.clip(((1.0 - uv[:, 1]) * h).astype(int), 0, h - 1)
        out[vertex] = image.pixels[row, col, :3]
    return out


def _part_rgb(model: Model) -> np.ndarray:
    from engine.outputs.part_materials import hex_rgb, part_material

    palette = np.array([hex_rgb(part_material(p, model.part_colors)[0]) for p in model.parts]) * 255
    return np.rint(palette[model.vertex_part]).astype(np.uint8)


def _with_hair(record: IdentityRecord | None, choice: HairChoice) -> IdentityRecord:
    """The identity record, carrying ``choice`` (a default-head record when the model had none)."""
    import copy

    from engine.identity.parameters import Identity

    # a record is shared between a model's copies: the haired head gets its own
    record = Identity() if record is None else copy.copy(record)
    record.hair = replace(choice)                      # type: ignore[attr-defined]
    return record
