import cv2
import numpy as np
from pipeline_scenes import BLUE, RED, WHITE, noisy_background

from signmapper_core.pipeline.colour import colour_masks, segments_from_mask
from signmapper_core.pipeline.config import DEFAULT_HSV_RANGES


def _segments(image, colour, search=None):
    masks = colour_masks(image, DEFAULT_HSV_RANGES, [colour], search)
    return segments_from_mask(masks[colour], colour)


def test_red_ring_is_one_filled_segment_with_its_outer_box():
    image = noisy_background()
    cv2.circle(image, (200, 150), 30, RED, -1)
    cv2.circle(image, (200, 150), 24, WHITE, -1)  # red ring around white, as on a prohibition sign
    segs = _segments(image, "red")
    assert len(segs) == 1
    seg = segs[0]
    x, y, w, h = seg.bbox
    assert abs(x - 170) <= 1 and abs(y - 120) <= 1 and abs(w - 61) <= 2 and abs(h - 61) <= 2
    assert seg.mask[h // 2, w // 2] == 255  # the white field is filled
    assert abs(seg.area_px - np.pi * 30.5**2) / (np.pi * 30.5**2) < 0.05
    assert not seg.touches_border


def test_both_ends_of_the_red_hue_circle_are_red():
    image = noisy_background()
    cv2.rectangle(image, (50, 50), (90, 90), (40, 20, 210), -1)  # hue ~ 3
    cv2.rectangle(image, (200, 50), (240, 90), (90, 20, 210), -1)  # hue ~ 170
    assert len(_segments(image, "red")) == 2


def test_blue_and_red_are_separate_and_grey_background_is_nothing():
    image = noisy_background()
    cv2.rectangle(image, (300, 100), (360, 160), BLUE, -1)
    masks = colour_masks(image, DEFAULT_HSV_RANGES, ["red", "blue", "yellow"])
    assert len(segments_from_mask(masks["blue"], "blue")) == 1
    assert not masks["red"].any() and not masks["yellow"].any()


def test_search_space_removes_colour_outside_the_depth_range():
    image = noisy_background()
    cv2.circle(image, (200, 150), 30, RED, -1)
    search = np.zeros(image.shape[:2], bool)
    assert _segments(image, "red", search) == []


def test_segment_cut_by_the_image_border_is_flagged():
    image = noisy_background()
    cv2.circle(image, (10, 150), 30, RED, -1)
    (seg,) = _segments(image, "red")
    assert seg.touches_border


def test_speckle_and_tiny_segments_are_dropped():
    image = noisy_background()
    rng = np.random.default_rng(3)
    ys, xs = rng.integers(0, 400, 300), rng.integers(0, 640, 300)
    image[ys, xs] = RED  # isolated red pixels
    cv2.rectangle(image, (100, 100), (105, 105), RED, -1)  # 6x6 px: too small to be a sign
    assert _segments(image, "red") == []
