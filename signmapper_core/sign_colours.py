"""The sign colours, declared once: the HSV thresholds of each colour the pipeline segments, and how a map
draws it.

``PipelineConfig`` takes its defaults from here and ``mapsigns`` offers these
colours as its choices, so adding a sign colour is a row in each table below
(and a test). Hue is OpenCV's 0-179 scale. Kept apart from ``pipeline`` so the
QGIS side can list the colours without importing OpenCV.
"""

from __future__ import annotations

from typing import Dict, Tuple

# (hue_lo, hue_hi, sat_lo, sat_hi, val_lo, val_hi); several ranges per colour are OR-ed.
HsvRange = Tuple[int, int, int, int, int, int]
HueBands = Tuple[Tuple[int, int], ...]

# Cavegn (2011)'s thresholds of the strong pass
HSV_RANGES: Dict[str, Tuple[HsvRange, ...]] = {
    # red wraps around hue 0, so it needs both ends of the hue circle
    "red": ((0, 10, 90, 255, 50, 255), (165, 179, 90, 255, 50, 255)),
    "blue": ((100, 130, 110, 255, 40, 255),),
    "yellow": ((16, 35, 110, 255, 90, 255),),
    # the families the SSV adds to Cavegn's three, from the official drawings' colours (OpenCV HSV): motorway
    # green (77, 255, 127) and emergency-exit green (60, 255, 186), kept above foliage's yellow-green; tourist
    # brown (3, 207, 122), dark where red is bright; diversion orange (13, 213, 245), between red and yellow
    "green": ((52, 95, 110, 255, 40, 255),),
    "brown": ((0, 14, 110, 255, 40, 170), (172, 179, 110, 255, 40, 170)),
    "orange": ((8, 18, 150, 255, 150, 255),),
}

# Hue bands of the weak (scene-adaptive) pass; its saturation/value floors come from the scene.
# Faded or dimly lit red rings on real photographs (GTSDB tune split) drift to magenta: hue 150-165
# held ~40 % of their ring pixels, where hardly any background is. Germany's priority road (3.03) is
# orange-yellow: hue 13-17 on most GTSDB photographs, below the strong band's 16.
WEAK_HUES: Dict[str, HueBands] = {
    "red": ((0, 10), (150, 179)),
    "blue": ((98, 132),),
    "yellow": ((11, 35),),
}

# Hue bands naming the tint of a Hough circle's ring (a faded ring, not a scene pass's segment: any
# saturation above the tint floor counts, so the bands are the strong ones widened for blue)
HOUGH_TINT_HUES: Dict[str, HueBands] = {
    "red": ((0, 10), (150, 179)),
    "yellow": ((16, 35),),
    "blue": ((95, 135),),
}

# Red by hue alone, whatever the saturation: where a danger triangle's hidden apex should be, pixels of another
# hue (leaves, a hedge) tell an occluder from the triangle's own faded or shadowed red (pipeline/hidden_apex.py)
RED_ANY_SATURATION_HUES: HueBands = ((0, 12), (150, 179))
# The red rim of an official drawing, clean and saturated: the training faces' rim (training/face_wear.py)
DRAWING_RED_HUES: HueBands = ((0, 11), (166, 179))
DRAWING_RED_MIN_SATURATION = 91


def in_hue_bands(hue, bands: HueBands):
    """Boolean array: ``hue`` (an array of OpenCV hues) inside any of ``bands`` (inclusive)."""
    inside = False
    for low, high in bands:
        inside = inside | ((hue >= low) & (hue <= high))
    return inside


# The colour a map draws each catalogue colour in (a plain marker where a template has no SVG pictogram); white
# is a catalogue colour too, found by outline rather than hue
DISPLAY_COLOURS: Dict[str, str] = {"red": "#d52b1e", "blue": "#1f5fae", "yellow": "#f5c400", "white": "#f0f0f0",
                                   "green": "#007f40", "brown": "#7a3228", "orange": "#f5821e"}

SIGN_COLOURS: Tuple[str, ...] = tuple(HSV_RANGES)  # the colours a run may segment, in the order offered
