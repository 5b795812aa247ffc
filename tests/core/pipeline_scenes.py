"""Small constructed scenes with known answers for the pipeline tests."""

from __future__ import annotations

import cv2
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


def paste(image: np.ndarray, bgr: np.ndarray, alpha: np.ndarray, x: int, y: int) -> None:
    """Alpha-blend a face into ``image`` with its top-left pixel at (x, y), in place, clipped to the image."""
    h, w = alpha.shape
    x0, y0 = max(0, x), max(0, y)
    x1, y1 = min(image.shape[1], x + w), min(image.shape[0], y + h)
    if x1 <= x0 or y1 <= y0:
        return
    a = alpha[y0 - y : y1 - y, x0 - x : x1 - x, None].astype(np.float32) / 255.0
    face = bgr[y0 - y : y1 - y, x0 - x : x1 - x]
    roi = image[y0:y1, x0:x1].astype(np.float32)
    image[y0:y1, x0:x1] = (face * a + roi * (1 - a)).astype(np.uint8)


def sign_scene(catalogue, template_id, size_m, sign_world, depth_m=None, seed=0, camera=CAMERA, pose=POSE,
               background_depth=None, variant=None):
    """Left image and depth of a flat sign face centred at ``sign_world``, facing the camera.

    Returns (left, depth, bbox). Depth is the sign's Z on the face (constant: it faces
    the camera) and ``background_depth`` elsewhere (default: the same plane). ``variant``: the index of one of
    the entry's further drawings (a pointer pointing the other way) instead of its master.
    """
    from signmapper_core.geometry import world_to_pixel

    u, v, z = world_to_pixel(camera, pose, np.asarray(sign_world, float))
    z = float(z if depth_m is None else depth_m)
    entry = catalogue[template_id]
    w_m, h_m = entry.formats[size_m] if isinstance(size_m, str) else size_m
    w, h = int(round(w_m * camera.fx / z)), int(round(h_m * camera.fy / z))
    if variant is None:
        bgr, alpha = catalogue.render(template_id, (w, h))
    else:
        drawn, drawn_alpha = catalogue.variant_masters(template_id)[variant]
        bgr = cv2.resize(drawn, (w, h), interpolation=cv2.INTER_AREA)
        alpha = np.where(cv2.resize(drawn_alpha, (w, h), interpolation=cv2.INTER_AREA) > 127, 255, 0).astype(np.uint8)
    left = noisy_background(seed=seed)
    x, y = int(round(float(u) - (w - 1) / 2)), int(round(float(v) - (h - 1) / 2))
    paste(left, bgr, alpha, x, y)
    depth = constant_depth(z if background_depth is None else background_depth)
    face = np.zeros(depth.shape, np.uint8)
    x0, y0 = max(0, x), max(0, y)
    x1, y1 = min(depth.shape[1], x + w), min(depth.shape[0], y + h)
    face[y0:y1, x0:x1] = alpha[y0 - y : y1 - y, x0 - x : x1 - x]
    depth[face > 127] = z
    return left, depth, (x, y, w, h)
