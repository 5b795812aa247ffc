"""Colour classes that follow the scene's illumination: white balance and thresholds from the image itself.

The fixed HSV thresholds of the colour step hold for signs in good light. On real
photographs a faded ring, a dull overcast scene or a camera's colour cast put the
ring's saturation below them. Two measures follow the scene:

- a white balance from the image's own near-neutral pixels (road, sky, walls):
  a cast shifts hues and lends every pixel a false saturation, so it is removed
  before the colour classes are read;
- a weak saturation (and brightness) floor per scene, from the saturation and
  brightness the scene's pixels typically have: a dull scene lowers it, a vivid
  one raises it (where more of the background is coloured).

The colour classes stay HSV hue bands (red / blue / yellow) as in Cavegn (2011);
only their saturation and brightness floors adapt.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, Tuple

import cv2
import numpy as np

from .config import HsvRange, PipelineConfig


@dataclass(frozen=True)
class SceneColour:
    """What the colour step learns about one image before segmenting it."""

    gains: Tuple[float, float, float]  # B, G, R factors that make the neutral pixels grey
    saturation: float  # median saturation (0-255) of the balanced image
    brightness: float  # median value (0-255) of the balanced image
    weak_ranges: Dict[str, Tuple[HsvRange, ...]]  # per colour: lowered saturation/value floors


def white_balance_gains(bgr: np.ndarray, scene) -> Tuple[float, float, float]:
    """Per-channel gains that bring the mean of the near-neutral pixels to grey (B = G = R).

    ``scene``: the config's scene section. Near-neutral: saturation below ``neutral_max_saturation``
    and brightness within ``neutral_value_range``. Gains are limited to ``1/max_white_balance_gain ..
    max_white_balance_gain``: a scene dominated by one colour (a green hedge) must not be turned
    magenta. With less than ``neutral_min_share`` neutral pixels: no change.
    """
    max_saturation, max_gain = scene.neutral_max_saturation, scene.max_white_balance_gain
    low, high = scene.neutral_value_range
    step = scene.scene_sample_step
    sample = np.ascontiguousarray(bgr[::step, ::step])
    if sample.size == 0:
        return (1.0, 1.0, 1.0)
    hsv = cv2.cvtColor(sample, cv2.COLOR_BGR2HSV)
    neutral = cv2.inRange(hsv, (0, 0, low), (180, max_saturation - 1, high))
    if cv2.countNonZero(neutral) < scene.neutral_min_share * neutral.size:
        return (1.0, 1.0, 1.0)
    means = np.array(cv2.mean(sample, mask=neutral)[:3])
    gains = np.clip(means.mean() / np.maximum(means, 1.0), 1.0 / max_gain, max_gain)
    return tuple(float(g) for g in gains)


def apply_gains(bgr: np.ndarray, gains: Tuple[float, float, float], min_change: float) -> np.ndarray:
    """The image with each channel scaled by its gain (saturating at 255); unchanged (the same array) when
    every gain is within ``min_change`` of 1 (``scene.white_balance_min_change``)."""
    if all(abs(g - 1.0) < min_change for g in gains):
        return bgr
    levels = np.arange(256, dtype=np.float32)[:, None] * np.asarray(gains, np.float32)[None, :]
    lut = np.clip(np.round(levels), 0, 255).astype(np.uint8).reshape(256, 1, 3)
    return cv2.LUT(bgr, lut)  # a table per channel: a fraction of the cost of a matrix transform


def weak_ranges(config: PipelineConfig, saturation: float, brightness: float) -> Dict[str, Tuple[HsvRange, ...]]:
    """Per colour, the weak pass's HSV ranges: ``config.scene.weak_hues`` with this scene's floors.

    Saturation floor = ``weak_sat_factor`` x the scene's median saturation + ``weak_sat_offset``,
    clipped to ``weak_sat_min`` .. the colour's strong floor (never above it); the value floor
    likewise from the scene's median brightness.
    """
    sat_floor = config.scene.weak_sat_factor * saturation + config.scene.weak_sat_offset
    val_floor = config.scene.weak_val_factor * brightness
    out = {}
    for colour, strong in config.colour.hsv_ranges.items():
        s_strong, v_strong = min(r[2] for r in strong), min(r[4] for r in strong)
        s = int(np.clip(sat_floor, config.scene.weak_sat_min, s_strong))
        v = int(np.clip(val_floor, config.scene.weak_val_min, v_strong))
        hues = config.scene.weak_hues.get(colour) or tuple((r[0], r[1]) for r in strong)
        out[colour] = tuple((h0, h1, s, 255, v, 255) for h0, h1 in hues)
    return out


def chroma_at_least(hsv: np.ndarray, min_chroma: int) -> np.ndarray:
    """Bool mask of pixels whose max - min of B, G, R (= S x V / 255) is at least ``min_chroma``.

    Unlike saturation, chroma is not inflated in dark pixels, where the hue is mostly noise.
    """
    s, v = cv2.extractChannel(hsv, 1), cv2.extractChannel(hsv, 2)
    return cv2.multiply(s, v, scale=1.0 / 255.0) >= min_chroma


def median_u8(values: np.ndarray) -> float:
    """Median of uint8 values (a 2-D array, a channel view too) from their histogram: a tenth of the cost of
    sorting a frame's worth."""
    counts = cv2.calcHist([values], [0], None, [256], [0, 256]).ravel().astype(np.int64).cumsum()
    if counts[-1] == 0:
        return 0.0
    lo = int(np.searchsorted(counts, (counts[-1] - 1) // 2 + 1))
    hi = int(np.searchsorted(counts, counts[-1] // 2 + 1))
    return (lo + hi) / 2.0


def scene_colour(bgr: np.ndarray, config: PipelineConfig) -> SceneColour:
    """White balance and weak colour ranges of one image (or image window)."""
    gains = white_balance_gains(bgr, config.scene) if config.scene.white_balance else (1.0, 1.0, 1.0)
    step = config.scene.scene_sample_step
    sample = apply_gains(np.ascontiguousarray(bgr[::step, ::step]), gains, config.scene.white_balance_min_change)
    hsv = cv2.cvtColor(sample, cv2.COLOR_BGR2HSV) if sample.size else np.zeros((1, 1, 3), np.uint8)
    saturation, brightness = median_u8(hsv[..., 1]), median_u8(hsv[..., 2])
    return SceneColour(gains, saturation, brightness, weak_ranges(config, saturation, brightness))
