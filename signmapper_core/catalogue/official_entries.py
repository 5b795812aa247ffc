"""Catalogue entries of the official signs the project has no own drawing of: colour, outline and size rule.

Every id of Signalo's table of official signs (``official_signs``) that is not a
supplementary plate (5.xx, the plate catalogue) is covered by the catalogue:

- by an entry under its own id: the signs of ``signs_ch`` (own drawings, masters
  mostly from the official drawings) and the entries below (masters from the
  official drawing only);
- by per-value entries where the sign carries a number (``2.30`` by ``2.30-50``
  ...; Signalo keeps the number as the sign's inscription);
- by a generic text panel (``text_panels``) where the ids differ only by their
  number of lines of text: ``text_panels.COVERED_BY_PANEL``.

Colour and outline were read off each drawing (share of the face in each hue
band; fill of the bounding box; aspect) and checked by eye; ``tests`` compare
them with the drawings again. The size rule says how a face's size is reported:

- ``"round"``, ``"triangle"``: the SSV's standard formats of discs and
  triangles (``formats.ROUND``, ``formats.TRIANGLE``);
- ``"square"``, ``"tall"``: information signs whose official drawing (1:20)
  gives the normal format, 0.50 x 0.50 m or 0.50 x 0.70 m; their other formats
  are estimates (``formats.SQUARE``, ``formats.TALL_INFO``, not certain);
- ``"measured"``: no standard size exists (direction signs, boards and panels
  sized by their text or content, lane signs, route markers): the face is
  mapped with its measured size; the catalogue's format is the drawing's size
  at 1:20 and gives only the aspect.
"""

from __future__ import annotations

from dataclasses import dataclass

from .official import Region

ROUND, TRIANGLE, SQUARE, TALL, MEASURED = "round", "triangle", "square", "tall", "measured"
SIZE_RULES = (ROUND, TRIANGLE, SQUARE, TALL, MEASURED)


@dataclass(frozen=True)
class OfficialEntry:
    colour: str
    shape: str
    size: str  # one of SIZE_RULES


def _e(colour: str, shape: str, size: str) -> OfficialEntry:
    return OfficialEntry(colour, shape, size)


def _group(ids, colour: str, shape: str, size: str) -> dict:
    return {i: OfficialEntry(colour, shape, size) for i in ids}


