"""What the detection steps of one stereo pair share: its image, camera, pose, depth source, settings,
catalogue and classifier, so each step takes the pair and what it works on instead of ten arguments."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Sequence, Tuple

import numpy as np

from ..geometry import Camera, Pose
from .classifiers import NccClassifier, classifier_for
from .config import PipelineConfig
from .depth_sources import DepthSource
from .planarity import PlanarityResult, segment_planarity

Roi = Tuple[int, int, int, int]  # x0, y0, x1, y1 (exclusive)


@dataclass(frozen=True, eq=False)
class PairContext:
    """One stereo pair (or a window of it, ``roi``) as the detection steps see it."""

    left: np.ndarray  # BGR uint8
    camera: Camera
    pose: Pose
    catalogue: object
    config: PipelineConfig
    depth_source: DepthSource
    roi: Roi

    @classmethod
    def whole(cls, left, camera, pose, catalogue, config, depth_source) -> PairContext:
        """The whole pair: the roi is the left image."""
        height, width = left.shape[:2]
        return cls(left, camera, pose, catalogue, config, depth_source, (0, 0, width, height))

    @property
    def is_whole_image(self) -> bool:
        return self.roi == (0, 0, self.left.shape[1], self.left.shape[0])

    @cached_property
    def classifier(self):
        """The classifier the config names for the catalogue (:func:`.classifiers.classifier_for`)."""
        return classifier_for(self.catalogue, self.config)

    @cached_property
    def template_matcher(self) -> NccClassifier:
        """The paper's template matching, which knows every template of the catalogue."""
        return NccClassifier(self.catalogue, self.config)

    def classifier_knowing(self, template_ids: Sequence[str]):
        """The configured classifier where it knows every one of ``template_ids``, else template matching: a
        learned network knows only the ids it was trained on (one trained before entries were catalogued lacks
        them), and a white circle from the Hough route may be any of them."""
        classifier = self.classifier
        return classifier if classifier.knows(template_ids) else self.template_matcher

    def planarity(self, depth: np.ndarray, bbox, mask: np.ndarray) -> PlanarityResult:
        """:func:`.planarity.segment_planarity` of a segment, allowing for the noise of the pair's depth source."""
        return segment_planarity(self.camera, depth, bbox, mask, self.config,
                                 self.depth_source.planarity_tolerance_px(self.config))

    @cached_property
    def smallest_face_px(self) -> float:
        """Pixels of the smallest side of any format at the farthest depth searched: the smallest face worth
        finding."""
        config = self.config
        entries = self.catalogue.filter(exclude=tuple(config.classification.exclude))
        sides = [min(f) for e in entries for f in e.formats.values()]
        smallest = min(sides) if sides else min(config.size.fallback_face_sides_m)
        return smallest * min(self.camera.fx, self.camera.fy) / config.depth.farthest_m
