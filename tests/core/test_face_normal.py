"""Face normals recovered from disparity planes of known 3D planes."""

import numpy as np
import pytest

from signmapper_core.fusion.face_normal import normal_from_disparity_plane, world_face_normal
from signmapper_core.fusion.signs import azimuth_deg
from signmapper_core.geometry import Camera, Pose, world_to_pixel

CAM = Camera(1920, 1080, 1750.0, 1750.0, 959.5, 539.5, 0.9)


def disparity_plane_of(centre_cam, normal_cam, half=0.3):
    """Fit d = a + b*u + c*v to the disparities of points on a 3D plane patch."""
    normal_cam = normal_cam / np.linalg.norm(normal_cam)
    e1 = np.cross(normal_cam, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(normal_cam, e1)
    s, t = np.meshgrid(np.linspace(-half, half, 15), np.linspace(-half, half, 15))
    pts = centre_cam + s.reshape(-1, 1) * e1 + t.reshape(-1, 1) * e2
    u, v, z = CAM.camera_to_pixel(pts)
    d = CAM.fx * CAM.baseline_m / z
    coef, *_ = np.linalg.lstsq(np.column_stack([np.ones_like(u), u, v]), d, rcond=None)
    return coef


@pytest.mark.parametrize("normal", [[0.0, 0.0, -1.0], [0.5, 0.0, -1.0], [-0.3, 0.1, -1.0], [0.8, -0.2, -0.6]])
def test_normal_of_a_known_plane_is_recovered(normal):
    normal = np.array(normal) / np.linalg.norm(normal)
    plane = disparity_plane_of(np.array([2.0, -0.5, 9.0]), normal)
    np.testing.assert_allclose(normal_from_disparity_plane(CAM, plane), normal, atol=1e-6)


def test_face_azimuth_in_the_world():
    # Camera driving east; a sign beside the road at the right, turned to face the oncoming car (west).
    pose = Pose(2600000.0, 1200000.0, 402.4, 90.0, 0.0, 0.0)
    centre_world = np.array([2600010.0, 1199996.0, 402.0])
    facing = np.radians(250.0)  # the face looks towards WSW
    normal_world = np.array([np.sin(facing), np.cos(facing), 0.0])
    centre_cam = pose.world_to_camera(centre_world)
    normal_cam = pose.rotation.T @ normal_world
    u, v, z = world_to_pixel(CAM, pose, centre_world)
    assert 0 < u < CAM.width and z > 0
    plane = disparity_plane_of(centre_cam, normal_cam)
    assert azimuth_deg(world_face_normal(CAM, pose, plane)) == pytest.approx(250.0, abs=1e-4)


def test_degenerate_plane_gives_none():
    assert normal_from_disparity_plane(CAM, (0.0, 0.0, 0.0)) is None
    assert world_face_normal(CAM, Pose(0, 0, 0, 0, 0, 0), None) is None
