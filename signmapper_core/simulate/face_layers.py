"""Ink layers of a clean sign face, and hue/saturation/value edits per layer.

A printed sign is white sheeting with coloured inks (or films) and a black layer
on top. Print, wear and the tests all need to know which pixel belongs to which
ink; this module labels the clean artwork once and edits colours per label.
"""

from __future__ import annotations

import cv2
import numpy as np

OTHER, WHITE, GREY, BLACK, RED, ORANGE, YELLOW, GREEN, BLUE = range(9)
LAYER_NAMES = ("other", "white", "grey", "black", "red", "orange", "yellow", "green", "blue")
N_LAYERS = len(LAYER_NAMES)


def ink_layers(bgr: np.ndarray) -> np.ndarray:
    """Label (uint8, one of the constants above) of each pixel of a clean face, from its HSV colour."""
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    h, s, v = hsv[..., 0], hsv[..., 1], hsv[..., 2]
    labels = np.full(h.shape, OTHER, np.uint8)
    grey = s < 60
    labels[grey & (v >= 170)] = WHITE
    labels[grey & (v < 170)] = GREY
    labels[grey & (v < 80)] = BLACK
    coloured = ~grey & (v >= 50)
    labels[coloured & ((h < 9) | (h >= 160))] = RED
    labels[coloured & (h >= 9) & (h < 18)] = ORANGE
    labels[coloured & (h >= 18) & (h < 35)] = YELLOW
    labels[coloured & (h >= 35) & (h < 86)] = GREEN
    labels[coloured & (h >= 86) & (h < 140)] = BLUE
    return labels


def to_hsv(bgr: np.ndarray) -> np.ndarray:
    """Float HSV: hue in degrees 0..360, saturation and value 0..1."""
    return cv2.cvtColor(np.clip(bgr, 0, 255).astype(np.float32) / 255.0, cv2.COLOR_BGR2HSV)


def from_hsv(hsv: np.ndarray) -> np.ndarray:
    """Float BGR 0..255 from :func:`to_hsv`'s layout (hue wrapped, S and V clipped)."""
    hsv = hsv.copy()
    hsv[..., 0] %= 360.0
    np.clip(hsv[..., 1:], 0.0, 1.0, out=hsv[..., 1:])
    return cv2.cvtColor(hsv, cv2.COLOR_HSV2BGR) * 255.0


def shift_layers(bgr: np.ndarray, labels: np.ndarray, hue_deg, sat_mul, val_mul, weight=None) -> np.ndarray:
    """Float BGR with each layer's hue shifted and saturation/value scaled by its entry in the tables.

    The tables have one value per label (length ``N_LAYERS``); ``weight`` (h, w) in
    0..1 fades the edit in and out locally (e.g. a mottled chalking).
    """
    hsv = to_hsv(bgr)
    dh = np.asarray(hue_deg, np.float32)[labels]
    ks = np.asarray(sat_mul, np.float32)[labels]
    kv = np.asarray(val_mul, np.float32)[labels]
    if weight is not None:
        dh, ks, kv = dh * weight, 1 + (ks - 1) * weight, 1 + (kv - 1) * weight
    hsv[..., 0] += dh
    hsv[..., 1] *= ks
    hsv[..., 2] *= kv
    return from_hsv(hsv)


def circular_mean_hue(bgr: np.ndarray, mask: np.ndarray) -> float:
    """Mean hue in degrees (-180..180] of the masked pixels, averaged on the circle (red sits at 0)."""
    hue = np.radians(to_hsv(bgr)[..., 0][mask])
    return float(np.degrees(np.arctan2(np.sin(hue).mean(), np.cos(hue).mean())))
