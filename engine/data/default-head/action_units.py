"""The FACS action units of Table 1 on the default head (§3.2), fitted to the artist's poses (§2.2.2).

A stage of ``derive_default_head.py``: :func:`add_action_units` adds one leaf
parameter per row and side of Table 1 (35 parameters; AU25/26/27 is the
existing ``jaw_open``), each fitted by :func:`engine.fitting.fit_parameter` to
the closest reference pose — an ARKit face unit or a MakeHuman expression
unit — and then tuned. :data:`ACTION_UNITS` is the recipe, as data; the
choices and the residuals are in ``docs/default-head.md`` ("Action units").

Value 1 is FACS intensity E, the AU at its maximum (Ekman, Friesen & Hager
2002): where the artist's pose falls short of what FACS shows at E, the pose
is scaled (:data:`E_GAIN`), and the furrows, wrinkles and bulges FACS lists
among the AU's appearance changes are added to it as geometry
(:data:`APPEARANCE`, ``facs_creases.py``). An AU that carries them is a
displacement field (a rotation or a uniform translation cannot hold a
furrow).

Bilateral poses are split across the midline by a smooth mask: the artist's
left and right poses are added (so that the two halves make the bilateral
pose exactly) and the sum is shared out by ``smoothstep((x + w) / 2w)``
(left, +X) and one minus it (right); a left AU moves nothing more than
``w`` = 8 mm to the right of the midline.
"""

from __future__ import annotations

from dataclasses import dataclass

import facs_creases as creases
import numpy as np

MIDLINE_MM = 8.0            # half-width of the left/right mask's ramp across the midline
EYE_BAND_MM = (5.0, 3.0)    # AU9's nose/brow split ramps from this far below to this far above the eye centres
AU9_NOSE_GAIN = 1.7         # the artist's sneer below the eyes, strengthened to FACS's AU9 at E (wings up 2.2-2.4 mm)
SKIN_AND_LASHES = ["skin", "eyelashes_left", "eyelashes_right"]
ARKIT, UNITS = "arkit/", "expression_units/"

# FACS intensity E: the artist's pose scaled where it falls short of the AU at its maximum (the landmark
# motions at E are in docs/default-head.md, "Action units at FACS intensity E", and the tests check them)
E_GAIN = {
    "AU1": 1.6,     # inner brow 5.3 -> 8.5 mm up: the brows' inner ends pulled up high, oblique
    "AU2": 1.25,    # outer brow 6.7 -> 8.4 mm up: the brow arched high at its tail
    "AU4": 1.2,     # brows 5.7 -> 6.8 mm down and 5 -> 6 mm closer: the brow low over the eye
    "AU5": 1.35,    # upper lid 2.9 -> 3.9 mm up: sclera above the iris
    "AU6": 1.4,     # cheek up 8 -> 11 mm: the lower lid pushed up, the eye narrowed
    "AU15": 1.25,   # lip corners 6.1 -> 7.6 mm down
    "AU20": 1.4,    # lip corners 5.1 -> 7.1 mm out each: the mouth stretched wide and flat
}

# FACS's appearance changes as geometry, per parameter (its name without the side): (N, 3) mm for both sides
APPEARANCE = {
    "AU1": lambda skin: creases.forehead_lines(skin, medial=True),
    "AU2": lambda skin: creases.forehead_lines(skin, medial=False),
    "AU4": creases.glabella,
    "AU6": lambda skin: creases.lower_lid_bag(skin) + creases.lower_lid_lift(skin),
    "AU9_nose": lambda skin: creases.nose_root(skin) + creases.nasolabial(skin, depth=1.0, cheek=0.0,
                                                                              upper_only=True),
    "AU10": lambda skin: creases.nasolabial(skin, depth=1.0, cheek=0.5, upper_only=True),
    "AU12": creases.nasolabial,
    "AU15": creases.corner_pouch,
    "AU17": creases.chin_boss,
}


