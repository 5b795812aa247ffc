"""Small constructed scenes with known answers for the pipeline tests."""

from __future__ import annotations

import numpy as np

from signmapper_core.geometry import Camera, Pose

CAMERA = Camera(width=640, height=400, fx=600.0, fy=600.0, cx=319.5, cy=199.5, baseline_m=0.9)
POSE = Pose(easting=2600000.0, northing=1200000.0, height=400.0, heading=90.0, pitch=0.0, roll=0.0)

RED = (30, 30, 200)
BLUE = (170, 80, 20)
WHITE = (245, 245, 245)


def noisy_background(height=CAMERA.height, width=CAMERA.width, seed=0, level=110, sigma=18) -> np.ndarray:
    """Grey, low-saturation textured background (BGR uint8)."""
    rng = np.random.default_rng(seed)
    grey = rng.normal(level, sigma, (height, width))
    tint = rng.normal(0, 4, (height, width, 3))
    return np.clip(grey[..., None] + tint, 0, 255).astype(np.uint8)


def constant_depth(z, height=CAMERA.height, width=CAMERA.width) -> np.ndarray:
    return np.full((height, width), z, dtype=np.float32)


def pixels_for(size_m: float, depth_m: float, camera: Camera = CAMERA) -> int:
    """Pixel extent of ``size_m`` metres at depth Z."""
    return int(round(size_m * camera.fx / depth_m))
