"""Figures per sign family of a run: the white and grey signs against the coloured ones, and each colour family.

:class:`FamilyFigures` (white and grey, or coloured): a reference sign of the family is detected when any mapped
feature lies within the matching radius (a feature of another family there still finds it, under a wrong id), and
correctly classified when the majority of those features carry its id (:func:`evaluation.evaluate`). A false
positive of the family is a mapped feature whose template belongs to the family and which matches no reference
sign of any family; per 100 pairs, so that per-pair detections of drives of any length compare.

:class:`GroupFigures`, of the fused signs, per colour family of the catalogue (red, blue, yellow, white and grey,
green, brown, orange) and, apart, the faces a synthetic drive printed from the project's own procedural designs
(:func:`sign_group`): signs in view, detected, given the right id whatever their status, fused signs accepted and
of them accepted with another id, and the 3D RMS of the matched fused signs' positions.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Callable, Iterable, Sequence

import numpy as np

from ..catalogue.model import COLOURS
from ..catalogue.text_panels import is_text_panel
from ..statuses import ACCEPTED
from .accuracy import evaluate, majority_id, match_to_reference, share_text

WHITE = ("white",)
COLOURED = tuple(c for c in COLOURS if c != "white")
PROCEDURAL_GROUP = "procedural designs"  # faces of the project's own procedural drawer (synthetic drives)
GROUPS = COLOURS + (PROCEDURAL_GROUP,)  # the rows of the per-family table, in this order
GROUP_TITLES = {"white": "white and grey"}


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


def sign_group(reference_sign, colour_of: Callable[[str], str]) -> str:
    """The row of a reference sign: :data:`PROCEDURAL_GROUP` for a synthetic face printed from a procedural
    design (the white text panels, set from their wording in the official layout, excepted), else the colour
    family of its template ("" for an id the catalogue does not hold)."""
    if getattr(reference_sign, "artwork", "") == "procedural" and not is_text_panel(reference_sign.template_id):
        return PROCEDURAL_GROUP
    return colour_of(reference_sign.template_id)


@dataclass
class GroupFigures:
    """Fused-sign figures of one row (a colour family or the procedural designs)."""

    in_view: int = 0  # reference signs
    detected: int = 0  # of them, matched by a fused sign
    right: int = 0  # of them, the majority of their fused signs carrying their id, whatever the status
    accepted: int = 0  # of them, matched by a fused sign with status accepted
    accepted_wrong: int = 0  # of those, by an accepted fused sign with another id
    accepted_no_sign: int = 0  # accepted fused signs of the row's colour (by their id) matching no reference sign
    matched: int = 0  # fused signs matched to a reference sign of the row
    squared_3d_m2: float = 0.0  # sum of their squared 3D position differences

    def __add__(self, other: GroupFigures) -> GroupFigures:
        return GroupFigures(*(getattr(self, f.name) + getattr(other, f.name) for f in fields(self)))

    @property
    def rms_3d_m(self) -> float:
        return float(np.sqrt(self.squared_3d_m2 / self.matched)) if self.matched else float("nan")

    def line(self, title: str) -> str:
        rms = f"{100 * self.rms_3d_m:.1f} cm" if self.matched else "-"
        return (f"{title:<20} {self.in_view:>7} {share_text(self.detected, self.in_view):>21} "
                f"{share_text(self.right, self.in_view):>21} {share_text(self.accepted, self.in_view):>21} "
                f"{share_text(self.accepted_wrong, self.accepted):>21} {self.accepted_no_sign:>9} {rms:>8}")


GROUP_HEADER = (f"{'':<20} {'in view':>7} {'detected':>21} {'right id, any status':>21} {'accepted':>21} "
                f"{'accepted, wrong id':>21} {'acc., none':>9} {'3D RMS':>8}")


def group_figures(signs: Sequence, reference: Sequence, match, colour_of: Callable[[str], str]
                  ) -> dict[str, GroupFigures]:
    """:class:`GroupFigures` per row (:func:`sign_group`) of fused ``signs`` (with ``template_id``, ``status``,
    ``position``) matched to ``reference`` by ``match`` (per fused sign the reference index or -1, as
    :func:`evaluation.evaluate` gives it). Every row of :data:`GROUPS` is present, empty or not."""
    figures = {group: GroupFigures() for group in GROUPS}
    match = np.asarray(match, int).reshape(-1)
    for k, ref in enumerate(reference):
        row = figures.setdefault(sign_group(ref, colour_of), GroupFigures())
        mine = [signs[i] for i in np.flatnonzero(match == k)]
        accepted = [sign for sign in mine if sign.status == ACCEPTED]
        row.in_view += 1
        row.detected += bool(mine)
        row.right += bool(mine) and majority_id([sign.template_id for sign in mine]) == ref.template_id
        row.accepted += bool(accepted)
        row.accepted_wrong += any(sign.template_id != ref.template_id for sign in accepted)
        row.matched += len(mine)
        row.squared_3d_m2 += sum(float(np.sum((np.asarray(sign.position, float) - ref.position) ** 2))
                                 for sign in mine)
    for sign, k in zip(signs, match):
        if k < 0 and sign.status == ACCEPTED:
            figures.setdefault(colour_of(sign.template_id), GroupFigures()).accepted_no_sign += 1
    return figures


def group_lines(figures: dict[str, GroupFigures], title: str) -> list[str]:
    """The per-family table: one line per row of :data:`GROUPS` (and any other row found), then the colour
    families together (the headline: every face showing an official drawing or set in the official layout)."""
    lines = [title, GROUP_HEADER]
    for group, row in figures.items():
        lines.append(row.line(GROUP_TITLES.get(group, group) or "(not catalogued)"))
    families = sum((row for group, row in figures.items() if group in COLOURS), GroupFigures())
    lines.append(families.line("all families"))
    return lines
