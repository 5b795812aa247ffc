"""Whether a face carries print: a sign's symbols, text or inner border make grey-level edges inside its
colour; a plain coloured patch (a façade, a tarpaulin, a painted door) has none."""

from __future__ import annotations

import cv2
import numpy as np


def print_share(bgr: np.ndarray, bbox, inset: float, low: int, high: int) -> float:
    """Share of the pixels of ``bbox``'s inner part (``inset`` of its width and height cut off each side) on a
    Canny edge (``low``, ``high``) of the grey image; 0.0 for a part too small to hold an edge."""
    x, y, w, h = bbox
    dx, dy = int(round(w * inset)), int(round(h * inset))
    inner = bgr[max(y + dy, 0) : max(y + h - dy, 0), max(x + dx, 0) : max(x + w - dx, 0)]
    if inner.shape[0] < 3 or inner.shape[1] < 3:
        return 0.0
    edges = cv2.Canny(cv2.cvtColor(inner, cv2.COLOR_BGR2GRAY), low, high)
    return float(np.count_nonzero(edges)) / edges.size
