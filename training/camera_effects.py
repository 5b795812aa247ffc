"""What the camera and the light add to a scene crop: exposure, colour cast, shadow, blur, resolution, noise, JPEG."""

from __future__ import annotations

import cv2
import numpy as np

from .face_wear import smooth_field


def lighting(img: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Over/under-exposure (clipped like a sensor), gamma, a colour cast, sometimes a shadow edge or glare."""
    x = img.astype(np.float32) / 255.0
    h, w = x.shape[:2]
    gain = float(np.clip(np.exp(rng.normal(-0.05, 0.45)), 0.25, 2.8))
    cast = np.clip(rng.normal(1.0, 0.09, 3), 0.7, 1.3).astype(np.float32)
    x = x * gain * cast
    if rng.random() < 0.25:  # a shadow edge across the crop
        yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
        ang = rng.uniform(0, np.pi)
        d = (xx - w / 2) * np.cos(ang) + (yy - h / 2) * np.sin(ang) - rng.uniform(-0.3, 0.3) * w
        soft = 1 / (1 + np.exp(np.clip(-d / max(0.5, rng.uniform(0.01, 0.1) * w), -50, 50)))
        x = x * (1 - rng.uniform(0.3, 0.7) * soft)[..., None]
    if rng.random() < 0.1:  # glare
        yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
        cx, cy, r = rng.uniform(0, w), rng.uniform(0, h), rng.uniform(0.1, 0.5) * w
        x = x + (rng.uniform(0.3, 1.0) * np.exp(-((xx - cx) ** 2 + (yy - cy) ** 2) / (2 * r * r)))[..., None]
    x = np.clip(x, 0, 1) ** float(np.exp(rng.normal(0, 0.2)))
    return (x * 255.0).astype(np.float32)


def motion_kernel(length: float, angle_deg: float) -> np.ndarray:
    size = int(np.ceil(length)) | 1
    k = np.zeros((size, size), np.float32)
    c = size // 2
    dx, dy = np.cos(np.radians(angle_deg)) * length / 2, np.sin(np.radians(angle_deg)) * length / 2
    cv2.line(k, (int(round(c - dx)), int(round(c - dy))), (int(round(c + dx)), int(round(c + dy))), 1.0, 1)
    return k / max(k.sum(), 1e-6)


def blur(img: np.ndarray, sign_px: float, rng: np.random.Generator) -> np.ndarray:
    """Defocus and motion blur, scaled to the sign's size so small signs are not wiped out entirely."""
    if rng.random() < 0.55:
        sigma = rng.uniform(0.3, 0.4 + 0.02 * sign_px)
        img = cv2.GaussianBlur(img, (0, 0), min(sigma, 3.0))
    if rng.random() < 0.3:
        length = rng.uniform(1.5, 2.0 + 0.05 * sign_px)
        img = cv2.filter2D(img, -1, motion_kernel(min(length, 9.0), rng.uniform(0, 180)))
    return img


def resolution_loss(img: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Soft optics or an upscaled crop: down and up again."""
    if rng.random() < 0.3:
        h, w = img.shape[:2]
        f = rng.uniform(1.2, 2.5)
        small = cv2.resize(img, (max(2, int(w / f)), max(2, int(h / f))), interpolation=cv2.INTER_AREA)
        img = cv2.resize(small, (w, h), interpolation=cv2.INTER_LINEAR)
    return img


def sensor_noise_and_jpeg(img: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Shot and read noise (some of it chromatic), then JPEG at a random quality."""
    x = img.astype(np.float32)
    if rng.random() < 0.75:
        sigma = rng.uniform(1, 9)
        x = x + rng.normal(0, sigma, x.shape[:2] + (1,)).astype(np.float32)
        x = x + rng.normal(0, sigma * 0.4, x.shape).astype(np.float32)
    if rng.random() < 0.2:  # low-frequency colour noise of a small sensor
        h, w = x.shape[:2]
        x = x + np.stack([smooth_field(rng, h, w, 6) for _ in range(3)], axis=2) * rng.uniform(2, 10)
    out = np.clip(x, 0, 255).astype(np.uint8)
    if rng.random() < 0.8:
        ok, buf = cv2.imencode(".jpg", out, [cv2.IMWRITE_JPEG_QUALITY, int(rng.integers(20, 96))])
        if ok:
            out = cv2.imdecode(buf, cv2.IMREAD_COLOR)
    return out
