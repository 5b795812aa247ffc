"""Step 9: Hough circle fallback for round signs the colour thresholds miss.

Faded red rings and white/grey round signs (end-of-restriction signs) have too
little saturation for the colour step. The Hough transform runs on the grey
image restricted to the search space: pixels outside the depth range are set to
black, so a round sign standing in front of a distant background also gets a
circular edge from the depth map. Candidates are downscaled for speed and go
through the same size, planarity and classification steps as colour segments.
"""

from __future__ import annotations

from dataclasses import replace
from typing import List, Optional, Sequence, Tuple

import cv2
import numpy as np

from .boxes import nonzero_box, touches_border
from .colour import Segment, hsv_mask, inscribed_disc
from .config import PipelineConfig


def radius_range_px(fx: float, near_m: float, far_m: float, diameters_m: Sequence[float], slack: float):
    """(min, max) radius in pixels of round signs of the given diameters within near..far, widened by ``slack``."""
    lo = min(diameters_m) * fx / (2.0 * far_m) * (1.0 - slack)
    hi = max(diameters_m) * fx / (2.0 * near_m) * (1.0 + slack)
    return max(3, int(np.floor(lo))), int(np.ceil(hi))


def hough_scale(r_min: float, scale: float, min_radius_px: float) -> float:
    """Scale of the Hough image: ``scale``, or an integer reduction (fast to average) that keeps the
    smallest radius sought at least ``min_radius_px`` (the transform's cost grows with the edge pixels)."""
    return float(min(scale, 1.0 / max(1, int(r_min // min_radius_px))))


def find_circles(
    bgr: np.ndarray,
    search_mask: np.ndarray,
    r_min: int,
    r_max: int,
    scale: float,
    config: PipelineConfig,
) -> np.ndarray:
    """Circles (N, 3) as (u, v, r) in full-image pixels, found in the search space (image at ``scale``); none
    where the search space is empty."""
    if not search_mask.any():
        return np.zeros((0, 3))
    grey = _reduced_search_grey(bgr, search_mask, scale, config.hough.hough_mask_median_px)
    lo, hi = max(2, int(r_min * scale)), max(3, int(np.ceil(r_max * scale)))
    circles = cv2.HoughCircles(
        grey, cv2.HOUGH_GRADIENT_ALT, dp=config.hough.hough_dp, minDist=max(4, lo),
        param1=config.hough.hough_edge_threshold, param2=config.hough.hough_circularity, minRadius=lo, maxRadius=hi,
    )
    if circles is None:
        return np.zeros((0, 3))
    return circles.reshape(-1, 3) / scale


def _search_grey(bgr: np.ndarray, search_mask: np.ndarray, scale: float, median_px: int) -> np.ndarray:
    """The grey image at ``scale`` where the search space is (its mask at ``scale`` smoothed by a median of
    ``median_px``, at least half full), 0 elsewhere: what the transform reads."""
    grey = cv2.cvtColor(bgr, cv2.COLOR_BGR2GRAY) if bgr.ndim == 3 else bgr.copy()
    mask = (search_mask.view(np.uint8) if search_mask.dtype == bool else search_mask.astype(np.uint8)) * 255
    if scale != 1.0:
        grey = cv2.resize(grey, None, fx=scale, fy=scale, interpolation=cv2.INTER_AREA)
        mask = cv2.resize(mask, (grey.shape[1], grey.shape[0]), interpolation=cv2.INTER_AREA)
    # a smooth search-space outline: speckle in a matched depth map would otherwise feed the
    # transform with many short edges (slow, and false circles)
    mask = cv2.medianBlur(mask, median_px)
    cv2.bitwise_and(grey, cv2.compare(mask, 128, cv2.CMP_GE), dst=grey)  # grey[mask < 128] = 0, in one pass
    return grey


def _reduced_search_grey(bgr: np.ndarray, search_mask: np.ndarray, scale: float, median_px: int) -> np.ndarray:
    """:func:`_search_grey`, computed only around the search space's box where the image is reduced by a whole
    factor that divides its size (the search space of a matched pair is a tenth of the frame).

    Each reduced pixel is then the mean of its own block of pixels, so the box's blocks reduce alone to the
    same values, and the reduced mask is 0 beyond them: the median is 0 where it sees only those zeros (more
    than its radius from the box) and reads the same pixels inside (the box's edge is 0 or the image's).
    """
    factor = int(round(1.0 / scale)) if scale < 1.0 else 1
    height, width = search_mask.shape[:2]
    if (factor < 2 or abs(scale * factor - 1.0) > 1e-9 or height % factor or width % factor
            or search_mask.dtype != bool or bgr.ndim != 3):
        return _search_grey(bgr, search_mask, scale, median_px)
    x, y, w, h = nonzero_box(search_mask.view(np.uint8))
    small_h, small_w = height // factor, width // factor
    out = np.zeros((small_h, small_w), np.uint8)
    if w == 0 or h == 0:
        return out
    margin = median_px // 2 + 1
    c0, r0 = max(0, x // factor - margin), max(0, y // factor - margin)
    c1 = min(small_w, -(-(x + w) // factor) + margin)
    r1 = min(small_h, -(-(y + h) // factor) + margin)
    rows, cols = slice(r0 * factor, r1 * factor), slice(c0 * factor, c1 * factor)
    size = (c1 - c0, r1 - r0)
    mask = cv2.resize(search_mask[rows, cols].view(np.uint8) * 255, size, interpolation=cv2.INTER_AREA)
    mask = cv2.medianBlur(mask, median_px)
    grey = cv2.resize(cv2.cvtColor(bgr[rows, cols], cv2.COLOR_BGR2GRAY), size, interpolation=cv2.INTER_AREA)
    cv2.bitwise_and(grey, cv2.compare(mask, 128, cv2.CMP_GE), dst=out[r0:r1, c0:c1])
    return out


def outer_ring(mask: np.ndarray, config: PipelineConfig) -> np.ndarray:
    """The outer ring of a disc mask (``hough_ring_share`` of its diameter deep), where a round sign carries its
    colour."""
    depth_px = max(1, int(mask.shape[0] * config.hough.hough_ring_share))
    return cv2.subtract(mask, cv2.erode(mask, np.ones((3, 3), np.uint8), iterations=depth_px))


def ring_colour_share(bgr: np.ndarray, mask: np.ndarray, ranges, config: PipelineConfig) -> float:
    """Share of the outer ring's pixels inside the colour step's HSV ranges (a full-colour ring: ~1)."""
    ring = outer_ring(mask, config) > 0
    if not ring.any():
        return 0.0
    return float(np.count_nonzero(hsv_mask(cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV), ranges)[ring])) / ring.sum()


def band_colour_shares(bgr: np.ndarray, bbox, bands: Sequence[Tuple[float, float]], colour_ranges: Sequence
                       ) -> List[Tuple[float, List[float]]]:
    """Per band (inner, outer radius, in radii of the disc ``bbox``: its box centre, half its longer side): the share
    of the band's pixels that lie in the image, and for each entry of ``colour_ranges`` the share of those pixels
    inside its HSV ranges (0 where none lies in the image). What surrounds a disc, read only where the image has it:
    a white field's ring, a red wall that goes on beyond it."""
    x, y, w, h = bbox
    radius = max(w, h) / 2.0
    cx, cy = x + w / 2.0, y + h / 2.0
    reach = int(np.ceil(radius * max(outer for _, outer in bands))) + 1
    x0, y0, x1, y1 = int(cx - reach), int(cy - reach), int(cx + reach) + 1, int(cy + reach) + 1
    ys, xs = np.mgrid[y0:y1, x0:x1]
    distance = np.hypot(xs + 0.5 - cx, ys + 0.5 - cy) / radius
    inside = (xs >= 0) & (ys >= 0) & (xs < bgr.shape[1]) & (ys < bgr.shape[0])
    cx0, cy0, cx1, cy1 = max(x0, 0), max(y0, 0), min(x1, bgr.shape[1]), min(y1, bgr.shape[0])
    coloured = [np.zeros(distance.shape, bool) for _ in colour_ranges]
    if cx1 > cx0 and cy1 > cy0:
        hsv = cv2.cvtColor(bgr[cy0:cy1, cx0:cx1], cv2.COLOR_BGR2HSV)
        for mask, ranges in zip(coloured, colour_ranges):
            mask[cy0 - y0 : cy1 - y0, cx0 - x0 : cx1 - x0] = hsv_mask(hsv, ranges) > 0
    out = []
    for inner, outer in bands:
        band = (distance >= inner) & (distance <= outer)
        seen = band & inside
        n_seen = int(np.count_nonzero(seen))
        out.append((n_seen / max(1, int(np.count_nonzero(band))),
                    [np.count_nonzero(mask & seen) / n_seen if n_seen else 0.0 for mask in coloured]))
    return out


def ringed_field(bgr: np.ndarray, seg: Segment, config: PipelineConfig) -> Optional[Segment]:
    """A white Hough circle as the field of a red ring around it (a red "hole" segment), or None.

    The colour step finds such a face as its ring; when a pole in front splits the ring or the image border cuts it,
    the ring is no segment and its white field is the circle Hough finds. Read as white, it would be mapped as a
    white sign (a 2.30.1 cut by the border as 2.53.1); as the ring's field, the face is grown from it as from any
    field inside a ring.
    """
    ranges = config.colour.hsv_ranges.get("red")
    if seg.colour != "white" or ranges is None:
        return None
    ((seen, (share,)),) = band_colour_shares(bgr, seg.bbox, (config.hough.hough_field_ring_band,), (ranges,))
    if seen < 0.5 or share < config.hough.hough_field_ring_share:
        return None
    return replace(seg, colour="red", source="hole")


def weak_colour(bgr: np.ndarray, mask: np.ndarray, config: PipelineConfig) -> str:
    """Dominant weak colour of the outer ring of a disc mask (``config.hough.hough_tint_hues``): red/blue/yellow, else
    white."""
    ring = outer_ring(mask, config)
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    pixels = hsv[ring > 0]
    if pixels.size == 0:
        return "white"
    tinted = pixels[pixels[:, 1] >= config.hough.hough_tint_min_saturation]
    best, best_share = "white", config.hough.hough_tint_min_share
    for name, ranges in config.hough.hough_tint_hues.items():
        hit = np.zeros(len(tinted), bool)
        for h0, h1 in ranges:
            hit |= (tinted[:, 0] >= h0) & (tinted[:, 0] <= h1)
        share = hit.sum() / float(len(pixels))
        if share > best_share:
            best, best_share = name, share
    return best


def circle_segment(bgr: np.ndarray, u: float, v: float, r: float, config: PipelineConfig) -> Optional[Segment]:
    """A Hough circle as a segment (disc mask in its box), its colour from the ring."""
    height, width = bgr.shape[:2]
    x0, y0 = int(round(u - r)), int(round(v - r))
    size = int(round(2 * r)) + 1
    if size < 3:
        return None
    touches = touches_border((x0, y0, size, size), width, height, config.colour.border_margin_px)
    if x0 < 0 or y0 < 0 or x0 + size > width or y0 + size > height:
        return None
    mask, contour = inscribed_disc(size)
    crop = bgr[y0 : y0 + size, x0 : x0 + size]
    colour = weak_colour(crop, mask, config)
    return Segment(colour, (x0, y0, size, size), mask, contour + np.array([x0, y0]),
                   int(np.count_nonzero(mask)), touches, source="hough")


def hough_segments(bgr: np.ndarray, circles: np.ndarray, config: PipelineConfig,
                   taken: Sequence[tuple] = ()) -> List[Segment]:
    """Round-sign segments of ``bgr`` from Hough ``circles`` (:func:`find_circles`) whose centre is not inside a
    ``taken`` box."""
    out = []
    for u, v, r in circles:
        if any(x <= u < x + w and y <= v < y + h for x, y, w, h in taken):
            continue
        seg = circle_segment(bgr, u, v, r, config)
        if seg is not None:
            out.append(seg)
    return out
