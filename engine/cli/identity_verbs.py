"""``identity``: a head for another person (sex, age, ancestry, face shape), with the rig carried over."""

from __future__ import annotations

import argparse
import json
from typing import Any

from engine.errors import UserError


def add_verbs(verbs: Any) -> None:
    p = verbs.add_parser("identity", help="make the head of another person (identity parameters, or a morph "
                                          "between two identities), its rig carried over; --list shows them")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="an identity parameter, e.g. sex=1, age=60, nose-scale-horiz-decr-incr=0.4 (repeat)")
    p.add_argument("--from", dest="source", metavar="A.xml", help="morph: the identity at T = 0 (a model file)")
    p.add_argument("--to", dest="target", metavar="B.xml", help="morph: the identity at T = 1 (a model file)")
    p.add_argument("--at", type=float, default=None, metavar="T", help="morph: where between A and B, 0 … 1")
    p.add_argument("-o", "--output", metavar="PERSON.xml", help="the model file to write (.xml + .h5)")
    p.add_argument("--list", action="store_true", help="list the identity parameters with their ranges")
    p.add_argument("--json", action="store_true", help="with --list: as JSON objects")
    p.set_defaults(run=run_identity)


def run_identity(args: argparse.Namespace) -> int:
    from engine.identity import IdentityError, identity_parameters

    if args.list:
        params = identity_parameters()
        if args.json:
            print(json.dumps([{k: v for k, v in p.as_json().items() if k != "description"} for p in params],
                             indent=1))
        else:
            group = None
            for p in params:
                if p.group != group:
                    group = p.group
                    print(f"[{group}]")
                print(f"  {p.name:42s} {p.minimum:g} … {p.maximum:g}  (default {p.default:.4g})  {p.description}")
        return 0
    if not args.output:
        raise UserError("identity: give -o PERSON.xml (or --list)")
    from engine.cli.common import model_output

    model_output(args.output)                  # not /dev/null (it wrote /dev/null.xml and /dev/null.h5), no folder
    morphing = [args.source, args.target, args.at]
    if any(v is not None for v in morphing) and not all(v is not None for v in morphing):
        raise IdentityError("a morph needs all of --from A.xml, --to B.xml and --at T")
    identity = _morph(args) if args.source is not None else _identity({})
    identity = identity.with_values(_assignments(args.set))
    from engine.formats.model_files import save_model
    from engine.identity import make_identity_head

    head = make_identity_head(identity)
    written = save_model(head, args.output)
    values = ", ".join(f"{k}={v:g}" for k, v in identity.values.items()) or "the default head"
    print(f"{written}: {head.name} ({values}); rig carried over, {len(head.parameters)} parameters")
    return 0


def _assignments(items: list[str]) -> dict[str, float]:
    from engine.identity import parse_assignments

    return parse_assignments(items)


def _identity(values: dict[str, float], file: str | None = None) -> Any:
    from engine.identity import Identity, IdentityError

    try:
        return Identity(values)
    except IdentityError as exc:
        if file is None:
            raise
        raise IdentityError(exc.message, file=file) from None


def _morph(args: argparse.Namespace) -> Any:
    from engine.formats.model_files import load_model
    from engine.identity import IdentityError, morph

    ends = []
    for path in (args.source, args.target):
        model = load_model(path)
        record = model.identity
        ends.append(_identity(record.values if record is not None else {}, path))
    if not 0.0 <= args.at <= 1.0:
        raise IdentityError(f"--at must be between 0 and 1, not {args.at:g}")
    return morph(ends[0], ends[1], args.at)
