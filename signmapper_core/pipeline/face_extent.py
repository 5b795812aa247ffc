"""Where a template's sign colour lies inside its face, to size faces from colour segments.

Most faces carry their colour up to the edge (a red ring, a blue disc), but
some have a white rim around the coloured part (the yellow diamond of the
priority road): the colour segment is then smaller than the face, and the
face's box must be grown before it is sized and matched. The extent is measured
once per template on its rendering, with the same HSV thresholds as the
colour step, so it follows whatever the catalogue draws.
"""

from __future__ import annotations

from typing import Dict, Tuple

import cv2
import numpy as np

from .classify import canonical_template
from .colour import hsv_mask

FULL = (0.0, 0.0, 1.0, 1.0)
_cache: Dict[Tuple[int, str, str], tuple] = {}

Extent = Tuple[float, float, float, float]  # x0, y0, x1, y1 as fractions of the face box


def colour_extent(catalogue, template_id: str, colour: str, hsv_ranges) -> Extent:
    """Bounding box of the template's ``colour`` pixels as fractions of its face box (FULL if none)."""
    key = (id(catalogue), template_id, colour)
    hit = _cache.get(key)
    if hit is not None and hit[0] is catalogue:
        return hit[1]
    extent = FULL
    if colour in hsv_ranges:
        bgr, alpha = canonical_template(catalogue, template_id)
        mask = hsv_mask(cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV), hsv_ranges[colour])
        mask[alpha <= 127] = 0
        ys, xs = np.nonzero(mask)
        if ys.size > 0.02 * mask.size:
            h, w = mask.shape
            extent = (xs.min() / w, ys.min() / h, (xs.max() + 1) / w, (ys.max() + 1) / h)
            if all(abs(a - b) < 0.03 for a, b in zip(extent, FULL)):
                extent = FULL  # colour reaches the edge: no correction, avoid rounding noise
    _cache[key] = (catalogue, extent)
    return extent


def face_bbox(segment_bbox, extent: Extent) -> Tuple[int, int, int, int]:
    """The face's pixel box given the colour segment's box and the template's colour extent."""
    if extent == FULL:
        return tuple(int(v) for v in segment_bbox)
    x, y, w, h = segment_bbox
    fx0, fy0, fx1, fy1 = extent
    fw, fh = w / (fx1 - fx0), h / (fy1 - fy0)
    return (int(round(x - fx0 * fw)), int(round(y - fy0 * fh)), int(round(fw)), int(round(fh)))
