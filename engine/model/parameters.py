"""Parameters and the parameter tree (§2.2).

A parameter is one degree of freedom of the face: a **rotation** about an axis
through a pivot (``value × degrees_per_unit`` degrees) or a **translation**
(``value × direction`` mm, or, for a blendshape, ``value ×`` a per-vertex
displacement field stored with the parameter's influence region).

Parameters form a tree. Non-leaf parameters are *group 1* (rigid motion:
head, jaw, eyes), leaves are *group 2* (everything else); the group is a
consequence of the tree, exactly as in the paper, so it changes when children
are added or removed.

>>> tree = ParameterTree([
...     Parameter("head_nod", "rotation", axis=(1, 0, 0), pivot=(0, 0, 0)),
...     Parameter("jaw_open", "rotation", parent="head_nod", axis=(1, 0, 0), pivot=(0, 60, 60)),
... ])
>>> tree.group("head_nod"), tree.group("jaw_open")
(1, 2)
"""

from __future__ import annotations

import re
from collections.abc import Collection, Iterable, Iterator
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import numpy.typing as npt

from engine.deform.transforms import rotation_about_axis, translation
from engine.errors import ParameterError

ROTATION = "rotation"
TRANSLATION = "translation"
KINDS = (ROTATION, TRANSLATION)
NAME_PATTERN = re.compile(r"[A-Za-z_][A-Za-z0-9_.\-]*")   # as in engine/formats/schemas/model.xsd


@dataclass
class Parameter:
    """One animation parameter.

    Attributes
    ----------
    name : str
        Unique identifier, e.g. ``"jaw_open"``.
    kind : ``"rotation"`` or ``"translation"``
    parent : str or None
        Parent in the tree; ``None`` for a root.
    minimum, maximum, default : float
        Value range and rest value (dimensionless activation).
    axis : (3,) array
        Rotation axis (normalised on construction); rotations only.
    pivot : (3,) array
        A point on the rotation axis, mm; rotations only.
    degrees_per_unit : float
        Rotation angle in degrees for value 1.
    direction : (3,) array
        Translation in mm for value 1 (uniform translations).
    field : bool
        True for a translation carrying a per-vertex displacement field (a
        blendshape); the field lives in the influence region and ``direction``
        is unused. Field translations are not rigid, so they must be leaves.
    description : str
        Free text shown to users.
    """

    name: str
    kind: str
    parent: str | None = None
    minimum: float = -1.0
    maximum: float = 1.0
    default: float = 0.0
    axis: np.ndarray = field(default_factory=lambda: np.array([1.0, 0.0, 0.0]))
    pivot: np.ndarray = field(default_factory=lambda: np.zeros(3))
    degrees_per_unit: float = 1.0
    direction: np.ndarray = field(default_factory=lambda: np.zeros(3))
    field: bool = False
    description: str = ""

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not NAME_PATTERN.fullmatch(self.name):
            raise ParameterError(
                f"parameter name {self.name!r} is not allowed: use letters, digits, '_', '.' and '-', "
                "starting with a letter or '_'")
        if self.kind not in KINDS:
            raise ParameterError(f"parameter '{self.name}': type must be rotation or translation, not '{self.kind}'")
        self.minimum, self.maximum, self.default = float(self.minimum), float(self.maximum), float(self.default)
        self.degrees_per_unit = float(self.degrees_per_unit)
        self.axis = _vector(self.axis, self.name, "axis")
        self.pivot = _vector(self.pivot, self.name, "pivot")
        self.direction = _vector(self.direction, self.name, "direction")
        if not all(np.isfinite([self.minimum, self.maximum, self.default, self.degrees_per_unit])):
            raise ParameterError(f"parameter '{self.name}': range, default and scale must be finite numbers")
        if self.minimum > self.maximum:
            raise ParameterError(f"parameter '{self.name}': minimum {self.minimum:g} is above maximum {self.maximum:g}")
        if not self.minimum <= self.default <= self.maximum:
            raise ParameterError(
                f"parameter '{self.name}': default {self.default:g} is outside its range "
                f"[{self.minimum:g}, {self.maximum:g}]")
        if self.kind == ROTATION:
            norm = np.linalg.norm(self.axis)
            if norm == 0:
                raise ParameterError(f"parameter '{self.name}': rotation axis is the zero vector")
            if abs(norm - 1.0) > 1e-12:     # normalise once, so that copies and reloads stay bit-identical
                self.axis = self.axis / norm
        if self.field and self.kind != TRANSLATION:
            raise ParameterError(f"parameter '{self.name}': only translations can carry a displacement field")

    def transform(self, value: float) -> np.ndarray:
        """The parameter's own 4×4 matrix ``T(v)`` (row convention, §2.2).

        For a field translation this is the identity: its motion is per-vertex
        and applied by the deformer, not by a matrix.
        """
        if value == 0.0:
            return np.eye(4)
        if self.kind == ROTATION:
            return rotation_about_axis(self.axis, self.pivot, value * self.degrees_per_unit)
        if self.field:
            return np.eye(4)
        return translation(value * self.direction)

    def copy(self, **changes: Any) -> Parameter:
        """A copy with some attributes changed (arrays are copied)."""
        base = replace(self, axis=self.axis.copy(), pivot=self.pivot.copy(), direction=self.direction.copy())
        return replace(base, **changes) if changes else base


