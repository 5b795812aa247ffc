"""Whether a disc sits inside a white panel at its own depth: a zone panel's disc read alone.

A panel reading wins over its disc only where the white around the disc matches the official panel
(``classify.surround_score``). A zone panel of another design, or one half in shadow, fails that, and its disc is
read alone as a speed limit or 2.61, confidently and wrongly (held-out drives 1172 and 1179: two of the four
accepted signs with a wrong id). What gives the panel away is plain geometry: white at the disc's own depth above
it (the panel's "ZONE" line) and beside it, where a disc on a pole has background or a wall behind it. There, a
panel reading whose surround failed the NCC wins over the disc, and a disc reading is held for review
(``detect.evaluate_segment``).
"""

from __future__ import annotations

from typing import Tuple

import cv2
import numpy as np

from .config import PipelineConfig

# strips around a disc box (x0, y0, x1, y1 in shares of its width and height from its top left): the panel's white
# above the disc and its margins left and right (10 % of the disc on the official panels, narrow on others)
ABOVE = (0.15, -0.30, 0.85, -0.04)
LEFT = (-0.10, 0.25, -0.02, 0.75)
RIGHT = (1.02, 0.25, 1.10, 0.75)
MIN_IN_IMAGE = 0.5  # a strip is read only when at least this share of it lies in the image


def strip_box(bbox, strip: Tuple[float, float, float, float]) -> Tuple[int, int, int, int]:
    """The pixel box (x0, y0, x1, y1) of ``strip`` around the disc box ``bbox`` (x, y, w, h); may lie past the
    image."""
    x, y, w, h = bbox
    sx0, sy0, sx1, sy1 = strip
    return (int(round(x + sx0 * w)), int(round(y + sy0 * h)),
            max(int(round(x + sx1 * w)), int(round(x + sx0 * w)) + 1),
            max(int(round(y + sy1 * h)), int(round(y + sy0 * h)) + 1))


def white_at_depth(image: np.ndarray, depth: np.ndarray, box, depth_m: float, at_depth_share: float,
                   config: PipelineConfig) -> bool:
    """Whether the pixel box ``box`` is white and at ``depth_m``: at least ``panel_white_share`` of its pixels
    white (saturation at most ``white_max_saturation``, value at least ``panel_white_min_value``), a depth for
    at least ``min_depth_coverage`` of them, and at least ``at_depth_share`` of those within
    ``panel_depth_tolerance`` (metres, or that share of the depth, the larger) of ``depth_m``."""
    x0, y0, x1, y1 = box
    height, width = image.shape[:2]
    cx0, cy0, cx1, cy1 = max(x0, 0), max(y0, 0), min(x1, width), min(y1, height)
    if cx1 <= cx0 or cy1 <= cy0 or (cx1 - cx0) * (cy1 - cy0) < MIN_IN_IMAGE * (x1 - x0) * (y1 - y0):
        return False
    settings = config.classification
    hsv = cv2.cvtColor(image[cy0:cy1, cx0:cx1], cv2.COLOR_BGR2HSV)
    white = (hsv[..., 1] <= config.white.white_max_saturation) & (hsv[..., 2] >= settings.panel_white_min_value)
    if np.mean(white) < settings.panel_white_share:
        return False
    seen = depth[cy0:cy1, cx0:cx1]
    seen = seen[np.isfinite(seen)]
    if seen.size < config.planarity.min_depth_coverage * white.size:
        return False
    metres, share = settings.panel_depth_tolerance
    return bool(np.mean(np.abs(seen - depth_m) <= max(metres, share * depth_m)) >= at_depth_share)


def inside_white_panel(image: np.ndarray, depth: np.ndarray, bbox, depth_m: float, config: PipelineConfig) -> bool:
    """Whether the disc ``bbox`` (x, y, w, h) at ``depth_m`` has white at its depth above it and on one side at
    least (``panel_at_depth``: the share needed above, and beside)."""
    above, beside = config.classification.panel_at_depth
    if not np.isfinite(depth_m) or not white_at_depth(image, depth, strip_box(bbox, ABOVE), depth_m, above, config):
        return False
    return any(white_at_depth(image, depth, strip_box(bbox, side), depth_m, beside, config) for side in (LEFT, RIGHT))
