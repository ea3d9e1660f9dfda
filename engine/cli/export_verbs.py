"""The ``export-gltf`` verb: the head with its parameters as glTF 2.0 morph targets (docs/export.md).

>>> from engine.cli import main
>>> main(["export-gltf", "-o", "head.glb"])                                      # doctest: +SKIP
>>> main(["export-gltf", "--skeleton", "-o", "rigged.glb"])                      # doctest: +SKIP
>>> main(["export-gltf", "--parameters", "jaw_open,brow_raise", "--no-arkit",
...       "--value", "jaw_open=0.5", "-o", "head.gltf"])                          # doctest: +SKIP
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from engine.cli.common import add_model_option, load_model_argument, require_suffix, setting


def add_verbs(verbs: Any) -> None:
    """Add ``export-gltf`` to the CLI's sub-parsers."""
    p = verbs.add_parser("export-gltf", help="write the model with its parameters as glTF 2.0 morph targets "
                                             "(Blender, Unity, Unreal, three.js)")
    add_model_option(p)
    p.add_argument("--parameters", default=None, type=_names, metavar="NAME,...",
                   help="parameters to export as morph targets, comma-separated (default: all; '' for none)")
    p.add_argument("--value", dest="values", action="extend", nargs="+", type=setting, default=[],
                   metavar="NAME=VALUE",
                   help="the value a parameter's target shows at weight 1 (default 1, or the range's end)")
    arkit = p.add_mutually_exclusive_group()
    arkit.add_argument("--arkit", dest="arkit", action="store_true", default=None,
                       help="add the ARKit-52 targets from the poses file (default: with the shipped head only)")
    arkit.add_argument("--no-arkit", dest="arkit", action="store_false", help="leave the ARKit-52 targets out")
    p.add_argument("--poses", default=None, metavar="POSES.h5",
                   help="file of displacement fields for --arkit and --pose-group "
                        "(default: the shipped head's reference-poses.h5)")
    p.add_argument("--pose-group", dest="pose_groups", action="append", default=[], metavar="GROUP",
                   help="also export every pose of this group of the poses file, e.g. expression_units")
    p.add_argument("--skeleton", action="store_true",
                   help="export the rigid group-1 parameters (head, jaw, eyes) as joints of a skeleton "
                        "instead of morph targets: exact at every value, and leaves ride on them as here")
    p.add_argument("--no-target-normals", dest="target_normals", action="store_false",
                   help="leave out the targets' normal changes (about half the file size)")
    p.add_argument("-o", "--output", required=True, metavar="OUT.(glb|gltf)",
                   help="binary .glb, or .gltf with its buffer beside it as .bin")
    p.set_defaults(run=run_export_gltf)


def _names(text: str) -> list[str]:
    return [n.strip() for n in text.split(",") if n.strip()]


def run_export_gltf(args: argparse.Namespace) -> int:
    """Export the model (``-m``, default the shipped head) with the targets the options choose
    (:func:`engine.outputs.gltf_export.export_targets`, as the workbench's File → Export → glTF… does)."""
    from engine.outputs.gltf_export import SUFFIXES, export_gltf, export_summary, export_targets
    from engine.paths import default_model_path

    out = require_suffix(args.output, SUFFIXES, "export-gltf")
    model = load_model_argument(args.model)
    model_file = Path(args.model) if args.model is not None else default_model_path()
    targets = export_targets(model, args.parameters, dict(args.values), arkit=args.arkit, poses=args.poses,
                             pose_groups=args.pose_groups, skeleton=args.skeleton, model_file=model_file)
    mesh = export_gltf(model, out, targets, target_normals=args.target_normals, skeleton=args.skeleton)
    print(f"wrote {out}: {export_summary(out, mesh)}")
    return 0
