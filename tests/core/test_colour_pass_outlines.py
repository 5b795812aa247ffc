"""Which outline a colour pass keeps for a face: small blurred faces and rings only the scene pass sees whole.

Both cases were misses of the colour step on GTSDB's tune split (priority-road diamonds of 30 px read
as octagons, speed-limit rings the strong pass kept only a third of).
"""

import cv2
import numpy as np
from pipeline_scenes import WHITE, noisy_background

from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.boxes import box_iou
from signmapper_core.pipeline.colour import Segment, find_colour_segments
from signmapper_core.pipeline.config import with_settings
from signmapper_core.pipeline.detect import segment_outline
from signmapper_core.pipeline.shape import ambiguity_margin, classify_shape

DEFAULT = PipelineConfig()
NO_BLUR_MARGIN = with_settings(DEFAULT, {"shape": {"shape_ambiguity_px": 0.0}})
STRONG_ONLY = with_settings(DEFAULT, {"scene": {"weak_colour": False}})
NO_FIELDS = with_settings(DEFAULT, {"bright_fields": {"field_pass": False}})
STRONG_NO_FIELDS = with_settings(STRONG_ONLY, {"bright_fields": {"field_pass": False}})


def _bgr(h, s, v):
    return cv2.cvtColor(np.uint8([[[h, s, v]]]), cv2.COLOR_HSV2BGR)[0, 0].tolist()


def _diamond(image, x, y, n, colour):
    c = n // 2
    cv2.fillPoly(image, [np.array([[x + c, y], [x + n, y + c], [x + c, y + n], [x, y + c]])], colour)


def _cornered_diamond():
    """A 19 px diamond whose tips are cut off, as blur cuts a small one's: an octagon fits it best (0.81),
    the diamond 0.05 less (0.76)."""
    mask = np.zeros((23, 23), np.uint8)
    _diamond(mask, 0, 0, 22, 255)
    return mask[2:21, 2:21].copy()


def _small_dim_priority_sign(x=200, y=150):
    """A 39 px priority road at dusk: dark edge, grey-white rim and a dim orange-yellow cornered diamond."""
    image = noisy_background(level=45, sigma=5)
    _diamond(image, x, y, 38, (25, 25, 25))
    _diamond(image, x + 2, y + 2, 34, (150, 150, 150))
    part = _cornered_diamond()
    window = image[y + 10:y + 29, x + 10:x + 29]
    window[part > 0] = _bgr(14, 170, 80)
    return image


def _yellow_near(segments, box):
    return [s for s in segments if s.colour == "yellow" and box_iou(s.bbox, box) > 0.5]


def test_ambiguity_margin_grows_as_the_segment_shrinks():
    assert ambiguity_margin(0.04, 1.2, 15, 20, 0.5) == 0.04 + 1.2 / 15
    assert ambiguity_margin(0.04, 1.2, 120, 120, 0.5) == 0.04 + 0.01
    assert ambiguity_margin(0.04, 0.0, 15, 15, 0.5) == 0.04


def test_a_bar_or_plate_gets_no_extra_margin():
    # a licence plate in a red car's back (83 x 20 px) read as a disc's field made it a no-entry sign
    assert ambiguity_margin(0.04, 1.2, 83, 20, 0.5) == 0.04
    assert ambiguity_margin(0.04, 1.2, 40, 20, 0.5) == 0.04 + 1.2 / 20


def test_small_diamond_cut_by_blur_keeps_the_diamond_among_its_outlines():
    mask = _cornered_diamond()
    seg = Segment("yellow", (100, 100, 19, 19), mask, np.zeros((0, 1, 2), np.int32), int(np.count_nonzero(mask)),
                  False)
    fits = classify_shape(seg.mask, 0.68, 0.2).fits
    assert fits["octagon"] > fits["diamond"]  # blur rounds its corners: the octagon fits best
    shapes, _ = segment_outline(seg, DEFAULT)
    assert "diamond" in shapes
    strict, _ = segment_outline(seg, NO_BLUR_MARGIN)
    assert "diamond" not in strict


