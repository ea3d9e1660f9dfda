"""The web player as one self-contained ES module: ``player/player.js`` with the three.js it imports
(``vendor/three``: the build, the glTF loader and its helper), bundled by esbuild into ``dist/player.js``,
so that a page loads it with ``import { ArtificialPerson } from "./player.js"`` and needs no import map
(hosted experiment platforms cannot add one).

The bundle is built once, by a developer, and shipped in the package (esbuild comes from npm, which the
toolkit's users and its CI need not have):

    npm install --prefix /tmp/esbuild esbuild@0.28.2
    python -m engine.web.player_bundle --esbuild /tmp/esbuild/node_modules/.bin/esbuild

Its first line records the SHA-256 of what it was built from (:func:`source_digest`: the sources, the
esbuild version and its options), and ``tests/engine/test_web_bundle.py`` fails when the sources change
and the bundle was not built again. three.js's MIT licence is beside it (``dist/three-LICENSE.txt``) and
goes into every site beside ``player.js``.

>>> recorded_digest(bundle_text()) == source_digest()
True
"""

from __future__ import annotations

import argparse
import hashlib
import re
import shutil
import subprocess
import sys
import tempfile
from importlib import resources
from pathlib import Path

from engine.errors import UserError

__all__ = ["BUNDLE", "ESBUILD_VERSION", "IMPORT", "LICENCE", "SHADER_MARK", "SOURCES", "build", "bundle_text",
           "licence_text", "recorded_digest", "source_digest"]

ESBUILD_VERSION = "0.28.2"
#: The files the bundle is made of, relative to ``engine/web``.
SOURCES = ("player/player.js", "vendor/three/build/three.module.min.js",
           "vendor/three/examples/jsm/loaders/GLTFLoader.js", "vendor/three/examples/jsm/utils/BufferGeometryUtils.js",
           "vendor/three/LICENSE")
#: esbuild's options (run in ``engine/web``): the loader's bare ``three`` is the vendored build.
OPTIONS = ("player/player.js", "--bundle", "--format=esm", "--minify", "--target=es2020", "--charset=utf8",
           "--legal-comments=eof", "--alias:three=./vendor/three/build/three.module.min.js")
BUNDLE = "dist/player.js"
LICENCE = "dist/three-LICENSE.txt"
#: Where the player takes the look's shader (engine.outputs.look_shader): replaced as a site is written.
SHADER_MARK = '"{{LOOK_SHADER}}"'
#: An import left in a bundle (a static or dynamic one): a self-contained bundle has none.
IMPORT = re.compile(r"\bimport\s*[({*\"']|(^|[;}])import\s*\w")
_HEADER = "// Artificial Person web player + three.js 0.170.0 (MIT: three-LICENSE.txt), one ES module. sources sha256 "


def source_digest(root: Path | None = None) -> str:
    """SHA-256 of the bundle's sources (each file's name and bytes), esbuild's version and its options."""
    folder = Path(str(resources.files("engine.web"))) if root is None else root
    digest = hashlib.sha256(f"esbuild {ESBUILD_VERSION}\n{' '.join(OPTIONS)}\n".encode())
    for name in SOURCES:
        data = (folder / name).read_bytes()
        digest.update(f"{name} {len(data)}\n".encode())
        digest.update(data)
    return digest.hexdigest()


def recorded_digest(bundle: str) -> str | None:
    """The source digest a bundle's first line records (None: not a bundle of ours)."""
    first = bundle.split("\n", 1)[0]
    return first[len(_HEADER):].split()[0] if first.startswith(_HEADER) and len(first) > len(_HEADER) else None


def bundle_text() -> str:
    """The shipped bundle (with the shader's marker still in it)."""
    return (resources.files("engine.web") / BUNDLE).read_text(encoding="utf-8")


def licence_text() -> str:
    """three.js's licence, which goes beside the bundle."""
    return (resources.files("engine.web") / LICENCE).read_text(encoding="utf-8")


def build(esbuild: str, root: Path) -> Path:
    """Bundle the sources in ``root`` (``engine/web`` of a checkout) with ``esbuild`` into ``root/dist``."""
    version = subprocess.run([esbuild, "--version"], capture_output=True, text=True, check=True).stdout.strip()
    if version != ESBUILD_VERSION:
        raise UserError(f"esbuild {version} given; the bundle is built with {ESBUILD_VERSION} (npm install "
                        f"esbuild@{ESBUILD_VERSION}), so that it is made again byte for byte")
    with tempfile.TemporaryDirectory() as scratch:
        out = Path(scratch) / "player.js"
        subprocess.run([esbuild, *OPTIONS, f"--outfile={out}", "--log-level=warning"], cwd=root, check=True)
        body = out.read_text(encoding="utf-8")
    if body.count(SHADER_MARK) != 1 or IMPORT.search(body):
        raise UserError("the bundle lost the shader's marker or kept an import: check player.js", file=root / BUNDLE)
    target = root / BUNDLE
    target.parent.mkdir(exist_ok=True)
    from engine.formats.atomic import atomic_write_text

    atomic_write_text(target, f"{_HEADER}{source_digest(root)} (engine/web/player_bundle.py)\n{body}")
    atomic_write_text(root / LICENCE, (root / "vendor/three/LICENSE").read_text(encoding="utf-8"))
    return target


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m engine.web.player_bundle", description=__doc__.split("\n\n")[0])
    parser.add_argument("--esbuild", default=shutil.which("esbuild"), help=f"esbuild {ESBUILD_VERSION} (from npm)")
    args = parser.parse_args(argv)
    if args.esbuild is None:
        print(f"error: no esbuild: npm install esbuild@{ESBUILD_VERSION} and give --esbuild PATH", file=sys.stderr)
        return 2
    root = Path(__file__).resolve().parent
    try:
        target = build(args.esbuild, root)
    except UserError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(f"wrote {target} ({target.stat().st_size / 1e3:.0f} kB), sources sha256 {source_digest(root)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
