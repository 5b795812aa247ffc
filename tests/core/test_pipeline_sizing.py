import cv2
import numpy as np
import pytest
from pipeline_scenes import CAMERA, pixels_for

from signmapper_core.pipeline.sizing import measure_segment, metric_size, segment_depth


def test_metric_size_of_a_60cm_disc_at_8m():
    d = pixels_for(0.60, 8.0)  # 45 px
    width_m, height_m = metric_size(CAMERA, (0, 0, d, d), 8.0)
    assert width_m == pytest.approx(0.60, abs=0.01) and height_m == pytest.approx(0.60, abs=0.01)


def test_median_depth_ignores_nan_and_out_of_range_pixels():
    depth = np.full((50, 50), 8.0, np.float32)
    depth[:10] = np.nan  # unmatched
    depth[10:15] = 40.0  # background seen through the filled outline
    mask = np.full((50, 50), 255, np.uint8)
    z, coverage = segment_depth(depth, (0, 0, 50, 50), mask, 4.0, 14.0)
    assert z == pytest.approx(8.0)
    assert coverage == pytest.approx(0.7)


def test_segment_without_depth_cannot_be_measured():
    depth = np.full((50, 50), np.nan, np.float32)
    mask = np.zeros((50, 50), np.uint8)
    cv2.circle(mask, (25, 25), 20, 255, -1)
    assert measure_segment(CAMERA, depth, (0, 0, 50, 50), mask, 4.0, 14.0) is None
    empty = np.zeros((50, 50), np.uint8)
    assert measure_segment(CAMERA, np.full((50, 50), 8.0, np.float32), (0, 0, 50, 50), empty, 4.0, 14.0) is None


def test_measure_segment_uses_pixels_of_the_segment_box():
    depth = np.full((400, 640), 20.0, np.float32)
    depth[100:160, 200:260] = 6.0
    mask = np.full((60, 60), 255, np.uint8)
    size = measure_segment(CAMERA, depth, (200, 100, 60, 60), mask, 4.0, 14.0)
    assert size.depth_m == pytest.approx(6.0)
    assert size.width_m == pytest.approx(0.60) and size.height_m == pytest.approx(0.60)
