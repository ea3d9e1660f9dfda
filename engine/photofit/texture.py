"""The photographs projected into the head's shared texture atlas.

Every skin polygon's UV triangle is drawn into the atlas
(:func:`engine.photofit.raster.rasterize`); each texel's 3-D point on the
fitted head is projected into each photograph by its camera and sampled
there. A photograph's weight at a texel is ``max(0, (n · v − g) / (1 − g))²`` (n the
surface normal, v the direction towards its camera, g = :data:`GRAZING`) where the point is visible (not
behind the head in that photograph's z-buffer) and on the person, not the
plain backdrop (:mod:`engine.photofit.backdrop`), so the views blend smoothly
where both see the skin. What no photograph sees fades into a fill that
continues the seen skin smoothly over the head (:func:`skin_fill`: its colour
and shading where it meets the photographs, no edge, the mean of its borders
far from them), not one flat colour. Eyes, teeth and tongue keep their colours.
The drawing loops ask ``should_stop`` as they go (:mod:`engine.photofit.stopping`).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from scipy.ndimage import distance_transform_edt

from engine.model import Model
from engine.model.cells import cell_sizes, cell_starts
from engine.model.texture import ModelTexture, TextureImage
from engine.photofit.backdrop import subject_weight
from engine.photofit.camera import WeakPerspective
from engine.photofit.raster import rasterize, sample_bilinear
from engine.photofit.stopping import ShouldStop, stop_if_asked
from engine.photofit.texture_cleanup import even_shadows

ATLAS_SIZE = 1024
ZBUFFER_SIDE = 600                  # px: the longer side of the visibility buffer
VISIBLE_SLACK = 2.0                 # mm a texel may lie behind the nearest surface and count as seen
GRAZING = 0.25                      # n · v below which a photo is not used (its silhouette is unreliable)
FILL_WEIGHT = 0.04                  # weight of the fill everywhere (what no photo sees becomes it)
FILL_SMOOTHNESS = 1.0               # weight of each skin edge's colour difference in the fill
IMAGE_NAME = "photo"
ISLAND_PADDING = 4                  # texels each UV island's colours are grown outwards (no seams when filtered)
INSIDE_MARGIN = 0.10                # of the head's width: the rim of its outline not taken as the person unasked


def skin_triangles(model: Model) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fan triangles of the textured skin polygons: vertex indices (T, 3), corner indices (T, 3), polygon (T,)."""
    skin = model.parts.index("skin") if "skin" in model.parts else 0
    tri_v, tri_c, tri_f = _fans(model.faces)
    sizes = cell_sizes(model.faces)
    corners = np.delete(np.asarray(model.faces), cell_starts(sizes))             # each polygon's vertices in turn
    whole = np.logical_and.reduceat(model.vertex_part[corners] == skin, np.cumsum(sizes) - sizes)
    keep = whole[tri_f]
    return tri_v[keep], tri_c[keep], tri_f[keep]


def all_triangles(model: Model) -> np.ndarray:
    """(T, 3) vertex indices: every polygon of the model as a fan from its first corner."""
    return _fans(model.faces)[0]


