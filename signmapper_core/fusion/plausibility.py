"""Whether a fused sign can be a sign where and as it was mapped: a sign that cannot waits for a person.

Three rules, each with a review reason of its own (``output.review_reasons``), on the settings of
``FusionConfig``; a sign the mapping accepted that breaks one goes to ``review`` with the first it breaks, none
is dropped (a face below the road may be a sign's reflection in a puddle, but a person looks):

- mounted too low: its face centre less than ``min_centre_above_road_m`` above the road beside it. The road is
  the nearest camera position less the camera's height above the road (:mod:`.mounting`), so the rule needs
  ``vehicle.camera_height_m`` in drive.json; without it it does not apply.
- turned away from the road: its face looks more than ``max_face_turn_deg`` away from the trajectory (from the
  sign towards the nearest point of the camera's path). A sign beside the road faces along it, ~90° from
  that direction; one on the back of a pole faces the other carriageway, also ~90°; a face turned towards the
  houses cannot have been read from the road.
- far from the road: more than ``max_lateral_m`` beside the trajectory, across its direction (a sign seen
  beyond the end of the drive is measured across the path's last direction, not along it).
"""

from __future__ import annotations

from typing import Optional, Sequence

import numpy as np

from ..output.review_reasons import FACES_AWAY, FAR_FROM_ROAD, MOUNTED_TOO_LOW
from ..statuses import ACCEPTED, REVIEW
from .mounting import height_above_road


def nearest_on_path(position: np.ndarray, path: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(the nearest point, the unit direction there) of the polyline ``path`` (camera centres in driving order),
    horizontally. A path of one point has the direction north."""
    xy = np.asarray(path, float).reshape(-1, 3)[:, :2]
    p = np.asarray(position, float)[:2]
    if len(xy) == 1:
        return xy[0], np.array([0.0, 1.0])
    starts, steps = xy[:-1], np.diff(xy, axis=0)
    lengths2 = np.maximum((steps ** 2).sum(axis=1), 1e-12)
    t = np.clip(((p - starts) * steps).sum(axis=1) / lengths2, 0.0, 1.0)
    points = starts + t[:, None] * steps
    k = int(np.argmin(((points - p) ** 2).sum(axis=1)))
    return points[k], steps[k] / np.sqrt(lengths2[k])


def lateral_distance(position: np.ndarray, path: np.ndarray) -> float:
    """Horizontal distance of ``position`` from the path, across the path's direction at its nearest point."""
    point, direction = nearest_on_path(position, path)
    offset = np.asarray(position, float)[:2] - point
    return float(abs(offset[0] * direction[1] - offset[1] * direction[0]))


def face_turn_deg(azimuth_deg: Optional[float], position: np.ndarray, path: np.ndarray) -> Optional[float]:
    """Angle [deg] between the direction a face looks to (azimuth, clockwise from north) and the direction from it
    to the nearest point of the path; None without an azimuth or with the sign on the path."""
    if azimuth_deg is None:
        return None
    point, _ = nearest_on_path(position, path)
    towards = point - np.asarray(position, float)[:2]
    if np.hypot(*towards) < 1e-6:
        return None
    looks = np.array([np.sin(np.radians(azimuth_deg)), np.cos(np.radians(azimuth_deg))])
    cos = float(looks @ towards / np.hypot(*towards))
    return float(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))


def implausibility(sign, path: np.ndarray, camera_height_m: Optional[float], config) -> Optional[str]:
    """The first rule a fused sign breaks (a review reason), or None. ``path``: the drive's camera centres in
    driving order; ``camera_height_m``: the camera's height above the road, None when the drive does not state it;
    ``config``: the ``FusionConfig``."""
    above = height_above_road(sign.position, path, camera_height_m)
    if above is not None and above < config.min_centre_above_road_m:
        return MOUNTED_TOO_LOW
    turn = face_turn_deg(sign.azimuth, sign.position, path)
    if turn is not None and turn > config.max_face_turn_deg:
        return FACES_AWAY
    if lateral_distance(sign.position, path) > config.max_lateral_m:
        return FAR_FROM_ROAD
    return None


def hold_implausible(signs: Sequence, path: np.ndarray, camera_height_m: Optional[float], config) -> int:
    """Send every accepted sign that breaks a rule (:func:`implausibility`) to review with its reason; a sign
    already in review keeps the reason that held it. Returns how many were sent."""
    if len(path) == 0:
        return 0
    held = 0
    for sign in signs:
        if sign.status != ACCEPTED:
            continue
        reason = implausibility(sign, path, camera_height_m, config)
        if reason is not None:
            sign.status, sign.review_reason = REVIEW, reason
            held += 1
    return held
