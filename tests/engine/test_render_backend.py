"""Which OpenGL draws the frames (issue 36): named, GPU when there is one, the same pixels on both."""

from __future__ import annotations

import io
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import engine
from engine.outputs.frame_pipe import FrameWriter
from engine.outputs.render import FrameRenderer
from engine.outputs.render_backend import classify, gpu_render_nodes, is_software, probe

ROOT = Path(__file__).resolve().parents[2]


def test_classify_names_software_rasterisers_and_gpus() -> None:
    assert classify("llvmpipe (LLVM 15.0.6, 256 bits)") == "software (Mesa llvmpipe)"
    assert classify("Mesa OffScreen") == "software (OSMesa)"
    assert classify("AMD Radeon RX 6600 (radeonsi, navi23, LLVM 15.0.6)") == \
        "GPU (AMD Radeon RX 6600 (radeonsi, navi23, LLVM 15.0.6))"
    assert is_software("software (Mesa llvmpipe)") and not is_software("GPU (Intel UHD 620)")
    assert classify("") == "unknown"


def test_render_nodes_are_listed_from_the_pattern(tmp_path: Path) -> None:
    (tmp_path / "renderD128").touch()
    (tmp_path / "card0").touch()
    assert gpu_render_nodes(str(tmp_path / "renderD*")) == [str(tmp_path / "renderD128")]


def test_the_renderer_reports_the_backend_it_draws_with() -> None:
    model = engine.load_model()
    with FrameRenderer(model, size=(32, 24)) as renderer:
        report = renderer.backend()
    assert report["renderer"] and report["vendor"] and report["version"]
    assert report["kind"] == classify(report["renderer"])
    assert probe()["kind"] == report["kind"]          # the bare probe opens the same OpenGL
    if not gpu_render_nodes():     # this machine (no /dev/dri): Mesa's software OpenGL
        assert is_software(report["kind"]), report
        assert report["gpu_render_nodes"] == "none"


class _Sink(io.BytesIO):
    """A pipe's stand-in that keeps what was written after the writer closes it."""

    written = b""

    def close(self) -> None:
        self.written = self.getvalue()
        super().close()


def test_the_frame_pipe_writes_width_height_channels_bytes_per_frame() -> None:
    sink = _Sink()
    writer = FrameWriter(sink)
    frames = [np.full((72, 128, 3), k, dtype=np.uint8) for k in range(5)]
    for frame in frames:
        assert writer.put(frame[:, :, :])
    writer.close()
    data = sink.written
    assert len(data) == 5 * 72 * 128 * 3                     # rgb24: no header, no padding
    assert data[72 * 128 * 3 * 4] == 4 and data[-1] == 4


_DRAW = """
import sys, numpy as np, engine
from engine.outputs.render import FrameRenderer
model = engine.load_model()
with FrameRenderer(model, size=(320, 240)) as renderer:
    image = renderer.render(model.deformer().deform(list(model.default_values().values())))
    print(renderer.backend()["kind"], file=sys.stderr)
np.save(sys.argv[1], image)
"""


def _draw(path: Path, **env: str) -> np.ndarray:
    environment = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    environment.update(env)
    subprocess.run([sys.executable, "-c", _DRAW, str(path)], cwd=ROOT, env=environment, check=True)
    return np.load(path)


@pytest.mark.skipif(not gpu_render_nodes(), reason="no GPU here: no /dev/dri/renderD* render node, "
                    "so only the software path (Mesa llvmpipe) can be drawn")
def test_gpu_and_software_draw_the_same_picture_within_tolerance(tmp_path: Path) -> None:
    gpu = _draw(tmp_path / "gpu.npy", VTK_DEFAULT_OPENGL_WINDOW="vtkEGLRenderWindow")
    software = _draw(tmp_path / "software.npy", VTK_DEFAULT_OPENGL_WINDOW="vtkOSOpenGLRenderWindow",
                     LIBGL_ALWAYS_SOFTWARE="1")
    difference = np.abs(gpu.astype(int) - software.astype(int))
    # tolerance: rasterisation rules and shader precision differ at edges, not in the surfaces
    assert difference.mean() <= 2.0, json.dumps({"mean": float(difference.mean())})
    assert np.percentile(difference.max(axis=2), 99) <= 32


def test_render_info_prints_the_backend_and_ends_with_status_0() -> None:
    from tests.engine.cli_in_process import run_in_process

    done = run_in_process("render", "--info")
    assert done.returncode == 0, done.stderr
    lines = dict(line.split(": ", 1) for line in done.stdout.splitlines())
    report = probe()
    assert lines["backend"] == report["kind"]
    assert lines["OpenGL renderer"] == report["renderer"] and lines["OpenGL version"] == report["version"]
    assert lines["window"].startswith(report["window"]) and lines["VTK"] == report["vtk"]
    assert lines["GPU render nodes"] == report["gpu_render_nodes"]


def test_a_drawn_sets_provenance_names_its_backend_and_an_old_file_still_reads(tmp_path: Path) -> None:
    from engine.errors import UserError
    from engine.stimuli import parse_design
    from engine.stimuli.manifest import PROVENANCE_VERSION, provenance, read_provenance

    drawn = provenance(parse_design('[factors]\ntext = ["Aa."]\n', "d.toml"), [])
    assert drawn["format_version"] == PROVENANCE_VERSION == 2
    assert drawn["render_backend"]["kind"] == probe()["kind"] and drawn["render_backend"]["renderer"]
    heard = provenance(parse_design('[output]\nkinds = ["wav"]\n[factors]\ntext = ["Aa."]\n', "d.toml"), [])
    assert heard["render_backend"] is None                       # nothing drawn: no OpenGL to name
    new = tmp_path / "new.json"
    new.write_text(json.dumps(drawn))
    assert read_provenance(new) == drawn
    old = tmp_path / "old.json"                                  # written before format_version existed
    old.write_text(json.dumps({k: v for k, v in drawn.items() if k not in ("format_version", "render_backend")}))
    assert read_provenance(old)["format_version"] == 1 and read_provenance(old)["render_backend"] is None
    newer = tmp_path / "newer.json"
    newer.write_text(json.dumps({**drawn, "format_version": PROVENANCE_VERSION + 1}))
    with pytest.raises(UserError, match="newer than this toolkit reads"):
        read_provenance(newer)
    broken = tmp_path / "broken.json"
    broken.write_text("{")
    with pytest.raises(UserError, match="not JSON"):
        read_provenance(broken)
