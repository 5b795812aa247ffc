"""Standard sign formats: the face bounding box in metres per format name.

Triangles and discs follow the SSV sizes (side / diameter); the values of
diamonds, information squares, zone and general-limit panels are best
knowledge, and entries using them are marked ``size_certain = False``.
"""

from __future__ import annotations

import math

SQRT3_2 = math.sqrt(3.0) / 2.0


def _r(v: float) -> float:
    return round(v, 3)


# Danger triangles and the inverted give-way triangle: side length.
TRIANGLE = {name: (_r(side), _r(side * SQRT3_2)) for name, side in
            (("large", 1.50), ("intermediate", 1.20), ("normal", 0.90), ("small", 0.60))}
# Round signs: diameter.
ROUND = {name: (d, d) for name, d in (("large", 1.20), ("intermediate", 0.90), ("normal", 0.60), ("small", 0.40))}
# Stop: octagon across flats.
OCTAGON = {name: (d, d) for name, d in (("large", 0.90), ("normal", 0.60), ("small", 0.50))}
# Priority road diamond: bounding box of a square of side s turned 45 degrees (uncertain).
DIAMOND = {name: (_r(s * math.sqrt(2)), _r(s * math.sqrt(2))) for name, s in
           (("large", 0.85), ("normal", 0.60), ("small", 0.42))}
# Square blue information / priority signs (uncertain).
SQUARE = {name: (d, d) for name, d in (("large", 0.90), ("normal", 0.60), ("small", 0.40))}
# Upright information panels with a sub-symbol, e.g. parking with disc (uncertain).
TALL_INFO = {"large": (0.90, 1.35), "normal": (0.60, 0.90)}
# Zone signs (Tempo-30-Zone, pedestrian zone), from the project brief (uncertain).
ZONE = {"large": (0.75, 1.05), "normal": (0.50, 0.70)}
# "50 generell" panel (uncertain).
GENERAL_LIMIT = {"large": (1.05, 1.50), "normal": (0.70, 1.00)}
