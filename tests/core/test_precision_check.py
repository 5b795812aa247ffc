"""scripts/precision_check: the error along and across a sign's line of sight in units of the σ it reports."""

from __future__ import annotations

import numpy as np
import pytest

from scripts.precision_check import error_ratios, mean_sight, merged_features


def test_error_ratios_split_the_error_along_and_across_the_line_of_sight():
    sight = np.array([0.0, 1.0, 0.0])
    # 0.4 m short along the line of sight, 0.3 m across it: 0.3 / √2 per axis of the plane across
    along, across = error_ratios([0.3, -0.4, 0.0], sight, sigma_along=0.2, sigma_across=0.15)
    assert along == pytest.approx(-2.0)
    assert across == pytest.approx(0.3 / np.sqrt(2) / 0.15)


def test_mean_sight_is_the_mean_of_the_views_unit_rays():
    cameras = [[-10.0, 0.0, 0.0], [0.0, -5.0, 0.0]]  # one 10 m west, one 5 m south of the sign
    sight = mean_sight([0.0, 0.0, 0.0], cameras)
    assert sight == pytest.approx(np.array([1.0, 1.0, 0.0]) / np.sqrt(2))


def test_merged_counts_a_feature_whose_views_saw_two_signs_one_of_them_left_without_one():
    reference = np.array([[0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [10.0, 0.0, 2.0]])
    merged = [[0.05, 0.0, 2.0], [0.95, 0.0, 2.0]]  # views of signs 0 and 1 fused into one feature, matched to 0
    alone = [[10.0, 0.1, 2.0], [10.1, 0.0, 2.0]]
    assert merged_features([merged, alone], reference, np.array([0, 2]), 0.75) == 1
    # both signs with a feature of their own: the stray view is no merge
    assert merged_features([merged, alone, [[1.0, 0.0, 2.0]]], reference, np.array([0, 2, 1]), 0.75) == 0
