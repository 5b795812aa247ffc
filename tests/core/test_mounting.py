"""Mounting height from the trajectory and the camera's height above the road."""

import numpy as np
import pytest

from signmapper_core.fusion.mounting import camera_height_above_road, mounting_height

CENTRES = np.array([[0.0, 0.0, 402.4], [2.0, 0.0, 402.5], [4.0, 0.0, 402.6]])  # climbing road, camera 2.4 m up


def test_lower_edge_above_the_road_beside_the_sign():
    sign = np.array([4.2, 3.0, 402.5])  # 0.60 m disc centred 2.3 m above the road at x = 4
    assert mounting_height(sign, 0.6, CENTRES, 2.4) == pytest.approx(2.0)


def test_unknown_camera_height_gives_none():
    assert mounting_height(np.array([4.2, 3.0, 402.5]), 0.6, CENTRES, None) is None


@pytest.mark.parametrize("metadata, expected", [
    ({"vehicle": {"camera_height_m": 2.4}}, 2.4),
    ({"vehicle": {"camera_height_m": "2.4"}}, None),
    ({"vehicle": {"camera_height_m": -1}}, None),
    ({"vehicle": "van"}, None),
    ({}, None),
])
def test_camera_height_from_drive_metadata(metadata, expected):
    assert camera_height_above_road(metadata) == expected
