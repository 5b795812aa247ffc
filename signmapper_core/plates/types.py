"""A text plate's SSV id from what it says, and what Signalo records of each plate.

Text plates (``catalogue.plates_ch``) have no drawing of their own to tell them
by: a plate whose first line is the word for "except" is an exception plate
(5.00-exception), one line of a distance is a distance plate (5.01), any other
text a plate of free text of its number of lines (5.00-1, 5.00-2, 5.00-3). A plate
whose text was not read keeps the untyped id ``plate``. Signalo writes a plate's
free text as inscriptions: a text plate's lines (an exception plate's without the
"except" word), a layout plate's text, none for a pictogram plate.
"""

from __future__ import annotations

from typing import Optional

from ..catalogue.plates_ch import DISTANCE_PLATE, EXCEPTION_PLATE, FREE_TEXT_PLATES, PICTOGRAM, kind_of
from .formats import PLATE_ID
from .text import DISTANCE, EXCEPT_WORDS

LINE_SEPARATOR = " / "  # how a plate's text joins its lines (plate_text.normalise_text)
MAX_INSCRIPTIONS = 3  # Signalo's inscription_1..3


def text_lines(text: Optional[str]) -> list:
    """The non-empty lines of a plate's text."""
    return [line.strip() for line in (text or "").split(LINE_SEPARATOR) if line.strip()]


def is_exception(lines: list) -> bool:
    """Whether a plate's lines start with the word for "except" (in any of the plates' languages)."""
    return bool(lines) and lines[0].lower() in {w.lower() for w in EXCEPT_WORDS.values()}


def text_plate_id(text: Optional[str]) -> str:
    """The SSV id of a text plate that says ``text`` (normalised, lines joined by " / "); ``plate`` for none."""
    lines = text_lines(text)
    if not lines:
        return PLATE_ID
    if is_exception(lines):
        return EXCEPTION_PLATE
    if len(lines) == 1 and DISTANCE.fullmatch(lines[0]):
        return DISTANCE_PLATE
    return FREE_TEXT_PLATES[min(len(lines), len(FREE_TEXT_PLATES)) - 1]


def inscriptions(template_id: str, text: Optional[str]) -> list:
    """Signalo's inscriptions of a plate: the free text of a text or layout plate in at most ``MAX_INSCRIPTIONS``
    lines (the last holding the rest); none for a pictogram plate (its text is its drawing's words)."""
    if kind_of(template_id) == PICTOGRAM:
        return []
    lines = text_lines(text)
    if template_id in (EXCEPTION_PLATE, PLATE_ID) and is_exception(lines):
        lines = lines[1:]
    if len(lines) > MAX_INSCRIPTIONS:
        lines = lines[:MAX_INSCRIPTIONS - 1] + [" ".join(lines[MAX_INSCRIPTIONS - 1:])]
    return lines
