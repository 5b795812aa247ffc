"""Attribute schema of the detection (and later sign) layers, and conversion from core results."""

from __future__ import annotations

from qgis.core import QgsFeature, QgsField, QgsFields, QgsGeometry, QgsPoint
from qgis.PyQt.QtCore import QVariant

# name, type, length/precision hint; order is the order in the layer
DETECTION_FIELDS = [
    ("template_id", QVariant.String),
    ("name", QVariant.String),
    ("colour", QVariant.String),
    ("shape", QVariant.String),
    ("width_m", QVariant.Double),
    ("height_m", QVariant.Double),
    ("format", QVariant.String),
    ("detection_indicator", QVariant.Double),
    ("classification_indicator", QVariant.Double),
    ("status", QVariant.String),
    ("reviewed", QVariant.Int),
    ("source", QVariant.String),
    ("pair_id", QVariant.String),
    ("time", QVariant.Double),
    ("u", QVariant.Double),
    ("v", QVariant.Double),
    ("bbox_x", QVariant.Int),
    ("bbox_y", QVariant.Int),
    ("bbox_w", QVariant.Int),
    ("bbox_h", QVariant.Int),
    ("depth_m", QVariant.Double),
]


# The fused layer "signs": one feature per physical sign. Pixel fields (pair_id, time, u, v, bbox_*, depth_m)
# describe its best observation, the one the review dock shows first.
SIGN_FIELDS = [("sign_id", QVariant.Int)] + DETECTION_FIELDS[:12] + [
    ("n_obs", QVariant.Int),
    ("vote_share", QVariant.Double),
    ("sigma_m", QVariant.Double),
    ("azimuth", QVariant.Double),
    ("mount_height_m", QVariant.Double),
    ("best_pair_id", QVariant.String),
] + DETECTION_FIELDS[13:]

# Detections additionally name the sign they were fused into.
DETECTION_LAYER_FIELDS = DETECTION_FIELDS + [("sign_id", QVariant.Int)]

STATUSES = ("accepted", "review", "rejected", "manual")


def make_fields(spec) -> QgsFields:
    fields = QgsFields()
    for name, kind in spec:
        fields.append(QgsField(name, kind))
    return fields


def detection_fields() -> QgsFields:
    return make_fields(DETECTION_FIELDS)


def detection_feature(fields: QgsFields, detection, record) -> QgsFeature:
    """A PointZ feature for one core ``Detection`` seen in pair ``record``."""
    east, north, up = (float(c) for c in detection.position)
    feature = QgsFeature(fields)
    feature.setGeometry(QgsGeometry(QgsPoint(east, north, up)))
    x, y, w, h = (int(c) for c in detection.bbox)
    feature.setAttributes([
        detection.template_id, detection.name, detection.colour, detection.shape,
        float(detection.width_m), float(detection.height_m), detection.format,
        round(float(detection.detection_indicator), 4), round(float(detection.classification_indicator), 4),
        detection.status, 0, getattr(detection, "source", "colour"),
        record.id, float(record.time), round(float(detection.u), 2), round(float(detection.v), 2),
        x, y, w, h, round(float(detection.depth_m), 3),
    ])
    return feature
