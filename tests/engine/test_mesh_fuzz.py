"""Fuzzing mesh import: mutated bytes of small valid files end in MeshImportError naming the file, never worse.

Seeds: ASCII and binary PLY (with texture coordinates and strips), OBJ with
an MTL, glTF (JSON with its .bin, and GLB), and legacy VTK (read by VTK in a
child process, so a crash or hang there must still end in our error). The
mutations overwrite, insert, delete and cut bytes, and insert numbers that
make counts huge, negative or non-finite.

A glTF's structure is fuzzed as well: its references (accessor, bufferView, buffer, mesh,
material, node, scene indices), node transforms and buffer URI given hostile values (negative
and huge indices, non-numbers, ``../`` and percent-encoded URIs, links out of the folder): each
reads without any warning, never with the bytes of the file outside the folder, or is refused.

CI size: ``AP_FUZZ_EXAMPLES`` inputs per format (default 200; legacy VTK (a
polygon surface and a volume grid), which starts a process per input, a tenth
of that). Release check:
``AP_FUZZ_EXAMPLES=10000 AP_FUZZ_REPORT=counts.txt pytest tests/engine/test_mesh_fuzz.py``
(with ``AP_FUZZ_REPORT`` each format appends a line: inputs tried, read,
refused with our error; see docs/meshes.md for the last such run).
"""

from __future__ import annotations

import json
import os
import tempfile
import warnings
from collections import Counter
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from engine.errors import MeshImportError
from engine.formats.mesh_io import read_mesh, write_mesh

EXAMPLES = int(os.environ.get("AP_FUZZ_EXAMPLES", "200"))
DATA = Path(__file__).parent / "data" / "meshes"

PLY_ASCII = (b"ply\nformat ascii 1.0\ncomment TextureFile skin.png\nelement vertex 4\nproperty float x\n"
             b"property float y\nproperty float z\nproperty float s\nproperty float t\nelement face 2\n"
             b"property list uchar int vertex_indices\nproperty list uchar float texcoord\n"
             b"element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
             b"0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n3 0 1 2 6 0 0 1 0 1 1\n3 0 2 3 0\n6 0 1 2 -1 2 3 0\n")
OBJ = (b"mtllib m.mtl\no head\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
       b"g skin\nusemtl skin\nf 1/1/1 2/2/1 3/3/1\nf -4 -2 -1\ng eye\nf 1//1 3//1 4//1\n")
VTK_LEGACY = (b"# vtk DataFile Version 3.0\nsquare\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
              b"0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 2 8\n3 0 1 2\n3 0 2 3\n")
VTK_GRID = (b"# vtk DataFile Version 3.0\ntet\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
            b"0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n")
VTK_SEEDS = {"square.vtk": VTK_LEGACY, "grid.vtk": VTK_GRID}


def _texcoord_ply() -> bytes:
    """MeshLab's layout (as in data/meshes/fuze.ply): per-corner texcoord lists and colours, two triangles."""
    header = (b"ply\nformat binary_little_endian 1.0\ncomment TextureFile skin.png\nelement vertex 4\n"
              b"property float x\nproperty float y\nproperty float z\nproperty uchar red\nelement face 2\n"
              b"property list uchar int vertex_indices\nproperty list uchar float texcoord\n"
              b"property uchar red\nend_header\n")
    vertices = b"".join(np.array(p, "<f4").tobytes() + bytes([200]) for p in np.eye(4, 3))
    faces = b""
    for triangle in ([0, 1, 2], [0, 2, 3]):
        faces += bytes([3]) + np.array(triangle, "<i4").tobytes()
        faces += bytes([6]) + np.array([0, 0, 1, 0, 1, 1], "<f4").tobytes() + bytes([255])
    return header + vertices + faces


def _binary_ply() -> bytes:
    with tempfile.TemporaryDirectory() as folder:
        return write_mesh(Path(folder) / "m.ply", np.eye(4, 3) * 10, [3, 0, 1, 2, 4, 0, 1, 2, 3]).read_bytes()


SEEDS = {
    "ascii.ply": PLY_ASCII,
    "binary.ply": _binary_ply(),
    "texcoord.ply": _texcoord_ply(),
    "mesh.obj": OBJ,
    "strip.gltf": (DATA / "Mesh_PrimitiveMode_04.gltf").read_bytes(),
    "box.glb": (DATA / "BoxTextured.glb").read_bytes(),
    "square.vtk": VTK_LEGACY,
}
NUMBERS = [b"-1", b"0", b"4294967295", b"99999999999999999999", b"1e308", b"nan", b"inf", b"-", b"\x00", b"\n"]


