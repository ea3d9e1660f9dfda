"""Verbs on one model: ``info``, ``render``, ``pose``, ``import-mesh``.

>>> from engine.cli import main
>>> main(["info", "--json"])                                   # doctest: +SKIP
>>> main(["render", "--set", "jaw_open=0.5", "head_turn=-0.3", "--view", "three-quarter",
...       "-o", "pose.png"])                                   # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import json
from typing import Any

import numpy as np

from engine.cli.common import (
    VIEW_NAMES,
    add_model_option,
    add_set_option,
    load_model_argument,
    parameter_values,
    positive_number,
    require_suffix,
    size,
)
from engine.cli.render_info import RenderInfoAction
from engine.model import Model
from engine.model.landmarks import landmark_sort_key

POSE_FORMATS = (".obj", ".ply", ".npz")


def add_verbs(verbs: Any) -> None:
    """Add ``info``, ``render``, ``pose`` and ``import-mesh`` to the CLI's sub-parsers."""
    p = verbs.add_parser("info", help="print the parameter tree, parts and landmarks")
    add_model_option(p)
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.set_defaults(run=run_info)

    p = verbs.add_parser("render", help="render one pose to a PNG picture")
    add_model_option(p)
    add_set_option(p)
    p.add_argument("--view", choices=VIEW_NAMES, default="front",
                   help="camera: front, side (from the subject's left) or three-quarter")
    p.add_argument("--size", type=size, default=(600, 800), metavar="WxH",
                   help="picture size in pixels (default 600x800)")
    p.add_argument("--look", default=None, metavar="NAME",
                   help="lighting and shading: portrait (default), flat, legacy, or a JSON file of a look's "
                        "settings (docs/looks.md)")
    p.add_argument("-o", "--output", required=True, metavar="OUT.png", help="picture to write")
    p.add_argument("--info", action=RenderInfoAction, help="print which OpenGL draws here (GPU or software) and end")
    p.set_defaults(run=run_render)

    p = verbs.add_parser("pose", help="write the deformed mesh (same vertex order as the model)")
    add_model_option(p)
    add_set_option(p)
    p.add_argument("-o", "--output", required=True, metavar="OUT.(obj|ply|npz)",
                   help="mesh file to write (a textured model's OBJ gets texture coordinates, an .mtl and the "
                        "images as PNG beside it)")
    p.set_defaults(run=run_pose)

    p = verbs.add_parser("import-mesh", help="make a model with no parameters from a mesh file")
    p.add_argument("file", metavar="FILE", help="OBJ, PLY, STL, VTK/VTP, glTF/GLB, …")
    p.add_argument("-o", "--output", required=True, metavar="MODEL.xml",
                   help="model description to write (its arrays go beside it as .h5)")
    p.add_argument("--scale", type=positive_number, default=None, metavar="S",
                   help="multiply coordinates by S to get mm (default: glTF is in metres, so 1000; "
                        "every other format is taken to be in mm, so 1)")
    p.add_argument("--keep-units", action="store_true",
                   help="keep the file's numbers as they are (no metres-to-mm conversion for glTF)")
    p.add_argument("--up", default="+Y", metavar="AXIS",
                   help="the file's up direction: Y (default), Z or X with a sign, e.g. --up Z or "
                        "--up Z- (or --up=-Z); the mesh is turned so that it points along +Y, the model's up")
    p.set_defaults(run=run_import_mesh)


def run_info(args: argparse.Namespace) -> int:
    model = load_model_argument(args.model)
    if args.json:
        print(json.dumps(model_summary(model), indent=2))
    else:
        print(model_report(model))
    return 0


def run_render(args: argparse.Namespace) -> int:
    out = require_suffix(args.output, (".png",), "render")
    model = load_model_argument(args.model)
    values = parameter_values(model, args.settings)
    from engine.outputs.looks import look_option
    from engine.outputs.render import render_model

    look = look_option(args.look) if args.look is not None else None
    render_model(model, values, view=args.view, size=args.size, path=out, look=look)
    return 0


def run_pose(args: argparse.Namespace) -> int:
    out = require_suffix(args.output, POSE_FORMATS, "pose")
    model = load_model_argument(args.model)
    values = parameter_values(model, args.settings)
    from engine.formats.mesh_io import write_mesh

    write_mesh(out, model.deform(values), model.faces, parts=model.parts, vertex_part=model.vertex_part,
               name=model.name, texture=model.texture if str(out).lower().endswith(".obj") else None)
    return 0


