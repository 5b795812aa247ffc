"""The square patch a learned classifier sees: a face box with a margin, resampled to a fixed size.

Training and mapping must cut patches the same way, so both call
:func:`face_patch`. The box may reach past the image edge (a sign at the border,
a box jittered by segmentation): the missing pixels are the replicated border,
never an empty array.
"""

from __future__ import annotations

import math

import cv2
import numpy as np


def expanded_box(bbox, margin: float) -> tuple[int, int, int, int]:
    """(x0, y0, x1, y1), exclusive, of ``bbox`` (x, y, w, h) grown by ``margin`` of its size on every side."""
    x, y, w, h = (float(v) for v in bbox)
    w, h = max(w, 1.0), max(h, 1.0)
    x0 = int(math.floor(x - margin * w))
    y0 = int(math.floor(y - margin * h))
    x1 = int(math.ceil(x + w + margin * w))
    y1 = int(math.ceil(y + h + margin * h))
    return x0, y0, max(x1, x0 + 1), max(y1, y0 + 1)


def face_patch(image: np.ndarray, bbox, size_px: int, margin: float) -> np.ndarray:
    """BGR uint8 (size_px, size_px, 3): the face box plus ``margin``, stretched to a square.

    Stretching (not letter-boxing) makes every face fill the patch whatever its
    aspect, as in the training data; area interpolation when shrinking keeps
    small pictogram strokes instead of aliasing them away.
    """
    if image.ndim != 3 or image.shape[2] != 3:
        raise ValueError(f"face_patch needs a BGR image, got shape {image.shape}")
    height, width = image.shape[:2]
    x0, y0, x1, y1 = expanded_box(bbox, margin)
    # clip the box to the image, then replicate the border for the part outside it
    cx0, cy0 = min(max(x0, 0), width - 1), min(max(y0, 0), height - 1)
    cx1, cy1 = max(min(x1, width), cx0 + 1), max(min(y1, height), cy0 + 1)
    region = image[cy0:cy1, cx0:cx1]
    pad = (max(0, cy0 - y0), max(0, y1 - cy1), max(0, cx0 - x0), max(0, x1 - cx1))
    if any(pad):
        region = cv2.copyMakeBorder(region, *pad, cv2.BORDER_REPLICATE)
    interp = cv2.INTER_AREA if region.shape[0] > size_px or region.shape[1] > size_px else cv2.INTER_LINEAR
    return cv2.resize(region, (size_px, size_px), interpolation=interp)


def standardise(patches: np.ndarray) -> np.ndarray:
    """float32 NCHW blob from uint8 NHWC BGR patches, each standardised over all its pixels and channels.

    Removing each patch's own mean and contrast takes exposure and contrast out of
    what the network must learn, but keeps the colour ratios that tell red from blue.
    """
    x = patches.astype(np.float32) / 255.0
    mean = x.mean(axis=(1, 2, 3), keepdims=True)
    std = x.std(axis=(1, 2, 3), keepdims=True)
    x = (x - mean) / (std + 0.05)
    return np.ascontiguousarray(x.transpose(0, 3, 1, 2))
