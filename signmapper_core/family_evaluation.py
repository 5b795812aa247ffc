"""Figures of one sign family (the white and grey signs, or the coloured ones) of a run: their own rows.

A reference sign of the family is detected when any mapped feature lies within the matching radius
(a feature of another family there still finds it, under a wrong id), and correctly classified when
the majority of those features carry its id (:func:`evaluation.evaluate`). A false positive of the
family is a mapped feature whose template belongs to the family and which matches no reference sign
of any family; per 100 pairs, so that per-pair detections of drives of any length compare.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Callable, Iterable, Sequence

import numpy as np

from .evaluation import evaluate, match_to_reference, share_text

WHITE = ("white",)
COLOURED = ("red", "blue", "yellow")


@dataclass
class FamilyFigures:
    pairs: int = 0
    reference: int = 0
    detected: int = 0
    correct: int = 0  # of the detected
    features: int = 0  # mapped features of the family
    false_positives: int = 0  # of those, matching no reference sign at all

    def __add__(self, other: FamilyFigures) -> FamilyFigures:
        return FamilyFigures(*(getattr(self, f.name) + getattr(other, f.name) for f in fields(self)))

    @property
    def false_positives_per_100_pairs(self) -> float:
        return 100.0 * self.false_positives / self.pairs if self.pairs else float("nan")

    def lines(self, title: str) -> list[str]:
        return [title,
                f"  reference signs in view         {self.reference}",
                f"  detected                        {share_text(self.detected, self.reference)}",
                f"  correctly classified            {share_text(self.correct, self.detected)} detected",
                f"  mapped features of the family   {self.features}",
                f"  false positive features         {self.false_positives} "
                f"({self.false_positives_per_100_pairs:.2f} per 100 pairs)"]


def family_figures(items: Sequence, reference: Sequence, colour_of: Callable[[str], str],
                   family: Iterable[str], trajectory_xy: np.ndarray, pairs: int, radius_m: float
                   ) -> FamilyFigures:
    """Figures of the signs whose template's colour (``colour_of(template_id)``) is in ``family``.

    ``items``: mapped features (per-pair detections or fused signs) with ``position`` and ``template_id``;
    ``reference``: the reference signs in view (truth rows with ``position`` and ``template_id``).
    """
    family = set(family)
    xyz = np.array([o.position for o in items], float).reshape(-1, 3)
    ids = [o.template_id for o in items]
    members = [r for r in reference if colour_of(r.template_id) in family]
    report = evaluate(xyz, ids, [r.position for r in members], [r.template_id for r in members], trajectory_xy,
                      radius_m)
    ours = np.array([colour_of(t) in family if t else False for t in ids], bool)
    unmatched = match_to_reference(xyz, np.array([r.position for r in reference], float).reshape(-1, 3),
                                   radius_m) < 0
    return FamilyFigures(pairs=pairs, reference=len(members), detected=report.table1.detected_signs,
                         correct=report.table1.correctly_classified_signs, features=int(ours.sum()),
                         false_positives=int((ours & unmatched).sum()))


def catalogue_colour(catalogue) -> Callable[[str], str]:
    """``template_id -> colour`` of a catalogue; ids it does not hold (plates) have the colour ""."""
    return lambda tid: catalogue[tid].colour if tid in catalogue else ""
