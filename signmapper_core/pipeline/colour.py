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
    depth_mask: Optional[np.ndarray] = None  # pixels for depth and planarity if not all of ``mask``

    @property
    def surface_mask(self) -> np.ndarray:
        """The pixels known to lie on the face: ``depth_mask`` if set, else ``mask``."""
        return self.mask if self.depth_mask is None else self.depth_mask

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



def box_gap(a, b) -> float:
    """Pixels between two boxes (x, y, w, h); 0 when they touch or overlap."""
    ax, ay, aw, ah = a
    bx, by, bw, bh = b
    dx = max(0, max(ax, bx) - min(ax + aw, bx + bw))
    dy = max(0, max(ay, by) - min(ay + ah, by + bh))
    return float(max(dx, dy))


def merge_segments(a: Segment, b: Segment) -> Segment:
    """One segment from two pieces of the same face (a pole or branch cut it): the hull of both.

    Depth and planarity are taken on the pieces only, not on the occluder between them.
    """
    points = np.vstack([a.contour.reshape(-1, 2), b.contour.reshape(-1, 2)])
    hull = cv2.convexHull(points)
    x, y, w, h = cv2.boundingRect(hull)
    mask = np.zeros((h, w), np.uint8)
    cv2.drawContours(mask, [hull], -1, 255, thickness=cv2.FILLED, offset=(-x, -y))
    pieces = np.zeros((h, w), np.uint8)
    for seg in (a, b):
        sx, sy, sw, sh = seg.bbox
        pieces[sy - y : sy - y + sh, sx - x : sx - x + sw] |= seg.surface_mask
    return Segment(a.colour, (x, y, w, h), mask, hull, int(np.count_nonzero(mask)),
                   a.touches_border or b.touches_border, a.source, 1.0, pieces)


def merge_candidates(segments: Sequence[Segment], max_gap_fraction: float = 0.35) -> List[Segment]:
    """Merged segments of same-coloured pieces close to each other, for faces split by an occluder.

    Two pieces qualify when the gap between their boxes is at most ``max_gap_fraction``
    of the merged box's size and the merged box is not elongated beyond 2:1.
    """
    out = []
    for i, a in enumerate(segments):
        for b in segments[i + 1 :]:
            if a.colour != b.colour:
                continue
            x0, y0 = min(a.bbox[0], b.bbox[0]), min(a.bbox[1], b.bbox[1])
            x1 = max(a.bbox[0] + a.bbox[2], b.bbox[0] + b.bbox[2])
            y1 = max(a.bbox[1] + a.bbox[3], b.bbox[1] + b.bbox[3])
            w, h = x1 - x0, y1 - y0
            if box_gap(a.bbox, b.bbox) > max_gap_fraction * max(w, h) or max(w, h) > 2 * min(w, h):
                continue
            out.append(merge_segments(a, b))
    return out
