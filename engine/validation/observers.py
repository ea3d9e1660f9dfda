"""The observers: models trained on photographs of real people, loaded once per process.

Four pinned, offline models judge a picture (``docs/validation.md`` gives each one's training
data and licence):

* dlib's HOG face detector (and, on request or when HOG finds nothing, its CNN detector,
  ``mmod_human_face_detector.dat``);
* dlib's 68-point shape predictor (``shape_predictor_68_face_landmarks.dat``, trained on
  iBUG 300-W: research use only);
* dlib's 128-D face descriptor (``dlib_face_recognition_resnet_model_v1.dat``): two faces
  less than 0.6 apart are the same person by dlib's convention;
* a FER2013 mini-Xception emotion classifier (``models/fer2013-mini-xception.tflite``,
  run by ``ai-edge-litert``), seven probabilities per face.

They come with the optional extra ``validate``; without it :func:`observers` raises
:class:`ObserversMissing`, one line saying what to install.

>>> from engine.validation.observers import observers
>>> eyes = observers()                                   # doctest: +SKIP
>>> eyes.detect(image)                                   # doctest: +SKIP
[Detection(box=(179.0, 83.0, 266.0, 170.0), score=1.53, detector='hog')]
"""

from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import os
import threading
from collections.abc import Iterator
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

from engine.errors import UserError

EMOTIONS = ("angry", "disgust", "fear", "happy", "sad", "surprise", "neutral")
"""The emotion classifier's classes, in its output order (FER2013's labels)."""

EMOTION_MODEL = Path(__file__).resolve().parent / "models" / "fer2013-mini-xception.tflite"
EMOTION_MODEL_SHA256 = "65e3961bb68f497bd02a8d075da8409364db90004edb80c0c6cb15647c4de559"
EMOTION_INPUT = 64
"""The classifier's input: a 64 × 64 grey face, values in [-1, 1]."""

FACE_SCORE = 0.3
"""A HOG detection counts as a face from this score up (dlib's own threshold is 0; below 0.3 the
detector fires on flags and folds of cloth in real photographs, checked on scikit-image's
astronaut)."""
CNN_CONFIDENCE = 0.3
#: dlib's trained models, as the face_recognition_models package ships them in its models/ folder.
DLIB_MODEL_FILES = ("mmod_human_face_detector.dat", "shape_predictor_68_face_landmarks.dat",
                    "dlib_face_recognition_resnet_model_v1.dat")
"""The same for the CNN detector's confidence."""
SAME_PERSON = 0.6
"""dlib's convention: two face descriptors less than this apart are the same person."""

EXTRA_HINT = ("validate needs its optional packages (dlib-bin, face_recognition_models, ai-edge-litert): "
              "pip install 'artificial-person[validate]'")


class ObserversMissing(UserError):
    """The ``validate`` extra is not installed."""


@dataclass(frozen=True)
class Detection:
    """One face found: its box (left, top, right, bottom, pixels), the detector's score, which detector."""

    box: tuple[float, float, float, float]
    score: float
    detector: str


@dataclass(frozen=True)
class ModelFacts:
    """What a report says of one observer: its name, file, version and licence."""

    role: str
    name: str
    file: str
    trained_on: str
    licence: str


def _dlib_models_folder() -> Path:
    """The folder of dlib's trained models in the ``face_recognition_models`` package, found without
    importing it: its ``__init__`` imports ``pkg_resources``, which setuptools 81 and later no longer have."""
    spec = importlib.util.find_spec("face_recognition_models")
    if spec is None or spec.origin is None:
        raise ObserversMissing(f"{EXTRA_HINT} (face_recognition_models is missing)")
    folder = Path(spec.origin).parent / "models"
    for name in DLIB_MODEL_FILES:
        if not (folder / name).is_file():
            raise ObserversMissing(f"{EXTRA_HINT} ({folder / name} is missing)")
    return folder


