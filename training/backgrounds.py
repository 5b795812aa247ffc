"""Backgrounds around synthetic faces: real photographs shipped with scikit-image and procedural street textures.

The scikit-image sample photographs are not traffic-sign photographs, so using
them keeps every real sign photograph out of training while still putting real
image statistics (sky, foliage, brick, gravel, machines) around the faces.
"""

from __future__ import annotations

import cv2
import numpy as np

from signmapper_core.simulate import textures

SKIMAGE_PHOTOS = ("rocket", "stereo_motorcycle", "coffee", "chelsea", "astronaut", "brick", "grass", "gravel",
                  "camera", "coins", "text", "page", "moon")


def skimage_photos() -> list[np.ndarray]:
    """The bundled scikit-image photographs as BGR uint8 (grey ones replicated)."""
    from skimage import data

    photos = []
    for name in SKIMAGE_PHOTOS:
        img = getattr(data, name)()
        img = np.asarray(img[0] if isinstance(img, tuple) else img)
        if img.dtype != np.uint8:
            img = cv2.normalize(img.astype(np.float32), None, 0, 255, cv2.NORM_MINMAX).astype(np.uint8)
        if img.ndim == 2:
            img = cv2.cvtColor(img, cv2.COLOR_GRAY2BGR)
        elif img.shape[2] == 4:
            img = cv2.cvtColor(img, cv2.COLOR_RGBA2BGR)
        else:
            img = cv2.cvtColor(img, cv2.COLOR_RGB2BGR)
        photos.append(np.ascontiguousarray(img))
    return photos


def procedural_backgrounds(rng: np.random.Generator, size: int = 384) -> list[np.ndarray]:
    """Street textures of the synthetic drive generator: façades, foliage, asphalt, bark, metal, sky, cars."""
    out = [
        textures.facade(rng, 8.0, 8.0, 8.0 / size),
        textures.facade(rng, 6.0, 6.0, 6.0 / size),
        textures.asphalt(rng, size, size, 0.01),
        textures.paving(rng, size, size, 0.01),
        textures.bark(rng, size, size),
        textures.metal(rng, size, size),
        textures.sky(size, size, size * 1.2, 800.0, rng),
    ]
    for dark in (False, True):
        tex = textures.foliage(rng, size, size, dark=dark)
        out.append(tex.bgr if hasattr(tex, "bgr") else np.asarray(tex))
    for body in ((40, 40, 160), (160, 90, 30), (200, 200, 200), (30, 30, 30)):
        tex = textures.car_side(rng, 4.5, 1.5, 4.5 / size, body)
        out.append(tex.bgr if hasattr(tex, "bgr") else np.asarray(tex))
    return [np.ascontiguousarray(cv2.resize(_bgr(t), (size, size))) for t in out]


def _bgr(img) -> np.ndarray:
    img = np.asarray(img)
    if img.ndim == 2:
        return cv2.cvtColor(img.astype(np.uint8), cv2.COLOR_GRAY2BGR)
    return img[:, :, :3].astype(np.uint8)


class BackgroundPool:
    """Random background crops of any size from a fixed list of source images."""

    def __init__(self, images: list[np.ndarray]):
        if not images:
            raise ValueError("no background images")
        self.images = images

    def crop(self, rng: np.random.Generator, height: int, width: int) -> np.ndarray:
        src = self.images[int(rng.integers(len(self.images)))]
        scale = float(np.exp(rng.uniform(np.log(0.25), np.log(2.0))))
        sh, sw = max(2, int(round(height / scale))), max(2, int(round(width / scale)))
        sh, sw = min(sh, src.shape[0]), min(sw, src.shape[1])
        y = int(rng.integers(0, src.shape[0] - sh + 1))
        x = int(rng.integers(0, src.shape[1] - sw + 1))
        patch = cv2.resize(src[y : y + sh, x : x + sw], (width, height), interpolation=cv2.INTER_LINEAR)
        if rng.random() < 0.5:
            patch = patch[:, ::-1]
        return np.ascontiguousarray(patch)
