"""Plausibility of fused signs (issue 45, item 3): a sign no sign can be goes to review with its own reason."""

from types import SimpleNamespace

import numpy as np
import pytest
from test_fusion import CAMERA, WEST, camera_at, seen_from

from signmapper_core.drive.reader import PairRecord
from signmapper_core.fusion.plausibility import hold_implausible, lateral_distance
from signmapper_core.fusion.signs import FusionConfig, fuse_observations
from signmapper_core.geometry import Pose
from signmapper_core.output.review_reasons import FACES_AWAY, FAR_FROM_ROAD, MOUNTED_TOO_LOW, ONE_VIEW
from signmapper_core.run.mapping import check_plausibility

CONFIG = FusionConfig()
PATH = np.array([camera_at(k) for k in range(20)])  # east along y = 0, camera 2.4 m above the road (z = 0)
NORTH = np.array([0.0, 1.0, 0.0])
EAST = np.array([1.0, 0.0, 0.0])


def sign_at(position, normal=WEST, pairs=(3, 4, 5, 6, 7)):
    (sign,) = fuse_observations(seen_from(np.array(position, float), pairs, normal=normal), CAMERA, CONFIG)
    assert sign.status == "accepted"
    return sign


@pytest.mark.parametrize("position, normal, reason", [
    ([20.0, 3.0, 2.5], WEST, None),  # beside the road, 2.5 m up, facing the traffic
    ([20.0, 3.0, 0.1], WEST, MOUNTED_TOO_LOW),  # centre 0.1 m above the road
    ([20.0, 3.0, -0.6], WEST, MOUNTED_TOO_LOW),  # below the road (a reflection in a puddle)
    ([20.0, 3.0, 0.45], WEST, None),  # a keep-right sign on a bollard
    ([20.0, 3.0, 2.5], NORTH, FACES_AWAY),  # looking at the houses, 180° from the road
    ([20.0, 3.0, 2.5], EAST, None),  # on the back of the pole, facing the other carriageway: 90°
    ([20.0, 30.0, 2.5], WEST, FAR_FROM_ROAD),  # 30 m beside the road
    ([20.0, 20.0, 2.5], WEST, None),  # the far side of a wide street
])
def test_each_rule_sends_its_sign_to_review_with_its_reason(position, normal, reason):
    sign = sign_at(position, normal)
    held = hold_implausible([sign], PATH, 2.4, CONFIG)
    assert (held, sign.status, sign.review_reason) == ((1, "review", reason) if reason else (0, "accepted", None))


def test_without_the_camera_height_the_height_rule_does_not_apply():
    sign = sign_at([20.0, 3.0, 0.1])
    assert hold_implausible([sign], PATH, None, CONFIG) == 0 and sign.status == "accepted"


def test_a_sign_beyond_the_end_of_the_drive_is_measured_across_the_last_direction():
    """Seen 30 m ahead of the last pair, 3 m beside the road: not far from it."""
    position = np.array([40.0, 3.0, 2.5])
    assert lateral_distance(position, PATH[:6]) == pytest.approx(3.0)
    sign = sign_at(position, pairs=range(0, 6))
    assert hold_implausible([sign], PATH[:6], 2.4, CONFIG) == 0 and sign.status == "accepted"


def test_a_sign_in_review_keeps_the_reason_that_held_it():
    (sign,) = fuse_observations(seen_from(np.array([20.0, 3.0, 0.1]), [5]), CAMERA, CONFIG)
    assert (sign.status, sign.review_reason) == ("review", ONE_VIEW)
    assert hold_implausible([sign], PATH, 2.4, CONFIG) == 0 and sign.review_reason == ONE_VIEW


def test_the_settings_set_the_bounds():
    sign = sign_at([20.0, 3.0, 0.45])
    assert hold_implausible([sign], PATH, 2.4, FusionConfig(min_centre_above_road_m=0.5)) == 1
    sign = sign_at([20.0, 20.0, 2.5])
    assert hold_implausible([sign], PATH, 2.4, FusionConfig(max_lateral_m=15.0)) == 1
    assert sign.review_reason == FAR_FROM_ROAD


def test_mapping_checks_every_sign_with_the_drives_path_and_camera_height():
    records = [PairRecord(k, f"{k:06d}", 0.2 * k, Pose(*camera_at(k), 90.0, 0.0, 0.0), None, None, None)
               for k in range(20)]
    drive = SimpleNamespace(pairs=records, metadata={"vehicle": {"camera_height_m": 2.4}})
    signs = [sign_at([20.0, 3.0, 2.5]), sign_at([30.0, 3.0, 0.1]), sign_at([24.0, -3.0, 2.5], NORTH, range(6, 11))]
    assert check_plausibility(drive, signs, CONFIG) == 1
    assert [s.review_reason for s in signs] == [None, MOUNTED_TOO_LOW, None]  # the third faces the road, from the south
    drive.metadata = {}
    assert check_plausibility(drive, [sign_at([30.0, 3.0, 0.1])], CONFIG) == 0
