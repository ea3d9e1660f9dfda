"""Making a head for an identity: the default head's mesh moved by the identity's targets, its rig carried over.

>>> from engine.identity import Identity, make_identity_head
>>> head = make_identity_head(Identity({"sex": 1.0, "age": 60}))
>>> head.identity.value("age"), head.n_vertices == make_identity_head(Identity()).n_vertices
(60.0, True)
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from functools import cache

import numpy as np
from scipy.spatial import cKDTree

from engine.identity.articulation_refit import refit_articulation
from engine.identity.carry_over import Similarity, carry_rig_over, similarity
from engine.identity.errors import IdentityError
from engine.identity.hair_style import HairChoice
from engine.identity.parameters import Identity
from engine.identity.rest_fit import (
    keep_eyelid_clearance,
    keep_fields_off_the_eyes,
    keep_lids_off_the_eyes,
    keep_mouth_bag_inside,
    keep_rest_lip_gap,
    line_fields_with_the_skin,
    refit_eyelid_angles,
)
from engine.identity.rest_lids import lowered_lids
from engine.identity.skin import apply_skin
from engine.identity.targets import IdentityTargets, shipped_targets
from engine.identity.weights import identity_displacement
from engine.model import Model
from engine.paths import reference_poses_path

GENERATED_NEIGHBOURS = 8      # made vertices (not MakeHuman's) follow this many nearest MakeHuman vertices


@cache
def default_head_sources() -> np.ndarray:
    """For each default-head vertex, its MakeHuman hm08 index (−1 for vertices the derivation made)."""
    import h5py

    with h5py.File(reference_poses_path(), "r") as f:
        return np.asarray(f["source_vertex"][()], dtype=np.int64)


@cache
def _default_head() -> Model:
    from engine.formats.model_files import load_model

    return load_model()


def identity_vertex_displacement(model: Model, identity: Identity,
                                 targets: IdentityTargets | None = None) -> tuple[np.ndarray, dict[str, Similarity]]:
    """(n, 3) mm that move ``model`` (the default head's vertices) to ``identity``, and the eyes' motions."""
    targets = targets or shipped_targets()
    source = default_head_sources()
    if model.n_vertices != len(source):
        raise IdentityError(f"identities are made on the default head's mesh ({len(source)} vertices); "
                            f"this model has {model.n_vertices}")
    made = source < 0
    pos = np.searchsorted(targets.hm08_vertex, source[~made])
    pos = np.minimum(pos, len(targets.hm08_vertex) - 1)
    if not np.array_equal(targets.hm08_vertex[pos], source[~made]):
        raise IdentityError("the identity targets file does not cover the default head's vertices",
                            file=targets.path)
    D_kept = identity_displacement(identity, targets)
    D = np.zeros((model.n_vertices, 3))
    D[~made] = D_kept[pos]
    skin = model.vertex_part[~made] == model.parts.index("skin") if "skin" in model.parts else slice(None)
    offset = np.median((model.vertices[~made] - targets.rest[pos])[skin], axis=0)   # MakeHuman frame → ours
    rigid: dict[str, Similarity] = {}
    for part, helper in targets.eye_helpers.items():
        if part in model.parts:
            rest_h = targets.rest[helper] + offset
            rigid[part] = similarity(rest_h, rest_h + D_kept[helper])
    D = keep_rest_lip_gap(model, keep_mouth_bag_inside(model, D))
    rigid = keep_eyelid_clearance(_skin_as_made(model, targets.rest[pos] + offset, ~made), D, rigid)
    for part, move in rigid.items():
        idx = model.part_vertices(part)
        D[idx] = move.point(model.vertices[idx]) - model.vertices[idx]
        made[idx] = False
    if made.any():      # other made vertices (an inner mouth, say) follow their nearest MakeHuman vertices
        known = np.flatnonzero(source >= 0)
        dist, near = cKDTree(model.vertices[known]).query(model.vertices[made], k=GENERATED_NEIGHBOURS)
        w = 1.0 / np.maximum(dist, 1e-6) ** 2
        D[made] = np.einsum("mk,mkd->md", w / w.sum(axis=1, keepdims=True), D[known[near]])
    # a relaxed rest lid: the upper lid lowered along the blink where it leaves the iris's top bare (rest_lids.py)
    moved, _ = lowered_lids(model, model.vertices + D, rigid)
    return moved - model.vertices, rigid


AS_MADE_MM = 2.0          # skin within this of MakeHuman's own place is taken back there for the eyes' clearance


def _skin_as_made(model: Model, made_rest: np.ndarray, kept: np.ndarray) -> Model:
    """``model`` with its skin where MakeHuman made it (``made_rest`` for the ``kept`` vertices), where
    it is within :data:`AS_MADE_MM` of it: the default head's lowered rest lids (rest_lids.py) taken
    back, so that each eyeball is fitted to the lids the identity's targets were made on.

    The result does not depend on the identity, only on the model and the targets, so it is kept for
    the next identity of the same model (a photo fit makes some sixty); the caller must not change it.
    """
    key = hashlib.blake2b(model.vertices.tobytes() + made_rest.tobytes() + kept.tobytes()
                          + model.vertex_part.tobytes() + "\0".join(model.parts).encode(), digest_size=16).digest()
    if key in _AS_MADE:
        return _AS_MADE[key]
    idx = np.flatnonzero(kept)
    is_skin = model.vertex_part[idx] == model.parts.index("skin") if "skin" in model.parts else np.ones(len(idx), bool)
    off = np.linalg.norm(model.vertices[idx] - made_rest, axis=1)
    back = is_skin & (off > 0) & (off < AS_MADE_MM)
    if not back.any():
        return model
    out = model.copy()
    out.vertices[idx[back]] = made_rest[back]
    out.changed()
    while len(_AS_MADE) >= AS_MADE_KEPT:
        del _AS_MADE[next(iter(_AS_MADE))]
    _AS_MADE[key] = out
    return out


AS_MADE_KEPT = 4          # models whose as-made skin is kept (the default head and a few others)
_AS_MADE: dict[bytes, Model] = {}


def make_identity_head(identity: Identity, base: Model | None = None,
                       between_stages: Callable[[], object] | None = None, hair: HairChoice | None = None) -> Model:
    """The head of ``identity``: ``base`` (the default head by default) reshaped, its rig carried over.

    ``base`` must have the default head's vertices and no identity of its own
    (a default head whose rig was edited keeps its edits). The result carries
    ``identity`` and is named after it. ``between_stages()`` is called before each of the
    build's stages; an exception it raises ends the build (how a photo fit is stopped part-way).
    ``hair`` (:mod:`engine.identity.hair`): brows, scalp and facial hair grown on the finished head; a
    random person's (``identity.drawn``) is the hair drawn with it (population_hair.drawn_hair) unless given.
    """
    checkpoint = between_stages if between_stages is not None else (lambda: None)
    base = base if base is not None else _default_head()
    if getattr(base, "identity", None) is not None and base.identity != Identity():
        raise IdentityError("this model already is an identity; make identities from the default head")
    D, rigid = identity_vertex_displacement(base, identity)
    checkpoint()
    head = carry_rig_over(base, base.vertices + D, rigid)
    if identity != Identity():
        for stage in (lambda: line_fields_with_the_skin(base, head), lambda: refit_articulation(base, head),
                      lambda: refit_eyelid_angles(base, head), lambda: keep_fields_off_the_eyes(head),
                      lambda: keep_lids_off_the_eyes(head)):
            checkpoint()
            stage()
    head.identity = identity
    apply_skin(head, identity)          # the person's own skin (engine.identity.skin; docs/skin.md)
    head.name = identity_name(identity)
    head.description = (f"{base.description} Identity: "
                        + (", ".join(f"{k}={v:g}" for k, v in identity.values.items()) or "the default head") + ".")
    if hair is None and identity.drawn is not None:     # a random person has the hair it was drawn with
        from engine.identity.population_hair import drawn_hair

        hair = drawn_hair(identity)
    if hair is not None:
        from engine.identity.hair import add_hair

        head = add_hair(head, hair)
    return head


def identity_name(identity: Identity) -> str:
    """A short model name for an identity, e.g. ``person-sex1-age60``."""
    parts = [f"{k.split('-')[0]}{v:.3g}" for k, v in list(identity.values.items())[:4]]
    return "-".join(["person", *parts]) if parts else "default-head"


def identity_vertices(identity: Identity, base: Model | None = None) -> np.ndarray:
    """Only the rest vertices of ``identity``'s head (no rig carried over): a fast preview while a slider moves.

    About 10 ms on the default head, against a few hundred for :func:`make_identity_head`.
    """
    base = base if base is not None else _default_head()
    D, _ = identity_vertex_displacement(base, identity)
    return base.vertices + D
