"""Which reference signs a drive could have mapped at all.

A sign counts only if, in at least one pair, its centre projects inside the
image at a depth within the search range and its face (not its back) is turned
towards the camera. Detection rates are computed over these signs, so a sign the
vehicle never saw does not count as missed.
"""

from __future__ import annotations

import numpy as np

from .geometry import world_to_pixel


def facing_vector(azimuth_deg: float) -> np.ndarray:
    a = np.radians(azimuth_deg)
    return np.array([np.sin(a), np.cos(a), 0.0])


def visible_in_pair(camera, pose, sign, near_m: float, far_m: float, max_face_angle_deg: float = 75.0) -> bool:
    u, v, z = world_to_pixel(camera, pose, sign.position)
    if not (near_m <= z <= far_m and 0 <= u <= camera.width - 1 and 0 <= v <= camera.height - 1):
        return False
    to_camera = pose.centre - sign.position
    to_camera[2] = 0.0
    norm = np.linalg.norm(to_camera)
    if norm == 0:
        return False
    cos_angle = float(facing_vector(sign.facing) @ (to_camera / norm))
    return cos_angle >= np.cos(np.radians(max_face_angle_deg))


def mappable_signs(drive, near_m: float = 4.0, far_m: float = 14.0) -> list:
    """Truth signs of ``drive`` seen face-on within the depth range in at least one pair."""
    if not drive.truth:
        return []
    return [
        sign for sign in drive.truth
        if any(visible_in_pair(drive.camera, rec.pose, sign, near_m, far_m) for rec in drive.pairs)
    ]
