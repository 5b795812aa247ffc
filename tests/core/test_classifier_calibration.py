"""The model card's acceptance threshold, as training and the calibration on real photographs both fit it."""

import numpy as np

from signmapper_core.pipeline.classifiers.calibration import acceptance_threshold


def test_threshold_is_the_lowest_probability_with_few_enough_wrong_above_it():
    best = np.array([0.6, 0.95, 0.8, 0.9, 0.7])
    right = np.array([False, True, False, True, True])
    # surest first: 0.95 ok, 0.9 ok, 0.8 wrong (1 of 3), 0.7 ok (1 of 4), 0.6 wrong (2 of 5)
    assert acceptance_threshold(best, right, 0.3) == 0.7
    assert acceptance_threshold(best, right, 0.0) == 0.9
    assert acceptance_threshold(best, right, 0.4) == 0.6


def test_threshold_stays_within_half_and_0_99():
    assert acceptance_threshold(np.array([0.3, 0.2]), np.array([True, True]), 0.01) == 0.5
    assert acceptance_threshold(np.array([0.999, 0.8]), np.array([False, True]), 0.01) == 0.99
