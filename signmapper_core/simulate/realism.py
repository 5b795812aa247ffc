"""Camera effects applied to the rendered images: what makes them look recorded.

Effects that come from the scene or the optics (exposure, white balance,
motion blur, glare from a sun at infinity) are the same in both images, so
stereo geometry is kept; sensor noise is independent per image.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import cv2
import numpy as np


@dataclass(frozen=True)
class PairEffects:
    """Randomly drawn effects of one stereo pair."""

    gain: float
    white_balance: tuple[float, float, float]
    right_gain: float
    blur_px: float
    blur_angle_deg: float
    noise_sigma: float
    glare: tuple[float, float, float] | None   # (u, v, strength)
    noise_seed: int
    vignette: bool = True


def draw_effects(rng: np.random.Generator, width: int, height: int, switches: dict) -> PairEffects:
    exposure = switches.get("exposure_changes", True)
    gain = float(np.exp(rng.normal(0.0, 0.12))) if exposure else 1.0
    wb = tuple(float(x) for x in np.exp(rng.normal(0.0, 0.04, 3))) if exposure else (1.0, 1.0, 1.0)
    right_gain = float(np.exp(rng.normal(0.0, 0.015))) if exposure else 1.0
    blur = float(rng.uniform(0.8, 2.5)) if switches.get("motion_blur", True) else 0.0
    angle = float(rng.uniform(-20, 20))
    sigma = float(rng.uniform(1.5, 3.5)) if switches.get("noise", True) else 0.0
    glare = None
    if switches.get("glare", True) and rng.random() < 0.12:
        glare = (float(rng.uniform(0.1, 0.9) * width), float(rng.uniform(-0.2, 0.25) * height),
                 float(rng.uniform(0.4, 0.9)))
    return PairEffects(gain, wb, right_gain, blur, angle, sigma, glare, int(rng.integers(2**63)), exposure)


def _motion_kernel(length: float, angle_deg: float) -> np.ndarray:
    size = int(np.ceil(length)) | 1
    k = np.zeros((size, size), np.float32)
    c = size // 2
    a = np.radians(angle_deg)
    for t in np.linspace(-length / 2, length / 2, 4 * size):
        x, y = c + t * np.cos(a), c + t * np.sin(a)
        k[int(round(y)), int(round(x))] += 1.0
    return k / k.sum()


def _glare_layer(width: int, height: int, glare) -> np.ndarray:
    """Veiling glare and a star of streaks around an (often off-image) sun."""
    u0, v0, strength = glare
    small = 4
    w, h = width // small + 1, height // small + 1
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    r = np.hypot(xx * small - u0, yy * small - v0) / max(width, height)
    veil = strength * 230.0 * np.exp(-r / 0.12) + strength * 40.0 * np.exp(-r / 0.5)
    layer = cv2.resize(veil.astype(np.float32), (width, height), interpolation=cv2.INTER_LINEAR)
    return layer[..., None] * np.array([0.85, 0.95, 1.0], np.float32)


@functools.lru_cache(maxsize=4)
def _vignette(width: int, height: int) -> np.ndarray:
    """Mild lens fall-off towards the corners (about 20 % darker there)."""
    xx = (np.arange(width, dtype=np.float32) - (width - 1) / 2) / (width / 2)
    yy = (np.arange(height, dtype=np.float32) - (height - 1) / 2) / (width / 2)
    r2 = yy[:, None] ** 2 + xx[None, :] ** 2
    return (1.0 - 0.2 * r2 / r2.max()).astype(np.float32)


def apply_effects(image: np.ndarray, fx: PairEffects, right: bool) -> np.ndarray:
    """Recorded image from a rendered one (BGR uint8 in, BGR uint8 out)."""
    img = image.astype(np.float32)
    if fx.blur_px >= 1.0:
        img = cv2.filter2D(img, -1, _motion_kernel(fx.blur_px, fx.blur_angle_deg))
    gains = np.array(fx.white_balance, np.float32) * fx.gain * (fx.right_gain if right else 1.0)
    img *= gains
    if fx.vignette:
        img *= _vignette(img.shape[1], img.shape[0])[..., None]
    if fx.glare is not None:
        veil = 0.18 * fx.glare[2]  # scattered light lowers contrast over the whole frame
        img = img * (1.0 - veil) + 255.0 * veil
        img += _glare_layer(img.shape[1], img.shape[0], fx.glare)
    if fx.noise_sigma > 0:
        # OpenCV's generator is fast and thread-local: seeding it right before use is deterministic
        cv2.setRNGSeed(int((fx.noise_seed + int(right)) % (2**31 - 1)))
        noise = np.empty(img.shape[:2], np.float32)
        cv2.randn(noise, 0.0, fx.noise_sigma)
        # luminance noise plus a little chroma noise at lower resolution
        img += noise[..., None]
        chroma = np.empty((img.shape[0] // 2 + 1, img.shape[1] // 2 + 1, 3), np.float32)
        cv2.randn(chroma, (0.0, 0.0, 0.0), (0.5 * fx.noise_sigma,) * 3)
        img += cv2.resize(chroma, (img.shape[1], img.shape[0]), interpolation=cv2.INTER_NEAREST)
    return np.clip(img, 0, 255).astype(np.uint8)
