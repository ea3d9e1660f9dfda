"""The command line, ``artificial-person <verb>`` (DESIGN.md, "Command line").

Every verb calls the same engine functions the workbench uses. Mistakes in
the user's input (a bad option, an unknown parameter, a malformed model file)
end with status 2 and one line on stderr, ``error: <file>:<line>: <what>``,
never a traceback.

>>> from engine.cli import main
>>> main(["info", "--json"])                                   # doctest: +SKIP
>>> main(["render", "--set", "jaw_open=0.5", "head_turn=-0.3", "--view", "three-quarter",
...       "-o", "pose.png"])                                   # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

from .errors import ModelFileError, UserError
from .landmarks import landmark_sort_key

PROG = "artificial-person"
VIEW_NAMES = ("front", "side", "three-quarter")
POSE_FORMATS = (".obj", ".ply", ".npz")


class _Parser(argparse.ArgumentParser):
    """argparse that reports a mistake as one :class:`UserError` instead of usage text and exit."""

    def error(self, message: str):
        raise UserError(message)


def main(argv: list[str] | None = None) -> int:
    """Run one command; returns the exit status (0 ok, 2 bad input, 1 environment trouble)."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
        return int(args.run(args) or 0)
    except UserError as exc:
        _say_error(str(exc))
        return 2
    except SystemExit as exc:  # --help and --version
        return exc.code if isinstance(exc.code, int) else 0
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:  # e.g. `artificial-person info | head`
        sys.stderr.close()
        return 0
    except OSError as exc:  # disk full, permissions: not a bug, so no traceback either
        where = f"{exc.filename}: " if exc.filename else ""
        _say_error(f"{where}{exc.strerror or exc}")
        return 1


def _say_error(text: str) -> None:
    print("error: " + " ".join(text.split()), file=sys.stderr)


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with one sub-parser per verb."""
    from . import __version__

    parser = _Parser(prog=PROG, description="Build, configure and animate the Artificial Person talking head.")
    parser.add_argument("--version", action="version", version=f"{PROG} {__version__}")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    p = verbs.add_parser("workbench", help="open the GUI on a model (default head)")
    p.add_argument("model", nargs="?", metavar="MODEL", help="model description (.xml); default: the shipped head")
    p.set_defaults(run=_run_workbench)

    p = verbs.add_parser("info", help="print the parameter tree, parts and landmarks")
    _add_model_option(p)
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.set_defaults(run=_run_info)

    p = verbs.add_parser("render", help="render one pose to a PNG picture")
    _add_model_option(p)
    _add_set_option(p)
    p.add_argument("--view", choices=VIEW_NAMES, default="front",
                   help="camera: front, side (from the subject's left) or three-quarter")
    p.add_argument("--size", type=_size, default=(600, 800), metavar="WxH",
                   help="picture size in pixels (default 600x800)")
    p.add_argument("-o", "--output", required=True, metavar="OUT.png", help="picture to write")
    p.set_defaults(run=_run_render)

    p = verbs.add_parser("pose", help="write the deformed mesh (same vertex order as the model)")
    _add_model_option(p)
    _add_set_option(p)
    p.add_argument("-o", "--output", required=True, metavar="OUT.(obj|ply|npz)", help="mesh file to write")
    p.set_defaults(run=_run_pose)

    p = verbs.add_parser("import-mesh", help="make a model with no parameters from a mesh file")
    p.add_argument("file", metavar="FILE", help="OBJ, PLY, STL, VTK/VTP, glTF/GLB, …")
    p.add_argument("-o", "--output", required=True, metavar="MODEL.xml",
                   help="model description to write (its arrays go beside it as .h5)")
    p.add_argument("--scale", type=_positive_number, default=None, metavar="S",
                   help="multiply coordinates by S to get mm (default 1: the file is in mm)")
    p.set_defaults(run=_run_import_mesh)

    from . import cli_commands, cli_export, cli_mocap, cli_speech

    cli_commands.add_verbs(verbs, _add_model_option, _positive_number)
    cli_speech.add_verbs(verbs, _add_model_option, _positive_number, _size, VIEW_NAMES)
    cli_export.add_verbs(verbs, _add_model_option)
    cli_mocap.add_verbs(verbs, _add_model_option, _positive_number)
    return parser


def _add_model_option(p: argparse.ArgumentParser) -> None:
    p.add_argument("-m", "--model", default=None, metavar="MODEL",
                   help="model description (.xml); default: the shipped head")


def _add_set_option(p: argparse.ArgumentParser) -> None:
    p.add_argument("--set", dest="settings", action="extend", nargs="+", type=_setting, default=[],
                   metavar="NAME=VALUE", help="parameter values (may be repeated); others take their default")


# -- argument types ------------------------------------------------------------

def _setting(text: str) -> tuple[str, float]:
    name, sep, value = text.partition("=")
    name = name.strip()
    if not sep or not name:
        raise argparse.ArgumentTypeError(f"'{text}' is not NAME=VALUE (e.g. jaw_open=0.5)")
    try:
        number = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}': '{value}' is not a number") from None
    if not math.isfinite(number):
        raise argparse.ArgumentTypeError(f"'{text}': the value must be a finite number")
    return name, number


def _size(text: str) -> tuple[int, int]:
    from .render import MAX_SIZE

    parts = text.lower().split("x")
    if len(parts) != 2 or not all(p.strip().isdigit() for p in parts):
        raise argparse.ArgumentTypeError(f"'{text}' is not WIDTHxHEIGHT in pixels (e.g. 800x600)")
    width, height = (int(p) for p in parts)
    if not (0 < width <= MAX_SIZE and 0 < height <= MAX_SIZE):
        raise argparse.ArgumentTypeError(f"'{text}': width and height must be 1..{MAX_SIZE} pixels")
    return width, height


def _positive_number(text: str) -> float:
    try:
        number = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
    if not (math.isfinite(number) and number > 0):
        raise argparse.ArgumentTypeError(f"'{text}' must be a positive number")
    return number


# -- helpers ---------------------------------------------------------------------

def _load(model_path):
    """Load a model; file problems the loader lets escape still become one error line."""
    from lxml import etree

    from .model_files import load_model
    from .paths import default_model_path

    try:
        return load_model(model_path)
    except etree.LxmlError as exc:  # e.g. schema validation choking on an unexpanded entity
        where = model_path if model_path is not None else default_model_path()
        raise ModelFileError(f"cannot read the model description: {exc}", file=where) from None
    except (ValueError, TypeError) as exc:  # malformed numbers or arrays in a damaged file
        where = model_path if model_path is not None else default_model_path()
        raise ModelFileError(f"damaged model: {exc}", file=where) from None


def _values(model, settings) -> dict[str, float]:
    """``--set`` pairs as a dict (the last one wins), checked against the model's ranges."""
    values = dict(settings)
    model.check_values(values)
    return values


