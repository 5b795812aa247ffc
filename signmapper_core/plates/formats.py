"""Supplementary plates (SSV 5.xx): their standard sizes and how the output names them.

A plate is as wide as the sign above it and one to three lines high. The sizes
are the usual Swiss ones (plates under 0.40, 0.60 and 0.90 m signs), a best
guess like the catalogue's ``size_certain: false`` entries: a road owner's own
table may replace them. No OpenCV here: the generator and the front ends read it.
"""

from __future__ import annotations

PLATE_ID = "plate"  # template id of a plate read for its text, not classified as a pictogram plate
PLATE_NAMES = {"de": "Zusatztafel", "fr": "Plaque complémentaire", "it": "Tavola complementare",
               "en": "Supplementary plate"}
# name -> (width_m, height_m)
PLATE_FORMATS = {
    "small-1": (0.40, 0.15), "small-2": (0.40, 0.25),
    "normal-1": (0.60, 0.20), "normal-2": (0.60, 0.30), "normal-3": (0.60, 0.40),
    "large-1": (0.90, 0.30), "large-2": (0.90, 0.45),
}


def plate_formats_for(sign_width_m: float) -> dict:
    """The formats of the plates that go with a sign of this width (the plate is as wide as the sign)."""
    width = min({w for w, _ in PLATE_FORMATS.values()}, key=lambda w: abs(w - sign_width_m))
    return {name: size for name, size in PLATE_FORMATS.items() if size[0] == width}
