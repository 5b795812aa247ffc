"""Where a colour lies inside each template's face: which templates a colour segment may be.

Most faces carry their colour up to the edge (a red ring, a blue disc), but
some have a white rim around the coloured part (the yellow diamond of the
priority road) or carry a coloured disc on a white panel (zone signs): the
colour segment is then smaller than the face, and the face's box must be grown
before it is sized and matched. And a sign catalogued under one colour may be
outlined by another (the blue no-parking disc has a red ring). The extent is
measured once per template and colour on its rendering, with the same HSV
thresholds as the colour step, so it follows whatever the catalogue draws.
"""

from __future__ import annotations

from typing import Dict, Iterable, List, Optional, Tuple

import cv2
import numpy as np

from .classify import canonical_template
from .colour import hsv_mask
from .shape import classify_shape

FULL = (0.0, 0.0, 1.0, 1.0)
_cache: Dict[Tuple[int, str, str], tuple] = {}
Extent = Tuple[float, float, float, float]  # x0, y0, x1, y1 as fractions of the face box


def colour_part(catalogue, template_id: str, colour: str, hsv_ranges) -> Tuple[Optional[Extent], Optional[str]]:
    """(extent, outline shape) of the template's ``colour`` pixels; (None, None) if it has none.

    The extent is the colour's bounding box as fractions of the face box; the
    shape is that of the filled outline of the colour's pixels, as the colour
    step would see it.
    """
    key = (id(catalogue), template_id, colour)
    hit = _cache.get(key)
    if hit is not None and hit[0] is catalogue:
        return hit[1]
    extent, shape = None, None
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
            filled = np.zeros_like(mask)
            contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
            cv2.drawContours(filled, contours, -1, 255, thickness=cv2.FILLED)
            part = filled[ys.min() : ys.max() + 1, xs.min() : xs.max() + 1]
            shape = classify_shape(part).shape
    _cache[key] = (catalogue, (extent, shape))
    return extent, shape


def colour_extent(catalogue, template_id: str, colour: str, hsv_ranges) -> Optional[Extent]:
    """Bounding box of the template's ``colour`` pixels as fractions of its face box; None if it has none."""
    return colour_part(catalogue, template_id, colour, hsv_ranges)[0]


def face_bbox(segment_bbox, extent: Extent) -> Tuple[int, int, int, int]:
    """The face's pixel box given the colour segment's box and the template's colour extent."""
    if extent == FULL:
        return tuple(int(v) for v in segment_bbox)
    x, y, w, h = segment_bbox
    fx0, fy0, fx1, fy1 = extent
    fw, fh = w / (fx1 - fx0), h / (fy1 - fy0)
    return (int(round(x - fx0 * fw)), int(round(y - fy0 * fh)), int(round(fw)), int(round(fh)))


def _area(extent: Extent) -> float:
    return (extent[2] - extent[0]) * (extent[3] - extent[1])


def candidate_entries(catalogue, colour: str, shapes: Iterable[str], hsv_ranges, allowed_colours: Iterable[str],
                      exclude: Iterable[str] = ()) -> List[Tuple[object, Extent]]:
    """(entry, colour extent) of the templates a ``colour`` segment of one of ``shapes`` may show.

    - entries of that colour and shape (extent as measured, FULL if not measurable);
    - entries of another allowed colour and that shape outlined by this colour;
    - rectangular panels carrying an inset part of this colour and shape (zone signs).
    """
    shapes, allowed, excluded = set(shapes), set(allowed_colours), set(exclude)
    out = []
    for entry in catalogue:
        if entry.id in excluded or entry.colour not in allowed:
            continue
        extent, part_shape = colour_part(catalogue, entry.id, colour, hsv_ranges)
        if entry.colour == colour and entry.shape in shapes and (extent in (None, FULL) or part_shape in shapes):
            out.append((entry, extent or FULL))
        elif extent is None:
            continue
        elif extent == FULL and entry.shape in shapes:
            out.append((entry, extent))
        elif entry.shape in ("rectangle", "square") and part_shape in shapes and 0.1 < _area(extent) < 0.8:
            out.append((entry, extent))
    return out
