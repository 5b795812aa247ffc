"""Priority-road diamonds found by their white frame: the yellow is judged against the white around it.

A priority road (3.03, 3.04) is a yellow diamond inside a white one. In dusk light its yellow turns dark
orange (hue 8-13, below the yellow band), washed out in a bright backlight it turns nearly white, and in front
of autumn leaves its yellow joins theirs into one segment. Its structure survives: on some level of the grey
ladder (:mod:`.bright_fields`) the whole sign, or its frame, is a bright component whose outline is a diamond;
and its middle is yellow *relative to its frame* (blue drops far more than red), a white balance local to the
sign like the red ring's against its field. The diamond's outline is the face's (the white frame is its
edge): it becomes a yellow segment of source "frame", which the catalogue's yellow diamonds fit whole.
"""

from __future__ import annotations

from typing import Optional, Tuple

import cv2
import numpy as np

from .config import PipelineConfig
from .shape import classify_shape

Box = Tuple[int, int, int, int]


def scaled_outline_mask(outline: np.ndarray, factor: float, size: Tuple[int, int]) -> np.ndarray:
    """uint8 0/255 mask (``size`` = (h, w)) of the outline (box pixels) shrunk by ``factor`` about its centroid."""
    points = outline.reshape(-1, 2).astype(np.float64)
    centre = points.mean(axis=0)
    mask = np.zeros(size, np.uint8)
    cv2.fillPoly(mask, [np.round(centre + factor * (points - centre)).astype(np.int32)], 255)
    return mask


def yellow_against_frame(core_bgr: np.ndarray, frame_bgr: np.ndarray, config: PipelineConfig) -> bool:
    """Whether a diamond's middle (mean or median B, G, R) is yellow relative to its frame's.

    Per channel, middle / frame: yellow keeps red and green and loses blue, whatever the light's colour
    (GTSDB tune split, priority roads: blue/red 0.29-0.76; a white middle: ~1).
    """
    q = (np.asarray(core_bgr, np.float64) + 1.0) / (np.asarray(frame_bgr, np.float64) + 1.0)
    fields = config.bright_fields
    return q[0] / q[2] <= fields.diamond_max_blue_red and q[1] / q[2] >= fields.diamond_min_green_red


def box_yellow_against_frame(small: np.ndarray, labels: np.ndarray, label: int, box: Box,
                             config: PipelineConfig) -> bool:
    """:func:`yellow_against_frame` read from the box alone (means): its middle against the component's pixels
    near its corners, where a diamond's frame reaches the box (its tips)."""
    x, y, w, h = box
    crop = small[y : y + h, x : x + w]
    inner = config.bright_fields.diamond_core_scale / 2.0
    cx0, cx1 = int(round(w * (0.5 - inner / 2))), int(round(w * (0.5 + inner / 2)))
    cy0, cy1 = int(round(h * (0.5 - inner / 2))), int(round(h * (0.5 + inner / 2)))
    frame = cv2.compare(labels[y : y + h, x : x + w], float(label), cv2.CMP_EQ)
    frame[h // 5 : h - h // 5, w // 5 : w - w // 5] = 0
    if cx1 <= cx0 or cy1 <= cy0 or not cv2.countNonZero(frame):
        return False
    core = np.asarray(cv2.mean(crop[cy0:cy1, cx0:cx1])[:3])
    return yellow_against_frame(core, cv2.mean(crop, mask=frame)[:3], config)


def _diamond_outline(labels: np.ndarray, label: int, box: Box, config: PipelineConfig):
    """The component's outer outline (box pixels) and its filled mask when that outline is a diamond."""
    x, y, w, h = box
    component = cv2.compare(labels[y : y + h, x : x + w], float(label), cv2.CMP_EQ)
    contours, _ = cv2.findContours(component, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    outline = max(contours, key=cv2.contourArea)
    filled = np.zeros((h, w), np.uint8)
    cv2.drawContours(filled, [outline], -1, 255, thickness=cv2.FILLED)
    result = classify_shape(filled, config.shape.min_shape_fit, config.shape.shape_fill_window)
    if result.shape != "diamond" or result.fit < config.bright_fields.diamond_min_fit:
        return None
    return outline, filled


def _core_and_frame(filled: np.ndarray, outline: np.ndarray, config: PipelineConfig):
    fields = config.bright_fields
    core = scaled_outline_mask(outline, fields.diamond_core_scale, filled.shape)
    frame = cv2.subtract(filled, scaled_outline_mask(outline, fields.diamond_frame_scale, filled.shape))
    return core, frame


def framed_diamond(image: np.ndarray, small: np.ndarray, labels: np.ndarray, label: int, box: Box,
                   scale: float, config: PipelineConfig) -> Optional[Tuple[Box, np.ndarray, np.ndarray]]:
    """(box, filled mask, outer contour) in full-image pixels of a white-framed diamond with a yellow middle.

    ``labels``/``label``/``box``: one bright component of the ladder on ``small`` (``image`` reduced by
    ``scale``) that passed :func:`box_yellow_against_frame`. None unless its outline is a diamond whose
    middle is yellow against its frame at full resolution (medians).
    """
    found = _diamond_outline(labels, label, box, config)
    if found is None:
        return None
    outline, filled = found
    x, y, w, h = box
    # the outline at full resolution (pixel centres)
    full = np.round((outline.reshape(-1, 2).astype(np.float64) + (x, y) + 0.5) / scale - 0.5).astype(np.int32)
    bx, by, bw, bh = cv2.boundingRect(full)
    if bx < 0 or by < 0 or bx + bw > image.shape[1] or by + bh > image.shape[0]:
        return None
    local = full - (bx, by)
    filled = np.zeros((bh, bw), np.uint8)
    cv2.drawContours(filled, [local], -1, 255, thickness=cv2.FILLED)
    core, frame = _core_and_frame(filled, local, config)
    crop = image[by : by + bh, bx : bx + bw]
    if not cv2.countNonZero(core) or not cv2.countNonZero(frame):
        return None
    if not yellow_against_frame(np.median(crop[core > 0], axis=0), np.median(crop[frame > 0], axis=0), config):
        return None
    return (bx, by, bw, bh), filled, full