class Observers:
    """The loaded models. Use :func:`observers` (one per process) rather than building one."""

    def __init__(self) -> None:
        try:
            import dlib
            from ai_edge_litert.interpreter import Interpreter, OpResolverType
        except ImportError as exc:
            raise ObserversMissing(f"{EXTRA_HINT} ({exc.name or exc} is missing)") from None
        models = _dlib_models_folder()
        self._dlib = dlib
        self._hog = dlib.get_frontal_face_detector()
        self._cnn: Any = None
        self._cnn_file = str(models / "mmod_human_face_detector.dat")
        self._points = dlib.shape_predictor(str(models / "shape_predictor_68_face_landmarks.dat"))
        self._describer = dlib.face_recognition_model_v1(str(models / "dlib_face_recognition_resnet_model_v1.dat"))
        if _sha256(EMOTION_MODEL) != EMOTION_MODEL_SHA256:
            raise ObserversMissing(f"the emotion model {EMOTION_MODEL} is not the one shipped (its SHA-256 differs); "
                                   "reinstall the toolkit")
        with _quiet_stderr():
            self._emotion = Interpreter(model_path=str(EMOTION_MODEL), num_threads=1,
                                        experimental_op_resolver_type=OpResolverType.BUILTIN_WITHOUT_DEFAULT_DELEGATES)
            self._emotion.allocate_tensors()
        self._emotion_in = self._emotion.get_input_details()[0]["index"]
        self._emotion_out = self._emotion.get_output_details()[0]["index"]
        self._lock = threading.Lock()       # the interpreter and dlib's nets are not re-entrant

    # -- faces -----------------------------------------------------------------------------

    def detect(self, rgb: np.ndarray, detector: str = "hog", upsample: int = 0) -> list[Detection]:
        """Faces in an (H, W, 3) uint8 picture, best first: HOG detections with a score of at least
        :data:`FACE_SCORE`, or the CNN's with a confidence of at least :data:`CNN_CONFIDENCE`."""
        with self._lock:
            if detector == "cnn":
                found = self._cnn_detector()(rgb, upsample)
                faces = [Detection(_box(d.rect), float(d.confidence), "cnn") for d in found
                         if d.confidence >= CNN_CONFIDENCE]
            else:
                rects, scores, _ = self._hog.run(rgb, upsample, 0.0)
                faces = [Detection(_box(r), float(s), "hog") for r, s in zip(rects, scores, strict=True)
                         if s >= FACE_SCORE]
        return sorted(faces, key=lambda d: -d.score)

    def landmarks(self, rgb: np.ndarray, box: tuple[float, float, float, float]) -> np.ndarray:
        """The 68 iBUG points (68, 2) of the face in ``box``, pixels (x right, y down)."""
        with self._lock:
            shape = self._points(rgb, self._rect(box))
        return np.array([(p.x, p.y) for p in shape.parts()], dtype=float)

    def descriptor(self, rgb: np.ndarray, points: np.ndarray) -> np.ndarray:
        """The 128-D face descriptor of the face whose 68 points are ``points``."""
        rect = self._rect((points[:, 0].min(), points[:, 1].min(), points[:, 0].max(), points[:, 1].max()))
        parts = [self._dlib.point(round(x), round(y)) for x, y in points]
        with self._lock:
            shape = self._dlib.full_object_detection(rect, parts)
            return np.array(self._describer.compute_face_descriptor(rgb, shape), dtype=float)

    def emotions(self, face: np.ndarray) -> np.ndarray:
        """The seven class probabilities (:data:`EMOTIONS` order) of a 64 × 64 grey face in [0, 255]."""
        x = (np.asarray(face, dtype=np.float32) / 255.0 - 0.5) * 2.0
        with self._lock:
            self._emotion.set_tensor(self._emotion_in, x.reshape(1, EMOTION_INPUT, EMOTION_INPUT, 1))
            self._emotion.invoke()
            out = np.array(self._emotion.get_tensor(self._emotion_out)[0], dtype=float)
        total = out.sum()
        return out / total if total > 0 else out

    def _cnn_detector(self) -> Any:
        if self._cnn is None:
            self._cnn = self._dlib.cnn_face_detection_model_v1(self._cnn_file)
        return self._cnn

    def _rect(self, box: tuple[float, float, float, float]) -> Any:
        left, top, right, bottom = (round(v) for v in box)
        return self._dlib.rectangle(left, top, right, bottom)


@cache
def observers() -> Observers:
    """The process's observers, loaded on first use (about 1 s)."""
    return Observers()


def model_facts() -> list[ModelFacts]:
    """What each observer is, for reports and provenance (no model is loaded)."""
    return [
        ModelFacts("face detection", "dlib HOG frontal face detector (CNN: mmod_human_face_detector)",
                   "dlib-bin 20.0.1.post1; face_recognition_models 0.3.0",
                   "faces labelled by dlib's author (HOG: LFW-style frontal faces; CNN: ImageNet, AFLW, "
                   "Pascal VOC, VGG, WIDER, FaceScrub images)",
                   "public domain (dlib-models README); dlib: Boost Software License"),
        ModelFacts("68 landmarks", "dlib shape_predictor_68_face_landmarks", "face_recognition_models 0.3.0",
                   "iBUG 300-W", "research use only: the 300-W licence excludes commercial use"),
        ModelFacts("identity", "dlib_face_recognition_resnet_model_v1 (128-D descriptor)",
                   "face_recognition_models 0.3.0",
                   "about 3 million faces of 7,485 people (FaceScrub, VGG and web images); 99.38 % on LFW",
                   "public domain (dlib-models README)"),
        ModelFacts("emotion", "FER2013 mini-Xception, int8 TensorFlow Lite", EMOTION_MODEL.name,
                   "FER2013: 35,887 grey 48 × 48 web photographs, 7 classes",
                   "model file MIT (fer, face_classification); FER2013 published for research"),
    ]


def _box(rect: Any) -> tuple[float, float, float, float]:
    return (float(rect.left()), float(rect.top()), float(rect.right()), float(rect.bottom()))


def _sha256(path: Path) -> str:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return ""


@contextlib.contextmanager
def _quiet_stderr() -> Iterator[None]:
    """Keep the TensorFlow Lite runtime's start-up lines off the user's terminal (fd 2)."""
    try:
        saved = os.dup(2)
    except OSError:
        yield
        return
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 2)
            yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)
