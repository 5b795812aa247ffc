"""Which reference signs a drive could have mapped at all.

A sign counts only if, in at least one pair, its centre projects inside the
image at a depth within the search range and its face (not its back) is turned
towards the camera. Detection rates are computed over these signs, so a sign the
vehicle never saw does not count as missed.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..drive.path_ahead import path_ahead
from ..geometry import world_to_pixel
from ..pipeline.config import DepthConfig
from ..pipeline.search_range import edge_share, in_search_range, path_limit_m

DEFAULT_RANGE = DepthConfig()  # the default range without a camera: no reach at the frame's edges
READABLE_FACE_ANGLE_DEG = 75.0  # a face turned farther than this away from the camera cannot be read


def facing_vector(azimuth_deg: float) -> np.ndarray:
    a = np.radians(azimuth_deg)
    return np.array([np.sin(a), np.cos(a), 0.0])


def visible_in_pair(camera, pose, sign, depth: DepthConfig = DEFAULT_RANGE,
                    max_face_angle_deg: float = READABLE_FACE_ANGLE_DEG) -> bool:
    """Whether ``sign``'s centre is in the image within the search range of ``depth`` (its reach at the frame's
    edges too) with its face turned towards the camera."""
    u, v, z = world_to_pixel(camera, pose, sign.position)
    if not (0 <= u <= camera.width - 1 and 0 <= v <= camera.height - 1
            and in_search_range(z, edge_share(camera, u, v), depth)):
        return False
    to_camera = pose.centre - sign.position
    to_camera[2] = 0.0
    norm = np.linalg.norm(to_camera)
    if norm == 0:
        return False
    cos_angle = float(facing_vector(sign.facing) @ (to_camera / norm))
    return cos_angle >= np.cos(np.radians(max_face_angle_deg))


def pose_ranges(poses, depth: DepthConfig) -> list:
    """The search range from each of a drive's ``poses``: ``depth`` with the pose's path ahead where it has a
    reach, as the mapping searches it."""
    if path_limit_m(depth) <= 0 or not poses:
        return [depth] * len(poses)
    ahead = path_ahead(poses, depth.turn_deg, path_limit_m(depth))
    return [dataclasses.replace(depth, ahead_m=float(a)) for a in ahead]


def pair_ranges(drive, depth: DepthConfig) -> list:
    """:func:`pose_ranges` of the poses of ``drive``'s pairs."""
    return pose_ranges([record.pose for record in drive.pairs], depth)


def mappable_signs(drive, depth: DepthConfig = DEFAULT_RANGE, plates: bool = False) -> list:
    """Truth signs of ``drive`` seen face-on within the depth range in at least one pair.

    Supplementary plates (rows with ``plate_of``) are left out, or with ``plates`` only they are given.
    """
    if not drive.truth:
        return []
    ranges = pair_ranges(drive, depth)
    return [
        sign for sign in drive.truth
        if sign.is_plate == plates
        and any(visible_in_pair(drive.camera, rec.pose, sign, pair_range)
                for rec, pair_range in zip(drive.pairs, ranges))
    ]


def largest_view_px(drive, sign, ranges: list) -> float:
    """Height in pixels of ``sign``'s face in the pair that sees it largest within its search range (0 if none);
    ``ranges``: :func:`pair_ranges` of the drive, computed once for all its signs."""
    best = 0.0
    for rec, pair_range in zip(drive.pairs, ranges):
        if visible_in_pair(drive.camera, rec.pose, sign, pair_range):
            z = world_to_pixel(drive.camera, rec.pose, sign.position)[2]
            best = max(best, drive.camera.fy * sign.height_m / z)
    return best


def densify(polyline_xy, step_m: float) -> np.ndarray:
    """Vertices every ``step_m`` metres along a polyline (a line layer may have only its ends)."""
    pts = np.asarray(polyline_xy, float).reshape(-1, 2)
    if len(pts) < 2:
        return pts
    seg = np.hypot(*np.diff(pts, axis=0).T)
    chain = np.concatenate([[0.0], np.cumsum(seg)])
    stations = np.arange(0.0, chain[-1] + 1e-9, step_m)
    return np.column_stack([np.interp(stations, chain, pts[:, 0]), np.interp(stations, chain, pts[:, 1])])


def faces_trajectory(position_xy, facing_deg: float, trajectory_xy: np.ndarray, max_distance_m: float = 20.0,
                     max_face_angle_deg: float = READABLE_FACE_ANGLE_DEG) -> bool:
    """True if from some trajectory vertex within ``max_distance_m`` the sign is ahead and its face looks back.

    For references without a camera model (a surveyed inventory with a facing
    azimuth), with a forward-looking camera: a sign whose face never looks
    towards an approaching vehicle cannot be mapped from the drive, such as the
    far sign of a back-to-back pair on a one-way drive.
    """
    traj = densify(trajectory_xy, step_m=1.0)
    if len(traj) < 2:
        return False
    heading = np.gradient(traj, axis=0)
    to_sign = np.asarray(position_xy, float)[:2] - traj
    dist = np.hypot(to_sign[:, 0], to_sign[:, 1])
    ahead = (to_sign * heading).sum(axis=1) > 0
    near = (dist > 0) & (dist <= max_distance_m) & ahead
    if not near.any():
        return False
    face = facing_vector(facing_deg)[:2]
    cos_angle = (-to_sign[near] @ face) / dist[near]
    return bool((cos_angle >= np.cos(np.radians(max_face_angle_deg))).any())