def run_import_mesh(args: argparse.Namespace) -> int:
    out = require_suffix(args.output, (".xml",), "import-mesh")
    from pathlib import Path

    from engine.formats.mesh_io import mesh_model, read_mesh
    from engine.formats.model_files import save_model

    mesh = read_mesh(args.file, scale=args.scale, keep_units=args.keep_units, up=args.up)
    model = mesh_model(mesh, Path(args.file))
    save_model(model, out)
    print(import_report(mesh, args.file, out, model))
    return 0


def import_report(mesh: Any, source: str, out: str | Any, model: Model | None = None) -> str:
    """What ``import-mesh`` read: sizes, units, up axis, texture coordinates and material images
    (and, given the model made, the images it keeps)."""
    lines = [f"{source}: {len(mesh.vertices)} vertices, {len(mesh.part_names)} part(s); model written to {out}",
             f"units: coordinates × {mesh.scale:g} to mm; up: " +
             ("+Y, as in the file" if mesh.up == "+Y" else f"the file's {mesh.up} turned to +Y")]
    texture = mesh.texture
    if texture is None or not texture.has_coordinates:
        lines.append("texture coordinates: none")
    else:
        seams = "one per vertex" if texture.vertex_uv(mesh.faces, len(mesh.vertices)) is not None \
            else "per polygon corner (the file has texture seams)"
        lines.append(f"texture coordinates: yes, {seams}")
    if texture is not None:
        lines += [f"material {m.name}: image {m.image or 'none'}" for m in texture.materials]
    if model is not None and model.texture is not None:
        kept = [f"{i.name} ({i.pixels.shape[1]}×{i.pixels.shape[0]})" for i in model.texture.images]
        lines.append(f"texture kept in the model: {len(model.texture.corner_uv)} corner coordinates, "
                     f"images: {', '.join(kept) or 'none'}")
    lines += [f"note: {note}" for note in mesh.notes]
    return "\n".join(lines)


def model_summary(model: Model) -> dict[str, Any]:
    """The ``info --json`` object: parameters (tree order), landmarks and vertex count."""
    tree = model.parameters
    parameters = []
    for name, _ in tree.depth_first():
        p = tree[name]
        parameters.append({"name": p.name, "type": p.kind, "group": tree.group(name), "parent": p.parent,
                           "min": p.minimum, "max": p.maximum, "default": p.default})
    summary: dict[str, Any] = {"parameters": parameters,
                               "landmarks": {k: int(v) for k, v in model.landmarks.items()},
                               "vertices": int(model.n_vertices)}
    if model.texture is not None:       # only textured models have the key
        texture = model.texture
        summary["texture"] = {"corners": len(texture.corner_uv),
                              "textured_polygons": int(texture.textured_faces().sum()),
                              "images": [{"name": i.name, "width": int(i.pixels.shape[1]),
                                          "height": int(i.pixels.shape[0]), "channels": i.channels}
                                         for i in texture.images]}
    return summary


def model_report(model: Model) -> str:
    """The ``info`` text: an indented parameter tree, then parts and landmarks."""
    tree = model.parameters
    n_polygons = len(model.polygons())
    lines = [f"{model.name}: {model.n_vertices} vertices, {n_polygons} polygons, "
             f"{len(model.parts)} parts, {len(model.parameters)} parameters"]
    rows = []
    for name, depth in tree.depth_first():
        p = tree[name]
        if p.kind == "rotation":
            scale = f"{p.degrees_per_unit:g} deg/unit"
        elif p.field:
            scale = "displacement field"
        else:
            scale = f"{float(np.linalg.norm(p.direction)):g} mm/unit"
        rows.append(("  " * depth + name, p.kind, f"group {tree.group(name)}",
                     f"[{p.minimum:g}, {p.maximum:g}]", f"default {p.default:g}", scale))
    if rows:
        widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
        lines.append("parameters (name, type, group, range, default, scale):")
        lines += ["  " + "  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows]
    else:
        lines.append("parameters: none")
    counts = np.bincount(model.vertex_part, minlength=len(model.parts))
    lines.append("parts: " + ", ".join(f"{part} ({counts[i]} vertices)" for i, part in enumerate(model.parts)))
    ids = sorted(model.landmarks, key=landmark_sort_key)
    lines.append(f"landmarks: {len(ids)}" + (f" ({', '.join(ids)})" if ids else ""))
    if model.texture is not None:
        texture = model.texture
        images = ", ".join(f"{i.name} ({i.pixels.shape[1]}×{i.pixels.shape[0]})" for i in texture.images)
        lines.append(f"texture: {int(texture.textured_faces().sum())} of {n_polygons} polygons show an image; "
                     f"images: {images or 'none'}")
    return "\n".join(lines)
