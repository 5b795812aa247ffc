"""Reflective sheeting: the micro-prismatic film every Swiss sign face is made of.

Up close the film shows the seal cells that hold its prisms (a faint diamond
grid a few millimetres across, each cell a little brighter or darker) and
sparkles where single prisms send light straight back. The film also reflects
the sky: a gentle sheen gradient across the face and sometimes a specular hot
spot that washes the colours out towards white.
"""

from __future__ import annotations

import numpy as np


def prism_texture(bgr: np.ndarray, rng: np.random.Generator, strength: float, px_per_m: float) -> np.ndarray:
    """Float BGR with the seal-cell grid, per-cell brightness and sparkles of the film."""
    h, w = bgr.shape[:2]
    img = bgr.astype(np.float32)
    cell = rng.uniform(0.006, 0.012) * px_per_m  # seal cells of 6-12 mm
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    theta = np.radians(rng.uniform(-10, 10) + 45.0)
    a = (xx * np.cos(theta) + yy * np.sin(theta)) / max(cell, 1.0)
    b = (-xx * np.sin(theta) + yy * np.cos(theta)) / max(cell, 1.0)
    table = rng.uniform(-1, 1, (64, 64)).astype(np.float32)
    cells = table[np.floor(a).astype(np.int64) % 64, np.floor(b).astype(np.int64) % 64]
    gain = 1.0 + strength * rng.uniform(0.01, 0.03) * cells
    if cell >= 3.0:  # seal lines are only drawn where they are resolved
        dist = np.minimum(np.abs(a - np.round(a)), np.abs(b - np.round(b))) * cell
        gain -= strength * rng.uniform(0.02, 0.05) * np.exp(-(dist / 0.7) ** 2)
    img *= gain[..., None]
    density = strength * rng.uniform(0.0005, 0.003)
    count = int(rng.poisson(density * h * w))
    if count:
        ys, xs = rng.integers(0, h, count), rng.integers(0, w, count)
        lift = rng.uniform(0.2, 0.6, count).astype(np.float32)[:, None]
        img[ys, xs] += lift * (255.0 - img[ys, xs])
    return img


def sheen(bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator, strength: float, hot_spot: bool
          ) -> np.ndarray:
    """Float BGR lit by a sheen gradient and, when ``hot_spot``, a specular spot towards white."""
    h, w = bgr.shape[:2]
    img = bgr.astype(np.float32)
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    x, y = xx / max(w - 1, 1) - 0.5, yy / max(h - 1, 1) - 0.5
    ang = rng.uniform(0, 2 * np.pi)
    gradient = 1.0 + strength * rng.uniform(0.03, 0.10) * 2 * (x * np.cos(ang) + y * np.sin(ang))
    img *= gradient[..., None]
    if hot_spot:
        inside = np.argwhere(alpha > 128)
        cy, cx = inside[int(rng.integers(len(inside)))] if len(inside) else (h / 2, w / 2)
        radius = rng.uniform(0.12, 0.3) * max(w, h)
        spot = np.exp(-((xx - cx) ** 2 + (yy - cy) ** 2) / (2 * radius ** 2))
        amount = strength * rng.uniform(0.12, 0.35) * spot
        img += amount[..., None] * (250.0 - img)
    return img
