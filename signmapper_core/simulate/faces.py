"""Where sign faces come from: the template catalogue's procedural ``render_face``.

The generator asks this module only, so the catalogue is consumed in one place.
Faces are varied per sign (FaceStyle from the catalogue, then weathering and
shadows here) and resampled, so no rendered sign is a pixel copy of a template.
"""

from __future__ import annotations

from dataclasses import dataclass

import cv2
import numpy as np

from .textures import smooth_noise

SIGN_COLOURS = ("red", "blue", "yellow")


@dataclass(frozen=True)
class SignKind:
    """What the layout needs to know about a template: id, colour, shape and standard formats."""

    template_id: str
    colour: str
    shape: str
    formats: tuple[tuple[str, float, float], ...]  # (name, width_m, height_m), sorted by name


def sign_kinds() -> list[SignKind]:
    """Red, blue and yellow catalogue entries in id order (deterministic)."""
    from ..catalogue import load_catalogue

    catalogue = load_catalogue()
    kinds = []
    for entry in sorted(catalogue.filter(colours=list(SIGN_COLOURS)), key=lambda e: e.id):
        formats = tuple(sorted((name, float(w), float(h)) for name, (w, h) in entry.formats.items()))
        if formats:
            kinds.append(SignKind(entry.id, entry.colour, entry.shape, formats))
    if not kinds:
        raise RuntimeError("the template catalogue has no red, blue or yellow signs to place")
    return kinds


def pick_format(kind: SignKind, rng: np.random.Generator) -> tuple[str, float, float]:
    """'normal' mostly, 'small' sometimes, otherwise any format the sign has."""
    by_name = {f[0]: f for f in kind.formats}
    if "normal" in by_name and "small" in by_name:
        return by_name["small"] if rng.random() < 0.3 else by_name["normal"]
    if "normal" in by_name:
        return by_name["normal"]
    return kind.formats[int(rng.integers(len(kind.formats)))]


def random_face_style(rng: np.random.Generator):
    """A random FaceStyle from the catalogue (pen widths, palette, font, details)."""
    from ..catalogue import FaceStyle

    return FaceStyle.random(rng, strength=float(rng.uniform(0.5, 1.0)))


def render_sign_face(template_id: str, size_wh: tuple[int, int], rng: np.random.Generator
                     ) -> tuple[np.ndarray, np.ndarray]:
    """Face (BGR, alpha) of one physical sign, (w, h) pixels, drawn by the catalogue with a random style."""
    from ..catalogue import render_face

    w, h = int(size_wh[0]), int(size_wh[1])
    bgr, alpha = render_face(template_id, (w, h), style=random_face_style(rng))
    if bgr.shape[:2] != (h, w):
        bgr = cv2.resize(bgr, (w, h), interpolation=cv2.INTER_AREA)
        alpha = cv2.resize(alpha, (w, h), interpolation=cv2.INTER_AREA)
    return np.ascontiguousarray(bgr), np.ascontiguousarray(alpha)


def weather_face(bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator, faded: float, dirt: float,
                 shadow: bool) -> np.ndarray:
    """Fading (loss of saturation and contrast), dirt blotches and a cast shadow, in texture space."""
    h, w = bgr.shape[:2]
    img = bgr.astype(np.float32)
    if faded > 0:
        grey = img.mean(axis=2, keepdims=True)
        img = img * (1 - faded) + (0.6 * grey + 0.4 * 200.0) * faded
    if dirt > 0:
        blot = np.clip(smooth_noise(rng, h, w, max(4.0, w / 12.0)), 0, None)[..., None]
        img = img * (1 - dirt * blot) + np.array([60, 75, 85], np.float32) * (dirt * blot)
    if shadow:
        yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
        ang = rng.uniform(0, np.pi)
        offset = rng.uniform(-0.3, 0.3) * w
        dist = (xx - w / 2) * np.cos(ang) + (yy - h / 2) * np.sin(ang) - offset
        edge = np.clip(dist / (0.04 * w) + smooth_noise(rng, h, w, max(3.0, w / 8.0)), -1, 1)
        img *= (0.78 + 0.22 * (edge[..., None] < 0)) if rng.random() < 0.5 else (0.6 + 0.2 * (edge[..., None] + 1))
    img = cv2.GaussianBlur(img, (0, 0), 0.6)
    return np.clip(img, 0, 255).astype(np.uint8)
