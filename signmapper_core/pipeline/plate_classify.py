"""Is a plate a pictogram plate (SSV 5.xx drawing), and which? Normalised cross-correlation with the templates.

The network of the sign catalogue does not know plates, so plates are compared
with the renderings of the official drawings (``plate_catalogue``) as the
template route compares signs: the plate's crop, grey, scaled to each template's
aspect at ``COMPARE_HEIGHT_PX``, correlated with it over a few pixels of shift
(the plate's box is found to a pixel or two) and a few insets (a box taken for
the inside of a frame is that much larger than the plate). Pixels hidden by
something in front (a branch) are painted the plate's paper first. Below
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


_DRAWN: dict = {}  # (id, variant, width) -> the template scaled for comparing (the masters never change)


def _drawn(template, width: int) -> np.ndarray:
    key = (template.id, template.variant, width)
    if key not in _DRAWN:
        _DRAWN[key] = _scaled(template.grey, width, COMPARE_HEIGHT_PX).astype(np.float32)
    return _DRAWN[key]


def _score(grey: np.ndarray, template, inset: float) -> float:
    cut = int(round(inset * grey.shape[0]))
    if grey.shape[0] - 2 * cut < 8 or grey.shape[1] - 2 * cut < 8:
        return -1.0
    width = max(8, int(round(COMPARE_HEIGHT_PX * template.aspect)))
    part = grey[cut:grey.shape[0] - cut, cut:grey.shape[1] - cut]
    seen = cv2.copyMakeBorder(_scaled(part, width, COMPARE_HEIGHT_PX), SHIFT_PX, SHIFT_PX, SHIFT_PX, SHIFT_PX,
                              cv2.BORDER_REPLICATE).astype(np.float32)
    return float(cv2.matchTemplate(seen, _drawn(template, width), cv2.TM_CCOEFF_NORMED).max())


def pictogram_scores(crop: np.ndarray, templates: Sequence, hidden: Optional[np.ndarray] = None) -> list:
    """Correlation (-1..1) of a plate crop (BGR or grey) with each template, best shift and inset (the insets
    only for the two templates the crop is most like as it is).

    ``hidden``: the crop's pixels hidden by something in front (same size): painted the plate's paper (the
    median of what is seen) before comparing, so a branch counts as a missing part, not as a dark one. Less than
    MIN_SEEN of it seen: no score (-1)."""
    grey = cv2.cvtColor(crop, cv2.COLOR_BGR2GRAY) if crop.ndim == 3 else crop
    if hidden is not None and hidden.any():
        shown = ~hidden.astype(bool)
        if shown.mean() < MIN_SEEN:
            return [-1.0] * len(templates)
        grey = grey.copy()
        grey[~shown] = int(np.median(grey[shown]))
    scores = [_score(grey, template, INSETS[0]) for template in templates]
    for k in np.argsort(scores)[::-1][:2]:
        scores[k] = max([scores[k]] + [_score(grey, templates[k], inset) for inset in INSETS[1:]])
    return scores


def classify_plate(crop: np.ndarray, templates: Sequence, min_score: float,
                   hidden: Optional[np.ndarray] = None) -> tuple[Optional[object], float]:
    """(the pictogram plate template the crop shows, its score), or (None, best score) for a text plate."""
    if not templates or crop.size == 0:
        return None, 0.0
    scores = pictogram_scores(crop, templates, hidden)
    best = int(np.argmax(scores))
    return (templates[best] if scores[best] >= min_score else None), scores[best]