@dataclass(frozen=True)
class ActionUnit:
    """One AU parameter: the pose it is fitted to and how.

    ``sources``: ``(reference pose, factor)`` pairs added to make the pose;
    ``side``: ``"left"``/``"right"`` (the subject's; the midline mask) or
    ``""`` (the whole pose); ``band``: ``"lower"``/``"upper"`` keeps the part
    of the pose below / above the eye centres (AU9's nose and brow);
    ``lips``: the lower lip is kept off the upper lip before the split
    (the artist's mouth poses push it through, see docs/default-head.md);
    ``kind``: ``rotation``, ``translation`` or ``field`` (``engine.fitting``);
    ``gain``: the artist's pose scaled to FACS intensity E (:data:`E_GAIN`).
    """

    name: str
    au: str
    kind: str
    parent: str
    sources: tuple[tuple[str, float], ...]
    side: str = ""
    band: str = ""
    lips: bool = False
    minimum: float = 0.0
    maximum: float = 1.0
    description: str = ""
    gain: float = 1.0

    @property
    def appearance_key(self) -> str:
        """The parameter's name without its side: its entry in :data:`APPEARANCE`."""
        return self.name.replace("_left", "").replace("_right", "")

    @property
    def stored_kind(self) -> str:
        """How the model keeps it: ``kind``, or a field where it carries furrows (:data:`APPEARANCE`): the
        motion is still fitted as ``kind``, and that motion at value 1 with the furrows added is the field."""
        return "field" if self.appearance_key in APPEARANCE else self.kind


def _pair(au, title, kind, parent, sources, suffix="", band="", lips=False, minimum=0.0, what=""):
    """The left and right parameters of a bilateral AU made from ``sources`` (left and right poses)."""
    sources = tuple((s, 1.0) if isinstance(s, str) else s for s in sources)
    return [ActionUnit(f"{au}_{side}{suffix}", au, kind, parent, sources, side=side, band=band, lips=lips,
                       minimum=minimum, description=f"{au} {title}, the subject's {side} side{what}",
                       gain=E_GAIN.get(au, 1.0) if not suffix else 1.0)
            for side in ("left", "right")]


def _one(au, title, kind, parent, sources, name=None, lips=False, what=""):
    sources = tuple((s, 1.0) if isinstance(s, str) else s for s in sources)
    return ActionUnit(name or au, au, kind, parent, sources, lips=lips, description=f"{au} {title}{what}")


