"""Attribute values of review decisions: accept, reject, reclassify, and a manually added sign.

What each writes follows ``signmapper_core.output.schema``: statuses, the
fields a catalogue entry gives (reclassify) and the fields of a new feature.
"""

from __future__ import annotations

from typing import Optional

from ..gpkg.fields import layer_feature
from ..signmapper_core.output.schema import DEFAULT_LANGUAGE, OutputContext, template_values
from ..signmapper_core.plates.text import normalise_text
from ..signmapper_core.statuses import ACCEPTED, MANUAL, REJECTED

DEFAULT_FORMAT = "normal"


def accept_values() -> dict:
    return {"status": ACCEPTED, "reviewed": 1}


def reject_values() -> dict:
    return {"status": REJECTED, "reviewed": 1}


def plate_text_values(text: str, current_status: str, current_template_id: str = "",
                      context: Optional[OutputContext] = None) -> dict:
    """A person read the plate and set its text: certain (confidence 1), the plate accepted and reviewed.
    Spelt as the mapping writes texts (``plate_text``): lines joined by " / ". A text plate (or one mapped
    untyped) is typed again by what it now says (``plate_types``), named in ``context``'s language."""
    from ..signmapper_core.catalogue.plates_ch import TEXT, kind_of  # delays OpenCV and numpy until used
    from ..signmapper_core.plates.types import text_plate_id  # delays OpenCV and numpy until used

    lines = [line for line in text.replace("\n", " / ").split("/")]
    written = normalise_text(lines)
    values = {"text": written or None, "text_confidence": 1.0 if written else None,
              "status": MANUAL if current_status == MANUAL else ACCEPTED, "reviewed": 1}
    if current_template_id and kind_of(current_template_id) == TEXT:
        typed = text_plate_id(written)
        values.update(template_id=typed, name=(context or OutputContext()).name(typed, typed))
    return values


def template_format(entry, current_format: Optional[str]) -> str:
    """The new template's format: the current one if it has it, else "normal", else its first."""
    for name in (current_format, DEFAULT_FORMAT):
        if name and name in entry.formats:
            return name
    return next(iter(entry.formats))


def reclassify_values(layer_kind: str, entry, current_format: Optional[str], current_status: str,
                      language: str = DEFAULT_LANGUAGE) -> dict:
    """A person assigned template ``entry``: what the template gives (id, name, colour, shape, size), reviewed."""
    values = template_values(layer_kind, entry, template_format(entry, current_format), language)
    values.update(status=MANUAL if current_status == MANUAL else ACCEPTED, reviewed=1)
    return values


def manual_feature(layer, layer_kind: str, item, context: Optional[OutputContext] = None):
    """A feature for a sign a person clicked: its Observation (detections) or manual FusedSign (signs)."""
    return layer_feature(layer.fields(), layer_kind, item, context)
