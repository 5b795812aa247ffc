"""Step 5: metric size of a segment from its depth, rounded to a standard format.

Signs come in a few standard formats (round 0.60/0.40 m, triangles 0.90/0.60 m
side, ...); a segment whose metric size fits none of the formats of its colour
and shape is not a sign. This removes most distractors (façades, cars, clothes).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..catalogue.model import MEASURED, STANDARD, SizeMatch
from ..geometry import Camera
from .search_space import valid_depth


@dataclass(frozen=True)
class SegmentSize:
    depth_m: float  # median depth of the segment's pixels
    width_m: float
    height_m: float
    coverage: float  # share of the segment's pixels with a valid depth


def segment_depth(depth: np.ndarray, bbox, mask: np.ndarray, near_m: float = 0.0, far_m: float = np.inf):
    """(median depth, coverage) of the masked pixels inside ``bbox``; NaN when none is valid.

    Only depths within near..far count, so background seen through holes of the
    filled outline (or matching errors) does not pull the median.
    """
    x, y, w, h = bbox
    values = depth[y : y + h, x : x + w][mask > 0]
    n = values.size
    if n == 0:
        return float("nan"), 0.0
    ok = valid_depth(values) & (values >= near_m) & (values <= far_m)
    if not ok.any():
        return float("nan"), 0.0
    return float(np.median(values[ok])), float(np.count_nonzero(ok)) / n


def metric_size(camera: Camera, bbox, depth_m: float) -> tuple:
    """(width_m, height_m) of a pixel bounding box at depth Z: ``w*Z/fx``, ``h*Z/fy``."""
    _, _, w, h = bbox
    return w * depth_m / camera.fx, h * depth_m / camera.fy


def measure_segment(camera: Camera, depth: np.ndarray, bbox, mask, near_m: float, far_m: float
                    ) -> Optional[SegmentSize]:
    """Depth and metric size of a segment, or None when it has no depth in range."""
    z, coverage = segment_depth(depth, bbox, mask, near_m, far_m)
    if not np.isfinite(z):
        return None
    width_m, height_m = metric_size(camera, bbox, z)
    return SegmentSize(z, width_m, height_m, coverage)


def round_to_format(catalogue, entries, width_m: float, height_m: float, tolerance: float,
                    off_format_factor: float = 1.0):
    """The first of :func:`size_readings`, or None."""
    readings = size_readings(catalogue, entries, width_m, height_m, tolerance, off_format_factor)
    return readings[0] if readings else None


def size_readings(catalogue, entries, width_m: float, height_m: float, tolerance: float,
                  off_format_factor: float = 1.0) -> list:
    """What a face of this size may be among ``entries``: the nearest standard format within ``tolerance``
    (:meth:`Catalogue.round_size`), and the signs without a standard size it could be (a ``measured``
    :class:`SizeMatch`), each a reading of its own, so that a disc's format does not hide a board of the
    same size.

    Where no standard format fits, a face within ``off_format_factor`` of some entries' formats (old and
    custom-made signs exist) is sized as measured too (:func:`off_format`); the caller decides whether such a
    reading is clear enough to map.
    """
    standard = [e for e in entries if e.sizing == STANDARD]
    measured = [e for e in entries if e.sizing != STANDARD]
    out = []
    match = catalogue.round_size(width_m, height_m, tolerance=tolerance, entries=standard) if standard else None
    if match is not None:
        out.append(match)
    elif standard and off_format_factor > 1.0:
        out.append(off_format(standard, width_m, height_m, off_format_factor, tolerance))
    if measured:
        out.append(catalogue.round_size(width_m, height_m, tolerance=tolerance, entries=measured))
    return [m for m in out if m is not None]


def off_format(entries, width_m: float, height_m: float, factor: float, aspect_tolerance: float):
    """A ``measured`` :class:`SizeMatch` of the standard-size entries with a format within ``factor`` of
    ``width_m`` x ``height_m`` in both sides and of its aspect within ``aspect_tolerance``, or None: a sign made
    at another size keeps its proportions (a triangle with its top hidden does not)."""
    if not (width_m > 0 and height_m > 0):
        return None
    limit, aspect_limit = np.log(factor), np.log(1.0 + aspect_tolerance)
    ids = tuple(e.id for e in entries if e.sizing == STANDARD and any(
        abs(np.log(width_m / w)) <= limit and abs(np.log(height_m / h)) <= limit
        and abs(np.log(width_m / height_m * h / w)) <= aspect_limit for w, h in e.formats.values()))
    return SizeMatch(MEASURED, width_m, height_m, 0.0, ids) if ids else None
