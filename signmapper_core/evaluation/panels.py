"""How well a run mapped the white text panels of a drive (4.29, 4.30, 4.33): their own rows.

The panels are signs (their detection, kind and false positives count in the white family's rows); these
rows add what only they carry: the text. A reference panel in view within the depth range is detected when
a mapped sign was matched to it (the sign evaluation's match), its kind is right when that sign has its id,
and its text is right when it equals the reference text exactly. Text is judged on the panels at least
``min_line_px`` high per line of text in the pair that saw them largest.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Optional, Sequence

from ..catalogue.text_panels import is_text_panel
from ..pipeline.config import DepthConfig
from .accuracy import share_text
from .visibility import DEFAULT_RANGE, largest_view_px, pair_ranges

MIN_LINE_PX = 20.0  # a line of a panel's lettering fills about half its line's height: ~10 px letters


@dataclass
class PanelFigures:
    reference: int = 0  # text panels in view
    detected: int = 0
    kinds_right: int = 0  # of the detected
    readable: int = 0  # reference panels with lines >= min_line_px
    readable_detected: int = 0
    texts_right: int = 0  # of the readable ones: text exactly right

    def __add__(self, other: PanelFigures) -> PanelFigures:
        return PanelFigures(*(getattr(self, f.name) + getattr(other, f.name) for f in fields(self)))

    def lines(self, title: str = "") -> list[str]:
        return [title,
                f"  text panels in view             {self.reference}",
                f"  detected                        {share_text(self.detected, self.reference)}",
                f"  kind right (4.29/4.30/4.33)     {share_text(self.kinds_right, self.detected)} detected",
                f"  text exactly right              {share_text(self.texts_right, self.readable)} of those with lines "
                f">= {MIN_LINE_PX:.0f} px ({share_text(self.texts_right, self.readable_detected)} of the detected)"]


def evaluate_panels(drive, signs: Sequence, reference: Sequence, match: Sequence[int],
                    depth: DepthConfig = DEFAULT_RANGE, min_line_px: float = MIN_LINE_PX,
                    evidence: Optional[list] = None) -> PanelFigures:
    """Text panel figures of one run. ``signs``: the fused signs (no plates) in the order of ``match``, the
    index of each one's reference sign in ``reference`` or -1 (``EvaluationReport.match``)."""
    figures = PanelFigures()
    ranges = pair_ranges(drive, depth)
    for k, ref in enumerate(reference):
        if not is_text_panel(ref.template_id):
            continue
        figures.reference += 1
        lines = max(1, len((ref.text or "").split(" / ")))
        largest_px = largest_view_px(drive, ref, ranges)
        readable = largest_px / lines >= min_line_px
        figures.readable += readable
        found = [s for s, m in zip(signs, match) if m == k]
        if not found:
            if evidence is not None:
                evidence.append(panel_line(ref, largest_px, None, "not detected"))
            continue
        best = max(found, key=lambda s: s.n_obs)
        figures.detected += 1
        figures.kinds_right += best.template_id == ref.template_id
        if readable:
            figures.readable_detected += 1
            figures.texts_right += (best.text or "") == (ref.text or "")
        if evidence is not None and (best.template_id != ref.template_id
                                     or (readable and (best.text or "") != (ref.text or ""))):
            evidence.append(panel_line(ref, largest_px, best, "read wrong"))
    return figures


def panel_line(ref, largest_px: float, mapped, what: str) -> str:
    """One line of evidence on a reference panel: what went wrong, its truth, and what was mapped for it."""
    line = f"  panel {ref.sign_id} ({largest_px:.0f} px high at most): {what}; truth {ref.template_id} {ref.text!r}"
    if mapped is not None:
        confidence = "-" if mapped.text_confidence is None else f"{mapped.text_confidence:.2f}"
        line += f"; mapped {mapped.template_id} {mapped.text!r} (confidence {confidence}, {mapped.n_obs} observations)"
    return line
