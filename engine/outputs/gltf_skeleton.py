"""glTF skeleton export: the rigid group-1 parameters (§2.2) as joints of a skin.

A joint rests at its parameter's pivot with its local +X along the rotation
axis (or translation direction), so a value is a turn about, or a slide
along, the joint's own X, and the skinning reproduces ``model.deform``
exactly, leaves riding on the joints as in the engine. Lengths in metres.

>>> import numpy as np
>>> r = rotation_from_x(np.array([0.0, 1.0, 0.0]))          # +X onto +Y: a quarter turn about +Z
>>> quaternion(r).round(6).tolist()
[0.0, 0.0, 0.707107, 0.707107]
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from engine.errors import UserError
from engine.formats.gltf_read import METRES_PER_MM

if TYPE_CHECKING:
    from engine.model import Model, Parameter
    from engine.outputs.gltf_buffer import GltfBuffer


def skeleton_parameters(model: Model) -> list[str]:
    """The parameters a skeleton exports as joints: the rigid group-1 (non-leaf) ones, in tree order."""
    tree = model.parameters
    return [name for name, _ in tree.depth_first() if tree.group(name) == 1]


class SkeletonRig:
    """Group-1 parameters as glTF joints: a ``root`` joint (vertices no rigid parameter carries),
    then one joint per parameter, nested as the parameter tree.

    A joint rests at its pivot (translations: at the origin) with its local +X
    along the rotation axis (translation direction), so a parameter value is a
    turn about, or a slide along, the joint's own X. Each joint's skinning
    matrix ``G · G_rest⁻¹`` is then the engine's propagated ``T'`` (column
    convention ``T'_c = T'_parent · T_c``), and the skin weights are the
    engine's normalised group-1 weights (at most four per vertex: more are cut
    to the four largest and renormalised).
    """

    def __init__(self, model: Model) -> None:
        tree = model.parameters
        self.names = skeleton_parameters(model)
        for name in self.names:
            if tree[name].default != 0:
                raise UserError(f"parameter '{name}' rests at {tree[name].default:g}: a skeleton needs "
                                "its rigid parameters to rest at 0")
        n = model.n_vertices
        w = np.stack([model.regions[name].dense(n) for name in self.names], axis=1) if self.names \
            else np.zeros((n, 0))
        total = w.sum(axis=1)
        w = np.hstack([(total == 0)[:, None].astype(float), np.divide(w, total[:, None], out=np.zeros_like(w),
                                                                       where=total[:, None] > 0)])
        order = np.argsort(-w, axis=1, kind="stable")[:, :4]
        top = np.take_along_axis(w, order, axis=1)
        if top.shape[1] < 4:
            order = np.hstack([order, np.zeros((n, 4 - top.shape[1]), dtype=order.dtype)])
            top = np.hstack([top, np.zeros((n, 4 - top.shape[1]))])
        top /= top.sum(axis=1, keepdims=True)
        order[top == 0] = 0
        dtype = np.uint8 if len(self.names) < 255 else np.uint16
        self.joints, self.weights = order.astype(dtype), top.astype(np.float32)
        self.frames = {name: joint_frame(tree[name]) for name in self.names}
        self.tree = tree

    def skin(self, nodes: list[dict[str, Any]], buf: GltfBuffer) -> dict:
        """Append the joint nodes to ``nodes``; return the skin."""
        first = len(nodes)
        index: dict[str | None, int] = {name: first + 1 + i for i, name in enumerate(self.names)}
        nodes.append({"name": "root", "children": []})
        ibm = [np.eye(4)]
        for name in self.names:
            p = self.tree[name]
            rotation, origin = self.frames[name]
            # a root parameter, or one whose parent is not a joint, hangs from the root joint
            parent_rotation, parent_origin = self.frames[p.parent] if p.parent in self.frames \
                else (np.eye(3), np.zeros(3))
            local = parent_rotation.T @ rotation
            node = {"name": name, "translation": (parent_rotation.T @ (origin - parent_origin)).tolist(),
                    "rotation": quaternion(local).tolist(),
                    "extras": {"parameter": name, "minimum": p.minimum, "maximum": p.maximum}}
            if p.kind == "rotation":
                node["extras"].update(motion="rotation about the joint's +X", degrees_per_unit=p.degrees_per_unit)
            else:
                node["extras"].update(motion="translation along the joint's +X",
                                      mm_per_unit=float(np.linalg.norm(p.direction)))
            nodes[index.get(p.parent, first)].setdefault("children", []).append(len(nodes))
            nodes.append(node)
            inverse = np.eye(4)
            inverse[:3, :3], inverse[:3, 3] = rotation.T, -rotation.T @ origin
            ibm.append(inverse)
        matrices = np.stack([m.T.reshape(16) for m in ibm]).astype(np.float32)   # glTF matrices are column-major
        return {"name": "parameters", "skeleton": first, "joints": list(range(first, len(nodes))),
                "inverseBindMatrices": buf.add(matrices, None, bounds=False, kind="MAT4")}


def joint_frame(p: Parameter) -> tuple[np.ndarray, np.ndarray]:
    """Rest orientation (local +X along the axis or direction) and origin (the pivot, metres) of a joint."""
    if p.kind == "rotation":
        return rotation_from_x(p.axis), p.pivot * METRES_PER_MM
    length = np.linalg.norm(p.direction)
    return rotation_from_x(p.direction / length if length else np.array([1.0, 0, 0])), np.zeros(3)


def rotation_from_x(a: np.ndarray) -> np.ndarray:
    """The smallest rotation taking +X to the unit vector ``a`` (Rodrigues)."""
    x = np.array([1.0, 0.0, 0.0])
    v, c = np.cross(x, a), float(x @ a)
    s2 = float(v @ v)
    if s2 < 1e-24:
        return np.eye(3) if c > 0 else np.diag([-1.0, 1.0, -1.0])
    k = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + k + k @ k * ((1 - c) / s2)


def quaternion(r: np.ndarray) -> np.ndarray:
    """Unit quaternion (x, y, z, w), glTF's order, of a rotation matrix (from its largest component)."""
    t = np.trace(r)
    options = [1 + t, 1 + r[0, 0] - r[1, 1] - r[2, 2], 1 - r[0, 0] + r[1, 1] - r[2, 2], 1 - r[0, 0] - r[1, 1] + r[2, 2]]
    k = int(np.argmax(options))
    s = 2 * np.sqrt(options[k])
    if k == 0:
        components = [(r[2, 1] - r[1, 2]) / s, (r[0, 2] - r[2, 0]) / s, (r[1, 0] - r[0, 1]) / s, s / 4]
    elif k == 1:
        components = [s / 4, (r[0, 1] + r[1, 0]) / s, (r[0, 2] + r[2, 0]) / s, (r[2, 1] - r[1, 2]) / s]
    elif k == 2:
        components = [(r[0, 1] + r[1, 0]) / s, s / 4, (r[1, 2] + r[2, 1]) / s, (r[0, 2] - r[2, 0]) / s]
    else:
        components = [(r[0, 2] + r[2, 0]) / s, (r[1, 2] + r[2, 1]) / s, s / 4, (r[1, 0] - r[0, 1]) / s]
    q = np.array(components)
    return q / np.linalg.norm(q)
