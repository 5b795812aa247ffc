"""Classification strategies: the paper's template matching and a learned network.

Colour and shape cut the candidate ids before any classifier runs (the paper's
hierarchy); a classifier only picks among them and says how sure it is. Every
strategy has ``name``, ``accept_threshold``, ``min_score``, ``knows(ids)`` and
``classify(image, bbox, candidate_ids) -> ClassificationResult``.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from ..classifier_names import CLASSIFIERS
from .learned import ClassifierError, LearnedClassifier, load_model_card, model_card_path
from .ncc import NccClassifier


def make_classifier(name: str, catalogue, config=None):
    """The classifier called ``name`` for ``catalogue``.

    ``auto`` is the learned network where the catalogue carries one
    (``classifier/model.json``), else template matching; ``cnn`` insists on the
    network and raises :class:`ClassifierError` naming the missing file.
    """
    if name not in CLASSIFIERS:
        raise ValueError(f"unknown classifier {name!r}; choose one of {', '.join(CLASSIFIERS)}")
    if name == "auto":
        name = "cnn" if model_card_path(catalogue.folder).is_file() else "ncc"
    if name == "cnn":
        return LearnedClassifier.for_catalogue(catalogue)
    return NccClassifier(catalogue, config)


@lru_cache(maxsize=4)
def _learned(card_path: Path, stamp: float) -> LearnedClassifier:
    """One loaded network per model file and modification time: loading costs ~10 ms, a pair has many segments."""
    return LearnedClassifier(load_model_card(card_path))


def classifier_for(catalogue, config):
    """The classifier ``config.classification.classifier`` names for ``catalogue`` (networks loaded once per model)."""
    name = config.classification.classifier
    card = model_card_path(catalogue.folder)
    if name == "auto":
        name = "cnn" if card.is_file() else "ncc"
    if name == "cnn":
        try:
            stamp = card.stat().st_mtime
        except OSError:
            raise ClassifierError(card, "no learned classifier for this catalogue (choose the classifier 'ncc')") \
                from None
        return _learned(card, stamp)
    return make_classifier(name, catalogue, config)


def accept_threshold(classifier, config) -> float:
    """The indicator needed for "accepted": the configured one, else the classifier's calibrated default."""
    chosen = config.classification.classification_threshold
    return classifier.accept_threshold if chosen is None else chosen


def min_score(classifier, config) -> float:
    """The indicator below which a segment is not reported at all."""
    chosen = config.classification.min_classification_score
    return classifier.min_score if chosen is None else chosen


def marginal_min_score(classifier, config) -> float:
    """The indicator a loosely fitting or oblique outline needs to be reported at all."""
    if config.shape.marginal_shape_min_score is not None:
        return config.shape.marginal_shape_min_score
    return classifier.marginal_min_score


__all__ = ["CLASSIFIERS", "ClassifierError", "LearnedClassifier", "NccClassifier", "accept_threshold",
           "classifier_for", "load_model_card", "make_classifier", "marginal_min_score", "min_score", "model_card_path"]
