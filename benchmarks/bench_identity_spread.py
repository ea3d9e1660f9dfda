#!/usr/bin/env python3
"""Random people to a face recogniser: how far the identity space's shape alone spreads them (issue 32 item 5).

    xvfb-run -a .venv/bin/python benchmarks/bench_identity_spread.py [--seed 7] [--count 10] [--apart]
        [--sheet docs/images/population/random-identities.png] [--no-baseline] [--no-continuum]

Draws ``--count`` people from the population model (``identity --random``, seeds ``seed`` …
``seed + count − 1``; with ``--apart`` the ``count`` furthest apart in shape of 4 × ``count``
draws, as a design's ``apart = true``), makes each head with its rig carried over, and renders
it front on at 640 × 480 with the engine's renderer: neutral, the six emotions of §4 at the
middle of their apex, and eight frames of Festival speaking a sentence. The validation's
observers (``engine.validation``: dlib's face descriptor) then say

* how many pairs of people are different people (descriptor distance ≥ 0.6, dlib's convention),
  the references being each person's neutral face (goal of issue 32: ≥ 90 % of the pairs);
* how many of each person's expressions and speech frames are nearer their own neutral face
  than any other person's (goal: ≥ 95 %);
* along a morph continuum between the first two people, at 0, 25, 50, 75 and 100 %, the
  distance of each step from the start and from the step before (even steps: the same size).

The five hand-made identities of docs/validation.md are measured the same way beside them
(``--no-baseline`` leaves them out). ``--sheet`` writes the contact sheet of the people's
neutral faces. About three minutes on two cores.
"""

from __future__ import annotations

import argparse
import itertools
import sys
import time
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from engine.commands import load_library, parse_commands_text, translate  # noqa: E402
from engine.identity import Identity, make_identity_head, morph  # noqa: E402
from engine.identity.population import draw_identities  # noqa: E402
from engine.outputs.render import FrameRenderer  # noqa: E402
from engine.timeline.timeline import Timeline  # noqa: E402
from engine.validation import Intended, judge_pixels, summarise  # noqa: E402
from engine.validation.observers import SAME_PERSON  # noqa: E402

SIZE = (640, 480)
EMOTIONS = {"Happy": "happy", "Sad": "sad", "Surprise": "surprise", "Fear": "fear", "Anger": "angry",
            "Disgust": "disgust"}
SENTENCE = "Pappa ampui pallon, mamma meni mökille."
SPEECH_FRAMES = 8
HAND_MADE = {
    "man 60 European": {"sex": 1.0, "age": 60, "caucasian": 1.0, "african": 0.0, "asian": 0.0},
    "woman 22 African": {"sex": 0.0, "age": 22, "african": 1.0, "caucasian": 0.0, "asian": 0.0},
    "man 35 Asian": {"sex": 1.0, "age": 35, "asian": 1.0, "caucasian": 0.0, "african": 0.0},
    "woman 45 European": {"sex": 0.0, "age": 45, "caucasian": 1.0, "african": 0.0, "asian": 0.0},
}


def apex_values(expression: str, library, head) -> dict[str, float]:
    """The parameter values in the middle of ``expression``'s apex."""
    commands = parse_commands_text(f'<commands><{expression} at="0"/></commands>')
    timeline = Timeline(translate(commands, library, head), head)
    args = {**library[expression].optional, **commands[0].arguments}
    return timeline.values_at(args.get("at", 0.0) + args["onset"] + args["apex"] / 2)


def speech_poses(head) -> list[dict[str, float]]:
    """The parameter values of SPEECH_FRAMES frames spread over the sentence, spoken by Festival."""
    from engine.speech.say import speak

    speech = speak(SENTENCE, head)
    times = np.linspace(0.1, 0.9, SPEECH_FRAMES) * speech.duration_ms
    return [speech.timeline.values_at(float(t)) for t in times]


def judge_person(label: str, head, library, speech: bool = True) -> tuple[list, np.ndarray]:
    """Verdicts on ``head``'s neutral face, six emotions and speech frames; and the neutral picture."""
    renderer = FrameRenderer(head, size=SIZE, view="front")
    try:
        neutral = renderer.render(head.deform({}))
        verdicts = [judge_pixels(neutral, f"{label}/neutral", Intended("neutral", identity=label))]
        for expression, emotion in EMOTIONS.items():
            picture = renderer.render(head.deform(apex_values(expression, library, head)))
            verdicts.append(judge_pixels(picture, f"{label}/{expression}", Intended(emotion, identity=label)))
        for k, pose in enumerate(speech_poses(head) if speech else []):
            picture = renderer.render(head.deform(pose))
            verdicts.append(judge_pixels(picture, f"{label}/speech-{k}", Intended(None, identity=label)))
    finally:
        renderer.close()
    return verdicts, neutral


