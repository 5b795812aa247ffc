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


def _point_feature(fields: QgsFields, position, attributes: list) -> QgsFeature:
    feature = QgsFeature(fields)
    east, north, up = (float(c) for c in position)
    feature.setGeometry(QgsGeometry(QgsPoint(east, north, up)))
    feature.setAttributes(attributes)
    return feature


def _sign_attributes(item) -> list:
    """The attributes shared by detections and signs, from a Detection or an Observation."""
    return [
        item.template_id, item.name, item.colour, item.shape,
        float(item.width_m), float(item.height_m), item.format,
        round(float(item.detection_indicator), 4), round(float(item.classification_indicator), 4),
        item.status, 0, item.source,
    ]


def _pixel_attributes(pair_id, time, obs) -> list:
    x, y, w, h = (int(c) for c in obs.bbox)
    return [pair_id, float(time), round(float(obs.u), 2), round(float(obs.v), 2), x, y, w, h,
            round(float(obs.depth_m), 3)]


def detection_feature(fields: QgsFields, observation) -> QgsFeature:
    """A PointZ feature for one observation (a detection in its pair), linked to its sign by ``sign_id``."""
    attributes = _sign_attributes(observation) + _pixel_attributes(observation.pair_id, observation.time, observation)
    if fields.indexOf("sign_id") >= 0:
        attributes.append(observation.sign_id)
    return _point_feature(fields, observation.position, attributes)


def sign_feature(fields: QgsFields, sign) -> QgsFeature:
    """A PointZ feature for one fused sign; the pixel fields describe its best observation."""
    best = sign.best
    attributes = [sign.sign_id] + _sign_attributes(sign) + [
        sign.n_obs, round(float(sign.vote_share), 3), round(float(sign.sigma_m), 4),
        None if sign.azimuth is None else round(float(sign.azimuth), 1),
        None if sign.mount_height_m is None else round(float(sign.mount_height_m), 2),
        best.pair_id,
    ] + _pixel_attributes(best.pair_id, best.time, best)[1:]
    return _point_feature(fields, sign.position, attributes)
