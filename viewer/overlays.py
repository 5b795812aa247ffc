"""What a pair of the drive shows over its left image: the mapped signs projected into it, its own detections.

Signs come from the map (their 3D point, standard size and status), so a sign
mapped from other pairs, or added by hand, shows where it should be; a pair's
detections are the boxes measured in exactly this image. Colours are the
status colours of ``output.schema``; projected boxes are dashed.
"""

from __future__ import annotations

import math
from typing import List

from qgis.core import QgsFeatureRequest, QgsRectangle

from ..gpkg.fields import feature_values
from ..review.layers import features_where
from ..signmapper_core.drive.viewing import project_sign
from ..signmapper_core.output.schema import DETECTIONS, SIGNS
from ..signmapper_core.statuses import STATUS_COLOURS
from ..ui.image_view import OverlayBox

SHOWN_WITHIN_M = 40.0  # signs farther from the camera are too small to draw usefully
OTHER_COLOUR = "#ffffff"


def key(kind: str, fid: int) -> str:
    return f"{kind}:{fid}"


def parse_key(text: str):
    kind, _, fid = text.partition(":")
    return kind, int(fid)


def faces_camera(azimuth, sign_xy, camera_xy) -> bool:
    """False only when the face is known to look away from the camera (we would see its back)."""
    if azimuth is None:
        return True
    to_camera = math.atan2(camera_xy[0] - sign_xy[0], camera_xy[1] - sign_xy[1])
    return math.cos(to_camera - math.radians(azimuth)) > -0.2


def sign_boxes(layer, camera, record) -> List[OverlayBox]:
    """The signs of ``layer`` near the pair's camera, projected into its left image."""
    pose = record.pose
    d = SHOWN_WITHIN_M
    request = QgsFeatureRequest().setFilterRect(QgsRectangle(pose.easting - d, pose.northing - d,
                                                             pose.easting + d, pose.northing + d))
    boxes = []
    for feature in layer.getFeatures(request):
        if not feature.hasGeometry():
            continue
        point = feature.geometry().constGet()
        z = point.z() if point.is3D() else None
        values = feature_values(feature, SIGNS)
        if z is None or z != z or not values["width_m"] or not values["height_m"]:
            continue
        if not faces_camera(values["azimuth"], (point.x(), point.y()), (pose.easting, pose.northing)):
            continue
        box = project_sign(camera, pose, (point.x(), point.y(), z), values["width_m"], values["height_m"])
        if box is None or box.depth_m > SHOWN_WITHIN_M:
            continue
        status = values["status"] or ""
        label = f"{values['template_id'] or '?'} #{values['sign_id']}" if values["sign_id"] is not None else \
            values["template_id"] or "?"
        boxes.append(OverlayBox(key(SIGNS, feature.id()), box.bbox, STATUS_COLOURS.get(status, OTHER_COLOUR),
                                label, dashed=True))
    return boxes


def detection_boxes(layer, record) -> List[OverlayBox]:
    """The detections made in this pair, as measured."""
    boxes = []
    for feature in features_where(layer, "pair_id", record.id):
        values = feature_values(feature, DETECTIONS)
        bbox = tuple(values[k] for k in ("bbox_x", "bbox_y", "bbox_w", "bbox_h"))
        if any(c is None for c in bbox):
            continue
        status = values["status"] or ""
        boxes.append(OverlayBox(key(DETECTIONS, feature.id()), tuple(float(c) for c in bbox),
                                STATUS_COLOURS.get(status, OTHER_COLOUR), ""))
    return boxes