def _fans(faces: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Every polygon of the flat cell array ``faces`` as a fan from its first corner, in polygon order:
    vertex indices (T, 3), corner indices (T, 3) (the polygons' corners counted in order) and polygon (T,)."""
    faces = np.asarray(faces, dtype=np.int64)
    sizes = cell_sizes(faces)
    starts = cell_starts(sizes)
    fans = sizes - 2
    tri_f = np.repeat(np.arange(len(sizes)), fans)
    k = np.arange(len(tri_f)) - np.repeat(np.cumsum(fans) - fans, fans) + 1          # 1 … n − 2 in each polygon
    first = starts[tri_f] + 1
    tri_v = np.stack([faces[first], faces[first + k], faces[first + k + 1]], axis=1)
    corner = (np.cumsum(sizes) - sizes)[tri_f]
    tri_c = np.stack([corner, corner + k, corner + k + 1], axis=1)
    return tri_v.reshape(-1, 3), tri_c.reshape(-1, 3), tri_f


def vertex_normals(vertices: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    face = np.cross(b - a, c - a)
    normals = np.zeros_like(vertices)
    for k in range(3):
        np.add.at(normals, triangles[:, k], face)
    return normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)


def bake_texture(model: Model, vertices: np.ndarray, photos: Mapping[str, np.ndarray],
                 cameras: Mapping[str, WeakPerspective], size: int = ATLAS_SIZE,
                 should_stop: ShouldStop = None, hidden: Mapping[str, np.ndarray] | None = None,
                 own_colours: np.ndarray | None = None,
                 shadows: np.ndarray | None = None) -> tuple[ModelTexture, np.ndarray]:
    """The model's texture with the photographs in its atlas, and the (size, size) weight the photos had.

    ``vertices`` are where the photographs show the head (its pose in them). ``hidden`` (view → (H, W) bool)
    marks pixels not read (the open mouth's teeth); texels of polygons wholly on ``own_colours`` (N,) vertices
    keep the model's vertex colours (the mouth's inside); ``shadows`` (N,) weights 0 … 1 where the
    photographs' shadows are evened out (:mod:`engine.photofit.texture_cleanup`).
    """
    assert model.texture is not None, "the head must have texture coordinates"
    tri_v, tri_c, tri_f = skin_triangles(model)
    uv = model.texture.corner_uv[tri_c]                                    # (T, 3, 2)
    in_atlas = np.all((uv >= 0) & (uv <= 1), axis=(1, 2))
    tri_v, tri_c, tri_f, uv = tri_v[in_atlas], tri_c[in_atlas], tri_f[in_atlas], uv[in_atlas]
    atlas_xy = np.stack([uv[..., 0] * size, (1 - uv[..., 1]) * size], axis=-1)
    hit, bary, _ = rasterize(atlas_xy, size, size, should_stop=should_stop)
    covered = hit >= 0
    t, b = hit[covered], bary[covered]
    points = np.einsum("nk,nkd->nd", b, vertices[tri_v[t]])
    normals = vertex_normals(vertices, all_triangles(model))
    normal = np.einsum("nk,nkd->nd", b, normals[tri_v[t]])
    normal /= np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-12)
    total = np.zeros(len(points))
    colour = np.zeros((len(points), 3))
    occluders = all_triangles(model)
    buffers = {view: DepthBuffer.of(vertices, occluders, cameras[view], photo.shape[:2], should_stop)
               for view, photo in photos.items()}
    subject = {view: subject_weight(photo, buffers[view].well_inside()) for view, photo in photos.items()}
    for view, mask in (hidden or {}).items():
        if view in subject and mask.any():
            before = subject[view]
            subject[view] = np.where(mask, 0.0, 1.0 if before is None else before)
    for view, photo in photos.items():
        camera = cameras[view]
        weight = np.clip((normal @ camera.toward_camera() - GRAZING) / (1 - GRAZING), 0, None) ** 2
        weight *= buffers[view].visible(points)
        weight *= _on_subject(subject[view], camera.project(points))
        stop_if_asked(should_stop)
        colour += weight[:, None] * sample_bilinear(photo, camera.project(points))
        total += weight
    seen = total > 0.25
    mean = (colour[seen].sum(0) / total[seen].sum()) if seen.any() else np.array([200.0, 160.0, 140.0])
    fill = skin_fill(model, vertices, photos, cameras, normals, occluders, mean, should_stop, subject, buffers)
    texels = (colour + FILL_WEIGHT * np.einsum("nk,nkd->nd", b, fill[tri_v[t]])) / (total + FILL_WEIGHT)[:, None]
    if own_colours is not None and model.vertex_colors is not None:
        own = np.all(own_colours[tri_v[t]], axis=1)
        texels[own] = np.einsum("nk,nkd->nd", b[own], model.vertex_colors[tri_v[t[own]]].astype(float))
    atlas = np.empty((size, size, 3))
    atlas[:] = mean
    atlas[covered] = texels
    if shadows is not None and shadows.any():
        region = np.zeros((size, size))
        region[covered] = np.einsum("nk,nk->n", b, shadows[tri_v[t]])
        even_shadows(atlas, region, covered, texels_per_mm(atlas_xy, vertices[tri_v]))
    pad_islands(atlas, covered, should_stop=should_stop)
    weights = np.zeros((size, size))
    weights[covered] = total
    face_image = np.full(len(cell_sizes(model.faces)), -1, dtype=np.int64)
    face_image[np.unique(tri_f)] = 0
    image = TextureImage(IMAGE_NAME, np.clip(np.round(atlas), 0, 255).astype(np.uint8))
    return ModelTexture(model.texture.corner_uv.copy(), [image], face_image), weights


def texels_per_mm(atlas_xy: np.ndarray, triangles: np.ndarray) -> float:
    """The atlas's median scale over (T, 3, 2) texel and (T, 3, 3) mm triangles (their first edges)."""
    texels = np.linalg.norm(atlas_xy[:, 1] - atlas_xy[:, 0], axis=1)
    mm = np.linalg.norm(triangles[:, 1] - triangles[:, 0], axis=1)
    good = mm > 1e-6
    return float(np.median(texels[good] / mm[good])) if good.any() else 1.0


def skin_fill(model: Model, vertices: np.ndarray, photos: Mapping[str, np.ndarray],
              cameras: Mapping[str, WeakPerspective], normals: np.ndarray, occluders: np.ndarray,
              mean: np.ndarray, should_stop: ShouldStop = None,
              subject: Mapping[str, np.ndarray | None] | None = None,
              buffers: Mapping[str, DepthBuffer] | None = None) -> np.ndarray:
    """(N, 3) colours for every vertex: the photographs' where they see the skin, continued smoothly elsewhere.

    Each skin vertex gets the photographs' colour and weight as a texel does;
    the fill ``x`` minimises ``Σ_v w_v |x_v − c_v|² + s Σ_edges |x_i − x_j|²``
    (``s`` = :data:`FILL_SMOOTHNESS`): where no photograph sees the skin
    (``w`` = 0) each colour is the average of its neighbours', so the fill
    carries the colour and shading of the skin it meets and has no edge.
    A faint pull (1e-6) to ``mean`` decides skin no seen vertex connects to.
    ``subject`` (view → :func:`~engine.photofit.backdrop.subject_weight`) keeps the backdrop out as for texels;
    ``buffers`` (view → :class:`DepthBuffer`) are the photographs' depth buffers if already drawn.
    """
    from scipy import sparse
    from scipy.sparse.linalg import spsolve

    tri_v, _, _ = skin_triangles(model)
    n = len(vertices)
    skin = np.unique(tri_v)
    colour = np.zeros((len(skin), 3))
    weight = np.zeros(len(skin))
    for view, photo in photos.items():
        camera = cameras[view]
        w = np.clip((normals[skin] @ camera.toward_camera() - GRAZING) / (1 - GRAZING), 0, None) ** 2
        buffer = buffers[view] if buffers is not None else DepthBuffer.of(vertices, occluders, camera,
                                                                            photo.shape[:2], should_stop)
        w *= buffer.visible(vertices[skin])
        w *= _on_subject((subject or {}).get(view), camera.project(vertices[skin]))
        colour += w[:, None] * sample_bilinear(photo, camera.project(vertices[skin]))
        weight += w
    observed = np.divide(colour, weight[:, None], out=np.tile(mean, (len(skin), 1)), where=weight[:, None] > 0)
    index = np.full(n, -1)
    index[skin] = np.arange(len(skin))
    edges = index[np.concatenate([tri_v[:, [0, 1]], tri_v[:, [1, 2]], tri_v[:, [2, 0]]])]
    adjacency = sparse.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(len(skin),) * 2)
    adjacency = ((adjacency + adjacency.T) > 0).astype(float).tocsr()
    laplacian = sparse.diags(np.asarray(adjacency.sum(axis=1)).ravel()) - adjacency
    pull = 1e-6
    system = (sparse.diags(weight + pull) + FILL_SMOOTHNESS * laplacian).tocsc()
    stop_if_asked(should_stop)
    solved = spsolve(system, weight[:, None] * observed + pull * mean)
    fill = np.tile(mean, (n, 1))
    fill[skin] = np.asarray(solved).reshape(len(skin), 3)
    return fill


