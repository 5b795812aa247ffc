"""How well a run mapped the supplementary plates of a drive with ground truth: their own rows.

A reference plate (truth row with ``plate_of``) counts when it was in view within
the depth range (:func:`visibility.mappable_signs`). It is detected when a mapped
plate lies within the matching radius; its link is right when that mapped plate's
sign (``plate_of``) is the mapped sign matched to the reference plate's sign; its
text is right when it equals the reference text exactly (a pictogram plate
without words: when it has none). Text is judged on the plates that were at
least ``min_text_px`` high in the pair that saw them largest. Each detected plate
is also classified: a text plate as one, a pictogram plate as its SSV id.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Optional

import numpy as np

from .evaluation import match_to_reference, share_text
from .plate_formats import PLATE_ID
from .visibility import largest_view_px, mappable_signs

MIN_TEXT_PX = 40.0


@dataclass
class PlateFigures:
    reference: int = 0  # plates in view
    detected: int = 0
    mapped: int = 0  # mapped plate features
    false_positives: int = 0  # mapped plates matching no reference plate
    duplicates: int = 0  # reference plates matched by more than one mapped plate
    links_right: int = 0  # of the detected
    readable: int = 0  # reference plates >= min_text_px high
    readable_detected: int = 0
    texts_right: int = 0  # of the readable ones: text exactly right
    texts_read: int = 0  # of the readable detected ones: any text
    pictograms: int = 0  # reference plates that are pictogram plates (SSV 5.xx drawings)
    kinds_right: int = 0  # of the detected: text plate told as a text plate, pictogram plate as its own id
    pictograms_right: int = 0  # of the detected pictogram plates: their id
    pictograms_detected: int = 0

    def __add__(self, other: PlateFigures) -> PlateFigures:
        return PlateFigures(*(getattr(self, f.name) + getattr(other, f.name) for f in fields(self)))

    def lines(self, title: str = "") -> list[str]:
        return [title or "Supplementary plates",
                f"  reference plates in view        {self.reference}",
                f"  detected                        {share_text(self.detected, self.reference)}",
                f"  linked to the right sign        {share_text(self.links_right, self.detected)} detected",
                f"  classified right (text/5.xx id) {share_text(self.kinds_right, self.detected)} detected",
                f"  pictogram plates (5.xx)         {self.pictograms} ({self.pictograms_detected} detected, "
                f"{self.pictograms_right} with their id)",
                f"  mapped plate features           {self.mapped}",
                f"  false positive plates           {self.false_positives}",
                f"  reference plates with >1 plate  {self.duplicates}",
                f"  plates >= {MIN_TEXT_PX:.0f} px high           {self.readable} ({self.readable_detected} detected)",
                f"  text exactly right              {share_text(self.texts_right, self.readable)} of those >= "
                f"{MIN_TEXT_PX:.0f} px ({share_text(self.texts_right, self.readable_detected)} of the detected)"]


def evaluate_plates(drive, signs, sign_reference, sign_match, near_m: float = 4.0, far_m: float = 14.0,
                    radius_m: float = 0.75, min_text_px: float = MIN_TEXT_PX,
                    evidence: Optional[list] = None) -> PlateFigures:
    """Plate figures of one run.

    ``signs``: every fused feature of the run (signs and plates); ``sign_reference``
    and ``sign_match``: the reference signs the non-plate features were evaluated
    against and, per non-plate feature in the order of ``signs``, the index of its
    reference sign or -1 (``EvaluationReport.match``).
    """
    reference = mappable_signs(drive, near_m, far_m, plates=True)
    mapped = [s for s in signs if s.plate_of is not None]
    sign_truth = {}
    for sign, ref in zip((s for s in signs if s.plate_of is None), sign_match):
        sign_truth[sign.sign_id] = sign_reference[ref].sign_id if ref >= 0 else None
    figures = PlateFigures(reference=len(reference), mapped=len(mapped),
                           pictograms=sum(r.template_id != PLATE_ID for r in reference))
    match = match_to_reference(np.array([p.position for p in mapped]).reshape(-1, 3),
                               np.array([r.position for r in reference]).reshape(-1, 3), radius_m)
    figures.false_positives = int((match < 0).sum())
    for k, ref in enumerate(reference):
        found = [mapped[i] for i in np.flatnonzero(match == k)]
        largest_px = largest_view_px(drive, ref, near_m, far_m)
        readable = largest_px >= min_text_px
        figures.readable += readable
        if not found:
            if evidence is not None:
                evidence.append(plate_line(ref, largest_px, None, "not detected"))
            continue
        figures.detected += 1
        figures.duplicates += len(found) > 1
        best = max(found, key=lambda p: p.n_obs)
        link_right = sign_truth.get(best.plate_of) == ref.plate_of
        figures.links_right += link_right
        figures.kinds_right += best.template_id == ref.template_id
        if ref.template_id != PLATE_ID:
            figures.pictograms_detected += 1
            figures.pictograms_right += best.template_id == ref.template_id
        if readable:
            figures.readable_detected += 1
            figures.texts_read += best.text is not None
            figures.texts_right += (best.text or "") == (ref.text or "")  # a pictogram alone: no text
        if evidence is not None and not link_right:
            evidence.append(plate_line(ref, largest_px, best, "linked to another sign"))
        elif evidence is not None and readable and (best.text or "") != (ref.text or ""):
            evidence.append(plate_line(ref, largest_px, best, "text wrong"))
    return figures


def plate_line(ref, largest_px: float, mapped, what: str) -> str:
    """One line of evidence on a reference plate: what went wrong, its truth, and what was mapped for it."""
    line = f"  plate {ref.sign_id} under sign {ref.plate_of} ({largest_px:.0f} px high at most): {what}; " \
           f"truth {ref.template_id} {ref.text!r}"
    if mapped is not None:
        confidence = "-" if mapped.text_confidence is None else f"{mapped.text_confidence:.2f}"
        line += f"; mapped {mapped.template_id} {mapped.text!r} (confidence {confidence}, {mapped.n_obs} observations)"
    return line