def test_scene_pass_keeps_a_small_diamond_whose_best_outline_is_an_octagon():
    image = _small_dim_priority_sign()
    assert _yellow_near(find_colour_segments(image, None, STRONG_ONLY, None),
                        (210, 160, 19, 19)) == []  # too dim for the strong pass
    assert _yellow_near(find_colour_segments(image, None, NO_BLUR_MARGIN, None),
                        (210, 160, 19, 19)) == []  # read as an octagon only: no priority road
    assert len(_yellow_near(find_colour_segments(image, None, DEFAULT, None), (210, 160, 19, 19))) == 1


def _ring_fading_downwards(diameter=34, ring_px=3, centre=(200, 150)):
    """A red ring whose lowest third is too pale for the strong pass (saturation 60 < 90)."""
    image = noisy_background(level=70, sigma=6)
    r = diameter // 2
    cv2.circle(image, centre, r, _bgr(176, 60, 150), -1)
    upper = np.zeros(image.shape[:2], np.uint8)
    cv2.circle(upper, centre, r, 255, -1)
    upper[centre[1] + r // 3:] = 0
    image[upper > 0] = _bgr(176, 200, 170)
    cv2.circle(image, centre, r - ring_px, WHITE, -1)
    return image, (centre[0] - r, centre[1] - r, diameter + 1, diameter + 1)


def test_ring_kept_whole_by_the_scene_pass_is_not_dropped_as_a_duplicate_of_its_strong_part():
    image, disc = _ring_fading_downwards()
    config = NO_FIELDS
    (part,) = [s for s in find_colour_segments(image, None, STRONG_NO_FIELDS, None)
               if s.colour == "red"]
    # the same place, but only part of the ring
    assert config.scene.pass_duplicate_iou <= box_iou(part.bbox, disc) < 0.8
    found = [s for s in find_colour_segments(image, None, config, None) if s.colour == "red"]
    (whole,) = [s for s in found if box_iou(s.bbox, disc) > 0.9]
    assert segment_outline(whole, config)[0][0] == "circle"
    assert part.bbox in [s.bbox for s in found]  # the part stays: split faces are merged from such pieces


def test_a_later_pass_with_the_same_outline_is_still_a_duplicate():
    image = noisy_background(level=70, sigma=6)
    cv2.circle(image, (200, 150), 30, _bgr(176, 200, 170), -1)
    cv2.circle(image, (200, 150), 24, WHITE, -1)
    red = [s for s in find_colour_segments(image, None, NO_FIELDS, None) if s.colour == "red"]
    assert len(red) == 1 and isinstance(red[0], Segment)


def test_a_dark_blue_disc_is_found_by_the_scene_pass_only_when_blue_is_asked_for_and_only_as_a_sharp_disc():
    # a dark blue disc at dusk (V 36): below the strong blue's value floor, within the scene pass's
    image = np.clip(np.random.default_rng(3).normal(70, 4, (200, 300, 3)), 0, 255).astype(np.uint8)
    cv2.circle(image, (150, 100), 22, (36, 14, 9), -1, cv2.LINE_AA)
    cv2.arrowedLine(image, (140, 90), (160, 110), (70, 70, 70), 4)
    image = cv2.GaussianBlur(image, (3, 3), 0)
    assert find_colour_segments(image, None, PipelineConfig(), None) == []  # blue is no scene colour by default
    with_blue = with_settings(PipelineConfig(), {"scene": {"weak_colours": ("red", "yellow", "blue")}})
    (disc,) = find_colour_segments(image, None, with_blue, None)
    assert disc.colour == "blue" and box_iou(disc.bbox, (128, 78, 45, 45)) > 0.9
    ragged_only = with_settings(with_blue, {"scene": {"weak_min_fit": {"blue": 0.99}}})
    assert find_colour_segments(image, None, ragged_only, None) == []
