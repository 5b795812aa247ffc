"""Is a plate a pictogram plate (SSV 5.xx drawing), and which? Normalised cross-correlation with the templates.

The network of the sign catalogue does not know plates, so plates are compared
with the renderings of the official drawings (``plate_catalogue``) as the
template route compares signs: the plate's crop, grey, scaled to each template's
aspect at ``COMPARE_HEIGHT_PX``, correlated with it over a few pixels of shift
(the plate's box is found to a pixel or two) and a few insets (a box taken for
the inside of a frame is that much larger than the plate). Pixels hidden by
something in front (a branch) are left out of the correlation. Below
``min_score`` it is a text plate and OCR reads it.
"""

from __future__ import annotations

from typing import Optional, Sequence

import cv2
import numpy as np

COMPARE_HEIGHT_PX = 36
SHIFT_PX = 3
INSETS = (0.0, 0.06, 0.12)  # of the crop's height, cut from each side before comparing
MIN_SEEN = 0.4  # share of the plate that must be seen to compare it at all


def _scaled(grey: np.ndarray, width: int, height: int) -> np.ndarray:
    interpolation = cv2.INTER_AREA if grey.shape[0] > height else cv2.INTER_LINEAR
    return cv2.resize(grey, (width, height), interpolation=interpolation)


def _masked_ncc(seen: np.ndarray, drawn: np.ndarray, weight: np.ndarray) -> float:
    """Best zero-mean normalised correlation of ``drawn`` over ``seen`` (padded by SHIFT_PX), over the
    pixels ``weight`` marks as seen."""
    h, w = drawn.shape
    best = -1.0
    for dy in range(0, seen.shape[0] - h + 1):
        for dx in range(0, seen.shape[1] - w + 1):
            m = weight[dy:dy + h, dx:dx + w]
            if m.sum() < MIN_SEEN * m.size:
                continue
            a, b = seen[dy:dy + h, dx:dx + w][m], drawn[m]
            a, b = a - a.mean(), b - b.mean()
            denominator = np.sqrt((a * a).sum() * (b * b).sum())
            if denominator > 0:
                best = max(best, float((a * b).sum() / denominator))
    return best


def pictogram_scores(crop: np.ndarray, templates: Sequence, hidden: Optional[np.ndarray] = None) -> list:
    """Correlation (-1..1) of a plate crop (BGR or grey) with each template, best shift and inset.

    ``hidden``: the crop's pixels hidden by something in front (same size), left out."""
    grey = cv2.cvtColor(crop, cv2.COLOR_BGR2GRAY) if crop.ndim == 3 else crop
    partial = hidden is not None and hidden.any()
    scores = []
    for template in templates:
        width = max(8, int(round(COMPARE_HEIGHT_PX * template.aspect)))
        drawn = _scaled(template.grey, width, COMPARE_HEIGHT_PX).astype(np.float32)
        best = -1.0
        for inset in INSETS:
            cut = int(round(inset * grey.shape[0]))
            if grey.shape[0] - 2 * cut < 8 or grey.shape[1] - 2 * cut < 8:
                continue
            part = grey[cut:grey.shape[0] - cut, cut:grey.shape[1] - cut]
            seen = cv2.copyMakeBorder(_scaled(part, width, COMPARE_HEIGHT_PX), SHIFT_PX, SHIFT_PX, SHIFT_PX,
                                      SHIFT_PX, cv2.BORDER_REPLICATE).astype(np.float32)
            if partial:
                mask = hidden[cut:grey.shape[0] - cut, cut:grey.shape[1] - cut].astype(np.uint8)
                shown = (cv2.resize(mask, (width, COMPARE_HEIGHT_PX), interpolation=cv2.INTER_NEAREST) == 0)
                visible = cv2.copyMakeBorder(shown.astype(np.uint8), SHIFT_PX, SHIFT_PX, SHIFT_PX, SHIFT_PX,
                                             cv2.BORDER_CONSTANT, value=0).astype(bool)
                best = max(best, _masked_ncc(seen, drawn, visible))
            else:
                best = max(best, float(cv2.matchTemplate(seen, drawn, cv2.TM_CCOEFF_NORMED).max()))
        scores.append(best)
    return scores


def classify_plate(crop: np.ndarray, templates: Sequence, min_score: float,
                   hidden: Optional[np.ndarray] = None) -> tuple[Optional[object], float]:
    """(the pictogram plate template the crop shows, its score), or (None, best score) for a text plate."""
    if not templates or crop.size == 0:
        return None, 0.0
    scores = pictogram_scores(crop, templates, hidden)
    best = int(np.argmax(scores))
    return (templates[best] if scores[best] >= min_score else None), scores[best]
