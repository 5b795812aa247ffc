import dataclasses

import cv2
import numpy as np
from pipeline_scenes import BLUE, RED, WHITE, noisy_background

from signmapper_core.pipeline.colour import colour_masks, segments_from_mask
from signmapper_core.pipeline.config import ColourConfig

COLOUR = ColourConfig()


def _segments(image, colour, search=None):
    masks = colour_masks(image, COLOUR, [colour], search)
    return segments_from_mask(masks[colour], colour, COLOUR.min_segment_px, COLOUR)


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
    masks = colour_masks(image, COLOUR, ["red", "blue", "yellow"])
    assert len(segments_from_mask(masks["blue"], "blue", COLOUR.min_segment_px, COLOUR)) == 1
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


def test_a_face_bitten_into_is_filled_to_its_hull_below_the_solidity_setting():
    mask = np.zeros((120, 120), np.uint8)
    cv2.circle(mask, (60, 60), 40, 255, -1)
    cv2.rectangle(mask, (55, 15), (105, 65), 0, -1)  # a quarter bitten out by an occluder: solidity 0.75
    (hull,) = segments_from_mask(mask, "blue", COLOUR.min_segment_px, COLOUR)
    (bitten,) = segments_from_mask(mask, "blue", COLOUR.min_segment_px, dataclasses.replace(COLOUR, min_solidity=0.7))
    assert hull.solidity == bitten.solidity < COLOUR.min_solidity
    assert bitten.area_px == np.count_nonzero(mask) and hull.area_px > 1.1 * bitten.area_px


def test_a_field_is_its_own_segment_where_the_outline_around_it_is_more_than_a_ring():
    mask = np.zeros((160, 220), np.uint8)
    cv2.circle(mask, (60, 80), 40, 255, -1)
    cv2.circle(mask, (60, 80), 32, 0, -1)  # a ring: outline 1.25 x its field
    ring_only = segments_from_mask(mask, "red", COLOUR.min_segment_px, COLOUR, holes=True)
    assert [s.source for s in ring_only] == ["colour"]
    cv2.rectangle(mask, (95, 70), (200, 90), 255, -1)  # a red roof touching it: the outline is no longer a ring
    sources = sorted(s.source for s in segments_from_mask(mask, "red", COLOUR.min_segment_px, COLOUR, holes=True))
    assert sources == ["colour", "hole"]
    wide = dataclasses.replace(COLOUR, max_ring_ratio=3.5)
    assert [s.source for s in segments_from_mask(mask, "red", COLOUR.min_segment_px, wide, holes=True)] == ["colour"]
