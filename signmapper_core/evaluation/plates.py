"""How well a run mapped the supplementary plates of a drive with ground truth: their own rows.

A reference plate (truth row with ``plate_of``) counts when it was in view within
the depth range (:func:`visibility.mappable_signs`). It is detected when a mapped
plate lies within the matching radius; its link is right when that mapped plate's
sign (``plate_of``) is the mapped sign matched to the reference plate's sign; it is
typed right when its id is the reference's SSV id. Plates are counted by kind
(``catalogue.plates_ch``): text plates (typed by what they say; a truth of the
untyped id ``plate`` is one too), layout plates (a drawing with free text) and
pictogram plates. The text of text and layout plates is right when it equals the
reference text exactly; it is judged on the plates that were at least
``min_text_px`` high in the pair that saw them largest (a pictogram plate's text
is its drawing's words, not read).
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Optional

import numpy as np

from ..catalogue.plates_ch import kind_of
from ..pipeline.config import DepthConfig
from .accuracy import match_to_reference, share_text
from .visibility import DEFAULT_RANGE, largest_view_px, mappable_signs, pair_ranges

MIN_TEXT_PX = 40.0
KINDS = ("text", "layout", "pictogram")  # catalogue.plates_ch's kinds, in the order reported


@dataclass
class PlateFigures:
    reference: int = 0  # plates in view
    detected: int = 0
    typed_right: int = 0  # of the detected: their SSV id
    mapped: int = 0  # mapped plate features
    false_positives: int = 0  # mapped plates matching no reference plate
    duplicates: int = 0  # reference plates matched by more than one mapped plate
    links_right: int = 0  # of the detected
    text: int = 0  # reference text plates (5.00-x, 5.01) ...
    text_detected: int = 0
    text_typed: int = 0  # ... detected with their id
    layout: int = 0  # reference layout plates (5.02, 5.03, 5.15, 5.17, 5.31-3) ...
    layout_detected: int = 0
    layout_typed: int = 0
    pictogram: int = 0  # reference pictogram plates ...
    pictogram_detected: int = 0
    pictogram_typed: int = 0
    readable: int = 0  # reference text and layout plates >= min_text_px high
    readable_detected: int = 0
    texts_right: int = 0  # of the readable ones: text exactly right
    texts_read: int = 0  # of the readable detected ones: any text

    def __add__(self, other: PlateFigures) -> PlateFigures:
        return PlateFigures(*(getattr(self, f.name) + getattr(other, f.name) for f in fields(self)))

    def lines(self, title: str = "") -> list[str]:
        rows = [title or "Supplementary plates",
                f"  reference plates in view        {self.reference}",
                f"  detected                        {share_text(self.detected, self.reference)}",
                f"  detected and typed right        {share_text(self.typed_right, self.reference)} "
                f"({share_text(self.typed_right, self.detected)} of the detected)",
                f"  linked to the right sign        {share_text(self.links_right, self.detected)} detected"]
        for kind in KINDS:
            n, found, typed = (getattr(self, f"{kind}{tail}") for tail in ("", "_detected", "_typed"))
            rows.append(f"  {kind + ' plates':<16}                {n}: {found} detected, {typed} typed right")
        return rows + [
            f"  mapped plate features           {self.mapped}",
            f"  false positive plates           {self.false_positives}",
            f"  reference plates with >1 plate  {self.duplicates}",
            f"  text/layout plates >= {MIN_TEXT_PX:.0f} px    {self.readable} ({self.readable_detected} detected)",
            f"  text exactly right              {share_text(self.texts_right, self.readable)} of those >= "
            f"{MIN_TEXT_PX:.0f} px ({share_text(self.texts_right, self.readable_detected)} of the detected)"]


def evaluate_plates(drive, signs, sign_reference, sign_match, depth: DepthConfig = DEFAULT_RANGE,
                    radius_m: float = 0.75, min_text_px: float = MIN_TEXT_PX,
                    evidence: Optional[list] = None) -> PlateFigures:
    """Plate figures of one run.

    ``signs``: every fused feature of the run (signs and plates); ``sign_reference``
    and ``sign_match``: the reference signs the non-plate features were evaluated
    against and, per non-plate feature in the order of ``signs``, the index of its
    reference sign or -1 (``EvaluationReport.match``).
    """
    reference = mappable_signs(drive, depth, plates=True)
    mapped = [s for s in signs if s.plate_of is not None]
    sign_truth = {}
    for sign, ref in zip((s for s in signs if s.plate_of is None), sign_match):
        sign_truth[sign.sign_id] = sign_reference[ref].sign_id if ref >= 0 else None
    figures = PlateFigures(reference=len(reference), mapped=len(mapped))
    match = match_to_reference(np.array([p.position for p in mapped]).reshape(-1, 3),
                               np.array([r.position for r in reference]).reshape(-1, 3), radius_m)
    figures.false_positives = int((match < 0).sum())
    ranges = pair_ranges(drive, depth)
    for k, ref in enumerate(reference):
        kind = kind_of(ref.template_id)
        setattr(figures, kind, getattr(figures, kind) + 1)
        found = [mapped[i] for i in np.flatnonzero(match == k)]
        largest_px = largest_view_px(drive, ref, ranges)
        readable = largest_px >= min_text_px and kind != "pictogram"
        figures.readable += readable
        if not found:
            if evidence is not None:
                evidence.append(plate_line(ref, largest_px, None, "not detected"))
            continue
        figures.detected += 1
        setattr(figures, f"{kind}_detected", getattr(figures, f"{kind}_detected") + 1)
        figures.duplicates += len(found) > 1
        best = max(found, key=lambda p: p.n_obs)
        link_right = sign_truth.get(best.plate_of) == ref.plate_of
        figures.links_right += link_right
        typed = best.template_id == ref.template_id
        figures.typed_right += typed
        setattr(figures, f"{kind}_typed", getattr(figures, f"{kind}_typed") + typed)
        text_right = (best.text or "") == (ref.text or "")
        if readable:
            figures.readable_detected += 1
            figures.texts_read += best.text is not None
            figures.texts_right += text_right
        if evidence is not None:
            what = [w for w, wrong in (("linked to another sign", not link_right), ("typed wrong", not typed),
                                       ("text wrong", readable and not text_right)) if wrong]
            if what:
                evidence.append(plate_line(ref, largest_px, best, ", ".join(what)))
    return figures


def plate_line(ref, largest_px: float, mapped, what: str) -> str:
    """One line of evidence on a reference plate: what went wrong, its truth, and what was mapped for it."""
    line = f"  plate {ref.sign_id} under sign {ref.plate_of} ({largest_px:.0f} px high at most): {what}; " \
           f"truth {ref.template_id} {ref.text!r}"
    if mapped is not None:
        confidence = "-" if mapped.text_confidence is None else f"{mapped.text_confidence:.2f}"
        line += f"; mapped {mapped.template_id} {mapped.text!r} (confidence {confidence}, {mapped.n_obs} observations)"
    return line