ACTION_UNITS: list[ActionUnit] = [
    # the brows slide over the forehead: rotations (§2.2.1)
    *_pair("AU1", "inner brow raiser", "rotation", "head_tilt", [ARKIT + "browInnerUp"]),
    *_pair("AU2", "outer brow raiser", "rotation", "head_tilt",
           [ARKIT + "browOuterUpLeft", ARKIT + "browOuterUpRight"]),
    *_pair("AU4", "brow lowerer", "rotation", "head_tilt", [ARKIT + "browDownLeft", ARKIT + "browDownRight"],
           what=": the brow down and towards the midline"),
    # the lids slide over the eyeball: rotations
    # AU41 (lid droop) is the blink's rotation about the eyeball part way, eyelid_*_close: the artist's
    # eyeWide turns about an axis 11 mm from the eye centre, so below 0 it would push the lid into the eye
    *_pair("AU5", "upper lid raiser", "rotation", "head_tilt", [ARKIT + "eyeWideLeft", ARKIT + "eyeWideRight"],
           what="; the lid droop AU41 is eyelid_<side>_close"),
    *_pair("AU6", "cheek raiser", "translation", "head_tilt", [ARKIT + "cheekSquintLeft", ARKIT + "cheekSquintRight"]),
    *_pair("AU7", "lid tightener", "rotation", "head_tilt", [ARKIT + "eyeSquintLeft", ARKIT + "eyeSquintRight"],
           what=": the lower lid up"),
    # AU9 in two parts: the sneer lifts the nose wing and upper lip and pulls the inner brow down;
    # the nose part at AU9_NOSE_GAIN times the artist's sneer, whose wings rise only 1.3-1.4 mm (docs/default-head.md)
    *_pair("AU9", "nose wrinkler", "field", "head_tilt",
           [(ARKIT + "noseSneerLeft", AU9_NOSE_GAIN), (ARKIT + "noseSneerRight", AU9_NOSE_GAIN)],
           suffix="_nose", band="lower", what=": nose wing, side of the nose and upper lip up"),
    *_pair("AU9", "nose wrinkler", "rotation", "head_tilt", [ARKIT + "noseSneerLeft", ARKIT + "noseSneerRight"],
           suffix="_brow", band="upper", what=": the inner brow down and in"),
    *_pair("AU10", "upper lip raiser", "translation", "head_tilt",
           [ARKIT + "mouthUpperUpLeft", ARKIT + "mouthUpperUpRight"], what=" of the upper lip"),
    _one("AU10", "upper lip raiser", "translation", "head_tilt", [ARKIT + "mouthShrugUpper"], name="AU10_middle",
         what=": the middle of the upper lip"),
    *_pair("AU11", "nasolabial furrow deepener", "translation", "head_tilt",
           [UNITS + "nose-left-elevation", UNITS + "nose-right-elevation"]),
    *_pair("AU12", "lip corner puller", "field", "head_tilt", [ARKIT + "mouthSmileLeft", ARKIT + "mouthSmileRight"],
           lips=True),
    *_pair("AU15", "lip corner depressor", "translation", "jaw_open",
           [ARKIT + "mouthFrownLeft", ARKIT + "mouthFrownRight"]),
    *_pair("AU16", "lower lip depressor", "translation", "jaw_open",
           [ARKIT + "mouthLowerDownLeft", ARKIT + "mouthLowerDownRight"]),
    _one("AU17", "chin raiser", "field", "jaw_open", [ARKIT + "mouthShrugLower", ARKIT + "mouthShrugUpper"],
         lips=True, what=": chin boss and lower lip up, pushing the upper lip up"),
    *_pair("AU20", "lip stretcher", "translation", "head_tilt",
           [ARKIT + "mouthStretchLeft", ARKIT + "mouthStretchRight"]),
    _one("AU23", "lip tightener", "field", "head_tilt",
         [(ARKIT + "mouthRollUpper", 0.3), (ARKIT + "mouthRollLower", 0.4)],
         lips=True, what=": the red of the lips narrowed"),
    *_pair("AU24", "lip presser", "field", "head_tilt", [ARKIT + "mouthPressLeft", ARKIT + "mouthPressRight"],
           lips=True),
    *_pair("AU38", "nostril dilator", "translation", "head_tilt",
           [UNITS + "nose-left-dilatation", UNITS + "nose-right-dilatation"],
           minimum=-1.0, what="; below 0 it compresses the nostril (AU39)"),
]


@dataclass
class ActionUnitFit:
    """An AU parameter as fitted and tuned, with its residual against the artist's pose.

    ``target``: the artist's pose for this parameter (the sources added,
    masked), (N, 3) mm; ``fit``: the :class:`engine.fitting.FitResult` of
    the tuned pose; ``fitted``: what the model's parameter does at value 1
    (its weights and fields rounded as stored), (N, 3) mm; residuals are
    ``target − fitted``. ``appearance`` and ``depth``: the parameter's
    furrows and bulges (:data:`APPEARANCE`), written to ``reference-poses.h5``
    (``/facs_appearance``) for wrinkle maps.
    """

    unit: ActionUnit
    fit: object
    target: np.ndarray
    fitted: np.ndarray
    appearance: np.ndarray | None = None    # the furrows and bulges the parameter carries, (N, 3) mm at value 1
    depth: np.ndarray | None = None         # … along the rest skin's normal, (N,) mm: − a furrow, + a bulge

    @property
    def moved(self) -> np.ndarray:
        return np.linalg.norm(self.target, axis=1) > 1e-9

    @property
    def residual(self) -> np.ndarray:
        return self.target - self.fitted

    @property
    def residual_rms_mm(self) -> float:
        """RMS of |target − fitted| over the vertices the artist's pose moves."""
        r = np.linalg.norm(self.residual[self.moved], axis=1)
        return float(np.sqrt(np.mean(r ** 2)))

    @property
    def residual_max_mm(self) -> float:
        return float(np.linalg.norm(self.residual, axis=1).max())

    @property
    def peak_mm(self) -> float:
        return float(np.linalg.norm(self.target, axis=1).max())

    @property
    def explained(self) -> float:
        return 1.0 - float(np.sum(self.residual ** 2) / np.sum(self.target ** 2))


