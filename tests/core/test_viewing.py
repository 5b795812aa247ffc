"""Drive viewer geometry: a sign's box in a pair, the view cone, the pair that sees a place best."""

import numpy as np
import pytest
from drive_fixtures import straight_poses

from signmapper_core.drive.reader import PairRecord
from signmapper_core.drive.viewing import best_pair_for, nearest_pair, project_sign, view_cone
from signmapper_core.geometry import Camera, pixel_to_world, world_to_pixel

CAMERA = Camera(width=1920, height=1080, fx=1750.0, fy=1750.0, cx=959.5, cy=539.5, baseline_m=0.9)


def records(n=20):
    return [PairRecord(i, pid, t, pose, None, None, None) for i, (pid, t, pose) in enumerate(straight_poses(n))]


def test_a_sign_projects_to_its_pixel_with_its_metric_size():
    pose = records()[0].pose  # heading 90: looking east
    position = pixel_to_world(CAMERA, pose, 1400.0, 300.0, 10.0)
    box = project_sign(CAMERA, pose, position, 0.6, 0.6)
    assert (box.u, box.v, box.depth_m) == pytest.approx((1400.0, 300.0, 10.0), abs=1e-6)
    assert box.bbox == pytest.approx((1400.0 - 52.5, 300.0 - 52.5, 105.0, 105.0))
    behind = pixel_to_world(CAMERA, pose, 900.0, 500.0, 10.0) - 20.0 * np.array([1.0, 0.0, 0.0])
    assert project_sign(CAMERA, pose, behind, 0.6, 0.6) is None
    far_left = pixel_to_world(CAMERA, pose, -300.0, 500.0, 10.0)
    assert project_sign(CAMERA, pose, far_left, 0.6, 0.6) is None


def test_view_cone_opens_along_the_heading_with_the_field_of_view():
    pose = records()[0].pose
    apex, left, right = view_cone(CAMERA, pose, 14.0)
    assert apex == pytest.approx((pose.easting, pose.northing))
    assert left[0] - apex[0] == pytest.approx(14.0) and right[0] - apex[0] == pytest.approx(14.0)
    half_width = 14.0 * 959.5 / 1750.0
    assert left[1] - apex[1] == pytest.approx(half_width) and right[1] - apex[1] == pytest.approx(-half_width)


def test_the_best_pair_sees_a_place_from_nearest_inside_the_range():
    pairs = records(20)  # 2 m apart, driving east from E 2600000
    place = (2600030.0, 1200003.0)  # 3 m left of the track
    best = best_pair_for(CAMERA, pairs, *place)
    depth = place[0] - pairs[best].pose.easting
    assert 4.0 <= depth <= 14.0
    # the next pair would be nearer but the place has left its view (or is nearer than 4 m)
    nxt = pairs[best + 1].pose
    u, _, z = (float(np.ravel(a)[0]) for a in world_to_pixel(CAMERA, nxt, [*place, nxt.height]))
    assert z < 4.0 or not 0.05 * CAMERA.width <= u <= 0.95 * CAMERA.width
    assert best_pair_for(CAMERA, pairs, 2600000.0, 1200500.0) is None  # far off the drive: nobody sees it
    assert nearest_pair(pairs, 2600011.2, 1200000.5) == (6, pytest.approx(np.hypot(0.8, 0.5)))
