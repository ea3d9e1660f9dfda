"""The ``export-gltf`` verb: the head with its parameters as glTF 2.0 morph targets (docs/export.md).

>>> from engine.cli import main
>>> main(["export-gltf", "-o", "head.glb"])                                      # doctest: +SKIP
>>> main(["export-gltf", "--skeleton", "-o", "rigged.glb"])                      # doctest: +SKIP
>>> main(["export-gltf", "--parameters", "jaw_open,brow_raise", "--no-arkit",
...       "--value", "jaw_open=0.5", "-o", "head.gltf"])                          # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import Any

from engine.cli.common import add_model_option, load_model_argument, require_suffix, setting
from engine.errors import UserError


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
    from engine.outputs.gltf_export import SUFFIXES, export_gltf, parameter_targets, pose_targets, skeleton_parameters
    from engine.paths import default_model_path

    out = require_suffix(args.output, SUFFIXES, "export-gltf")
    model = load_model_argument(args.model)
    shipped = args.model is None or Path(args.model).resolve() == default_model_path().resolve()
    values = dict(args.values)
    names = args.parameters
    if names is None and args.skeleton:
        joints = set(skeleton_parameters(model))
        names = [name for name, _ in model.parameters.depth_first() if name not in joints]
    targets = parameter_targets(model, names, values)
    groups = list(args.pose_groups)
    if (shipped if args.arkit is None else args.arkit) and "arkit" not in groups:
        groups.insert(0, "arkit")
    if groups and args.poses is None and not shipped:
        raise UserError("the shipped poses fit the shipped head only: give --poses POSES.h5 for this model")
    for group in groups:
        targets += pose_targets(model, args.poses, group)
    mesh = export_gltf(model, out, targets, target_normals=args.target_normals, skeleton=args.skeleton)
    size = out.stat().st_size + (out.with_suffix(".bin").stat().st_size if out.suffix.lower() == ".gltf" else 0)
    print(f"wrote {out}: {len(mesh.primitives)} parts, {mesh.n_points} vertices, "
          f"{len(mesh.target_names)} morph targets"
          + (f", {len(mesh.skin.names)} joints" if mesh.skin is not None else "") + f", {_megabytes(size)}")
    return 0


def _megabytes(size: int) -> str:
    return f"{size / 1e6:.1f} MB" if size >= 1e5 else f"{math.ceil(size / 1e3)} kB"
