"""Attribute values of review decisions: accept, reject, reclassify, and a manually added sign."""

from __future__ import annotations

from typing import Optional

from qgis.core import NULL, QgsFeature, QgsGeometry, QgsPoint

ACCEPTED, REVIEW, REJECTED, MANUAL = "accepted", "review", "rejected", "manual"  # algorithms/sign_fields.STATUSES
DEFAULT_FORMAT = "normal"


def accept_values() -> dict:
    return {"status": ACCEPTED, "reviewed": 1}


def reject_values() -> dict:
    return {"status": REJECTED, "reviewed": 1}


def template_format(entry, current_format: Optional[str]):
    """(name, (w, h)) of the new template's format: the current one if it has it, else "normal", else its first."""
    for name in (current_format, DEFAULT_FORMAT):
        if name and name in entry.formats:
            return name, entry.formats[name]
    name = next(iter(entry.formats))
    return name, entry.formats[name]


def reclassify_values(entry, current_format: Optional[str], current_status: str) -> dict:
    """A person assigned template ``entry``: its id, name, colour, shape and size, reviewed."""
    name, (width, height) = template_format(entry, current_format)
    return {
        "template_id": entry.id, "name": entry.name("de"), "colour": entry.colour, "shape": entry.shape,
        "width_m": float(width), "height_m": float(height), "format": name,
        "status": MANUAL if current_status == MANUAL else ACCEPTED, "reviewed": 1,
    }


def manual_feature(layer, item) -> QgsFeature:
    """A PointZ feature for a sign a person clicked: an Observation (detections) or its manual FusedSign (signs).

    Fields are matched by name so both layer kinds work.
    """
    east, north, up = (float(c) for c in item.position)
    best = getattr(item, "best", item)
    x, y, w, h = (int(c) for c in best.bbox)
    is_sign = best is not item
    values = {
        "template_id": item.template_id, "name": item.name, "colour": item.colour,
        "shape": item.shape, "width_m": float(item.width_m), "height_m": float(item.height_m),
        "format": item.format, "detection_indicator": round(float(item.detection_indicator), 4),
        "classification_indicator": round(float(item.classification_indicator), 4),
        "status": MANUAL, "reviewed": 1, "source": item.source,
        "pair_id": best.pair_id, "best_pair_id": best.pair_id, "time": float(best.time),
        "u": round(float(best.u), 2), "v": round(float(best.v), 2),
        "bbox_x": x, "bbox_y": y, "bbox_w": w, "bbox_h": h, "depth_m": round(float(best.depth_m), 3),
        "sign_id": item.sign_id, "n_obs": item.n_obs if is_sign else None,
        "vote_share": item.vote_share if is_sign else None,
        "azimuth": item.azimuth if is_sign else None,
    }
    fields = layer.fields()
    feature = QgsFeature(fields)
    for name in fields.names():
        if name in values:
            feature[name] = NULL if values[name] is None else values[name]
    feature.setGeometry(QgsGeometry(QgsPoint(east, north, up)))
    return feature
