"""Long texts: ``say`` to WAV on 1, 4, 16 and 64 sentences, side by side with Festival alone.

Each size runs in a fresh interpreter (so its peak memory is its own) and is
reported with:

* ``say``: the whole pipeline to a WAV file (Festival, articulation with
  coarticulation, the timeline, the phones table), wall-clock seconds and
  peak resident memory;
* the floor, Festival's own ``text2wave`` on the same text (what nothing can
  beat: the synthesizer that makes the audio);
* Festival given the whole text as one utterance (how ``say`` called it before
  issue 16 §3), to show what utterance-by-utterance synthesis saves.

Time and memory must grow linearly: 16× the text, about 16× the time.

    .venv/bin/python benchmarks/bench_long_texts.py [--sizes 1 4 16 64] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SENTENCE = "Pappa ampui pallon, ja Maija meni kotiin kauniina kesäpäivänä."

_SAY = """
import resource, sys, time
from engine import load_model
from engine.speech.say import speak
from engine.speech.synthesis import write_wav, write_phones_csv
text = open(sys.argv[1], encoding="utf-8").read()
model = load_model()
started = time.perf_counter()
speech = speak(text, model)
write_wav(sys.argv[2] + ".wav", speech.utterance)
write_phones_csv(sys.argv[2] + ".csv", speech.utterance)
print(time.perf_counter() - started, speech.duration_ms / 1000,
      resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
"""


def _child_peak_mb() -> float:
    return resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024


def measure(sentences: int, folder: Path) -> dict:
    text = " ".join([SENTENCE] * sentences)
    source = folder / f"text-{sentences}.txt"
    source.write_text(text, encoding="utf-8")
    out = subprocess.run([sys.executable, "-c", _SAY, str(source), str(folder / f"say-{sentences}")],
                         capture_output=True, text=True, check=True)
    say_s, audio_s, say_mb = (float(v) for v in out.stdout.split())

    latin1 = source.with_suffix(".latin1")
    latin1.write_bytes(text.encode("latin-1"))                  # what Festival reads
    started = time.perf_counter()
    subprocess.run(["text2wave", "-eval", "(voice_suo_fi_lj_diphone)", str(latin1), "-o", str(folder / "floor.wav")],
                   check=True, capture_output=True)
    floor_s = time.perf_counter() - started

    script = folder / "one.scm"
    script.write_bytes(('(voice_suo_fi_lj_diphone)\n(set! u (utt.synth (Utterance Text "'
                        + text.replace('"', '\\"') + '")))\n(utt.save.wave u "one.wav")\n').encode("latin-1"))
    before = _child_peak_mb()
    started = time.perf_counter()
    subprocess.run(["festival", "--batch", str(script)], cwd=folder, check=True, capture_output=True)
    one_s = time.perf_counter() - started
    one_mb = max(_child_peak_mb(), before)
    return {"sentences": sentences, "audio_s": audio_s, "say_s": say_s, "say_peak_mb": say_mb,
            "text2wave_s": floor_s, "one_utterance_festival_s": one_s, "children_peak_mb": one_mb}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1, 4, 16, 64])
    parser.add_argument("--json", type=Path)
    args = parser.parse_args(argv)
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for size in args.sizes:
            rows.append(measure(size, Path(folder)))
            row = rows[-1]
            print(f"{size:3d} sentences, {row['audio_s']:6.1f} s of speech: say {row['say_s']:6.2f} s "
                  f"(peak {row['say_peak_mb']:5.0f} MB) | text2wave (floor) {row['text2wave_s']:6.2f} s | "
                  f"Festival, one utterance {row['one_utterance_festival_s']:6.2f} s", flush=True)
    base = rows[0]
    for row in rows[1:]:
        factor = row["sentences"] / base["sentences"]
        print(f"{factor:4.0f}× the text: say {row['say_s'] / base['say_s']:5.1f}× the time, "
              f"{row['say_peak_mb'] / base['say_peak_mb']:4.1f}× the memory")
    if args.json:
        args.json.write_text(json.dumps(rows, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
