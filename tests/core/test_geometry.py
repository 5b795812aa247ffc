"""The rotation and projection conventions of drive-format.md, pinned."""

import numpy as np
import pytest

from signmapper_core.geometry import (
    Camera,
    Pose,
    angles_from_rotation,
    camera_rotation,
    pixel_to_world,
    world_to_pixel,
)

CAM = Camera(1920, 1080, 1750.0, 1750.0, 959.5, 539.5, 0.9)
AXIS = np.array([0.0, 0.0, 1.0])  # optical axis in the camera frame


def test_level_camera_looking_north_maps_axes_as_r0():
    r = camera_rotation(0, 0, 0)
    np.testing.assert_allclose(r @ [1, 0, 0], [1, 0, 0], atol=1e-12)  # x -> east
    np.testing.assert_allclose(r @ [0, 1, 0], [0, 0, -1], atol=1e-12)  # y (down) -> down
    np.testing.assert_allclose(r @ AXIS, [0, 1, 0], atol=1e-12)  # z -> north


@pytest.mark.parametrize(
    "heading, expected", [(90, [1, 0, 0]), (180, [0, -1, 0]), (270, [-1, 0, 0]), (45, [0.7071, 0.7071, 0])]
)
def test_heading_is_clockwise_from_north(heading, expected):
    np.testing.assert_allclose(camera_rotation(heading, 0, 0) @ AXIS, expected, atol=1e-4)


def test_positive_pitch_looks_up():
    axis = camera_rotation(90, 10, 0) @ AXIS
    assert axis[2] == pytest.approx(np.sin(np.radians(10)))
    assert axis[0] == pytest.approx(np.cos(np.radians(10)))


def test_positive_roll_is_clockwise_seen_from_behind():
    # Rolling clockwise (seen from behind) turns the camera's x axis (right) downwards.
    x_world = camera_rotation(0, 0, 10) @ [1, 0, 0]
    assert x_world[2] < 0
    assert x_world[2] == pytest.approx(-np.sin(np.radians(10)))


def test_rotation_is_orthonormal_and_angles_round_trip():
    rng = np.random.default_rng(1)
    for _ in range(50):
        h, p, r = rng.uniform(0, 360), rng.uniform(-80, 80), rng.uniform(-170, 170)
        rot = camera_rotation(h, p, r)
        np.testing.assert_allclose(rot @ rot.T, np.eye(3), atol=1e-12)
        assert np.linalg.det(rot) == pytest.approx(1.0)
        np.testing.assert_allclose(angles_from_rotation(rot), (h, p, r), atol=1e-9)


def test_principal_point_lies_on_the_optical_axis():
    pose = Pose(2600000.0, 1200000.0, 400.0, 90.0, 0.0, 0.0)
    world = pixel_to_world(CAM, pose, CAM.cx, CAM.cy, 10.0)
    np.testing.assert_allclose(world, [2600010.0, 1200000.0, 400.0], atol=1e-9)


def test_pixel_below_centre_is_lower_in_the_world():
    pose = Pose(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    world = pixel_to_world(CAM, pose, CAM.cx, CAM.cy + 175.0, 10.0)
    np.testing.assert_allclose(world, [0.0, 10.0, -1.0], atol=1e-12)


def test_world_point_projects_back_to_its_pixel():
    rng = np.random.default_rng(2)
    pose = Pose(2615000.0, 1264000.0, 290.0, 37.0, 2.5, -1.2)
    u, v = rng.uniform(0, 1919, 100), rng.uniform(0, 1079, 100)
    z = rng.uniform(4, 14, 100)
    world = pixel_to_world(CAM, pose, u, v, z)
    u2, v2, z2 = world_to_pixel(CAM, pose, world)
    np.testing.assert_allclose(u2, u, atol=1e-6)
    np.testing.assert_allclose(v2, v, atol=1e-6)
    np.testing.assert_allclose(z2, z, atol=1e-9)


def test_disparity_and_depth_are_inverse():
    assert CAM.disparity_from_depth(10.0) == pytest.approx(157.5)
    assert CAM.depth_from_disparity(157.5) == pytest.approx(10.0)
    assert np.isnan(CAM.depth_from_disparity(0.0))
