"""Depth sources: the pair's depth and its noise policy, chosen once per pair."""

import numpy as np
import pytest
from pipeline_scenes import CAMERA, POSE, constant_depth, sign_scene

from signmapper_core.pipeline import PipelineConfig, detect_pair
from signmapper_core.pipeline.config import DepthConfig
from signmapper_core.pipeline.depth_sources import GivenDepth, StereoMatching, depth_source_for
from signmapper_core.pipeline.detect import detect
from signmapper_core.pipeline.pair_context import PairContext

CONFIG = PipelineConfig()
FORWARD, RIGHT, DOWN = POSE.rotation[:, 2], POSE.rotation[:, 0], POSE.rotation[:, 1]


def test_the_source_is_the_given_depth_else_matching_of_the_right_image():
    depth, right = constant_depth(8.0), np.zeros((CAMERA.height, CAMERA.width, 3), np.uint8)
    assert isinstance(depth_source_for(depth, right), GivenDepth)
    assert isinstance(depth_source_for(None, right), StereoMatching)
    with pytest.raises(ValueError, match="no depth map and no right image"):
        depth_source_for(None, None)


def test_each_source_brings_its_own_noise_policy():
    given, matched = GivenDepth(constant_depth(8.0)), StereoMatching(np.zeros((4, 4, 3), np.uint8))
    assert given.planarity_tolerance_px(CONFIG) == CONFIG.planarity.planarity_tolerance_px
    assert matched.planarity_tolerance_px(CONFIG) == CONFIG.planarity.sgbm_planarity_tolerance_px
    search = np.zeros((200, 200), bool)
    search[50:150, 50:150] = True
    search[100, 100] = False  # a hole in a given depth's search space (a sign's uniform field)
    closed = given.search_cut(search, CONFIG)
    assert closed[100, 100] and closed.sum() == 100 * 100  # closed, not grown
    grown = matched.search_cut(search, CONFIG)
    half = CONFIG.depth.search_grow_px // 2
    assert grown[100, 100] and grown[50 - half, 100] and not grown[50 - half - 1, 100]  # SGBM loses edges: grown


def test_only_stereo_matching_asks_for_colour_candidates_first():
    assert not GivenDepth(constant_depth(8.0)).wants_candidate_boxes(CONFIG)
    matched = StereoMatching(np.zeros((4, 4, 3), np.uint8))
    assert matched.wants_candidate_boxes(CONFIG)
    assert not matched.wants_candidate_boxes(PipelineConfig(depth=DepthConfig(sgbm_rows_only=False)))


def test_stereo_matching_matches_only_around_the_candidates():
    rng = np.random.default_rng(3)
    d = int(round(CAMERA.fx * CAMERA.baseline_m / 6.0))  # one plane at 6 m
    wide = rng.integers(0, 255, (CAMERA.height, CAMERA.width + d, 3), dtype=np.uint8)
    left, right = wide[:, : CAMERA.width].copy(), wide[:, d : d + CAMERA.width].copy()
    source, roi = StereoMatching(right), (0, 0, CAMERA.width, CAMERA.height)
    assert np.isnan(source.depth_map(left, CAMERA, CONFIG, roi, [])).all()  # no candidate, no matching
    depth = source.depth_map(left, CAMERA, CONFIG, roi, [(300, 150, 40, 40)])
    rows = np.flatnonzero(np.isfinite(depth).any(axis=1))
    margin = CONFIG.depth.sgbm_row_margin_px
    assert rows.min() >= 150 - margin and rows.max() < 190 + margin
    assert np.nanmedian(depth) == pytest.approx(6.0, rel=0.02)


def test_stereo_matching_gives_a_small_candidate_beside_a_tall_one_only_its_own_rows():
    rng = np.random.default_rng(4)
    d = int(round(CAMERA.fx * CAMERA.baseline_m / 6.0))
    wide = rng.integers(0, 255, (CAMERA.height, CAMERA.width + d, 3), dtype=np.uint8)
    left, right = wide[:, : CAMERA.width].copy(), wide[:, d : d + CAMERA.width].copy()
    source, roi = StereoMatching(right), (0, 0, CAMERA.width, CAMERA.height)
    tall, small = (60, 40, 40, 300), (500, 150, 40, 40)
    margin = CONFIG.depth.sgbm_row_margin_px

    def rows_beside(config):
        depth = source.depth_map(left, CAMERA, config, roi, [tall, small])
        return np.flatnonzero(np.isfinite(depth[:, 500:540]).any(axis=1))

    rows = rows_beside(CONFIG)
    assert rows.min() == 150 - margin and rows.max() == 190 + margin - 1
    banded = rows_beside(PipelineConfig(depth=DepthConfig(sgbm_box_windows=False)))
    assert banded.min() == 40 - margin and banded.max() == 340 + margin - 1  # the tall one's band


def test_detect_pair_is_detection_with_the_pairs_depth_source(catalogue):
    sign = POSE.centre + 7.0 * FORWARD + 1.5 * RIGHT - 0.4 * DOWN
    left, depth, _ = sign_scene(catalogue, "2.30-50", "normal", sign)
    (det,) = detect(PairContext.whole(left, CAMERA, POSE, catalogue, CONFIG, GivenDepth(depth)))
    (same,) = detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG)
    assert (det.template_id, det.bbox, det.detection_indicator, det.classification_indicator) == \
        (same.template_id, same.bbox, same.detection_indicator, same.classification_indicator)
    assert det.template_id == "2.30-50" and np.array_equal(det.position, same.position)


class NoisyScan(GivenDepth):
    """Another depth method is one class: a noisy depth map (a rough scanner, a learned matcher) and its noise."""

    name = "noisy scan"

    def planarity_tolerance_px(self, config) -> float:
        return 3.0


def test_a_new_depth_method_plugs_in_with_its_own_noise_policy(catalogue):
    sign = POSE.centre + 7.0 * FORWARD + 1.5 * RIGHT - 0.4 * DOWN
    left, depth, _ = sign_scene(catalogue, "2.30-50", "normal", sign)
    fb = CAMERA.fx * CAMERA.baseline_m
    noisy = (fb / (fb / depth + np.random.default_rng(1).normal(0, 0.8, depth.shape))).astype(np.float32)
    # read as a given depth map, the 0.8 px disparity noise spoils the planarity of the face...
    assert detect(PairContext.whole(left, CAMERA, POSE, catalogue, CONFIG, GivenDepth(noisy))) == []
    # ...the source that knows its noise finds the sign
    (det,) = detect(PairContext.whole(left, CAMERA, POSE, catalogue, CONFIG, NoisyScan(noisy)))
    assert det.template_id == "2.30-50" and det.detection_indicator > 0.9
    assert np.linalg.norm(det.position - sign) < 0.1