@st.composite
def mutated(draw: st.DrawFn, seed: bytes) -> bytes:
    data = bytearray(seed)
    for _ in range(draw(st.integers(1, 6))):
        at = draw(st.integers(0, max(len(data) - 1, 0)))
        kind = draw(st.sampled_from(["byte", "insert", "delete", "cut", "number"]))
        if kind == "byte" and data:
            data[at] = draw(st.integers(0, 255))
        elif kind == "insert":
            data[at:at] = draw(st.binary(min_size=1, max_size=8))
        elif kind == "delete":
            del data[at:at + draw(st.integers(1, 40))]
        elif kind == "cut":
            del data[at:]
        else:
            data[at:at] = draw(st.sampled_from(NUMBERS))
    return bytes(data)


def _report(name: str, counts: Counter) -> None:
    """One line per format in the file ``AP_FUZZ_REPORT`` names (for the release check's figures)."""
    report = os.environ.get("AP_FUZZ_REPORT")
    if report:
        with open(report, "a", encoding="utf-8") as out:
            contained = (f" (of them, VTK's reader crashed {counts['vtk crashed']} times and was stopped "
                         f"{counts['vtk stopped']} times in its child process)" if "vtk" in name else "")
            out.write(f"{name}: {counts['tried']} inputs, {counts['read']} read, {counts['refused']} refused "
                      f"with MeshImportError naming the file{contained}; 0 other exceptions, and this process "
                      "never crashed or hung\n")


def _check(name: str, data: bytes, tmp: Path, counts: Counter | None = None) -> None:
    counts = Counter() if counts is None else counts
    counts["tried"] += 1
    path = tmp / name
    path.write_bytes(data)
    (tmp / "m.mtl").write_bytes(b"newmtl skin\nmap_Kd skin.png\n")
    if name == "strip.gltf":
        (tmp / "Mesh_PrimitiveMode_04.bin").write_bytes((DATA / "Mesh_PrimitiveMode_04.bin").read_bytes())
    try:
        mesh = read_mesh(path, timeout=30)
    except MeshImportError as exc:
        message = str(exc)
    else:
        assert np.all(np.isfinite(mesh.vertices)) and len(mesh.faces)
        counts["read"] += 1
        return
    assert message.startswith(f"{path}:"), message
    counts["refused"] += 1
    counts["vtk crashed"] += "VTK's reader crashed" in message
    counts["vtk stopped"] += "did not finish" in message


