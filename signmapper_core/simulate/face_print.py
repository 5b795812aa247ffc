"""Different print: every physical sign comes out of its own print run.

Inks differ in hue, saturation and value per colour; the black layer's lines
come out slightly bolder or thinner, and the black screen sits slightly off its
register so a thin line of white sheeting shows on one side of the pictogram.
"""

from __future__ import annotations

import cv2
import numpy as np

from .face_layers import BLUE, GREEN, GREY, N_LAYERS, ORANGE, RED, WHITE, YELLOW, shift_layers, to_hsv

# per colour: max hue shift (degrees), saturation and value factor ranges
INK_TOLERANCES = {
    RED: (4.0, (0.88, 1.06), (0.90, 1.06)),
    ORANGE: (4.0, (0.88, 1.06), (0.90, 1.06)),
    YELLOW: (3.0, (0.85, 1.04), (0.92, 1.04)),
    GREEN: (5.0, (0.85, 1.06), (0.90, 1.08)),
    BLUE: (5.0, (0.85, 1.08), (0.88, 1.10)),
    WHITE: (0.0, (1.0, 1.0), (0.93, 1.0)),
    GREY: (0.0, (1.0, 1.0), (0.90, 1.10)),
}


def ink_tables(rng: np.random.Generator, strength: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Hue shift, saturation and value factor per layer for one print run."""
    dh, ks, kv = np.zeros(N_LAYERS, np.float32), np.ones(N_LAYERS, np.float32), np.ones(N_LAYERS, np.float32)
    for layer, (hue, sat, val) in INK_TOLERANCES.items():
        dh[layer] = strength * rng.uniform(-hue, hue)
        ks[layer] = 1 + strength * (rng.uniform(*sat) - 1)
        kv[layer] = 1 + strength * (rng.uniform(*val) - 1)
    return dh, ks, kv


def black_matte(bgr: np.ndarray) -> np.ndarray:
    """Coverage 0..1 of the black layer, including its anti-aliased edges (float32)."""
    hsv = to_hsv(bgr)
    s, v = hsv[..., 1], hsv[..., 2]
    solid = ((v < 0.3) & (s < 0.35)).astype(np.uint8)
    near = cv2.dilate(solid, np.ones((3, 3), np.uint8)).astype(bool)
    matte = np.clip((0.88 - v) / (0.88 - 0.12), 0, 1) * (s < 0.35) * near
    return matte.astype(np.float32)


def print_variation(bgr: np.ndarray, labels: np.ndarray, rng: np.random.Generator, strength: float,
                    px_per_m: float) -> np.ndarray:
    """Float BGR of the face as printed in another run: inks, line weight, register of the black layer."""
    img = shift_layers(bgr, labels, *ink_tables(rng, strength))
    matte = black_matte(bgr)
    if not matte.any():
        return img
    ink_old = float(np.median(bgr[matte > 0.95])) if (matte > 0.95).any() else 22.0
    white = img[labels == WHITE]
    paper = np.median(white, axis=0) if len(white) > 50 else np.array([240.0, 240.0, 240.0])
    # line weight: grow or shrink the black layer by about 1-2 mm per side
    new = matte
    radius = int(round(strength * rng.uniform(0.0, 0.0022) * px_per_m))
    if radius >= 1:
        kernel = cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (2 * radius + 1, 2 * radius + 1))
        new = cv2.dilate(matte, kernel) if rng.random() < 0.5 else cv2.erode(matte, kernel)
    # register: the black screen off by up to ~2.5 mm
    offset = strength * rng.uniform(0.0, 0.0025) * px_per_m
    angle = rng.uniform(0, 2 * np.pi)
    if offset >= 0.3:
        shift = np.float32([[1, 0, offset * np.cos(angle)], [0, 1, offset * np.sin(angle)]])
        new = cv2.warpAffine(new, shift, new.shape[::-1], flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT)
    ink_value = rng.uniform(14.0, 42.0)
    ink = ink_value + rng.uniform(-3.0, 3.0, 3)
    # lift the old black off (what lies under it is the white sheeting), lay the new one on
    under = img + matte[..., None] * (paper - ink_old)
    return under * (1 - new[..., None]) + ink * new[..., None]

