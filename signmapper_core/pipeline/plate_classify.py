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

from ..plates.catalogue import LAYOUT, TEXT
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


def _score(grey: np.ndarray, template, inset: float, plates: PlateConfig, hidden: Optional[np.ndarray] = None
           ) -> float:
    """Best correlation of ``grey`` (cut by ``inset``) with ``template``; pixels ``hidden`` (uint8, the crop's
    size) are left out of it (widened by the shift searched: the drawing moves under them)."""
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
    if hidden is not None:
        gone = cv2.resize(hidden[cut:grey.shape[0] - cut, cut:grey.shape[1] - cut], (width, height),
                          interpolation=cv2.INTER_NEAREST)
        gone = cv2.dilate(gone, np.ones((2 * shift + 1, 2 * shift + 1), np.uint8))
        mask = (np.ones((height, width), np.float32) if mask is None else mask) * (gone == 0)
        if mask.mean() < plates.plate_pictogram_min_seen:  # too little of the drawing left to tell it by
            return -1.0
    scores = cv2.matchTemplate(seen, drawn, cv2.TM_CCOEFF_NORMED, mask=mask)
    return float(np.clip(np.nan_to_num(scores, nan=-1.0, posinf=-1.0, neginf=-1.0), -1.0, 1.0).max())


def _painted(grey: np.ndarray, hidden: Optional[np.ndarray]) -> np.ndarray:
    """``grey`` with its ``hidden`` pixels painted the plate's paper (the median of what is seen)."""
    if hidden is None:
        return grey
    out = grey.copy()
    out[hidden > 0] = int(np.median(grey[hidden == 0]))
    return out


def comparable(template, crop_shape, plates: PlateConfig) -> bool:
    """Whether a crop of ``crop_shape`` may show ``template``: a drawing (not a text plate) of about its aspect."""
    if template.kind == TEXT or min(crop_shape[:2]) < 1:
        return False
    aspect = crop_shape[1] / crop_shape[0]
    return abs(math.log(aspect / template.aspect)) <= math.log(1.0 + plates.plate_aspect_tolerance)


def crossing_occluders(not_white: np.ndarray, sign_columns: tuple, sign_width: int, plates: PlateConfig) -> np.ndarray:
    """uint8 mask of the window's narrow vertical runs of ``not_white`` (uint8) pixels that cross it from top to
    bottom within the sign's columns (``sign_columns``: first, last + 1 in the window): a lamp post or trunk in
    front of sign and plate, whose depth is unknown where stereo matched only around the sign's colour."""
    height = not_white.shape[0]
    c0, c1 = max(0, sign_columns[0]), min(not_white.shape[1], sign_columns[1])
    out = np.zeros_like(not_white)
    span = int(plates.plate_occluder_span * height)
    if c1 - c0 < 2 or span < 2:
        return out
    runs = cv2.morphologyEx(np.ascontiguousarray(not_white[:, c0:c1]), cv2.MORPH_OPEN, np.ones((span, 1), np.uint8),
                            borderType=cv2.BORDER_CONSTANT, borderValue=0)  # beyond the window: no run
    count, labels, stats, _ = cv2.connectedComponentsWithStats(runs, connectivity=4)
    narrow = np.zeros(count, bool)
    narrow[1:] = stats[1:, cv2.CC_STAT_WIDTH] <= plates.plate_occluder_max_width * sign_width
    out[:, c0:c1] = narrow[labels].astype(np.uint8)
    return out


def crop_poles(grey: np.ndarray, plates: PlateConfig) -> np.ndarray:
    """uint8 mask of a plate crop's narrow dark runs from top to bottom away from its edges: a pole in front of
    the plate whose depth is unknown and whose grey passed for the plate's paper where the plate step looked for
    one (:func:`crossing_occluders` on the crop, darker than ``plate_occluder_contrast`` x its paper)."""
    height, width = grey.shape[:2]
    edge = int(round(plates.plate_frame_share * min(height, width))) + 1
    darker = (grey < plates.plate_occluder_contrast * float(np.median(grey))).astype(np.uint8)
    return crossing_occluders(darker, (edge, width - edge), width, plates)


def pictogram_scores(crop: np.ndarray, templates: Sequence, config: PipelineConfig,
                     hidden: Optional[np.ndarray] = None) -> list:
    """Correlation (-1..1) of a plate crop (BGR or grey) with each template, best shift and inset (the insets
    only for the ``plate_inset_candidates`` templates the crop is most like as it is); -1 for a template it is
    not :func:`comparable` with.

    ``hidden``: the crop's pixels hidden by something in front (same size): left out of the correlation (and
    painted the plate's paper), so a branch counts as a missing part, not as a dark one; a drawing in colour
    (``coloured``: its coloured print is "hidden" too) scores the better of that and the crop as seen; a pole
    crossing the crop (:func:`crop_poles`) is tried as hidden too. Less than ``plate_pictogram_min_seen`` of it
    seen: no score (-1)."""
    plates = config.plates
    grey = cv2.cvtColor(crop, cv2.COLOR_BGR2GRAY) if crop.ndim == 3 else crop
    hidden = None if hidden is None or not hidden.any() else hidden.astype(np.uint8)
    min_seen = plates.plate_pictogram_min_seen
    if hidden is not None and 1.0 - hidden.mean() < min_seen:
        return [-1.0] * len(templates)
    poles = crop_poles(grey, plates)
    # what is compared: the crop as the plate step saw it; with a pole found in it hidden too (a drawing's own
    # upright arrow runs top to bottom as well: the better of the two counts); and a drawing in colour also as
    # seen, its coloured print not hidden (the plate step takes coloured pixels for something in front)
    masks = [hidden] + ([poles if hidden is None else hidden | poles] if poles.any() else [])
    views = [(_painted(grey, gone), gone) for gone in masks if gone is None or 1.0 - gone.mean() >= min_seen]
    as_seen = [(grey, None)] if hidden is not None else []
    first, *more = plates.plate_compare_insets

    def score(template, inset):
        return max([_score(seen, template, inset, plates, gone)
                    for seen, gone in views + (as_seen if template.coloured else [])], default=-1.0)

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
