"""The photo fit's fan triangles of the head's polygons (engine/photofit/texture.py), against a loop."""

from __future__ import annotations

import numpy as np

from engine.model.cells import cell_sizes, cell_starts
from engine.photofit.texture import all_triangles, skin_triangles


def _fans_one_by_one(model, skin_only):
    sizes = cell_sizes(model.faces)
    starts = cell_starts(sizes)
    skin = model.parts.index("skin")
    tri_v, tri_c, tri_f = [], [], []
    corner = 0
    for f, (n, s) in enumerate(zip(sizes, starts, strict=True)):
        verts = model.faces[s + 1:s + 1 + n]
        if not skin_only or np.all(model.vertex_part[verts] == skin):
            for k in range(1, n - 1):
                tri_v.append((verts[0], verts[k], verts[k + 1]))
                tri_c.append((corner, corner + k, corner + k + 1))
                tri_f.append(f)
        corner += n
    return np.array(tri_v), np.array(tri_c), np.array(tri_f)


def test_the_fans_are_the_polygons_one_by_one(head):
    assert len(set(cell_sizes(head.faces).tolist())) > 1         # triangles and quads (at least) to fan
    tri_v, tri_c, tri_f = skin_triangles(head)
    want_v, want_c, want_f = _fans_one_by_one(head, skin_only=True)
    np.testing.assert_array_equal(tri_v, want_v)
    np.testing.assert_array_equal(tri_c, want_c)
    np.testing.assert_array_equal(tri_f, want_f)
    np.testing.assert_array_equal(all_triangles(head), _fans_one_by_one(head, skin_only=False)[0])
    assert len(all_triangles(head)) > len(tri_v)                 # eyes, teeth and tongue are not skin
