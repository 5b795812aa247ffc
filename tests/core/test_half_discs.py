"""Round faces of which only one half kept its colour: the disc read from the half."""

import cv2
import numpy as np
import pytest
from pipeline_scenes import CAMERA, POSE, RED, constant_depth, noisy_background, paste

from signmapper_core.pipeline import PipelineConfig, detect_pair
from signmapper_core.pipeline.boxes import box_iou
from signmapper_core.pipeline.candidates import colour_step
from signmapper_core.pipeline.colour import find_colour_segments
from signmapper_core.pipeline.half_discs import half_disc_mask, half_disc_side, with_half_discs

CATALOGUE = "reference drawing"  # scenes and templates of our reference drawing (tests/conftest.py)
N = 60
FACE = (300, 150, N, N)


def _no_entry_half_in_shade(catalogue, shaded_half: str):
    """A no-entry sign whose lower (or upper) half lies in deep shade: its red there is a dark grey."""
    bgr, alpha = catalogue.render("2.02", N)
    bgr = bgr.copy()
    rows = slice(N // 2, N) if shaded_half == "lower" else slice(0, N // 2)
    bgr[rows] = (cv2.cvtColor(cv2.cvtColor(bgr[rows], cv2.COLOR_BGR2GRAY), cv2.COLOR_GRAY2BGR) * 0.35).astype(np.uint8)
    image = noisy_background()
    paste(image, bgr, alpha, FACE[0], FACE[1])
    return image


def test_half_disc_masks_are_the_halves_of_the_disc_in_their_box():
    upper, lower = half_disc_mask(40, 20, True), half_disc_mask(40, 20, False)
    assert upper[19, 20] == 255 and upper[0, 1] == 0 and upper[19, 0] == 255  # flat side down
    assert lower[0, 20] == 255 and lower[19, 1] == 0 and lower[0, 0] == 255  # flat side up
    assert abs(np.count_nonzero(upper) - np.pi * 20 * 20 / 2) < 0.05 * np.pi * 20 * 20 / 2


@pytest.mark.parametrize("shaded_half", ["lower", "upper"])
def test_no_entry_with_one_half_in_shade_is_read_whole(catalogue, shaded_half):
    image = _no_entry_half_in_shade(catalogue, shaded_half)
    (half,) = [s for s in find_colour_segments(image, None, PipelineConfig(), None) if s.colour == "red"]
    assert half.bbox[3] < 0.6 * N
    assert half_disc_side(half, PipelineConfig()) is (shaded_half == "lower")
    segments, candidates = colour_step(image, catalogue, hough=False)
    (disc,) = [s for s in segments if s.source == "half"]
    assert box_iou(disc.bbox, FACE) > 0.85
    # depth and planarity are read where the colour is, not on the shaded half
    surface = np.count_nonzero(disc.surface_mask)
    assert 0.9 * np.count_nonzero(half.mask) < surface <= np.count_nonzero(half.mask)
    assert any("2.02" in r.template_ids and box_iou(r.bbox, FACE) > 0.85
               for c in candidates if c.segment.source == "half" for r in c.readings)
    (det,) = detect_pair(image, constant_depth(0.6 * CAMERA.fx / N), None, CAMERA, POSE, catalogue, PipelineConfig())
    assert det.template_id == "2.02" and det.source == "half" and det.format == "normal"
    assert box_iou(det.bbox, FACE) > 0.85


def test_a_red_bar_or_a_whole_disc_gives_no_half_disc():
    image = noisy_background()
    cv2.rectangle(image, (100, 100), (159, 129), RED, -1)  # 60 x 30: a half disc's box, not its outline
    cv2.circle(image, (400, 200), 30, RED, -1)
    segments = find_colour_segments(image, None, PipelineConfig(), None)
    assert len(segments) == 2
    assert [half_disc_side(s, PipelineConfig()) for s in segments] == [None, None]
    assert with_half_discs(segments, (image.shape[1], image.shape[0]), PipelineConfig()) == segments


def test_a_half_whose_disc_is_outlined_already_adds_nothing(catalogue):
    image = noisy_background()
    cv2.circle(image, (400, 200), 30, RED, -1)
    cv2.rectangle(image, (365, 200), (435, 240), (90, 90, 90), -1)  # the lower half in shade...
    (half,) = find_colour_segments(image, None, PipelineConfig(), None)
    whole = find_colour_segments(noisy_background(), None, PipelineConfig(), None)
    assert whole == [] and half_disc_side(half, PipelineConfig()) is True
    disc_image = noisy_background()
    cv2.circle(disc_image, (400, 200), 30, RED, -1)
    (disc,) = find_colour_segments(disc_image, None, PipelineConfig(), None)
    # ...but a segment of the whole disc (another pass) stands for it
    assert len(with_half_discs([half, disc], (640, 400), PipelineConfig())) == 2
    assert len(with_half_discs([half], (640, 400), PipelineConfig())) == 2


def test_a_disc_the_depth_range_halved_is_not_read_whole(catalogue):
    # the same red half, but the face's lower half lies beyond the search space (a different depth): that half
    # lost its depth, not its colour
    image = _no_entry_half_in_shade(catalogue, "lower")
    z = 0.6 * CAMERA.fx / N
    depth = constant_depth(z)
    depth[FACE[1] + N // 2 - 2 :, :] = 30.0  # beyond the 14 m far end
    assert [d for d in detect_pair(image, depth, None, CAMERA, POSE, catalogue, PipelineConfig())
            if d.source == "half"] == []
    search = np.ones(image.shape[:2], bool)
    (half,) = [s for s in find_colour_segments(image, None, PipelineConfig(), None) if s.colour == "red"]
    assert len(with_half_discs([half], (640, 400), PipelineConfig(), search)) == 2
    search[FACE[1] + N // 2 - 2 :, :] = False
    assert with_half_discs([half], (640, 400), PipelineConfig(), search) == [half]
