"""Wear of an old sign face: sun and weather over the years.

UV light bleaches the inks unevenly: red drifts towards orange or towards pink,
blue chalks (lighter, powdery, less saturated), all colours lose saturation and
the face loses contrast. Where the sheeting lifted and peeled off, the bare
aluminium blank shows through with a ragged edge.
"""

from __future__ import annotations

import cv2
import numpy as np

from .face_layers import BLUE, N_LAYERS, ORANGE, RED, shift_layers
from .textures import smooth_noise

ALUMINIUM_BGR = np.array([172.0, 172.0, 168.0], np.float32)


def uv_ageing(bgr: np.ndarray, labels: np.ndarray, rng: np.random.Generator, strength: float) -> np.ndarray:
    """Float BGR faded: red towards orange or pink, chalked blue, less saturation and contrast."""
    h, w = bgr.shape[:2]
    s = float(strength)
    dh, ks, kv = np.zeros(N_LAYERS, np.float32), np.full(N_LAYERS, 1 - 0.15 * s, np.float32), \
        np.ones(N_LAYERS, np.float32)
    towards_orange = rng.random() < 0.6
    red_shift = s * (rng.uniform(4.0, 12.0) if towards_orange else -rng.uniform(1.0, 4.0))
    dh[RED] = dh[ORANGE] = red_shift
    if not towards_orange:  # pink: paler and lighter
        ks[RED] = ks[ORANGE] = 1 - 0.4 * s
        kv[RED] = kv[ORANGE] = 1 + 0.12 * s
    img = shift_layers(bgr, labels, dh, ks, kv)
    # chalking of blue: mottled, paler, lighter
    chalk = np.clip(0.8 + 0.3 * smooth_noise(rng, h, w, max(3.0, w / 5.0)), 0, 1).astype(np.float32)
    no_hue = np.zeros(N_LAYERS, np.float32)
    ones = np.ones(N_LAYERS, np.float32)
    sat, val = ones.copy(), ones.copy()
    sat[BLUE], val[BLUE] = 1 - 0.4 * s, 1 + 0.22 * s
    img = shift_layers(img, labels, no_hue, sat, val, weight=chalk)
    # contrast loss towards the face's mean grey
    loss = s * rng.uniform(0.05, 0.15)
    mean = img.reshape(-1, 3).mean(axis=0)
    return img * (1 - loss) + mean * loss


def peel(bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator, strength: float) -> np.ndarray:
    """Float BGR with 1-3 ragged patches of lost sheeting showing the aluminium, mostly along the edge."""
    h, w = bgr.shape[:2]
    img = bgr.astype(np.float32)
    inside = (alpha > 200).astype(np.uint8)
    if not inside.any():
        return img
    to_edge = cv2.distanceTransform(inside, cv2.DIST_L2, 3)
    edge_band = np.argwhere((to_edge > 1) & (to_edge < 0.08 * w))
    anywhere = np.argwhere(to_edge > 1)
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    ragged = smooth_noise(rng, h, w, max(2.0, w / 40.0))
    patch = np.full((h, w), -1.0, np.float32)  # > 0 inside a patch, 0 on its edge
    for _ in range(int(rng.integers(1, 4))):
        pool = edge_band if len(edge_band) and rng.random() < 0.75 else anywhere
        cy, cx = pool[int(rng.integers(len(pool)))]
        radius = strength * rng.uniform(0.025, 0.06) * w
        rx, ry = radius * rng.uniform(0.6, 1.4), radius * rng.uniform(0.6, 1.4)
        blob = 1.0 - np.sqrt(((xx - cx) / rx) ** 2 + ((yy - cy) / ry) ** 2) + 0.5 * ragged
        patch = np.maximum(patch, blob)
    bare = np.clip(patch * 6.0, 0, 1) * inside
    rim = np.clip(1.0 - np.abs(patch) * 8.0, 0, 1) * inside  # the lifted, darker edge of the film
    brushed = cv2.GaussianBlur(rng.standard_normal((h, w)).astype(np.float32), (0, 0), sigmaX=6.0, sigmaY=0.5)
    metal = ALUMINIUM_BGR + (brushed * 20.0)[..., None]
    img = img * (1 - 0.35 * rim[..., None])
    return img * (1 - bare[..., None]) + metal * bare[..., None]
