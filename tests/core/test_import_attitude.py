"""Angle conventions, lever arm and boresight against hand-checked cases, and round trips of every convention."""

import numpy as np
import pytest

from signmapper_core.geometry import angles_from_rotation
from signmapper_core.importdrive.attitude import CONVENTIONS, convention, forward_heading
from signmapper_core.importdrive.mount import Mount

EAST, NORTH, UP = np.eye(3)


def camera_angles(name, angles, lever=(0, 0, 0), boresight=(0, 0, 0), body_centre=(0, 0, 0)):
    """Drive-format (heading, pitch, roll) and centre of the camera on a body with these recorded angles."""
    conv = convention(name)
    centre, rotation = Mount.from_boresight(conv, lever, boresight).camera_pose(np.array(body_centre, float),
                                                                                conv.rotation(angles))
    return angles_from_rotation(rotation), centre


# (convention, recorded angles) -> camera (heading, pitch, roll) of a camera looking along the body's forward axis;
# every case worked out by hand from the convention's definition (module docstring of attitude.py)
HAND_CHECKED = [
    ("ned_ypr", (0, 0, 0), (0, 0, 0)),        # nose north, level
    ("ned_ypr", (90, 0, 0), (90, 0, 0)),      # heading clockwise from north: east
    ("ned_ypr", (0, 10, 0), (0, 10, 0)),      # pitch positive nose up
    ("ned_ypr", (0, 0, 5), (0, 0, 5)),        # roll positive right side down = camera clockwise from behind
    ("enu_ypr", (0, 0, 0), (90, 0, 0)),       # yaw 0 = east
    ("enu_ypr", (90, 0, 0), (0, 0, 0)),       # yaw counter-clockwise: 90 = north
    ("enu_ypr", (0, 10, 0), (90, -10, 0)),    # pitch about y (left) tips the nose down
    ("enu_ypr", (0, 0, 5), (90, 0, 5)),       # roll about x: left side up = right side down
    ("opk", (90, 0, 0), (0, 0, 0)),           # omega 90: looking north, level
    ("opk", (90, -90, 0), (90, 0, 0)),        # then phi -90 turns about the vertical to the east
    ("opk", (60, 0, 0), (0, -30, 0)),         # omega 60: north, 30 degrees below the horizon
    ("opk", (90, 0, 10), (0, 0, -10)),        # kappa turns the image counter-clockwise seen from behind
    ("camera_hpr", (37, -4, 2), (37, -4, 2)),  # the drive format's own
]


@pytest.mark.parametrize("name, recorded, expected", HAND_CHECKED)
def test_hand_checked_orientations(name, recorded, expected):
    (heading, pitch, roll), _ = camera_angles(name, recorded)
    assert (heading % 360, pitch, roll) == pytest.approx((expected[0] % 360, expected[1], expected[2]), abs=1e-9)


def test_axes_of_the_navigation_frames():
    ned = convention("ned_ypr").rotation((90, 0, 0))
    assert ned @ [1, 0, 0] == pytest.approx(EAST) and ned @ [0, 0, 1] == pytest.approx(-UP)
    enu = convention("enu_ypr").rotation((0, 0, 0))
    assert enu @ [1, 0, 0] == pytest.approx(EAST) and enu @ [0, 1, 0] == pytest.approx(NORTH)
    opk = convention("opk").rotation((0, 0, 0))
    assert opk @ [0, 0, -1] == pytest.approx(-UP)   # omega=phi=kappa=0 is a nadir view


@pytest.mark.parametrize("name", sorted(CONVENTIONS))
def test_every_convention_round_trips(name):
    conv = convention(name)
    rng = np.random.default_rng(3)
    for _ in range(200):
        angles = rng.uniform([-179, -85, -179], [179, 85, 179])
        back = np.array(conv.angles(conv.rotation(angles)))
        diff = (back - angles + 180) % 360 - 180
        assert np.abs(diff).max() < 1e-9, (angles, back)


def test_unknown_convention_lists_the_known_ones():
    with pytest.raises(ValueError, match="ned_ypr"):
        convention("euler")


def test_forward_heading_of_each_body():
    assert forward_heading(convention("ned_ypr").rotation((123, 5, 3)), convention("ned_ypr")) == pytest.approx(123)
    assert forward_heading(convention("enu_ypr").rotation((30, 5, 3)), convention("enu_ypr")) == pytest.approx(60)
    assert forward_heading(convention("opk").rotation((90, -90, 0)), convention("opk")) == pytest.approx(90)


def test_lever_arm_in_body_axes():
    # NED body (x fwd, y right, z down) heading east: 1 m forward = 1 m east, 0.5 m down
    _, centre = camera_angles("ned_ypr", (90, 0, 0), lever=(1, 0, 0.5), body_centre=(100, 200, 10))
    assert centre == pytest.approx([101, 200, 9.5])
    # ENU body (x fwd, y left, z up) facing east: 1 m to the left is 1 m north
    _, centre = camera_angles("enu_ypr", (0, 0, 0), lever=(0, 1, 0))
    assert centre == pytest.approx(NORTH)
    # a tilted body carries the arm with it: nose 30 degrees up, 2 m forward = 1 m up
    _, centre = camera_angles("ned_ypr", (0, 30, 0), lever=(2, 0, 0))
    assert centre == pytest.approx([0, np.sqrt(3), 1])


def test_boresight_angles_relative_to_the_body():
    assert camera_angles("ned_ypr", (0, 0, 0), boresight=(90, 0, 0))[0] == pytest.approx((90, 0, 0))  # right side
    assert camera_angles("ned_ypr", (30, 0, 0), boresight=(90, 0, 0))[0] == pytest.approx((120, 0, 0))
    assert camera_angles("ned_ypr", (0, 0, 0), boresight=(0, -5, 0))[0] == pytest.approx((0, -5, 0))
    assert camera_angles("ned_ypr", (0, 0, 0), boresight=(0, 0, 3))[0] == pytest.approx((0, 0, 3))
    assert camera_angles("enu_ypr", (90, 0, 0), boresight=(-90, 0, 0))[0][0] % 360 == pytest.approx(270)
    # a body that is itself a camera: boresight relative to its view direction
    assert camera_angles("opk", (90, 0, 0), boresight=(90, 0, 0))[0] == pytest.approx((90, 0, 0))
    # body pitched up 10, camera pitched down 10 relative to it: level
    assert camera_angles("ned_ypr", (0, 10, 0), boresight=(0, -10, 0))[0] == pytest.approx((0, 0, 0), abs=1e-9)
