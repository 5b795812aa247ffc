import cv2
import numpy as np
from pipeline_scenes import CAMERA, noisy_background, pixels_for

from signmapper_core.pipeline.config import DepthConfig, PipelineConfig, with_settings
from signmapper_core.pipeline.hough import (
    circle_segment,
    find_circles,
    hough_segments,
    radius_range_px,
    ring_colour_share,
    ringed_field,
    weak_colour,
)
from signmapper_core.pipeline.search_range import in_search_range

CONFIG = PipelineConfig()
SLACK = CONFIG.hough.hough_radius_slack


def _scene(ring_bgr, field_bgr, u=300, v=180, z=7.0):
    image = noisy_background(level=150, sigma=6)
    r = pixels_for(0.60, z) // 2
    cv2.circle(image, (u, v), r, ring_bgr, -1)
    cv2.circle(image, (u, v), int(r * 0.8), field_bgr, -1)
    depth = np.full(image.shape[:2], 30.0, np.float32)  # far background
    disc = np.zeros(image.shape[:2], np.uint8)
    cv2.circle(disc, (u, v), r, 255, -1)
    depth[disc > 0] = z
    return image, depth, r


def test_radius_range_covers_round_formats_in_the_search_space():
    lo, hi = radius_range_px(CAMERA.fx, 4.0, 14.0, [0.4, 0.6], SLACK)
    assert lo <= 0.4 * CAMERA.fx / 28.0 and hi >= 0.6 * CAMERA.fx / 8.0


def test_faded_red_ring_is_found_and_named_red():
    faded_red = (120, 115, 165)  # saturation ~ 80: below the red threshold of the colour step
    image, depth, r = _scene(faded_red, (200, 200, 200))
    search = in_search_range(depth, np.zeros_like(depth), DepthConfig())
    circles = find_circles(image, search, *radius_range_px(CAMERA.fx, 4.0, 14.0, [0.4, 0.6], SLACK), 0.5, CONFIG)
    segs = hough_segments(image, circles, CONFIG)
    assert len(segs) >= 1
    best = min(segs, key=lambda s: abs(s.bbox[0] + s.bbox[2] / 2 - 300) + abs(s.bbox[1] + s.bbox[3] / 2 - 180))
    x, y, w, h = best.bbox
    assert abs(x + w / 2 - 300) < 4 and abs(y + h / 2 - 180) < 4 and abs(w - 2 * r) < 6
    assert best.colour == "red" and best.source == "hough"


def test_white_round_sign_is_found_from_the_depth_edge():
    image, depth, r = _scene((160, 160, 160), (160, 160, 160))  # same grey as the background
    search = in_search_range(depth, np.zeros_like(depth), DepthConfig())
    circles = find_circles(image, search, *radius_range_px(CAMERA.fx, 4.0, 14.0, [0.4, 0.6], SLACK), 0.5, CONFIG)
    assert any(abs(u - 300) < 4 and abs(v - 180) < 4 and abs(rr - r) < 4 for u, v, rr in circles)


def test_nothing_in_the_search_space_means_no_circles():
    image, depth, _ = _scene((120, 115, 165), (200, 200, 200), z=20.0)
    search = in_search_range(depth, np.zeros_like(depth), DepthConfig())
    assert hough_segments(image, find_circles(image, search, 10, 60, 0.5, CONFIG), CONFIG) == []


def test_weak_colour_of_grey_ring_is_white():
    patch = np.full((41, 41, 3), 180, np.uint8)
    mask = np.zeros((41, 41), np.uint8)
    cv2.circle(mask, (20, 20), 20, 255, -1)
    assert weak_colour(patch, mask, CONFIG) == "white"


def test_the_ring_read_for_a_circles_colour_is_its_outer_share():
    """A thin red ring (5 % of the diameter deep) around a white field: read to 10 % of the diameter it is
    red; read to 40 %, the field outweighs it and the circle is white."""
    size = 101
    crop = np.full((size, size, 3), 235, np.uint8)
    cv2.circle(crop, (50, 50), 50, (40, 40, 200), -1)
    cv2.circle(crop, (50, 50), 45, (235, 235, 235), -1)
    mask = np.zeros((size, size), np.uint8)
    cv2.circle(mask, (50, 50), 50, 255, -1)
    red = CONFIG.colour.hsv_ranges["red"]
    deeper = with_settings(CONFIG, {"hough": {"hough_ring_share": 0.4}})
    assert weak_colour(crop, mask, CONFIG) == "red" and ring_colour_share(crop, mask, red, CONFIG) > 0.4
    assert weak_colour(crop, mask, deeper) == "white" and ring_colour_share(crop, mask, red, deeper) < 0.25


def _field_in_ring(u, ring_bgr, width=400):
    """A white field (r 40) in a ring (r 52) centred at (u, 100) on grey, and the white Hough circle of the field."""
    image = np.full((200, width, 3), 150, np.uint8)
    cv2.circle(image, (u, 100), 52, ring_bgr, -1)
    cv2.circle(image, (u, 100), 40, (235, 235, 235), -1)
    seg = circle_segment(image, u, 100, 40, CONFIG)
    assert seg is not None and seg.colour == "white"
    return image, seg


def test_a_white_circle_in_a_red_ring_is_the_rings_field():
    image, seg = _field_in_ring(200, (40, 40, 200))
    field = ringed_field(image, seg, CONFIG)
    assert field is not None and field.colour == "red" and field.source == "hole" and field.bbox == seg.bbox


def test_a_red_ring_cut_by_the_image_border_still_names_its_field():
    image, seg = _field_in_ring(350, (40, 40, 200), width=395)  # the ring reaches 7 px past the right border
    assert ringed_field(image, seg, CONFIG).colour == "red"


def test_a_white_circle_on_grey_or_in_a_blue_ring_stays_white():
    for ring in ((150, 150, 150), (200, 90, 20)):
        image, seg = _field_in_ring(200, ring)
        assert ringed_field(image, seg, CONFIG) is None


def test_a_ring_mostly_outside_the_image_is_not_read():
    """Where less than half of the band around the circle is in the image, what lies there says too little."""
    image = np.full((200, 400, 3), 150, np.uint8)
    cv2.circle(image, (200, 100), 52, (40, 40, 200), -1)
    cv2.circle(image, (200, 100), 40, (235, 235, 235), -1)
    crop = np.ascontiguousarray(image[60:141, 160:241])  # the field's box alone: a third of the band is in it
    seg = circle_segment(crop, 40, 40, 40, CONFIG)
    assert seg is not None and ringed_field(crop, seg, CONFIG) is None
