"""Attribute values of review decisions: accept, reject, reclassify, and a manually added sign."""

from __future__ import annotations

import math
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


def _facing_camera(east: float, north: float, pose) -> float:
    """Azimuth (degrees from grid north) from the sign towards the camera: a face seen face-on looks that way."""
    return math.degrees(math.atan2(pose.easting - east, pose.northing - north)) % 360.0


def manual_feature(layer, detection, record, next_sign_id: Optional[int] = None) -> QgsFeature:
    """A PointZ feature for a sign a person clicked; fields are matched by name so both layer kinds work."""
    east, north, up = (float(c) for c in detection.position)
    x, y, w, h = (int(c) for c in detection.bbox)
    values = {
        "template_id": detection.template_id, "name": detection.name, "colour": detection.colour,
        "shape": detection.shape, "width_m": float(detection.width_m), "height_m": float(detection.height_m),
        "format": detection.format, "detection_indicator": round(float(detection.detection_indicator), 4),
        "classification_indicator": round(float(detection.classification_indicator), 4),
        "status": MANUAL, "reviewed": 1, "source": detection.source,
        "pair_id": record.id, "best_pair_id": record.id, "time": float(record.time),
        "u": round(float(detection.u), 2), "v": round(float(detection.v), 2),
        "bbox_x": x, "bbox_y": y, "bbox_w": w, "bbox_h": h, "depth_m": round(float(detection.depth_m), 3),
        "sign_id": next_sign_id, "n_obs": 1 if next_sign_id is not None else None,
        "vote_share": 1.0 if next_sign_id is not None else None,
        "azimuth": _facing_camera(east, north, record.pose) if next_sign_id is not None else None,
    }
    fields = layer.fields()
    feature = QgsFeature(fields)
    for name in fields.names():
        if name in values:
            feature[name] = NULL if values[name] is None else values[name]
    feature.setGeometry(QgsGeometry(QgsPoint(east, north, up)))
    return feature