def report(title: str, verdicts: list) -> dict[str, float]:
    summary = summarise(verdicts)
    names, distances = summary.identities, np.array(summary.identity_distances)
    pairs = [distances[i, j] for i, j in itertools.combinations(range(len(names)), 2)]
    apart = sum(d >= SAME_PERSON for d in pairs)
    others = [v for v in verdicts if v.intended.emotion != "neutral"]
    found = [v for v in others if v.identity_own is not None]
    own = sum(v.nearest_other_distance is None or v.identity_own < v.nearest_other_distance for v in found)
    lost = sum(v.descriptor is None for v in verdicts)
    print(f"\n{title}: {len(names)} people, {len(verdicts)} pictures ({lost} without a face)")
    print(f"  pairs that are different people (≥ {SAME_PERSON}): {apart} of {len(pairs)} "
          f"({100 * apart / max(1, len(pairs)):.0f} %); distances min {min(pairs):.3f}, "
          f"median {np.median(pairs):.3f}, max {max(pairs):.3f}")
    print(f"  expressions and speech frames nearest their own neutral: {own} of {len(found)} "
          f"({100 * own / max(1, len(found)):.1f} %)")
    for v in sorted(found, key=lambda v: (v.nearest_other_distance or 9) - v.identity_own)[:3]:
        print(f"    closest call: {v.file}: own {v.identity_own:.3f}, nearest other {v.nearest_other} "
              f"{v.nearest_other_distance:.3f}")
    return {"pairs_apart": apart, "pairs": len(pairs), "own": own, "judged": len(found)}


def continuum(a: Identity, b: Identity, library) -> None:
    """Descriptor distances along the morph from ``a`` to ``b`` at 0, 25, 50, 75, 100 %."""
    descriptors = []
    for t in (0.0, 0.25, 0.5, 0.75, 1.0):
        head = make_identity_head(morph(a, b, t))
        verdicts, _ = judge_person(f"{t:.2f}", head, library, speech=False)
        descriptors.append(verdicts[0].descriptor)
    start = [float(np.linalg.norm(d - descriptors[0])) for d in descriptors]
    steps = [float(np.linalg.norm(q - p)) for p, q in itertools.pairwise(descriptors)]
    print(f"\ncontinuum {a.drawn and a.drawn['seed']} → {b.drawn and b.drawn['seed']} at 0/25/50/75/100 %:")
    print("  distance from the start: " + ", ".join(f"{d:.3f}" for d in start))
    print("  each step: " + ", ".join(f"{d:.3f}" for d in steps)
          + f"  (largest / smallest {max(steps) / min(steps):.2f}; mean {np.mean(steps):.3f}, "
            f"sd {np.std(steps):.3f})")


def contact_sheet(pictures: list[tuple[str, np.ndarray]], path: Path) -> None:
    """The neutral faces side by side, five a row, each labelled."""
    tile = (192, 216)
    font = ImageFont.load_default(size=13)
    rows = (len(pictures) + 4) // 5
    sheet = Image.new("RGB", (tile[0] * 5, (tile[1] + 34) * rows), "white")
    draw = ImageDraw.Draw(sheet)
    for k, (label, picture) in enumerate(pictures):
        image = Image.fromarray(picture)
        w, h = image.size
        face = image.crop((int(w * 0.25), int(h * 0.12), int(w * 0.75), int(h * 0.93))).resize(tile, Image.LANCZOS)
        x, y = (k % 5) * tile[0], (k // 5) * (tile[1] + 34)
        sheet.paste(face, (x, y))
        for n, line in enumerate(label.split("\n")):
            draw.text((x + 6, y + tile[1] + 2 + 15 * n), line, fill=(0, 0, 0), font=font)
    path.parent.mkdir(parents=True, exist_ok=True)
    sheet.save(path, optimize=True)


def describe(person: Identity) -> str:
    shares = person.ancestry()
    main = max(shares, key=shares.__getitem__)
    mix = "" if shares[main] > 0.95 else f" {100 * shares[main]:.0f}%"
    sex = "woman" if person.value("sex") < 0.5 else "man"
    seed = person.drawn["seed"] if person.drawn else "?"
    return f"seed {seed}\n{sex} {person.value('age'):.0f}, {main}{mix}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--count", type=int, default=10)
    parser.add_argument("--apart", action="store_true", help="the people furthest apart of 4 × count draws")
    parser.add_argument("--sheet", type=Path, help="write the contact sheet of the neutral faces here")
    parser.add_argument("--no-baseline", action="store_true", help="leave out the five hand-made identities")
    parser.add_argument("--no-continuum", action="store_true", help="leave out the morph continuum")
    args = parser.parse_args()
    started = time.perf_counter()
    library = load_library()
    people = draw_identities(args.count, args.seed, apart=args.apart)
    verdicts, pictures = [], []
    for person in people:
        label = f"seed-{person.drawn['seed'] if person.drawn else '?'}"
        judged, neutral = judge_person(label, make_identity_head(person), library)
        verdicts += judged
        pictures.append((describe(person), neutral))
        print(f"{label}: {describe(person).splitlines()[1]}; {len(person.values)} values", flush=True)
    kind = "apart" if args.apart else "in a row"
    report(f"{args.count} random people (population model {people[0].drawn['population'] if people[0].drawn else '?'}, "
           f"seeds from {args.seed}, {kind})", verdicts)
    if args.sheet:
        contact_sheet(pictures, args.sheet)
        print(f"\ncontact sheet: {args.sheet}")
    if not args.no_baseline:
        from engine import load_model

        hand = []
        for label, values in {"default head": None, **HAND_MADE}.items():
            head = load_model() if values is None else make_identity_head(Identity(values))
            hand += judge_person(label, head, library)[0]
        report("the five hand-made identities (docs/validation.md)", hand)
    if not args.no_continuum and len(people) >= 2:
        continuum(people[0], people[1], library)
    print(f"\n({time.perf_counter() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