def _vector(value: npt.ArrayLike, name: str, what: str) -> np.ndarray:
    try:
        v = np.array(value, dtype=float).reshape(3)
    except (TypeError, ValueError):
        raise ParameterError(f"parameter '{name}': {what} must be three numbers") from None
    if not np.all(np.isfinite(v)):
        raise ParameterError(f"parameter '{name}': {what} must be finite")
    return v


class ParameterTree:
    """An ordered collection of parameters linked by ``parent`` names.

    The order is the order of definition; :meth:`topological` gives parents
    before children. The tree is validated on construction and after every
    edit: names unique, parents exist, no cycles, field translations are leaves.
    """

    def __init__(self, parameters: Iterable[Parameter] = ()):
        self._params: dict[str, Parameter] = {}
        for p in parameters:
            if p.name in self._params:
                raise ParameterError(f"parameter '{p.name}' is defined twice")
            self._params[p.name] = p
        self._validate()

    # -- queries ---------------------------------------------------------
    def __iter__(self) -> Iterator[Parameter]:
        return iter(self._params.values())

    def __len__(self) -> int:
        return len(self._params)

    def __contains__(self, name: object) -> bool:
        return name in self._params

    def __getitem__(self, name: str) -> Parameter:
        try:
            return self._params[name]
        except KeyError:
            raise ParameterError(f"unknown parameter '{name}'{_suggest(name, self._params)}") from None

    @property
    def names(self) -> list[str]:
        return list(self._params)

    def children(self, name: str) -> list[str]:
        return [p.name for p in self._params.values() if p.parent == name]

    def roots(self) -> list[str]:
        return [p.name for p in self._params.values() if p.parent is None]

    def is_leaf(self, name: str) -> bool:
        self[name]
        return not any(p.parent == name for p in self._params.values())

    def group(self, name: str) -> int:
        """1 for non-leaf (rigid) parameters, 2 for leaves (§2.2)."""
        return 2 if self.is_leaf(name) else 1

    def ancestors(self, name: str) -> list[str]:
        """Parent, grandparent, … up to the root."""
        out, p = [], self[name].parent
        while p is not None:
            out.append(p)
            p = self._params[p].parent
        return out

    def topological(self) -> list[str]:
        """Names with every parent before its children (stable otherwise)."""
        done: list[str] = []
        seen: set[str] = set()

        def visit(n: str) -> None:
            if n in seen:
                return
            parent = self._params[n].parent
            if parent is not None:
                visit(parent)
            seen.add(n)
            done.append(n)

        for n in self._params:
            visit(n)
        return done

    def depth_first(self) -> list[tuple[str, int]]:
        """(name, depth) from each root down, children in definition order (the tree as shown to users)."""
        out: list[tuple[str, int]] = []

        def visit(name: str, depth: int) -> None:
            out.append((name, depth))
            for child in self.children(name):
                visit(child, depth + 1)

        for root in self.roots():
            visit(root, 0)
        return out

    def copy(self) -> ParameterTree:
        return ParameterTree(p.copy() for p in self._params.values())

    # -- edits -----------------------------------------------------------
    def add(self, parameter: Parameter) -> None:
        if parameter.name in self._params:
            raise ParameterError(f"parameter '{parameter.name}' already exists")
        self._params[parameter.name] = parameter
        try:
            self._validate()
        except ParameterError:
            del self._params[parameter.name]
            raise

    def remove(self, name: str) -> Parameter:
        """Remove a parameter; its children move up to its parent."""
        removed = self[name]
        for p in self._params.values():
            if p.parent == name:
                p.parent = removed.parent
        del self._params[name]
        return removed

    def replace(self, parameter: Parameter) -> None:
        """Replace the parameter of the same name (e.g. after editing it)."""
        old = self[parameter.name]
        self._params[parameter.name] = parameter
        try:
            self._validate()
        except ParameterError:
            self._params[parameter.name] = old
            raise

    def _validate(self) -> None:
        for p in self._params.values():
            if p.parent is not None and p.parent not in self._params:
                raise ParameterError(f"parameter '{p.name}': parent '{p.parent}' does not exist")
        for p in self._params.values():
            seen = {p.name}
            q = p.parent
            while q is not None:
                if q in seen:
                    raise ParameterError(f"parameter '{p.name}': the parent chain loops through '{q}'")
                seen.add(q)
                q = self._params[q].parent
        for p in self._params.values():
            if p.field and any(c.parent == p.name for c in self._params.values()):
                raise ParameterError(
                    f"parameter '{p.name}' carries a displacement field, which is not rigid, "
                    "so it cannot have children (it must stay a leaf, group 2)")


def _suggest(name: str, known: Collection[str]) -> str:
    import difflib

    close = difflib.get_close_matches(str(name), list(known), n=1)
    if close:
        return f" (did you mean '{close[0]}'?)"
    names = sorted(known)
    if not names:
        return " (the model has no parameters)"
    shown = ", ".join(names[:12]) + (", …" if len(names) > 12 else "")
    return f" (parameters: {shown})"
