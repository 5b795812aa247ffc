"""Which plate drawing (SSV 5.xx) does a plate show? Normalised cross-correlation with the templates.

The network of the sign catalogue does not know plates, so plates are compared
with the renderings of the official drawings (``plate_catalogue``) as the
template route compares signs: the plate's crop, grey, scaled to each template's
aspect at ``plate_compare_height_px``, both a little blurred, correlated with it
over a few pixels of shift (the plate's box is found to a pixel or two) and a few insets (a box taken
for the inside of a frame is that much larger than the plate). Only drawings of
about the crop's aspect are compared (``plate_aspect_tolerance``): a plate's box
is measured well, and a vehicle plate stretched to another's aspect can look much
like it. A layout plate (a drawing with a field of free text, 5.03) is compared
outside its text field only (a mask): its text differs from plate to plate.
Pixels hidden by something in front (a branch) are painted the plate's paper
first. Below ``plate_pictogram_min_score`` it is a text plate and OCR reads it.
The settings are those of ``PlateConfig`` (``config.plates``).
"""

from __future__ import annotations

import math
from typing import Optional, Sequence

import cv2
import numpy as np

from ..plate_catalogue import LAYOUT, TEXT
from .config import PipelineConfig, PlateConfig


def _scaled(grey: np.ndarray, width: int, height: int, blur_px: float) -> np.ndarray:
    """``grey`` at width x height, blurred by ``blur_px`` (Gaussian sigma): a thin frame or stroke a pixel off
    between crop and drawing then still overlaps."""
    interpolation = cv2.INTER_AREA if grey.shape[0] > height else cv2.INTER_LINEAR
    out = cv2.resize(grey, (width, height), interpolation=interpolation)
    return cv2.GaussianBlur(out, (0, 0), blur_px) if blur_px > 0 else out


# (id, variant, width, height) -> the template scaled for comparing and its mask (the masters never change)
_DRAWN: dict = {}


def _drawn(template, width: int, height: int, blur_px: float) -> tuple:
    """(the template at width x height, blurred by ``blur_px``, float32; the mask of what is compared: None for
    the whole drawing, else 1 outside a layout plate's text field and 0 in it)."""
    key = (template.id, template.variant, width, height, blur_px)
    if key not in _DRAWN:
        mask = None
        if template.kind == LAYOUT:
            x0, y0, x1, y1 = template.field
            mask = np.ones((height, width), np.float32)
            mask[int(round(y0 * height)):int(round(y1 * height)), int(round(x0 * width)):int(round(x1 * width))] = 0
        _DRAWN[key] = (_scaled(template.grey, width, height, blur_px).astype(np.float32), mask)
    return _DRAWN[key]


def _compare_size(template, plates: PlateConfig) -> tuple:
    """(width, height) a template is compared at: ``plate_compare_height_px`` on its shorter side."""
    short, smallest = plates.plate_compare_height_px, plates.plate_compare_min_px
    if template.aspect >= 1.0:
        return max(smallest, int(round(short * template.aspect))), short
    return short, max(smallest, int(round(short / template.aspect)))


def _score(grey: np.ndarray, template, inset: float, plates: PlateConfig) -> float:
    cut = int(round(inset * min(grey.shape[:2])))
    smallest, shift = plates.plate_compare_min_px, plates.plate_compare_shift_px
    if grey.shape[0] - 2 * cut < smallest or grey.shape[1] - 2 * cut < smallest:
        return -1.0
    width, height = _compare_size(template, plates)
    part = grey[cut:grey.shape[0] - cut, cut:grey.shape[1] - cut]
    blur = plates.plate_compare_blur_px
    seen = cv2.copyMakeBorder(_scaled(part, width, height, blur), shift, shift, shift, shift,
                              cv2.BORDER_REPLICATE).astype(np.float32)
    drawn, mask = _drawn(template, width, height, blur)
    scores = cv2.matchTemplate(seen, drawn, cv2.TM_CCOEFF_NORMED, mask=mask)
    return float(np.nan_to_num(scores, nan=-1.0, posinf=-1.0, neginf=-1.0).max())


def comparable(template, crop_shape, plates: PlateConfig) -> bool:
    """Whether a crop of ``crop_shape`` may show ``template``: a drawing (not a text plate) of about its aspect."""
    if template.kind == TEXT or min(crop_shape[:2]) < 1:
        return False
    aspect = crop_shape[1] / crop_shape[0]
    return abs(math.log(aspect / template.aspect)) <= math.log(1.0 + plates.plate_aspect_tolerance)


def pictogram_scores(crop: np.ndarray, templates: Sequence, config: PipelineConfig,
                     hidden: Optional[np.ndarray] = None) -> list:
    """Correlation (-1..1) of a plate crop (BGR or grey) with each template, best shift and inset (the insets
    only for the ``plate_inset_candidates`` templates the crop is most like as it is); -1 for a template it is
    not :func:`comparable` with.

    ``hidden``: the crop's pixels hidden by something in front (same size): painted the plate's paper (the
    median of what is seen) before comparing, so a branch counts as a missing part, not as a dark one; a drawing
    in colour (``coloured``: its coloured print is "hidden" too) scores the better of that and the crop as seen.
    Less than ``plate_pictogram_min_seen`` of it seen: no score (-1)."""
    plates = config.plates
    grey = raw = cv2.cvtColor(crop, cv2.COLOR_BGR2GRAY) if crop.ndim == 3 else crop
    if hidden is not None and hidden.any():
        shown = ~hidden.astype(bool)
        if shown.mean() < plates.plate_pictogram_min_seen:
            return [-1.0] * len(templates)
        grey = grey.copy()
        grey[~shown] = int(np.median(grey[shown]))
    else:
        raw = None  # nothing painted over: one comparison
    first, *more = plates.plate_compare_insets

    def score(template, inset):
        # a drawing in colour is compared as seen too: its coloured print counts as hidden in front
        painted = _score(grey, template, inset, plates)
        return max(painted, _score(raw, template, inset, plates)) if template.coloured and raw is not None \
            else painted

    scores = [score(template, first) if comparable(template, grey.shape, plates) else -1.0 for template in templates]
    for k in np.argsort(scores)[::-1][:plates.plate_inset_candidates]:
        if scores[k] > -1.0:
            scores[k] = max([scores[k]] + [score(templates[k], inset) for inset in more])
    return scores


def classify_plate(crop: np.ndarray, templates: Sequence, config: PipelineConfig,
                   hidden: Optional[np.ndarray] = None) -> tuple[Optional[object], float]:
    """(the pictogram or layout plate template the crop shows, its score), or (None, best score) for a text plate
    (below ``plate_pictogram_min_score``)."""
    if not templates or crop.size == 0:
        return None, 0.0
    scores = pictogram_scores(crop, templates, config, hidden)
    best = int(np.argmax(scores))
    return (templates[best] if scores[best] >= config.plates.plate_pictogram_min_score else None), scores[best]
