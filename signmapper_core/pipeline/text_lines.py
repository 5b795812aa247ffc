"""Counting the lines of text on a direction sign's face, to type it within its group of line counts.

The face's field is its most common colour; text (white on brown, blue or green, black on orange) is every
pixel far from it. Rows holding text form one band per line; a band narrower than a share of the face's height,
or than a share of the highest band, is a stroke of the border, a speck or a line's accents, not a line.
"""

from __future__ import annotations

from typing import Optional

import cv2
import numpy as np

from ..catalogue.text_lines import line_groups, with_lines

_groups: dict = {}  # id(catalogue) -> (catalogue, its line groups): every detection of a run asks again


def text_line_count(bgr: np.ndarray, bbox, config) -> Optional[int]:
    """Lines of text inside face ``bbox`` of ``bgr``; None when the face is too low to tell
    (``config.text_lines_min_px``) or holds no text.

    ``config``: the ``ClassificationConfig`` (``text_lines_*``): the share of the face cut off at the top and
    bottom (its border) and at each side (border and a pointer's tip), the Lab distance from the field that
    counts as text, the share of a column's pixels above which it is something in front (a pole), the share
    of a row's pixels that makes it a text row, and the least height of a line as a share of the face's.
    """
    x, y, w, h = bbox
    if h < config.text_lines_min_px:
        return None
    dy, dx = int(round(h * config.text_lines_inset[1])), int(round(w * config.text_lines_inset[0]))
    inner = bgr[max(y + dy, 0) : max(y + h - dy, 0), max(x + dx, 0) : max(x + w - dx, 0)]
    if inner.shape[0] < 3 or inner.shape[1] < 3:
        return None
    lab = cv2.cvtColor(inner, cv2.COLOR_BGR2LAB).reshape(-1, 3).astype(np.float32)
    field = np.median(lab, axis=0)
    ink = (np.linalg.norm(lab - field, axis=1) > config.text_lines_contrast).reshape(inner.shape[:2])
    ink = ink[:, ink.mean(axis=0) <= config.text_lines_max_column_ink]  # a pole in front is no text
    if ink.shape[1] == 0:
        return None
    rows = ink.mean(axis=1) >= config.text_lines_row_share
    edges = np.flatnonzero(np.diff(np.concatenate(([0], rows.astype(np.int8), [0]))))
    bands = edges[1::2] - edges[0::2]
    if bands.size == 0:
        return None
    # a line's band is as high as the others (one font a sign): a thinner one is accents or a descender's tail
    least = max(config.text_lines_min_height * h, config.text_lines_min_band_share * bands.max())
    lines = int((bands >= least).sum())
    return lines or None


def line_member(template_id: str, bgr: np.ndarray, bbox, catalogue, config) -> Optional[str]:
    """The entry of ``template_id``'s line group (``catalogue.text_lines.line_groups``) whose line count the face
    ``bbox`` shows; None when it is in no group, the lines cannot be counted or no entry has that count."""
    hit = _groups.get(id(catalogue))
    if hit is None or hit[0] is not catalogue:
        hit = _groups[id(catalogue)] = (catalogue, line_groups(catalogue))
    groups = hit[1]
    if template_id not in groups:
        return None
    lines = text_line_count(bgr, bbox, config)
    return with_lines(groups, template_id, lines) if lines else None


def typed_by_lines(template_id: str, bgr: np.ndarray, bbox, catalogue, config) -> str:
    """``template_id``, or the member of its line group the face's lines of text say (:func:`line_member`)."""
    return line_member(template_id, bgr, bbox, catalogue, config) or template_id