def _require_suffix(path: str, allowed: tuple[str, ...], what: str) -> Path:
    out = Path(path)
    if out.suffix.lower() not in allowed:
        raise UserError(f"unknown output extension '{out.suffix or out.name}' for {what} "
                        f"(use {_either(allowed)})", file=out)
    return out


# -- verbs ---------------------------------------------------------------------

def _run_workbench(args) -> int:
    if args.model is not None and not Path(args.model).exists():
        raise ModelFileError("no such file", file=args.model)
    try:
        from workbench.app import main as workbench_main
    except ImportError as exc:
        _say_error(f"cannot start the workbench: {exc}")
        return 1
    return workbench_main(args.model)


def _run_info(args) -> int:
    model = _load(args.model)
    if args.json:
        print(json.dumps(model_summary(model), indent=2))
    else:
        print(model_report(model))
    return 0


def _run_render(args) -> int:
    out = _require_suffix(args.output, (".png",), "render")
    model = _load(args.model)
    values = _values(model, args.settings)
    from .render import render_model

    render_model(model, values, view=args.view, size=args.size, path=out)
    return 0


def _run_pose(args) -> int:
    out = _require_suffix(args.output, POSE_FORMATS, "pose")
    model = _load(args.model)
    values = _values(model, args.settings)
    from .mesh_io import write_mesh

    write_mesh(out, model.deform(values), model.faces, parts=model.parts, vertex_part=model.vertex_part,
               name=model.name)
    return 0


def _run_import_mesh(args) -> int:
    out = _require_suffix(args.output, (".xml",), "import-mesh")
    from .mesh_io import import_mesh
    from .model_files import save_model

    save_model(import_mesh(args.file, scale=args.scale), out)
    return 0


# -- info ------------------------------------------------------------------------

def model_summary(model) -> dict:
    """The ``info --json`` object: parameters (tree order), landmarks and vertex count."""
    tree = model.parameters
    parameters = []
    for name, _ in tree.depth_first():
        p = tree[name]
        parameters.append({"name": p.name, "type": p.kind, "group": tree.group(name), "parent": p.parent,
                           "min": p.minimum, "max": p.maximum, "default": p.default})
    return {"parameters": parameters, "landmarks": {k: int(v) for k, v in model.landmarks.items()},
            "vertices": int(model.n_vertices)}


def model_report(model) -> str:
    """The ``info`` text: an indented parameter tree, then parts and landmarks."""
    import numpy as np

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
        lines += ["  " + "  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in rows]
    else:
        lines.append("parameters: none")
    counts = np.bincount(model.vertex_part, minlength=len(model.parts))
    lines.append("parts: " + ", ".join(f"{part} ({counts[i]} vertices)" for i, part in enumerate(model.parts)))
    ids = sorted(model.landmarks, key=landmark_sort_key)
    lines.append(f"landmarks: {len(ids)}" + (f" ({', '.join(ids)})" if ids else ""))
    return "\n".join(lines)



def _either(options: tuple[str, ...]) -> str:
    return options[0] if len(options) == 1 else ", ".join(options[:-1]) + " or " + options[-1]
