"""Faces near or past the image border: no crash anywhere, crops padded, signs near the edge still found."""

import numpy as np
import pytest
from pipeline_scenes import CAMERA, POSE, constant_depth, noisy_background, paste, pixels_for

from signmapper_core.pipeline import PipelineConfig, detect_pair
from signmapper_core.pipeline.classify import classify_segment, crop_for_matching, padded_crop

CONFIG = PipelineConfig()

H, W = CAMERA.height, CAMERA.width
SIDE = pixels_for(0.6, 8.0)  # a 0.60 m disc at 8 m
INSET = 4  # px between the face and the border: more than border_margin_px, so the segment is not cut
PLACES = {
    "top": (300, INSET), "bottom": (300, H - SIDE - INSET), "left": (INSET, 150), "right": (W - SIDE - INSET, 150),
    "top-left": (INSET, INSET), "top-right": (W - SIDE - INSET, INSET),
    "bottom-left": (INSET, H - SIDE - INSET), "bottom-right": (W - SIDE - INSET, H - SIDE - INSET),
}


@pytest.mark.parametrize("place", PLACES)
def test_sign_next_to_each_edge_and_corner_is_found_without_error(catalogue, place):
    # a red ring near the border is also read as the ring of a zone panel, whose face box then
    # reaches past the border: its classification crop used to be empty (cv2 error ending the run)
    x, y = PLACES[place]
    bgr, alpha = catalogue.render("2.30-50", SIDE)
    image = noisy_background()
    paste(image, bgr, alpha, x, y)
    found = detect_pair(image, constant_depth(8.0), None, CAMERA, POSE, catalogue, PipelineConfig())
    assert [d.template_id for d in found] == ["2.30-50"]
    fx, fy, fw, fh = found[0].bbox
    assert abs(fx - x) <= 2 and abs(fy - y) <= 2 and abs(fw - SIDE) <= 3 and abs(fh - SIDE) <= 3


BOXES = {  # (x, y, w, h) partly or wholly outside a W x H image
    "left": (-30, 150, 60, 60), "right": (W - 30, 150, 60, 60), "top": (300, -30, 60, 60),
    "bottom": (300, H - 30, 60, 60), "top-left": (-30, -30, 60, 60), "top-right": (W - 30, -30, 60, 60),
    "bottom-left": (-30, H - 30, 60, 60), "bottom-right": (W - 30, H - 30, 60, 60),
    "far outside": (-500, -500, 60, 60), "beyond bottom-right": (W + 100, H + 100, 60, 60),
    "empty box": (100, 100, 0, 0),
}


@pytest.mark.parametrize("name", BOXES)
def test_classification_of_a_box_past_the_border_pads_instead_of_failing(catalogue, name):
    bgr, alpha = catalogue.render("2.30-50", 60)
    image = noisy_background()
    x, y, w, h = BOXES[name]
    paste(image, bgr, alpha, x, y)  # clipped to the image: the visible part of the face
    region, factor, size = crop_for_matching(image, BOXES[name], (0.92, 1.0, 1.08), 0.08, 96)
    margin = int(np.ceil(0.04 * max(w, h, 1) + 0.08 * max(w, h, 1))) + 2
    assert region.shape == (max(h, 1) + 2 * margin, max(w, 1) + 2 * margin, 3)
    result = classify_segment(image, BOXES[name], catalogue, ["2.30-50", "2.30-60", "2.01", "1.01"], CONFIG)
    assert result.template_id is not None and 0.0 <= result.score <= 1.0


def test_half_visible_face_at_the_left_border_still_matches_its_template(catalogue):
    bgr, alpha = catalogue.render("2.30-50", 60)
    image = noisy_background()
    paste(image, bgr, alpha, -12, 150)  # a fifth of the face beyond the border
    result = classify_segment(image, (-12, 150, 60, 60), catalogue, ["2.30-50", "1.01", "2.01", "4.17"], CONFIG)
    assert result.template_id == "2.30-50"


def test_padded_crop_replicates_the_edge_and_keeps_inside_crops_unchanged():
    image = np.arange(5 * 6 * 3, dtype=np.uint8).reshape(5, 6, 3)
    assert np.array_equal(padded_crop(image, 1, 1, 4, 3), image[1:3, 1:4])
    out = padded_crop(image, -2, -1, 2, 2)
    assert out.shape == (3, 4, 3)
    assert np.array_equal(out[0, 0], image[0, 0]) and np.array_equal(out[2, 3], image[1, 1])
    beyond = padded_crop(image, 10, 10, 13, 12)  # wholly past the bottom-right corner: its corner pixel
    assert beyond.shape == (2, 3, 3) and (beyond == image[4, 5]).all()
