"""Dents and bends: a sign panel that is not quite flat any more.

A height field (a few smooth dents, sometimes a bend across the panel, a few
millimetres deep) shades the face where its slope turns it towards or away
from the light, and shifts texture a little as seen from an oblique view. The
outline moves with it, so the back of the panel uses the same warp.
"""

from __future__ import annotations

from dataclasses import dataclass

import cv2
import numpy as np


@dataclass(frozen=True)
class DentWarp:
    """Remap tables and a shading factor of one panel's deformation, all (h, w) float32."""

    map_x: np.ndarray
    map_y: np.ndarray
    shading: np.ndarray

    def outline(self, alpha: np.ndarray) -> np.ndarray:
        return cv2.remap(alpha, self.map_x, self.map_y, cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT)

    def apply(self, bgr: np.ndarray) -> np.ndarray:
        """Float BGR warped and shaded."""
        img = cv2.remap(bgr.astype(np.float32), self.map_x, self.map_y, cv2.INTER_LINEAR,
                        borderMode=cv2.BORDER_REPLICATE)
        return img * self.shading[..., None]


def dent_warp(size_wh: tuple[int, int], rng: np.random.Generator, strength: float, bend: bool) -> DentWarp:
    """The deformation of a w x h face: 1-3 dents and, when ``bend``, a bend across the panel."""
    w, h = int(size_wh[0]), int(size_wh[1])
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    height = np.zeros((h, w), np.float32)  # in pixels of the face, towards the viewer
    for _ in range(int(rng.integers(1, 4))):
        cx, cy = rng.uniform(0.15, 0.85) * w, rng.uniform(0.15, 0.85) * h
        radius = rng.uniform(0.06, 0.18) * w
        depth = strength * rng.uniform(0.004, 0.012) * w * (1 if rng.random() < 0.3 else -1)
        height += depth * np.exp(-((xx - cx) ** 2 + (yy - cy) ** 2) / (2 * radius ** 2))
    if bend:
        ang = rng.uniform(0, np.pi)
        through = rng.uniform(0.2, 0.8)
        d = ((xx / max(w - 1, 1) - through) * np.cos(ang) + (yy / max(h - 1, 1) - through) * np.sin(ang))
        height += strength * rng.uniform(0.01, 0.03) * w * np.log1p(np.exp(d * 12.0)) / 12.0
    gy, gx = np.gradient(height)
    light = rng.uniform(0, 2 * np.pi)
    shading = 1.0 + 2.2 * (gx * np.cos(light) + gy * np.sin(light))
    shading = np.clip(shading, 0.85, 1.15).astype(np.float32)
    view = rng.uniform(0, 2 * np.pi)
    oblique = rng.uniform(0.15, 0.45)  # tan of the viewing angle: parallax of the raised parts
    map_x = (xx - oblique * np.cos(view) * height).astype(np.float32)
    map_y = (yy - oblique * np.sin(view) * height).astype(np.float32)
    return DentWarp(map_x, map_y, shading)
