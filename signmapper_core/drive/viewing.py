"""Looking through a drive: where mapped signs appear in a pair, what the camera sees on the map, which pair
sees a place best. Used by the drive viewer; pure geometry on the drive's camera and poses.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple

import numpy as np

from ..geometry import pixel_to_world, world_to_pixel
from ..pipeline.config import DepthConfig

NEAREST_M = 1.0  # nearer than this a projected sign is not drawn (it fills the frame)
VIEW_MARGIN = 0.05  # share of the image width a place must keep from the border to count as well seen


@dataclass(frozen=True)
class ProjectedBox:
    """A 3D sign face as it appears in the left image of one pair."""

    u: float  # centre column (pixel centres at integers)
    v: float
    depth_m: float
    bbox: Tuple[float, float, float, float]  # x, y, w, h of the face's box


def project_sign(camera, pose, position, width_m: float, height_m: float) -> Optional[ProjectedBox]:
    """The box of a face of ``width_m`` x ``height_m`` centred at ``position`` (E, N, H), facing the camera.

    None when the centre is behind the camera, nearer than NEAREST_M or its box misses the image.
    """
    u, v, z = (float(np.ravel(a)[0]) for a in world_to_pixel(camera, pose, np.asarray(position, float)))
    if not z > NEAREST_M:
        return None
    w, h = camera.fx * width_m / z, camera.fy * height_m / z
    x, y = u - w / 2.0, v - h / 2.0
    if x + w < 0 or y + h < 0 or x > camera.width - 1 or y > camera.height - 1:
        return None
    return ProjectedBox(u, v, z, (x, y, w, h))


def view_cone(camera, pose, far_m: float) -> List[Tuple[float, float]]:
    """The camera's horizontal field of view up to ``far_m`` on the map: (E, N) of apex, left edge, right edge."""
    edges = pixel_to_world(camera, pose, np.array([0.0, camera.width - 1.0]), np.array([camera.cy, camera.cy]),
                           np.array([far_m, far_m]))
    centre = pose.centre
    return [(float(centre[0]), float(centre[1]))] + [(float(e[0]), float(e[1])) for e in edges]


def nearest_pair(pairs: Sequence, east: float, north: float) -> Tuple[int, float]:
    """(index into ``pairs``, planimetric distance [m]) of the pose nearest to a map point."""
    xy = np.array([[p.pose.easting, p.pose.northing] for p in pairs])
    d = np.hypot(xy[:, 0] - east, xy[:, 1] - north)
    i = int(np.argmin(d))
    return i, float(d[i])


def best_pair_for(camera, pairs: Sequence, east: float, north: float, height: Optional[float] = None,
                  near_m: float = DepthConfig.near_m, far_m: float = DepthConfig.far_m) -> Optional[int]:
    """Index of the pair that sees a map place best, None if no pair has it in view.

    A place is seen well when it is in front of the camera inside the image
    (with a margin) within the depth range; the best such pair sees it from
    nearest, as the mapping does. Without a ``height`` the place is taken at
    each camera's own height (a click on the map has none).
    """
    best, best_depth = None, np.inf
    margin = VIEW_MARGIN * camera.width
    for i, record in enumerate(pairs):
        pose = record.pose
        point = np.array([east, north, pose.height if height is None else height])
        u, v, z = (float(np.ravel(a)[0]) for a in world_to_pixel(camera, pose, point))
        if not (near_m <= z <= far_m) or not (margin <= u <= camera.width - 1 - margin):
            continue
        if height is not None and not 0 <= v <= camera.height - 1:
            continue
        if z < best_depth:
            best, best_depth = i, z
    return best
