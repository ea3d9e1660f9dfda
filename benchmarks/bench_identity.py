#!/usr/bin/env python3
"""A new identity with the rig carried over, beside loading the default head (issue 18: goal < 1 s).

    .venv/bin/python benchmarks/bench_identity.py

Times, median of 5 in one process each: loading the default head from its
files (the floor: what any model costs to open), making an identity's head
(``make_identity_head``: targets, rig carried over, lip closure and eyelids
refitted), and the rest-shape preview a slider drag uses
(``identity_vertices``). The identity's cost by face modifiers set (1, 4, 16)
shows that it grows with the work.
"""

import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from engine import load_model
from engine.identity import Identity, identity_parameters, identity_vertices, make_identity_head


def median_ms(fn, repeats=5):
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        times.append((time.perf_counter() - t) * 1000)
    return statistics.median(times)


def main() -> int:
    base = load_model()
    person = Identity({"sex": 1.0, "age": 60, "caucasian": 1.0, "african": 0.0, "asian": 0.0})
    make_identity_head(person, base)            # the targets file is read once per process
    print(f"load the default head (floor)        {median_ms(load_model):7.1f} ms")
    print(f"make an identity, rig carried over   {median_ms(lambda: make_identity_head(person, base)):7.1f} ms")
    print(f"rest-shape preview (slider drag)     {median_ms(lambda: identity_vertices(person, base), 20):7.1f} ms")
    modifiers = [p.name for p in identity_parameters() if p.group != "macro" and "." not in p.name]
    for n in (1, 4, 16):
        ident = Identity({**person.values, **dict.fromkeys(modifiers[:n], 0.3)})
        ms = median_ms(lambda i=ident: make_identity_head(i, base))
        ms = median_ms(lambda i=ident: make_identity_head(i, base))
        print(f"  with {n:2d} face modifiers             {ms:7.1f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
