"""Danger triangles whose top is hidden by something in front: the whole triangle read from its base.

A branch or a hedge over the top of a triangle leaves a red trapezoid: its width is the triangle's (the base is
seen), its height too small for any format, so the size step rejects it. When what lies where the apex should be
is coloured but not red (leaves, a hedge: saturated, of another hue), the face is the triangle standing on the
segment's base, as wide as the segment and as high as the catalogue's triangles are for that width. Classification
then decides on that face as on any other (the pictogram is mostly below the hidden top). Only segments whose
outline still reads as a triangle are completed: with about a third of the top hidden the trapezoid fits a disc or
an octagon better, and is not taken for a triangle at all.
"""

from __future__ import annotations

from typing import Optional, Tuple

import cv2
import numpy as np

from ..sign_colours import RED_ANY_SATURATION_HUES, in_hue_bands
from .shape import ideal_mask

Box = Tuple[int, int, int, int]


def apex_completed_face(image: np.ndarray, bbox: Box, aspect: float, config) -> Optional[Box]:
    """The face box of a triangle of ``aspect`` (width / height of its formats, ``TemplateEntry.aspect``) standing
    on the segment's base, when the segment is too low for one and the part of that triangle above it is hidden by
    something coloured that is not the red of the ring (``config.size.apex_min_hidden`` of its pixels); else None."""
    x, y, w, h = bbox
    full_h = int(round(w / aspect))
    if h >= (1.0 - config.size.size_tolerance) * full_h:
        return None  # tall enough: a triangle as it is
    top = y + h - full_h
    if top < 0:
        return None  # the apex lies beyond the image: cut, not hidden
    above = full_h - h
    region = image[top:top + above, x:x + w]
    inside = ideal_mask("triangle", w, full_h)[:above] > 0
    if region.size == 0 or not inside.any():
        return None
    hsv = cv2.cvtColor(region, cv2.COLOR_BGR2HSV)
    hidden = (hsv[..., 1] > config.size.apex_min_saturation) & ~_red(hsv)
    if np.count_nonzero(hidden & inside) < config.size.apex_min_hidden * np.count_nonzero(inside):
        return None
    return (x, top, w, full_h)


def _red(hsv: np.ndarray) -> np.ndarray:
    """Pixels of a red hue (either end of the hue circle), whatever their saturation."""
    return in_hue_bands(hsv[..., 0], RED_ANY_SATURATION_HUES)
