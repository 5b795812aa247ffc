"""Step 8: 3D position of a detected sign face in the drive's CRS."""

from __future__ import annotations

import numpy as np

from ..geometry import Camera, Pose, pixel_to_world


def locate(camera: Camera, pose: Pose, u: float, v: float, depth_m: float) -> np.ndarray:
    """World (E, N, H) of pixel (u, v) at depth Z: the segment centre on the sign face."""
    return np.asarray(pixel_to_world(camera, pose, u, v, depth_m), dtype=float)


def bbox_centre(bbox) -> tuple:
    """Centre (u, v) of a pixel bounding box in pixel-centre coordinates."""
    x, y, w, h = bbox
    return x + (w - 1) / 2.0, y + (h - 1) / 2.0
