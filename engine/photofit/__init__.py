"""A person's own face from photographs (§2.4): fitted, textured and still animatable.

The user marks a few MPEG-4 landmarks on a front (and optionally a side)
photograph (:mod:`engine.photofit.points`). :func:`fit_photos` finds a
weak-perspective camera for each photograph and the identity parameters
that put the head's landmarks there (:mod:`engine.photofit.shape`), warps
the rest smoothly onto the landmarks, carries the rig over and projects the
photographs into the head's texture atlas (:mod:`engine.photofit.texture`).
"""

from engine.photofit.errors import PhotoFitError
from engine.photofit.fit import PhotoFit, fit_photo_files, fit_photos
from engine.photofit.photos import read_photo
from engine.photofit.points import REQUIRED_FRONT, read_points
from engine.photofit.stopping import FitStopped

__all__ = ["REQUIRED_FRONT", "FitStopped", "PhotoFit", "PhotoFitError", "fit_photo_files", "fit_photos",
           "read_photo", "read_points"]
