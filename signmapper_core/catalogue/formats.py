"""Standard sign formats: the face bounding box in metres per format name.

Sources: SSV (SR 741.21) Annex 1 for triangles (side 150/120/90/60 cm),
discs (diameter 120/90/60/40 cm), Stop (90/60/50 cm across flats) and zone
signs (normal format 50 x 70 cm, or 70 x 50 cm); the official ASTRA drawings,
which are at 1:20 of the normal format, for the rest: a triangle's face box is
smaller than its side because of the rounded corners (a 90 cm triangle is
84.9 x 74.4 cm), the priority-road diamond is a 50 cm square turned 45 degrees,
information squares are 50 cm and the upright information panels 50 x 70 cm.
Only the normal format of diamonds and information signs is sourced; their
large and small formats are estimates and entries using them are marked
``size_certain = False``.
"""

from __future__ import annotations

import math


def _r(v: float) -> float:
    return round(v, 3)


# Face box of a rounded-corner triangle per unit side, measured on the official 1:20 drawings (1.01, 3.02).
TRIANGLE_BOX_PER_SIDE = (0.9431, 0.8271)
# Danger triangles and the inverted give-way triangle, by side length.
TRIANGLE = {name: (_r(side * TRIANGLE_BOX_PER_SIDE[0]), _r(side * TRIANGLE_BOX_PER_SIDE[1])) for name, side in
            (("large", 1.50), ("intermediate", 1.20), ("normal", 0.90), ("small", 0.60))}
# Round signs: diameter.
ROUND = {name: (d, d) for name, d in (("large", 1.20), ("intermediate", 0.90), ("normal", 0.60), ("small", 0.40))}
# Stop: octagon across flats.
OCTAGON = {name: (d, d) for name, d in (("large", 0.90), ("normal", 0.60), ("small", 0.50))}
# Priority road: a square of side s turned 45 degrees; normal s = 0.50 (drawing), large and small estimated.
DIAMOND = {name: (_r(s * math.sqrt(2)), _r(s * math.sqrt(2))) for name, s in
           (("large", 0.75), ("normal", 0.50), ("small", 0.35))}
# Square information signs: normal 0.50 (drawing), large and small estimated.
SQUARE = {name: (d, d) for name, d in (("large", 0.75), ("normal", 0.50), ("small", 0.35))}
# Upright information panels (4.11, 4.18, 4.20): normal 0.50 x 0.70 (drawing), large and small estimated.
TALL_INFO = {"large": (0.75, 1.05), "normal": (0.50, 0.70), "small": (0.35, 0.49)}
# Zone signs: SSV Annex 1 gives only the normal format, upright or landscape.
ZONE = {"normal": (0.50, 0.70)}
ZONE_WIDE = {"normal": (0.70, 0.50)}
