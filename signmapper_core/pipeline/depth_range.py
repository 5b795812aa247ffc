"""The search range a drive's camera gives: near and far limits across the frame, and a reach at its edges.

A stereo depth's uncertainty grows with the square of the depth, σ_Z = Z² σ_d / (f B), so how far a camera
measures a sign well depends on its focal length f and baseline B, not on a constant. Three rules:

- **far**: the depth is still known to ``survey_sigma_m`` (a few centimetres): Z = sqrt(σ f B / σ_d).
- **near**: the matcher's disparity search reaches ``max_disparity_share`` of the image width: Z = f B / d_max.
  Closer faces are cut by the frame anyway; searching them costs the matcher a wider disparity range.
- **reach**: a sign that leaves the view before it comes within *far* (far to the side, high over the road,
  across a junction) is searched where it is seen best, out to where a normal-format disc (SSV Annex 1,
  60 cm) still spans ``ColourConfig.min_face_px`` and its depth is known to ``placing_sigma_m``.

For the paper's camera (1920 x 1080, f = 1750 px, B = 0.9 m) the first two give 4 and 14 m, the range Cavegn
(2011) searched. Whether a face at depth Z will leave the view before it comes within *far* follows from where
it is in the image (:func:`edge_share`): driving straight on, a point at share e of the way from the principal
point to the frame's edge leaves the view at depth Z e.
"""

from __future__ import annotations

import dataclasses
import math
from functools import lru_cache

import numpy as np

from ..catalogue.formats import ROUND
from ..geometry import Camera
from .config import DepthConfig

READ_FACE_M = min(ROUND["normal"])  # the normal disc: the format of most regulatory signs


def depth_known_to(camera: Camera, sigma_m: float, disparity_sigma_px: float) -> float:
    """The depth [m] up to which a stereo depth is known to ``sigma_m``."""
    return math.sqrt(sigma_m * camera.fx * camera.baseline_m / disparity_sigma_px)


def readable_depth(camera: Camera, face_m: float, min_face_px: float) -> float:
    """The depth [m] up to which a face ``face_m`` wide spans ``min_face_px`` pixels."""
    return min(camera.fx, camera.fy) * face_m / min_face_px


def camera_depth_range(camera: Camera, depth: DepthConfig, min_face_px: float) -> DepthConfig:
    """``depth`` with near_m, far_m and reach_m from ``camera`` by the module's rules, in whole metres
    (near at least 1 m; far above near; reach at least far)."""
    near = camera.fx * camera.baseline_m / (depth.max_disparity_share * camera.width)
    far = depth_known_to(camera, depth.survey_sigma_m, depth.disparity_sigma_px)
    reach = min(readable_depth(camera, READ_FACE_M, min_face_px),
                depth_known_to(camera, depth.placing_sigma_m, depth.disparity_sigma_px))
    near_m = max(1.0, float(round(near)))
    far_m = max(near_m + 1.0, float(round(far)))
    return dataclasses.replace(depth, near_m=near_m, far_m=far_m, reach_m=max(far_m, float(round(reach))))


def range_text(depth: DepthConfig) -> str:
    """'4-14 m (to 56 m at the frame's edges)' for the log and the run's summary."""
    text = f"{depth.near_m:g}-{depth.far_m:g} m"
    if depth.reach_m and depth.reach_m > depth.far_m:
        text += f" (to {depth.reach_m:g} m for signs that leave the view before {depth.far_m:g} m)"
    return text


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


def in_search_range(z, edge, depth: DepthConfig, slack: float = 0.0):
    """Whether depth ``z`` at edge share ``edge`` is searched: near..far anywhere, and up to the reach where
    the face leaves the view before it comes within far. ``slack`` widens every limit by that share."""
    z = np.asarray(z, dtype=np.float32)
    with np.errstate(invalid="ignore"):
        inside = (z >= depth.near_m * (1.0 - slack)) & (z <= depth.far_m * (1.0 + slack))
        if depth.reach_m and depth.reach_m > depth.far_m:
            inside |= (z * edge >= depth.far_m * (1.0 - slack)) & (z <= depth.reach_m * (1.0 + slack))
    return inside


def face_depth(plane_depth: float, median_depth: float, camera: Camera, u: float, v: float, depth: DepthConfig,
               slack: float) -> float:
    """Depth of a face's centre (u, v): on its fitted plane, or the segment's median depth where the plane
    puts it outside the search range widened by ``slack`` (a face reaching past the range's limits)."""
    if np.isfinite(plane_depth) and in_search_range(plane_depth, edge_share(camera, u, v), depth, slack):
        return float(plane_depth)
    return float(median_depth)


def config_for_camera(config, camera: Camera):
    """``config`` (a PipelineConfig) with the depth range of ``camera`` where it asks for one
    (``depth.range_from_camera``), else as it is."""
    if not config.depth.range_from_camera:
        return config
    return dataclasses.replace(config, depth=camera_depth_range(camera, config.depth, config.colour.min_face_px))
