"""Mounting height of a sign: its lower edge above the road beside it.

The road surface under the vehicle is the camera's projection centre minus the
camera's height above the road. drive-format.md lets writers add keys to
drive.json; Sign Mapper reads ``vehicle.camera_height_m`` when a drive states
it. Without it the height stays unknown rather than guessed.
"""

from __future__ import annotations

from typing import Optional

import numpy as np


def camera_height_above_road(metadata: dict) -> Optional[float]:
    """``vehicle.camera_height_m`` of drive.json, if given as a positive number."""
    vehicle = metadata.get("vehicle") if isinstance(metadata, dict) else None
    value = vehicle.get("camera_height_m") if isinstance(vehicle, dict) else None
    if isinstance(value, (int, float)) and not isinstance(value, bool) and np.isfinite(value) and value > 0:
        return float(value)
    return None


def road_height_near(position: np.ndarray, camera_centres: np.ndarray, camera_height_m: float) -> float:
    """Road height under the camera position nearest (planimetrically) to ``position``."""
    centres = np.asarray(camera_centres, float).reshape(-1, 3)
    nearest = np.argmin(np.hypot(centres[:, 0] - position[0], centres[:, 1] - position[1]))
    return float(centres[nearest, 2] - camera_height_m)


def height_above_road(position: np.ndarray, camera_centres: np.ndarray,
                      camera_height_m: Optional[float]) -> Optional[float]:
    """Height of ``position`` above the road beside it, or None when the camera height is unknown."""
    if camera_height_m is None or len(camera_centres) == 0:
        return None
    return float(position[2] - road_height_near(position, camera_centres, camera_height_m))


def mounting_height(position: np.ndarray, face_height_m: float, camera_centres: np.ndarray,
                    camera_height_m: Optional[float]) -> Optional[float]:
    """Lower edge of the face above the road, or None when the camera height is unknown."""
    centre = height_above_road(position, camera_centres, camera_height_m)
    return None if centre is None else centre - face_height_m / 2.0
