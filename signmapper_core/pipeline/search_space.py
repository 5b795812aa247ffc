"""Step 2: the search space, pixels whose depth lies in the configured range (``search_range.in_search_range``),
and the morphology that keeps a sign's face whole in it."""

from __future__ import annotations

import cv2
import numpy as np


def valid_depth(depth: np.ndarray) -> np.ndarray:
    """Boolean mask of pixels with a usable depth (finite and positive)."""
    with np.errstate(invalid="ignore"):
        return np.isfinite(depth) & (depth > 0)


def close_holes(mask: np.ndarray, size_px: int) -> np.ndarray:
    """Morphological closing of a boolean mask with a ``size_px`` square.

    Matched depth has holes on a sign's uniform white field and at its pictogram;
    cutting the colour mask with the raw search space would break a red ring into
    pieces. A square kernel keeps this cheap (separable: a few ms on Full HD).
    """
    if size_px <= 1:
        return mask
    kernel = cv2.getStructuringElement(cv2.MORPH_RECT, (size_px, size_px))
    return cv2.morphologyEx(mask.astype(np.uint8), cv2.MORPH_CLOSE, kernel) > 0


def grow(mask: np.ndarray, size_px: int) -> np.ndarray:
    """Dilation of a boolean mask with a ``size_px`` square.

    SGBM loses the left edge of a sign standing in front of a distant background
    (the matching window there straddles both depths): 10-20 px of its ring fall
    out of the search space, which is no hole that a closing could fill.
    """
    if size_px <= 1:
        return mask
    kernel = cv2.getStructuringElement(cv2.MORPH_RECT, (size_px, size_px))
    if mask.dtype == bool:
        return cv2.dilate(mask.view(np.uint8), kernel).view(bool)  # bool bytes are 0/1: dilated, still 0/1
    return cv2.dilate(mask.astype(np.uint8), kernel) > 0
