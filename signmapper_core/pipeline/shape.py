"""Step 4: the outline shape of a segment from two descriptors.

The fill ratio (area / bounding-box area) separates the families: ~0.5 for
triangles and diamonds, ~0.8 for circles and octagons, ~1 for rectangles. The
outline fit (IoU with each ideal outline drawn into the same box) then picks
the shape inside the family, which also tells an up from a down triangle and a
circle (IoU with an octagon 0.95) from an octagon. Ideal outlines are drawn into
the bounding box, so mild perspective (ellipses, sheared boxes) still fits.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Dict, Optional, Tuple

import cv2
import numpy as np

_A = 1.0 / (2.0 + np.sqrt(2.0))  # corner cut of a regular octagon, fraction of its width

# Vertices in the unit box (x right, y down).
IDEAL_POLYGONS = {
    "triangle": [(0.5, 0.0), (1.0, 1.0), (0.0, 1.0)],
    "triangle-down": [(0.0, 0.0), (1.0, 0.0), (0.5, 1.0)],
    "octagon": [(_A, 0), (1 - _A, 0), (1, _A), (1, 1 - _A), (1 - _A, 1), (_A, 1), (0, 1 - _A), (0, _A)],
    "diamond": [(0.5, 0.0), (1.0, 0.5), (0.5, 1.0), (0.0, 0.5)],
    "rectangle": [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
}
# St Andrew's crosses (3.22-3.25): not convex, in one or two parts, each read off its official drawing (322.svg
# ... 325.svg) in the unit box; upright ones are the wide ones turned. All are the catalogue's shape "cross".
_CROSS = [(0.0, 0.066), (0.037, 0.241), (0.33, 0.496), (0.037, 0.755), (0.006, 0.938), (0.096, 0.996),
          (0.498, 0.642), (0.902, 0.996), (0.998, 0.931), (0.961, 0.755), (0.668, 0.5), (0.961, 0.241),
          (0.996, 0.062), (0.904, 0.0), (0.5, 0.354), (0.094, 0.0)]
_CROSS_DOUBLE = ([(0.0, 0.046), (0.037, 0.168), (0.33, 0.345), (0.035, 0.525), (0.002, 0.65), (0.094, 0.693),
                  (0.498, 0.447), (0.904, 0.693), (0.998, 0.647), (0.963, 0.525), (0.668, 0.348), (0.961, 0.168),
                  (0.996, 0.043), (0.904, 0.0), (0.5, 0.246), (0.094, 0.0)],
                 [(0.0, 0.952), (0.094, 0.997), (0.498, 0.751), (0.904, 0.997), (0.998, 0.952), (0.961, 0.83),
                  (0.5, 0.551), (0.037, 0.83)])
_CROSS_DOUBLE_UPRIGHT = ([(0.064, 0.0), (0.0, 0.064), (0.351, 0.344), (0.0, 0.617), (0.059, 0.678), (0.239, 0.658),
                          (0.5, 0.457), (0.755, 0.658), (0.931, 0.682), (0.995, 0.617), (0.644, 0.338),
                          (0.995, 0.064), (0.936, 0.004), (0.755, 0.023), (0.495, 0.225), (0.239, 0.023)],
                         [(0.495, 0.545), (0.0, 0.936), (0.064, 0.998), (0.239, 0.975), (0.5, 0.773), (0.755, 0.975),
                          (0.931, 0.998), (0.995, 0.934)])
CROSS_OUTLINES = {
    "cross": (_CROSS,),
    "cross-upright": ([(y, x) for x, y in _CROSS],),
    "cross-double": _CROSS_DOUBLE,
    "cross-double-upright": _CROSS_DOUBLE_UPRIGHT,
}
DOUBLE_CROSS_OUTLINES = ("cross-double", "cross-double-upright")  # two parts: found as two colour segments
IDEAL_FILL = {"circle": np.pi / 4, "triangle": 0.5, "triangle-down": 0.5, "octagon": 2 / (1 + np.sqrt(2)),
              "diamond": 0.5, "rectangle": 1.0, "cross": 0.5, "cross-upright": 0.5, "cross-double": 0.54,
              "cross-double-upright": 0.53}
SHAPES = tuple(IDEAL_FILL)
_SHIFT = 4  # fixed-point bits for sub-pixel drawing
_POLYGON_ARRAYS = {shape: (np.array(corners, dtype=np.float64),) for shape, corners in IDEAL_POLYGONS.items()}
_POLYGON_ARRAYS.update({shape: tuple(np.array(part, dtype=np.float64) for part in parts)
                        for shape, parts in CROSS_OUTLINES.items()})


@dataclass(frozen=True)
class ShapeResult:
    shape: Optional[str]  # None: no ideal outline fits
    fit: float  # IoU with the chosen ideal outline
    fill_ratio: float
    circularity: float
    corners: int
    fits: Dict[str, float]


def ideal_mask(shape: str, width: int, height: int) -> np.ndarray:
    """uint8 0/255 mask of the ideal ``shape`` filling a width x height box.

    The box spans the pixels' outer edges, -0.5 .. width-0.5 in pixel-centre coordinates.
    """
    return _drawn_ideal(shape, width, height, 255)


def _drawn_ideal(shape: str, width: int, height: int, value: int) -> np.ndarray:
    """:func:`ideal_mask` drawn with ``value`` (1: a mask that views as bool without a comparison pass)."""
    mask = np.zeros((height, width), dtype=np.uint8)
    scale = 1 << _SHIFT
    if shape == "circle":
        centre = (int(round((width - 1) / 2 * scale)), int(round((height - 1) / 2 * scale)))
        axes = (int(round(width / 2 * scale)), int(round(height / 2 * scale)))
        cv2.ellipse(mask, centre, axes, 0, 0, 360, value, thickness=cv2.FILLED, shift=_SHIFT)
        return mask
    parts = [np.round((part * (width, height) - 0.5) * scale).astype(np.int32) for part in _POLYGON_ARRAYS[shape]]
    cv2.fillPoly(mask, parts, value, shift=_SHIFT)
    return mask


_CACHED_IDEAL_PX = 128 * 128  # larger boxes are rare and each would hold much memory


def _ideal(shape: str, width: int, height: int) -> Tuple[np.ndarray, int]:
    ideal = _drawn_ideal(shape, width, height, 1).view(np.bool_)
    return ideal, int(np.count_nonzero(ideal))


@lru_cache(maxsize=512)
def _cached_ideal(shape: str, width: int, height: int) -> Tuple[np.ndarray, int]:
    ideal, count = _ideal(shape, width, height)
    ideal.flags.writeable = False
    return ideal, count


def _ideal_pixels(shape: str, width: int, height: int) -> Tuple[np.ndarray, int]:
    """(bool mask of :func:`ideal_mask`, its pixel count): a segment's outline is fitted several times a pair,
    at the same size."""
    if width * height <= _CACHED_IDEAL_PX:
        return _cached_ideal(shape, width, height)
    return _ideal(shape, width, height)


def mask_iou(a: np.ndarray, b: np.ndarray, counts: Optional[Tuple[int, int]] = None) -> float:
    """IoU of two bool masks; ``counts`` (their pixel counts, when known) spares counting their union."""
    if counts is None:
        union = np.count_nonzero(a | b)
        return float(np.count_nonzero(a & b)) / union if union else 0.0
    inter = np.count_nonzero(a & b)
    union = counts[0] + counts[1] - inter
    return float(inter) / union if union else 0.0


def fill_ratio(mask: np.ndarray) -> float:
    """Share of a mask's bounding box (the mask's own array) that it fills."""
    height, width = mask.shape[:2]
    return float(np.count_nonzero(mask)) / float(width * height) if width * height else 0.0


def shapes_tried(fill: float, fill_window: float) -> Tuple[str, ...]:
    """The shapes :func:`classify_shape` fits to a mask of this fill ratio: those whose ideal fill ratio is within
    ``fill_window`` of it."""
    return tuple(shape for shape, ideal_fill in IDEAL_FILL.items() if abs(fill - ideal_fill) <= fill_window)


def shape_fits(mask: np.ndarray, shapes, count: Optional[int] = None) -> Dict[str, float]:
    """IoU of a filled segment mask (cropped to its bounding box) with the ideal outline of each of ``shapes``;
    ``count``: its nonzero pixels, when already counted."""
    height, width = mask.shape[:2]
    pixels = mask > 0
    if count is None or mask.dtype not in (np.uint8, np.bool_):
        count = int(np.count_nonzero(pixels))
    fits = {}
    for shape in shapes:
        ideal, ideal_count = _ideal_pixels(shape, width, height)
        fits[shape] = mask_iou(pixels, ideal, (count, ideal_count))
    return fits


def classify_shape(mask: np.ndarray, min_fit: float, fill_window: float) -> ShapeResult:
    """Shape of a filled segment mask cropped to its bounding box.

    Shapes whose ideal fill ratio is more than ``fill_window`` from the measured
    one are not considered; of the rest, the best outline fit wins if >= ``min_fit``.
    """
    height, width = mask.shape[:2]
    area = float(np.count_nonzero(mask))
    fill = area / float(width * height) if width * height else 0.0  # fill_ratio, its pixels counted once
    # findContours reads any nonzero byte as 1: a uint8 mask needs no conversion
    contours, _ = cv2.findContours(mask if mask.dtype == np.uint8 else (mask > 0).astype(np.uint8),
                                   cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    circularity, corners = 0.0, 0
    if contours:
        contour = max(contours, key=cv2.contourArea)
        perimeter = cv2.arcLength(contour, True)
        if perimeter > 0:
            circularity = float(4 * np.pi * cv2.contourArea(contour) / perimeter**2)
            hull = cv2.convexHull(contour)
            corners = len(cv2.approxPolyDP(hull, 0.04 * cv2.arcLength(hull, True), True))
    fits = shape_fits(mask, shapes_tried(fill, fill_window), int(area))
    best = max(fits, key=fits.get) if fits else None
    if best is None or fits[best] < min_fit:
        return ShapeResult(None, fits.get(best, 0.0) if best else 0.0, fill, circularity, corners, fits)
    return ShapeResult(best, fits[best], fill, circularity, corners, fits)


def outline_shapes(result: ShapeResult, margin: float, min_fit: float) -> Tuple[str, ...]:
    """The best-fitting shape and every other one within ``margin`` of its fit (and >= ``min_fit``).

    A small disc and a small octagon differ by a few pixels at their corners (their ideal
    outlines overlap by IoU 0.95): where the fits are that close, both readings stay open
    and the templates decide.
    """
    if result.shape is None:
        return ()
    best = result.fits[result.shape]
    others = sorted((s for s, f in result.fits.items() if s != result.shape and f >= max(min_fit, best - margin)),
                    key=result.fits.get, reverse=True)
    return (result.shape, *others)


def ambiguity_margin(base: float, blur_px: float, width_px: int, height_px: int, min_axis_ratio: float) -> float:
    """How close another outline's fit must be to the best one to stay a candidate, for a segment of this size.

    A blurred edge moves the outline by about ``blur_px`` all round, which costs a shape's fit about
    ``blur_px`` / its shorter side: on a 15 px segment the corners of a diamond and an octagon are that blur.
    Only compact boxes get the extra margin: faces other than rectangles are never longer than
    1 / ``min_axis_ratio`` (a disc seen at an angle), so for a bar or a plate no other reading opens.
    """
    short, long_ = min(width_px, height_px), max(width_px, height_px, 1)
    if short < min_axis_ratio * long_:
        return base
    return base + blur_px / max(1, short)


def plausible_outlines(mask: np.ndarray, config) -> Tuple[ShapeResult, Tuple[str, ...]]:
    """(the outline's fits, the shapes it may have, best first) of a segment mask with a run's settings
    (``config``: a ``PipelineConfig``): the best fit and every other within :func:`ambiguity_margin` of it."""
    shape = config.shape
    result = classify_shape(mask, shape.min_shape_fit, shape.shape_fill_window)
    height, width = mask.shape[:2]
    margin = ambiguity_margin(shape.shape_ambiguity, shape.shape_ambiguity_px, width, height,
                              config.size.min_round_axis_ratio)
    return result, outline_shapes(result, margin, shape.min_shape_fit)


def catalogue_shape(shape: str) -> str:
    """The catalogue's name of a detected outline (the four cross outlines are its 'cross')."""
    return "cross" if shape in CROSS_OUTLINES else shape


def catalogue_shapes(shape: str, width_px: int, height_px: int) -> tuple:
    """Catalogue shape names a detected outline may be: a rectangle may be a square, or a direction sign's
    pointer (its pointed end costs a rectangle's outline about a tenth of its fit)."""
    if shape == "rectangle":
        return ("square", "rectangle", "pointer")
    if shape in CROSS_OUTLINES:
        return ("cross",)
    return (shape,)
