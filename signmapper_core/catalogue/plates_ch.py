"""Swiss supplementary plates (SSV 5.xx): every plate of Signalo's table, how Sign Mapper types each.

The ids, names and drawings are those of Signalo's table of official signs
(``official_signs``: every id from 5.00 up, one drawing per language version
where the words differ: German ``de``, French ``fr``). A plate is one of three
kinds, which says how the mapping tells it:

- ``pictogram``: a fixed drawing (a vehicle class, an arrow, "gestattet" under a
  bicycle); told by its drawing alone (normalised cross-correlation), its text is
  the words the drawing carries.
- ``layout``: a fixed drawing with a field of free text (5.03's two arrows around
  a length, 5.17's fuel pump before a distance); told by the drawing outside that
  field, its text (Signalo's inscription) read by OCR inside it.
- ``text``: text only (5.00-1/2/3, 5.00-exception, 5.01); told by what it says
  (``plate_types``), never by its drawing.

A direction plate (Signalo's ``directional_sign``: 5.02, 5.07) is two of our ids,
``-l`` and ``-r``, one per drawing: the mapping must say which way it points
(Signalo's ``natural_direction_or_left``). Text fields are shares of the plate's
width and height (x0, y0, x1, y1), measured on the official drawings with room
for longer texts; the build checks that each holds its drawing's text and
leaves the fixed drawing outside it.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from .official_signs import official_signs

PICTOGRAM, LAYOUT, TEXT = "pictogram", "layout", "text"
PLATE_PREFIX = "5."
LEFT, RIGHT = "l", "r"
DIRECTION_NAMES = {LEFT: {"de": "links", "fr": "gauche", "it": "sinistra"},
                   RIGHT: {"de": "rechts", "fr": "droite", "it": "destra"}}

FREE_TEXT_PLATES = ("5.00-1", "5.00-2", "5.00-3")  # one to three lines of any text
EXCEPTION_PLATE = "5.00-exception"  # "ausgenommen" and what is excepted
DISTANCE_PLATE = "5.01"  # a distance
TEXT_PLATES = FREE_TEXT_PLATES + (EXCEPTION_PLATE, DISTANCE_PLATE)
# layout plates: Signalo id -> text field per direction ("" for a plate without one)
TEXT_FIELDS = {
    "5.02": {LEFT: (0.06, 0.54, 0.68, 0.95), RIGHT: (0.32, 0.54, 0.94, 0.95)},  # "50 m" under the turning arrow
    "5.03": {"": (0.18, 0.08, 0.82, 0.92)},  # "2,5 km" between two upward arrows
    "5.15": {"": (0.21, 0.08, 0.79, 0.92)},  # "3,20 m" between two triangles pointing at it
    "5.17": {"": (0.30, 0.12, 0.95, 0.88)},  # "48 km" after the fuel pump
    "5.31-3": {"": (0.06, 0.68, 0.94, 0.94)},  # "Taxis" under "ausgenommen <bicycle> und"
}
# words printed on a pictogram plate's drawing, per language version
PRINTED_WORDS = {
    "5.25-5.30-5.31": {"de": "ausgenommen", "fr": "exceptés"},
    "5.31-1": {"de": "gestattet", "fr": "autorisés"},
    "5.31-2": {"de": "ausgenommen", "fr": "exceptés"},
    "5.57": {"de": "SOS"},
}
# a plate's distinct drawings in Signalo's table, in its column order: German, then French where the words differ
# (the Italian and Romansh columns of every plate name the German or French drawing)
VARIANTS = ("de", "fr")


@dataclass(frozen=True)
class PlateDrawing:
    """One official drawing of a plate, as the build renders it and the mapping knows it."""

    id: str  # Signalo's id; a direction plate's with -l / -r
    variant: str  # language version: "de", or "fr" where the French drawing differs
    drawing: str  # SVG file name in the official set
    kind: str  # PICTOGRAM, LAYOUT or TEXT
    names: dict  # language -> name
    words: str  # words printed on a pictogram plate ("" for none; a layout plate's text is read)
    field: tuple = ()  # a layout plate's text field (x0, y0, x1, y1), shares of the plate

    @property
    def signalo_id(self) -> str:
        return signalo_id(self.id)

    @property
    def direction(self) -> str:
        """LEFT or RIGHT for a direction plate, "" for the others."""
        return direction_of(self.id)


def signalo_id(plate_id: str) -> str:
    """Signalo's id of one of our plate ids (a direction plate's without its -l / -r)."""
    base, _, tail = plate_id.rpartition("-")
    return base if tail in (LEFT, RIGHT) and base in official_signs() else plate_id


def direction_of(plate_id: str) -> str:
    """LEFT or RIGHT for one of our direction plate ids, "" for any other id."""
    base, _, tail = plate_id.rpartition("-")
    return tail if tail in (LEFT, RIGHT) and base in official_signs() else ""


def _kind(official_id: str) -> str:
    return TEXT if official_id in TEXT_PLATES else LAYOUT if official_id in TEXT_FIELDS else PICTOGRAM


def _variants(sign) -> list:
    """(direction, language version, drawing file) of each distinct drawing of one Signalo row."""
    if sign.directional:
        return [(LEFT, "de", sign.left_drawing), (RIGHT, "de", sign.right_drawing)]
    if len(sign.drawings) > len(VARIANTS):
        raise ValueError(f"plate {sign.id} has {len(sign.drawings)} drawings: more language versions than "
                         f"{', '.join(VARIANTS)}")
    return [("", variant, drawing) for variant, drawing in zip(VARIANTS, sign.drawings)]


@lru_cache(maxsize=1)
def plate_drawings() -> tuple:
    """Every drawing of every plate of Signalo's table (ids from 5.00 up), in the table's order."""
    out = []
    for official_id, sign in official_signs().items():
        if not official_id.startswith(PLATE_PREFIX):
            continue
        kind = _kind(official_id)
        for direction, variant, drawing in _variants(sign):
            plate_id = f"{official_id}-{direction}" if direction else official_id
            names = dict(sign.names)
            if direction:
                names = {lang: f"{name} ({DIRECTION_NAMES[direction].get(lang, direction)})"
                         for lang, name in names.items()}
            words = PRINTED_WORDS.get(official_id, {})
            out.append(PlateDrawing(plate_id, variant, drawing, kind, names,
                                    words.get(variant, words.get("de", "")),
                                    TEXT_FIELDS.get(official_id, {}).get(direction, ())))
    return tuple(out)


def kind_of(plate_id: str) -> str:
    """The kind of one of our plate ids; TEXT for an id the table lacks (the untyped ``plate``: a plate read for
    its text)."""
    return next((p.kind for p in plate_drawings() if p.id == plate_id), TEXT)
