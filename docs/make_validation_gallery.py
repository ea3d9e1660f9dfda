#!/usr/bin/env python3
"""The shipped emotions on five people, judged by ``validate``: the figures of docs/validation.md.

    .venv/bin/python docs/make_validation_gallery.py [--keep FOLDER] [--look NAME] [--out FOLDER]
                                                                          (from the project root)

Renders Neutral and the six emotions of the paper's evaluation (§4: Happy, Sad, Surprise, Fear,
Anger, Disgust) at the middle of their apex, front view, 640 × 480, on the default head and
four identities (a man of 60, European; a woman of 22, African; a man of 35, Asian; a woman of
45, European), writes the stills and their ``--intended`` table to a folder (temporary unless
``--keep``), runs ``artificial-person validate`` on them, and writes to ``docs/images/validation/``:

``contact-sheet.jpg``    the 35 stills, each labelled with the emotion meant and the one judged;
``report.png``           the HTML report's first screen, as Chromium shows it;
``validation.csv``, ``validation-confusion.csv``, ``validation-identities.csv``  the tables.

``--look`` renders in another look (docs/looks.md; default: the renderer's default), ``--out`` writes
the pictures and tables to another folder than ``docs/images/validation/`` (to compare looks without
touching the docs' figures). About two minutes on two cores.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from PIL import Image, ImageDraw, ImageFont

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import engine  # noqa: E402
from engine.commands import load_library, parse_commands_text, translate  # noqa: E402
from engine.identity import Identity, make_identity_head  # noqa: E402
from engine.outputs.render import FrameRenderer  # noqa: E402
from engine.timeline.timeline import Timeline  # noqa: E402

OUT = ROOT / "docs" / "images" / "validation"
EXPRESSIONS = ["Neutral", "Happy", "Sad", "Surprise", "Fear", "Anger", "Disgust"]
PEOPLE = {
    "default head": None,
    "man 60 European": {"sex": 1.0, "age": 60, "caucasian": 1.0, "african": 0.0, "asian": 0.0},
    "woman 22 African": {"sex": 0.0, "age": 22, "african": 1.0, "caucasian": 0.0, "asian": 0.0},
    "man 35 Asian": {"sex": 1.0, "age": 35, "asian": 1.0, "caucasian": 0.0, "african": 0.0},
    "woman 45 European": {"sex": 0.0, "age": 45, "caucasian": 1.0, "african": 0.0, "asian": 0.0},
}
SIZE = (640, 480)
TILE = (200, 200)


def apex_values(script: str, library, head) -> dict[str, float]:
    """Parameter values in the middle of the apex of the one command of ``script``."""
    commands = parse_commands_text(f"<commands>{script}</commands>")
    timeline = Timeline(translate(commands, library, head), head)
    command = commands[0]
    args = {**library[command.name].optional, **command.arguments}
    begin = args.get("at", 0.0) + args["onset"]
    return timeline.values_at(begin + args["apex"] / 2)


def render_stills(folder: Path, look=None) -> None:
    library = load_library()
    lines = ["file,emotion,identity"]
    for person, values in PEOPLE.items():
        head = engine.load_model() if values is None else make_identity_head(Identity(values))
        renderer = FrameRenderer(head, size=SIZE, view="front", look=look)
        try:
            for expression in EXPRESSIONS:
                pose = apex_values(f'<{expression} at="0"/>', library, head)
                name = f"{person.replace(' ', '-')}_{expression}.png"
                Image.fromarray(renderer.render(head.deform(pose))).save(folder / name)
                lines.append(f"{name},{expression},{person}")
        finally:
            renderer.close()
        print(f"rendered {person}", flush=True)
    (folder / "intended.csv").write_text("\n".join(lines) + "\n")


def contact_sheet(folder: Path, table: Path, path: Path) -> None:
    import csv

    rows = {Path(r["file"]).name: r for r in csv.DictReader(table.open())}
    font = ImageFont.load_default(size=14)
    people = list(PEOPLE)
    sheet = Image.new("RGB", (150 + TILE[0] * len(EXPRESSIONS), 30 + (TILE[1] + 20) * len(people)), "white")
    draw = ImageDraw.Draw(sheet)
    for j, expression in enumerate(EXPRESSIONS):
        draw.text((150 + j * TILE[0] + 6, 8), expression, fill=(0, 0, 0), font=font)
    for i, person in enumerate(people):
        y = 30 + i * (TILE[1] + 20)
        draw.text((6, y + TILE[1] // 2), person, fill=(0, 0, 0), font=font)
        for j, expression in enumerate(EXPRESSIONS):
            name = f"{person.replace(' ', '-')}_{expression}.png"
            image = Image.open(folder / name)
            w, h = image.size
            face = image.crop((w * 0.25, h * 0.18, w * 0.75, h * 0.85)).resize(TILE, Image.LANCZOS)
            sheet.paste(face, (150 + j * TILE[0], y))
            row = rows[name]
            good = row["read_as_intended"] == "yes"
            text = f"{row['judged_emotion']} {float(row['judged_probability'] or 0):.2f}"
            draw.text((150 + j * TILE[0] + 6, y + TILE[1] + 2), text, font=font,
                      fill=(0, 120, 0) if good else (180, 0, 0))
    sheet.save(path, quality=88, optimize=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--keep", type=Path, help="keep the stills in this folder")
    parser.add_argument("--look", default=None, help="the look to render in (portrait, flat, legacy, or a JSON "
                                                     "file of a look's settings)")
    parser.add_argument("--out", type=Path, default=OUT, help="where the sheet, report and tables go")
    args = parser.parse_args()
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as name:
        folder = args.keep or Path(name)
        folder.mkdir(parents=True, exist_ok=True)
        from engine.outputs.looks import look_option

        render_stills(folder, look_option(args.look) if args.look else None)
        table, report = out / "validation.csv", folder / "report.html"
        stills = sorted(str(p) for p in folder.glob("*.png"))
        done = subprocess.run([sys.executable, "-m", "engine", "validate", *stills, "--intended",
                               str(folder / "intended.csv"), "--report", str(report), "-o", str(table)],
                              capture_output=True, text=True, check=False)
        print(done.stdout, done.stderr, end="")
        if done.returncode != 0:
            return done.returncode
        _relative_files(table, folder)
        contact_sheet(folder, table, out / "contact-sheet.jpg")
        chromium = shutil.which("chromium")
        if chromium:
            subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                            "--disable-background-networking", "--disable-component-update", "--disable-sync",
                            f"--screenshot={out / 'report.png'}", "--window-size=1150,1500",
                            report.as_uri()], capture_output=True, timeout=120, check=False)
    return 0


def _relative_files(table: Path, folder: Path) -> None:
    """The table names the stills by file name only (the folder was temporary)."""
    text = table.read_text().replace(f"{folder}/", "")
    table.write_text(text)


if __name__ == "__main__":
    sys.exit(main())
