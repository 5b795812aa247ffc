"""White information panels whose content is text: the place-name and direction panels of secondary roads.

SSV 4.29 (a place begins: its name), 4.30 (a place ends: its name over a black bar, the next place and its
distance below) and 4.33 (direction panel: a pointer with one to three destinations). Their wording, and
with it their width, changes from panel to panel, so the catalogue holds one generic entry per kind: it is
found by outline and depth, told apart by its layout (a pointer, a bar), its text is read by OCR, and its size
is measured, not rounded to a standard format.

Sizes: the norms size these panels from their lettering. The official drawings (signalo, 1:20) give
0.57 x 0.42 m for 4.29 with a four-letter name and 0.77 x 0.20 m for a one-line 4.33; the ranges below are
estimates around them for names of 3 to 16 letters and one to three lines (the entries are ``size_certain``
False).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Tuple

Size = Tuple[float, float]  # width_m, height_m of the face's bounding box

PLACE_NAME, PLACE_END, DIRECTION = "place-name", "place-end", "direction"


@dataclass(frozen=True)
class TextPanelKind:
    """One generic text panel of the catalogue: its id, layout and the range of its face size."""

    id: str
    layout: str  # PLACE_NAME, PLACE_END or DIRECTION
    nominal: Size  # a typical face: the catalogue's format, of the official drawing's aspect
    smallest: Size  # width and height of the smallest face of this kind
    largest: Size  # ... and of the largest
    lines: Tuple[int, int]  # fewest and most lines of text

    def fits(self, width_m: float, height_m: float, tolerance: float) -> bool:
        """Whether a measured face size lies within this kind's range, widened by ``tolerance``."""
        (w0, h0), (w1, h1) = self.smallest, self.largest
        return (w0 * (1.0 - tolerance) <= width_m <= w1 * (1.0 + tolerance)
                and h0 * (1.0 - tolerance) <= height_m <= h1 * (1.0 + tolerance))


TEXT_PANELS = {
    k.id: k for k in (
        TextPanelKind("4.29", PLACE_NAME, (0.70, 0.50), (0.50, 0.35), (1.80, 0.80), (1, 2)),
        TextPanelKind("4.30", PLACE_END, (0.70, 0.50), (0.55, 0.45), (1.80, 0.90), (2, 3)),
        TextPanelKind("4.33", DIRECTION, (1.00, 0.24), (0.60, 0.15), (1.80, 0.60), (1, 3)),
    )
}


# Signalo ids that differ only by their lines of text (1 to 3), each stood for by one generic panel above
COVERED_BY_PANEL = {"4.29-1": "4.29", "4.29-2": "4.29", "4.29-3": "4.29",
                    "4.33-1": "4.33", "4.33-2": "4.33", "4.33-3": "4.33"}


def is_text_panel(template_id: str) -> bool:
    """Whether ``template_id`` is a generic text panel (its size and text vary from face to face)."""
    return template_id in TEXT_PANELS
