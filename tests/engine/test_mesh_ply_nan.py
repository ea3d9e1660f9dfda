"""A NaN of any kind in a binary PLY or a glTF is refused (coordinates) or taken as missing (texture coordinates)
without a numpy warning, which a user sees on stderr before the one error line, and which fails where warnings are
errors (found by the release-size fuzz, tests/engine/test_mesh_fuzz.py)."""

from __future__ import annotations

import numpy as np
import pytest

from engine.formats.mesh_io import read_mesh

SIGNALLING_NAN = b"\x01\x00\x80\x7f"      # float32 0x7f800001: a NaN whose cast to float64 raises "invalid"


@pytest.mark.parametrize("where", ["coordinate", "texcoord"])
def test_a_signalling_nan_in_a_binary_ply_is_refused_without_a_warning(tmp_path, where):
    import struct
    import warnings

    from engine.errors import MeshImportError

    one = struct.pack("<f", 1.0)
    zero = struct.pack("<f", 0.0)
    first = SIGNALLING_NAN if where == "coordinate" else one
    vertices = first + zero + zero + zero + one + zero + zero + zero + one
    corner = SIGNALLING_NAN if where == "texcoord" else zero
    face = b"\x03" + struct.pack("<3i", 0, 1, 2) + b"\x06" + corner + zero * 5
    path = tmp_path / "m.ply"
    path.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                     b"property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                     b"property list uchar float texcoord\nend_header\n" + vertices + face)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        if where == "coordinate":
            with pytest.raises(MeshImportError, match="not finite"):
                read_mesh(path)
        else:
            mesh = read_mesh(path)
            assert np.isnan(mesh.texture.corner_uv[0, 0])


def test_a_signalling_nan_in_a_glb_position_is_refused_without_a_warning(tmp_path):
    """The same NaN in a glTF's POSITION accessor (BoxTextured.glb: bufferView 1, the positions 288 bytes into it)."""
    import struct
    import warnings
    from pathlib import Path

    from engine.errors import MeshImportError

    data = bytearray((Path(__file__).parent / "data" / "meshes" / "BoxTextured.glb").read_bytes())
    json_length = struct.unpack_from("<I", data, 12)[0]
    binary = 12 + 8 + json_length + 8                 # the BIN chunk's first byte
    data[binary + 288:binary + 292] = SIGNALLING_NAN
    path = tmp_path / "box.glb"
    path.write_bytes(bytes(data))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(MeshImportError, match="not finite"):
            read_mesh(path)
