import cv2
import numpy as np
import pytest

from signmapper_core.pipeline.config import TEMPLATE_GEOMETRY
from signmapper_core.pipeline.shape import (
    ShapeResult,
    classify_shape,
    fill_ratio,
    outline_shapes,
    shape_fits,
    shapes_tried,
)

SIZE = 61
# clean drawn outlines, read as the catalogue's templates are
FIT, WINDOW = TEMPLATE_GEOMETRY.template_min_fit, TEMPLATE_GEOMETRY.template_fill_window


def _polygon(points):
    mask = np.zeros((SIZE, SIZE), np.uint8)
    cv2.fillPoly(mask, [np.array(points, np.int32)], 255)
    return mask


def _crop(mask):
    ys, xs = np.nonzero(mask)
    return mask[ys.min() : ys.max() + 1, xs.min() : xs.max() + 1]


def _octagon(r, c=30):
    angles = np.radians(22.5 + 45 * np.arange(8))
    return _polygon([(c + r * np.cos(a), c + r * np.sin(a)) for a in angles])


def _drawn(shape, r=28):
    if shape == "circle":
        mask = np.zeros((SIZE, SIZE), np.uint8)
        cv2.circle(mask, (30, 30), r, 255, -1)
        return mask
    if shape == "triangle":
        return _polygon([(30, 2), (58, 51), (2, 51)])
    if shape == "triangle-down":
        return _polygon([(2, 5), (58, 5), (30, 54)])
    if shape == "octagon":
        return _octagon(r)
    if shape == "diamond":
        return _polygon([(30, 2), (58, 30), (30, 58), (2, 30)])
    if shape == "rectangle":
        return _polygon([(5, 15), (55, 15), (55, 45), (5, 45)])
    raise ValueError(shape)


@pytest.mark.parametrize("shape", ["circle", "triangle", "triangle-down", "octagon", "diamond", "rectangle"])
def test_drawn_shapes_are_recognised(shape):
    result = classify_shape(_crop(_drawn(shape)), FIT, WINDOW)
    assert result.shape == shape, result


@pytest.mark.parametrize("shape,radius", [("circle", 12), ("octagon", 14), ("circle", 45), ("octagon", 45)])
def test_circle_and_octagon_differ_at_small_and_large_sizes(shape, radius):
    size = 2 * radius + 5
    mask = np.zeros((size, size), np.uint8)
    c = size // 2
    if shape == "circle":
        cv2.circle(mask, (c, c), radius, 255, -1)
    else:
        angles = np.radians(22.5 + 45 * np.arange(8))
        pts = np.array([(c + radius * np.cos(a), c + radius * np.sin(a)) for a in angles], np.int32)
        cv2.fillPoly(mask, [pts], 255)
    assert classify_shape(_crop(mask), FIT, WINDOW).shape == shape


def test_square_is_a_rectangle_and_ellipse_a_circle():
    square = np.full((40, 40), 255, np.uint8)
    assert classify_shape(square, FIT, WINDOW).shape == "rectangle"
    ellipse = np.zeros((40, 60), np.uint8)  # a round sign seen at an angle
    cv2.ellipse(ellipse, (30, 20), (29, 19), 0, 0, 360, 255, -1)
    assert classify_shape(ellipse, FIT, WINDOW).shape == "circle"


def test_noisy_outline_still_fits():
    rng = np.random.default_rng(1)
    mask = _drawn("triangle").astype(np.int16)
    edge = cv2.morphologyEx(mask.astype(np.uint8), cv2.MORPH_GRADIENT, np.ones((3, 3), np.uint8)) > 0
    flip = edge & (rng.random(mask.shape) < 0.3)
    mask[flip] = 255 - mask[flip]
    assert classify_shape(_crop(mask.astype(np.uint8)), FIT, WINDOW).shape == "triangle"


def test_blob_without_sign_shape_is_rejected():
    blob = np.zeros((40, 40), np.uint8)
    cv2.fillPoly(blob, [np.array([(0, 0), (39, 0), (39, 10), (10, 10), (10, 39), (0, 39)], np.int32)], 255)  # an L
    result = classify_shape(blob, FIT, WINDOW)
    assert result.shape is None


def test_empty_mask_has_no_shape():
    assert classify_shape(np.zeros((20, 20), np.uint8), FIT, WINDOW).shape is None


def test_near_tied_outlines_keep_both_readings():
    # a small Stop with rounded corners fits a circle about as well as an octagon: both go to classification
    def result(fits):
        best = max(fits, key=fits.get)
        return ShapeResult(best, fits[best], 0.8, 0.9, 8, fits)

    assert outline_shapes(result({"circle": 0.966, "octagon": 0.950}), 0.03, FIT) == ("circle", "octagon")
    assert outline_shapes(result({"circle": 0.972, "octagon": 0.921}), 0.03, FIT) == ("circle",)
    assert outline_shapes(result({"octagon": 0.95, "circle": 0.93, "rectangle": 0.8}), 0.03, FIT) == \
        ("octagon", "circle")


@pytest.mark.parametrize("shape", ["circle", "triangle", "octagon", "rectangle"])
def test_the_shapes_tried_are_those_fitted(shape):
    # read_faces skips the fit when a rectangle is not among the shapes tried: they must be the ones fitted
    mask = _crop(_drawn(shape))
    result = classify_shape(mask, FIT, WINDOW)
    tried = shapes_tried(fill_ratio(mask), WINDOW)
    assert set(result.fits) == set(tried) and shape.split("-")[0] in tried
    assert ("rectangle" in tried) == (shape == "rectangle")
    assert shape_fits(mask, tried) == result.fits  # is_cross fits the crosses alone first, with the same values
