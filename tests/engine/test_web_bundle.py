"""The web player's bundle (engine/web/dist/player.js, engine/web/player_bundle.py): one ES module holding the
player and the three.js it uses, built from the sources it records — checked without npm.

The bundle's first line holds the SHA-256 of its sources (player.js, the vendored three.js files, esbuild's
version and options); a source changed without building the bundle again fails here. Where esbuild
0.28.2 is at hand (``AP_ESBUILD`` or ``esbuild`` on the PATH), the bundle is also built again and must
come out byte for byte.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from engine.web.player_bundle import (
    BUNDLE,
    ESBUILD_VERSION,
    IMPORT,
    LICENCE,
    SHADER_MARK,
    SOURCES,
    build,
    bundle_text,
    licence_text,
    recorded_digest,
    source_digest,
)

WEB = Path(__file__).resolve().parents[2] / "engine" / "web"
REBUILD = ("python -m engine.web.player_bundle --esbuild PATH (npm install esbuild@"
           f"{ESBUILD_VERSION}; engine/web/player_bundle.py)")


def test_the_bundle_is_built_from_the_sources_as_they_are():
    assert recorded_digest(bundle_text()) == source_digest(), f"the player's sources changed: build again: {REBUILD}"


def test_a_changed_source_no_longer_matches_the_bundle(tmp_path):
    copy = tmp_path / "web"
    for name in SOURCES:
        (copy / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(WEB / name, copy / name)
    assert source_digest(copy) == recorded_digest(bundle_text())
    for name in ("player/player.js", "vendor/three/examples/jsm/loaders/GLTFLoader.js"):
        original = (copy / name).read_bytes()
        (copy / name).write_bytes(original.replace(b"\n", b"\n ", 1))
        assert source_digest(copy) != recorded_digest(bundle_text()), name
        (copy / name).write_bytes(original)
    assert recorded_digest("// something else\n") is None


def test_the_bundle_is_one_module_that_imports_nothing():
    text = bundle_text()
    assert IMPORT.search(text) is None
    assert IMPORT.search((WEB / "player/player.js").read_text()) is not None     # the check sees an import
    assert re.search(r"export\s*\{[^}]*\bas ArtificialPerson\b[^}]*\}\s*;?", text)
    assert text.count(SHADER_MARK) == 1                                         # the site puts the shader here
    assert 'window.__THREE__="170"' in text                                     # three.js 0.170.0 inside
    assert "@license" in text and "Three.js Authors" in text


def test_three_js_s_licence_is_beside_the_bundle():
    assert (WEB / LICENCE).parent == (WEB / BUNDLE).parent
    assert licence_text() == (WEB / "vendor/three/LICENSE").read_text()
    assert "MIT License" in licence_text() and "three.js authors" in licence_text()


def _esbuild() -> str | None:
    found = os.environ.get("AP_ESBUILD") or shutil.which("esbuild")
    if found is None:
        return None
    version = subprocess.run([found, "--version"], capture_output=True, text=True, check=False).stdout.strip()
    return found if version == ESBUILD_VERSION else None


@pytest.mark.skipif(_esbuild() is None, reason=f"no esbuild {ESBUILD_VERSION} (AP_ESBUILD or on the PATH; from npm)")
def test_building_again_gives_the_same_bundle(tmp_path):
    copy = tmp_path / "web"
    for name in SOURCES:
        (copy / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(WEB / name, copy / name)
    esbuild = _esbuild()
    assert esbuild is not None
    built = build(esbuild, copy)
    assert built.read_bytes() == (WEB / BUNDLE).read_bytes()
    assert (copy / LICENCE).read_bytes() == (WEB / LICENCE).read_bytes()
