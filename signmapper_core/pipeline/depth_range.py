"""The reach a drive's camera gives: how far beyond the far limit a sign that never comes closer is searched.

Between near and far (the paper's 4-14 m, ``DepthConfig``) every sign is searched in every pair. A sign that
is never seen within far (it leaves the view first: far to the side on a wide street, high over the road; or the
drive ends or turns off before it: ``drive/path_ahead.py``) is searched beyond it, where it is seen best: out
to where a normal-format disc (SSV Annex 1, 60 cm) still spans ``ColourConfig.min_face_px`` and one view's
depth, whose error grows as σ_Z = Z² σ_d / (f B), is known to ``placing_sigma_m``. Which faces those are:
``search_range.py``.

Near and far stay the paper's for every camera: derived from a camera by the same precision rule (one view's
depth known to 6 cm gives the paper's camera 4-14 m), they shrink to 1-7 m for KITTI's 1242 x 375 camera, and
the fewer views cost recognition there (docs/measurements.md, 2026-12-07).
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


def camera_reach(camera: Camera, depth: DepthConfig, min_face_px: float) -> DepthConfig:
    """``depth`` with the reach ``camera`` gives by the module's rule, in whole metres (at least far)."""
    reach = min(readable_depth(camera, READ_FACE_M, min_face_px),
                depth_known_to(camera, depth.placing_sigma_m, depth.disparity_sigma_px))
    return dataclasses.replace(depth, reach_m=max(depth.far_m, float(round(reach))))


def range_text(depth: DepthConfig) -> str:
    """'4-14 m (to 56 m for signs never seen within 14 m)' for the log."""
    text = f"{depth.near_m:g}-{depth.far_m:g} m"
    if depth.reach_m and depth.reach_m > depth.far_m:
        text += f" (to {depth.reach_m:g} m for signs never seen within {depth.far_m:g} m)"
    return text


def config_for_pair(config, ahead_m):
    """``config`` (a PipelineConfig) with one pair's path ahead (``PairRecord.ahead_m``) where it has a reach."""
    if ahead_m is None or not config.depth.reach_m or config.depth.reach_m <= config.depth.far_m:
        return config
    return dataclasses.replace(config, depth=dataclasses.replace(config.depth, ahead_m=float(ahead_m)))


def config_for_camera(config, camera: Camera):
    """``config`` (a PipelineConfig) with the reach of ``camera`` where it asks for one
    (``depth.range_from_camera``), else as it is."""
    if not config.depth.range_from_camera:
        return config
    return dataclasses.replace(config, depth=camera_reach(camera, config.depth, config.colour.min_face_px))