def smoothstep(t):
    t = np.clip(t, 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def side_mask(x, side: str) -> np.ndarray:
    """The share of a bilateral pose that goes to ``side`` at each x (mm; the subject's left is +X)."""
    left = smoothstep((np.asarray(x, dtype=float) + MIDLINE_MM) / (2 * MIDLINE_MM))
    return {"left": left, "right": 1.0 - left, "": np.ones_like(left)}[side]


def band_mask(y, eye_level: float, band: str) -> np.ndarray:
    """The share below (``lower``) or above (``upper``) the eye centres' height ``eye_level`` (mm)."""
    below, above = EYE_BAND_MM
    upper = smoothstep((np.asarray(y, dtype=float) - (eye_level - below)) / (below + above))
    return {"upper": upper, "lower": 1.0 - upper, "": np.ones_like(upper)}[band]


def source_pose(unit: ActionUnit, pose) -> np.ndarray:
    """The sources of ``unit`` added and scaled to FACS intensity E (``unit.gain``), (N, 3) mm, before the masks."""
    return unit.gain * sum(factor * pose(name) for name, factor in unit.sources)


def appearance(unit: ActionUnit, skin: creases.Skin) -> np.ndarray:
    """The furrows and bulges ``unit`` carries (:data:`APPEARANCE`), on its side of the face, (N, 3) mm;
    the lashes on a lid they move go with it (each as its nearest skin vertex)."""
    make = APPEARANCE.get(unit.appearance_key)
    if make is None:
        return np.zeros_like(skin.vertices)
    return skin.carry_lashes(make(skin) * side_mask(skin.vertices[:, 0], unit.side)[:, None])


def unit_target(unit: ActionUnit, pose, model, D=None, skin: creases.Skin | None = None) -> np.ndarray:
    """What ``unit`` at value 1 is to do, (N, 3) mm: the (tuned) pose ``D`` — by default its sources —
    masked to its side and band, and its appearance changes added."""
    eye_level = float(model.landmark_positions()["3.5"][1])
    D = source_pose(unit, pose) if D is None else D
    skin = skin or creases.Skin.of(model)
    return masked(unit, D, model.vertices, eye_level) + appearance(unit, skin)


def masked(unit: ActionUnit, D, vertices, eye_level: float) -> np.ndarray:
    share = side_mask(vertices[:, 0], unit.side) * band_mask(vertices[:, 1], eye_level, unit.band)
    return D * share[:, None]


def add_action_units(model, pose, lips_apart=None, smoothness: float = 0.01) -> list[ActionUnitFit]:
    """Fit every AU of :data:`ACTION_UNITS` and add it to ``model`` (leaves, in table order).

    ``pose(name)``: a reference pose as (N, 3) mm on the model's vertices.
    ``lips_apart(D, others)``: ``D`` with the lower lip kept off the upper
    lip, alone and added to each pose of ``others`` (the bilateral poses of
    the lip AUs before it, so that they combine too), for the AUs marked
    ``lips`` (the derivation's lip-contact check; ``None`` leaves the poses
    as the artist made them).
    """
    from engine import InfluenceRegion
    from engine.fitting import fit_parameter

    skin = creases.Skin.of(model)
    eye_level = float(model.landmark_positions()["3.5"][1])
    tuned: dict[tuple, np.ndarray] = {}
    out = []
    for unit in ACTION_UNITS:
        artist = source_pose(unit, pose)
        D = artist
        if unit.lips and lips_apart is not None:
            key = (unit.sources, unit.gain)
            if key not in tuned:          # both sides share one tuning of the bilateral pose
                tuned[key] = lips_apart(artist, list(tuned.values()))
            D = tuned[key]
        options = dict(name=unit.name, parent=unit.parent, region=SKIN_AND_LASHES, smoothness=smoothness,
                       value_range=(unit.minimum, unit.maximum), description=unit.description)
        D = masked(unit, D, model.vertices, eye_level)
        if unit.kind == "field":
            fit = fit_parameter(model, D + appearance(unit, skin), "field", **options)
        else:
            fit = fit_parameter(model, D, unit.kind, **options)
            if unit.stored_kind == "field":       # the fitted motion, smooth as before, and its furrows
                fit = fit_parameter(model, fit.fitted + appearance(unit, skin), "field", **options)
        region = fit.region
        fit.region = InfluenceRegion(region.indices, np.round(region.weights, 6),      # as the file keeps them
                                     None if region.displacements is None else np.round(region.displacements, 4))
        fit.apply(model)
        keep_off_eyeballs(model, unit.name)
        fitted = model.deform({unit.name: 1.0}) - model.deform()
        extra = appearance(unit, skin)
        out.append(ActionUnitFit(unit, fit, unit_target(unit, pose, model, artist, skin), fitted,
                                 extra, np.einsum("ij,ij->i", extra, skin.normals)))
    return out


def keep_off_eyeballs(model, name: str, clearance: float = 0.05) -> int:
    """Lower the weights of the vertices that ``name`` at its minimum or maximum would push into an eyeball.

    Eq. 1 is linear in the weight, so a vertex outside an eyeball (radius
    ``r`` about the centre of its gaze rotation) at rest stays ``clearance``
    mm outside it (or keeps half its gap, when closer) when its weight is at
    most the first root of ``|P − c + w·m|² = (r + clearance)²``, ``m`` its
    motion at full weight.
    The artist's cheek raiser, for one, lifts a few lower lashes 0.2 mm into
    the eye. Returns the number of weights lowered.
    """
    from engine import InfluenceRegion

    p, region = model.parameters[name], model.regions[name]
    P = model.vertices[region.indices]
    w = region.weights.copy()
    for side in ("left", "right"):
        centre = model.parameters[f"eye_{side}_turn"].pivot
        eyeball = np.linalg.norm(model.vertices[model.part_vertices(f"eye_{side}")] - centre, axis=1).max()
        rest = np.linalg.norm(P - centre, axis=1)
        radius = np.minimum(eyeball + clearance, (eyeball + rest) / 2)    # those already closer keep half their gap
        for value in (p.minimum, p.maximum):
            if value == 0.0:
                continue
            if p.field:
                m = value * region.displacements
            else:
                T = p.transform(value)
                m = P @ T[:3, :3] + T[3, :3] - P
            a = P - centre
            A, B, C = (m * m).sum(axis=1), 2 * (a * m).sum(axis=1), (a * a).sum(axis=1) - radius ** 2
            disc = B * B - 4 * A * C
            enters = (C > 0) & (A > 0) & (B < 0) & (disc > 0)
            root = np.full(len(P), np.inf)
            root[enters] = (-B[enters] - np.sqrt(disc[enters])) / (2 * A[enters])
            w = np.minimum(w, np.floor(root * 1e6) / 1e6)
    lowered = int(np.sum(w < region.weights))
    if lowered:
        model.set_region(name, InfluenceRegion(region.indices, w, region.displacements))
    return lowered
