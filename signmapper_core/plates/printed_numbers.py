"""The number printed on a speed-limit face, and the band of the face it is read from.

A speed limit read as another speed limit (a heavy "30" taken for "80") is the
worst misreading a survey can carry, and the classifier makes it with high
confidence on faces printed in other fonts. The digits themselves are a second,
independent reading: Tesseract reads them from a band across the middle of the
face, and :mod:`.number_check` sends a sign whose digits say another number to
review.
"""

from __future__ import annotations

import re
from typing import Iterable, Optional, Tuple

import numpy as np

# ids "2.30-<km/h>": the maximum speeds; the general limits carry their number in the drawing only
SPEED_LIMIT = re.compile(r"^2\.30-(\d+)$")
GENERAL_LIMITS = {"2.30.1": "50"}
# the band the digits fill, as shares of the face box (width, height), centred: wide enough for "120",
# low enough to leave out most of the red ring (measured on GTSRB tune crops and the tune drives)
BAND_SHARE = (0.76, 0.46)
# a face smaller than this is not read: Tesseract misreads more small speed limits than the classifier does (GTSRB
# tune crops below 30 px); the drives see a 0.6-m face at 14 m ~60 px wide
MIN_FACE_PX = 30
BAND_KEEP_PX = 96  # a band is kept (and read) at most this high: enough for Tesseract, small to carry
READ_BORDER_PX = 20  # plain white around the digits: Tesseract reads little on a line touching the frame


def speed_limit_number(template_id: Optional[str]) -> Optional[str]:
    """The number of a maximum speed's id ("80" for 2.30-80); None for every other id, the general limits
    included (their number is part of the drawing, not of the id)."""
    found = SPEED_LIMIT.match(template_id) if template_id else None
    return found.group(1) if found else None


def printed_number(template_id: Optional[str]) -> Optional[str]:
    """The number a speed-limit template prints ("30" for 2.30-30, "50" for the general limit 2.30.1); None for
    any other template."""
    return speed_limit_number(template_id) or GENERAL_LIMITS.get(template_id)


def printed_numbers(template_ids: Iterable[str]) -> frozenset:
    """Every number the speed-limit templates among ``template_ids`` print: the readings that name a sign."""
    return frozenset(n for n in map(printed_number, template_ids) if n is not None)


def band_box(bbox: Tuple[int, int, int, int]) -> Tuple[int, int, int, int]:
    """(x0, y0, x1, y1) of the digits' band of a face box (x, y, w, h), full-image pixels."""
    x, y, w, h = bbox
    bw, bh = BAND_SHARE[0] * w, BAND_SHARE[1] * h
    cx, cy = x + w / 2.0, y + h / 2.0
    return int(round(cx - bw / 2)), int(round(cy - bh / 2)), int(round(cx + bw / 2)), int(round(cy + bh / 2))


def number_band(image: np.ndarray, bbox: Tuple[int, int, int, int]) -> Optional[np.ndarray]:
    """The grey digits' band of the face ``bbox`` in ``image`` (BGR uint8), at most ``BAND_KEEP_PX`` high;
    None when the band is cut by the image's edge or the face is smaller than ``MIN_FACE_PX``."""
    import cv2

    x0, y0, x1, y1 = band_box(bbox)
    height, width = image.shape[:2]
    if x0 < 0 or y0 < 0 or x1 > width or y1 > height or min(bbox[2], bbox[3]) < MIN_FACE_PX:
        return None
    band = cv2.cvtColor(image[y0:y1, x0:x1], cv2.COLOR_BGR2GRAY)
    if band.shape[0] > BAND_KEEP_PX:
        scale = BAND_KEEP_PX / band.shape[0]
        band = cv2.resize(band, None, fx=scale, fy=scale, interpolation=cv2.INTER_AREA)
    return band


def prepared_band(band: np.ndarray) -> np.ndarray:
    """A band as Tesseract reads digits best: ``BAND_KEEP_PX`` high, black digits on white (Otsu's threshold:
    the digits are the darker of the field's two tones), a white border."""
    import cv2

    scale = BAND_KEEP_PX / max(band.shape[0], 1)
    grey = cv2.resize(band, None, fx=scale, fy=scale, interpolation=cv2.INTER_CUBIC)
    _, binary = cv2.threshold(grey, 0, 255, cv2.THRESH_BINARY + cv2.THRESH_OTSU)
    b = READ_BORDER_PX
    return cv2.copyMakeBorder(binary, b, b, b, b, cv2.BORDER_CONSTANT, value=255)
