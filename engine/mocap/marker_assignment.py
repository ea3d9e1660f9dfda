"""Naming a session's markers after import: labels that name no feature point, assigning points, the marker map.

A session names each marker by its MPEG-4 feature point id (``2.1``,
``8.3`` …) or keeps the label the file gave it (:mod:`engine.mocap.naming`).
A take whose labels spell no ids — NaturalPoint's ``root-1`` … ``root-6`` and
``section1-1`` … ``section14-3`` — arrives with none of the names multistage
PCA and ``mocap apply`` look for, and its markers are named afterwards, one
at a time, by someone who sees where each sits on the face:

* :func:`unmapped_labels` lists the labels a naming keeps as they are (what
  the import warns about);
* :func:`assign_marker` gives a marker a feature point id (or takes it back
  to its file label); a marker that held that id goes back to its own label,
  so one id is never on two markers (:func:`assignment_renames` says which
  renames that takes, without making them);
* :func:`rename_markers` is the rename every change is made of: the
  session's markers, its reference set and its report (gaps, naming) follow,
  and it returns the renames that undo it;
* :func:`session_mapping` is the session's naming as a mapping file's
  ``{label: id}`` (:func:`~engine.mocap.naming.write_mapping` writes it, and
  ``mocap import --map`` names the next take of the set the same way);
  :func:`marker_map_renames` puts such a mapping onto a session.

A session remembers each marker's file label in its report
(``report["naming"]["renamed"]``, ``{label: name}``), which the session file
keeps; names given here are saved with the session.

Names given after import do not turn the markers: the axes (+Y up, +Z
facing) were found at import from the names the markers had then, so a take
imported with none keeps the file's axes until it is imported again with the
map (or with ``--up``).

>>> import numpy as np
>>> from engine.mocap.session import Session
>>> s = Session(markers=["root-1", "chin"], positions=np.zeros((1, 2, 3)), raw=np.zeros((1, 2, 3)), rate_hz=100,
...             missing=np.zeros((1, 2), bool), alignment=np.eye(4)[None])
>>> assign_marker(s, "chin", "2.1")
{'chin': '2.1'}
>>> s.markers, marker_labels(s), session_mapping(s)
(['root-1', '2.1'], ['root-1', 'chin'], {'chin': '2.1'})
>>> rename_markers(s, {"2.1": "chin"}); s.markers
{'chin': '2.1'}
['root-1', 'chin']
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING, NamedTuple

from engine.mocap.errors import MocapError
from engine.mocap.naming import DROP, REFERENCE_POINTS, normalise_label
from engine.model.landmarks import FEATURE_POINTS, landmark_sort_key

if TYPE_CHECKING:
    from engine.mocap.session import Session
    from engine.model import Model

#: MPEG-4 feature point groups (ISO/IEC 14496-2 Annex C numbers them 2 … 11), and 20: the paper's head-fixed markers.
FEATURE_POINT_GROUPS = frozenset({*range(2, 12), 20})


class PointChoice(NamedTuple):
    """A feature point a marker can be given: its id, what the engine says it is, whether the model places it."""

    id: str
    description: str
    on_model: bool


def is_feature_point(name: str) -> bool:
    """Whether ``name`` is a feature point id as sessions spell it (``8.3``; not ``FP8_3``, ``08.3`` or ``1.1``).

    >>> [is_feature_point(n) for n in ("2.1", "20.4", "FP2_1", "1.1", "section14-2")]
    [True, True, False, False, False]
    """
    if normalise_label(name) != name:
        return False
    return int(name.split(".")[0]) in FEATURE_POINT_GROUPS


def unmapped_labels(labels: Iterable[str], names: Iterable[str | None]) -> list[str]:
    """The file labels whose session name (``names``, one per label; ``None``: dropped) is no feature point id.

    >>> unmapped_labels(["FP2_1", "root-1", "Unlabeled1"], ["2.1", "root-1", None])
    ['root-1']
    """
    return [label for label, name in zip(labels, names, strict=True)
            if name is not None and not is_feature_point(name)]


def marker_labels(session: Session) -> list[str]:
    """The file label of every marker of ``session``, in marker order (the name itself where it was kept)."""
    label_of = {name: label for label, name in _naming(session).get("renamed", {}).items()}
    return [label_of.get(m, m) for m in session.markers]


def rename_markers(session: Session, renames: Mapping[str, str]) -> dict[str, str]:
    """Rename markers of ``session`` in place, all at once (``{"2.1": "chin", "chin": "2.1"}`` swaps two).

    The reference set, the report's gap table and head-motion reference,
    and its naming (each marker's file label) follow. A new name must be
    writable to a mapping file (not empty, no ``#``, ``=`` or line break, no
    spaces at either end) and the names must stay unique; otherwise
    :class:`MocapError` and the session is unchanged. Returns the renames
    that undo this one.
    """
    renames = {str(old): str(new) for old, new in renames.items() if str(old) != str(new)}
    for old, new in renames.items():
        session.marker_index(old)
        if not new or new != new.strip() or any(c in new for c in "#=\r\n"):
            raise MocapError(f"cannot name marker '{old}' '{new}': a marker name is not empty and holds no '#', "
                             "'=', line break or spaces at either end")
    markers = [renames.get(m, m) for m in session.markers]
    seen: dict[str, str] = {}
    for old, new in zip(session.markers, markers, strict=True):
        if new in seen:
            raise MocapError(f"markers '{seen[new]}' and '{old}' would both be named '{new}'")
        seen[new] = old
    labels = marker_labels(session)
    session.markers = markers
    session.reference = [renames.get(m, m) for m in session.reference]
    report = session.report
    if isinstance(report.get("gaps"), dict):
        report["gaps"] = {renames.get(m, m): g for m, g in report["gaps"].items()}
    head = report.get("head_motion")
    if isinstance(head, dict) and isinstance(head.get("reference"), list):
        head["reference"] = [renames.get(m, m) for m in head["reference"]]
    naming = report.setdefault("naming", {})
    naming["renamed"] = {label: name for label, name in zip(labels, markers, strict=True) if label != name}
    naming["not_feature_points"] = unmapped_labels(labels, markers)
    return {new: old for old, new in renames.items()}


def marker_map_renames(session: Session, mapping: Mapping[str, str]) -> dict[str, str]:
    """The renames that name ``session``'s markers by a mapping file's ``{file label: id}``.

    Labels the session lacks are passed over (one map serves many takes);
    ``-`` (drop) is passed over too: a marker is dropped at import. A marker
    the mapping does not name that holds an id the mapping gives goes back
    to its own file label. Apply the result with :func:`rename_markers`.
    """
    labels = marker_labels(session)
    targets = {name: str(mapping[label]).strip() for label, name in zip(labels, session.markers, strict=True)
               if label in mapping and str(mapping[label]).strip() != DROP}
    return _with_displaced(session, labels, targets)


def assignment_renames(session: Session, marker: str, point: str | None) -> dict[str, str]:
    """The renames that give ``marker`` the feature point id ``point`` (its file label back: None or empty).

    A marker that had ``point`` goes back to its own file label. ``point``
    must be a feature point id (:func:`is_feature_point`), ``marker`` one of
    the session's: :class:`MocapError` otherwise. Nothing is changed; apply
    the result with :func:`rename_markers`.
    """
    session.marker_index(marker)
    labels = marker_labels(session)
    point = (point or "").strip()
    if not point:
        target = labels[session.markers.index(marker)]
    elif is_feature_point(point):
        target = point
    else:
        raise MocapError(f"'{point}' is no MPEG-4 feature point id (ids look like 2.1, 8.3 or 20.1)")
    return _with_displaced(session, labels, {marker: target})


def assign_marker(session: Session, marker: str, point: str | None) -> dict[str, str]:
    """Give ``marker`` the feature point id ``point`` (:func:`assignment_renames`), in place; the renames made.

    :func:`rename_markers` with the renames reversed undoes it. On any
    error the session is unchanged.
    """
    renames = assignment_renames(session, marker, point)
    rename_markers(session, renames)
    return renames


def session_mapping(session: Session) -> dict[str, str]:
    """The session's naming as a mapping file's ``{file label: id}`` (``-`` for the labels dropped at import).

    Holds every marker whose name is not what its label would become
    without a mapping (:func:`~engine.mocap.naming.normalise_label`), so the
    file names the next import the same way.
    """
    out = {label: name for label, name in zip(marker_labels(session), session.markers, strict=True)
           if name != (normalise_label(label) or label)}
    out.update({str(label): DROP for label in _naming(session).get("dropped", [])})
    return out


def feature_point_choices(model: Model) -> list[PointChoice]:
    """The ids a marker can be given: the model's landmarks first, then the head-fixed reference points.

    With their descriptions where the engine has them; ``on_model`` says
    whether the model has a vertex for the point (its landmark, or a
    head-fixed point the engine places on the skin:
    :func:`engine.mocap.synthetic.marker_vertices`), i.e. whether a marker
    of that name is drawn on the face and used by ``mocap apply``.
    """
    from engine.errors import UserError
    from engine.mocap.synthetic import marker_vertices

    landmarks = sorted((p for p in model.landmarks if is_feature_point(p)), key=landmark_sort_key)
    out = [PointChoice(p, FEATURE_POINTS.get(p) or REFERENCE_POINTS.get(p, ""), True) for p in landmarks]
    for point in sorted(set(REFERENCE_POINTS) - set(landmarks), key=landmark_sort_key):
        try:
            marker_vertices(model, [point])
            placed = True
        except UserError:
            placed = False
        out.append(PointChoice(point, REFERENCE_POINTS[point], placed))
    return out


def _naming(session: Session) -> dict:
    naming = session.report.get("naming")
    return naming if isinstance(naming, dict) else {}


def _with_displaced(session: Session, labels: list[str], targets: dict[str, str]) -> dict[str, str]:
    """``targets`` ({marker: new name}) plus, for every other marker holding one of the new names, its file label."""
    taken = set(targets.values())
    displaced = {name: label for name, label in zip(session.markers, labels, strict=True)
                 if name not in targets and name in taken}          # rename_markers refuses a label that is taken
    return {old: new for old, new in {**targets, **displaced}.items() if old != new}
