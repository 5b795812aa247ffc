"""A small convolutional network, trained on synthetic faces of the official drawings, run by OpenCV's dnn.

The catalogue folder carries the model as ``classifier/model.json`` (the card:
classes, input size, margin, temperature, acceptance threshold) beside
``classifier/model.onnx``. Colour and shape have already cut the candidates;
the network's logits are restricted to them plus a background class and turned
into probabilities with the calibrated temperature, so the classification
indicator is an estimate of the probability that the id is right.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

import cv2
import numpy as np

from ...errors import InputFileError
from ..classify import ClassificationResult
from .face_patch import face_patch, standardise

CARD_FORMAT = "signmapper-classifier/1"
BACKGROUND = "__background__"
MODEL_DIR = "classifier"


class ClassifierError(InputFileError):
    """A classifier model folder is missing or malformed; the message names the file and the field."""


@dataclass(frozen=True)
class ModelCard:
    """What the network needs around it: its classes and how patches are cut, and its calibration."""

    path: Path
    onnx: Path
    classes: tuple[str, ...]
    input_px: int
    margin: float
    temperature: float
    accept_threshold: float  # calibrated probability above which a sign is "accepted"
    min_score: float  # below this probability the segment is not reported as a sign
    views: tuple = ((0.0, 0.0, 1.0),)  # (dx, dy, scale) of the box, in box sizes: logits averaged over them
    # a face whose best candidate's logit is below this matches no candidate well (None: not calibrated)
    unknown_logit: float | None = None

    def index(self, template_id: str) -> int:
        return self.classes.index(template_id)


def model_card_path(catalogue_folder) -> Path:
    return Path(catalogue_folder) / MODEL_DIR / "model.json"


def load_model_card(path) -> ModelCard:
    """Read and check a model card; every problem is a :class:`ClassifierError` naming the file."""
    path = Path(path)
    try:
        raw = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ClassifierError(path, "no such file") from None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ClassifierError(path, f"cannot be read as JSON ({exc})") from None
    if not isinstance(raw, dict) or raw.get("format") != CARD_FORMAT:
        raise ClassifierError(path, f"'format' must be {CARD_FORMAT!r}")

    def field(name, kind, check, what):
        value = raw.get(name)
        if not isinstance(value, kind) or isinstance(value, bool) or not check(value):
            raise ClassifierError(path, f"field '{name}' must be {what}, got {value!r}")
        return value

    classes = field("classes", list, lambda v: len(v) >= 2 and all(isinstance(c, str) and c for c in v),
                    "a list of at least two template ids")
    if len(set(classes)) != len(classes):
        raise ClassifierError(path, "field 'classes' lists an id twice")
    if BACKGROUND not in classes:
        raise ClassifierError(path, f"field 'classes' needs the background class {BACKGROUND!r}")
    onnx = path.parent / field("onnx", str, bool, "the model file name")
    views = raw.get("views", [[0.0, 0.0, 1.0]])
    if (not isinstance(views, list) or not views or not all(
            isinstance(v, list) and len(v) == 3 and all(isinstance(c, (int, float)) for c in v)
            and abs(v[0]) <= 0.5 and abs(v[1]) <= 0.5 and 0.5 <= v[2] <= 2 for v in views)):
        raise ClassifierError(path, f"field 'views' must be a list of [dx, dy, scale] (|d| <= 0.5, scale 0.5..2), "
                                    f"got {views!r}")
    if not onnx.is_file():
        raise ClassifierError(onnx, "model file missing (named by field 'onnx' of model.json)")
    return ModelCard(
        path=path, onnx=onnx, classes=tuple(classes),
        input_px=field("input_px", int, lambda v: 8 <= v <= 512, "an integer 8..512"),
        margin=float(field("margin", (int, float), lambda v: 0 <= v <= 1, "a number 0..1")),
        temperature=float(field("temperature", (int, float), lambda v: 0.05 <= v <= 20, "a number 0.05..20")),
        accept_threshold=float(field("accept_threshold", (int, float), lambda v: 0 < v < 1, "a number in (0, 1)")),
        min_score=float(field("min_score", (int, float), lambda v: 0 <= v < 1, "a number in [0, 1)")),
        views=tuple(tuple(float(c) for c in v) for v in views),
        unknown_logit=_optional_number(raw, "unknown_logit", path),
    )


def _optional_number(raw: dict, name: str, path: Path) -> float | None:
    value = raw.get(name)
    if value is None:
        return None
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not -100 < value < 100:
        raise ClassifierError(path, f"field '{name}' must be a number, got {value!r}")
    return float(value)


def _view(bbox, view) -> tuple:
    """``bbox`` moved by (dx, dy) box sizes and scaled about its centre: another look at an uncertain box."""
    x, y, w, h = (float(c) for c in bbox)
    dx, dy, scale = view
    cx, cy = x + w / 2 + dx * w, y + h / 2 + dy * h
    return cx - scale * w / 2, cy - scale * h / 2, scale * w, scale * h


def _softmax(z: np.ndarray) -> np.ndarray:
    e = np.exp(z - z.max())
    return e / e.sum()


class LearnedClassifier:
    """Classifies a face box among candidate ids with the catalogue's ONNX network."""

    name = "cnn"

    def __init__(self, card: ModelCard):
        self.card = card
        self.accept_threshold = card.accept_threshold
        self.min_score = card.min_score
        self.marginal_min_score = card.accept_threshold  # a loose or oblique outline must be read with confidence
        self._index = {c: i for i, c in enumerate(card.classes)}
        self.unknown_logit = card.unknown_logit
        try:
            self._net = cv2.dnn.readNetFromONNX(str(card.onnx))
        except cv2.error as exc:
            raise ClassifierError(card.onnx, f"OpenCV cannot load the model ({exc})") from None

    @classmethod
    def for_catalogue(cls, catalogue) -> LearnedClassifier:
        return cls(load_model_card(model_card_path(catalogue.folder)))

    def knows(self, template_ids: Sequence[str]) -> bool:
        return all(t in self._index for t in template_ids)

    def unknown(self, template_ids: Sequence[str]) -> list:
        """The ids among ``template_ids`` the network was not trained on: it cannot read them."""
        return [t for t in template_ids if t not in self._index]

    def logits(self, image: np.ndarray, bboxes: Sequence) -> np.ndarray:
        """Network outputs (n, classes) for face boxes of one image, averaged over the card's views of each."""
        views = self.card.views
        boxes = [_view(b, v) for b in bboxes for v in views]
        patches = np.stack([face_patch(image, b, self.card.input_px, self.card.margin) for b in boxes])
        self._net.setInput(standardise(patches))
        out = np.asarray(self._net.forward(), dtype=np.float64).reshape(len(bboxes), len(views), -1)
        return out.mean(axis=1)

    def probabilities(self, logits: np.ndarray, candidate_ids: Sequence[str]) -> np.ndarray:
        """Calibrated probabilities of the candidates and, last, of the background."""
        picked = [self._index[t] for t in candidate_ids] + [self._index[BACKGROUND]]
        return _softmax(logits[picked] / self.card.temperature)

    def classify(self, image: np.ndarray, bbox, candidate_ids: Sequence[str]) -> ClassificationResult:
        # entries added to the catalogue after the network was trained are not its to read (the pipeline asks
        # template matching where a face may be one of them: PairContext.classifier_knowing)
        ids = [t for t in dict.fromkeys(candidate_ids) if t in self._index]
        if not ids:
            return ClassificationResult(None, 0.0)
        z = self.logits(image, [bbox])[0]
        p = self.probabilities(z, ids)
        best = int(np.argmax(p[:-1]))
        scores = {t: float(p[i]) for i, t in enumerate(ids)}
        every = _softmax(z / self.card.temperature)
        fit = float(max(z[self._index[t]] for t in ids))
        return ClassificationResult(ids[best], float(p[best]), scores, fit=fit,
                                    background=float(every[self._index[BACKGROUND]]))
