"""``fit-photos``: a person's head from a front (and optional side) photograph, landmarks placed or found.

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
    p.add_argument("--landmarks", metavar="POINTS.json",
                   help='{"front": {"<MPEG-4 id>": [x, y], ...}, "side": {...}} in pixels, origin top left; '
                        "without it the points are found by themselves and written to PERSON-landmarks.json")
    p.add_argument("-o", "--output", required=True, metavar="PERSON.xml", help="the model file to write")
    p.set_defaults(run=run_fit_photos)


def describe_person(identity: Any) -> str:
    """The fitted sex, age and ancestry in words, e.g. ``sex 0.91 (a man's face), age 47, ancestry …``."""
    sex = identity.value("sex")
    kind = "a man's face" if sex >= 0.6 else "a woman's face" if sex <= 0.4 else "between a woman's and a man's"
    shares = " · ".join(f"{race.capitalize()} {share:.2f}" for race, share in identity.ancestry().items())
    return f"sex {sex:.2f} ({kind}), age {identity.value('age'):.0f}, ancestry {shares}"


def run_fit_photos(args: argparse.Namespace) -> int:
    from engine.cli.common import model_output, require_suffix
    from engine.formats.model_files import save_model
    from engine.photofit import fit_photo_files
    from engine.photofit.auto_landmarks import landmarks_path

    require_suffix(args.output, (".xml",), "a model file")
    model_output(args.output)
    found_to = None if args.landmarks else landmarks_path(args.output)
    result = fit_photo_files(args.front, args.side, args.landmarks, found_to=found_to)
    written = save_model(result.head, args.output)
    if result.found_points is not None:
        print(f"landmarks: found by themselves, written to {result.found_points} (correct them there and fit "
              "again with --landmarks)")
    s = result.seconds
    shape = result.shape
    print(f"{written}: fitted to {', '.join(shape.cameras)}; landmark error {shape.error:.2f} px RMS "
          f"({shape.error_before_warp:.2f} px before the residual warp)")
    print(f"time: landmarks {s['landmarks']:.2f} s → shape {s['shape']:.2f} s → texture {s['texture']:.2f} s")
    print(f"person: {describe_person(shape.identity)}")
    values = ", ".join(f"{k}={v:.3g}" for k, v in shape.identity.values.items()) or "the default head"
    print(f"identity: {values}")
    moves = ", ".join(f"{k}={v:.2g}" for k, v in shape.expression.items()) or "none (a neutral face)"
    print(f"expression in the photograph (taken out of the head at rest): {moves}")
    return 0