@pytest.mark.parametrize("name", [n for n in SEEDS if not n.endswith(".vtk")])
def test_own_readers_survive_mutated_files(name, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fuzz")
    seed: Counter = Counter()
    _check(name, SEEDS[name], tmp, seed)
    assert seed["read"] == 1, "the seed itself reads"
    counts: Counter = Counter()

    @settings(max_examples=EXAMPLES, deadline=None, derandomize=True, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(mutated(SEEDS[name]))
    def run(data: bytes) -> None:
        _check(name, data, tmp, counts)

    run()
    _report(name, counts)


@pytest.mark.parametrize("name", sorted(VTK_SEEDS))
def test_vtk_in_a_child_survives_mutated_files(name, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fuzz")
    seed: Counter = Counter()
    _check(name, VTK_SEEDS[name], tmp, seed)
    assert seed["read"] == 1, "the seed itself reads"
    counts: Counter = Counter()

    @settings(max_examples=max(EXAMPLES // 10, 5), deadline=None, derandomize=True, database=None,
              suppress_health_check=[HealthCheck.too_slow])
    @given(mutated(VTK_SEEDS[name]))
    def run(data: bytes) -> None:
        _check(name, data, tmp, counts)

    run()
    _report(f"{name} (VTK in a child process)", counts)


# -- glTF structure: hostile references, transforms and URIs ---------------------------------------------

STRIP = json.loads((DATA / "Mesh_PrimitiveMode_04.gltf").read_text())
STRIP_BIN = (DATA / "Mesh_PrimitiveMode_04.bin").read_bytes()
#: outside the glTF's folder, of the .bin's length and a valid buffer too, so that a read of it would succeed
OUTSIDE = (np.frombuffer(STRIP_BIN, "<f4") + 7).astype("<f4").tobytes()
FIELDS = [("accessors", 0, "bufferView"), ("accessors", 0, "count"), ("accessors", 0, "byteOffset"),
          ("accessors", 0, "componentType"), ("bufferViews", 0, "buffer"), ("bufferViews", 0, "byteOffset"),
          ("bufferViews", 0, "byteLength"), ("bufferViews", 0, "byteStride"), ("buffers", 0, "byteLength"),
          ("meshes", 0, "primitives", 0, "attributes", "POSITION"), ("meshes", 0, "primitives", 0, "indices"),
          ("meshes", 0, "primitives", 0, "material"), ("meshes", 0, "primitives", 0, "mode"), ("nodes", 0, "mesh"),
          ("nodes", 0, "children"), ("nodes", 0, "scale"), ("nodes", 0, "rotation"), ("nodes", 0, "translation"),
          ("nodes", 0, "matrix"), ("scenes", 0, "nodes"), ("scene",)]
VALUES = [-1, -2, 0, 1, 2, 3, 2**31, 2**64, 1.5, 1e308, float("nan"), float("inf"), True, None, "0", [], [-1],
          [1e300, 1e300, 1e300], [1e300, 0, 0, 1], [0, 0, 0, 0], [1e-300, 0, 0, 0], [float("nan")] * 3,
          [1e300] + [0] * 4 + [1e300] + [0] * 4 + [1e300] + [0] * 5, {}]
URIS = ["../outside.bin", "%2e%2e/outside.bin", "%2E%2E%2Foutside.bin", "sub%2F..%2F..%2Foutside.bin",
        "..%5Coutside.bin", "link.bin", "up/outside.bin", "/etc/passwd", "file:///etc/passwd", "%00", "%ff",
        "Mesh_PrimitiveMode_04.bin", "./Mesh_PrimitiveMode_04.bin", "Mesh%5FPrimitiveMode%5F04.bin", ""]


@st.composite
def hostile_gltf(draw: st.DrawFn) -> dict:
    doc = json.loads(json.dumps(STRIP))
    for _ in range(draw(st.integers(1, 4))):
        if draw(st.booleans()):
            doc["buffers"][0]["uri"] = draw(st.sampled_from(URIS))
            continue
        *keys, last = draw(st.sampled_from(FIELDS))
        node = doc
        for key in keys:
            node = node[key]
        node[last] = draw(st.sampled_from(VALUES))
    return doc


def test_gltf_structure_with_hostile_values_reads_cleanly_or_is_refused(tmp_path_factory):
    root = tmp_path_factory.mktemp("hostile")
    outside = root / "outside.bin"
    outside.write_bytes(OUTSIDE)
    folder = root / "models"
    folder.mkdir()
    (folder / "Mesh_PrimitiveMode_04.bin").write_bytes(STRIP_BIN)
    (folder / "link.bin").symlink_to(root / "outside.bin")
    (folder / "up").symlink_to(root)
    path = folder / "strip.gltf"
    counts: Counter = Counter()

    @settings(max_examples=EXAMPLES, deadline=None, derandomize=True, database=None,
              suppress_health_check=[HealthCheck.too_slow])
    @given(hostile_gltf())
    def run(doc: dict) -> None:
        counts["tried"] += 1
        path.write_text(json.dumps(doc))
        with warnings.catch_warnings():
            warnings.simplefilter("error")          # numpy's RuntimeWarnings too, whichever module they come from
            try:
                mesh = read_mesh(path, timeout=30)
            except MeshImportError as exc:
                message = str(exc)
            else:
                message = ""
        if message:
            assert message.startswith(f"{path}:"), message
            counts["refused"] += 1
            return
        assert np.all(np.isfinite(mesh.vertices)) and len(mesh.faces)
        outside.write_bytes(OUTSIDE[::-1])             # were the file outside read, the mesh would change with it
        try:
            again = read_mesh(path, timeout=30).vertices
        finally:
            outside.write_bytes(OUTSIDE)
        assert np.array_equal(again, mesh.vertices), "the file outside the folder was read"
        counts["read"] += 1

    run()
    _report("glTF structure (hostile references, transforms, URIs)", counts)
