"""Step 3: colour segmentation in HSV and connected segments with filled outlines.

Red signs are a red ring around a white field, so each segment is the filled
outer contour of its colour component, not the coloured pixels alone. Where
that outline is far from convex (a ring opened by an occluding pole or branch),
the convex hull is used instead: every sign outline is convex.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, Iterable, List, Optional, Sequence, Tuple

import cv2
import numpy as np

from .config import HsvRange


@dataclass
class Segment:
    """One candidate sign face in the left image.

    ``mask`` is the filled outline inside ``bbox`` (uint8 0/255, shape (h, w)),
    ``contour`` the outer contour in full-image pixel coordinates.
    """

    colour: str
    bbox: Tuple[int, int, int, int]  # x, y, w, h
    mask: np.ndarray
    contour: np.ndarray
    area_px: int
    touches_border: bool
    source: str = "colour"
    solidity: float = 1.0  # filled outline area / convex hull area, before any hull filling

    @property
    def centroid(self) -> Tuple[float, float]:
        """(u, v) of the filled outline's centroid in full-image pixels."""
        ys, xs = np.nonzero(self.mask)
        return float(xs.mean() + self.bbox[0]), float(ys.mean() + self.bbox[1])


def hsv_mask(hsv: np.ndarray, ranges: Sequence[HsvRange]) -> np.ndarray:
    """uint8 0/255 mask of pixels inside any of the HSV ranges."""
    out = np.zeros(hsv.shape[:2], dtype=np.uint8)
    for h0, h1, s0, s1, v0, v1 in ranges:
        out |= cv2.inRange(hsv, (h0, s0, v0), (h1, s1, v1))
    return out


def _kernel(size: int) -> Optional[np.ndarray]:
    return cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (size, size)) if size > 1 else None


def clean_mask(mask: np.ndarray, open_px: int, close_px: int) -> np.ndarray:
    """Morphological opening (speckle) then closing (gaps in thin rings)."""
    k_open, k_close = _kernel(open_px), _kernel(close_px)
    if k_open is not None:
        mask = cv2.morphologyEx(mask, cv2.MORPH_OPEN, k_open)
    if k_close is not None:
        mask = cv2.morphologyEx(mask, cv2.MORPH_CLOSE, k_close)
    return mask


def colour_masks(
    bgr: np.ndarray,
    hsv_ranges: Dict[str, Sequence[HsvRange]],
    colours: Iterable[str],
    search_mask: Optional[np.ndarray] = None,
    open_px: int = 3,
    close_px: int = 5,
) -> Dict[str, np.ndarray]:
    """Cleaned uint8 masks per colour, limited to ``search_mask`` (bool) when given."""
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    masks = {}
    for colour in colours:
        mask = hsv_mask(hsv, hsv_ranges[colour])
        if search_mask is not None:
            mask[~search_mask] = 0
        masks[colour] = clean_mask(mask, open_px, close_px)
    return masks


def segments_from_mask(
    mask: np.ndarray,
    colour: str,
    min_area_px: int = 150,
    min_bbox_px: int = 12,
    border_margin_px: int = 2,
    source: str = "colour",
    min_solidity: float = 0.85,
) -> List[Segment]:
    """Connected segments of ``mask`` as filled outer contours with bounding boxes.

    Outlines with a solidity below ``min_solidity`` are replaced by their convex hull.
    """
    height, width = mask.shape[:2]
    contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    out = []
    for contour in contours:
        x, y, w, h = cv2.boundingRect(contour)
        if w < min_bbox_px or h < min_bbox_px:
            continue
        filled = np.zeros((h, w), dtype=np.uint8)
        cv2.drawContours(filled, [contour], -1, 255, thickness=cv2.FILLED, offset=(-x, -y))
        area = int(np.count_nonzero(filled))
        if area < min_area_px:
            continue
        hull = cv2.convexHull(contour)
        hull_area = max(1.0, cv2.contourArea(hull))
        solidity = min(1.0, cv2.contourArea(contour) / hull_area)
        if solidity < min_solidity:
            cv2.drawContours(filled, [hull], -1, 255, thickness=cv2.FILLED, offset=(-x, -y))
            area = int(np.count_nonzero(filled))
        m = border_margin_px
        touches = x <= m or y <= m or x + w >= width - m or y + h >= height - m
        out.append(Segment(colour, (x, y, w, h), filled, contour, area, touches, source, solidity))
    return out

