"""The search range a drive's camera gives: near and far limits across the frame, and a reach at its edges.

A stereo depth's uncertainty grows with the square of the depth, σ_Z = Z² σ_d / (f B), so how far a camera
measures a sign well depends on its focal length f and baseline B, not on a constant. Three rules:

- **far**: the depth is still known to ``survey_sigma_m`` (a few centimetres): Z = sqrt(σ f B / σ_d).
- **near**: the matcher's disparity search reaches ``max_disparity_px``: Z = f B / d_max. Its cost grows with the
  disparities searched; closer faces are mostly cut by the frame anyway.
- **reach**: a sign that leaves the view before it comes within *far* (far to the side, high over the road,
  across a junction) is searched where it is seen best, out to where a normal-format disc (SSV Annex 1,
  60 cm) still spans ``ColourConfig.min_face_px`` and its depth is known to ``placing_sigma_m``.

For the paper's camera (1920 x 1080, f = 1750 px, B = 0.9 m) the first two give 4 and 14 m, the range Cavegn
(2011) searched. Where a face will leave the view before it comes within *far*: ``search_range.py``.
"""

from __future__ import annotations

import dataclasses
import math

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
    near = camera.fx * camera.baseline_m / depth.max_disparity_px
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


def config_for_camera(config, camera: Camera):
    """``config`` (a PipelineConfig) with the depth range of ``camera`` where it asks for one
    (``depth.range_from_camera``), else as it is."""
    if not config.depth.range_from_camera:
        return config
    return dataclasses.replace(config, depth=camera_depth_range(camera, config.depth, config.colour.min_face_px))