def pad_islands(atlas: np.ndarray, covered: np.ndarray, texels: int = ISLAND_PADDING,
                should_stop: ShouldStop = None) -> None:
    """Grow each UV island's colours ``texels`` outwards, so filtering across its edge shows no seam."""
    filled = covered.copy()
    for _ in range(texels):
        stop_if_asked(should_stop)
        total = np.zeros(atlas.shape)
        count = np.zeros(filled.shape)
        for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
            shifted = np.roll(filled, (dy, dx), axis=(0, 1))
            total += np.roll(atlas * filled[..., None], (dy, dx), axis=(0, 1))
            count += shifted
        grow = ~filled & (count > 0)
        atlas[grow] = total[grow] / count[grow][:, None]
        filled |= grow


def _on_subject(weights: np.ndarray | None, pixels: np.ndarray) -> np.ndarray:
    """(N,) the photograph's :func:`~engine.photofit.backdrop.subject_weight` at (N, 2) pixels (1 without one)."""
    if weights is None:
        return np.ones(len(pixels))
    return np.asarray(sample_bilinear(weights[..., None], pixels)[:, 0])


class DepthBuffer:
    """The fitted head drawn into one photograph's frame at :data:`ZBUFFER_SIDE` px: which polygon covers
    each pixel and how near it is. Drawn once per photograph for the texture, the fill and the outline test."""

    def __init__(self, camera: WeakPerspective, shape: tuple[int, ...], hit: np.ndarray, depth: np.ndarray,
                 factor: float) -> None:
        self.camera, self.shape, self.hit, self.depth, self.factor = camera, (shape[0], shape[1]), hit, depth, factor

    @classmethod
    def of(cls, vertices: np.ndarray, triangles: np.ndarray, camera: WeakPerspective, shape: tuple[int, ...],
           should_stop: ShouldStop = None) -> DepthBuffer:
        """Draw ``triangles`` (T, 3 vertex indices) of ``vertices`` as ``camera`` sees them in a photograph of
        ``shape``."""
        height, width = shape[0], shape[1]
        factor = ZBUFFER_SIDE / max(height, width)
        w, h = max(round(width * factor), 1), max(round(height * factor), 1)
        projected = camera.project(vertices) * factor
        depth = camera.depth(vertices)
        hit, _, zbuf = rasterize(projected[triangles], w, h, depth[triangles], should_stop)
        return cls(camera, shape, hit, zbuf, factor)

    def visible(self, points: np.ndarray) -> np.ndarray:
        """(N,) 1 where a point is the nearest surface in the photograph, else 0 (a coarse z-buffer)."""
        h, w = self.depth.shape
        xy = self.camera.project(points) * self.factor
        col = np.clip(xy[:, 0].astype(int), 0, w - 1)
        row = np.clip(xy[:, 1].astype(int), 0, h - 1)
        inside = (xy[:, 0] >= 0) & (xy[:, 0] < w) & (xy[:, 1] >= 0) & (xy[:, 1] < h)
        return np.asarray(inside & (self.camera.depth(points) >= self.depth[row, col] - VISIBLE_SLACK), dtype=float)

    def well_inside(self) -> np.ndarray:
        """(H, W) bool at the photograph's size: its pixels within the fitted head's outline and farther than
        :data:`INSIDE_MARGIN` of the head's width from it (the rim, where the fit may lie outside the person,
        left out)."""
        height, width = self.shape
        outline = self.hit >= 0
        if not outline.any():
            return np.zeros((height, width), dtype=bool)
        columns = np.flatnonzero(outline.any(axis=0))
        inner = distance_transform_edt(outline) > INSIDE_MARGIN * (columns[-1] - columns[0] + 1)
        h, w = outline.shape
        rows = np.minimum((np.arange(height) * self.factor).astype(int), h - 1)
        cols = np.minimum((np.arange(width) * self.factor).astype(int), w - 1)
        return np.asarray(inner[rows[:, None], cols[None, :]])
