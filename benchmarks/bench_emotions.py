#!/usr/bin/env python3
"""The shipped emotions on five people, as `validate`'s FER2013 classifier reads them (issue 32's goal).

    .venv/bin/python benchmarks/bench_emotions.py [--amplitude 100] [--people 5] [-L FOLDER]
                                                  [--expressions Neutral,Happy,...] [--look NAME]

Renders each expression at the middle of its apex, front view, 640 × 480, on the default head and
the four identities of ``docs/make_validation_gallery.py`` (the same renderer, look and heads), and
judges each picture in memory with the classifier of ``engine.validation`` (no files written). It
prints the table of people × expressions (the class judged and its probability, ``*`` where it is
the intended one) and the figures of issue 32: how many read as intended, the mean probability of
the intended class, and neutral read as neutral. ``-L`` adds a folder of library files (a command
there overrides the shipped one of its name), ``--expressions`` names the commands to render; a
command whose name is not a classifier class is scored as the class named after ``=``
(``--expressions Anger2=Anger``). No timing is measured.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
from PIL import Image

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "docs"))

from make_validation_gallery import EXPRESSIONS, PEOPLE, SIZE, apex_values  # noqa: E402

import engine  # noqa: E402
from engine.commands import load_library  # noqa: E402
from engine.identity import Identity, make_identity_head  # noqa: E402
from engine.outputs.render import FrameRenderer  # noqa: E402
from engine.validation.intended import Intended, intended_emotion  # noqa: E402
from engine.validation.judge import judge_pixels  # noqa: E402
from engine.validation.observers import observers  # noqa: E402


def _commands(text: str | None) -> list[tuple[str, str]]:
    """(command, class it is meant to show) for each name of ``--expressions``."""
    names = text.split(",") if text else EXPRESSIONS
    pairs = []
    for name in names:
        command, _, meant = name.strip().partition("=")
        pairs.append((command, meant or command))
    return pairs


def measure(commands: list[tuple[str, str]], amplitude: float, people: int, folders: list[str],
            look: str | None, save: Path | None = None) -> dict[tuple[str, str], tuple[str, float, float, str]]:
    """(person, command) → (judged class, its probability, intended class's probability, intended)."""
    library = load_library(folders)
    eyes = observers()
    cells = {}
    for person, values in list(PEOPLE.items())[:people]:
        head = engine.load_model() if values is None else make_identity_head(Identity(values))
        renderer = FrameRenderer(head, size=SIZE, view="front", look=look)
        try:
            for command, meant in commands:
                level = 100 if command == "Neutral" else amplitude
                pose = apex_values(f'<{command} at="0" amplitude="{level:g}"/>', library, head)
                intended = intended_emotion(meant)
                pixels = renderer.render(head.deform(pose))
                if save is not None:
                    Image.fromarray(pixels).save(save / f"{person.replace(' ', '-')}_{command}.png")
                verdict = judge_pixels(pixels, f"{person} {command}", Intended(emotion=intended), eyes=eyes)
                cells[(person, command)] = (verdict.judged or "-", verdict.judged_probability or 0.0,
                                            verdict.intended_probability or 0.0, intended or "?")
        finally:
            renderer.close()
        print(f"rendered {person}", file=sys.stderr, flush=True)
    return cells


def report(cells, commands: list[tuple[str, str]], people: int) -> None:
    """The table and the figures, on stdout."""
    names = list(PEOPLE)[:people]
    print("| person | " + " | ".join(c for c, _ in commands) + " |")
    print("|---" * (len(commands) + 1) + "|")
    for person in names:
        row = []
        for command, _ in commands:
            judged, p, _, intended = cells[(person, command)]
            row.append(f"{'**' if judged == intended else ''}{judged} {p:.2f}{'**' if judged == intended else ''}")
        print(f"| {person} | " + " | ".join(row) + " |")
    hits = [cells[k][0] == cells[k][3] for k in cells]
    probabilities = [cells[k][2] for k in cells]
    neutral = [cells[(p, "Neutral")][0] == "neutral" for p in names if (p, "Neutral") in cells]
    print(f"\nread as intended: {sum(hits)} of {len(hits)} ({100 * np.mean(hits):.0f} %)")
    print(f"mean probability of the intended class: {np.mean(probabilities):.2f}")
    if neutral:
        print(f"neutral read as neutral: {sum(neutral)} of {len(neutral)}")
    for command, _ in commands:
        got = sum(cells[(p, command)][0] == cells[(p, command)][3] for p in names)
        mean = np.mean([cells[(p, command)][2] for p in names])
        print(f"  {command}: {got} of {len(names)}, mean probability of the intended class {mean:.2f}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--amplitude", type=float, default=100, help="percent, for every emotion but Neutral")
    parser.add_argument("--people", type=int, default=len(PEOPLE), help="the first N of the five")
    parser.add_argument("-L", dest="folders", action="append", default=[], help="a folder of library files")
    parser.add_argument("--expressions", help="commands to render, comma-separated (Name or Name=Class)")
    parser.add_argument("--look", default=None, help="a look's name (docs/looks.md)")
    parser.add_argument("--save", type=Path, help="write each still to this folder too")
    args = parser.parse_args()
    commands = _commands(args.expressions)
    if args.save:
        args.save.mkdir(parents=True, exist_ok=True)
    cells = measure(commands, args.amplitude, args.people, args.folders, args.look, args.save)
    print(f"amplitude {args.amplitude:g} %, look {args.look or 'default'}")
    report(cells, commands, args.people)
    return 0


if __name__ == "__main__":
    sys.exit(main())