OFFICIAL_ENTRIES: dict = {
    # tourist signs: brown direction signs with a destination (pointing, straight on, not pointing)
    **_group(("0.1", "0.1-2", "0.1-3"), "brown", "pointer", MEASURED),
    **_group(("0.1-1.1", "0.1-1.2", "0.1-2.1", "0.1-2.2", "0.1-3.1", "0.1-3.2"), "brown", "rectangle", MEASURED),
    "0.2": _e("yellow", "pointer", MEASURED),  # pedestrian tourist route
    "0.3": _e("yellow", "rectangle", MEASURED),  # hotel
    # danger signs
    **_group(("1.13a", "1.25a", "1.28", "1.29"), "red", "triangle", TRIANGLE),
    "1.17": _e("red", "rectangle", MEASURED),  # distance beacon: one of its three boards (ARTWORK)
    # prohibitions and mandatory signs
    **_group(("2.09.1", "2.15.1", "2.15.2", "2.15.3", "2.51", "2.52"), "red", "circle", ROUND),
    "2.54-30": _e("blue", "circle", ROUND),  # end of minimum speed, with the value of its drawing
    "2.56.1": _e("white", "circle", ROUND),
    **_group(("2.57", "2.60.1", "2.61-a", "2.62-a", "2.63-1-a", "2.63-a", "2.64-a"), "blue", "circle", ROUND),
    # panels: dangerous goods direction, zone signs
    **_group(("2.41.2", "2.41.2a", "2.41.2b"), "white", "rectangle", MEASURED),
    **_group(("2.59.1-NP", "2.59.1-P", "2.59.2-NP", "2.59.2-P"), "white", "rectangle", MEASURED),
    "2.65": _e("white", "square", MEASURED),  # lane-control light signal: its red-cross state (ARTWORK)
    # priority signs: flashing lights at level crossings and St Andrew's crosses
    "3.20": _e("red", "triangle", MEASURED),
    "3.21": _e("red", "triangle", MEASURED),
    **_group(("3.22", "3.23", "3.24", "3.25"), "red", "cross", MEASURED),
    # information signs with a pictogram
    **_group(("4.01", "4.02", "4.03", "4.04"), "green", "rectangle", TALL),
    **_group(("4.05", "4.06", "4.09.1", "4.21", "4.25", "4.25a"), "blue", "square", SQUARE),
    **_group(("4.07", "4.08.1", "4.11a", "4.12", "4.12a", "4.13", "4.13a", "4.15", "4.16", "4.21-1", "4.21-2",
              "4.24", "4.25b", "4.25c", "4.25d", "4.79", "4.80", "4.81", "4.82", "4.83", "4.84", "4.85", "4.86",
              "4.87", "4.88", "4.89", "4.92"), "blue", "rectangle", TALL),
    "4.19": _e("white", "rectangle", TALL),
    "4.95": _e("green", "rectangle", TALL),
    # information signs with a distance or text: no standard size
    **_group(("4.07a", "4.10", "4.22", "4.23", "4.90"), "blue", "rectangle", MEASURED),
    "4.91": _e("blue", "rectangle", MEASURED),  # church services: narrower than the information panels (0.66)
    # place names on main roads, direction signs, advance direction signs and boards
    **_group(("4.27-1", "4.27-2", "4.27-3", "4.28"), "blue", "rectangle", MEASURED),
    **_group(("4.31-1", "4.31-2", "4.31-3"), "green", "pointer", MEASURED),
    **_group(("4.32-1", "4.32-2", "4.32-3"), "blue", "pointer", MEASURED),
    **_group(("4.34", "4.34-2", "4.34-3", "4.34.1"), "orange", "pointer", MEASURED),
    **_group(("4.34.2-1", "4.34.2-2", "4.34.2-3", "4.34.3-1", "4.34.3-2", "4.34.3-3"), "orange", "rectangle",
             MEASURED),
    **_group(("4.35", "4.37", "4.39", "4.52", "4.59", "4.59.1", "4.71"), "white", "rectangle", MEASURED),
    "4.93": _e("blue", "rectangle", MEASURED),  # general speed limits: white fields in a blue frame
    **_group(("4.42", "4.42-2", "4.51.4"), "white", "square", MEASURED),
    **_group(("4.36", "4.38", "4.40", "4.41", "4.53", "4.54", "4.55", "4.57", "4.60", "4.61", "4.62", "4.75",
              "4.76"), "blue", "rectangle", MEASURED),
    "4.63": _e("blue", "square", MEASURED),
    **_group(("4.45", "4.46", "4.46.1", "4.47", "4.48", "4.49"), "white", "pointer", MEASURED),
    # cycle and other slow-traffic routes: red
    **_group(("4.50.1", "4.50.3", "4.50.4", "4.51.1"), "red", "pointer", MEASURED),
    "4.50.5": _e("red", "square", MEASURED),
    **_group(("4.50.6", "4.51.2", "4.51.3", "4.58"), "red", "rectangle", MEASURED),
    **_group(("4.51.1-a", "4.51.1-b"), "red", "diamond", MEASURED),
    # motorway signs
    **_group(("4.56", "4.64", "4.65", "4.66", "4.67", "4.68", "4.69", "4.94"), "green", "rectangle", MEASURED),
    "4.70": _e("orange", "pointer", MEASURED),  # emergency telephone
    "4.72": _e("white", "square", MEASURED),  # kilometre post
    "4.73": _e("white", "rectangle", MEASURED),  # hectometre plate
    # lane signs (white with black arrows)
    **_group(("4.77.2-1", "4.77.2-2", "4.77.2-3", "4.77/02", "4.77/03", "4.77/06", "4.77/07", "4.77/08", "4.77/09",
              "4.77/11-1", "4.77/11-2", "4.77/13", "4.77/14", "4.77/18", "4.77/19", "4.77/25", "4.77/28-1",
              "4.77/28-2"), "white", "square", MEASURED),
    **_group(("4.77/01", "4.77/04", "4.77/05", "4.77/10-1", "4.77/10-2", "4.77/12", "4.77/15", "4.77/16", "4.77/17",
              "4.77/20", "4.77/21", "4.77/22", "4.77/23", "4.77/24", "4.77/26", "4.77/27", "4.77/29"), "white",
             "rectangle", MEASURED),
}

# Drawings that are not one face as they stand: one board of a row of boards (areas in the drawing's user units);
# the other boards are the entry's variants. 1.17: the beacons with three, two and one stripes; 2.65: the red
# cross, green arrow and yellow arrow states of the light signal.
ARTWORK = {
    "1.17": Region("117.svg", (0.652, 0.309, 43.172, 142.035)),
    "2.65": Region("265.svg", (0.703, 0.652, 85.742, 85.691)),
}
VARIANT_ARTWORK = {
    "1.17": (Region("117.svg", (50.262, 0.309, 92.781, 142.035)), Region("117.svg", (99.863, 0.309, 142.383, 142.035))),
    "2.65": (Region("265.svg", (107.0, 0.652, 192.039, 85.691)), Region("265.svg", (213.301, 0.652, 298.340, 85.691))),
}
# Outlines further from their shape's ideal than the build's check allows (official.OUTLINE_MIN_IOU): the light
# signals' triangles have corners rounded to a quarter of their side (overlap 0.81 and 0.72).
OUTLINE_OVERLAP = {"3.20": 0.78, "3.21": 0.70}
# Per-value entries drawn from the base sign's drawing as it stands (its drawing shows that value).
VALUE_DRAWINGS = {"2.54-30": "254.svg"}
