"""Where a depth range is searched: near..far anywhere in the frame, and out to the reach where a face is never
seen within far.

Driving straight on, a point at share e of the way from the principal point to the frame's edge
(:func:`edge_share`) at depth Z leaves the view at depth Z e; and where the camera moves on only d along its axis
before the drive ends or turns (``DepthConfig.ahead_m``, ``drive/path_ahead.py``), it comes no closer than Z - d.
Where either is beyond far, the sign is never seen closer, and its views out to the reach are the best it gets
(``pipeline/depth_range.py`` sets the limits).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from ..geometry import Camera
from .config import DepthConfig
from .locate import bbox_centre


def edge_share(camera: Camera, u, v):
    """How far (u, v) is from the principal point towards the frame's nearest edge it moves to, 0..1:
    the larger of the horizontal and vertical shares (a point leaves the view by whichever edge it reaches
    first)."""
    u, v = np.asarray(u, dtype=np.float32), np.asarray(v, dtype=np.float32)
    right, bottom = camera.width - 1 - camera.cx, camera.height - 1 - camera.cy
    du = np.where(u >= camera.cx, (u - camera.cx) / right, (camera.cx - u) / camera.cx)
    dv = np.where(v >= camera.cy, (v - camera.cy) / bottom, (camera.cy - v) / camera.cy)
    return np.clip(np.maximum(du, dv), 0.0, 1.0)


@lru_cache(maxsize=4)
def edge_share_image(camera: Camera) -> np.ndarray:
    """:func:`edge_share` of every pixel (float32, height x width)."""
    shares = edge_share(camera, np.arange(camera.width, dtype=np.float32)[None, :],
                        np.arange(camera.height, dtype=np.float32)[:, None]).astype(np.float32)
    shares.flags.writeable = False  # cached and shared by every pair of the camera
    return shares


def closest_depth(z, edge, depth: DepthConfig):
    """The depth a face at depth ``z`` and edge share ``edge`` comes to at the closest before it leaves the view
    (z x edge) or the camera stops coming nearer (z - ``depth.ahead_m``), whichever is farther."""
    z = np.asarray(z, dtype=np.float32)
    closest = z * edge
    if depth.ahead_m is not None:
        closest = np.maximum(closest, z - np.float32(depth.ahead_m))
    return closest


def path_limit_m(depth: DepthConfig) -> float:
    """How far ahead a pair's path matters: a camera that moves on this far brings every face within the reach
    within far (0: no reach, the path does not matter)."""
    return max(0.0, (depth.reach_m or depth.far_m) - depth.far_m)


def in_search_range(z, edge, depth: DepthConfig, slack: float = 0.0):
    """Whether depth ``z`` at edge share ``edge`` is searched: near..far anywhere, and up to the reach where
    the face is never seen within far (:func:`closest_depth`). ``slack`` widens every limit by that share."""
    z = np.asarray(z, dtype=np.float32)
    with np.errstate(invalid="ignore"):
        inside = (z >= depth.near_m * (1.0 - slack)) & (z <= depth.far_m * (1.0 + slack))
        if depth.reach_m and depth.reach_m > depth.far_m:
            inside |= ((closest_depth(z, edge, depth) >= depth.far_m * (1.0 - slack))
                       & (z <= depth.reach_m * (1.0 + slack)))
    return inside


def face_depth(plane_depth: float, median_depth: float, camera: Camera, u: float, v: float, depth: DepthConfig,
               slack: float) -> float:
    """Depth of a face's centre (u, v): on its fitted plane, or the segment's median depth where the plane
    puts it outside the search range widened by ``slack`` (a face reaching past the range's limits)."""
    if np.isfinite(plane_depth) and in_search_range(plane_depth, edge_share(camera, u, v), depth, slack):
        return float(plane_depth)
    return float(median_depth)


def _box_edge_share(camera: Camera, bbox) -> float:
    return float(edge_share(camera, *bbox_centre(bbox)))


def face_depth_limits(camera: Camera, bbox, depth: DepthConfig) -> tuple:
    """(nearest, farthest) depth a face in pixel box ``bbox`` (x, y, w, h) is measured within: near..far, or out to
    the reach where a face there at the reach is never seen within far."""
    edge = _box_edge_share(camera, bbox)
    reaches = (depth.reach_m and depth.reach_m > depth.far_m
               and closest_depth(depth.reach_m, edge, depth) >= depth.far_m)
    return depth.near_m, depth.reach_m if reaches else depth.far_m


def face_in_range(camera: Camera, bbox, z: float, depth: DepthConfig) -> bool:
    """Whether a face in pixel box ``bbox`` measured at depth ``z`` lies in the search range (its limits widened
    by ``face_depth_slack``): a face beside one in range, taken in by the search space's growth, is not."""
    return bool(in_search_range(z, _box_edge_share(camera, bbox), depth, depth.face_depth_slack))
