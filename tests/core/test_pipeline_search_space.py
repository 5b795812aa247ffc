import numpy as np

from signmapper_core.pipeline.search_space import search_space_mask, valid_depth


def test_search_space_keeps_only_depths_in_range():
    depth = np.array([[3.9, 4.0, 8.0, 14.0, 14.1, np.nan, np.inf, 0.0, -5.0]], dtype=np.float32)
    mask = search_space_mask(depth, 4.0, 14.0)
    assert mask.tolist() == [[False, True, True, True, False, False, False, False, False]]


def test_valid_depth_rejects_nan_inf_and_nonpositive():
    depth = np.array([np.nan, np.inf, -1.0, 0.0, 2.5], dtype=np.float32)
    assert valid_depth(depth).tolist() == [False, False, False, False, True]
