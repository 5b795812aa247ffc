import numpy as np
import pytest
from pipeline_scenes import CAMERA, POSE

from signmapper_core.geometry import Pose, world_to_pixel
from signmapper_core.pipeline.locate import bbox_centre, locate


@pytest.mark.parametrize("pose", [POSE, Pose(2600010.0, 1200020.0, 401.5, 33.0, 2.0, -1.0)])
def test_locate_recovers_a_known_sign_centre(pose):
    # a sign 8 m ahead, 2.5 m right of and 1 m above the camera
    forward = pose.rotation[:, 2]
    right = pose.rotation[:, 0]
    down = pose.rotation[:, 1]
    sign = pose.centre + 8.0 * forward + 2.5 * right - 1.0 * down
    u, v, z = world_to_pixel(CAMERA, pose, sign)
    assert z == pytest.approx(8.0)
    assert np.allclose(locate(CAMERA, pose, float(u), float(v), float(z)), sign, atol=1e-9)
    # heading 90: the optical axis points east
    if pose is POSE:
        assert sign[0] == pytest.approx(POSE.easting + 8.0) and sign[2] == pytest.approx(POSE.height + 1.0)


def test_bbox_centre_uses_pixel_centre_coordinates():
    assert bbox_centre((10, 20, 5, 7)) == (12.0, 23.0)
    assert bbox_centre((0, 0, 2, 2)) == (0.5, 0.5)
