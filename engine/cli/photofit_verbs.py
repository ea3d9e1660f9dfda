"""``fit-photos``: a person's head from a front (and optional side) photograph and landmarks placed on them.

>>> from engine.cli import main
>>> main(["fit-photos", "--front", "me.jpg", "--landmarks", "points.json", "-o", "me.xml"])   # doctest: +SKIP
"""

from __future__ import annotations

import argparse
from typing import Any


def add_verbs(verbs: Any) -> None:
    p = verbs.add_parser("fit-photos", help="fit the head (shape, texture, rig carried over) to a front and an "
                                            "optional side photograph with landmarks placed on them")
    p.add_argument("--front", required=True, metavar="F.jpg", help="the front photograph (JPEG or PNG)")
    p.add_argument("--side", metavar="S.jpg", help="a side photograph from the subject's left (optional)")
    p.add_argument("--landmarks", required=True, metavar="POINTS.json",
                   help='{"front": {"<MPEG-4 id>": [x, y], ...}, "side": {...}} in pixels, origin top left')
    p.add_argument("-o", "--output", required=True, metavar="PERSON.xml", help="the model file to write")
    p.set_defaults(run=run_fit_photos)


def run_fit_photos(args: argparse.Namespace) -> int:
    from engine.cli.common import model_output, require_suffix
    from engine.formats.model_files import save_model
    from engine.photofit import fit_photo_files

    require_suffix(args.output, (".xml",), "a model file")
    model_output(args.output)
    result = fit_photo_files(args.front, args.side, args.landmarks)
    written = save_model(result.head, args.output)
    s = result.seconds
    shape = result.shape
    print(f"{written}: fitted to {', '.join(shape.cameras)}; landmark error {shape.error:.2f} px RMS "
          f"({shape.error_before_warp:.2f} px before the residual warp)")
    print(f"time: landmarks {s['landmarks']:.2f} s → shape {s['shape']:.2f} s → texture {s['texture']:.2f} s")
    values = ", ".join(f"{k}={v:.3g}" for k, v in shape.identity.values.items()) or "the default head"
    print(f"identity: {values}")
    return 0
