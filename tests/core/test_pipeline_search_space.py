import numpy as np

from signmapper_core.pipeline.config import DepthConfig
from signmapper_core.pipeline.search_range import in_search_range
from signmapper_core.pipeline.search_space import valid_depth


def test_search_space_keeps_only_depths_in_range():
    depth = np.array([[3.9, 4.0, 8.0, 14.0, 14.1, np.nan, np.inf, 0.0, -5.0]], dtype=np.float32)
    mask = in_search_range(depth, np.zeros_like(depth), DepthConfig(near_m=4.0, far_m=14.0))
    assert mask.tolist() == [[False, True, True, True, False, False, False, False, False]]


def test_valid_depth_rejects_nan_inf_and_nonpositive():
    depth = np.array([np.nan, np.inf, -1.0, 0.0, 2.5], dtype=np.float32)
    assert valid_depth(depth).tolist() == [False, False, False, False, True]
