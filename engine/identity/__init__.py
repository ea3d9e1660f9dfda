"""Faces of many people: an identity space on the default head, with the rig carried over.

An :class:`Identity` names a person by MakeHuman's macro parameters (sex,
age, ancestry, muscle, weight) and its face modifiers (about 180 of them:
nose, mouth, eyes, chin …). :func:`make_identity_head` makes that person's
head on the default head's vertices, with every pivot, axis and displacement
field of the rig moved with the face (:mod:`engine.identity.carry_over`), so
the same parameter values make the same expression and the same speech on
every identity. :func:`morph` blends two identities; the result is again an
identity. The shape targets are MakeHuman's (CC0), cut to the head by
``engine/data/identity/derive_identity_targets.py``.

>>> from engine.identity import Identity, make_identity_head, morph
>>> a, b = Identity({"sex": 0.0, "age": 30}), Identity({"sex": 0.8, "age": 70, "african": 1.0})
>>> middle = make_identity_head(morph(a, b, 0.5))
>>> sorted(middle.identity.values)
['african', 'age', 'sex']
"""

from engine.identity.build import identity_name, identity_vertices, make_identity_head
from engine.identity.errors import IdentityError
from engine.identity.parameters import (
    Identity,
    IdentityParameter,
    continuum,
    identity_parameter,
    identity_parameters,
    morph,
    parse_assignments,
)

__all__ = ["Identity", "IdentityError", "IdentityParameter", "continuum", "identity_name", "identity_parameter",
           "identity_parameters", "identity_vertices", "make_identity_head", "morph", "parse_assignments"]
