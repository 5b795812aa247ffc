
import cv2
import numpy as np
import pytest
from pipeline_scenes import CAMERA

from signmapper_core.pipeline.config import PipelineConfig, with_settings
from signmapper_core.pipeline.depth import (
    box_windows,
    disparity_range,
    largest_disparity_px,
    match_windows,
    merge_row_bands,
    sgbm_depth,
)

CONFIG = PipelineConfig()  # the depth range 4-14 m and SGBM settings of a run


def _textured_pair(disparity, seed=0):
    """Left/right of a fronto-parallel textured plane at the given disparity (pixels)."""
    rng = np.random.default_rng(seed)
    texture = rng.integers(0, 256, (CAMERA.height // 4 + 1, (CAMERA.width + disparity) // 4 + 1)).astype(np.uint8)
    texture = cv2.resize(texture, None, fx=4, fy=4, interpolation=cv2.INTER_LINEAR)[: CAMERA.height]
    left = texture[:, : CAMERA.width]
    right = texture[:, disparity : disparity + CAMERA.width]  # right(u) shows left(u + d)
    return cv2.merge([left] * 3), cv2.merge([right] * 3)


def test_disparity_range_covers_the_search_space_in_multiples_of_16():
    fb = CAMERA.fx * CAMERA.baseline_m  # 540 px*m
    d_min, num = disparity_range(CAMERA, 4.0, 14.0)
    assert d_min <= fb / 14.0 and d_min + num >= fb / 4.0
    assert num % 16 == 0 and num <= (fb / 4.0 - fb / 14.0) + 16 + 4
    d_min_half, num_half = disparity_range(CAMERA, 4.0, 14.0, scale=0.5)
    assert d_min_half <= fb / 28.0 and d_min_half + num_half >= fb / 8.0 and num_half % 16 == 0


@pytest.mark.parametrize("scale", [1.0, 0.5])
def test_sgbm_depth_of_a_textured_plane(scale):
    z_true = 6.0
    disparity = int(round(CAMERA.fx * CAMERA.baseline_m / z_true))  # 90 px
    left, right = _textured_pair(disparity)
    depth = sgbm_depth(left, right, CAMERA, with_settings(CONFIG, {"depth": {"sgbm_scale": scale}}))
    usable = depth[20:-20, 100:-20]  # columns left of the disparity (90 px) have no match
    valid = np.isfinite(usable)
    assert valid.mean() > 0.9
    assert np.median(usable[valid]) == pytest.approx(z_true, rel=0.01)
    assert np.mean(np.abs(usable[valid] - z_true) < 0.15) > 0.95


def test_plane_beyond_the_far_limit_does_not_enter_the_search_space():
    # 30 m is beyond 14 m; the matcher searches down to 2x far (28 m) so the plane is not forced
    # onto a wrong disparity inside the 4-14 m range
    disparity = int(round(CAMERA.fx * CAMERA.baseline_m / 30.0))
    left, right = _textured_pair(disparity, seed=1)
    depth = sgbm_depth(left, right, CAMERA, CONFIG)
    usable = depth[20:-20, 20:-20]
    assert np.mean((usable >= 4.0) & (usable <= 14.0)) < 0.05


def test_columns_left_of_the_largest_disparity_are_matched():
    disparity = 90  # 6 m
    left, right = _textured_pair(disparity)
    depth = sgbm_depth(left, right, CAMERA, CONFIG)
    strip = depth[20:-20, 100:150]  # inside the disparity range width: empty without left padding
    assert np.mean(np.abs(strip - 6.0) < 0.15) > 0.9


def test_sgbm_on_row_bands_leaves_other_rows_nan():
    disparity = 90
    left, right = _textured_pair(disparity)
    depth = sgbm_depth(left, right, CAMERA, CONFIG, row_bands=[(100, 160)])
    assert np.isnan(depth[:100]).all() and np.isnan(depth[160:]).all()
    band = depth[100:160, 160:-20]
    assert np.nanmedian(band) == pytest.approx(6.0, rel=0.01)


def test_merge_row_bands():
    assert merge_row_bands([(50, 60), (10, 20), (58, 70)], 100, 5) == [(5, 25), (45, 75)]
    assert merge_row_bands([(0, 10), (95, 100)], 100, 10) == [(0, 20), (85, 100)]
    assert merge_row_bands([], 100, 5) == []


def test_match_windows_take_the_candidates_rows_and_columns():
    boxes = [(400, 100, 40, 40), (470, 110, 30, 30), (100, 300, 20, 20)]
    windows = match_windows(boxes, 640, 400, 10, 10)
    # the two boxes side by side share a band; 30 px apart, their grown spans are two windows in it
    assert windows == [(390, 90, 450, 150), (460, 90, 510, 150), (90, 290, 130, 330)]
    assert match_windows([(400, 100, 40, 40), (455, 110, 30, 30)], 640, 400, 10, 10) == [(390, 90, 495, 150)]
    assert match_windows([], 640, 400, 10, 10) == []


def test_box_windows_give_each_candidate_its_own_rows():
    tall, small = (100, 20, 60, 300), (500, 150, 30, 30)  # side by side: the band of the tall one holds the small
    (_, band_of_small) = match_windows([tall, small], 640, 400, 10, 10)
    assert band_of_small == (490, 10, 540, 330)  # the bands gave the small one the tall one's 320 rows
    assert box_windows([tall, small], 640, 400, 10) == [(90, 10, 170, 330), (490, 140, 540, 190)]
    # overlapping grown boxes are joined into their bounding box, until no two windows overlap
    joined = box_windows([(100, 100, 40, 40), (150, 120, 40, 40), (195, 65, 20, 20)], 640, 400, 10)
    assert joined == [(90, 55, 225, 170)]
    assert box_windows([(0, 390, 30, 30)], 640, 400, 10) == [(0, 380, 40, 400)]  # clipped to the image
    assert box_windows([], 640, 400, 10) == []


@pytest.mark.parametrize("x", [400, 560, 110])  # a window in the middle, at the right, near the left edge
def test_sgbm_on_windows_matches_them_like_the_whole_rows_and_leaves_the_rest_nan(x):
    disparity = 90  # 6 m
    left, right = _textured_pair(disparity)
    reach = largest_disparity_px(CAMERA, 4.0, 14.0, 0.5, 2.0)
    assert reach >= CAMERA.fx * CAMERA.baseline_m / 4.0
    (window,) = match_windows([(x, 120, 60, 40)], CAMERA.width, CAMERA.height, 10, 10)
    depth = sgbm_depth(left, right, CAMERA, CONFIG, windows=[window])
    rows = sgbm_depth(left, right, CAMERA, CONFIG, row_bands=[(110, 170)])
    kept = np.isfinite(depth)
    ys, xs = np.nonzero(kept)
    assert (ys.min(), ys.max() + 1) == (110, 170) and (xs.min(), xs.max() + 1) == (max(0, x - 10), x + 70)
    box = depth[120:160, x : x + 60]
    assert np.mean(np.abs(box - 6.0) < 0.15) > 0.95
    assert np.mean(np.abs(box - rows[120:160, x : x + 60]) < 0.05) > 0.95
