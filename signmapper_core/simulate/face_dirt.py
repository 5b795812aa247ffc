"""Dirt on a sign face: road grime rising from the bottom, spots and rain streaks.

Spray from the road settles most on the lower part of a face; splashes leave
spots (mud, and now and then a pale one); rain running down from the top edge
leaves thin vertical streaks.
"""

from __future__ import annotations

import cv2
import numpy as np

from .textures import smooth_noise

GRIME_BGR = np.array([58.0, 72.0, 84.0], np.float32)


def grime(bgr: np.ndarray, rng: np.random.Generator, strength: float) -> np.ndarray:
    """Float BGR with a mottled grime gradient from the bottom edge up."""
    h, w = bgr.shape[:2]
    img = bgr.astype(np.float32)
    start = rng.uniform(0.25, 0.7)  # where the grime begins, as a fraction of the height
    rows = np.clip((np.arange(h, dtype=np.float32) / max(h - 1, 1) - start) / (1 - start), 0, 1) ** 1.5
    mottle = np.clip(0.7 + 0.5 * smooth_noise(rng, h, w, max(4.0, w / 10.0)), 0, 1)
    amount = strength * rng.uniform(0.15, 0.4) * rows[:, None] * mottle
    return img * (1 - amount[..., None]) + GRIME_BGR * amount[..., None]


def spots(bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator, strength: float) -> np.ndarray:
    """Float BGR with splash spots (mostly dark mud, a few pale ones) inside the outline."""
    h, w = bgr.shape[:2]
    img = bgr.astype(np.float32)
    inside = np.argwhere(alpha > 128)
    count = int(rng.poisson(20 * strength))
    if not count or not len(inside):
        return img
    dark = np.zeros((h, w), np.float32)
    pale = np.zeros((h, w), np.float32)
    for _ in range(count):
        y, x = inside[int(rng.integers(len(inside)))]
        radius = max(1, int(round(rng.uniform(0.003, 0.012) * w)))
        target = pale if rng.random() < 0.12 else dark
        cv2.circle(target, (int(x), int(y)), radius, float(rng.uniform(0.3, 0.7)), -1, cv2.LINE_AA)
    dark = cv2.GaussianBlur(dark, (0, 0), 0.8)
    pale = cv2.GaussianBlur(pale, (0, 0), 0.8)
    img = img * (1 - dark[..., None]) + np.array([40.0, 52.0, 62.0], np.float32) * dark[..., None]
    return img * (1 - pale[..., None]) + np.array([200.0, 208.0, 210.0], np.float32) * pale[..., None]


def rain_streaks(bgr: np.ndarray, rng: np.random.Generator, strength: float) -> np.ndarray:
    """Float BGR with thin vertical streaks running down from near the top, fading downwards."""
    h, w = bgr.shape[:2]
    img = bgr.astype(np.float32)
    streaks = np.zeros((h, w), np.float32)
    for _ in range(int(rng.integers(4, 20))):
        x = int(rng.integers(0, w))
        y0 = int(rng.uniform(0.0, 0.35) * h)
        length = int(rng.uniform(0.2, 0.7) * h)
        width = max(1, int(round(rng.uniform(0.002, 0.008) * w)))
        ys = np.arange(y0, min(h, y0 + length))
        if not len(ys):
            continue
        fade = np.linspace(1.0, 0.0, len(ys), dtype=np.float32) ** 0.7 * rng.uniform(0.5, 1.0)
        wobble = np.round(np.cumsum(rng.normal(0, 0.15, len(ys)))).astype(int)
        for dx in range(width):
            cols = np.clip(x + dx + wobble, 0, w - 1)
            streaks[ys, cols] = np.maximum(streaks[ys, cols], fade)
    streaks = cv2.GaussianBlur(streaks, (0, 0), sigmaX=0.6, sigmaY=2.0)
    amount = strength * rng.uniform(0.12, 0.3) * streaks
    return img * (1 - amount[..., None]) + GRIME_BGR * amount[..., None]
