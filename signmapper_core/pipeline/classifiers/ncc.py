"""The paper's classifier: normalised cross-correlation against the catalogue's templates."""

from __future__ import annotations

from typing import Sequence

import numpy as np

from ..classify import ClassificationResult, classify_segment
from ..config import PipelineConfig


class NccClassifier:
    """Template matching of :func:`classify_segment`; its best score is the classification indicator."""

    name = "ncc"
    accept_threshold = 0.6  # NCC score needed for "accepted" (the first version's default)
    min_score = 0.35  # below this no template resembles the segment: not reported
    marginal_min_score = 0.5  # a loose or oblique outline must resemble its template clearly

    def __init__(self, catalogue, config=None):
        """``config``: the PipelineConfig whose classification settings apply (None: the defaults)."""
        self.catalogue = catalogue
        self.config = config if config is not None else PipelineConfig()

    def knows(self, template_ids: Sequence[str]) -> bool:
        return all(t in self.catalogue for t in template_ids)

    def classify(self, image: np.ndarray, bbox, candidate_ids: Sequence[str]) -> ClassificationResult:
        return classify_segment(image, bbox, self.catalogue, candidate_ids, self.config)
