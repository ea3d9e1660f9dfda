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
    p.add_argument("--random", action="store_true",
                   help="draw a plausible adult from the population model (docs/identity.md); needs --seed")
    p.add_argument("--seed", metavar="N", help="with --random: which person, a whole number 0 … 4294967295 "
                                               "(the same seed draws the same person)")
    p.add_argument("--sex", metavar="female|male", help="with --random: draw a woman or a man")
    p.add_argument("--age", metavar="YEARS|LOW-HIGH", help="with --random: this age, or an age drawn from this "
                                                           "range (default 18-75)")
    p.add_argument("--population", metavar="VERSION", help="with --random: the population model's version "
                                                           "(default: the newest, 2; 1 draws an old set again)")
    p.add_argument("--from", dest="source", metavar="A.xml", help="morph: the identity at T = 0 (a model file)")
    p.add_argument("--to", dest="target", metavar="B.xml", help="morph: the identity at T = 1 (a model file)")
    p.add_argument("--at", type=float, default=None, metavar="T", help="morph: where between A and B, 0 … 1")
    p.add_argument("--hair", metavar="STYLE", help="scalp hair: none (bald), short, long or tied (docs/hair.md); "
                                                  "without hair options the head stays as before: bald, brows painted "
                                                  "(a --random person: the hair drawn with it)")
    p.add_argument("--hair-colour", "--hair-color", dest="hair_colour", metavar="COLOUR",
                   help="black, dark-brown, brown, blond, red, grey or white (default: chosen from age and ancestry)")
    p.add_argument("--beard", metavar="KIND", help="facial hair: none, stubble, moustache or beard")
    p.add_argument("--brows", metavar="THICKNESS", help="brows as hair: none, thin, medium (default) or thick")
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
    if args.random:
        if args.source is not None:
            raise IdentityError("--random draws a new person; it cannot also morph (--from, --to, --at)")
        identity = _random(args)
    else:
        for option in ("seed", "sex", "age", "population"):
            if getattr(args, option) is not None:
                raise IdentityError(f"--{option} chooses what --random draws: give --random too (or --set "
                                    f"{'sex=0' if option == 'sex' else 'age=40' if option == 'age' else 'NAME=VALUE'})")
        identity = _morph(args) if args.source is not None else _identity({})
        identity = identity.with_values(_assignments(args.set))
    from engine.formats.model_files import save_model
    from engine.identity import make_identity_head

    head = make_identity_head(identity, hair=_hair(args, identity))
    if identity.drawn is not None:
        head.name = f"random-person-{identity.drawn['seed']}"
    written = save_model(head, args.output)
    if identity.drawn is not None:
        values = (f"drawn from population model {identity.drawn['population']} with seed {identity.drawn['seed']}: "
                  f"sex={identity.value('sex'):g}, age={identity.value('age'):g}, {len(identity.values)} values")
    else:
        values = ", ".join(f"{k}={v:g}" for k, v in identity.values.items()) or "the default head"
    from engine.identity.hair_style import hair_of

    hair = hair_of(head.identity)
    worn = f"; {hair.describe()}" if hair is not None else ""
    print(f"{written}: {head.name} ({values}); rig carried over, {len(head.parameters)} parameters{worn}")
    return 0


def _hair(args: argparse.Namespace, identity: Any = None) -> Any:
    """The hair ``--hair``, ``--hair-colour``, ``--beard`` and ``--brows`` ask for (None: none of them given).

    A random person starts from the hair drawn with it (population_hair.drawn_hair); each option given replaces
    that part (``--hair none`` a bald scalp, ``--beard none`` a shaven face, ``--brows none`` painted brows).
    """
    given = [args.hair, args.hair_colour, args.beard, args.brows]
    if all(v is None for v in given):
        return None
    from engine.identity.hair_style import HairChoice

    asked = HairChoice.parse(style=args.hair, colour=args.hair_colour, beard=args.beard, brows=args.brows)
    from engine.identity.population_hair import drawn_hair

    drawn = drawn_hair(identity) if identity is not None else None
    if drawn is None:
        return asked
    from dataclasses import replace

    return replace(drawn, **{field: getattr(asked, field) for field, value in
                             zip(("style", "colour", "beard", "brows"), given, strict=True) if value is not None})


def _random(args: argparse.Namespace) -> Any:
    """The person ``--random --seed N [--sex …] [--age …] [--set …]`` asks for."""
    from engine.identity import IdentityError
    from engine.identity.population import MAX_SEED, draw_identity

    if args.seed is None:
        raise IdentityError("--random needs --seed N (a whole number 0 … 4294967295), so the same person can be "
                            "drawn again")
    text = args.seed.strip()
    if not text.isdigit() or len(text) > 10 or int(text) > MAX_SEED:
        shown = text if len(text) <= 20 else f"{text[:20]}… ({len(text)} characters)"
        raise IdentityError(f"--seed must be a whole number from 0 to {MAX_SEED}, not '{shown}'")
    fixed = _assignments(args.set)
    ages = None
    if args.age is not None:
        low, dash, high = args.age.strip().partition("-")
        try:
            numbers = (float(low), float(high) if dash else float(low))
        except ValueError:
            raise IdentityError(f"--age must be YEARS or LOW-HIGH (e.g. 40 or 20-35), not '{args.age[:20]}'") \
                from None
        if not dash:
            if "age" in fixed and fixed["age"] != numbers[0]:
                raise IdentityError(f"--age {args.age} contradicts --set age={fixed['age']:g}")
            fixed["age"] = numbers[0]
        else:
            ages = numbers
    population = None
    if args.population is not None:
        from engine.identity.population import POPULATIONS

        if args.population.strip() not in {str(v) for v in POPULATIONS}:
            raise IdentityError(f"--population must be one of {', '.join(map(str, POPULATIONS))}, "
                                f"not '{args.population[:20]}'")
        population = int(args.population)
    if population is None:
        return draw_identity(int(text), sex=args.sex, ages=ages, fixed=fixed)
    return draw_identity(int(text), sex=args.sex, ages=ages, fixed=fixed, population=population)


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
