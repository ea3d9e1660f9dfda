"""Work out the default head's skin image and write it to ``skin.png`` beside this script (issue 32 item 1).

The image is the skin :mod:`engine.identity.skin` synthesises for the default
identity (``Identity()``) on the shipped head, at the atlas size every identity
gets (``ATLAS_SIZE``), with the key of everything it is computed from in a PNG
text chunk (:mod:`engine.identity.skin_cache`).
:func:`engine.formats.default_head_skin.put_on_shipped_skin` puts it on the
shipped head; ``make_identity_head`` takes it for the default identity while
its key is current (docs/skin.md "The default head").
``tests/engine/test_skin_default_head.py`` fails when the code has moved on:
then run this again and commit the new image::

    .venv/bin/python engine/data/default-head/default_skin.py

The image is ours (synthesised by this project's code, no photograph or
third-party image in it), released under CC0 1.0 like the rest of the head
(``ATTRIBUTION.md``).
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[3]))

from engine.formats.model_files import load_model
from engine.identity import Identity
from engine.identity.skin import ATLAS_SIZE, skin_texture
from engine.identity.skin_cache import SHIPPED_SKIN, skin_key, skin_png_bytes


def main() -> None:
    head = load_model()
    pixels = skin_texture(head, Identity(), ATLAS_SIZE).pixels
    temporary = SHIPPED_SKIN.with_suffix(".tmp")
    temporary.write_bytes(skin_png_bytes(pixels, skin_key(head, Identity(), ATLAS_SIZE), level=9))
    temporary.replace(SHIPPED_SKIN)
    print(f"wrote {SHIPPED_SKIN} ({SHIPPED_SKIN.stat().st_size / 1e6:.2f} MB, {ATLAS_SIZE}×{ATLAS_SIZE})")


if __name__ == "__main__":
    main()
