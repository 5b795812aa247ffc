"""Step 2: the search space, pixels whose depth lies in the configured range.

Signs are searched only 4-14 m ahead by default: nearer they are cut by the
image border, farther they are too small to classify.
"""

from __future__ import annotations

import numpy as np


def valid_depth(depth: np.ndarray) -> np.ndarray:
    """Boolean mask of pixels with a usable depth (finite and positive)."""
    with np.errstate(invalid="ignore"):
        return np.isfinite(depth) & (depth > 0)


def search_space_mask(depth: np.ndarray, near_m: float, far_m: float) -> np.ndarray:
    """Boolean mask of pixels with ``near_m <= Z <= far_m``; NaN/inf/<=0 are outside."""
    with np.errstate(invalid="ignore"):
        return (depth >= near_m) & (depth <= far_m)
