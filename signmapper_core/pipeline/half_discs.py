"""Round faces of which the colour step kept only one half: the whole disc read from the half.

A no-entry sign's white bar cuts its red disc into two halves; a ring in shade keeps its colour on the lit
half only. When the other half is lost (too dark, or joined to the sign below it and outlined with that
one), the half that is left is a segment about twice as wide as high whose hull is a half disc, flat side
down (the upper half) or up (the lower). The face is then the square on that segment's width, extending
across the flat side. It becomes a segment of its own (source ``"half"``): outlined as the disc, its depth
and planarity read on the half's own pixels, its class decided like any round face's, as a marginal outline.
"""

from __future__ import annotations

from typing import List, Optional, Sequence, Tuple

import cv2
import numpy as np

from .boxes import box_iou, touches_border
from .colour import Segment, inscribed_disc
from .config import PipelineConfig
from .shape import mask_iou


def half_disc_mask(width: int, height: int, upper: bool) -> np.ndarray:
    """uint8 0/255 (height, width) mask of the upper (flat side down) or lower half of a disc filling the box."""
    mask = np.zeros((height, width), np.uint8)
    centre = (width / 2.0 - 0.5, height - 0.5 if upper else -0.5)
    cv2.ellipse(mask, (centre, (float(width), 2.0 * height), 0.0), 255, thickness=cv2.FILLED)
    return mask


def half_disc_side(seg: Segment, config: PipelineConfig) -> Optional[bool]:
    """True when the segment is the upper half of a disc, False when the lower, None when neither."""
    x, y, w, h = seg.bbox
    low, high = config.shape.half_disc_aspect
    if seg.source != "colour" or not (low * h <= w <= high * h) or h < config.colour.min_bbox_px // 2:
        return None
    hull = np.zeros((h, w), np.uint8)  # an arc of a ring is a crescent; its hull is the half disc
    cv2.drawContours(hull, [cv2.convexHull(seg.contour.reshape(-1, 1, 2))], -1, 255, thickness=cv2.FILLED,
                     offset=(-x, -y))
    upper, lower = (mask_iou(hull > 0, half_disc_mask(w, h, side) > 0) for side in (True, False))
    if max(upper, lower) < config.shape.half_disc_min_fit:
        return None
    return upper >= lower


def whole_disc(seg: Segment, upper: bool, image_size: Tuple[int, int], config: PipelineConfig) -> Segment:
    """The disc a half belongs to: the square on its width across its flat side, the half's pixels its surface."""
    x, y, w, h = seg.bbox
    top = y if upper else y + h - w
    mask, contour = inscribed_disc(w)
    surface = np.zeros((w, w), np.uint8)
    rows = slice(0, h) if upper else slice(w - h, w)
    surface[rows] = seg.surface_mask
    surface = cv2.bitwise_and(surface, mask)
    touches = touches_border((x, top, w, w), image_size[0], image_size[1], config.colour.border_margin_px)
    return Segment(seg.colour, (x, top, w, w), mask, contour + np.array([x, top]),
                   int(np.count_nonzero(mask)), seg.touches_border or touches, "half", 1.0, surface)


def other_half_in_search(disc: Segment, half: Segment, search: Optional[np.ndarray], min_share: float) -> bool:
    """Whether the part of the disc's box outside the half lies in the search space (bool mask, image size) by at
    least ``min_share``: the other half lost its colour, not its depth (the search space did not cut it off)."""
    if search is None:
        return True
    x, y, w, h = disc.bbox
    region = search[max(0, y) : y + h, max(0, x) : x + w].copy()
    hx, hy, hw, hh = half.bbox
    region[max(0, hy - y) : hy - y + hh, max(0, hx - x) : hx - x + hw] = False
    outside_half = w * h - hw * hh
    return outside_half > 0 and np.count_nonzero(region) >= min_share * outside_half


def with_half_discs(segments: Sequence[Segment], image_size: Tuple[int, int], config: PipelineConfig,
                    search: Optional[np.ndarray] = None, colours: Sequence[str] = ("red",)) -> List[Segment]:
    """``segments`` followed by the whole discs of those that are half a disc of one of ``colours`` (red: rings
    and no-entry discs), unless a segment of the same colour already outlines that disc (``half_disc_same_iou``)
    or the search space (bool mask, when given) cut the other half off (:func:`other_half_in_search`)."""
    out = list(segments)
    for seg in segments:
        if seg.colour not in colours:
            continue
        side = half_disc_side(seg, config)
        if side is None:
            continue
        disc = whole_disc(seg, side, image_size, config)
        if not other_half_in_search(disc, seg, search, config.shape.half_disc_min_search_share):
            continue  # a face cut by the depth range, whose other half lies nearer or farther
        if not any(o.colour == disc.colour and box_iou(o.bbox, disc.bbox) >= config.shape.half_disc_same_iou
                   for o in out):
            out.append(disc)
    return out
